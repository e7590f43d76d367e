"""The engine dialect (seed 003): names, clauses, the seed's examples, errors."""

from __future__ import annotations

import itertools
import math

import pytest

from ngc.engine import Dwell, Engine, EngineSegment, ModeChange, Setup, run
from ngc.engine.bezier import point
from ngc.engine.names import MOVE, code_of
from ngc.engine.setup import Fixture
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
    ("G2 X1 Y1 R1", "G2 \\(circle cw\\) with no feed rate"),
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


# ---- the codes after the first part ------------------------------------------------------------

def ends(text: str, engine: Engine | None = None) -> list[dict[str, float]]:
    """Each segment's end point on the axes it names, rounded to 1e-9."""
    return [{a: round(c[3], 9) + 0.0 for a, c in s.axes.items()}
            for s in run(text, engine) if isinstance(s, EngineSegment)]


def test_circle_cw_and_ccw_stay_on_the_circle() -> None:
    segs = segments("F 10\nG2 X2 Y0 I1 J0")
    assert len(segs) == 2 and all(s.motion == "arc" for s in segs)
    assert segs[0].axes["Y"][3] == pytest.approx(1.0)  # clockwise from (0, 0) about (1, 0): up
    for x, y in samples(segs):
        assert abs(math.hypot(x - 1.0, y) - 1.0) < 3e-4
    assert (segs[-1].axes["X"][3], segs[-1].axes["Y"][3]) == (2.0, 0.0)
    segs = segments("F 10\nG3 X2 Y0 I1 J0")
    assert segs[0].axes["Y"][3] == pytest.approx(-1.0)
    # a half circle of radius 1 at 10 mm/s
    assert sum(s.duration for s in segs) == pytest.approx(math.pi / 10, rel=1e-3)


def test_circle_with_r_short_and_long() -> None:
    short = segments("F 10\nG2 X1 Y1 R1")
    assert len(short) == 1  # a quarter turn about (1, 0)
    for x, y in samples(short):
        assert abs(math.hypot(x - 1.0, y) - 1.0) < 3e-4
    long = segments("F 10\nG2 X1 Y1 R-1")
    assert len(long) == 3  # three quarters about (0, 1)
    for x, y in samples(long):
        assert abs(math.hypot(x, y - 1.0) - 1.0) < 3e-4


def test_full_circle_and_helix_in_other_planes() -> None:
    segs = segments("F 10\nG2 X0 Y0 I1 Z-1")
    assert len(segs) == 4 and segs[-1].axes["Z"][3] == -1.0
    assert segs[1].axes["Z"][3] == pytest.approx(-0.5)
    segs = segments("F 10\nG18\nG3 Z2 X0 K1")  # ZX plane: centre (Z 1, X 0)
    for s in segs:
        for i in range(65):
            z, x = point(s.axes["Z"], i / 64), point(s.axes["X"], i / 64)
            assert abs(math.hypot(z - 1.0, x) - 1.0) < 3e-4
    # counter-clockwise in (Z, X) as LinuxCNC's G18 (rs274: ARC_FEED(2, 0, 1, 0, 1, ...)): from
    # 180 degrees (Z 0) through 270 (X -1)
    assert segs[0].axes["X"][3] == pytest.approx(-1.0)


def test_circle_segments_grow_with_radius() -> None:
    assert len(segments("F 10\nG3 X-4 Y0 I-2")) == 4  # 180 degrees of radius 2


def test_polar_coordinates_g16() -> None:
    assert ends("G16 X0 Y0\nG0 X5 Y90\nmove Y180\nG91\nmove X1\nG15\nG90\nG0 X1 Y1") == [
        {"X": 0.0, "Y": 5.0}, {"X": -5.0, "Y": 0.0}, {"X": -6.0, "Y": 0.0}, {"X": 1.0, "Y": 1.0}]
    # the origin is where G16 names it, the current position elsewhere; a second G16 goes
    # through the polar translation first
    # origin (5, 4), to (5, 6); the new origin 1 at 180 degrees from the old: (4, 4)
    assert ends("G0 X3 Y4\nG16 X5\nG0 X2 Y90\nG16 X1 Y180\nG0 X1 Y0") == [
        {"X": 3.0, "Y": 4.0}, {"X": 5.0, "Y": 6.0}, {"X": 5.0, "Y": 4.0}]


