"""Messages that name the problem: ``check``, ``canon`` and ``time`` give rs274's message and then
what it is about (the unknown code, a character that is not ASCII by its Unicode name), with the
caret under the word; an error found running a line has no column; ``ngc rs274`` keeps rs274's
text.  rs274's own words here were recorded from rs274 (LinuxCNC 2.9)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from ngc.errors import NgcError, describe_char, word_column


def _ngc(cwd: Path, *argv: str) -> subprocess.CompletedProcess[bytes]:
    return subprocess.run([sys.executable, "-m", "ngc", *argv], cwd=cwd, capture_output=True,
                          timeout=60)


def _write(tmp_path: Path, name: str, data: bytes) -> str:
    (tmp_path / name).write_bytes(data)
    return name


@pytest.mark.parametrize("command", ["check", "canon", "time"])
def test_unknown_g_code_names_the_code_and_the_caret_stands_under_it(
        tmp_path: Path, command: str) -> None:
    name = _write(tmp_path, "g78.ngc", b"G21\nG0 X1\n   G78 X2\nM2\n")
    err = _ngc(tmp_path, command, name).stderr.decode()
    assert err.splitlines()[-3:] == ["g78.ngc:3:4: Unknown g code used: G78",
                                     "       G78 X2", "       ^"]


def test_rs274_keeps_rs274s_text(tmp_path: Path) -> None:
    name = _write(tmp_path, "g78.ngc", b"G21\nG0 X1\n   G78 X2\nM2\n")
    err = _ngc(tmp_path, "rs274", "-g", name).stderr.decode()
    assert "Unknown g code used\n   G78 X2\n" in err  # rs274's two lines, nothing added


def test_a_pasted_dash_is_named(tmp_path: Path) -> None:
    name = _write(tmp_path, "dash.ngc", "G21\nG0 X\u20135\nM2\n".encode())
    err = _ngc(tmp_path, "check", name).stderr.decode()
    assert err.splitlines() == [
        "dash.ngc:2:5: bad number format (conversion failed) parsing '': "
        "'\u2013' (EN DASH, U+2013)",
        "    G0 X\u20135", "        ^"]


@pytest.mark.parametrize(("data", "rs274_says", "about"), [
    (b"G21\n(\xe9)\nG0 X1 \xe9\nM2\n", "'\\351'", "the byte 0xE9, which is not UTF-8 text"),
    (b"G21\nG0 X1 \xc3\xa9\nM2\n", "'\\303'", "'\u00e9' (LATIN SMALL LETTER E WITH ACUTE, U+00E9)"),
    (b"G21\nG0 X1 \xe2\x80\x94\nM2\n", "'\\342'", "'\u2014' (EM DASH, U+2014)"),
])
def test_a_bad_character_is_shown_by_its_byte_then_named(
        tmp_path: Path, data: bytes, rs274_says: str, about: str) -> None:
    name = _write(tmp_path, "bad.ngc", data)
    err = _ngc(tmp_path, "check", name).stderr.decode("utf-8", "replace")
    first = err.splitlines()[0]
    assert first.endswith(f": Bad character {rs274_says} used: {about}")
    assert err.splitlines()[2] == "          ^"  # under the character (column 7)
    record = json.loads(_ngc(tmp_path, "check", "--format", "json", name).stdout)["error"]
    assert record["message"] == f"Bad character {rs274_says} used"
    assert record["about"] == about and record["column"] == 7


def test_an_error_found_running_a_line_has_no_column(tmp_path: Path) -> None:
    name = _write(tmp_path, "nof.ngc", b"G21\n  G1 X1\nM2\n")
    proc = _ngc(tmp_path, "check", name)
    assert proc.stderr.decode().splitlines() == [
        "nof.ngc:2: Cannot do g1 with zero feed rate", "      G1 X1"]
    record = json.loads(_ngc(tmp_path, "check", "--format", "json", name).stdout)["error"]
    assert record["column"] is None and record["line"] == 2 and record["about"] is None


def test_where_and_render_without_a_column() -> None:
    error = NgcError("Cannot do g1 with zero feed rate", file="a.ngc", line=4, source="G1 X1")
    assert error.where() == "a.ngc:4"
    assert error.render() == "a.ngc:4: Cannot do g1 with zero feed rate\n    G1 X1"


@pytest.mark.parametrize(("line", "expected"), [
    ("G0 X1 F-1", "2:7: Negative f word used: F-1"),
    ("G0 X1 G1 X2", "2:7: Two g codes used from same modal group: G1"),
    ("M3 M4 S100", "2:4: Two m codes used from same modal group: M4"),
    ("G1000", "2:1: G-code out of range: G1000"),
])
def test_a_word_error_names_the_word(tmp_path: Path, line: str, expected: str) -> None:
    name = _write(tmp_path, "w.ngc", f"G21\n{line}\nM2\n".encode())
    err = _ngc(tmp_path, "check", name).stderr.decode()
    assert err.splitlines()[0] == f"w.ngc:{expected}"


def test_word_column() -> None:
    assert word_column("G0 (G78) g 7 8 X1", "g", 78.0) == 10  # not in the comment; spaced digits
    assert word_column("G0 X1 G0 X2", "g", 0.0) == 7  # the second of two: the one refused
    assert word_column("G#1 X2", "g", 78.0) == 1  # not a literal: the first such word
    assert word_column("X2", "g", 78.0) is None


def test_describe_char() -> None:
    assert describe_char("\u2013") == "'\u2013' (EN DASH, U+2013)"
    assert describe_char("\udce9") == "the byte 0xE9, which is not UTF-8 text"
    assert describe_char("\x85") == "a control character (U+0085)"
