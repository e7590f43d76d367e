"""What planning (or drawing) costs on top of interpretation: ``ngc time FILE`` (or ``ngc plot
FILE -o OUT.svg``, ``--command plot``) against ``ngc canon FILE``.

``ngc canon`` interprets a program and prints its canonical operations; ``ngc time`` interprets it
the same way and runs every move through the look-ahead planner instead of printing it.  The
ratio time / canon, pair by pair, says how much the planner adds: at most 1x the interpretation
(a ratio of 2) is the bar.  Memory: the peak resident size of ``ngc time`` on the first 25 %,
50 % and 100 % of the program, which should stay flat.

    python benchmarks/planner_cost.py                       # surface, 200000 lines, 7 pairs
    python benchmarks/planner_cost.py --kinds surface,contour --runs 9
    python benchmarks/planner_cost.py --ngc 'python -m ngc'

The programs are ``bench.py``'s (``benchmarks/out/KIND-LINES.ngc``, made from
``../shared/bench/benchgen.py`` when missing).  Timing is ``bench.py``'s: one warm-up run each,
then alternated runs with output to /dev/null, wall time and the child's CPU time.
"""

from __future__ import annotations

import argparse
import shlex
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench import (  # the benchmark next to this file
    DEFAULT_OUT_DIR,
    DEFAULT_SHARED,
    CommandError,
    child_env,
    ensure_program,
    machine_name,
    private_home,
    run_captured,
    run_timed,
)

# A small process that runs the command and prints its children's peak resident size: measured
# from this process directly, the peak would include the pages the child had before it started
# the command (this process's own, which hold a copy of the program).
PEAK = ("import resource, subprocess, sys; rc = subprocess.call(sys.argv[1:]); "
        "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss); sys.exit(rc)")


def peak_rss_mib(prefix: list[str], program: Path) -> float:
    """The peak resident size of one run, in MiB (the kernel's accounting of the finished
    command)."""
    with private_home() as home:
        proc = subprocess.run([sys.executable, "-c", PEAK, *prefix, program.name],
                              cwd=program.parent, env=child_env(home), stdin=subprocess.DEVNULL,
                              capture_output=True, text=True, check=False)
    if proc.returncode != 0:
        raise CommandError(f"{shlex.join(prefix)} exited {proc.returncode}")
    return int(proc.stdout.strip().splitlines()[-1]) / 1024.0


def head_of(program: Path, fraction: float, folder: Path) -> Path:
    """The first ``fraction`` of the program's lines, ended by M2, in ``folder``."""
    lines = program.read_text().splitlines(keepends=True)
    keep = lines[: max(1, int(len(lines) * fraction))]
    if keep[-1].strip() != "M2":
        keep.append("M2\n")
    out = folder / f"{program.stem}-{int(fraction * 100)}pct.ngc"
    out.write_text("".join(keep))
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--ngc", default="ngc", help="the ngc command (default: %(default)s)")
    ap.add_argument("--kinds", default="surface", help="program kinds (default: %(default)s)")
    ap.add_argument("--lines", type=int, default=200_000, help="program size")
    ap.add_argument("--runs", type=int, default=7, help="timed pairs (default: %(default)s)")
    ap.add_argument("--shared", type=Path, default=DEFAULT_SHARED)
    ap.add_argument("--out-dir", type=Path, default=DEFAULT_OUT_DIR)
    ap.add_argument("--command", choices=("time", "plot"), default="time",
                    help="the command measured against canon (plot: an SVG in a scratch "
                    "directory; default: %(default)s)")
    args = ap.parse_args(argv)
    ngc = shlex.split(args.ngc)
    with tempfile.TemporaryDirectory(prefix="ngc-cost-") as scratch:
        canon = [*ngc, "canon"]
        timed = ([*ngc, "time"] if args.command == "time"
                 else [*ngc, "plot", "-o", str(Path(scratch) / "out.svg")])
        return _measure(args, canon, timed)


def _measure(args: argparse.Namespace, canon: list[str], timed: list[str]) -> int:
    cmd = args.command
    print(f"machine: {machine_name()}; `{args.ngc} canon|{cmd} FILE`; {args.runs} pairs, "
          "medians\n")
    print(f"| program | lines | canon wall s | {cmd} wall s | {cmd} / canon (wall) "
          f"| {cmd} / canon (cpu) | {cmd} peak MiB at 25 / 50 / 100 % |")
    print("|---|---:|---:|---:|---:|---:|---|")
    for kind in [k for k in args.kinds.split(",") if k]:
        try:
            program = ensure_program(args.shared, args.out_dir, kind, args.lines)
            run_captured(timed, program, None)  # fails early if the program does not run
            for prefix in (canon, timed):  # warm-up: page cache, compiled byte code
                run_timed(prefix, program, None)
            pairs = []
            for n in range(args.runs):
                print(f"{program.name}: pair {n + 1}/{args.runs}", file=sys.stderr, flush=True)
                pairs.append((run_timed(canon, program, None), run_timed(timed, program, None)))
            with tempfile.TemporaryDirectory(prefix="ngc-planner-cost-") as tmp:
                peaks = [peak_rss_mib(timed, head_of(program, f, Path(tmp)) if f < 1 else program)
                         for f in (0.25, 0.5, 1.0)]
        except CommandError as exc:
            print(f"| {kind} | {args.lines} | failed: {exc} | | | | |")
            continue
        wall = statistics.median(t.wall_s / c.wall_s for c, t in pairs)
        cpu = statistics.median(t.cpu_s / c.cpu_s for c, t in pairs)
        print(f"| {kind} | {args.lines} | {statistics.median(c.wall_s for c, _ in pairs):.3f} "
              f"| {statistics.median(t.wall_s for _, t in pairs):.3f} | {wall:.2f} | {cpu:.2f} "
              f"| {' / '.join(f'{p:.1f}' for p in peaks)} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
