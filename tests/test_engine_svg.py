"""SVG drawings of engine toolpaths (``ngc.engine.svg``): what the module draws of the seed's
examples (``docs/engine``, whose pictures ``ngc plot`` makes: tests/test_plot_golden.py), read back
from the SVG itself, is the seed's geometry; the viewBox holds the curves; rapids are dashed;
``python -m ngc.engine.svg``."""

from __future__ import annotations

import itertools
import math
import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from ngc.engine import run, svg
from ngc.engine.bezier import point
from ngc.engine.svg import draw

DOCS = Path(__file__).resolve().parent.parent / "docs"
DRAWINGS = DOCS / "engine"
NS = "{http://www.w3.org/2000/svg}"
PROGRAMS = {
    "epicyclic": "move PZ 0 360 0.5 0 PZ 0 3960 0.125 0",
    "epicyclic-external": "move PZ 0 360 0.5 0 PZ 0 -3960 0.18 0",
    "oval": "move PZ 0 360 0.5 0 PZ 0 -360 0.25 0",
    "trim": "move PZ 0 3600 0.125 0 X 2",
}
SAMPLES = 64

Point = tuple[float, float]
Curve = tuple[Point, Point, Point, Point]


# -- reading an SVG back ---------------------------------------------------------------------------
def parse_path(d: str) -> list[Curve]:
    """The cubics of path data made of ``M x,y`` and ``C x1,y1 x2,y2 x,y`` commands, in the
    drawing's coordinates."""
    tokens = re.findall(r"[A-Za-z]|[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?", d)
    curves: list[Curve] = []
    pen: Point | None = None
    i = 0
    while i < len(tokens):
        command = tokens[i]
        numbers = [float(t) for t in tokens[i + 1:i + 1 + (2 if command == "M" else 6)]]
        if command == "M":
            pen = (numbers[0], numbers[1])
        elif command == "C":
            assert pen is not None, "C before any M"
            p1, p2, p3 = (numbers[0], numbers[1]), (numbers[2], numbers[3]), (numbers[4], numbers[5])
            curves.append((pen, p1, p2, p3))
            pen = p3
        else:
            raise AssertionError(f"unexpected path command {command!r}")
        i += 1 + len(numbers)
    return curves


def paths(text: str) -> list[ET.Element]:
    return list(ET.fromstring(text).iter(f"{NS}path"))


def curves_of(text: str) -> list[Curve]:
    return [c for p in paths(text) for c in parse_path(p.attrib["d"])]


def view_box(text: str) -> tuple[float, float, float, float]:
    x, y, w, h = (float(v) for v in ET.fromstring(text).attrib["viewBox"].split())
    return x, y, w, h


def at(c: Curve, t: float) -> Point:
    s = 1.0 - t
    w = (s * s * s, 3.0 * s * s * t, 3.0 * s * t * t, t * t * t)
    return (sum(wi * p[0] for wi, p in zip(w, c, strict=True)),
            sum(wi * p[1] for wi, p in zip(w, c, strict=True)))


def sampled(curves: list[Curve], per: int = SAMPLES) -> list[Point]:
    return [at(c, i / per) for c in curves for i in range(per + 1)]


def unflipped(points: list[Point]) -> list[Point]:
    """Back from the drawing's coordinates (y down) to the program's (Y up)."""
    return [(x, -y) for x, y in points]


def drawing(name: str) -> str:
    """The module's drawing of the docs' example ``name``."""
    return draw(run((DRAWINGS / f"{name}.ngc").read_text(encoding="utf-8")))


def ellipse_distance(x: float, y: float, a: float, b: float) -> float:
    """The distance from (x, y) to the ellipse x²/a² + y²/b² = 1: Newton's method on the angle
    of the nearest point, from the point's own angle."""
    theta = math.atan2(y / b, x / a)
    for _ in range(20):
        s, c = math.sin(theta), math.cos(theta)
        # half the derivative of the squared distance, and its derivative
        g = a * x * s - b * y * c - (a * a - b * b) * s * c
        dg = a * x * c + b * y * s - (a * a - b * b) * (c * c - s * s)
        if dg == 0.0:
            break
        step = g / dg
        theta -= step
        if abs(step) < 1e-15:
            break
    return math.hypot(x - a * math.cos(theta), y - b * math.sin(theta))


# -- (a) the docs' examples are the seed's ----------------------------------------------------------
@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_docs_example_is_the_seeds(name: str) -> None:
    program = (DRAWINGS / f"{name}.ngc").read_text(encoding="utf-8")
    assert program.splitlines() == ["(dialect: engine)", PROGRAMS[name]]


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_docs_page_shows_the_drawing(name: str) -> None:
    assert f"](engine/{name}.svg)" in (DOCS / "engine-dialect.md").read_text(encoding="utf-8")


