"""One contract for every command: the machine inputs (``-i``, ``-t``, ``-v``,
``--max-iterations``) and ``-`` on ``canon`` and ``check``; ``check`` writes nothing and reports
on stderr; strict JSON; encodings that never crash; the byte-order mark; ``ngc rs274 --help``
and rs274's own messages; the library's ``interpret`` and ``help(ngc)``."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import threading
from pathlib import Path

import pytest

import ngc
from cli_helpers import run
from ngc import options
from ngc.canon import ops
from ngc.canon.jsonl import JsonSink, dumps, text_of
from ngc.commands import rs274
from ngc.errors import NgcConfigError

SRC = Path(__file__).resolve().parent.parent / "src"

LOOP = "o1 while [1]\no1 endwhile\nM2\n"
GOOD = "G21 F100\nG1 X10\nM2\n"
STARTUP = [
    "USE_LENGTH_UNITS(CANON_UNITS_MM)",
    "SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)",
    "SET_G92_OFFSET(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)",
    "SET_XY_ROTATION(0.0000)",
    "SET_FEED_REFERENCE(CANON_XYZ)",
]


def ngc_process(*argv: str | bytes, cwd: Path, env: dict[str, str] | None = None,
                stdin: bytes = b"") -> subprocess.CompletedProcess[bytes]:
    """``python -m ngc argv...`` in a fresh process (bytes in, bytes out)."""
    environ = {**os.environ, "PYTHONPATH": str(SRC), **(env or {})}
    return subprocess.run([sys.executable, "-m", "ngc", *argv], input=stdin, cwd=cwd,
                          capture_output=True, env=environ, timeout=60, check=False)


def calls(transcript: str) -> list[str]:
    """The calls of a transcript, without the counter and N columns."""
    return [line[13:] for line in transcript.splitlines()]


def strict_json(line: str | bytes) -> object:
    """Parse one line as strict JSON in strict UTF-8, refusing Infinity/NaN and lone surrogates."""
    if isinstance(line, bytes):
        line = line.decode("utf-8")  # strict

    def refuse(name: str) -> object:
        raise ValueError(f"not JSON: {name}")

    value = json.loads(line, parse_constant=refuse)
    json.dumps(value, ensure_ascii=False).encode("utf-8")  # strict: no lone surrogate survives
    return value


@pytest.fixture
def work(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.chdir(tmp_path)
    return tmp_path


# -- --max-iterations ------------------------------------------------------------------------------
@pytest.mark.parametrize("command", ["canon", "check"])
def test_max_iterations_before_the_file(capsys: pytest.CaptureFixture[str], work: Path,
                                        command: str) -> None:
    """``N`` is the option's value, not a file name; the error names the option it has."""
    (work / "loop.ngc").write_text(LOOP)
    code, _, err = run(capsys, command, "--max-iterations", "100", "loop.ngc")
    assert code == 1
    assert err.splitlines()[0] == (
        "loop.ngc:2: Work limit reached: 100 loop iterations and subroutine calls; the program "
        "looks like it runs forever (raise the limit with --max-iterations)"
    )


@pytest.mark.parametrize("command", ["canon", "check"])
@pytest.mark.parametrize("value", ["0", "-3", "ten", "1e3", "٣"])
def test_max_iterations_needs_a_positive_number(capsys: pytest.CaptureFixture[str], work: Path,
                                                command: str, value: str) -> None:
    (work / "f.ngc").write_text(GOOD)
    code, out, err = run(capsys, command, f"--max-iterations={value}", "f.ngc")
    assert (code, out) == (2, "")
    assert "argument --max-iterations: needs a positive number" in err


def test_max_iterations_enough_for_the_program(capsys: pytest.CaptureFixture[str],
                                               work: Path) -> None:
    (work / "count.ngc").write_text("#1=0\no1 while [#1 LT 50]\n#1=[#1+1]\no1 endwhile\nM2\n")
    assert run(capsys, "check", "--max-iterations", "50", "count.ngc")[0] == 0
    assert run(capsys, "check", "--max-iterations", "49", "count.ngc")[0] == 1


