"""The machine inputs read as the machine the INI describes reads them (``check``, ``canon``,
``time``, ``plot``, :class:`ngc.Program`): the tool table and the parameter file's offsets in its
units, subroutine files where it finds them (PROGRAM_PREFIX and SUBROUTINE_PATH from the INI
file's folder, and next to the program), a tool the table lacks named with what to do about it.
``ngc rs274`` reads them as rs274 does; what rs274 printed for the same inputs (LinuxCNC 2.9) is
written down here."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

import ngc
from ngc.options import LINEAR_OFFSETS, MachineOptions, load_setup, search_path

METRIC = "[TRAJ]\nLINEAR_UNITS = mm\n"
INCH = "[TRAJ]\nLINEAR_UNITS = inch\n"
TOOL_CHANGE = "G21\nT5 M6\nG43\nG0 X1\nM2\n"


def _ngc(cwd: Path, *argv: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "ngc", *argv], cwd=cwd, capture_output=True,
                          text=True, timeout=120)


@pytest.fixture
def machine(tmp_path: Path) -> Path:
    (tmp_path / "metric.ini").write_text(METRIC)
    (tmp_path / "inch.ini").write_text(INCH)
    (tmp_path / "tools.tbl").write_text("T5 P5 D6.0 Z10 ;five\n")
    (tmp_path / "p.ngc").write_text(TOOL_CHANGE)
    return tmp_path


def _offset_line(out: str) -> str:
    return next(line.split("N..... ")[1] for line in out.splitlines()
                if "USE_TOOL_LENGTH_OFFSET" in line)


@pytest.mark.parametrize(("ini", "z"), [(["-i", "metric.ini"], "10.0000"),
                                        (["-i", "inch.ini"], "254.0000"),
                                        ([], "254.0000")])
def test_the_tool_table_is_in_the_machines_units(machine: Path, ini: list[str], z: str) -> None:
    out = _ngc(machine, "canon", *ini, "-t", "tools.tbl", "p.ngc").stdout
    assert _offset_line(out) == (f"USE_TOOL_LENGTH_OFFSET(0.0000 0.0000 {z}, 0.0000 0.0000 0.0000, "
                                 "0.0000 0.0000 0.0000)")


def test_rs274_reads_the_tool_table_in_inches_whatever_the_ini(machine: Path) -> None:
    # rs274 -i metric.ini -t tools.tbl -g p.ngc printed 254.0000 (its standalone machine is inch)
    out = _ngc(machine, "rs274", "-i", "metric.ini", "-t", "tools.tbl", "-g", "p.ngc").stdout
    assert _offset_line(out) == ("USE_TOOL_LENGTH_OFFSET(0.0000 0.0000 254.0000, 0.0000 0.0000 "
                                 "0.0000, 0.0000 0.0000 0.0000)")


def test_the_tool_length_moves_the_machine_in_its_units(machine: Path) -> None:
    program = ngc.Program.load(str(machine / "p.ngc"), tools=str(machine / "tools.tbl"),
                               ini=str(machine / "metric.ini"))
    moves = list(program.moves())
    assert moves[-1].end[2] == pytest.approx(0.0) and moves[-1].tool_offset[2] == pytest.approx(10)


def test_the_parameter_files_offsets_are_in_the_machines_units(machine: Path) -> None:
    (machine / "p.var").write_text("5221 10\n5224 90\n5230 30\n")  # G54 X 10, A 90, rotation 30
    (machine / "v.ngc").write_text("G21\nG0 X0\nM2\n")
    out = _ngc(machine, "canon", "-i", "metric.ini", "-v", "p.var", "v.ngc").stdout
    assert "SET_G5X_OFFSET(1, 10.0000, 0.0000, 0.0000, 90.0000, 0.0000, 0.0000)" in out
    assert "SET_XY_ROTATION(30.0000)" in out
    # rs274 -i metric.ini -v p.var printed SET_G5X_OFFSET(1, 254.0000, ...)
    out = _ngc(machine, "rs274", "-i", "metric.ini", "-v", "p.var", "-g", "v.ngc").stdout
    assert "SET_G5X_OFFSET(1, 254.0000, 0.0000, 0.0000, 90.0000, 0.0000, 0.0000)" in out


def test_linear_offsets() -> None:
    assert {5161, 5163, 5167, 5211, 5221, 5229, 5381, 5389} <= LINEAR_OFFSETS
    assert not {5164, 5210, 5220, 5224, 5230, 5390, 5400} & LINEAR_OFFSETS


def test_a_missing_tool_says_what_to_do(machine: Path) -> None:
    proc = _ngc(machine, "check", "p.ngc")
    assert proc.returncode == 1
    assert proc.stderr.splitlines() == [
        "p.ngc:2:1: Requested tool 5 not found in the tool table: give the machine's tool table "
        "with -t FILE (without it, rs274's sample table: tools 1, 2, 3 and 99999), or --any-tool "
        "to take a tool it lacks as one with no offsets",
        "    T5 M6", "    ^"]
    assert "Requested tool 5 not found in the tool table\n" in _ngc(
        machine, "rs274", "-g", "p.ngc").stderr  # rs274's text alone


@pytest.mark.parametrize("command", ["check", "canon", "time"])
def test_any_tool_takes_an_unknown_tool_with_a_warning(machine: Path, command: str) -> None:
    (machine / "q.ngc").write_text("G21\nT5 M6\nG43\nG0 X1\nT7 M6\nT5 M6\nG41 D7 G1 X5 F100\n"
                                   "G40 G0 X0\nM2\n")
    proc = _ngc(machine, command, "--any-tool", "q.ngc")
    assert proc.returncode == 0, proc.stderr
    assert proc.stderr == "".join(
        f"ngc {command}: warning: tool {n} is not in the tool table: taken as a tool with no "
        "offsets and no diameter (--any-tool)\n" for n in (5, 7))


def test_search_path_order(tmp_path: Path) -> None:
    (tmp_path / "cfg" / "subs").mkdir(parents=True)
    (tmp_path / "prefix").mkdir()
    (tmp_path / "cfg" / "m.ini").write_text(
        "[DISPLAY]\nPROGRAM_PREFIX = ../prefix\n[RS274NGC]\nSUBROUTINE_PATH = subs\n")
    setup = load_setup(MachineOptions(ini_file=str(tmp_path / "cfg" / "m.ini")))
    assert search_path(setup, "parts/a.ngc") == [
        str(tmp_path / "cfg"), str(tmp_path / "prefix"), str(tmp_path / "cfg" / "subs"),
        "parts", "."]


@pytest.fixture
def shop(tmp_path: Path) -> Path:
    """A machine folder with an INI naming a prefix and a subroutine folder, and a part folder
    with a program calling three subroutine files: one in each place, one next to it."""
    for folder in ("cfg/subs", "nc", "parts"):
        (tmp_path / folder).mkdir(parents=True)
    (tmp_path / "cfg" / "mill.ini").write_text(
        METRIC + "[DISPLAY]\nPROGRAM_PREFIX = ../nc\n[RS274NGC]\nSUBROUTINE_PATH = subs\n")
    for where, name, x in (("nc", "a", 1), ("cfg/subs", "b", 2), ("parts", "c", 3)):
        (tmp_path / where / f"{name}.ngc").write_text(
            f"o<{name}> sub\nG0 X{x}\no<{name}> endsub\nM2\n")
    (tmp_path / "parts" / "main.ngc").write_text(
        "G21\no<a> call\no<b> call\no<c> call\nM2\n")
    return tmp_path


@pytest.mark.parametrize("cwd", [".", "parts", "cfg"])
def test_subroutine_files_are_found_as_the_machine_finds_them(shop: Path, cwd: str) -> None:
    main = str(shop / "parts" / "main.ngc")
    ini = str(shop / "cfg" / "mill.ini")
    proc = _ngc(shop / cwd, "check", "-i", ini, main)
    assert proc.returncode == 0, proc.stderr
    assert "moves: 3 (3 traverse" in proc.stdout
    out = _ngc(shop / cwd, "canon", "-i", ini, main).stdout
    assert [line.split("(")[1].split(",")[0] for line in out.splitlines()
            if "STRAIGHT_TRAVERSE" in line] == ["1.0000", "2.0000", "3.0000"]


def test_a_subroutine_next_to_the_program_from_the_parent_folder(shop: Path) -> None:
    (shop / "parts" / "solo.ngc").write_text("G21\no<c> call\nM2\n")
    proc = _ngc(shop, "check", "parts/solo.ngc")
    assert proc.returncode == 0, proc.stderr
    # rs274 -g parts/solo.ngc, run from the parent folder: its working directory only
    err = _ngc(shop, "rs274", "-g", "parts/solo.ngc").stderr
    assert "EOF in file:parts/solo.ngc seeking o-word: o<c> from line: 2" in err


def test_rs274_searches_the_program_prefix(shop: Path) -> None:
    """rs274 searches its working directory, then PROGRAM_PREFIX (relative to the working
    directory, ``~`` expanded), then SUBROUTINE_PATH (observed with LinuxCNC 2.9)."""
    (shop / "cfg" / "rs.ini").write_text("[DISPLAY]\nPROGRAM_PREFIX = nc\n")
    (shop / "x.ngc").write_text("G21\no<a> call\nM2\n")
    out = _ngc(shop, "rs274", "-i", "cfg/rs.ini", "-g", "x.ngc").stdout
    assert "STRAIGHT_TRAVERSE(1.0000, 0.0000" in out
    (shop / "a.ngc").write_text("o<a> sub\nG0 X9\no<a> endsub\nM2\n")  # the working directory's
    out = _ngc(shop, "rs274", "-i", "cfg/rs.ini", "-g", "x.ngc").stdout
    assert "STRAIGHT_TRAVERSE(9.0000, 0.0000" in out


@pytest.mark.parametrize("command", ["check", "time", "plot"])
def test_a_file_that_only_defines_subroutines_says_so(shop: Path, command: str) -> None:
    extra = ["-o", str(shop / "a.svg")] if command == "plot" else []
    proc = _ngc(shop, command, "nc/a.ngc", *extra)
    assert proc.returncode == 0
    expected = ("nc/a.ngc moves nothing: it defines o<a> (a subroutine file is run through a "
                "program that calls it)")
    if command == "check":
        assert "no moves: the file defines o<a>" in proc.stdout
    else:
        assert proc.stderr == f"ngc {command}: warning: {expected}\n"
