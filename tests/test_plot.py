"""``ngc plot``: the drawing read back and compared with the toolpath (arc radii, end points,
extents), PNG pixels, an error stop, bad command lines."""

from __future__ import annotations

import math
import sys
from pathlib import Path

import pytest

from cli_helpers import run, write
from ngc.interp.interpreter import Interpreter
from ngc.toolpath.moves import Move, MoveList
from plot_reader import read_png, read_svg

SAMPLE = """G21 G90 G17
G0 X0 Y0 Z5
G1 Z-1 F200
G1 X40 F600
G3 X60 Y20 R20
G1 Y50
G2 X40 Y70 I-20 J0
G1 X0
G0 Z5
G81 X10 Y30 Z-3 R2 F100
X20
G80
G1 X30 Y35 Z-2 F300
G2 X30 Y35 Z-6 I5 J0 P3
G0 Z5
M2
"""


def toolpath(text: str) -> list[Move]:
    out: list[object] = []
    reader = MoveList(out.append)
    interp = Interpreter(reader.toolpath)
    interp.startup()
    interp.run(text.splitlines())
    return [m for m in out if isinstance(m, Move)]


def plot(tmp_path: Path, capsys: pytest.CaptureFixture[str], text: str, *args: str,
         out: str = "out.svg") -> tuple[int, str, str]:
    src = write(tmp_path, "prog.ngc", text)
    code, _, err = run(capsys, "plot", src, "-o", str(tmp_path / out), *args)
    data = (tmp_path / out).read_text() if out.endswith(".svg") and code in (0, 1) else ""
    return code, data, err


def test_arcs_are_exact_svg_arcs_with_the_toolpath_radii(tmp_path: Path,
                                                         capsys: pytest.CaptureFixture[str]) -> None:
    code, text, _ = plot(tmp_path, capsys, SAMPLE)
    assert code == 0
    _, segments, _ = read_svg(text)
    arcs = [s for s in segments if s.kind == "A"]
    # the quarter and the three-quarter circle of radius 20; the helix (seen from its axis, a
    # circle of radius 5) as two halves of a whole circle
    radii = sorted(round(a.args[0], 4) for a in arcs)
    assert radii == [5.0, 5.0, 20.0, 20.0]
    moves = toolpath(SAMPLE)
    quarter = next(a for a in arcs if a.args[0] == 20 and a.args[3] == 0)  # large-arc 0
    assert quarter.start == (40.0, 0.0) and quarter.end == (60.0, 20.0)
    assert quarter.args[4] == 1  # counterclockwise (G3), y up
    three = next(a for a in arcs if a.args[0] == 20 and a.args[3] == 1)
    assert three.start == (60.0, 50.0) and three.end == (40.0, 70.0) and three.args[4] == 0
    # every drawn end point is a toolpath point
    ends = {(round(m.end[0], 4), round(m.end[1], 4)) for m in moves}
    assert all((round(s.end[0], 4), round(s.end[1], 4)) in ends | {(40.0, 35.0)}  # (the helix's half)
               for s in segments if s.kind != "M")


