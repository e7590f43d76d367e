"""``ngc time`` on hostile input: machine settings at the ends of their ranges, coordinates and
times past anything a machine runs, moves of axes the machine does not have, TOML files no
reader should choke on, and a trajectory that would never end.  Each gives a result whose
times are finite, or a clear error with its exit code; none leaves a partial output file."""

from __future__ import annotations

import json
import math
import time
from pathlib import Path

import pytest

from cli_helpers import run, write
from ngc.errors import NgcError
from ngc.planner.geometry import blend_arc
from ngc.planner.lookahead import MAX_SECONDS
from ngc.planner.machine import DEFAULT_MACHINE, AxisLimits, Machine
from ngc.planner.moves import MAX_COORDINATE
from ngc.planner.timing import time_file, time_text
from ngc.planner.trajectory import DEFAULT_MAX_ROWS

NINES = "9" * 160


def finite_times(machine: Machine, text: str) -> float:
    result = time_text(text, machine)
    parts = [result.total_s, result.naive_s, *result.by_kind.values(),
             *result.by_tool.values(), *result.by_line.values()]
    assert all(math.isfinite(part) and part >= 0.0 for part in parts)
    return result.total_s


# -- the kink ratio: any value >= 0 --------------------------------------------------------------
@pytest.mark.parametrize("ratio", [0.0, 0.999, 1.0, 2.0, 614.0, 1e6])
@pytest.mark.parametrize("text", [
    "G18F100G2I5\nK5M2\n",  # a G18 circle and a helix
    "G0X30\nG0X3\nM2\n",  # a turn back
    "G61 G1 X10 F3000\nY10\nX0\nM2\n",  # exact-path corners
    "G64 G1 X10 F600\nX20 Y0.001\nX30 Y0.003\nM2\n",  # kinks
])
def test_any_kink_ratio_times_finitely(ratio: float, text: str) -> None:
    machine = Machine(arc_blend_kink_ratio=ratio)
    assert finite_times(machine, text) > 0.0


def test_a_kink_ratio_past_one_acts_as_the_largest_share(tmp_path: Path) -> None:
    text = "G64 G1 X10 F600\nX20 Y0.001\nX30 Y0.003\nG0X30\nG0X3\nM2\n"
    times = {ratio: time_text(text, Machine(arc_blend_kink_ratio=ratio)).total_s
             for ratio in (0.999, 1.0, 2.0, 614.0)}
    assert len(set(times.values())) == 1


# -- coordinates and times out of reach ----------------------------------------------------------
@pytest.mark.parametrize("text", [
    f"G1A{NINES}F1M2\n",
    f"G0X{NINES}M2\n",
    "G93G0X[EXP[709]]M2\n",
    "G0 X[10**10]\nM2\n",
    "G0 X-1000000001\nM2\n",
    "G2 X0 Y0 I[10**10] F100\nM2\n",  # a centre out of reach
    "G10 L2 P1 X[10**10]\nG0 X1\nM2\n",  # an offset takes the move out of reach
])
def test_a_move_out_of_reach_is_an_error(text: str) -> None:
    with pytest.raises(NgcError, match="too far to time") as caught:
        time_text(text)
    assert caught.value.line is not None


def test_a_move_within_reach_is_timed() -> None:
    assert finite_times(DEFAULT_MACHINE, f"G0 X{MAX_COORDINATE:.0f}\nG0 X-{MAX_COORDINATE:.0f}\n"
                        "M2\n") > 0.0


@pytest.mark.parametrize("text", [
    "G1 X1 F[10**-300]\nM2\n",
    "G4 P[10**300]\nG4 P[10**300]\nM2\n",
    "G4 P[10**12]\nG4 P1\nM2\n",
    "G1 X1000000000 F[10**-6]\nM2\n",
])
def test_a_run_too_long_to_time_is_an_error(text: str) -> None:
    with pytest.raises(NgcError, match="too long to time") as caught:
        time_text(text)
    assert caught.value.line is not None
    assert MAX_SECONDS == 1e12


def test_out_of_reach_on_the_command_line(capsys: pytest.CaptureFixture[str],
                                          tmp_path: Path) -> None:
    path = write(tmp_path, "p.ngc", f"G0X{NINES}M2\n")
    code, out, err = run(capsys, "time", "--format", "json", path)
    assert (code, out) == (1, "")
    assert err.startswith(f"{path}:1: ngc time: the move goes past 1e+09 machine units")


def test_a_failed_run_leaves_no_trajectory(capsys: pytest.CaptureFixture[str],
                                           tmp_path: Path) -> None:
    path = write(tmp_path, "p.ngc", "G1 X10 F600\nG93G0X[EXP[709]]M2\n")
    code, out, _ = run(capsys, "time", "--trajectory", str(tmp_path / "t.csv"), path)
    assert (code, out) == (1, "")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p.ngc"]