def test_polar_coordinates_follow_the_plane() -> None:
    # ZX: the radius on Z, the angle on X
    (seg,) = segments("G18\nG16 Z0 X0\nG0 Z2 X90")
    assert seg.axes["X"][3] == pytest.approx(2.0) and seg.axes["Z"][3] == pytest.approx(0.0)


def test_probe_is_a_feed_and_sets_probe_stop() -> None:
    ops = list(run("F 5\nG31 X1\n#1 = [#<__probe_stop> + 7]\nG0 X#1"))
    segs = [op for op in ops if isinstance(op, EngineSegment)]
    assert segs[0].motion == "probe" and segs[0].duration == pytest.approx(0.2)
    assert segs[1].axes["X"][3] == 7.0


SETUP = Setup(
    fixtures=(Fixture(),
              Fixture(offsets=(10.0, 20.0, 0.0, 0, 0, 0, 0, 0, 0)),
              Fixture(offsets=(0.0, 0.0, 5.0, 0, 0, 0, 0, 0, 0), tool_axis=(0, -1.0)),
              *(Fixture(),) * 4),
    tool=3, lengths={3: 25.0})


def test_fixtures_and_tool_length() -> None:
    program = "G0 X1\nG54\nG0 X1\nG43\nG0 Z0\nG55\nG0 X0 Z0\nG49\nG0 X0\nG53\nG0 X0 Y0 Z0"
    assert ends(program, Engine(setup=SETUP)) == [
        {"X": 1.0},
        {"X": 11.0},                     # G54: X + 10 (Y not named: stays)
        {"Z": 25.0},                     # G43: the tool along Z
        {"X": -25.0, "Z": 5.0},          # G55: its tool axis is -X
        {"X": 0.0},                      # G49
        {"X": 0.0, "Y": 0.0, "Z": 0.0}]  # G53: fixture 0


def test_g43_needs_a_selected_tool_with_a_length() -> None:
    with pytest.raises(NgcError, match="the machine setup selects no tool") as info:
        list(run("G0 X1\nG43"))
    assert info.value.line == 2
    with pytest.raises(NgcError, match="gives tool 3 no length"):
        list(run("G43", Engine(setup=Setup(tool=3))))


def test_preset_keeps_the_fixture() -> None:
    ops = list(run("G54\nG0 X1\nG92 X0\nG0 X1", Engine(setup=SETUP)))
    preset = [op for op in ops if isinstance(op, ModeChange) and op.name == "SET_POSITION"]
    assert preset[0].value["X"] == 10.0  # type: ignore[index]  # machine X reads program X 0
    assert ends("G54\nG0 X1\nG92 X0\nG0 X1", Engine(setup=SETUP))[-1]["X"] == 11.0


def test_exact_stop_after_each_command() -> None:
    ops = list(run("G61\nG0 X1\nF 10\nG1 X2\nG2 X4 I1\nG64\nG0 X0"))
    kinds = [type(op).__name__ for op in ops if not isinstance(op, ModeChange)]
    assert kinds == ["EngineSegment", "Stop", "EngineSegment", "Stop",
                     "EngineSegment", "EngineSegment", "Stop", "EngineSegment"]


def test_drill_cycle_along_the_drill_vector() -> None:
    ops = list(run("F 10\nG0 Z5\nG81 X1 Y2 Z-3 R1\nG81 X4"))
    segs = [op for op in ops if isinstance(op, EngineSegment)]
    path = [(s.motion, {a: s.axes[a][3] for a in s.axes}) for s in segs[1:]]
    assert path == [
        ("rapid", {"X": 1.0, "Y": 2.0}), ("rapid", {"Z": 1.0}),
        ("feed", {"Z": -3.0}), ("rapid", {"Z": 1.0}),
        ("rapid", {"X": 4.0}), ("feed", {"Z": -3.0}), ("rapid", {"Z": 1.0})]
    # along X: the hole's bottom is the X named; across it, Y and Z
    segs = segments("F 10\nG107 VX\nG81 X-2 Y1 Z1 R0.5")
    assert [{a: s.axes[a][3] for a in s.axes} for s in segs] == [
        {"X": 0.5}, {"Y": 1.0, "Z": 1.0}, {"X": -2.0}, {"X": 0.5}]


