"""The golden drawings (``tests/golden/plot``): ``ngc plot`` of each program gives its recorded
SVG, byte for byte (``python tests/golden/plot_regen.py`` rewrites them), and exits 0, or 1 for
the program that stops on an error."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent / "golden"))

import plot_regen

PROGRAMS = sorted(plot_regen.HERE.glob("*.ngc"))


def test_the_set_covers_the_kinds_of_move() -> None:
    names = {p.stem for p in PROGRAMS}
    assert {"lines", "arcs-xy", "arcs-xz", "arcs-yz", "helix", "cycles", "ccomp-mill",
            "ccomp-lathe", "lathe-cycles", "nurbs", "rotation-offsets", "inch",
            "error-stop", "tools"} <= names


ENGINE_DOCS = sorted((Path(__file__).resolve().parent.parent / "docs" / "engine").glob("*.ngc"))


@pytest.mark.parametrize("program", ENGINE_DOCS, ids=[p.stem for p in ENGINE_DOCS])
def test_engine_docs_pictures_are_ngc_plots(program: Path, tmp_path: Path) -> None:
    """The engine dialect's pictures (docs/engine-dialect.md) are what ngc plot makes."""
    out = tmp_path / "out.svg"
    assert plot_regen.draw(program, out) == 0
    assert out.read_text() == program.with_suffix(".svg").read_text()


@pytest.mark.parametrize("program", PROGRAMS, ids=[p.stem for p in PROGRAMS])
def test_drawing(program: Path, tmp_path: Path) -> None:
    out = tmp_path / "out.svg"
    code = plot_regen.draw(program, out)
    assert code == (1 if program.stem.startswith("error") else 0)
    assert out.read_text() == program.with_suffix(".svg").read_text()
