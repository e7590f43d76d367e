"""M codes and S in the engine dialect: the seed's examples end with M2 and run the same, the
spindle, the coolant, stops and the end, and the commands that read engine programs."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from ngc import cli
from ngc.canon.jsonl import ListSink
from ngc.engine import EngineSegment, ModeChange, ProgramStop, run, svg
from ngc.engine.output import as_dict, as_text
from ngc.errors import NgcError
from ngc.interp.interpreter import Interpreter

DRAWINGS = Path(__file__).resolve().parent.parent / "docs" / "engine"
EXAMPLES = sorted(DRAWINGS.glob("*.ngc"))


@pytest.mark.parametrize("program", EXAMPLES, ids=[p.stem for p in EXAMPLES])
@pytest.mark.parametrize("end", ["M2", "M30", "m2", "M 30"])
def test_seed_examples_end_with_m2(program: Path, end: str) -> None:
    text = program.read_text(encoding="utf-8")
    ops = list(run(text + end + "\n"))
    assert ops[:-1] == list(run(text))
    assert ops[-1] == ProgramStop(3, "PROGRAM_END")
    assert svg.draw(run(text + end + "\n")) == svg.draw(run(text))


def test_nothing_runs_after_the_end() -> None:
    ops = list(run("G0 X1\nM2\nG0 X2\nfrobnicate\n"))
    assert [type(op) for op in ops] == [EngineSegment, ProgramStop]


def settings(text: str) -> list[tuple[int, str, object]]:
    return [(op.line, op.name, op.value) for op in run(text) if isinstance(op, ModeChange)]


def test_spindle_and_speed() -> None:
    assert settings("S1000 M3\nM3\nM4 S 200.5\nS [2 * 100]\nM5\nM5") == [
        (1, "SPINDLE_SPEED", 1000.0), (1, "SPINDLE", "clockwise"),
        (3, "SPINDLE_SPEED", 200.5), (3, "SPINDLE", "counterclockwise"),
        (4, "SPINDLE_SPEED", 200.0), (5, "SPINDLE", "off")]


def test_coolant_mist_and_flood_together() -> None:
    assert settings("M7\nM8\nM8\nM9\nM8") == [
        (1, "COOLANT", {"mist": True, "flood": False}),
        (2, "COOLANT", {"mist": True, "flood": True}),
        (4, "COOLANT", {"mist": False, "flood": False}),
        (5, "COOLANT", {"mist": False, "flood": True})]


def test_one_line_runs_speed_spindle_coolant_then_the_end() -> None:
    ops = list(run("M3 M8 S500\nM2 M9 M5"))
    assert [(op.line, op.name) for op in ops if isinstance(op, (ModeChange, ProgramStop))] == [
        (1, "SPINDLE_SPEED"), (1, "SPINDLE"), (1, "COOLANT"),
        (2, "SPINDLE"), (2, "COOLANT"), (2, "PROGRAM_END")]


def test_the_end_turns_spindle_and_coolant_off() -> None:
    assert settings("M4 S9\nM7\nM30")[-2:] == [
        (3, "SPINDLE", "off"), (3, "COOLANT", {"mist": False, "flood": False})]
    assert settings("M2") == []


def test_stops_go_on() -> None:
    ops = list(run("M0\nM1\nG0 X1"))
    assert ops[:2] == [ProgramStop(1, "PROGRAM_STOP"), ProgramStop(2, "OPTIONAL_PROGRAM_STOP")]
    assert isinstance(ops[2], EngineSegment)


def test_after_settings_and_names_are_not_m_lines() -> None:
    ops = list(run("G21 G90 M3 S10\nset vector VX X 2\nmove X1"))
    assert [getattr(op, "name", None) for op in ops[:5]] == [
        "UNITS", "DISTANCE", "SPINDLE_SPEED", "SPINDLE", "VECTORS"]


def test_text_and_json() -> None:
    end = ProgramStop(4, "PROGRAM_END")
    assert as_text(end) == "PROGRAM_END(line=4)"
    assert as_dict(end) == {"op": "PROGRAM_END", "line": 4}
    assert as_text(ModeChange(2, "COOLANT", {"mist": True, "flood": False})) == (
        'COOLANT(line=2, {"mist": true, "flood": false})')


@pytest.mark.parametrize(("text", "message"), [
    ("M6", "Unknown code M6"),
    ("M2.5", "Unknown code M2.5"),
    ("M62 P1", "Unknown code M62"),
    ("M3 M4", "M3 \\(spindle clockwise\\) and M4 \\(spindle counterclockwise\\) on one line"),
    ("M7 M8", "M7 \\(mist\\) and M8 \\(flood\\) on one line"),
    ("M0 M2", "M0 \\(program stop\\) and M2 \\(program end\\) on one line"),
    ("S 1 S 2", "S given twice on one line"),
    ("S-5 M3", "S -5: a spindle speed must not be negative"),
    ("M3 X1", "'X' on a line of M codes"),
    ("M3 S", "S without a value"),
    ("G0 X1 M2", "M2: M codes go on a line of their own"),
])
def test_errors(text: str, message: str) -> None:
    with pytest.raises(NgcError, match=message) as info:
        list(run("G21\n" + text + "\nM2"))
    assert info.value.line == 2


def test_check_and_canon_commands(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    program = tmp_path / "p.ngc"
    program.write_text("S1200 M3\nM8\nF10\nfeed X3\nM2\nfeed X9\n")
    assert cli.main(["check", "--dialect", "engine", "--format", "json", str(program)]) == 0
    record = json.loads(capsys.readouterr().out)
    assert record["ok"] is True and record["summary"]["extents"]["high"][0] == 3.0
    assert cli.main(["canon", "--dialect", "engine", "--format", "json", str(program)]) == 0
    last = json.loads(capsys.readouterr().out.splitlines()[-1])
    assert last == {"op": "PROGRAM_END", "line": 5}
    assert svg.main([str(program), "-o", str(tmp_path / "p.svg")]) == 0
    assert 'd="M0,0\nC1,0 2,0 3,0"' in (tmp_path / "p.svg").read_text()


# -- the same M codes under both dialects ----------------------------------------------------------
_LINUXCNC_M = {"StartSpindleClockwise": "clockwise", "StartSpindleCounterclockwise":
               "counterclockwise", "StopSpindleTurning": "off", "ProgramStop": "PROGRAM_STOP",
               "OptionalProgramStop": "OPTIONAL_PROGRAM_STOP", "ProgramEnd": "PROGRAM_END"}


def _linuxcnc_m(text: str) -> list[tuple[int, str]]:
    """(line, what) of the spindle's turns and the stops of a LinuxCNC-dialect run."""
    sink = ListSink()
    interp = Interpreter(sink)
    interp.startup()
    interp.run(text.splitlines())
    out = []
    for op, _label, line in sink.ops:
        name = type(op).__name__
        if line and name in _LINUXCNC_M:
            out.append((line, _LINUXCNC_M[name]))
        elif line and name == "SetSpindleSpeed":
            out.append((line, f"S{op.rpm:g}"))  # type: ignore[union-attr]
    return out


def _engine_m(text: str) -> list[tuple[int, str]]:
    out = []
    for op in run(text):
        if isinstance(op, ProgramStop):
            out.append((op.line, op.name))
        elif isinstance(op, ModeChange) and op.name == "SPINDLE":
            out.append((op.line, str(op.value)))
        elif isinstance(op, ModeChange) and op.name == "SPINDLE_SPEED":
            out.append((op.line, f"S{op.value:g}"))
    return out


def test_spindle_and_stops_as_linuxcnc_runs_them() -> None:
    program = "G21\nS1000 M3\nG0 X1\nM4 S250\nM0\nM1\nM5\nG0 X2\nM3 S 800\nM2\n"
    assert _engine_m(program) == _linuxcnc_m(program)