# -- (b) the geometry, read from the SVG -----------------------------------------------------------
def test_oval_is_an_ellipse_of_075_by_025() -> None:
    curves = curves_of(drawing("oval"))
    assert len(curves) == 4
    # centred where the two circles' centres add: (-0.75, 0)
    worst = max(ellipse_distance(x + 0.75, y, 0.75, 0.25)
                for x, y in unflipped(sampled(curves)))
    assert worst < 3e-4
    assert math.dist(curves[-1][3], curves[0][0]) < 1e-9


def test_ellipse_distance_is_a_distance() -> None:
    assert ellipse_distance(0.75, 0.0, 0.75, 0.25) == pytest.approx(0.0, abs=1e-15)
    assert ellipse_distance(0.0, 0.35, 0.75, 0.25) == pytest.approx(0.1)
    assert ellipse_distance(1.0, 0.0, 0.75, 0.25) == pytest.approx(0.25)
    # a point off the axes: the nearest point's normal passes through it
    x, y = 0.5, 0.3
    d = ellipse_distance(x, y, 0.75, 0.25)
    best = min(math.hypot(x - 0.75 * math.cos(t), y - 0.25 * math.sin(t))
               for t in (i * 2 * math.pi / 200000 for i in range(200000)))
    assert d == pytest.approx(best, abs=1e-9)


@pytest.mark.parametrize("name", ["epicyclic", "epicyclic-external"])
def test_epicyclic_has_44_cubics_and_closes(name: str) -> None:
    curves = curves_of(drawing(name))
    assert len(curves) == 44
    assert math.dist(curves[-1][3], curves[0][0]) < 1e-9


def test_epicyclic_loops_lie_between_the_circles() -> None:
    # both circles start at angle 0, so their centres add to (-0.625, 0); the point is 0.125
    # from the small circle's centre, which is 0.5 from there
    for x, y in unflipped(sampled(curves_of(drawing("epicyclic")))):
        r = math.hypot(x + 0.625, y)
        assert 0.375 - 1e-4 < r < 0.625 + 1e-4


def test_trim_has_40_cubics_advancing_x_by_2() -> None:
    curves = curves_of(drawing("trim"))
    assert len(curves) == 40
    (x0, y0), (x1, y1) = curves[0][0], curves[-1][3]
    assert x1 - x0 == 2.0
    assert abs(y1 - y0) < 1e-9


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_cubics_join(name: str) -> None:
    curves = curves_of(drawing(name))
    for a, b in itertools.pairwise(curves):
        assert a[3] == b[0]


# -- (c) the viewBox -------------------------------------------------------------------------------
@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_view_box_holds_the_curves_with_a_margin(name: str) -> None:
    text = drawing(name)
    x, y, w, h = view_box(text)
    points = sampled(curves_of(text), 256)
    for px, py in points:
        assert x <= px <= x + w and y <= py <= y + h
    # fitted to the curves (not their control points): the margin is the same on every side
    size = max(w, h) / (1.0 + 2.0 * svg.MARGIN)
    margin = svg.MARGIN * size
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    for edge, extreme in ((x, min(xs)), (x + w, max(xs)), (y, min(ys)), (y + h, max(ys))):
        assert abs(abs(edge - extreme) - margin) < 1e-5


def test_extent_finds_the_turning_point() -> None:
    # control points reach 1, the curve only 0.75
    assert svg.extent((0.0, 1.0, 1.0, 0.0)) == (0.0, 0.75)
    assert svg.extent((0.0, 1.0, 2.0, 3.0)) == (0.0, 3.0)
    lo, hi = svg.extent((1.0, -2.0, 3.0, 0.5))
    values = [point((1.0, -2.0, 3.0, 0.5), i / 10000) for i in range(10001)]
    assert lo == pytest.approx(min(values), abs=1e-7) and lo < min(values) + 1e-12
    assert hi == pytest.approx(max(values), abs=1e-7) and hi > max(values) - 1e-12


def test_empty_program_is_a_valid_drawing() -> None:
    text = draw(run("(nothing)\nG90"))
    assert paths(text) == []
    assert view_box(text) == (-0.05, -0.05, 0.1, 0.1)


# -- (d) styles ------------------------------------------------------------------------------------
@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_docs_drawings_are_dashed_rapids(name: str) -> None:
    (path,) = paths(drawing(name))
    assert path.attrib["class"] == "rapid"
    assert path.attrib["stroke-dasharray"]


def test_motions_each_get_a_path_and_only_rapids_are_dashed() -> None:
    text = draw(run("G0 X1\nG0 X2\nG1 F10 X3\nG2 X5 I1\nG31 X0\nG0 Y1"))
    found = [(p.attrib["class"], len(parse_path(p.attrib["d"])), "stroke-dasharray" in p.attrib)
             for p in paths(text)]
    assert found == [("rapid", 2, True), ("feed", 1, False), ("arc", 2, False),
                     ("probe", 1, False), ("rapid", 1, True)]
    assert len({p.attrib["stroke"] for p in paths(text)}) == 4
    assert "<title>Engine toolpath on the XY plane: 7 segments</title>" in text


