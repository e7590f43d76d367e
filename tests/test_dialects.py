"""The dialect, selectable everywhere: ``--dialect`` and ``--setup`` on ``rs274``, ``canon`` and
``check``, the first-line marker (per file in ``check``, on standard input too), the engine
summary of ``ngc check``, ``dialect=`` in ``ngc.interpret`` and ``ngc.check_file``, the sinks
with engine operations, and the errors of each combination that does not fit."""

from __future__ import annotations

import doctest
import io
import json
import math
import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

import ngc
import ngc.engine
from cli_helpers import run
from ngc import dialects
from ngc.canon.jsonl import JsonSink, ListSink
from ngc.canon.ops import StraightFeed
from ngc.canon.text import TextSink
from ngc.commands import check_engine as engine_report
from ngc.commands.check import CheckResult
from ngc.commands.check_engine import EngineCheckResult, cubic_range
from ngc.engine import Dwell, EngineSegment
from ngc.errors import NgcConfigError, NgcError

SRC = Path(__file__).resolve().parent.parent / "src"

ENGINE = "move X1 Y2\nF10\nfeed X3\ndwell P0.5\n"
MARKED = "(dialect: engine)\n" + ENGINE
LINUXCNC = "G21 F100\nG1 X3 Y4\nG0 Z1\nM2\n"
SETUP = "tool = 1\n[tools.1]\nlength = 5.0\n[fixtures.1]\nX = 10.0\n"

# ENGINE's operations as ngc canon --dialect engine prints them (on a machine at rest at 0).
ENGINE_TEXT = [
    "ENGINE_SEGMENT(line=1, motion=rapid, duration=0.080000, "
    "X=[0.000000, 0.333333, 0.666667, 1.000000], Y=[0.000000, 0.666667, 1.333333, 2.000000])",
    "ENGINE_SEGMENT(line=3, motion=feed, duration=0.200000, "
    "X=[1.000000, 1.666667, 2.333333, 3.000000])",
    "DWELL(line=4, seconds=0.500000)",
]

# What ngc rs274 -g printed for LINUXCNC before the dialects, as rs274 prints it.
RS274_LINUXCNC = """\
    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
    2 N..... SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
    3 N..... SET_G92_OFFSET(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
    4 N..... SET_XY_ROTATION(0.0000)
    5 N..... SET_FEED_REFERENCE(CANON_XYZ)
    6 N..... ON_RESET()
    7 N..... SET_FEED_RATE(100.0000)
    8 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
    9 N..... STRAIGHT_FEED(3.0000, 4.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   10 N..... STRAIGHT_TRAVERSE(3.0000, 4.0000, 1.0000, 0.0000, 0.0000, 0.0000)
   11 N..... SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   12 N..... SET_XY_ROTATION(0.0000)
   13 N..... SET_FEED_MODE(0, 0)
   14 N..... SET_FEED_RATE(0.0000)
   15 N..... STOP_SPINDLE_TURNING(0)
   16 N..... SET_SPINDLE_MODE(0 0.0000)
   17 N..... PROGRAM_END()
   18 N..... ON_RESET()
   19 N..... ON_RESET()
"""


