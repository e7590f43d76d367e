"""The engine dialect (seed 003): names, clauses, the seed's examples, errors."""

from __future__ import annotations

import itertools
import math

import pytest

from ngc.engine import Dwell, EngineSegment, ModeChange, run
from ngc.engine.bezier import point
from ngc.engine.names import MOVE, code_of
from ngc.errors import NgcError


def segments(text: str) -> list[EngineSegment]:
    return [op for op in run(text) if isinstance(op, EngineSegment)]


def samples(segs: list[EngineSegment], per: int = 64) -> list[tuple[float, float]]:
    out = []
    for s in segs:
        for i in range(per + 1):
            t = i / per
            out.append((point(s.axes["X"], t), point(s.axes["Y"], t)))
    return out


@pytest.mark.parametrize(("words", "code"), [
    ("rapid", 0), ("rapidmoveto", 0), ("Rapid Move To", 0), ("RAPID move", 0),
    ("feed", 1), ("feedto", 1), ("Feed To", 1),
    ("circle cw", 2), ("helical motion clockwise", 2), ("circle clockwise", 2),
    ("circle ccw", 3), ("circle counter-clockwise", 3), ("helical counterclockwise", 3),
    ("dwell", 4), ("pause", 4), ("cancel polar", 15), ("set polar origin to", 16),
    ("xy", 17), ("use X-Y plane", 17), ("zx plane", 18), ("yz", 19),
    ("inch", 20), ("set metric units", 21), ("probe move to", 31), ("probeing", 31),
    ("apply tool length offset", 43), ("cancel tool", 49),
    ("fixture", 53), ("select default fixture 0", 53), ("fixture 1", 54), ("fixture6", 59),
    ("exact stop", 61), ("cancel exact stop mode", 64), ("constant velocity", 64),
    ("maintain motor momentum mode", 64), ("cancel coordinate rotation", 69),
    ("chip breaking drill", 73), ("cancel fixed cycles", 80), ("drill", 81),
    ("drill, dwell", 82), ("drill dwell", 82), ("chip clearing drill", 83),
    ("drill, feed out", 85), ("drill, dwell, spindle off, out", 86), ("drill dwell feed out", 89),
    ("abs", 90), ("set absolute coordinates mode", 90), ("incremental", 91),
    ("preset", 92), ("preload coordinates", 92), ("run", 100), ("rotate vectors", 101),
    ("set vector", 102), ("set polar center", 103), ("set polar axis", 104),
    ("set polar zero", 105), ("set drill vector", 107), ("set vector position", 108),
    ("move", MOVE),
])
def test_names(words: str, code: int) -> None:
    assert code_of(words) == code


@pytest.mark.parametrize("words", ["rapids", "feedtoo", "circle", "fixture 7", "set", "xyz"])
def test_not_names(words: str) -> None:
    assert code_of(words) is None


def test_oval_is_an_ellipse() -> None:
    segs = segments("move PZ 0 360 0.5 0 PZ 0 -360 0.25 0")
    assert len(segs) == 4
    # centred where the two arcs' centres add: (-0.75, 0); semi-axes 0.75 and 0.25
    worst = 0.0
    for x, y in samples(segs):
        a = math.atan2(y / 0.25, (x + 0.75) / 0.75)
        ex_, ey = -0.75 + 0.75 * math.cos(a), 0.25 * math.sin(a)
        # distance to the ellipse, bounded by the distance to the point at the same angle
        worst = max(worst, math.hypot(x - ex_, y - ey))
    assert worst < 3e-4
    end = segs[-1].axes
    assert abs(end["X"][3]) < 1e-9 and abs(end["Y"][3]) < 1e-9


def test_epicyclic_closes_in_44_segments() -> None:
    segs = segments("move PZ 0 360 0.5 0 PZ 0 3960 0.125 0")
    assert len(segs) == 44
    assert abs(segs[-1].axes["X"][3]) < 1e-9 and abs(segs[-1].axes["Y"][3]) < 1e-9
    # the segments join
    for a, b in itertools.pairwise(segs):
        assert a.axes["X"][3] == pytest.approx(b.axes["X"][0], abs=1e-12)


def test_external_loops_close() -> None:
    segs = segments("move PZ 0 360 0.5 0 PZ 0 -3960 0.18 0")
    assert len(segs) == 44
    assert abs(segs[-1].axes["X"][3]) < 1e-9 and abs(segs[-1].axes["Y"][3]) < 1e-9


def test_trim_pattern_advances_x_by_2() -> None:
    segs = segments("move PZ 0 3600 0.125 0 X 2")
    assert len(segs) == 40
    assert segs[-1].axes["X"][3] == pytest.approx(2.0, abs=1e-12)
    assert abs(segs[-1].axes["Y"][3]) < 1e-9


def test_arc_samples_lie_on_the_circle() -> None:
    segs = segments("move PZ 90 0 2 0")  # a quarter turn clockwise, radius 2 (2 segments)
    assert len(segs) == 2
    for x, y in samples(segs):
        assert abs(math.hypot(x, y + 2.0) - 2.0) < 1e-3