def test_the_trajectory_is_named_after_the_report(capsys: pytest.CaptureFixture[str],
                                                  tmp_path: Path,
                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    path = write(tmp_path, "p.ngc", "G1 X10 F600\nM2\n")

    def fail(*args: object) -> None:
        raise NgcError("the report failed")

    from ngc.commands import time_run

    monkeypatch.setattr(time_run, "_print_time", fail)
    code, _, _ = run(capsys, "time", "--trajectory", str(tmp_path / "t.csv"), path)
    assert code == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p.ngc"]


# -- axes the machine does not have --------------------------------------------------------------
Z_ONLY = Machine(axes={"Z": AxisLimits(100.0, 500.0)})


@pytest.mark.parametrize(("machine", "text", "axis", "line"), [
    (DEFAULT_MACHINE, "G0A5M2\n", "A", 1),
    (DEFAULT_MACHINE, "G1 X1 F100\nG91 G0 A90\nM2\n", "A", 2),
    (DEFAULT_MACHINE, "G1 X1 C1 F100\nM2\n", "C", 1),
    (DEFAULT_MACHINE, "G2 X1 Y0 R5 B3 F100\nM2\n", "B", 1),
    (Z_ONLY, "G0C7M2\n", "C", 1),
    (Z_ONLY, "G0 Z1\nG1 X1 F100\nM2\n", "X", 2),
    (Z_ONLY, "G2 I5 F100\nM2\n", "X", 1),  # a full circle in XY: its end is its start
    (Z_ONLY, "G64 P0.1 Q0.1 G1 Z1 F100\nZ2\nY1\nM2\n", "Y", 3),  # merged feeds
    (Machine(axes={"X": AxisLimits(1.0, 1.0)}), "G3 X0 Y0 J2 F100\nM2\n", "Y", 1),
])
def test_a_move_of_a_missing_axis_is_an_error(machine: Machine, text: str, axis: str,
                                              line: int) -> None:
    with pytest.raises(NgcError) as caught:
        time_text(text, machine)
    assert caught.value.line == line
    assert f"the machine has no {axis} axis" in caught.value.message


@pytest.mark.parametrize(("machine", "text"), [
    (DEFAULT_MACHINE, "G0 X1 A0\nM2\n"),  # A stays where it is
    (DEFAULT_MACHINE, "G10 L2 P1 A10\nG0 X1\nG92 A3\nG0 X2\nM2\n"),  # offsets do not move A
    (Z_ONLY, "G0 Z5\nG1 Z1 F100\nM2\n"),
    (Machine(axes={"X": AxisLimits(1.0, 1.0), "Z": AxisLimits(1.0, 1.0)}),
     "G18 G2 X2 Z0 I1 F100\nM2\n"),  # an XZ arc on a lathe
])
def test_a_move_that_leaves_missing_axes_alone_is_timed(machine: Machine, text: str) -> None:
    assert finite_times(machine, text) >= 0.0


def test_a_missing_axis_on_the_command_line(capsys: pytest.CaptureFixture[str],
                                            tmp_path: Path) -> None:
    ini = write(tmp_path, "u.ini", "[AXIS_U]\nMAX_VELOCITY=1\nMAX_ACCELERATION=1\n")
    path = write(tmp_path, "p.ngc", "G0A5M2\n")
    code, out, err = run(capsys, "time", "-i", ini, "--format", "json", path)
    assert (code, out) == (1, "")
    assert err == (f"{path}:1: ngc time: the move changes A, and the machine has no A axis "
                   "(its axes: U)\n")


def test_json_report_on_a_kink_ratio_of_two(capsys: pytest.CaptureFixture[str],
                                            tmp_path: Path) -> None:
    toml = write(tmp_path, "m.toml", "[blending]\nkink_ratio = 2\n")
    path = write(tmp_path, "p.ngc", "G18F100G2I5\nK5M2\n")
    code, out, err = run(capsys, "time", "--machine", toml, "--format", "json", path)
    assert (code, err) == (0, "")
    assert math.isfinite(json.loads(out)["total_s"])


# -- the trajectory's size -----------------------------------------------------------------------
DAY = "G1 X100000000 F6000\nG4 P1\nG4 P1\nM2 %\n"  # some 11.6 days of motion


def test_a_trajectory_past_the_row_limit_stops_at_once(capsys: pytest.CaptureFixture[str],
                                                       tmp_path: Path) -> None:
    path = write(tmp_path, "p.ngc", DAY)
    started = time.process_time()  # (CPU time: a busy machine does not make it slow)
    code, out, err = run(capsys, "time", "--trajectory", str(tmp_path / "t.csv"), path)
    assert time.process_time() - started < 30.0  # (it wrote rows for minutes)
    assert (code, out) == (2, "")
    assert err.startswith(f"ngc time: the trajectory would have more than {DEFAULT_MAX_ROWS} "
                          "rows (a row every 0.001 s up to ")
    assert err.endswith("s at least): give --every a larger spacing or --max-rows a larger "
                        "number\n")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p.ngc"]


@pytest.mark.parametrize(("text", "rows"), [
    ("G61.1 G1 X100 F6000\nM2\n", 1102),  # 1.1 s: 1100 rows, a last one, and the header
    ("G4 P0.5\nM2\n", 502),
])
def test_max_rows_bounds_the_rows(capsys: pytest.CaptureFixture[str], tmp_path: Path,
                                  text: str, rows: int) -> None:
    path = write(tmp_path, "p.ngc", text)
    csv = tmp_path / "t.csv"
    code, _, err = run(capsys, "time", "--trajectory", str(csv), "--max-rows", str(rows - 1),
                       path)
    assert (code, err) == (0, "")
    assert len(csv.read_text().splitlines()) == rows
    csv.unlink()
    code, out, err = run(capsys, "time", "--trajectory", str(csv), "--max-rows", str(rows - 2),
                         path)
    assert (code, out) == (2, "")
    assert f"more than {rows - 2} rows" in err
    assert not csv.exists()
    code, _, _ = run(capsys, "time", "--trajectory", str(csv), "--max-rows", str(rows - 2),
                     "--every", "0.01", path)
    assert code == 0


def test_max_rows_needs_a_trajectory(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    path = write(tmp_path, "p.ngc", "G0 X1\nM2\n")
    assert run(capsys, "time", "--max-rows", "5", path) == (
        2, "", "ngc time: --max-rows needs --trajectory\n")
    code, out, err = run(capsys, "time", "--trajectory", "t.csv", "--max-rows", "0", path)
    assert (code, out) == (2, "")
    assert "argument --max-rows: needs a positive number, not '0'" in err


# -- found by the soak ---------------------------------------------------------------------------
def test_a_line_never_takes_less_than_no_time() -> None:
    # a move after a parabolic blend ran alongside the move before for longer than it took
    # itself (by 3e-19 s): its line's time came out negative
    path = Path(__file__).resolve().parent / "timing" / "cases" / "19_engrave.ngc"
    result = time_file(str(path))
    assert min(seconds for _, seconds in result.by_line.items()) >= 0.0
    assert all(seg_time >= 0.0 for seg_time in result.by_kind.values())


@pytest.mark.parametrize("theta", [1e-9, 2e-9, 1e-8, 1e-6])
def test_a_blend_for_a_turn_too_slight_for_its_cosine(theta: float) -> None:
    # cos(θ/2) is 1.0 for θ below some 2e-8 rad: the tolerance's radius divided by zero
    blend = blend_arc(theta, 10.0, 1.0, 0.01, 500.0, 866.0)
    assert blend is not None and math.isfinite(blend.radius) and blend.radius > 0.0


@pytest.mark.parametrize("period", [0.1, 0.25, 1.0])
def test_a_stop_just_past_whole_servo_periods_keeps_the_moves_time(period: float) -> None:
    # Y at 1 unit/s and 1e9 units/s²: the move takes 1 s and 2 ns, a millionth of a period past
    # whole periods at most.  The stop was rounded down to the whole periods, so by_kind, by_tool
    # and by_line (the move's own 1.000000001 s) came to more than the total.
    machine = Machine(axes={"X": AxisLimits(1.0, 1e9), "Y": AxisLimits(1.0, 1e9)},
                      servo_period=period)
    result = time_text("G0 Y-1\nM2\n", machine)
    for parts in (result.by_kind, result.by_tool, dict(result.by_line.items())):
        assert math.fsum(parts.values()) <= result.total_s
    assert result.total_s == pytest.approx(1.0, abs=1e-6)


def test_arc_tolerance_at_a_join_that_does_not_turn(monkeypatch: pytest.MonkeyPatch) -> None:
    """An arc curving into a join whose tangents do not turn (theta 0, found by the lathe soak on
    a G7 G64 P0.01 job): the blend's tolerance stays as it is, not a division by zero."""
    from types import SimpleNamespace

    from ngc.planner import arcjoin

    arc = SimpleNamespace(sweep=0.5)
    monkeypatch.setattr(arcjoin, "arcs_at", lambda prev, seg: iter([(arc, True, True)]))
    prev = SimpleNamespace(tolerance=0.01)
    assert arcjoin.arc_tolerance(prev, prev, 0.0) == 0.01  # type: ignore[arg-type]