@pytest.fixture
def work(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A working directory with the programs and setup sheets of these tests."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "e.ngc").write_text(ENGINE)
    (tmp_path / "m.ngc").write_text(MARKED)
    (tmp_path / "l.ngc").write_text(LINUXCNC)
    (tmp_path / "s.toml").write_text(SETUP)
    return tmp_path


def engine_lines(out: str) -> list[str]:
    """The lines of engine text output, without the settings (FEED_RATE, ...)."""
    return [line for line in out.splitlines() if line.startswith(("ENGINE_SEGMENT", "DWELL"))]


def ngc_process(*argv: str, cwd: Path, stdin: bytes = b"") -> subprocess.CompletedProcess[bytes]:
    """``python -m ngc argv...`` in a fresh process, the program piped in."""
    environ = {**os.environ, "PYTHONPATH": str(SRC)}
    return subprocess.run([sys.executable, "-m", "ngc", *argv], input=stdin, cwd=cwd,
                          capture_output=True, env=environ, timeout=60, check=False)


class SetupSeen:
    """Stands in for ``ngc.engine.Engine``: keeps the setup each engine is made with."""

    def __init__(self) -> None:
        self.setups: list[Any] = []

    def __call__(self, **kwargs: Any) -> Any:
        self.setups.append(kwargs.get("setup"))
        return ENGINE_CLASS(**kwargs)


ENGINE_CLASS = ngc.engine.Engine


@pytest.fixture
def seen(monkeypatch: pytest.MonkeyPatch) -> SetupSeen:
    spy = SetupSeen()
    monkeypatch.setattr(ngc.engine, "Engine", spy)
    return spy


def assert_is_the_sheet(setup: Any) -> None:
    """``setup`` is SETUP, read."""
    assert setup.tool == 1
    assert dict(setup.lengths) == {1: 5.0}
    assert setup.fixtures[1].offsets[0] == 10.0


# -- ngc canon -------------------------------------------------------------------------------------
def test_canon_engine_text(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    code, out, err = run(capsys, "canon", "--dialect", "engine", "e.ngc")
    assert (code, err) == (0, "")
    assert engine_lines(out) == ENGINE_TEXT
    assert not any(line.startswith("    1 N") for line in out.splitlines())


def test_canon_engine_json(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    code, out, err = run(capsys, "canon", "--dialect", "engine", "--format", "json", "e.ngc")
    assert (code, err) == (0, "")
    records = [json.loads(line) for line in out.splitlines()]
    segments = [r for r in records if r["op"] == "ENGINE_SEGMENT"]
    assert [s["motion"] for s in segments] == ["rapid", "feed"]
    assert segments[1]["axes"]["X"][3] == 3.0 and segments[1]["line"] == 3
    assert records[-1] == {"op": "DWELL", "line": 4, "seconds": 0.5}


def test_canon_marker_and_the_option_over_it(capsys: pytest.CaptureFixture[str],
                                             work: Path) -> None:
    code, out, _ = run(capsys, "canon", "m.ngc")
    assert code == 0
    assert engine_lines(out) == [  # the marker is line 1
        ENGINE_TEXT[0].replace("line=1", "line=2"), ENGINE_TEXT[1].replace("line=3", "line=4"),
        ENGINE_TEXT[2].replace("line=4", "line=5")]
    # --dialect linuxcnc reads the marked program as LinuxCNC (where 'move' is no code)
    code, out, err = run(capsys, "canon", "--dialect", "linuxcnc", "m.ngc")
    assert code == 1
    assert "USE_LENGTH_UNITS(CANON_UNITS_MM)" in out and "m.ngc:2:" in err


@pytest.mark.parametrize("marker", ["; dialect: engine", "(DIALECT: Engine)", "  ( dialect:engine )  ",
                                    "\ufeff(dialect: engine)"])
def test_marker_forms(capsys: pytest.CaptureFixture[str], work: Path, marker: str) -> None:
    (work / "f.ngc").write_text(f"{marker}\r\n{ENGINE}")
    code, out, _ = run(capsys, "canon", "f.ngc")
    assert code == 0
    assert len(engine_lines(out)) == 3


@pytest.mark.parametrize("first", ["(dialect: linuxcnc)", "(dialect: engine) G0 X1",
                                   "(dialect: fanuc)", "G0 X1 (dialect: engine)"])
def test_not_an_engine_marker(first: str) -> None:
    assert dialects.of_text(f"{first}\nG0 X1\n") == "linuxcnc"


def test_canon_engine_error(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    (work / "bad.ngc").write_text("(dialect: engine)\nrapid X 1\nfrobnicate\n")
    code, out, err = run(capsys, "canon", "bad.ngc")
    assert code == 1
    assert out.startswith("ENGINE_SEGMENT(line=2, motion=rapid")
    assert err.startswith("bad.ngc:3:1: Unknown name 'frobnicate'\n    frobnicate\n    ^")


def test_canon_cannot_open(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    code, out, err = run(capsys, "canon", "--dialect", "engine", "nope.ngc")
    assert (code, out) == (2, "")
    assert err == "ngc canon: cannot open nope.ngc: No such file or directory\n"


def test_canon_passes_the_setup(capsys: pytest.CaptureFixture[str], work: Path,
                                seen: SetupSeen) -> None:
    code, out, _ = run(capsys, "canon", "--dialect", "engine", "--setup", "s.toml", "e.ngc")
    assert code == 0 and engine_lines(out) == ENGINE_TEXT
    assert len(seen.setups) == 1
    assert_is_the_sheet(seen.setups[0])
    run(capsys, "canon", "--dialect", "engine", "e.ngc")
    assert seen.setups[1:] == [None]  # no sheet: the default machine


# -- ngc check -------------------------------------------------------------------------------------
def test_check_engine_text(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    code, out, err = run(capsys, "check", "--dialect", "engine", "e.ngc")
    assert (code, err) == (0, "")
    assert out == (
        "e.ngc: ok, 4 lines (engine dialect)\n"
        "  segments: 2 (1 rapid, 1 feed, 0 arc, 0 probe, 0 run), dwells: 1\n"
        "  time: 0.7800 s (rapid 0.0800, feed 0.2000, arc 0.0000, probe 0.0000, run 0.0000, "
        "dwell 0.5000)\n"
        "  length: 4.2361 mm (rapid 2.2361, feed 2.0000, arc 0.0000, probe 0.0000, run 0.0000)\n"
        "  extents: X 0.0000 .. 3.0000  Y 0.0000 .. 2.0000 mm\n")


def test_check_engine_json(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    code, out, err = run(capsys, "check", "--dialect", "engine", "--format", "json", "e.ngc")
    assert (code, err) == (0, "")
    record = json.loads(out)
    assert record["file"] == "e.ngc" and record["dialect"] == "engine"
    assert (record["ok"], record["lines"], record["error"]) == (True, 4, None)
    s = record["summary"]
    assert s["units"] == "mm" and s["mixed_units"] is False
    assert (s["segments"], s["dwells"]) == (2, 1)
    assert s["segments_by_motion"] == {"rapid": 1, "feed": 1, "arc": 0, "probe": 0, "run": 0}
    assert s["time"] == pytest.approx(0.78)
    assert s["time_by_kind"]["dwell"] == 0.5 and s["time_by_kind"]["rapid"] == pytest.approx(0.08)
    assert s["length"] == pytest.approx(2.0 + math.sqrt(5.0))
    assert s["length_by_motion"]["feed"] == pytest.approx(2.0)
    assert s["extents"] == {"low": [0.0, 0.0, None], "high": [3.0, 2.0, None]}


def test_check_engine_error(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    (work / "bad.ngc").write_text("F10\nfeed X2\nfrobnicate\nfeed X9\n")
    code, out, err = run(capsys, "check", "--dialect", "engine", "bad.ngc")
    assert code == 1
    assert err.startswith("bad.ngc:3:1: Unknown name 'frobnicate'\n")
    assert out.startswith("bad.ngc: stopped by an error at line 3, 4 lines (engine dialect)\n"
                          "  segments: 1 (0 rapid, 1 feed,")
    code, out, _ = run(capsys, "check", "--dialect", "engine", "--format", "json", "bad.ngc")
    record = json.loads(out)
    assert code == 1 and record["ok"] is False
    assert record["error"] == {"message": "Unknown name 'frobnicate'", "about": None,
                               "file": "bad.ngc", "line": 3, "column": 1,
                               "source": "frobnicate"}
    assert record["summary"]["length"] == pytest.approx(2.0)


def test_check_marker_per_file(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    code, out, err = run(capsys, "check", "--format", "json", "m.ngc", "l.ngc", "nope.ngc",
                         "e.ngc")
    records = [json.loads(line) for line in out.splitlines()]
    assert code == 2  # nope.ngc
    assert [r.get("dialect") for r in records] == ["engine", None, None, None]
    assert records[0]["summary"]["segments"] == 2
    assert records[1]["summary"]["feeds"] == 1 and records[1]["ok"] is True
    assert records[2]["lines"] is None
    assert records[3]["ok"] is False  # unmarked: LinuxCNC, where 'move' is no code
    assert "ngc check: cannot open nope.ngc" in err and "e.ngc:1:" in err
    code, out, _ = run(capsys, "check", "m.ngc", "l.ngc")
    assert code == 0
    first, second = out.split("\n\n")
    assert first.startswith("m.ngc: ok, 5 lines (engine dialect)\n  segments: 2")
    assert second.startswith("l.ngc: ok, 4 lines\n  moves: 2 (1 traverse, 1 feed, 0 arc)")


def test_check_gives_each_file_its_dialects_inputs(capsys: pytest.CaptureFixture[str],
                                                   work: Path, seen: SetupSeen) -> None:
    """Without --dialect, -t applies to the LinuxCNC files and --setup to the engine ones."""
    (work / "tools.tbl").write_text("T7 P7 D0.1 Z0.5 ;not in rs274's sample table\n")
    (work / "t.ngc").write_text("T7 M6\nM2\n")
    code, out, err = run(capsys, "check", "t.ngc")
    assert code == 1 and "Requested tool 7 not found in the tool table" in err
    code, out, err = run(capsys, "check", "-j", "1", "-t", "tools.tbl", "--setup", "s.toml",
                         "--format", "json", "m.ngc", "t.ngc")
    records = [json.loads(line) for line in out.splitlines()]
    assert (code, err) == (0, "")
    assert [r["ok"] for r in records] == [True, True]
    assert len(seen.setups) == 1
    assert_is_the_sheet(seen.setups[0])


def test_check_engine_units(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    (work / "u.ngc").write_text("F10\nfeed X25.4\nG20\n")
    code, out, _ = run(capsys, "check", "--dialect", "engine", "--format", "json", "u.ngc")
    s = json.loads(out)["summary"]
    assert code == 0
    assert (s["units"], s["mixed_units"]) == ("inch", True)
    assert s["length"] == pytest.approx(1.0)
    assert s["extents"]["high"][0] == pytest.approx(1.0)


# -- standard input --------------------------------------------------------------------------------
def test_stdin_with_dialect(work: Path) -> None:
    proc = ngc_process("canon", "--dialect", "engine", "-", cwd=work, stdin=ENGINE.encode())
    assert proc.returncode == 0
    assert engine_lines(proc.stdout.decode()) == ENGINE_TEXT
    proc = ngc_process("check", "--dialect", "engine", "--format", "json", "-", cwd=work,
                       stdin=ENGINE.encode())
    record = json.loads(proc.stdout)
    assert (proc.returncode, record["file"], record["dialect"]) == (0, "<stdin>", "engine")
    assert record["summary"]["dwells"] == 1
    proc = ngc_process("check", "--dialect", "engine", "-", cwd=work, stdin=b"frobnicate\n")
    assert proc.returncode == 1
    assert proc.stderr.startswith(b"<stdin>:1:1: Unknown name 'frobnicate'")


def test_stdin_marker_through_a_pipe(work: Path) -> None:
    proc = ngc_process("check", "--format", "json", "-", cwd=work,
                       stdin=b"\xef\xbb\xbf" + MARKED.encode())
    assert proc.returncode == 0
    assert json.loads(proc.stdout)["summary"]["segments"] == 2
    # a LinuxCNC program piped in reads as it did: the first line is given back to it
    piped = ngc_process("canon", "-", cwd=work, stdin=b"\xef\xbb\xbf" + LINUXCNC.encode())
    named = ngc_process("canon", "l.ngc", cwd=work)
    assert (piped.returncode, piped.stdout) == (0, named.stdout)
    long_first = b"(" + b"a" * 600 + b")\nM2\n"
    piped = ngc_process("check", "-", cwd=work, stdin=long_first)
    assert piped.returncode == 1 and b"<stdin>:1: Command too long" in piped.stderr


def test_stdin_marker_from_a_file(capsys: pytest.CaptureFixture[str], work: Path,
                                  monkeypatch: pytest.MonkeyPatch) -> None:
    with open(work / "m.ngc", "rb") as handle:
        monkeypatch.setattr(sys, "stdin", handle)
        code, out, _ = run(capsys, "canon", "-")
    assert code == 0 and len(engine_lines(out)) == 3


# -- ngc rs274 -------------------------------------------------------------------------------------
def test_rs274_default_unchanged(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    code, out, err = run(capsys, "rs274", "-g", "l.ngc")
    assert (code, out, err) == (0, RS274_LINUXCNC, "executing\n")
    code, out, err = run(capsys, "rs274", "--dialect", "linuxcnc", "-g", "l.ngc")
    assert (code, out, err) == (0, RS274_LINUXCNC, "executing\n")
    (work / "c.ngc").write_text("(dialect: linuxcnc)\n" + LINUXCNC)
    code, out, _ = run(capsys, "rs274", "-g", "c.ngc")
    assert code == 0
    assert "COMMENT(\"dialect: linuxcnc\")" in out  # rs274 reads the marker as the comment it is
    assert "N..... STRAIGHT_FEED(3.0000, 4.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n" in out


def test_rs274_engine(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    code, out, err = run(capsys, "rs274", "--dialect", "engine", "-g", "e.ngc")
    assert (code, err) == (0, "executing\n")
    assert engine_lines(out) == ENGINE_TEXT
    code, out, _ = run(capsys, "rs274", "m.ngc")
    assert code == 0 and len(engine_lines(out)) == 3
    code, out, err = run(capsys, "rs274", "-g", "e.ngc", "out.txt", "--dialect=engine")
    assert (code, out) == (0, "")
    assert engine_lines((work / "out.txt").read_text()) == ENGINE_TEXT


def test_rs274_engine_error(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    (work / "bad.ngc").write_text("rapid X 1\nfrobnicate\n")
    code, out, err = run(capsys, "rs274", "--dialect", "engine", "bad.ngc")
    assert code == 1
    assert out.startswith("ENGINE_SEGMENT(line=1, motion=rapid")
    assert err == ("executing\nbad.ngc:2:1: Unknown name 'frobnicate'\n    frobnicate\n"
                   "    ^\n")


def test_rs274_passes_the_setup(capsys: pytest.CaptureFixture[str], work: Path,
                                seen: SetupSeen) -> None:
    code, _, _ = run(capsys, "rs274", "--setup", "s.toml", "m.ngc")
    assert code == 0
    assert_is_the_sheet(seen.setups[0])


def test_rs274_engine_bytes_written_back(work: Path) -> None:
    (work / "b.ngc").write_bytes(b"(dialect: engine)\n(caf\xe9)\nfrobnicate (\xe9)\n")
    proc = ngc_process("rs274", "b.ngc", cwd=work)
    assert proc.returncode == 1
    assert b"    frobnicate (\xe9)\n" in proc.stderr


# -- errors ----------------------------------------------------------------------------------------
@pytest.mark.parametrize(("command", "choices"), [("canon", "'linuxcnc', 'engine'"),
                                                 ("check", "'linuxcnc', 'engine', 'grbl', 'grblhal'")])
def test_bad_dialect_choice(capsys: pytest.CaptureFixture[str], work: Path, command: str,
                            choices: str) -> None:
    code, out, err = run(capsys, command, "--dialect", "fanuc", "l.ngc")
    assert (code, out) == (2, "")
    assert f"argument --dialect: invalid choice: 'fanuc' (choose from {choices})" in err


def test_rs274_bad_dialect_choice(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    code, out, err = run(capsys, "rs274", "--dialect", "fanuc", "l.ngc")
    assert (code, out) == (1, "")
    assert err.startswith("ngc rs274: --dialect must be linuxcnc or engine, not 'fanuc'\n")


SETUP_REFUSED = "--setup is the engine dialect's machine setup sheet, not an input of the LinuxCNC"


@pytest.mark.parametrize("argv", [
    ["canon", "--setup", "s.toml", "l.ngc"],
    ["canon", "--dialect", "linuxcnc", "--setup", "s.toml", "m.ngc"],
    ["check", "--dialect", "linuxcnc", "--setup", "s.toml", "l.ngc"],
    ["rs274", "--setup", "s.toml", "l.ngc"],
])
def test_setup_with_linuxcnc(capsys: pytest.CaptureFixture[str], work: Path,
                             argv: list[str]) -> None:
    code, out, err = run(capsys, *argv)
    assert (code, out) == (1 if argv[0] == "rs274" else 2, "")
    assert err.startswith(f"ngc {argv[0]}: {SETUP_REFUSED}")


@pytest.mark.parametrize(("argv", "flags"), [
    (["canon", "--dialect", "engine", "-t", "x.tbl", "l.ngc"], "-t is an input"),
    (["canon", "-i", "x.ini", "-v", "x.var", "m.ngc"], "-i, -v are inputs"),
    (["canon", "--probe", "p.toml", "m.ngc"], "--probe is an input"),
    (["check", "--dialect", "engine", "-t", "x.tbl", "e.ngc"], "-t is an input"),
    (["rs274", "--dialect", "engine", "-t", "x.tbl", "e.ngc"], "-t is an input"),
    (["rs274", "-b", "-n", "0", "m.ngc"], "-b, -n 0 are inputs"),
])
def test_linuxcnc_inputs_with_engine(capsys: pytest.CaptureFixture[str], work: Path,
                                     argv: list[str], flags: str) -> None:
    code, out, err = run(capsys, *argv)
    assert (code, out) == (1 if argv[0] == "rs274" else 2, "")
    assert err == (f"ngc {argv[0]}: {flags} of the LinuxCNC dialect, not of the engine dialect "
                   "(whose machine is described by --setup FILE)\n")


@pytest.mark.parametrize("command", ["canon", "check", "rs274"])
def test_unreadable_setup(capsys: pytest.CaptureFixture[str], work: Path, command: str) -> None:
    code, out, err = run(capsys, command, "--dialect", "engine", "--setup", "nope.toml", "e.ngc")
    assert (code, out) == (1 if command == "rs274" else 2, "")
    assert err == f"ngc {command}: cannot open setup file nope.toml: No such file or directory\n"


@pytest.mark.parametrize("command", ["canon", "check", "rs274"])
def test_setup_with_an_unknown_key(capsys: pytest.CaptureFixture[str], work: Path,
                                   command: str) -> None:
    (work / "bad.toml").write_text("tool = 1\n[tools.1]\nlenght = 5.0\n")
    code, out, err = run(capsys, command, "--setup", "bad.toml", "m.ngc")
    assert (code, out) == (1 if command == "rs274" else 2, "")
    assert err == (f"ngc {command}: setup file bad.toml: tools.1: unknown key 'lenght' "
                   "(length)\n")


def test_check_setup_read_before_any_file(capsys: pytest.CaptureFixture[str],
                                          work: Path) -> None:
    (work / "bad.toml").write_text("speed = 3\n")
    code, out, err = run(capsys, "check", "--setup", "bad.toml", "l.ngc")
    assert (code, out) == (2, "")
    assert "unknown key 'speed'" in err


def test_help_names_the_options(capsys: pytest.CaptureFixture[str]) -> None:
    for command, choices in (("canon", "{linuxcnc,engine}"), ("check", "{linuxcnc,engine,grbl,grblhal}")):
        code, out, _ = run(capsys, command, "--help")
        assert code == 0 and f"--dialect {choices}" in out and "--setup FILE" in out
    code, out, _ = run(capsys, "rs274", "--help")
    assert code == 0 and "--dialect linuxcnc|engine" in out and "--setup FILE" in out


# -- the API ---------------------------------------------------------------------------------------
def test_interpret_engine_into_a_list() -> None:
    sink = ListSink()
    ngc.interpret(ENGINE, sink, dialect="engine")
    kinds = [(type(op), label, line) for op, label, line in sink.ops
             if isinstance(op, EngineSegment | Dwell)]
    assert kinds == [(EngineSegment, "ENGINE_SEGMENT", 1), (EngineSegment, "ENGINE_SEGMENT", 3),
                     (Dwell, "DWELL", 4)]
    assert all(label == dialects.engine_record(op)["op"] for op, label, _ in sink.ops)


def test_interpret_dialect_by_marker_and_explicit() -> None:
    sink = ListSink()
    ngc.interpret(MARKED, sink)
    assert sum(isinstance(op, EngineSegment) for op, _, _ in sink.ops) == 2
    sink = ListSink()
    ngc.interpret(LINUXCNC, sink, dialect="linuxcnc")
    assert StraightFeed(3.0, 4.0, 0.0, 0.0, 0.0, 0.0) in [op for op, _, _ in sink.ops]
    with pytest.raises(NgcError, match="Unknown word"):
        ngc.interpret(MARKED, ListSink(), dialect="linuxcnc")
    with pytest.raises(NgcError, match="Unknown name 'T7'"):
        ngc.interpret("T7 M6\n", ListSink(), dialect="engine")


def test_interpret_engine_text_and_json_sinks() -> None:
    out = io.StringIO()
    ngc.interpret(ENGINE, TextSink(out), dialect="engine")
    assert engine_lines(out.getvalue()) == ENGINE_TEXT
    out = io.StringIO()
    ngc.interpret(ENGINE, JsonSink(out), dialect="engine")
    records = [json.loads(line) for line in out.getvalue().splitlines()]
    assert records[-1] == {"op": "DWELL", "line": 4, "seconds": 0.5}
    assert [r["motion"] for r in records if r["op"] == "ENGINE_SEGMENT"] == ["rapid", "feed"]


def test_sinks_refuse_what_is_no_operation() -> None:
    class Strange:
        line = 1

    for sink in (TextSink(io.StringIO()), JsonSink(io.StringIO())):
        with pytest.raises(TypeError, match="neither a canonical operation"):
            sink.emit(Strange(), "N..... ", 1)  # type: ignore[arg-type]


def test_interpret_flushes_after_an_engine_error() -> None:
    out = io.StringIO()
    with pytest.raises(NgcError) as info:
        ngc.interpret("rapid X1\nfrobnicate\n", TextSink(out), dialect="engine", file="p.ngc")
    assert info.value.line == 2 and info.value.file == "p.ngc"
    assert out.getvalue().startswith("ENGINE_SEGMENT(line=1")


def test_interpret_passes_the_setup(work: Path, seen: SetupSeen) -> None:
    ngc.interpret(ENGINE, ListSink(), dialect="engine",
                  setup=ngc.engine.read_setup(str(work / "s.toml")))
    assert_is_the_sheet(seen.setups[0])


def test_interpret_wrong_keywords() -> None:
    with pytest.raises(ValueError, match="unknown dialect 'fanuc': choose 'linuxcnc' or 'engine'"):
        ngc.interpret(ENGINE, ListSink(), dialect="fanuc")
    with pytest.raises(ValueError, match="setup is the engine dialect's machine setup sheet"):
        ngc.interpret(LINUXCNC, ListSink(), setup=ngc.engine.Setup())
    with pytest.raises(ValueError, match="probe is an input of the LinuxCNC dialect"):
        ngc.interpret(ENGINE, ListSink(), dialect="engine", probe=object())  # type: ignore[arg-type]


def test_check_file_both_dialects(work: Path, seen: SetupSeen) -> None:
    marked = ngc.check_file(work / "m.ngc")
    assert isinstance(marked, EngineCheckResult)
    assert (marked.ok, marked.lines, marked.dialect) == (True, 5, "engine")
    assert marked.summary.segments["feed"] == 1 and marked.summary.dwells == 1
    plain = ngc.check_file(work / "l.ngc")
    assert isinstance(plain, CheckResult) and plain.dialect == "linuxcnc"
    assert plain.summary.feeds == 1
    as_engine = ngc.check_file(work / "e.ngc", dialect="engine",
                               setup=ngc.engine.read_setup(str(work / "s.toml")))
    assert isinstance(as_engine, EngineCheckResult) and as_engine.summary.dwells == 1
    assert_is_the_sheet(seen.setups[-1])
    as_linuxcnc = ngc.check_file(work / "m.ngc", dialect="linuxcnc")
    assert isinstance(as_linuxcnc, CheckResult) and not as_linuxcnc.ok


def test_check_file_errors(work: Path) -> None:
    with pytest.raises(ValueError, match="choose 'linuxcnc' or 'engine'"):
        ngc.check_file(work / "l.ngc", dialect="Engine")
    with pytest.raises(ValueError, match="setup is the engine dialect's"):
        ngc.check_file(work / "l.ngc", setup=ngc.engine.Setup())
    with pytest.raises(OSError):
        ngc.check_file(work / "nope.ngc", dialect="engine")
    (work / "bad.ngc").write_text("F10\nfeed X2\nfrobnicate\n")
    result = ngc.check_file(work / "bad.ngc", dialect="engine")
    assert result.error is not None and result.error.line == 3 and not result.ok
    assert result.summary.length == pytest.approx(2.0)


def test_read_setup_error_is_a_config_error(work: Path) -> None:
    with pytest.raises(NgcConfigError, match="cannot open setup file"):
        ngc.engine.read_setup(str(work / "nope.toml"))


# -- the summary's maths ---------------------------------------------------------------------------
@pytest.mark.parametrize(("cubic", "low", "high"), [
    ((0.0, 1.0, 2.0, 3.0), 0.0, 3.0),  # a straight line: its ends
    ((0.0, 1.0, 1.0, 0.0), 0.0, 0.75),  # up and back: the top at t = 1/2
    ((0.0, -2.0, 3.0, 1.0), -0.4820, 1.4820),  # a dip below the start, a bump past the end
    ((1.0, 1.0, 1.0, 1.0), 1.0, 1.0),
])
def test_cubic_range(cubic: tuple[float, float, float, float], low: float, high: float) -> None:
    from ngc.engine.bezier import point

    got = cubic_range(cubic)
    assert got == pytest.approx((low, high), abs=1e-4)
    samples = [point(cubic, i / 1000) for i in range(1001)]
    assert got[0] <= min(samples) + 1e-12 and got[1] >= max(samples) - 1e-12
    assert min(samples) - got[0] < 1e-5 and got[1] - max(samples) < 1e-5


@pytest.mark.parametrize("start", [0, 45, 30])
def test_extents_of_a_circle(start: int) -> None:
    """A circle of radius 0.5 in quarter-turn cubics from ``start`` degrees: where the quarters
    do not end on the circle's extreme points, the extents are the curves' tops, between the
    ends (at 45 degrees, the cubic from 45 to 135 is symmetric: its top is at t = 1/2)."""
    s = engine_report.summarize(ngc.engine.run(f"F10\nfeed PZ {start} {start + 360} 0.5 0\n"))
    a = math.radians(start)
    cx, cy = -0.5 * math.cos(a), -0.5 * math.sin(a)
    assert s.extents["X"] == pytest.approx((cx - 0.5, cx + 0.5), abs=5e-4)
    assert s.extents["Y"] == pytest.approx((cy - 0.5, cy + 0.5), abs=5e-4)
    assert s.length == pytest.approx(math.pi, rel=1e-3)


def test_cubic_range_of_a_symmetric_bump_with_rounding_noise() -> None:
    assert cubic_range((0.0, 0.19526214587563498, 0.195262145875635, 5.551115123125783e-17)) \
        == pytest.approx((0.0, 0.1464466), abs=1e-7)


@pytest.mark.parametrize("module", [dialects, engine_report], ids=lambda m: m.__name__)
def test_doctests(module: object) -> None:
    failed, attempted = doctest.testmod(module)  # type: ignore[arg-type]
    assert attempted > 0
    assert failed == 0
