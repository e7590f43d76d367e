"""What ``ngc flatten`` costs against ``ngc canon`` on the same program: wall time (best and
median of the runs) and peak resident memory of the process tree (the verification runs in a
second process), for each program kind and length.

    /usr/bin/python3 benchmarks/flatten_cost.py                       # surface and contour, 200k
    /usr/bin/python3 benchmarks/flatten_cost.py --kinds surface --lines 1000000 --runs 1
    /usr/bin/python3 benchmarks/flatten_cost.py --target grbl

The programs are ``bench.py``'s (``benchmarks/out/KIND-LINES.ngc``, made from
``../shared/bench/benchgen.py`` when missing).  Both commands write to /dev/null; the Python
that runs them is the one running this script (name it in the results: Debian's python3 is built
with PGO).
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench import DEFAULT_OUT_DIR, DEFAULT_SHARED, ensure_program  # (the benchmark here)

SRC = Path(__file__).resolve().parent.parent / "src"


def _run(argv: list[str]) -> tuple[float, float]:
    """Wall seconds and the peak resident MiB of the command and its children."""
    env = dict(os.environ, PYTHONPATH=str(SRC))
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    start = time.perf_counter()
    done = subprocess.run(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=env,
                          text=True, check=False)
    wall = time.perf_counter() - start
    if done.returncode != 0:
        raise SystemExit(f"{' '.join(argv)}: exit {done.returncode}: {done.stderr[-400:]}")
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    return wall, max(peak, before) / 1024.0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--kinds", default="surface,contour")
    parser.add_argument("--lines", type=int, default=200000)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--target", default="linuxcnc")
    options = parser.parse_args()
    python = sys.executable
    # (the package's modules compiled first, as an installed package has them: a module whose
    # cached bytecode is stale is compiled again at each start)
    subprocess.run([python, "-m", "compileall", "-q", str(SRC)], check=True)
    print(f"python: {python} {sys.version.split()[0]}; {os.cpu_count()} cores; "
          f"target {options.target}")
    print(f"{'program':<18} {'canon s':>9} {'flatten s':>10} {'ratio':>6} {'flatten MiB':>12}")
    for kind in options.kinds.split(","):
        program = ensure_program(DEFAULT_SHARED, DEFAULT_OUT_DIR, kind, options.lines)
        canon, flat, memory = [], [], 0.0
        for _ in range(options.runs):
            canon.append(_run([python, "-m", "ngc", "canon", str(program)])[0])
            wall, peak = _run([python, "-m", "ngc", "flatten", "--target", options.target,
                               str(program), "-o", os.devnull])
            flat.append(wall)
            memory = max(memory, peak)
        best = min(flat) / min(canon)
        print(f"{program.name:<18} {min(canon):>9.2f} {min(flat):>10.2f} {best:>6.2f} "
              f"{memory:>12.0f}   (medians {statistics.median(canon):.2f} / "
              f"{statistics.median(flat):.2f})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
