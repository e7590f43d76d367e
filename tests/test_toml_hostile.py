"""TOML machine inputs (``--machine``, ``--probe``, ``--setup``) that no reader should choke on:
bytes that are not UTF-8, nesting deeper than the reader goes, integers past 64 bits.  Each is a
clean error naming the file and the problem, exit 2."""

from __future__ import annotations

from pathlib import Path

import pytest

from cli_helpers import run, write
from ngc.errors import NgcConfigError
from ngc.planner.config import machine_from_toml

DEEP = "a = " + "[" * 5000 + "]" * 5000 + "\n"


@pytest.mark.parametrize(("text", "problem"), [
    (DEEP, "arrays or tables nested too deeply"),
    ("a = " + "{b = " * 3000 + "1" + "}" * 3000 + "\n", "arrays or tables nested too deeply"),
    (b"servo_period = 0.001\n\x80\n", "not UTF-8 text: byte 0x80 at offset 21"),
    (b"\xff\xfe", "not UTF-8 text: byte 0xff at offset 0"),
    ("servo_period = 1" + "0" * 400 + "\n", "an integer outside TOML's 64-bit range"),
    ("[start]\nX = -1" + "0" * 30 + "\n", "an integer outside TOML's 64-bit range"),
    ("servo_period = 1" + "0" * 5000 + "\n", "an integer of thousands of digits"),
], ids=["arrays", "tables", "byte 0x80", "byte 0xff", "401 digits", "31 digits", "5001 digits"])
@pytest.mark.parametrize("option", ["--machine", "--probe", "--setup"])
def test_a_toml_file_no_reader_takes_is_a_clean_error(
        capsys: pytest.CaptureFixture[str], tmp_path: Path, text: str | bytes, problem: str,
        option: str) -> None:
    toml = write(tmp_path, "f.toml", text)
    path = write(tmp_path, "p.ngc", "G0 X1\nM2\n")
    command = "check" if option == "--setup" else "time"
    code, out, err = run(capsys, command, option, toml, path)
    what = {"--machine": "machine file", "--probe": "probe file", "--setup": "setup file"}[option]
    assert (code, out) == (2, "")
    assert err.startswith(f"ngc {command}: {what} {toml}: {problem}")
    assert "Traceback" not in err


def test_a_toml_machine_file_in_the_library(tmp_path: Path) -> None:
    with pytest.raises(NgcConfigError, match="nested too deeply"):
        machine_from_toml(write(tmp_path, "m.toml", DEEP))


def test_a_64_bit_integer_is_read(tmp_path: Path) -> None:
    path = write(tmp_path, "m.toml", "tool_change_time = 9223372036854775807\n")
    with pytest.raises(NgcConfigError, match="tool_change_time"):
        machine_from_toml(path)  # read, then refused as a time out of range