def test_peck_and_dwell_cycles() -> None:
    ops = list(run("F 10\nG83 X0 Y0 Z-2 R0 Q1\nG80\nG82 X1 Z-1 R0 P0.5"))
    zs = [(op.motion, op.axes["Z"][3]) for op in ops
          if isinstance(op, EngineSegment) and "Z" in op.axes]
    assert zs[:5] == [("feed", -1.0), ("rapid", 0.0), ("rapid", pytest.approx(-0.746)),
                      ("feed", -2.0), ("rapid", 0.0)]
    assert Dwell(4, 0.5) in ops


def test_run_axes_move_on_until_positioned() -> None:
    ops = list(run("G100 X50\nG0 Y5\nG4 P1\nG0 X0"))
    segs = [op for op in ops if isinstance(op, EngineSegment)]
    assert segs[0].axes["X"] == pytest.approx((0.0, 0.8333333, 1.6666667, 2.5))  # 12.5 mm/s
    assert segs[1].motion == "run" and segs[1].axes["X"][3] == pytest.approx(15.0)
    assert segs[2].axes["X"][0] == pytest.approx(15.0)
    runs = [op.value for op in ops if isinstance(op, ModeChange) and op.name == "RUN"]
    assert runs == [{"X": 50.0}, {}]


def test_inches() -> None:
    # G20: positions in inches, feed in inches per minute; kept in mm inside
    (seg,) = segments("G20\nF 60\nG1 X2")
    assert seg.axes["X"][3] == 2.0 and seg.duration == pytest.approx(2.0)
    (a, b) = segments("G20\nG0 X1\nG21\nG0 Y1")
    assert b.axes["Y"][3] == 1.0 and "X" not in b.axes
    assert a.duration == pytest.approx(25.4 / 25.0)


@pytest.mark.parametrize(("text", "message"), [
    ("F 1\nG2 X1 Y1", "G2 \\(circle cw\\) needs the centre \\(I J K\\) or the radius \\(R\\)"),
    ("F 1\nG3 X1 I1 R1", "G3 \\(circle ccw\\) takes I J K or R, not both"),
    ("F 1\nG2 X1 K1", "K is not a centre offset in the XY plane \\(I J\\)"),
    ("F 1\nG2 X3 I1", "Radius to end of arc differs from radius to start"),
    ("F 1\nG2 X3 R1", "Arc radius too small to reach end point"),
    ("F 1\nG2 I0", "Zero-radius arc"),
    ("F 1\nG2 X1 Q1 I1", "Q is not a word of G2 \\(circle cw\\)"),
    ("F 1\nG2 X1 2 I1", "X takes 1 expression in G2 \\(circle cw\\), not 2"),
    ("G16 A1", "G16 \\(set polar origin\\) takes X Y Z each with one value, not A"),
    ("G16\nG0 X1 2 3", "X takes 1 expression in polar coordinates \\(G16\\), not 3"),
    ("G81 X1 Z-1", "G81 \\(drill\\) needs R \\(the retract level\\)"),
    ("G81 X1 R1", "G81 \\(drill\\) needs the bottom of the hole"),
    ("G81 X1 Z2 R1", "G81 \\(drill\\): the bottom of the hole is above R"),
    ("G83 X1 Z-1 R1", "G83 \\(chip clearing drill\\) needs Q \\(the peck\\)"),
    ("G73 X1 Z-1 R1 Q-1", "G73 \\(chip breaking drill\\): Q \\(the peck\\) must be positive"),
    ("G82 X1 Z-1 R1", "G82 \\(drill, dwell\\) needs P \\(the dwell\\)"),
    ("G81 X1 Z-1 R1", "G81 \\(drill\\) with no feed rate"),
    ("G81 X1 Z-1 R1 I2", "I is not a word of G81 \\(drill\\)"),
    ("G100 X150", "G100 \\(run\\): X at 150% is over its maximum speed"),
    ("G100 VX 10", "G100 \\(run\\) takes axes each with one value, not VX"),
    ("G4 P-1", "G4 \\(dwell\\): the time must not be negative"),
    ("G4 P[EXP[709.78]]", "G4 \\(dwell\\) lasts more than 1e\\+18 s: too long to run"),
    ("G4 P2000000000000000000", "G4 \\(dwell\\) lasts more than 1e\\+18 s: too long to run"),
    ("G82 X1 Z-1 R1 P10000000000000000000 F1",
     "G82 \\(drill, dwell\\): P \\(the dwell\\) lasts more than 1e\\+18 s: too long to run"),
    ("F0.000001\nG1 X10000000000000", "The move lasts more than 1e\\+18 s: too long to run"),
    ("G92 PZ 1", "G92 \\(preset\\) takes axes each with one value, not PZ"),
    ("G54 X1", "G54 takes no arguments, not 'X 1'"),
    ("G43 H1", "G43 \\(apply tool length offset\\) takes no arguments"),
    ("G0 R1", "R is not a reference of G0"),
    ("F -1", "Negative feed rate F -1"),
])
def test_more_errors(text: str, message: str) -> None:
    lines = text.count("\n") + 2
    with pytest.raises(NgcError, match=message) as info:
        list(run("G21\n" + text))
    assert info.value.line == lines


