"""The ``ngc`` command line: ``canon``, ``check``, the ``rs274`` pass-through, exit codes, the
never-a-traceback guard; and that interpreters in one process do not share state."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from cli_helpers import run
from ngc import cli
from ngc.canon import ops
from ngc.canon.jsonl import ListSink
from ngc.commands import check as report
from ngc.commands import rs274
from ngc.errors import NgcSemanticError
from ngc.interp.interpreter import Interpreter

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"

GOOD = "(a square)\nG21 G90 F100\nG0 X0 Y0 Z1\nG1 Z-1\nN20 G1 X10\nY10\nX0\nY0\nG0 Z1\nM2\n"
BAD = "G21 F100\nG1 X1\nG2 X2 R0.1\nM2\n"  # line 3: the radius cannot reach the end point
BAD_MESSAGE = "Arc radius too small to reach end point"


@pytest.fixture
def good(tmp_path: Path) -> Path:
    path = tmp_path / "good.ngc"
    path.write_text(GOOD)
    return path


@pytest.fixture
def bad(tmp_path: Path) -> Path:
    path = tmp_path / "bad.ngc"
    path.write_text(BAD)
    return path


# -- ngc canon ------------------------------------------------------------------------------------
def test_canon_text_is_rs274_format(capsys: pytest.CaptureFixture[str], good: Path) -> None:
    code, out, err = run(capsys, "canon", str(good))
    lines = out.splitlines()
    assert (code, err) == (0, "")
    assert lines[0] == "    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)"
    assert "    5 N..... SET_FEED_REFERENCE(CANON_XYZ)" in lines
    assert lines[10] == (
        "   11 N20    STRAIGHT_FEED(10.0000, 0.0000, -1.0000, 0.0000, 0.0000, 0.0000)"
    )
    assert lines[-1].endswith("PROGRAM_END()")
    assert [int(line[:5]) for line in lines] == list(range(1, len(lines) + 1))


def test_canon_text_matches_rs274_transcript(
    capsys: pytest.CaptureFixture[str], good: Path
) -> None:
    """Same operations as ``ngc rs274``, without rs274's ON_RESET calls around the program."""
    _, canon, _ = run(capsys, "canon", str(good))
    _, transcript, _ = run(capsys, "rs274", "-g", str(good))

    def calls(text: str) -> list[str]:
        return [line[6:] for line in text.splitlines() if "ON_RESET" not in line]

    assert calls(canon) == calls(transcript)


def test_canon_json(capsys: pytest.CaptureFixture[str], good: Path) -> None:
    code, out, err = run(capsys, "canon", str(good), "--format", "json")
    records = [json.loads(line) for line in out.splitlines()]
    assert (code, err) == (0, "")
    assert records[0] == {"op": "USE_LENGTH_UNITS", "line": 0, "n": None, "units": "CANON_UNITS_MM"}
    feed = next(r for r in records if r["n"] == 20)
    assert feed == {
        "op": "STRAIGHT_FEED", "line": 5, "n": 20,
        "x": 10.0, "y": 0.0, "z": -1.0, "a": 0.0, "b": 0.0, "c": 0.0,
    }  # fmt: skip
    assert records[-1]["op"] == "PROGRAM_END"


def test_canon_error_is_placed_at_its_line(capsys: pytest.CaptureFixture[str], bad: Path) -> None:
    # an error found running a line has a line and no column: no column 1, no caret
    code, out, err = run(capsys, "canon", str(bad))
    assert code == 1
    assert err.splitlines() == [
        f"{bad}:3: {BAD_MESSAGE}",
        "    G2 X2 R0.1",
    ]
    assert "STRAIGHT_FEED(1.0000" in out  # what ran before the error is printed
    assert "ARC_FEED" not in out