def test_extents_and_dimension_lines(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    _, text, _ = plot(tmp_path, capsys, SAMPLE)
    root, segments, (a, _, _, d, _e, _f) = read_svg(text)
    xs = [p for s in segments for p in (s.start[0], s.end[0]) if s.kind != "M"]
    ys = [p for s in segments for p in (s.start[1], s.end[1]) if s.kind != "M"]
    # the three-quarter circle about (40, 50) reaches X 20 and Y 30; the drawing spans X 0..60
    # (the G81 holes at X 10, 20 lie inside), Y 0..70
    assert min(xs) == 0.0 and max(xs) == 60.0 and min(ys) == 0.0 and max(ys) == 70.0
    dims = "".join(root.find("{http://www.w3.org/2000/svg}g[@id='dimensions']").itertext())  # type: ignore[union-attr]
    assert "X 60.000 mm" in dims and "Y 70.000 mm" in dims
    assert a == -d > 0  # one scale on both axes, Y up


def test_rapids_are_dashed_and_the_approach_is_left_out(tmp_path: Path,
                                                         capsys: pytest.CaptureFixture[str]) -> None:
    _, text, _ = plot(tmp_path, capsys, SAMPLE)
    _, segments, _ = read_svg(text)
    rapids = [s for s in segments if s.dashed and s.kind == "L"]
    assert rapids and all(not s.dashed for s in segments if s.kind == "A")
    assert all(s.start != (0.0, 0.0) or s.kind == "M" for s in rapids)  # no G0 X0 Y0 Z5
    _, text, _ = plot(tmp_path, capsys, "G0 X-10 Y-10\nG1 X0 Y0 F100\nM2\n", "--approach")
    _, segments, _ = read_svg(text)
    assert any(s.dashed and s.end == (-10.0, -10.0) for s in segments)


def test_drill_points_are_marked(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    _, text, _ = plot(tmp_path, capsys, SAMPLE)
    root, _, (a, _, _, d, e, f) = read_svg(text)
    circles = root.findall(".//{http://www.w3.org/2000/svg}g[@id='marks']/"
                           "{http://www.w3.org/2000/svg}circle")
    centres = sorted((round((float(c.attrib["cx"]) - e) / a, 1),
                      round((float(c.attrib["cy"]) - f) / d, 1)) for c in circles)
    assert centres == [(10.0, 30.0), (20.0, 30.0)]


def test_helix_seen_from_the_side_is_beziers_on_the_helix(tmp_path: Path,
                                                          capsys: pytest.CaptureFixture[str]) -> None:
    prog = "G21 G0 X5 Y0 Z0\nG17 G3 X5 Y0 Z-6 I-5 J0 F100 P2\nM2\n"
    _, text, _ = plot(tmp_path, capsys, prog, "--view", "front")
    _, segments, _ = read_svg(text)
    curves = [s for s in segments if s.kind == "C"]
    assert len(curves) >= 8
    for s in curves:  # each end on the helix: x = 5 cos(t), z = -6 t / 4 pi
        x, z = s.end
        t = -z / 6 * 4 * math.pi
        assert x == pytest.approx(5 * math.cos(t), abs=2e-4)
    # midpoints of the Béziers within a micrometre of the helix
    for s in curves:
        p0, c1, c2, p3 = s.start, s.args[0:2], s.args[2:4], s.args[4:6]
        mx = (p0[0] + 3 * c1[0] + 3 * c2[0] + p3[0]) / 8
        mz = (p0[1] + 3 * c1[1] + 3 * c2[1] + p3[1]) / 8
        t = -mz / 6 * 4 * math.pi
        assert mx == pytest.approx(5 * math.cos(t), abs=1e-3)


def test_an_error_stops_the_drawing_and_is_written_on_it(tmp_path: Path,
                                                         capsys: pytest.CaptureFixture[str]) -> None:
    code, text, err = plot(tmp_path, capsys, "G21 G1 X10 F100\nG1 Y10\nG2 X0 Y0 R1\nG1 X5\nM2\n")
    assert code == 1
    assert "Arc radius too small to reach end point" in err
    root, segments, _ = read_svg(text)
    assert root.find(".//{http://www.w3.org/2000/svg}path[@id='stopped']") is not None
    error = root.find("{http://www.w3.org/2000/svg}text[@id='error']")
    assert error is not None and "line 3" in (error.text or "")
    assert max(s.end[1] for s in segments) == 10.0


def test_png_pixels_have_the_toolpath_aspect_ratio(tmp_path: Path,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    pytest.importorskip("resvg_py")
    prog = "G21 G0 X0 Y0\nG1 X80 F100\nG1 Y30\nG1 X0\nG1 Y0\nM2\n"
    code, _, _ = plot(tmp_path, capsys, prog, "--size", "600x500", out="out.png")
    assert code == 0
    width, height, rows = read_png((tmp_path / "out.png").read_bytes())
    assert (width, height) == (600, 500)
    channels = len(rows[0]) // width
    xs, ys = [], []
    for y, row in enumerate(rows):
        if y < 100:  # (the legend's sample lines)
            continue
        for x in range(width):
            r, _g, b = row[x * channels:x * channels + 3]
            if b > 120 and r < 120:  # the feeds' blue
                xs.append(x)
                ys.append(y)
    w, h = max(xs) - min(xs), max(ys) - min(ys)
    assert w / h == pytest.approx(80 / 30, rel=0.02)


def test_png_without_the_renderer_names_the_extra(tmp_path: Path,
                                                  capsys: pytest.CaptureFixture[str],
                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "resvg_py", None)
    code, _, err = plot(tmp_path, capsys, "G1 X1 F100\nM2\n", out="out.png")
    assert code == 2
    assert "pip install 'ngc[png]'" in err
    assert not (tmp_path / "out.png").exists()


@pytest.mark.parametrize(("args", "message"), [
    (("-o", "x.pdf"), "must end in .svg or .png"),
    (("-o", "x.svg", "--size", "10x"), "WIDTHxHEIGHT"),
    (("-o", "x.svg", "--view", "bottom"), "invalid choice"),
])
def test_bad_command_lines(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                           args: tuple[str, ...], message: str) -> None:
    src = write(tmp_path, "p.ngc", "G1 X1 F100\nM2\n")
    try:
        code, _, err = run(capsys, "plot", src, *args)
    except SystemExit as exc:  # argparse's own errors
        code, err = int(exc.code or 0), capsys.readouterr().err
    assert code == 2
    assert message in err


def test_engine_programs_are_drawn_from_their_cubics(tmp_path: Path,
                                                     capsys: pytest.CaptureFixture[str]) -> None:
    src = write(tmp_path, "e.ngc", "(dialect: engine)\nF10\nfeed X2 Y1\nG2 X4 Y1 I1\n")
    code, _, err = run(capsys, "plot", src, "-o", str(tmp_path / "e.svg"))
    assert code == 0, err
    _, segments, _ = read_svg((tmp_path / "e.svg").read_text())
    assert {s.kind for s in segments} == {"M", "C"}
    assert max(s.end[0] for s in segments) == pytest.approx(4.0)
    code, _, err = run(capsys, "plot", src, "-o", str(tmp_path / "e.svg"), "--time")
    assert code == 2 and "engine dialect" in err
    code, _, err = run(capsys, "plot", src, "-o", str(tmp_path / "e.svg"), "-t", src)
    assert code == 2


def test_an_unreadable_program(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = run(capsys, "plot", str(tmp_path / "none.ngc"), "-o", str(tmp_path / "x.svg"))
    assert code == 2 and "none.ngc" in err


@pytest.mark.parametrize("view", ["top", "iso", "front"])
@pytest.mark.parametrize("program", [
    "#1=[EXP[690]]\nG0 X#1 Y[0-#1]\nG1 X0 F100\nM2\n",  # a path past a double's range
    "G1 X1 F100\n#1=[EXP[460]]\nG2 X1 Y0 I#1 J0 P3\nM2\n",  # an arc of radius 1e200
    "G1 X1 F100\nG0 X[EXP[700]]\nG0 X[0-EXP[700]]\nM2\n",
])
def test_numbers_past_a_doubles_range_draw_nothing_they_cannot(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], program: str, view: str) -> None:
    code, text, _ = plot(tmp_path, capsys, program, "--view", view)
    assert code == 0
    assert "nan" not in text and "inf" not in text
    read_svg(text)