def test_constant_and_bezier_axes() -> None:
    (seg,) = segments("G90 rapid X 3 Y 1 2 3")
    assert seg.axes["X"] == pytest.approx((0.0, 1.0, 2.0, 3.0))
    assert seg.axes["Y"] == (0.0, 1.0, 2.0, 3.0)
    # duplicated references add; a constant speed adds a skew to a Bézier
    (seg,) = segments("G91 G0 X 1 X 0 0 3")
    assert seg.axes["X"] == pytest.approx((0.0, 1.0 / 3.0, 2.0 / 3.0, 4.0))


def test_incremental_and_absolute() -> None:
    segs = segments("G0 X1\nG91\nG0 X1\nG90\nG0 X1")
    assert [s.axes["X"][3] for s in segs] == [1.0, 2.0, 1.0]


def test_vectors_and_vector_position() -> None:
    segs = segments("G102 VX X 1 Y 1\nmove VX 2\nmove VX 3\nG108 VX 0\nmove VX 1")
    assert [(s.axes["X"][3], s.axes["Y"][3]) for s in segs] == [(2, 2), (3, 3), (4, 4)]


def test_rotate_vector() -> None:
    (seg,) = segments("G101 VZ 90 VX\nmove VX 1")
    assert seg.axes["Y"][3] == pytest.approx(1.0)
    assert seg.axes["X"][3] == pytest.approx(0.0, abs=1e-12)


def test_polar_point_needs_a_centre_then_goes_there() -> None:
    with pytest.raises(NgcError, match="PZ has no centre") as info:
        list(run("G0 X1\nmove PZ 90 1"))
    assert info.value.line == 2
    (seg,) = segments("G103 PZ 0 1\nmove PZ 90")  # centre at (-1, 0), radius 1 kept
    assert (seg.axes["X"][3], seg.axes["Y"][3]) == pytest.approx((-1.0, 1.0))


def test_helix_offset_along_the_normal() -> None:
    segs = segments("move PZ 0 720 1 4")
    assert len(segs) == 8
    assert segs[-1].axes["Z"][3] == pytest.approx(4.0)
    assert segs[3].axes["Z"][3] == pytest.approx(2.0)


def test_segment_counts_grow_with_radius() -> None:
    assert len(segments("move PZ 0 90 3 0")) == 3
    assert len(segments("move PZ 0 360 1 0")) == 4


def test_durations() -> None:
    (seg,) = segments("G21 G1 X 10 F 5")  # mm/s
    assert seg.duration == pytest.approx(2.0)
    (seg,) = segments("G20 G1 X 1 F 30")  # in/min
    assert seg.duration == pytest.approx(2.0)
    (seg,) = segments("G21 rapid X 50")  # 25 mm/s rapids
    assert seg.duration == pytest.approx(2.0)


def test_dwell_and_settings() -> None:
    ops = list(run("dwell P 2.5\npause 1\nG20\nG91\nG64\nG61"))
    assert ops[0] == Dwell(1, 2.5) and ops[1] == Dwell(2, 1.0)
    names = [op.name for op in ops if isinstance(op, ModeChange)]
    assert names == ["UNITS", "DISTANCE", "EXACT_STOP", "EXACT_STOP"]


def test_expressions_and_parameters() -> None:
    (seg,) = segments("#1 = 2\n#<r> = [#1 * 2]\nG0 X [#1 + 1], Y #<r>")
    assert (seg.axes["X"][3], seg.axes["Y"][3]) == (3.0, 4.0)


@pytest.mark.parametrize(("text", "message"), [
    ("frobnicate X1", "Unknown name 'frobnicate'"),
    ("G0 X 1 2", "X takes 1 or 3 expressions, not 2"),
    ("G0 VX 1 2 3 4", "VX takes 1 or 3 expressions, not 4"),
    ("G0 PZ 1 2 3 4 5", "PZ takes 1 to 4 expressions, not 5"),
    ("G1 X 1", "G1 \\(feed\\) with no feed rate"),
    ("G0 1 X2", "Expression '1' before any reference"),
    ("G2 X1 Y1 R1", "G2/G3 \\(circle\\) with no feed rate"),
    ("G999", "Unknown code G999"),
    ("G102 VQ X 1", "'VQ' is not a vector"),
    ("G104 PQ VX", "'PQ' is not a polar transform"),
])
def test_errors(text: str, message: str) -> None:
    with pytest.raises(NgcError, match=message) as info:
        list(run("G21\n" + text))
    assert info.value.line == 2


def test_cli_canon_engine(tmp_path, capsys) -> None:  # type: ignore[no-untyped-def]
    from ngc.cli import main

    prog = tmp_path / "oval.ngc"
    prog.write_text("(dialect: engine)\nmove PZ 0 360 0.5 0 PZ 0 -360 0.25 0\n")
    assert main(["canon", "--format", "json", str(prog)]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert len(lines) == 4 and all('"op": "ENGINE_SEGMENT"' in line for line in lines)
    plain = tmp_path / "plain.ngc"
    plain.write_text("rapid X 1\nfrobnicate\n")
    assert main(["canon", "--dialect", "engine", str(plain)]) == 1
    captured = capsys.readouterr()
    assert captured.out.startswith("ENGINE_SEGMENT(line=1, motion=rapid, duration=0.040000, X=[0.000000")
    assert "plain.ngc:2:1: Unknown name 'frobnicate'" in captured.err