def test_stroke_scales_with_the_drawing() -> None:
    small = paths(draw(run("G0 X1 Y1")))[0].attrib["stroke-width"]
    large = paths(draw(run("G0 X100 Y100")))[0].attrib["stroke-width"]
    assert float(large) == pytest.approx(100 * float(small))


# -- projection and numbers ------------------------------------------------------------------------
@pytest.mark.parametrize(("plane", "end"), [("XY", (1.0, -2.0)), ("XZ", (1.0, -3.0)),
                                            ("YZ", (2.0, -3.0))])
def test_planes_with_up_up(plane: str, end: Point) -> None:
    (curve,) = curves_of(draw(run("G0 X1 Y2 Z3"), plane=plane))
    assert curve[0] == (0.0, 0.0) and curve[3] == end


def test_unknown_plane() -> None:
    with pytest.raises(ValueError, match="not 'ZX'"):
        draw(run("G0 X1"), plane="ZX")


def test_absent_axes_hold_and_a_jump_starts_a_subpath() -> None:
    # Y alone, then X alone from there; G92 presets X without motion: the pen jumps
    text = draw(run("G0 Y1\nG0 X1\nG92 X5\nG0 Y2"))
    (path,) = paths(text)
    assert path.attrib["d"].count("M") == 2
    curves = parse_path(path.attrib["d"])
    assert [(c[0], c[3]) for c in curves] == [((0, 0), (0, -1)), ((0, -1), (1, -1)),
                                              ((5, -1), (5, -2))]


@pytest.mark.parametrize(("x", "text"), [
    (0.0, "0"), (-0.0, "0"), (-1e-12, "0"), (2.0, "2"), (-0.25, "-0.25"), (1 / 3, "0.3333333333"),
    (123456.5, "123456.5"), (5.685e-18, "0"),
])
def test_numbers(x: float, text: str) -> None:
    assert svg.number(x) == text


def test_numbers_must_be_finite() -> None:
    with pytest.raises(ValueError):
        svg.number(math.nan)


# -- (e) the command -------------------------------------------------------------------------------
def test_command_writes_the_drawing(tmp_path: Path) -> None:
    out = tmp_path / "oval.svg"
    done = subprocess.run([sys.executable, "-m", "ngc.engine.svg", str(DRAWINGS / "oval.ngc"),
                           "-o", str(out)], capture_output=True, text=True, check=False)
    assert (done.returncode, done.stdout, done.stderr) == (0, "", "")
    assert out.read_text(encoding="utf-8") == drawing("oval")


def test_command_draws_on_stdout_on_a_plane(capsys: pytest.CaptureFixture[str],
                                            tmp_path: Path) -> None:
    program = tmp_path / "p.ngc"
    program.write_text("(dialect: engine)\nG0 X1 Y2 Z3\n")
    assert svg.main([str(program), "--plane", "yz"]) == 0
    out, err = capsys.readouterr()
    assert err == ""
    assert out == draw(run("G0 X1 Y2 Z3"), plane="YZ")


def test_command_program_error(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    program = tmp_path / "bad.ngc"
    program.write_text("(dialect: engine)\nG0 X1\nmove PZ 90 1\n")
    out_file = tmp_path / "bad.svg"
    assert svg.main([str(program), "-o", str(out_file)]) == 1
    out, err = capsys.readouterr()
    assert out == ""
    assert err == (f"{program}:3: PZ has no centre: set one with G103 (set polar center)\n"
                   "    move PZ 90 1\n")
    assert not out_file.exists()


def test_command_cannot_open(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    missing = tmp_path / "nope.ngc"
    assert svg.main([str(missing)]) == 2
    out, err = capsys.readouterr()
    assert out == ""
    assert err == f"python -m ngc.engine.svg: cannot open {missing}: No such file or directory\n"


def test_command_cannot_write(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    out_file = tmp_path / "no-such-dir" / "x.svg"
    assert svg.main([str(DRAWINGS / "oval.ngc"), "-o", str(out_file)]) == 2
    _, err = capsys.readouterr()
    assert err == f"python -m ngc.engine.svg: cannot write {out_file}: No such file or directory\n"


def test_command_usage_errors(capsys: pytest.CaptureFixture[str]) -> None:
    assert svg.main([str(DRAWINGS / "oval.ngc"), "--plane", "ZX"]) == 2
    assert "invalid choice: 'ZX'" in capsys.readouterr().err
    assert svg.main([]) == 2
    assert "required" in capsys.readouterr().err