# -- -i INI --------------------------------------------------------------------------------------
@pytest.fixture
def ini_case(work: Path) -> Path:
    """A subroutine in a folder named by the INI file's SUBROUTINE_PATH, and an INI parameter."""
    (work / "subs").mkdir()
    (work / "subs" / "lift.ngc").write_text("o<lift> sub\nG0 Z#1\no<lift> endsub\nM2\n")
    (work / "machine.ini").write_text("[RS274NGC]\nSUBROUTINE_PATH = subs\n[JOB]\nSAFE = 7\n")
    (work / "job.ngc").write_text("o<lift> call [#<_ini[job]safe>]\nM2\n")
    return work


def test_canon_applies_the_ini_file(capsys: pytest.CaptureFixture[str], ini_case: Path) -> None:
    code, out, err = run(capsys, "canon", "-i", "machine.ini", "job.ngc")
    assert (code, err) == (0, "")
    assert "STRAIGHT_TRAVERSE(0.0000, 0.0000, 7.0000, 0.0000, 0.0000, 0.0000)" in calls(out)
    code, _, err = run(capsys, "canon", "job.ngc")  # without it, neither is known
    assert code == 1


def test_check_applies_the_ini_file(capsys: pytest.CaptureFixture[str], ini_case: Path) -> None:
    code, out, err = run(capsys, "check", "-i", "machine.ini", "job.ngc")
    assert (code, err) == (0, "")
    assert "  rapid length: 7.0000 mm, feed length: 0.0000 mm" in out.splitlines()


def test_canon_matches_rs274_with_ini_and_var_file(capsys: pytest.CaptureFixture[str],
                                                   ini_case: Path) -> None:
    """The three commands build their interpreter the same way: same calls for the same inputs
    (rs274 adds ON_RESET calls around the program)."""
    (ini_case / "offsets.var").write_text("5221 2.5\n5222 -1\n")
    _, canon, _ = run(capsys, "canon", "-i", "machine.ini", "-v", "offsets.var", "job.ngc")
    _, transcript, _ = run(capsys, "rs274", "-g", "-i", "machine.ini", "-v", "offsets.var",
                           "job.ngc")
    assert calls(canon) == [c for c in calls(transcript) if c != "ON_RESET()"]
    # rs274 reads a parameter file in inches: 2.5 in = 63.5 mm
    assert calls(canon)[1] == "SET_G5X_OFFSET(1, 63.5000, -25.4000, 0.0000, 0.0000, 0.0000, 0.0000)"


