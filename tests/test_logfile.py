"""The log comments (LOGOPEN, LOGAPPEND, LOG, LOGCLOSE), the probe log (PROBEOPEN, PROBECLOSE) and
the confinement of the files they write to the working directory.

rs274 writes no file for these comments: it prints the canonical calls (``LOGOPEN("name")``,
``LOG("text")``, ...; PROBEOPEN / PROBECLOSE as ``COMMENT``).  The expected transcripts below are
what rs274 printed for the same programs; each LOG line's text plus a newline is what ngc writes.
"""

from __future__ import annotations

import io
import os
from collections.abc import Iterator
from pathlib import Path

import pytest

from ngc.canon import ops
from ngc.canon.jsonl import ListSink
from ngc.commands import rs274
from ngc.errors import NgcRuntimeError
from ngc.interp.handlers import logfile
from ngc.interp.interpreter import Interpreter


@pytest.fixture
def cwd(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """An empty working directory, with a sibling ``outside`` folder next to it."""
    work = tmp_path / "work"
    work.mkdir()
    (tmp_path / "outside").mkdir()
    monkeypatch.chdir(work)
    return work


def run(program: str) -> tuple[int, str, str]:
    """``rs274 -g prog.ngc`` in the working directory: exit code, stdout, stderr."""
    Path("prog.ngc").write_text(program, encoding="latin-1")
    out, err = io.StringIO(), io.StringIO()
    code = rs274.run(["-g", "prog.ngc"], stdout=out, stderr=err)
    return code, out.getvalue(), err.getvalue()


def program_part(out: str) -> list[str]:
    """The transcript lines of the program: after the start-up ON_RESET, before the end resets."""
    lines = out.splitlines()[6:]
    for i, line in enumerate(lines):
        if "SET_G5X_OFFSET" in line or "ON_RESET" in line:
            return lines[:i]
    return lines


def files(folder: Path) -> set[str]:
    return {p.name for p in folder.iterdir()}


# -- LOG ------------------------------------------------------------------------------------------
BASIC = """#1=3.5
(LOGOPEN,log.txt)
(LOG,hello #1 world)
(LOG,  spaced %d#1 x)
(LOG,)
(LOG,#<_x> #<nosuch> %.2f#1)
(LOG,"quoted" back\\slash %%)
(LOGCLOSE)
(LOG,after close)
M2
"""
# rs274 printed these for BASIC.
BASIC_RS274 = [
    '    7 N..... LOGOPEN("log.txt")',
    '    8 N..... LOG("hello 3.500000 world")',
    '    9 N..... LOG("  spaced 4 x")',
    '   10 N..... LOG("")',
    '   11 N..... LOG("0.000000 ###### 3.50")',
    '   12 N..... LOG(""quoted" back\\slash %%")',
    "   13 N..... LOGCLOSE()",
    '   14 N..... LOG("after close")',
]


def test_log_writes_each_text_and_a_newline(cwd: Path) -> None:
    code, out, err = run(BASIC)
    assert (code, err) == (0, "executing\n")
    assert program_part(out) == BASIC_RS274
    assert (cwd / "log.txt").read_bytes() == (
        b'hello 3.500000 world\n  spaced 4 x\n\n0.000000 ###### 3.50\n"quoted" back\\slash %%\n'
    )


def test_log_without_an_open_log_only_prints_the_call(cwd: Path) -> None:
    code, out, _ = run("(LOG,nothing open)\n(LOGCLOSE)\nM2\n")
    assert code == 0
    assert program_part(out) == ['    7 N..... LOG("nothing open")', "    8 N..... LOGCLOSE()"]
    assert files(cwd) == {"prog.ngc"}


def test_logopen_truncates_and_logappend_appends(cwd: Path) -> None:
    (cwd / "a.txt").write_bytes(b"old\n")
    (cwd / "t.txt").write_bytes(b"old\n")
    code, out, _ = run("(LOGAPPEND,a.txt)\n(LOG,one)\n(LOGCLOSE)\n(LOGOPEN,t.txt)\n(LOG,two)\nM2\n")
    assert code == 0
    assert program_part(out)[0] == '    7 N..... LOGAPPEND("a.txt")'
    assert (cwd / "a.txt").read_bytes() == b"old\none\n"
    assert (cwd / "t.txt").read_bytes() == b"two\n"


def test_a_second_logopen_switches_files(cwd: Path) -> None:
    code, _, _ = run("(LOGOPEN,a.txt)\n(LOG,1)\n(LOGOPEN,b.txt)\n(LOG,2)\n(LOGCLOSE)\nM2\n")
    assert code == 0
    assert (cwd / "a.txt").read_bytes() == b"1\n"
    assert (cwd / "b.txt").read_bytes() == b"2\n"


FORMS = """(logopen,lower.txt)
(  LogAppend,mixed.txt)
(\tLOG,tab before)
(LOG,\ttab after)
(LOG)
(LOG x)
(LOG ,space before comma)
(L O G,spaced)
(LOGOPENx,y)
(LOGCLOSE )
(LOGCLOSE,)
(LOGCLOSE extra)
(LOG,a)(foo)
(foo)(LOG,b)
G0 X1 ;(LOG,semi)
N10 G0 X2 (LOG,numbered)
(  logclose)
M2
"""
# rs274 printed these for FORMS.
FORMS_RS274 = [
    '    7 N..... LOGOPEN("lower.txt")',
    '    8 N..... LOGAPPEND("mixed.txt")',
    '    9 N..... LOG("tab before")',
    '   10 N..... LOG("\ttab after")',
    '   11 N..... COMMENT("LOG")',
    '   12 N..... COMMENT("LOG x")',
    '   13 N..... COMMENT("LOG ,space before comma")',
    '   14 N..... COMMENT("L O G,spaced")',
    '   15 N..... COMMENT("LOGOPENx,y")',
    '   16 N..... COMMENT("LOGCLOSE ")',
    '   17 N..... COMMENT("LOGCLOSE,")',
    '   18 N..... COMMENT("LOGCLOSE extra")',
    '   19 N..... COMMENT("foo")',
    '   20 N..... LOG("b")',
    "   21 N..... STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)",
    '   22 N10    LOG("numbered")',
    "   23 N10    STRAIGHT_TRAVERSE(2.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)",
    "   24 N..... LOGCLOSE()",
]


def test_keyword_any_case_after_white_space_and_only_the_last_comment(cwd: Path) -> None:
    code, out, _ = run(FORMS)
    assert code == 0
    assert program_part(out) == FORMS_RS274
    assert (cwd / "lower.txt").read_bytes() == b""
    assert (cwd / "mixed.txt").read_bytes() == b"tab before\n\ttab after\nb\nnumbered\n"


def test_the_log_is_complete_when_the_program_stops_on_an_error(cwd: Path) -> None:
    # rs274 prints the block's LOG before the motion fails.
    code, out, err = run("(LOGOPEN,e.txt)\n(LOG,before error)\nG1 X3 F0 (LOG,error line)\nM2\n")
    assert code == 1
    assert err == "executing\nCannot do g1 with zero feed rate\nG1 X3 F0 (LOG,error line)\n"
    assert program_part(out) == [
        '    7 N..... LOGOPEN("e.txt")',
        '    8 N..... LOG("before error")',
        '    9 N..... LOG("error line")',
        "   10 N..... SET_FEED_RATE(0.0000)",
    ]
    assert (cwd / "e.txt").read_bytes() == b"before error\nerror line\n"


def test_the_log_is_complete_at_program_end_without_logclose(cwd: Path) -> None:
    code, _, _ = run("(LOGOPEN,m.txt)\n(LOG,kept)\nM2\n")
    assert code == 0
    assert (cwd / "m.txt").read_bytes() == b"kept\n"


def test_log_bytes_pass_through_unchanged(cwd: Path) -> None:
    code, out, _ = run("(LOGOPEN,u.txt)\n(LOG,caf\xc3\xa9 \xe9)\nM2\n")  # UTF-8 e-acute, latin-1 one
    assert code == 0
    assert program_part(out)[1] == '    8 N..... LOG("caf\xc3\xa9 \xe9")'  # rs274 printed these bytes
    assert (cwd / "u.txt").read_bytes() == b"caf\xc3\xa9 \xe9\n"


# -- parameter substitution (shared with DEBUG, PRINT, ABORT) -------------------------------------
SUBSTITUTION = """#1=7
#2=1.23456789
(LOGOPEN,s.txt)
(LOG,a#0 b#5601 c#5602 d#4294967297 e#18446744073709551617 f#2147483648)
(LOG,g#-1 h#+1 i# 1 j#000001)
(LOG,k%.x#2 l%.%d#2 m%.12f#2 n%.3f#2 o%5.2f#2)
(LOG,p%d#<_nosuch> %d)
(PRINT,q#0 #5602 %.x#2)
M2
"""
# rs274 printed these for SUBSTITUTION: #0 reads 0, numbers out of range read ######, the number is
# taken modulo 2**32, and a "%" before a "." that starts no format is dropped.
SUBSTITUTION_RS274 = [
    "q0.000000 ###### .x1.234568",
    '    7 N..... LOGOPEN("s.txt")',
    '    8 N..... LOG("a0.000000 b0.000000 c###### d7.000000 e###### f######")',
    '    9 N..... LOG("g#-1 h#+1 i# 1 j7.000000")',
    '   10 N..... LOG("k.x1.234568 l.1 m.12f1 n1.235 o%5.2f1.235")',
    '   11 N..... LOG("p###### ")',
]


def test_substitution_like_rs274(cwd: Path) -> None:
    code, out, _ = run(SUBSTITUTION)
    assert code == 0
    assert sorted(program_part(out)) == sorted(SUBSTITUTION_RS274)
    assert (cwd / "s.txt").read_bytes() == b"".join(
        line.split('LOG("', 1)[1][:-2].encode() + b"\n" for line in SUBSTITUTION_RS274[2:]
    )


# -- the probe log --------------------------------------------------------------------------------
PROBE = """(PROBEOPEN probe.txt)
(probeopen  p3.txt )
(PROBEOPEN,p2.txt)
(PROBECLOSE)
(PROBECLOSE,x)
M2
"""
# rs274 printed these for PROBE: the probe log comments are ordinary comments to it.
PROBE_RS274 = [
    '    7 N..... COMMENT("PROBEOPEN probe.txt")',
    '    8 N..... COMMENT("probeopen  p3.txt ")',
    '    9 N..... COMMENT("PROBEOPEN,p2.txt")',
    '   10 N..... COMMENT("PROBECLOSE")',
    '   11 N..... COMMENT("PROBECLOSE,x")',
]


def test_probeopen_opens_and_probeclose_closes(cwd: Path) -> None:
    code, out, _ = run(PROBE)
    assert code == 0
    assert program_part(out) == PROBE_RS274
    # A comma is not the documented form: p2.txt is not opened.
    assert files(cwd) == {"prog.ngc", "probe.txt", "p3.txt"}
    assert (cwd / "probe.txt").read_bytes() == b""


def interpreter(*lines: str) -> Interpreter:
    interp = Interpreter(ListSink())
    for number, line in enumerate(lines, 1):
        interp.execute_line(line, number)
    return interp


def test_write_probe_logs_nine_coordinates_per_line(cwd: Path) -> None:
    interp = interpreter("(PROBEOPEN p.txt)")
    logfile.write_probe(interp, [1.0, -2.5, 3.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.125])
    logfile.write_probe(interp, [0.0] * 9)
    assert (cwd / "p.txt").read_bytes() == (
        b"1.000000 -2.500000 3.000000 0.000000 0.000000 0.000000 0.000000 0.000000 0.125000\n"
        + b" ".join([b"0.000000"] * 9)
        + b"\n"
    )
    interp.execute_line("(PROBECLOSE)", 2)
    assert interp.probe_log is None
    logfile.write_probe(interp, [9.0] * 9)
    assert (cwd / "p.txt").read_bytes().count(b"\n") == 2


def test_a_second_probeopen_truncates_its_file_and_closes_the_first(cwd: Path) -> None:
    (cwd / "b.txt").write_bytes(b"old\n")
    interp = interpreter("(PROBEOPEN a.txt)", "(PROBEOPEN b.txt)")
    logfile.write_probe(interp, [1.0] * 9)
    assert (cwd / "a.txt").read_bytes() == b""
    assert (cwd / "b.txt").read_bytes() == b" ".join([b"1.000000"] * 9) + b"\n"


def test_close_releases_the_files(cwd: Path) -> None:
    interp = interpreter("(LOGOPEN,l.txt)", "(PROBEOPEN p.txt)")
    log, probe = interp.log, interp.probe_log
    assert log is not None and probe is not None
    interp.close()
    assert (interp.log, interp.probe_log) == (None, None)
    assert log.closed and probe.closed


def test_log_ops_reach_the_sink(cwd: Path) -> None:
    interp = interpreter("(LOGOPEN,l.txt)", "(LOGAPPEND,m.txt)", "(LOG,x #<_y>)", "(LOGCLOSE)")
    assert isinstance(interp.sink, ListSink)
    assert [op for op, _, _ in interp.sink.ops] == [
        ops.LogOpen("l.txt"), ops.LogAppend("m.txt"), ops.Log("x 0.000000"), ops.LogClose()
    ]


# -- errors ---------------------------------------------------------------------------------------
@pytest.fixture
def links(cwd: Path) -> Iterator[Path]:
    """``out`` -> the outside folder, ``escape.txt`` -> a file outside, ``in`` -> ``sub``."""
    (cwd / "sub").mkdir()
    os.symlink(cwd.parent / "outside", cwd / "out")
    os.symlink(cwd.parent / "outside" / "x.txt", cwd / "escape.txt")
    os.symlink(cwd / "sub", cwd / "in")
    yield cwd


OUTSIDE = ["../x.txt", "sub/../../x.txt", "out/x.txt", "escape.txt", "in/../../outside/x.txt"]


@pytest.mark.parametrize("command", ["LOGOPEN,", "LOGAPPEND,", "PROBEOPEN "])
@pytest.mark.parametrize("name", OUTSIDE)
def test_files_outside_the_working_directory_are_refused(links: Path, command: str, name: str) -> None:
    source = f"({command}{name})"
    code, out, err = run(f"(LOG,first)\n{source}\nM2\n")
    keyword = command[:-1]
    assert code == 1
    assert err == f"executing\n{keyword}: file '{name}' is outside the working directory\n{source}\n"
    assert program_part(out) == ['    7 N..... LOG("first")']
    assert files(links.parent / "outside") == set()


@pytest.mark.parametrize("command", ["LOGOPEN,", "LOGAPPEND,", "PROBEOPEN "])
def test_absolute_names_are_refused_even_inside(cwd: Path, command: str) -> None:
    name = str(cwd / "x.txt")
    code, _, err = run(f"({command}{name})\nM2\n")
    assert code == 1
    assert err.splitlines()[1] == (
        f"{command[:-1]}: file '{name}' is an absolute path; only files in the working directory "
        "can be written"
    )
    assert files(cwd) == {"prog.ngc"}


@pytest.mark.parametrize("name", ["sub/x.txt", "in/x.txt", "./sub/../y.txt"])
def test_names_inside_the_working_directory_are_allowed(links: Path, name: str) -> None:
    code, _, err = run(f"(LOGOPEN,{name})\n(LOG,ok)\nM2\n")
    assert (code, err) == (0, "executing\n")
    assert (links / name).read_bytes() == b"ok\n"


@pytest.mark.parametrize(
    ("source", "message"),
    [
        ("(LOGOPEN,)", "LOGOPEN: no file name"),
        ("(LOGAPPEND,  )", "LOGAPPEND: no file name"),
        ("(PROBEOPEN)", "PROBEOPEN: no file name"),
        ("(PROBEOPEN   )", "PROBEOPEN: no file name"),
        ("(LOGOPEN,nodir/x.txt)", "LOGOPEN: cannot open 'nodir/x.txt': No such file or directory"),
        ("(LOGAPPEND,sub)", "LOGAPPEND: cannot open 'sub': Is a directory"),
        ("(PROBEOPEN nodir/p.txt)", "PROBEOPEN: cannot open 'nodir/p.txt': No such file or directory"),
    ],
)
def test_names_that_cannot_be_opened_are_errors(cwd: Path, source: str, message: str) -> None:
    (cwd / "sub").mkdir()
    code, out, err = run(f"{source}\nM2\n")
    assert code == 1
    assert err == f"executing\n{message}\n{source}\n"
    assert program_part(out) == []


class FullFile(io.StringIO):
    name = "full.txt"

    def write(self, text: str) -> int:
        raise OSError(28, "No space left on device")


def test_a_failed_write_is_an_error_at_the_line(cwd: Path) -> None:
    interp = Interpreter(ListSink())
    interp.machine.log = FullFile()
    with pytest.raises(NgcRuntimeError) as caught:
        interp.run(["G0 X1", "(LOG,x)", "M2"])
    assert caught.value.message == "LOG: cannot write 'full.txt': No space left on device"
    assert (caught.value.line, caught.value.source) == (2, "(LOG,x)")


def test_write_files_false_emits_the_calls_and_writes_nothing(cwd: Path) -> None:
    sink = ListSink()
    interp = Interpreter(sink, write_files=False)
    interp.run(["(LOGOPEN,a.txt)", "(LOG,hello)", "(LOGAPPEND,b.txt)", "(LOGCLOSE)",
                "(PROBEOPEN c.txt)", "(PROBECLOSE)", "M2"])
    names = [type(op).__name__ for op, _, _ in sink.ops]
    assert names[:4] == ["LogOpen", "Log", "LogAppend", "LogClose"]
    assert os.listdir(cwd) == []


# -- only regular files with one link -------------------------------------------------------------
COMMANDS = ["LOGOPEN,", "LOGAPPEND,", "PROBEOPEN "]


def refused(command: str, name: str, why: str) -> tuple[int, str]:
    """What a refused file prints: exit 1 and ``KEYWORD: 'name' why`` at the line."""
    source = f"({command}{name})"
    return 1, f"executing\n{command[:-1]}: '{name}' {why}\n{source}\n"


@pytest.mark.parametrize("command", COMMANDS)
def test_a_fifo_is_refused_without_blocking(cwd: Path, command: str) -> None:
    os.mkfifo(cwd / "fifo")
    code, _, err = run(f"({command}fifo)\nM2\n")
    assert (code, err) == refused(command, "fifo", "is not a regular file")


@pytest.mark.parametrize("command", COMMANDS)
def test_a_fifo_with_a_reader_is_refused_and_gets_nothing(cwd: Path, command: str) -> None:
    os.mkfifo(cwd / "fifo")
    reader = os.open(cwd / "fifo", os.O_RDONLY | os.O_NONBLOCK)
    try:
        code, _, err = run(f"({command}fifo)\n(LOG,x)\nM2\n")
        assert (code, err) == refused(command, "fifo", "is not a regular file")
        assert os.read(reader, 10) == b""  # end of file: nothing written, no writer left
    finally:
        os.close(reader)


@pytest.mark.parametrize("command", COMMANDS)
def test_a_device_is_refused(monkeypatch: pytest.MonkeyPatch, command: str) -> None:
    monkeypatch.chdir("/dev")  # a program there may name the device null
    interp = Interpreter(ListSink())
    with pytest.raises(NgcRuntimeError) as caught:
        interp.execute_line(f"({command}null)", 1)
    assert caught.value.message == f"{command[:-1]}: 'null' is not a regular file"
    assert (interp.machine.log, interp.machine.probe_log) == (None, None)


@pytest.mark.parametrize("command", COMMANDS)
def test_a_hard_link_to_a_file_outside_is_refused_and_left_alone(cwd: Path, command: str) -> None:
    outside = cwd.parent / "outside" / "f"
    outside.write_bytes(b"precious\n")
    os.link(outside, cwd / "x")
    code, _, err = run(f"({command}x)\n(LOG,overwrite)\nM2\n")
    assert (code, err) == refused(command, "x", "has other hard links")
    assert outside.read_bytes() == b"precious\n"
    assert os.stat(outside).st_nlink == 2


def test_a_hard_link_inside_is_refused_too(cwd: Path) -> None:
    (cwd / "a").write_bytes(b"old\n")
    os.link(cwd / "a", cwd / "b")
    code, _, err = run("(LOGOPEN,b)\nM2\n")
    assert (code, err) == refused("LOGOPEN,", "b", "has other hard links")
    assert (cwd / "a").read_bytes() == b"old\n"


def test_a_file_whose_other_link_is_gone_is_written(cwd: Path) -> None:
    (cwd / "a").write_bytes(b"old\n")
    os.link(cwd / "a", cwd / "b")
    os.unlink(cwd / "a")
    code, _, err = run("(LOGAPPEND,b)\n(LOG,new)\nM2\n")
    assert (code, err) == (0, "executing\n")
    assert (cwd / "b").read_bytes() == b"old\nnew\n"


@pytest.fixture
def blind_lstat(monkeypatch: pytest.MonkeyPatch) -> None:
    """The name changes between the first look and the open: only the open descriptor tells."""

    def missing(path: object) -> os.stat_result:
        raise FileNotFoundError(2, "No such file or directory")

    monkeypatch.setattr(logfile.os, "lstat", missing)


@pytest.mark.parametrize("command", ["LOGOPEN", "LOGAPPEND", "PROBEOPEN"])
def test_what_is_opened_is_checked_again(cwd: Path, blind_lstat: None, command: str) -> None:
    os.mkfifo(cwd / "fifo")
    os.symlink(cwd / "target", cwd / "link")
    (cwd / "a").write_bytes(b"old\n")
    os.link(cwd / "a", cwd / "b")
    reader = os.open(cwd / "fifo", os.O_RDONLY | os.O_NONBLOCK)
    try:
        for name, why in [("fifo", "is not a regular file"), ("b", "has other hard links")]:
            with pytest.raises(NgcRuntimeError) as caught:
                logfile.open_log(command, name, str(cwd / name), append=False)
            assert caught.value.message == f"{command}: '{name}' {why}"
    finally:
        os.close(reader)
    for name in ["fifo", "link"]:  # a FIFO without a reader, a symbolic link put in since
        with pytest.raises(NgcRuntimeError) as caught:
            logfile.open_log(command, name, str(cwd / name), append=True)
        assert caught.value.message == f"{command}: '{name}' is not a regular file"
    assert (cwd / "a").read_bytes() == b"old\n"
    assert not (cwd / "target").exists()


def test_a_file_that_cannot_be_truncated_is_an_error(cwd: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    (cwd / "a.txt").write_bytes(b"old\n")

    def refuse(fd: int, length: int) -> None:
        raise PermissionError(1, "Operation not permitted")

    monkeypatch.setattr(logfile.os, "ftruncate", refuse)
    code, _, err = run("(LOGOPEN,a.txt)\nM2\n")
    assert (code, err) == (
        1, "executing\nLOGOPEN: cannot open 'a.txt': Operation not permitted\n(LOGOPEN,a.txt)\n"
    )
    assert (cwd / "a.txt").read_bytes() == b"old\n"


def test_write_files_false_opens_no_fifo(cwd: Path) -> None:
    os.mkfifo(cwd / "fifo")
    interp = Interpreter(ListSink(), write_files=False)
    interp.run(["(LOGOPEN,fifo)", "(LOGAPPEND,fifo)", "(PROBEOPEN fifo)", "M2"])
    assert (interp.machine.log, interp.machine.probe_log) == (None, None)


def test_a_file_name_is_the_bytes_the_program_holds(cwd: Path) -> None:
    # rs274 reads the program as bytes: "€" is three of them, and names the file "€.log".
    Path("prog.ngc").write_bytes("(LOGOPEN,€.log)\n(LOG,hi)\n(LOGCLOSE)\nM2\n".encode())
    out, err = io.StringIO(), io.StringIO()
    assert rs274.run(["-g", "prog.ngc"], stdout=out, stderr=err) == 0
    assert (cwd / "€.log").read_text() == "hi\n"
