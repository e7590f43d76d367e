"""Write the golden drawings: ``ngc plot`` of each ``tests/golden/plot/NAME.ngc`` (its first line
``(plot: ARGS)`` gives the options) to ``NAME.svg``, and the engine dialect's pictures
(``docs/engine/NAME.ngc``).  Run after a change to the drawing that is
meant, and look at what changed.

    python tests/golden/plot_regen.py
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent / "plot"
ARGS = re.compile(r"^\(plot: ([^)]*)\)")


def args_of(program: Path) -> list[str]:
    m = ARGS.match(program.read_text().splitlines()[0])
    return m.group(1).split() if m else []


def draw(program: Path, out: Path) -> int:
    """``ngc plot`` of ``program`` to ``out``, run in the golden folder; its exit code."""
    return subprocess.run([sys.executable, "-m", "ngc", "plot", program.name, *args_of(program),
                           "-o", str(out)], cwd=program.parent, capture_output=True,
                          check=False).returncode


ENGINE_DOCS = Path(__file__).resolve().parents[2] / "docs" / "engine"


# the drawings kept as PNG too, the reference images of the pixel test, at this size
PNGS = ("arcs-xy", "ccomp-mill", "helix", "lathe-cycles")
PNG_SIZE = "600x450"


def draw_png(program: Path, out: Path) -> int:
    return subprocess.run([sys.executable, "-m", "ngc", "plot", program.name, *args_of(program),
                           "--size", PNG_SIZE, "-o", str(out)], cwd=program.parent,
                          capture_output=True, check=False).returncode


def main() -> int:
    for program in sorted([*HERE.glob("*.ngc"), *ENGINE_DOCS.glob("*.ngc")]):
        code = draw(program, program.with_suffix(".svg"))
        print(f"{program.name}: exit {code}")
    for name in PNGS:
        program = HERE / f"{name}.ngc"
        print(f"{name}.png: exit {draw_png(program, program.with_suffix('.png'))}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
