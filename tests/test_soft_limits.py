"""``ngc check -i``: the machine's soft limits ([AXIS_<letter>]/[JOINT_<n>] MIN_LIMIT, MAX_LIMIT)
against the program's moves in machine coordinates, as AXIS warns on load."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from cli_helpers import run, write

MILL = """[TRAJ]
COORDINATES = X Y Z
LINEAR_UNITS = mm
[AXIS_X]
MIN_LIMIT = -10
MAX_LIMIT = 100
[AXIS_Y]
MIN_LIMIT = -200
MAX_LIMIT = 10
[AXIS_Z]
MIN_LIMIT = -100
MAX_LIMIT = 0
[JOINT_0]
MAX_LIMIT = 90
"""


def check(tmp_path: Path, capsys: pytest.CaptureFixture[str], program: str, ini: str = MILL,
          *args: str) -> tuple[int, str, str]:
    ini_path = write(tmp_path, "mill.ini", ini)
    path = write(tmp_path, "p.ngc", program)
    return run(capsys, "check", "-j", "1", "-i", ini_path, *args, path)


def test_a_program_past_a_soft_limit_is_reported_and_fails(tmp_path: Path,
                                                           capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = check(tmp_path, capsys, "G21 G0 X500 Y-300 Z-5\nG1 X0 Y0 F100\nM2\n")
    assert code == 1
    assert "past the machine's soft limits" in out.splitlines()[0]
    # the joint's 90 is narrower than the axis's 100
    assert "Program exceeds machine maximum on axis X: 410.0000 mm past 90, first at line 1" in out
    assert "Program exceeds machine minimum on axis Y: 100.0000 mm past -200, first at line 1" in out
    assert "axis Z" not in out


def test_within_the_limits_is_ok(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = check(tmp_path, capsys, "G21 G0 X50 Y-50 Z-5\nG1 X0 Y0 F100\nM2\n")
    assert code == 0 and out.startswith(str(tmp_path / "p.ngc") + ": ok")


def test_an_arc_counts_with_its_extremes(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # ends at X 80 and X 80, the half circle about X 80 Y 0 bulges to X 95
    code, out, _ = check(tmp_path, capsys, "G21 G0 X80 Y-15 Z-1\nG3 X80 Y15 I0 J15 F100\nM2\n")
    assert code == 1
    assert "axis X: 5.0000 mm past 90, first at line 2" in out


def test_the_tool_length_offset_counts(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # rs274's sample table: T1 is 0.511 (inch, as its tool table is read) long: Z 0 is Z 12.98
    code, out, _ = check(tmp_path, capsys, "G21 T1 M6 G43 H1\nG0 Z0\nM2\n")
    assert code == 1
    assert "axis Z: 12.9794 mm past 0, first at line 2" in out


def test_an_inch_machine(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    ini = "[TRAJ]\nCOORDINATES = X Y Z\nLINEAR_UNITS = inch\n[AXIS_X]\nMAX_LIMIT = 10\n"
    code, out, _ = check(tmp_path, capsys, "G21 G0 X300\nM2\n", ini)  # 300 mm: 11.811 inch
    assert code == 1
    assert "axis X: 1.8110 inch past 10, first at line 1" in out


def test_json(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = check(tmp_path, capsys, "G21 G0 X500\nM2\n", MILL, "--format", "json")
    record = json.loads(out)
    assert code == 1 and record["ok"] is False
    assert record["soft_limits"] == [{"axis": "X", "side": "maximum", "limit": 90.0, "by": 410.0,
                                      "line": 1, "units": "mm"}]


def test_without_limits_nothing_is_said(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = check(tmp_path, capsys, "G21 G0 X500\nM2\n", "[TRAJ]\nCOORDINATES = X Y Z\n")
    assert code == 0 and "exceeds" not in out


SPEEDS = "MAX_VELOCITY = 50\nMAX_ACCELERATION = 500\n"
PAST = "G21 G0 X500 Y-300 Z-5\nG1 X0 Y0 F100\nM2\n"
PAST_TEXT = ["  Program exceeds machine maximum on axis X: 410.0000 mm past 90, first at line 1",
             "  Program exceeds machine minimum on axis Y: 100.0000 mm past -200, first at line 1"]


def test_time_holds_the_moves_against_the_travel(tmp_path: Path,
                                                 capsys: pytest.CaptureFixture[str]) -> None:
    ini = "".join(f"{line}\n{SPEEDS}" if line.startswith("[AXIS_") else f"{line}\n"
                  for line in MILL.splitlines())
    ini_path = write(tmp_path, "mill.ini", ini)
    path = write(tmp_path, "p.ngc", PAST)
    code, out, _ = run(capsys, "time", "-j", "1", "-i", ini_path, path)
    assert code == 1
    assert out.splitlines()[-2:] == PAST_TEXT
    assert "X 50 mm/s 500 mm/s^2 travel -10..90" in out
    code, out, _ = run(capsys, "time", "-j", "1", "--format", "json", "-i", ini_path, path)
    record = json.loads(out)
    assert code == 1 and [(e["axis"], e["side"], e["by"], e["line"])
                          for e in record["soft_limits"]] == [("X", "maximum", 410.0, 1),
                                                               ("Y", "minimum", 100.0, 1)]
    assert record["machine"]["axes"]["Z"]["travel"] == [-100.0, 0.0]
    ok = write(tmp_path, "ok.ngc", "G21 G0 X50 Y-50 Z-5\nM2\n")
    code, out, _ = run(capsys, "time", "-j", "1", "-i", ini_path, ok)
    assert code == 0 and "exceeds" not in out


def test_plot_draws_and_says_it_goes_past(tmp_path: Path,
                                          capsys: pytest.CaptureFixture[str]) -> None:
    ini_path = write(tmp_path, "mill.ini", MILL)  # (no speeds: plot does not time)
    path = write(tmp_path, "p.ngc", PAST)
    svg = str(tmp_path / "p.svg")
    code, _, err = run(capsys, "plot", "-i", ini_path, path, "-o", svg)
    assert code == 1 and Path(svg).stat().st_size > 0
    assert err.splitlines() == [f"ngc plot: {path}: {line.strip()}" for line in PAST_TEXT]


TRAVEL = """units = "mm"
[axes.X]
travel = [0, 300]
[axes.Z]
travel = [-150, 0]
"""


@pytest.mark.parametrize("command", ["check", "time", "plot"])
def test_the_toml_machines_travel(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                  command: str) -> None:
    toml = write(tmp_path, "m.toml", TRAVEL)
    path = write(tmp_path, "p.ngc", "G21 G0 X-5 Z10\nG1 X400 F1000\nM2\n")
    extra = ["-o", str(tmp_path / "p.svg")] if command == "plot" else []
    code, out, err = run(capsys, command, "--machine", toml, path, *extra)
    assert code == 1
    said = [line.strip() for line in (err if command == "plot" else out).splitlines()
            if "exceeds" in line]
    assert [line.split(": ", 2)[-1] if command == "plot" else line for line in said] == [
        "Program exceeds machine minimum on axis X: 5.0000 mm past 0, first at line 1",
        "Program exceeds machine maximum on axis X: 100.0000 mm past 300, first at line 2",
        "Program exceeds machine maximum on axis Z: 10.0000 mm past 0, first at line 1"]


@pytest.mark.parametrize(("travel", "message"), [
    ("[0]", "axes.X.travel must be [min, max], not [0]"),
    ("[5, 1]", "axes.X.travel: the minimum 5 is not below the maximum 1"),
    ('["a", 1]', "axes.X.travel"),
])
def test_a_bad_travel_is_refused(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                 travel: str, message: str) -> None:
    toml = write(tmp_path, "m.toml", f"[axes.X]\ntravel = {travel}\n")
    path = write(tmp_path, "p.ngc", "G0 X1\nM2\n")
    code, _, err = run(capsys, "check", "--machine", toml, path)
    assert code == 2 and message in err


FAST = """[TRAJ]
LINEAR_UNITS = mm
MAX_LINEAR_VELOCITY = 40
[AXIS_X]
MAX_VELOCITY = 30
[AXIS_Z]
MAX_VELOCITY = 5
"""


def test_feeds_past_max_velocity_are_noted(tmp_path: Path,
                                           capsys: pytest.CaptureFixture[str]) -> None:
    program = ("G21\nG1 X10 F1200\nG1 X20 Y10 F3000\nG1 Z-5 F600\nG2 X30 Y0 I5 J-5 F1200\n"
               "G20 G1 X2 F60\nM2\n")
    code, out, _ = check(tmp_path, capsys, program, FAST)
    assert code == 0  # a note: the machine runs them slower
    assert [line.strip() for line in out.splitlines() if "faster" in line] == [
        # line 3: 3000 mm/min along (10, 10): X at 50 / sqrt 2; line 6: F60 runs before G20 (1 mm/s)
        "Feed faster than the machine: axis X asked for up to 35.3553 mm/s, past its "
        "MAX_VELOCITY of 30 mm/s, first at line 3 (the machine runs those moves slower)",
        "Feed faster than the machine: axis Z asked for up to 10.0000 mm/s, past its "
        "MAX_VELOCITY of 5 mm/s, first at line 4 (the machine runs those moves slower)",
        "Feed faster than the machine: the path asked for up to 50.0000 mm/s, past its "
        "MAX_LINEAR_VELOCITY of 40 mm/s, first at line 3 (the machine runs those moves slower)"]
    code, out, _ = check(tmp_path, capsys, program, FAST, "--format", "json")
    assert [(f["axis"], round(f["asked"], 4), f["limit"], f["line"])
            for f in json.loads(out)["fast_feeds"]] == [
        ("X", 35.3553, 30.0, 3), ("Z", 10.0, 5.0, 4), ("path", 50.0, 40.0, 3)]


def test_an_arc_asks_its_planes_axes_for_the_whole_feed(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = check(tmp_path, capsys, "G21\nG2 X10 Y0 I5 J0 F2000\nM2\n", FAST)
    assert code == 0 and "axis X asked for up to 33.3333 mm/s" in out and "axis Z" not in out
