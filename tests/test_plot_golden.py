"""The golden drawings (``tests/golden/plot``): ``ngc plot`` of each program gives its recorded
SVG, byte for byte (``python tests/golden/plot_regen.py`` rewrites them), and exits 0, or 1 for
the program that stops on an error; a few are kept as PNG too, reference images the PNG output is
compared with pixel by pixel, within a tolerance."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent / "golden"))
sys.path.insert(0, str(Path(__file__).parent))

import plot_regen

from plot_reader import read_png

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


def _ink(data: bytes) -> tuple[tuple[int, int], set[tuple[int, int]]]:
    """A PNG's size and the pixels drawn in a colour (the toolpath's: the text, the dimension
    lines and the scale bar are grey or black, and depend on the fonts a machine has)."""
    width, height, rows = read_png(data)
    channels = len(rows[0]) // width
    found = set()
    for y, row in enumerate(rows):
        for x in range(width):
            r, g, b = row[x * channels:x * channels + 3]
            if max(r, g, b) - min(r, g, b) > 60:
                found.add((x, y))
    return (width, height), found


@pytest.mark.parametrize("name", plot_regen.PNGS)
def test_png_matches_its_reference_image(name: str, tmp_path: Path) -> None:
    pytest.importorskip("resvg_py")
    program = plot_regen.HERE / f"{name}.ngc"
    out = tmp_path / "out.png"
    assert plot_regen.draw_png(program, out) == 0
    size, ink = _ink(out.read_bytes())
    ref_size, ref_ink = _ink(program.with_suffix(".png").read_bytes())
    assert size == ref_size
    assert len(ink) > 500
    # anti-aliasing may differ between renderer builds: at most 2 % of the inked pixels
    assert len(ink ^ ref_ink) <= 0.02 * len(ink | ref_ink)
