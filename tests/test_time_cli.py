"""``ngc time``: the text and JSON reports, the machine inputs and their errors, program errors,
standard input, the engine dialect refused, and the ``--trajectory`` CSV file; the trajectory
sampler and the timer's listeners underneath.

The checks are relative (sums, bounds, continuity) so that they hold however the planner's
accuracy is tuned; the one absolute time is a single exact-stop move, a trapezoid by hand."""

from __future__ import annotations

import csv
import doctest
import itertools
import json
import math
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from cli_helpers import run, write
from ngc.commands import time_report
from ngc.planner import timing, trajectory
from ngc.planner.geometry import Line
from ngc.planner.machine import DEFAULT_MACHINE
from ngc.planner.segment import Segment
from ngc.planner.timing import time_file, time_lines
from ngc.planner.trajectory import Profile, TrajectoryWriter, sample
from test_progress import on_terminal, painted_and_erased

SRC = Path(__file__).resolve().parent.parent / "src"

# 100 mm at 100 mm/s with 1000 mm/s² up and down: 0.1 + 0.9 + 0.1 s.
SINGLE = "G61.1 G1 X100 F6000\nM2\n"
SINGLE_S = 1.1
# Rapids, feeds, arcs, a dwell, corners blended in G64: between lines, and between a line and an
# arc at a right angle (a join where the next move may start before the one before has ended).
MIXED = ("G21 G64\nG0 X10 Y5 Z2\nG1 Z-1 F300\nG1 X20 F3000\nG2 X30 Y5 R5\nG1 Y30\nX0\n"
         "G4 P1.5\nG2 X-10 Y20 I0 J-10\nG1 Y0\nX10 Y5\nG0 Z5\nM2\n")
# The same path in exact-path mode (G61): no move runs alongside another, each ends before the
# next starts, so the times by kind, by tool and by line add up to the total, but for the rounding
# of each stop to whole servo cycles.
EXACT_PATH = MIXED.replace("G64", "G61")
DWELL_LINE = 8
DWELL_S = 1.5
MIXED_END = {"x": 10.0, "y": 5.0, "z": 5.0}
TOOL_CHANGE = "G21 G61\nG1 X10 F600\nT1 M6\nG1 X20\nT2 M6\nG1 X30\nM2\n"
BAD = "G21 F100\nG1 X1\nG2 X2 R0.1\nM2\n"
SPEED_BOUND = math.hypot(200.0, 200.0, 100.0)  # the default machine's X, Y, Z at full speed
PERIOD = DEFAULT_MACHINE.servo_period


def program(tmp_path: Path, text: str, name: str = "prog.ngc") -> str:
    path = tmp_path / name
    path.write_text(text)
    return str(path)


def timed(capsys: pytest.CaptureFixture[str], *argv: str) -> dict[str, object]:
    code, out, err = run(capsys, "time", "--format", "json", *argv)
    assert (code, err) == (0, "")
    assert out.count("\n") == 1
    record = json.loads(out)
    assert isinstance(record, dict)
    return record


def seconds(record: dict[str, object], key: str) -> dict[str, float]:
    value = record[key]
    assert isinstance(value, dict)
    return value


def rows(path: Path) -> list[dict[str, float]]:
    with path.open(newline="") as handle:
        return [{key: float(value) for key, value in row.items()}
                for row in csv.DictReader(handle)]