def test_ini_settings_messages_are_warnings(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    (work / "bad.ini").write_text("[RS274NGC]\nCENTER_ARC_RADIUS_TOLERANCE_MM = -1\n")
    (work / "f.ngc").write_text(GOOD)
    code, _, err = run(capsys, "check", "-i", "bad.ini", "f.ngc")
    assert code == 0
    assert err == ("ngc check: warning: invalid [RS274NGC]CENTER_ARC_RADIUS_TOLERANCE_MM "
                   "in INI file\n")


# -- -v VARS -------------------------------------------------------------------------------------
@pytest.mark.parametrize("command", ["canon", "check"])
def test_var_file_is_read_never_written(capsys: pytest.CaptureFixture[str], work: Path,
                                        command: str) -> None:
    var = work / "params.var"
    var.write_text("31 4.5\n5221 10\n")
    (work / "f.ngc").write_text("G21 F100\nG1 X#31\n#31 = 99\nM2\n")
    before = (var.read_bytes(), var.stat().st_mtime_ns)
    code, out, err = run(capsys, command, "-v", "params.var", "f.ngc")
    assert (code, err) == (0, "")
    assert (var.read_bytes(), var.stat().st_mtime_ns) == before
    assert sorted(p.name for p in work.iterdir()) == ["f.ngc", "params.var"]  # no backup, no temp
    if command == "canon":
        assert "STRAIGHT_FEED(4.5000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)" in calls(out)
    else:
        # (the feed starts at the machine origin, X-254 in G54 with X offset 10 inches)
        assert "  extents: X -254.0000 .. 4.5000  Y 0.0000 .. 0.0000  Z 0.0000 .. 0.0000 mm" in out


def test_rs274_writes_the_var_file_back(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    var = work / "params.var"
    var.write_text("31 4.5\n")
    (work / "f.ngc").write_text("#31 = 99\nM2\n")
    assert run(capsys, "rs274", "-g", "-v", "params.var", "f.ngc")[0] == 0
    assert "31\t99.000000\n" in var.read_text()


def test_bad_var_file(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    (work / "bad.var").write_text("99999 1\n")
    (work / "f.ngc").write_text(GOOD)
    code, out, err = run(capsys, "canon", "-v", "bad.var", "f.ngc")
    assert (code, out) == (2, "")
    assert err == "ngc canon: parameter file bad.var: Parameter number out of range\n"


# -- files given to -i, -t, -v --------------------------------------------------------------------
@pytest.mark.parametrize("command", ["canon", "check"])
@pytest.mark.parametrize(("flag", "what"), [("-i", "INI file"), ("-t", "tool table"),
                                            ("-v", "parameter file")])
def test_missing_input_file(capsys: pytest.CaptureFixture[str], work: Path, command: str,
                            flag: str, what: str) -> None:
    (work / "f.ngc").write_text(GOOD)
    code, out, err = run(capsys, command, flag, "nope", "f.ngc")
    assert (code, out) == (2, "")
    assert err == f"ngc {command}: cannot open {what} nope: No such file or directory\n"


@pytest.mark.parametrize(("flag", "what"), [("-i", "INI file"), ("-t", "tool table"),
                                            ("-v", "parameter file")])
def test_input_that_is_not_a_regular_file(capsys: pytest.CaptureFixture[str], work: Path,
                                          flag: str, what: str) -> None:
    """A directory, and a FIFO with no writer (which must not block)."""
    (work / "f.ngc").write_text(GOOD)
    (work / "folder").mkdir()
    os.mkfifo(work / "fifo")
    for name in ("folder", "fifo"):
        code, out, err = run(capsys, "check", flag, name, "f.ngc")
        assert (code, out) == (2, "")
        assert err == f"ngc check: {what} {name} is not a regular file\n"


def test_tool_table_is_kept_for_later(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    (work / "tools.tbl").write_text("T1 P1 D0.125 ;end mill\n")
    (work / "f.ngc").write_text(GOOD)
    assert run(capsys, "canon", "-t", "tools.tbl", "f.ngc")[0] == 0
    assert run(capsys, "check", "-t", "tools.tbl", "f.ngc")[0] == 0
    assert rs274.parse_args(["-t", "tools.tbl", "f.ngc"]).machine().tool_table == "tools.tbl"


def test_load_setup_and_new_interpreter(work: Path) -> None:
    (work / "p.var").write_text("5221 3\n")
    machine = options.MachineOptions(var_file="p.var", max_iterations=7)
    setup = options.load_setup(machine)
    assert setup.parameters == {5221: 3.0}
    interp = options.new_interpreter(ngc.canon.jsonl.ListSink(), machine, setup,
                                     write_files=False)
    assert interp.flow.max_iterations == 7
    assert interp.state.g5x[0] == pytest.approx(76.2)  # parameter files hold inches
    assert interp.machine.write_files is False
    with pytest.raises(NgcConfigError, match=r"cannot open INI file x\.ini"):
        options.load_setup(options.MachineOptions(ini_file="x.ini"))


# -- - (standard input) --------------------------------------------------------------------------
@pytest.fixture
def stdin_program(work: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    path = work / "stdin.ngc"
    path.write_bytes(b"\xef\xbb\xbfG21 F100\nG1 X3\nM2\n")
    handle = open(path, "rb")  # noqa: SIM115 (closed at teardown)
    monkeypatch.setattr(sys, "stdin", handle)
    yield
    handle.close()


@pytest.mark.usefixtures("stdin_program")
def test_canon_reads_standard_input(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(capsys, "canon", "-")
    assert (code, err) == (0, "")
    assert "STRAIGHT_FEED(3.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)" in calls(out)


@pytest.mark.usefixtures("stdin_program")
def test_check_reads_standard_input(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(capsys, "check", "--format", "json", "-")
    record = strict_json(out)
    assert (code, err) == (0, "")
    assert isinstance(record, dict)
    assert (record["file"], record["lines"]) == ("<stdin>", 3)


def test_stdin_error_is_named(work: Path) -> None:
    proc = ngc_process("check", "-", cwd=work, stdin=b"G1 X1\nM2\n")
    assert proc.returncode == 1
    assert proc.stderr.startswith(b"<stdin>:1: Cannot do g1 with zero feed rate\n")


# -- ngc check: nothing written, errors on stderr ------------------------------------------------
def test_check_writes_nothing(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    (work / "log.ngc").write_text("(LOGOPEN,run.log)\n(LOG,hello)\n(LOGCLOSE)\n"
                                  "(PROBEOPEN probe.txt)\n(PROBECLOSE)\nM2\n")
    code, _, err = run(capsys, "check", "log.ngc")
    assert (code, err) == (0, "")
    assert sorted(p.name for p in work.iterdir()) == ["log.ngc"]
    assert ngc.check_file(work / "log.ngc").ok
    assert sorted(p.name for p in work.iterdir()) == ["log.ngc"]


def test_canon_still_writes_log_files(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    (work / "log.ngc").write_text("(LOGOPEN,run.log)\n(LOG,hello)\n(LOGCLOSE)\nM2\n")
    assert run(capsys, "canon", "log.ngc")[0] == 0
    assert (work / "run.log").read_text() == "hello\n"


def test_check_json(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    (work / "good.ngc").write_text("G20 F10\nG1 X1\nG0 Y2\nM2\n")
    (work / "bad.ngc").write_text("G21 F100\nG1 X1\nG2 X2 R0.1\nM2\n")
    code, out, err = run(capsys, "check", "--format", "json", "good.ngc", "nope.ngc", "bad.ngc")
    records = [strict_json(line) for line in out.splitlines()]
    assert code == 2
    assert records[0] == {
        "file": "good.ngc", "ok": True, "lines": 4, "error": None,
        "summary": {"units": "inch", "moves": 2, "traverses": 1, "feeds": 1, "arcs": 0,
                    "rapid_length": 2.0, "feed_length": 1.0, "mixed_units": False,
                    "extents": {"low": [0.0, 0.0, 0.0], "high": [1.0, 2.0, 0.0]},
                    # (F10 runs before G20 on its line: 10 mm/min, as LinuxCNC feeds it)
                    "tools": [{"tool": 0, "diameter": None, "length": None, "cut_length": 1.0,
                               "cut_seconds": pytest.approx(152.4)}],
                    "feed_per_minute": [pytest.approx(10 / 25.4)] * 2, "feed_per_rev": None,
                    "spindle_rpm": None, "surface_speed": None},
    }  # fmt: skip
    assert records[1] == {
        "file": "nope.ngc", "ok": False, "lines": None, "summary": None,
        "error": {"message": "cannot open: No such file or directory", "about": None,
                  "file": "nope.ngc", "line": None, "column": None, "source": None},
    }  # fmt: skip
    assert isinstance(records[2], dict)
    assert records[2]["error"] == {
        "message": "Arc radius too small to reach end point", "about": None, "file": "bad.ngc",
        "line": 3, "column": None, "source": "G2 X2 R0.1",
    }  # fmt: skip
    assert err.splitlines() == [
        "ngc check: cannot open nope.ngc: No such file or directory",
        "bad.ngc:3: Arc radius too small to reach end point", "    G2 X2 R0.1",
    ]  # fmt: skip


# -- strict JSON and UTF-8 -----------------------------------------------------------------------
NOT_UTF8 = b"(caf\xe9)\n(print,na\xefve \xff)\n(msg,\xe2\x82\xac ok)\nG0 X1\nM2\n"


def test_canon_json_is_strict_with_bytes_that_are_not_utf8(work: Path) -> None:
    (work / "latin1.ngc").write_bytes(NOT_UTF8)
    proc = ngc_process("canon", "--format", "json", "latin1.ngc", cwd=work)
    assert (proc.returncode, proc.stderr) == (0, b"")
    records = [strict_json(line) for line in proc.stdout.splitlines()]
    texts = [r.get("text") for r in records if isinstance(r, dict) and "text" in r]
    assert texts == ["caf\\xe9", "na\\xefve \\xff", "€ ok"]


@pytest.mark.parametrize("command", [["canon", "--format", "json"], ["check", "--format", "json"]])
def test_json_of_huge_numbers_is_strict(work: Path, command: list[str]) -> None:
    """Whatever the interpreter makes of an overflow (an error, or an infinity), the output is
    strict JSON."""
    (work / "huge.ngc").write_text("G21 F100\nG0 X[EXP[710]]\nG1 Y[0-EXP[710]]\nM2\n")
    proc = ngc_process(*command, "huge.ngc", cwd=work)
    assert proc.returncode in (0, 1)
    for line in proc.stdout.splitlines():
        strict_json(line)


def test_json_sink_non_finite_numbers_are_null() -> None:
    lines: list[str] = []

    class Collect:
        def write(self, text: str) -> int:
            lines.append(text)
            return len(text)

    sink = JsonSink(Collect())  # type: ignore[arg-type]
    sink.emit(ops.StraightFeed(float("inf"), float("-inf"), float("nan"), 0.0, 0.0, 0.0), "N10  ", 3)
    sink.print_text("x\udcff")
    assert [strict_json(line) for line in lines] == [
        {"op": "STRAIGHT_FEED", "line": 3, "n": 10, "x": None, "y": None, "z": None,
         "a": 0.0, "b": 0.0, "c": 0.0},
        {"op": "PRINT", "text": "x\\xff"},
    ]  # fmt: skip


def test_json_text_escapes() -> None:
    assert text_of("plain €") == "plain €"
    assert text_of("a\udc80b\udcffc") == "a\\x80b\\xffc"
    assert text_of("\ud800") == "\\ud800"  # not from a byte: only an API caller can make one
    assert dumps({"s": "\\udc80 is text"}) == '{"s": "\\\\udc80 is text"}'
    assert strict_json(dumps({"k\udce9": [1.5, float("nan")]})) == {"k\\xe9": [1.5, None]}


def test_check_json_of_an_infinite_summary() -> None:
    from ngc.commands import check as report

    summary = report.Summary("mm", 1, 0, 0, float("inf"), 0.0,
                             report.Extents((float("inf"), 0.0, 0.0), (float("inf"), 0.0, 0.0)),
                             False)
    record = report.record(report.CheckResult("x.ngc", 2, summary, None))
    assert strict_json(dumps(record)) == {
        "file": "x.ngc", "ok": True, "lines": 2, "error": None,
        "summary": {"units": "mm", "moves": 1, "traverses": 1, "feeds": 0, "arcs": 0,
                    "rapid_length": None, "feed_length": 0.0, "mixed_units": False,
                    "extents": {"low": [None, 0.0, 0.0], "high": [None, 0.0, 0.0]},
                    "tools": [], "feed_per_minute": None, "feed_per_rev": None,
                    "spindle_rpm": None, "surface_speed": None},
    }  # fmt: skip


# -- encodings never crash -----------------------------------------------------------------------
EURO = "\u20ac"


@pytest.mark.parametrize("name", [f"{EURO}.ngc", "caf\udce9.ngc"], ids=["euro", "latin1-byte"])
def test_rs274_file_names_are_bytes(work: Path, name: str) -> None:
    raw = os.fsencode(name)
    (work / name).write_text("o<nosuch> call\nM2\n")
    proc = ngc_process("rs274", "-g", raw, cwd=work)
    assert proc.returncode == 1
    assert proc.stderr == (b"executing\nEOF in file:" + raw
                           + b" seeking o-word: o<nosuch> from line: 1\nM2\n")
    (work / name).write_text("G0 X1\nM2\n")
    assert ngc_process("rs274", "-g", raw, cwd=work).returncode == 0
    missing = b"missing-" + raw
    proc = ngc_process("rs274", "-g", missing, cwd=work)
    assert proc.returncode == 1
    assert proc.stderr == b"executing\nUnable to open file <" + missing + b">\n\n"
    proc = ngc_process("rs274", "-g", "-i", missing, raw, b"/nonexistent/" + raw, cwd=work)
    assert proc.stderr == b"executing\ncould not open output file /nonexistent/" + raw + b"\n"


def test_rs274_ini_and_var_file_names_are_bytes(work: Path) -> None:
    (work / "f.ngc").write_text("G0 X1\nM2\n")
    ini = os.fsencode(f"{EURO}.ini")
    proc = ngc_process("rs274", "-g", "-i", ini, "f.ngc", cwd=work)
    assert proc.returncode == 0
    assert proc.stderr == b"executing\nUnable to open inifile:" + ini + b":\n"


@pytest.mark.parametrize("encoding", ["ascii", "latin-1", "utf-8:strict", "cp1252"])
@pytest.mark.parametrize("command", ["canon", "check"])
def test_any_stdout_encoding(work: Path, encoding: str, command: str) -> None:
    """Comments and file names go out as the bytes they came in as, whatever the encoding."""
    name = f"{EURO}-caf\u00e9.ngc"
    raw = os.fsencode(name)
    (work / name).write_bytes(b"(caf\xc3\xa9 \xe2\x82\xac)\n(latin \xe9)\nG1 X1\nM2\n")
    proc = ngc_process(command, raw, cwd=work, env={"PYTHONIOENCODING": encoding})
    assert proc.returncode == 1  # G1 with no feed rate, on line 3
    assert proc.stderr.startswith(raw + b":3: Cannot do g1 with zero feed rate\n")
    if command == "canon":
        assert b'COMMENT("caf\xc3\xa9 \xe2\x82\xac")' in proc.stdout
        assert b'COMMENT("latin \xe9")' in proc.stdout
    else:
        assert proc.stdout.startswith(raw + b": stopped by an error at line 3, 4 lines\n")


def test_check_cannot_open_a_name_that_is_not_utf8(work: Path) -> None:
    raw = b"caf\xe9.ngc"
    proc = ngc_process("check", raw, cwd=work, env={"PYTHONIOENCODING": "ascii"})
    assert proc.returncode == 2
    assert proc.stderr == b"ngc check: cannot open " + raw + b": No such file or directory\n"


# -- the byte-order mark -------------------------------------------------------------------------
BOM = b"\xef\xbb\xbf"


def test_rs274_stops_on_a_byte_order_mark_as_rs274_does(work: Path) -> None:
    (work / "bom.ngc").write_bytes(BOM + b"G0 X1\nM2\n")
    proc = ngc_process("rs274", "-g", "bom.ngc", cwd=work)
    assert proc.returncode == 1
    assert proc.stderr == b"executing\nBad character '\\357' used\n" + BOM + b"G0 X1\n"
    assert [line[13:] for line in proc.stdout.decode().splitlines()] == [
        *STARTUP, "ON_RESET()", "ON_RESET()", "ON_RESET()",
    ]


def test_canon_and_check_skip_a_byte_order_mark(capsys: pytest.CaptureFixture[str],
                                                work: Path) -> None:
    (work / "bom.ngc").write_bytes(BOM + b"G0 X1\nG1 X2\nM2\n")
    code, out, err = run(capsys, "canon", "bom.ngc")
    assert code == 1
    assert calls(out)[5] == "STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)"
    assert err.splitlines()[0] == "bom.ngc:2: Cannot do g1 with zero feed rate"
    code, out, _ = run(capsys, "check", "bom.ngc")
    assert out.startswith("bom.ngc: stopped by an error at line 2, 3 lines\n")
    assert ngc.check_file(work / "bom.ngc").summary.traverses == 1


def test_only_a_leading_byte_order_mark_is_skipped(capsys: pytest.CaptureFixture[str],
                                                   work: Path) -> None:
    (work / "bom.ngc").write_bytes(b"G0 X1\n" + BOM + b"G0 X2\nM2\n")
    code, _, err = run(capsys, "canon", "bom.ngc")
    assert code == 1
    assert err.startswith("bom.ngc:2:1: ")


# -- ngc rs274: help and rs274's own messages ----------------------------------------------------
@pytest.mark.parametrize("flag", ["--help", "-h", "--he"])
def test_rs274_help(capsys: pytest.CaptureFixture[str], flag: str) -> None:
    code, out, err = run(capsys, "rs274", flag)
    assert (code, err) == (0, "")
    assert out == rs274.HELP
    for option in ("-t FILE", "-v FILE", "-i FILE", "-n 0|1|2", "-b ", "-s ", "-g ", "-p FILE",
                   "--max-iterations N", "-h, --help"):
        assert f"\n    {option}" in out, option
    assert "default 10000000" in out


def test_ngc_help_lists_every_command_option(capsys: pytest.CaptureFixture[str]) -> None:
    for command in ("canon", "check"):
        code, out, _ = run(capsys, command, "--help")
        assert code == 0
        for option in ("-i INI", "-t TOOLS", "-v VARS", "--max-iterations N", "--format",
                       "byte-order mark", "progress"):
            assert option in out.replace("\n", " ").replace("  ", " "), (command, option)


# rs274's stderr for a bad command line (recorded from LinuxCNC 2.9.0~pre1's rs274).
RS274_BAD_OPTIONS = [
    (["-x", "f.ngc"], "rs274: invalid option -- 'x'\n"),
    (["-g", "-n"], "rs274: option requires an argument -- 'n'\n"),
    (["--foo"], "rs274: invalid option -- '-'\n"),
    (["-g", "f.ngc", "--bar"], "rs274: invalid option -- '-'\n"),
]


@pytest.mark.parametrize(("argv", "first"), RS274_BAD_OPTIONS)
def test_rs274_bad_option_as_rs274(capsys: pytest.CaptureFixture[str], argv: list[str],
                                   first: str) -> None:
    code, out, err = run(capsys, "rs274", *argv)
    assert (code, out) == (1, "")
    assert err == first + rs274.USAGE
    assert rs274.USAGE.endswith("    -l: specify the log_level (default: -1)\n")


def test_rs274_missing_program_as_rs274(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    """rs274 starts the interpreter, then cannot open the program: no ON_RESET, exit 1; the
    parameter file was saved at the start."""
    code, out, err = run(capsys, "rs274", "-g", "-v", "p.var", "nope.ngc")
    assert code == 1
    assert calls(out) == STARTUP
    assert err == ("executing\nlink (updating variable file): No such file or directory\n"
                   "Unable to open file <nope.ngc>\n\n")
    assert (work / "p.var").exists()


def test_rs274_output_file_that_cannot_be_opened(capsys: pytest.CaptureFixture[str],
                                                 work: Path) -> None:
    (work / "f.ngc").write_text(GOOD)
    code, out, err = run(capsys, "rs274", "-g", "-i", "nope.ini", "f.ngc", "no/such/out.txt")
    assert (code, out) == (1, "")
    assert err == "executing\ncould not open output file no/such/out.txt\n"


def test_rs274_directory_reads_as_an_empty_program(capsys: pytest.CaptureFixture[str],
                                                   work: Path) -> None:
    (work / "folder.ngc").mkdir()
    code, out, err = run(capsys, "rs274", "-g", "folder.ngc")
    assert code == 1
    assert calls(out) == STARTUP
    assert err == "executing\nFile ended with no percent sign\n\n"


def test_rs274_max_iterations(capsys: pytest.CaptureFixture[str], work: Path) -> None:
    (work / "loop.ngc").write_text(LOOP)
    code, _, err = run(capsys, "rs274", "-g", "--max-iterations", "10", "loop.ngc")
    assert code == 1
    assert "Work limit reached: 10 loop iterations" in err
    code, _, err = run(capsys, "rs274", "-g", "--max-iterations=x", "loop.ngc")
    assert code == 1
    assert err.startswith("ngc rs274: --max-iterations needs a positive number\n")


# -- the library ---------------------------------------------------------------------------------
def test_interpret_flushes_its_sink(work: Path) -> None:
    script = ("import sys, ngc\nfrom ngc.canon.text import TextSink\n"
              "ngc.interpret('G0 X1\\nM2\\n', TextSink(sys.stdout))\n")
    proc = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                          env={**os.environ, "PYTHONPATH": str(SRC)}, timeout=60, check=True)
    assert calls(proc.stdout)[5] == (
        "STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)")
    assert calls(proc.stdout)[-1] == "PROGRAM_END()"


def test_interpret_flushes_its_sink_on_error() -> None:
    flushed = threading.Event()

    class Sink(ngc.canon.jsonl.ListSink):
        def flush(self) -> None:
            flushed.set()

    with pytest.raises(ngc.NgcError, match="zero feed rate"):
        ngc.interpret("G0 X1\nG1 X2\nM2\n", Sink())
    assert flushed.is_set()


def test_help_lists_the_public_api_only() -> None:
    proc = subprocess.run([sys.executable, "-c", "import ngc; help(ngc)"], capture_output=True,
                          text=True, env={**os.environ, "PYTHONPATH": str(SRC), "PAGER": "cat"},
                          timeout=60, check=True)
    text = proc.stdout
    for name in ngc.__all__:
        assert f"class {name}(" in text or f"\n    {name}(" in text, name
    sections = text.split("\nCLASSES\n", 1)[1].split("\nVERSION\n", 1)[0]
    listed = [line.strip() for line in sections.splitlines()
              if line.startswith("    ") and not line.startswith("     ")]
    for entry in listed:
        assert not entry.startswith("_") or entry.startswith("__all__"), entry
    assert "__getattr__" not in text and "_REPORT" not in text and "_Package" not in text
    assert "interpret(" in text and "DESCRIPTION" in text


def test_lazy_names_are_real() -> None:
    from ngc.commands import check as report

    assert ngc.check_file is report.check_file
    assert ngc.Summary is report.Summary
    assert set(ngc.__all__) <= set(dir(ngc))
    with pytest.raises(AttributeError, match="no attribute 'nothing'"):
        ngc.nothing  # type: ignore[attr-defined]  # noqa: B018


@pytest.mark.parametrize(("data", "shown"), [
    (b"G21\n(\xe9)\nG0 X1 \xe9\nM2\n", b"'\\351'"),  # a byte that is not UTF-8: the byte
    (b"G21\nG0 X1 \xe2\x80\x94\nM2\n", b"'\\342'"),  # an em dash: its first byte, as rs274 reads it
])
def test_a_bad_character_is_shown_as_rs274_shows_its_byte(tmp_path: Path, data: bytes,
                                                          shown: bytes) -> None:
    path = tmp_path / "p.ngc"
    path.write_bytes(data)
    for command in ("check", "canon"):
        done = subprocess.run([sys.executable, "-m", "ngc", command, str(path)],
                              capture_output=True, check=False)
        assert done.returncode == 1
        assert b"Bad character " + shown + b" used" in done.stderr


@pytest.mark.parametrize("command", [["check"], ["check", "--format", "json"], ["time"],
                                     ["time", "--format", "json"]])
def test_jobs_give_the_output_of_one_job(tmp_path: Path, command: list[str]) -> None:
    """``-j 2`` runs files on two processes; stdout, stderr and the exit code are -j 1's."""
    names = []
    for i in range(7):
        text = f"G21 G1 X{i + 1} F600\nM2\n" if i != 3 else "G1 X1 F100\nG2 X0 Y0 R0.1\nM2\n"
        (tmp_path / f"p{i}.ngc").write_text(text)
        names.append(f"p{i}.ngc")
    names.insert(5, "missing.ngc")
    runs = [subprocess.run([sys.executable, "-m", "ngc", *command, "-j", jobs, *names],
                           cwd=tmp_path, capture_output=True, check=False)
            for jobs in ("1", "2")]
    assert runs[0].returncode == runs[1].returncode == 2
    assert runs[0].stdout == runs[1].stdout and runs[0].stdout.count(b"p6.ngc") >= 1
    assert runs[0].stderr == runs[1].stderr
