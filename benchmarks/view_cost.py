"""What ``ngc view`` makes of a large program, and how a browser takes it: the time to write the
page, its size, and in Debian's chromium (headless, SwiftShader WebGL, through Playwright) the
time from navigation to ``window.ngcView.ready`` (the first frame drawn), the tab's JavaScript
heap and the resident size of its renderer and GPU processes.

    python benchmarks/view_cost.py                         # surface, 1,000,000 lines
    python benchmarks/view_cost.py --kind contour --lines 200000 --runs 3

The programs are ``bench.py``'s (``benchmarks/out/KIND-LINES.ngc``, made from
``../shared/bench/benchgen.py`` when missing).
"""

from __future__ import annotations

import argparse
import shlex
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench import ensure_program  # the benchmark next to this file

HERE = Path(__file__).resolve().parent
ARGS = ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader"]


def _resident_mib(kind: str) -> float:
    out = subprocess.run(["ps", "-eo", "rss,args"], capture_output=True, text=True).stdout
    return sum(int(line.split()[0]) for line in out.splitlines()[1:]
               if "chromium" in line and f"--type={kind}" in line) / 1024.0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--kind", default="surface")
    parser.add_argument("--lines", type=int, default=1_000_000)
    parser.add_argument("--runs", type=int, default=3, help="page loads (the median is shown)")
    parser.add_argument("--ngc", default=f"{sys.executable} -m ngc")
    parser.add_argument("--shared", default=str(HERE.parent.parent / "shared"))
    options = parser.parse_args()
    from playwright.sync_api import sync_playwright

    chromium = shutil.which("chromium")
    if chromium is None:
        sys.exit("view_cost: no chromium (apt-get install chromium)")
    program = ensure_program(Path(options.shared), HERE / "out", options.kind, options.lines)
    with tempfile.TemporaryDirectory() as folder:
        page = Path(folder) / "page.html"
        start = time.perf_counter()
        done = subprocess.run([*shlex.split(options.ngc), "view", str(program), "-o", str(page)],
                              capture_output=True, text=True)
        written = time.perf_counter() - start
        print(done.stderr.strip())
        size = page.stat().st_size
        loads, heaps, renderers, gpus = [], [], [], []
        with sync_playwright() as p:
            for _ in range(options.runs):
                browser = p.chromium.launch(executable_path=chromium, args=ARGS)
                tab = browser.new_page(viewport={"width": 1400, "height": 850})
                cdp = tab.context.new_cdp_session(tab)
                cdp.send("Performance.enable")
                start = time.perf_counter()
                tab.goto(page.as_uri(), timeout=300_000)
                tab.evaluate("window.ngcView.ready.then(() => true)")
                loads.append(time.perf_counter() - start)
                metrics = {m["name"]: m["value"] for m in cdp.send("Performance.getMetrics")["metrics"]}
                heaps.append(metrics["JSHeapUsedSize"] / 2**20)
                renderers.append(_resident_mib("renderer"))
                gpus.append(_resident_mib("gpu-process"))
                segments = tab.evaluate("window.ngcView.segments")
                browser.close()
    print(f"| {options.kind} | {options.lines} | {segments} | {written:.1f} | {size / 1e6:.1f} | "
          f"{statistics.median(loads):.2f} | {statistics.median(heaps):.0f} | "
          f"{statistics.median(renderers):.0f} | {statistics.median(gpus):.0f} |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