# -- the text report ------------------------------------------------------------------------------
def test_text_report(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    path = program(tmp_path, SINGLE)
    code, out, err = run(capsys, "time", path)
    assert (code, err) == (0, "")
    lines = out.splitlines()
    found = re.fullmatch(r".*prog\.ngc: 0:00:0(\d\.\d{3}) \((\d+\.\d{3}) s\)", lines[0])
    assert found is not None
    assert float(found[1]) == float(found[2]) == pytest.approx(SINGLE_S, abs=0.002)
    assert lines[1].startswith("  naive (distance / feed): 0:00:01.000 (1.000 s), planned / naive:")
    assert lines[2].startswith("  by kind: feed ")
    assert lines[3].startswith("  by tool: T0 ")
    assert lines[4] == "  motion: 1 segments, path length 100.000 mm"
    assert lines[5] == "  machine: mm, servo period 0.001 s"
    assert lines[6] == "  axes: X 200 mm/s 1000 mm/s^2, Y 200 mm/s 1000 mm/s^2, Z 100 mm/s 500 mm/s^2"
    assert lines[7] == "  slowest lines:"
    assert re.fullmatch(r"    line 1 +1\.\d{3} s  G61\.1 G1 X100 F6000", lines[8])
    assert len(lines) == 9  # M2 takes no time


def test_top_limits_the_slowest_lines(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    path = program(tmp_path, MIXED)
    _, out, _ = run(capsys, "time", "--top", "3", path)
    listed = [line for line in out.splitlines() if line.startswith("    line ")]
    assert len(listed) == 3
    assert f"line {DWELL_LINE}" in listed[0]  # the dwell is the slowest line
    assert listed[0].endswith("G4 P1.5")
    _, out, _ = run(capsys, "time", "--top", "0", path)
    assert "slowest lines" not in out


# -- JSON -----------------------------------------------------------------------------------------
def test_json_shape(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    record = timed(capsys, program(tmp_path, MIXED))
    assert {"file", "total_s", "naive_s", "ratio", "by_kind", "by_tool", "by_line",
            "slowest_lines", "segments", "length", "units", "machine"} <= set(record)
    total = record["total_s"]
    assert isinstance(total, float) and total > 0.0
    by_kind, by_line = seconds(record, "by_kind"), seconds(record, "by_line")
    assert set(by_kind) == {"rapid", "feed", "arc", "dwell"}
    assert set(seconds(record, "by_tool")) == {"T0"}
    assert all(key.isdigit() for key in by_line)
    assert set(by_line) <= {str(n) for n in range(1, MIXED.count("\n") + 1)}
    assert DWELL_S <= by_kind["dwell"] <= DWELL_S + 0.01
    assert by_line[str(DWELL_LINE)] == by_kind["dwell"]
    assert record["ratio"] == pytest.approx(total / record["naive_s"], abs=1e-5)  # type: ignore[operator]
    assert record["segments"] >= 10  # type: ignore[operator]
    assert record["units"] == "mm"
    machine = seconds(record, "machine")
    assert machine["servo_period"] == PERIOD
    assert machine["axes"] == {  # type: ignore[comparison-overlap]
        "X": {"max_velocity": 200.0, "max_acceleration": 1000.0},
        "Y": {"max_velocity": 200.0, "max_acceleration": 1000.0},
        "Z": {"max_velocity": 100.0, "max_acceleration": 500.0}}
    slowest = record["slowest_lines"]
    assert isinstance(slowest, list) and len(slowest) == 10
    assert slowest[0] == {"line": DWELL_LINE, "s": by_kind["dwell"], "source": "G4 P1.5"}


def test_the_parts_add_up_to_the_total(capsys: pytest.CaptureFixture[str],
                                       tmp_path: Path) -> None:
    record = timed(capsys, program(tmp_path, EXACT_PATH))
    total = record["total_s"]
    segments = record["segments"]
    assert isinstance(total, float) and isinstance(segments, int)
    for key in ("by_kind", "by_tool", "by_line"):
        parts = sum(seconds(record, key).values())
        assert total - (segments + 1) * PERIOD <= parts <= total + 1e-5, key


def test_json_numbers_are_rounded(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    record = timed(capsys, program(tmp_path, MIXED))
    for value in [record["total_s"], record["length"], *seconds(record, "by_line").values()]:
        assert isinstance(value, float)
        assert round(value, 6) == value


def test_single_move_time(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    record = timed(capsys, program(tmp_path, SINGLE))
    assert record["total_s"] == pytest.approx(SINGLE_S, abs=0.002)
    assert record["naive_s"] == pytest.approx(1.0)
    assert record["length"] == pytest.approx(100.0)
    assert seconds(record, "by_line") == {"1": pytest.approx(SINGLE_S, abs=0.002)}


def test_a_dwell_alone(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    record = timed(capsys, program(tmp_path, "G4 P2.5\nM2\n"))
    assert seconds(record, "by_kind") == {"dwell": pytest.approx(2.5, abs=0.01)}
    assert record["total_s"] == seconds(record, "by_kind")["dwell"]
    assert record["segments"] == 0


def test_tool_changes_from_the_machine_file(capsys: pytest.CaptureFixture[str],
                                            tmp_path: Path) -> None:
    machine = tmp_path / "machine.toml"
    machine.write_text("tool_change_time = 6.0\n")
    path = program(tmp_path, TOOL_CHANGE)
    plain = timed(capsys, path)
    record = timed(capsys, "--machine", str(machine), path)
    by_kind, by_tool = seconds(record, "by_kind"), seconds(record, "by_tool")
    assert by_kind["tool change"] == pytest.approx(12.0)
    assert "tool change" not in seconds(plain, "by_kind")
    assert record["total_s"] == pytest.approx(plain["total_s"] + 12.0, abs=0.01)  # type: ignore[operator]
    assert set(by_tool) == {"T0", "T1", "T2"}
    assert sum(by_tool.values()) == pytest.approx(record["total_s"], abs=0.01)
    # a change counts for the tool it puts in: T2's time is its move and its change
    assert by_tool["T2"] == pytest.approx(seconds(plain, "by_tool")["T2"] + 6.0)
    assert seconds(record, "machine")["tool_change_time"] == 6.0
    code, out, _ = run(capsys, "time", "--machine", str(machine), path)
    assert code == 0 and "tool change 12.000 s" in out and "tool change 6 s" in out


def test_the_ini_file_gives_the_machine(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    ini = tmp_path / "mill.ini"
    ini.write_text("[TRAJ]\nCOORDINATES = X Y Z\n[EMCMOT]\nSERVO_PERIOD = 500000\n"
                   "[AXIS_X]\nMAX_VELOCITY = 50\nMAX_ACCELERATION = 500\n"
                   "[AXIS_Y]\nMAX_VELOCITY = 50\nMAX_ACCELERATION = 500\n"
                   "[AXIS_Z]\nMAX_VELOCITY = 20\nMAX_ACCELERATION = 200\n")
    path = program(tmp_path, "G61.1 G1 X100 F#<_ini[axis_x]max_velocity>\nM2\n")
    record = timed(capsys, "-i", str(ini), path)
    machine = seconds(record, "machine")
    assert machine["servo_period"] == 0.0005
    assert machine["axes"]["X"] == {"max_velocity": 50.0, "max_acceleration": 500.0}  # type: ignore[index]
    # F50 is 50 mm/min (the INI parameter reached the interpreter): 120 s, nearly all cruise
    assert record["naive_s"] == pytest.approx(120.0)
    assert 120.0 <= record["total_s"] <= 120.01  # type: ignore[operator]


# -- errors ---------------------------------------------------------------------------------------
def test_machine_file_errors(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    path = program(tmp_path, SINGLE)
    code, out, err = run(capsys, "time", "--machine", str(tmp_path / "none.toml"), path)
    assert (code, out) == (2, "")
    assert err.startswith("ngc time: cannot open machine file ") and "none.toml" in err
    bad = tmp_path / "bad.toml"
    bad.write_text("tool_change_time = -1\n")
    code, out, err = run(capsys, "time", "--machine", str(bad), path)
    assert (code, out) == (2, "")
    assert "tool_change_time must be a number from 0 to 1000000, not -1" in err
    code, out, err = run(capsys, "time", "--machine", str(tmp_path), path)
    assert (code, out) == (2, "")
    assert "is not a regular file" in err


def test_a_program_error_prints_no_time(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    path = program(tmp_path, BAD, "bad.ngc")
    out_csv = tmp_path / "out.csv"
    out_csv.write_text("kept\n")
    for argv in (["time", path], ["time", "--format", "json", path],
                 ["time", "--trajectory", str(out_csv), path]):
        code, out, err = run(capsys, *argv)
        assert (code, out) == (1, "")
        assert err.splitlines()[0] == f"{path}:3: Arc radius too small to reach end point"
    assert out_csv.read_text() == "kept\n"  # the file named is replaced only by a good run
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.ngc", "out.csv"]


def test_usage_errors(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    path = program(tmp_path, SINGLE)
    code, out, err = run(capsys, "time", "--every", "0.01", path)
    assert (code, out, err) == (2, "", "ngc time: --every needs --trajectory\n")
    for argv in (["--every", "0"], ["--every", "-1"], ["--every", "nan"], ["--top", "-1"],
                 ["--format", "xml"]):
        code, out, _ = run(capsys, "time", *argv, "--trajectory", str(tmp_path / "t.csv"), path)
        assert (code, out) == (2, "")
    code, _, err = run(capsys, "time", str(tmp_path / "none.ngc"))
    assert code == 2 and err.startswith("ngc time: cannot open ")
    code, _, err = run(capsys, "time", "--trajectory", str(tmp_path / "no" / "t.csv"), path)
    assert code == 2 and err.startswith("ngc time: cannot write ")
    assert not (tmp_path / "t.csv").exists()


@pytest.mark.parametrize("how", ["first line", "option"])
def test_the_engine_dialect_is_refused(capsys: pytest.CaptureFixture[str], tmp_path: Path,
                                       how: str) -> None:
    text = "(dialect: engine)\n" if how == "first line" else ""
    path = program(tmp_path, text + "move PZ 0 360 0.5 0\n")
    argv = ["--dialect", "engine"] if how == "option" else []
    code, out, err = run(capsys, "time", *argv, path)
    assert (code, out) == (2, "")
    assert "ngc time runs LinuxCNC programs" in err


def test_standard_input(tmp_path: Path) -> None:
    environ = {**os.environ, "PYTHONPATH": str(SRC)}
    done = subprocess.run([sys.executable, "-m", "ngc", "time", "--format", "json", "-"],
                          input=SINGLE.encode(), capture_output=True, env=environ, cwd=tmp_path,
                          timeout=60, check=False)
    assert (done.returncode, done.stderr) == (0, b"")
    record = json.loads(done.stdout)
    assert record["file"] == "<stdin>"
    assert record["total_s"] == pytest.approx(SINGLE_S, abs=0.002)
    assert record["slowest_lines"][0]["source"] is None  # standard input is not read twice


def test_progress_on_a_terminal(tmp_path: Path) -> None:
    path = tmp_path / "big.ngc"
    body = "".join(f"G1 X{i % 97} Y{i % 89}\n" for i in range(60_000))
    path.write_text("G21 F6000\n" + body + "M2\n")
    code, out, terminal = on_terminal(["time", "--top", "1", str(path)])
    assert code == 0
    painted_and_erased(terminal)
    assert f"{path}: ".encode() in terminal
    assert out.startswith(f"{path}: ".encode())


def test_ctrl_c_ends_cleanly(tmp_path: Path) -> None:
    path = tmp_path / "huge.ngc"
    path.write_text("G21 F100\n" + "G1 X1 Y2\nG1 X2 Y1\n" * 500_000 + "M2\n")
    out_csv = tmp_path / "out.csv"
    argv = ["time", "--trajectory", str(out_csv), "--every", "10", str(path)]
    code, out, terminal = on_terminal(argv, interrupt=True)
    assert (code, out) == (130, b"")
    assert b"Traceback" not in terminal and terminal.endswith(b"\r\x1b[K")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["huge.ngc"]  # no file half written


# -- the trajectory -------------------------------------------------------------------------------
def test_trajectory_of_a_single_move(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    out_csv = tmp_path / "out.csv"
    record = timed(capsys, "--trajectory", str(out_csv), program(tmp_path, SINGLE))
    assert out_csv.read_text().splitlines()[0] == "t,x,y,z,velocity,line"
    table = rows(out_csv)
    times = [row["t"] for row in table]
    assert times[0] == 0.0 and times[-1] == record["total_s"]
    steps = [b - a for a, b in itertools.pairwise(times)]
    assert all(step == pytest.approx(PERIOD, abs=1e-6) for step in steps[:-1])
    assert 0.0 < steps[-1] <= PERIOD + 1e-6
    assert table[-1]["x"] == 100.0 and table[-1]["velocity"] == 0.0
    assert max(row["velocity"] for row in table) == pytest.approx(100.0)
    assert {row["line"] for row in table} == {1.0}
    xs = [row["x"] for row in table]
    assert xs == sorted(xs)


def test_trajectory_of_a_program(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    out_csv = tmp_path / "out.csv"
    record = timed(capsys, "--trajectory", str(out_csv), program(tmp_path, MIXED))
    table = rows(out_csv)
    assert table[-1]["t"] == record["total_s"]
    assert {axis: table[-1][axis] for axis in "xyz"} == MIXED_END
    for before, after in itertools.pairwise(table):
        step = after["t"] - before["t"]
        assert step > 0.0
        moved = math.dist([before[a] for a in "xyz"], [after[a] for a in "xyz"])
        assert moved <= SPEED_BOUND * step + 2e-6  # continuous, at segment boundaries too
        assert 0.0 <= after["velocity"] <= SPEED_BOUND
    dwell = [row for row in table if row["line"] == DWELL_LINE]
    assert len(dwell) == pytest.approx(DWELL_S / PERIOD, abs=15)
    assert all(row["velocity"] == 0.0 for row in dwell)
    assert len({(row["x"], row["y"], row["z"]) for row in dwell}) == 1


def test_trajectory_sample_spacing(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    out_csv = tmp_path / "out.csv"
    record = timed(capsys, "--trajectory", str(out_csv), "--every", "0.05",
                   program(tmp_path, MIXED))
    times = [row["t"] for row in rows(out_csv)]
    assert times[:-1] == [round(0.05 * k, 6) for k in range(len(times) - 1)]
    assert times[-1] == record["total_s"]
    assert len(times) == math.ceil(record["total_s"] / 0.05) + 1


def test_trajectory_rotary_columns(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    machine = tmp_path / "machine.toml"
    machine.write_text("[axes.A]\nmax_velocity = 360\nmax_acceleration = 3600\n")
    out_csv = tmp_path / "out.csv"
    timed(capsys, "--machine", str(machine), "--trajectory", str(out_csv),
          program(tmp_path, "G21 G61\nG0 X10 A90\nG1 A180 F600\nM2\n"))
    assert out_csv.read_text().splitlines()[0] == "t,x,y,z,a,velocity,line"
    last = rows(out_csv)[-1]
    assert (last["x"], last["a"]) == (10.0, 180.0)


# -- underneath: the sampler and the timer's listeners ---------------------------------------------
def test_profile_ends_exactly_at_its_length() -> None:
    line = Line((0.0,) * 6, (3.0, 4.0, 0.0, 0.0, 0.0, 0.0), 5.0)
    # a profile a little off its length (as rounding leaves it) still ends at the line's end
    profile = Profile(line, t0=2.0, time=0.6, vin=0.0, peak=10.0, vout=0.0, accel=40.0)
    assert profile.point(1.0) == line.start
    assert profile.point(2.6) == line.end and profile.distance(9.0) == 5.0
    distances = [profile.distance(2.0 + k * 0.01) for k in range(61)]
    assert distances == sorted(distances) and distances[-1] == pytest.approx(5.0)
    assert profile.speed(2.3) == pytest.approx(max(profile.speed(2.0 + k * 0.01)
                                                   for k in range(60)))


def test_sample_follows_a_segment() -> None:
    segments: list[Segment] = []
    time_lines(["G61.1 G1 X100 F6000\n", "M2\n"], on_segment=segments.append)
    (seg,) = segments
    samples = list(sample(seg, [seg.t0 - 1.0, seg.t0, seg.t0 + 0.5 * seg.time,
                                seg.t0 + seg.time]))
    assert samples[0] == samples[1] == ((0.0,) * 6, 0.0)
    assert samples[2][0][0] == pytest.approx(50.0) and samples[2][1] == pytest.approx(100.0)
    assert samples[3] == ((100.0, 0.0, 0.0, 0.0, 0.0, 0.0), 0.0)


def test_timer_listeners(tmp_path: Path) -> None:
    segments: list[Segment] = []
    waits: list[tuple[str, float, float, int]] = []
    path = program(tmp_path, MIXED)
    result = time_file(path, on_segment=segments.append,
                       on_wait=lambda *wait: waits.append(wait))
    assert len(segments) == result.segments
    starts = [seg.t0 for seg in segments]
    assert starts == sorted(starts)
    ((kind, start, duration, line),) = waits
    assert (kind, line) == ("dwell", DWELL_LINE)
    assert duration == result.by_kind["dwell"]
    before = [seg for seg in segments if seg.line < DWELL_LINE]
    assert max(seg.t0 + seg.time for seg in before) <= start + 1e-9
    assert all(seg.t0 >= start + duration - 1e-9 for seg in segments if seg.line > DWELL_LINE)


def test_writer_refuses_a_spacing_of_zero() -> None:
    with pytest.raises(ValueError, match="positive"):
        TrajectoryWriter(open(os.devnull, "w"), DEFAULT_MACHINE, 0.0)  # noqa: SIM115


@pytest.mark.parametrize("module", [time_report, trajectory, timing])
def test_doctests(module: object) -> None:
    failed, attempted = doctest.testmod(module)  # type: ignore[arg-type]
    assert attempted > 0 and failed == 0


@pytest.mark.parametrize("lines", [0, 1, time_report.JSON_CHUNK - 1, time_report.JSON_CHUNK,
                                   time_report.JSON_CHUNK + 1, 2 * time_report.JSON_CHUNK])
def test_the_json_by_line_is_whole_at_any_count(lines: int) -> None:
    import io

    result = timing.TimeResult()
    for line in range(1, lines + 1):
        result.by_line.add(line, 0.5)
    out = io.StringIO()
    time_report.write_json(out, "x.ngc", result, DEFAULT_MACHINE)
    record = json.loads(out.getvalue())
    assert len(record["by_line"]) == lines
    assert all(value == 0.5 for value in record["by_line"].values())


def test_many_files_each_in_turn(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    a = write(tmp_path, "a.ngc", "G1 X10 F600\nM2\n")
    bad = write(tmp_path, "bad.ngc", "G1 X10 F600\nG2 X0 Y0 R0.1\nM2\n")
    b = write(tmp_path, "b.ngc", "G1 X20 F600\nM2\n")
    code, out, err = run(capsys, "time", a, bad, b)
    assert code == 1
    assert [p.split(":")[0] for p in out.split("\n\n")] == [a, b]
    assert "Arc radius too small" in err
    code, out, _ = run(capsys, "time", "--format", "json", a, b)
    assert code == 0
    assert [json.loads(line)["total_s"] for line in out.splitlines()] == [1.02, 2.02]
    code, _, err = run(capsys, "time", "--trajectory", str(tmp_path / "t.csv"), a, b)
    assert code == 2 and "--trajectory takes one program" in err