def test_canon_missing_file(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    missing = tmp_path / "nope.ngc"
    code, out, err = run(capsys, "canon", str(missing))
    assert (code, out) == (2, "")
    assert err == f"ngc canon: cannot open {missing}: No such file or directory\n"


def test_canon_bad_format(capsys: pytest.CaptureFixture[str], good: Path) -> None:
    code, out, err = run(capsys, "canon", str(good), "--format", "xml")
    assert (code, out) == (2, "")
    assert "invalid choice: 'xml'" in err


# -- ngc check ------------------------------------------------------------------------------------
def test_check_good_file(capsys: pytest.CaptureFixture[str], good: Path) -> None:
    code, out, err = run(capsys, "check", str(good))
    assert (code, err) == (0, "")
    assert out.splitlines() == [
        f"{good}: ok, 10 lines",
        "  moves: 7 (2 traverse, 5 feed, 0 arc)",
        "  rapid length: 3.0000 mm, feed length: 42.0000 mm",
        "  extents: X 0.0000 .. 10.0000  Y 0.0000 .. 10.0000  Z -1.0000 .. 1.0000 mm",
        "  no tool: cuts 42.0000 mm, 0:00:25.200 at the programmed feed",
        "  feed: 100 .. 100 mm/min",
    ]


def test_check_bad_file(capsys: pytest.CaptureFixture[str], bad: Path) -> None:
    """The error on stderr (with its caret), the summary of what ran before it on stdout."""
    code, out, err = run(capsys, "check", str(bad))
    lines = out.splitlines()
    assert code == 1
    assert err.splitlines() == [f"{bad}:3: {BAD_MESSAGE}", "    G2 X2 R0.1"]
    assert lines[0] == f"{bad}: stopped by an error at line 3, 4 lines"
    assert lines[1] == "  moves: 1 (0 traverse, 1 feed, 0 arc)"


def test_check_inch_program_reports_inches(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    path = tmp_path / "inch.ngc"
    path.write_text("G20 F10\nG1 X1\nG0 Y2\nM2\n")
    code, out, _ = run(capsys, "check", str(path))
    assert code == 0
    assert "  rapid length: 2.0000 inch, feed length: 1.0000 inch" in out.splitlines()


def test_check_multiple_files(capsys: pytest.CaptureFixture[str], good: Path, bad: Path) -> None:
    code, out, err = run(capsys, "check", str(good), str(bad), str(good))
    paragraphs = out.split("\n\n")
    assert code == 1
    assert len(paragraphs) == 3
    assert paragraphs[0].startswith(f"{good}: ok")
    assert paragraphs[1].startswith(f"{bad}: stopped by an error at line 3, 4 lines\n")
    assert paragraphs[2].startswith(f"{good}: ok")
    assert err.startswith(f"{bad}:3: {BAD_MESSAGE}\n")


def test_check_missing_file(
    capsys: pytest.CaptureFixture[str], good: Path, bad: Path, tmp_path: Path
) -> None:
    """"cannot open" goes to stderr; stdout holds the reports of the files that were read."""
    missing = tmp_path / "nope.ngc"
    code, out, err = run(capsys, "check", str(bad), str(missing), str(good))
    assert code == 2  # an unreadable file outranks a program error
    assert f"ngc check: cannot open {missing}: No such file or directory" in err.splitlines()
    assert "cannot open" not in out
    assert out.count(": ok, ") == 1


def test_check_needs_a_file(capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = run(capsys, "check")
    assert code == 2
    assert "required: FILE" in err


@pytest.mark.parametrize("example", sorted(EXAMPLES.glob("*.ngc")), ids=lambda p: p.name)
def test_examples_check_clean(capsys: pytest.CaptureFixture[str], example: Path) -> None:
    code, out, _ = run(capsys, "check", str(example))
    assert code == 0, out


# -- dispatch and exit codes ----------------------------------------------------------------------
def test_no_command_is_a_usage_error(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(capsys)
    assert (code, out) == (2, "")
    assert "rs274" in err and "canon" in err and "check" in err


def test_help(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "--help")
    assert code == 0
    assert "usage: ngc" in out


def test_unknown_command(capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = run(capsys, "frobnicate")
    assert code == 2
    assert "invalid choice: 'frobnicate'" in err


def test_rs274_arguments_pass_through_untouched(
    capsys: pytest.CaptureFixture[str], good: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    seen: list[list[str]] = []
    monkeypatch.setattr(rs274, "run", lambda argv: seen.append(argv) or 7)
    argv = ["-g", "--help", "-n", "0", str(good), "canon"]
    assert cli.main(["rs274", *argv]) == 7
    assert seen == [argv]


def test_rs274_runs(capsys: pytest.CaptureFixture[str], good: Path) -> None:
    code, out, err = run(capsys, "rs274", "-g", str(good))
    assert (code, err) == (0, "executing\n")
    assert out.splitlines()[-1].endswith("ON_RESET()")


def test_internal_error_is_not_a_traceback(
    capsys: pytest.CaptureFixture[str], good: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    def broken(*args: object, **kwargs: object) -> None:
        raise ZeroDivisionError("float division by zero")

    monkeypatch.setattr(report, "check_lines", broken)
    code, _, err = run(capsys, "check", str(good))
    assert code == 70
    assert err == "ngc: internal error: ZeroDivisionError: float division by zero\n"


def test_keyboard_interrupt_is_quiet(
    capsys: pytest.CaptureFixture[str], good: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    def interrupted(*args: object, **kwargs: object) -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr(report, "check_lines", interrupted)
    code, _, err = run(capsys, "check", str(good))
    assert (code, err) == (130, "")


def test_escaping_ngc_error_is_reported_normally(
    capsys: pytest.CaptureFixture[str], good: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    def failing(*args: object, **kwargs: object) -> None:
        raise NgcSemanticError("Bad thing", file="x.ngc", line=4, column=2, source="G1 X1")

    monkeypatch.setattr(report, "check_lines", failing)
    code, _, err = run(capsys, "check", str(good))
    assert code == 1
    assert err == "x.ngc:4:2: Bad thing\n    G1 X1\n     ^\n"


def test_console_entry_point_end_to_end(bad: Path) -> None:
    """``python -m ngc`` in a fresh process: exit code and stderr, no traceback."""
    proc = subprocess.run(
        [sys.executable, "-m", "ngc", "canon", str(bad)],
        capture_output=True, text=True, timeout=60, check=False,
    )  # fmt: skip
    assert proc.returncode == 1
    assert proc.stderr.startswith(f"{bad}:3: {BAD_MESSAGE}\n")
    assert "Traceback" not in proc.stderr


def test_canon_passes_undecodable_bytes_through(tmp_path: Path) -> None:
    """Latin-1 comments come out as the same bytes, even where stdout is strict UTF-8."""
    path = tmp_path / "latin1.ngc"
    path.write_bytes(b"(caf\xe9)\nG0 X1\nM2\n")
    proc = subprocess.run(
        [sys.executable, "-m", "ngc", "canon", str(path)],
        capture_output=True, timeout=60, check=False,
        env={**os.environ, "PYTHONIOENCODING": "utf-8:strict"},
    )  # fmt: skip
    assert (proc.returncode, proc.stderr) == (0, b"")
    assert b'COMMENT("caf\xe9")' in proc.stdout


def test_closed_pipe_is_quiet(tmp_path: Path) -> None:
    """``ngc canon big.ngc | head -1``: no traceback, no "Exception ignored" noise."""
    path = tmp_path / "big.ngc"
    path.write_text("G21 F100\n" + "".join(f"G1 X{i % 97}\n" for i in range(20000)) + "M2\n")
    proc = subprocess.Popen(
        [sys.executable, "-m", "ngc", "canon", str(path)],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE,
    )  # fmt: skip
    assert proc.stdout is not None and proc.stderr is not None
    assert proc.stdout.readline().endswith(b"USE_LENGTH_UNITS(CANON_UNITS_MM)\n")
    proc.stdout.close()
    assert proc.wait(timeout=60) == 141
    assert proc.stderr.read() == b""
    proc.stderr.close()


# -- two interpreters in one process --------------------------------------------------------------
def test_two_interpreters_are_independent() -> None:
    """Interleaved lines on two interpreters: units, parameters, offsets, modes stay separate
    (STYLE.md, habit 6: no module-level mutable state)."""
    inch, metric = ListSink(), ListSink()
    a, b = Interpreter(inch), Interpreter(metric)
    a.startup()
    b.startup()
    steps = [
        (a, "G20 G91 F5"),
        (b, "G21 G90 F500"),
        (a, "#1 = 2.5"),
        (b, "#1 = 40"),
        (a, "#<depth> = -0.25"),
        (b, "#<depth> = -3"),
        (a, "G10 L2 P1 X1"),
        (a, "G1 X#1 Z#<depth>"),
        (b, "G1 X#1 Z#<depth>"),
        (a, "G1 X#1"),
        (b, "G1 X#1"),
        (a, "(print,#1 #<depth> #<_metric> #<_incremental> #5221)"),
        (b, "(print,#1 #<depth> #<_metric> #<_incremental> #5221)"),
    ]
    for number, (interp, line) in enumerate(steps, 1):
        interp.execute_line(line, number)

    def moves(sink: ListSink) -> list[tuple[float, float]]:
        return [(op.x, op.z) for op, _, _ in sink.ops if isinstance(op, ops.StraightFeed)]

    def units(sink: ListSink) -> list[str]:
        return [op.units for op, _, _ in sink.ops if isinstance(op, ops.UseLengthUnits)]

    assert moves(inch) == [(1.5, -0.25), (4.0, -0.25)]  # incremental, X origin moved by 1
    assert moves(metric) == [(40.0, -3.0), (40.0, -3.0)]
    assert units(inch) == ["CANON_UNITS_MM", "CANON_UNITS_INCHES"]
    assert units(metric) == ["CANON_UNITS_MM", "CANON_UNITS_MM"]
    assert inch.printed == ["2.500000 -0.250000 0.000000 1.000000 1.000000"]
    assert metric.printed == ["40.000000 -3.000000 1.000000 0.000000 0.000000"]


def test_check_names_the_subroutine_file_an_error_is_in(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "bad.ngc").write_text("o<bad> sub\nG1 X1 F100\nG2 X0 Y0 R0.1\no<bad> endsub\nM2\n")
    (tmp_path / "main.ngc").write_text("G21\no<bad> call\nM2\n")
    monkeypatch.chdir(tmp_path)
    code, out, err = run(capsys, "check", "main.ngc")
    assert code == 1
    assert out.startswith("main.ngc: stopped by an error at line 3 of bad.ngc, 3 lines\n")
    assert err.startswith("bad.ngc:3:")


def test_check_says_a_file_is_empty(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "empty.ngc").write_text("")
    code, out, err = run(capsys, "check", str(tmp_path / "empty.ngc"))
    assert code == 1
    assert out.startswith(f"{tmp_path / 'empty.ngc'}: the file is empty, 0 lines")
    assert err == f"{tmp_path / 'empty.ngc'}: File ended with no percent sign: the file is empty\n"


def test_check_names_the_subroutines_a_file_only_defines(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "subs.ngc").write_text(
        "o<a> sub\nG1 X1 F100\no<a> endsub\no100 sub\nG0 X0\no100 endsub\nM2\n")
    code, out, _ = run(capsys, "check", str(tmp_path / "subs.ngc"))
    assert code == 0
    assert "  no moves: the file defines o<a>, o100 (a subroutine file is checked" in out


def test_check_gives_x_as_a_diameter_in_diameter_mode(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "l.ngc").write_text("G18 G7 G21 G0 X40 Z2\nG1 X10 Z-5 F100\nM2\n")
    (tmp_path / "r.ngc").write_text("G18 G8 G21 G0 X40 Z2\nG1 X10 Z-5 F100\nM2\n")
    _, out, _ = run(capsys, "check", "-j", "1", str(tmp_path / "l.ngc"), str(tmp_path / "r.ngc"))
    lathe, radius = out.split("\n\n")
    assert "extents: X (diameter) 10.0000 .. 40.0000  Y" in lathe
    assert "extents: X 10.0000 .. 40.0000  Y" in radius
    _, out, _ = run(capsys, "check", "--format", "json", str(tmp_path / "l.ngc"))
    record = json.loads(out)
    assert record["x_as_diameter"] is True and record["summary"]["extents"]["high"][0] == 20.0