@pytest.mark.parametrize(("sheet", "message"), [
    ("frob = 1", "unknown key 'frob' \\(tool, tools, fixtures, axes\\)"),
    ("tool = 1.5", "tool must be a whole number, not 1.5"),
    ("[tools.1]\nlen = 2", "tools.1: unknown key 'len' \\(length\\)"),
    ("[tools.x]\nlength = 2", "tools: 'x' is not a number"),
    ("[tools.1]\nlength = 'a'", "tools.1.length must be a number, not 'a'"),
    ("[fixtures.9]\nX = 1", "fixtures: there is no fixture 9 \\(0 to 6\\)"),
    ("[fixtures.1]\nQ = 1", "fixtures.1: unknown key 'Q' \\(X ... W, tool_axis\\)"),
    ("[fixtures.1]\ntool_axis = 'VZ'", "fixtures.1.tool_axis must be an axis letter"),
    ("[axes.Q]\nmax_speed = 1", "axes: 'Q' is not an axis"),
    ("[axes.X]\nmax_speed = 0", "axes.X.max_speed must be a number from 0.000001 to 1000000, "
                                "not 0"),
    ("[axes.X]\nmax_speed = 5e-324", "axes.X.max_speed must be a number from 0.000001 to "),
    ("[axes.A]\nmax_speed = inf", "axes.A.max_speed must be a number from .* not inf"),
    ("[fixtures.1]\nX = nan", "fixtures.1.X must be a number from -1000000000 to 1000000000, "
                              "not nan"),
    ("[fixtures.0]\nZ = 1e300", "fixtures.0.Z must be a number from -1000000000 to "),
    ("[tools.1]\nlength = -1.7976931348623157e308", "tools.1.length must be a number from "),
    ("fixtures = 3", "fixtures must be a table"),
    ("tool = [", "setup file .*: "),
])
def test_setup_sheet_errors(tmp_path, sheet: str, message: str) -> None:  # type: ignore[no-untyped-def]
    from ngc.engine import read_setup
    from ngc.errors import NgcConfigError

    path = tmp_path / "machine.toml"
    path.write_text(sheet + "\n")
    with pytest.raises(NgcConfigError, match=message):
        read_setup(str(path))


def test_setup_sheet_read(tmp_path) -> None:  # type: ignore[no-untyped-def]
    from ngc.engine import read_setup

    path = tmp_path / "machine.toml"
    path.write_text("tool = 2\n[tools.2]\nlength = 4\n[fixtures.6]\nY = -1\ntool_axis = '-x'\n"
                    "[axes.A]\nmax_speed = 90\n")
    setup = read_setup(str(path))
    assert setup.tool == 2 and setup.lengths == {2: 4.0}
    assert setup.fixtures[6].offsets[1] == -1.0 and setup.fixtures[6].tool_axis == (0, -1.0)
    assert setup.max_speed[3] == 90.0 and setup.max_speed[0] == 25.0
    ops = list(run("G59\nG43\nG0 X0", Engine(setup=setup)))
    assert ops[-1].axes["X"][3] == -4.0  # type: ignore[union-attr]
