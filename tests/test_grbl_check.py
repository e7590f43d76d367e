"""``ngc check --dialect grbl`` and :mod:`ngc.grbl`: each error Grbl 1.1 answers in check mode
from a minimal program, programs it accepts whole, the state carried from line to line, what its
line reader keeps of a line, its numbers in single precision, and the command line."""

from __future__ import annotations

import doctest
import io
import json
from pathlib import Path

import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

import ngc.grbl
from cli_helpers import run, write
from ngc.grbl import GRBL, Grbl, Rules, check_text, codes, lines, numbers
from ngc.grbl import check as grbl_check
from ngc.grbl.lines import PIECE_CHARS, kept, read_lines

ROOT = Path(__file__).resolve().parent.parent


def rejected(program: str, rules: Rules = GRBL) -> list[tuple[int, int]]:
    """(line, code) of each line Grbl rejects."""
    return [(error.line, error.code) for error in check_text(program, rules)]


# -- each error, from a minimal program -------------------------------------------------------------
ERRORS = [
    # 1: a character that is not a letter where a word starts
    ("%\nG0 X1\n%\n", [(1, 1), (3, 1)]),
    ("G0 X1.2.3\n", [(1, 1)]),  # the number ends at the second point; '.3' starts no word
    ("#1=5\n", [(1, 1)]),
    ("G0 X[1+2]\n", [(1, 2)]),  # X has no digits before '['
    ("G0 X1 )\n", [(1, 1)]),  # a ')' outside a comment is kept
    # 2: a word with no number
    ("G0 X\n", [(1, 2)]),
    ("G0 X-\n", [(1, 2)]),
    ("G0 X.\n", [(1, 2)]),
    ("G0 X+-1\n", [(1, 2)]),
    # 4: F N P S T negative
    ("F-1\n", [(1, 4)]),
    ("S-100\n", [(1, 4)]),
    ("T-1\n", [(1, 4)]),
    ("N-5 G0 X1\n", [(1, 4)]),
    ("G4 P-1\n", [(1, 4)]),
    # 20: codes and letters Grbl does not have
    ("M6\n", [(1, 20)]),
    ("T1 M6\n", [(1, 20)]),
    ("G43 H1 Z5\n", [(1, 20)]),
    ("G81 X0 Y0 Z-1 R1 F100\n", [(1, 20)]),
    ("G64\n", [(1, 20)]),
    ("G95\n", [(1, 20)]),
    ("O100 sub\n", [(1, 20)]),
    ("G0 A10\n", [(1, 20)]),
    ("M7\n", [(1, 20)]),  # no mist coolant in the default build
    ("G28.2\n", [(1, 20)]),
    ("G90.1\n", [(1, 20)]),
    ("G10 L3 P1 X0\n", [(1, 20)]),
    ("G10 P1 X0\n", [(1, 20)]),  # P without L: L is 0
    ("G10 L2 P1 R1 X0\n", [(1, 20)]),
    # 21: two codes of one modal group
    ("G17 G18\n", [(1, 21)]),
    ("M3 M5\n", [(1, 21)]),
    ("M8 M9\n", [(1, 21)]),
    ("G20 G21\n", [(1, 21)]),
    ("G54 G55\n", [(1, 21)]),
    ("G4 P1 G53\n", [(1, 21)]),
    ("G0 G80\n", [(1, 21)]),
    # 22: no feed rate
    ("G1 X1\n", [(1, 22)]),
    ("G1\n", [(1, 22)]),  # G1 named, even with no axis word
    ("G2 X2 Y0 I1 J0\n", [(1, 22)]),
    ("G38.2 Z-5\n", [(1, 22)]),
    ("G1 X1 F0\n", [(1, 22)]),
    ("G1 X1 F0.000000009\n", [(1, 22)]),  # read_float keeps 8 digits: all zeros
    ("G93 G1 X1\n", [(1, 22)]),
    ("G93 G1 X1 F10\nG1 X2\n", [(2, 22)]),  # inverse time: an F on every move
    ("G93 G1 X1 F10\nG94 G1 X2\n", [(2, 22)]),  # back to G94: no feed rate until one is given
    # 23: a code that must be whole
    ("G59.1\n", [(1, 23)]),
    ("G0.5 X1\n", [(1, 23)]),
    ("G4.5 P1\n", [(1, 23)]),
    ("G17.1\n", [(1, 23)]),
    ("M3.5\n", [(1, 23)]),
    ("G10.5 L2 P1 X0\n", [(1, 23)]),
    # 24: two commands that use the axis words
    ("G0 G1 X1\n", [(1, 24)]),
    ("G0 G0 X1\n", [(1, 24)]),
    ("G10 L2 P1 G28 X0\n", [(1, 24)]),
    ("G43.1 Z1 G0 X1\n", [(1, 24)]),
    ("G1 G38.1 X1 F100\n", [(1, 24)]),  # the axis command is checked before G38.1's fraction
    # 25: a word twice
    ("G0 X1 X2\n", [(1, 25)]),
    ("G1 X1 F100 F200\n", [(1, 25)]),
    # 26: no axis words where a command needs them
    ("G10 L2 P1\n", [(1, 26)]),
    ("G92\n", [(1, 26)]),
    ("F100\nG2 I1\n", [(2, 26)]),
    ("F100\nG38.2\n", [(2, 26)]),
    # 27: N past 10,000,000
    ("N10000001 G0 X1\n", [(1, 27)]),
    ("N0 G0 X1\nN10000000 G0 X2\nN10000001\n", [(3, 27)]),
    # 28: a value word missing
    ("G4\n", [(1, 28)]),
    ("G10 X1\n", [(1, 28)]),  # neither L nor P
    # 29: G10 P past G59
    ("G10 L2 P7 X0\n", [(1, 29)]),
    ("G10 L20 P9 X0\n", [(1, 29)]),
    # 30: G53 with a motion other than G0 G1
    ("F100\nG53 G2 X10 Y0 R5\n", [(2, 30)]),
    ("G80\nG53 X1\n", [(2, 30)]),  # (before error 31)
    ("F100\nG2 X2 Y0 I1 J0\nG53\n", [(3, 30)]),
    # 31: axis words under G80
    ("G80 X1\n", [(1, 31)]),
    ("G80\nX5\n", [(2, 31)]),
    ("G80\nG92 X0\n", [(2, 31)]),  # even for a command that uses them
    # 32: an arc with no axis word in its plane
    ("F100\nG2 Z5 I1\n", [(2, 32)]),
    ("F100\nG18 G2 Y5 I1\n", [(2, 32)]),
    # 33: a target that is not one
    ("F100\nG1 X10\nG2 X20 Y0 I3 J0\n", [(3, 33)]),  # the end is not on the circle
    ("F100\nG2 X0 Y0 R5\n", [(2, 33)]),  # an R arc to where it starts
    ("F100\nG38.2 X0\n", [(2, 33)]),  # a probe to where it is
    ("F100\nG38.2 X0.000000012\n", [(2, 33)]),  # read_float: 0
    # 34: a radius that does not reach
    ("F100\nG2 X10 Y0 R4\n", [(2, 34)]),
    ("F100\nG2 X10 Y0 R-4.99\n", [(2, 34)]),
    # 35: an arc with no offset in its plane
    ("F100\nG2 X10 Y0\n", [(2, 35)]),
    ("F100\nG2 X10 Y0 K5\n", [(2, 35)]),
    # 36: words nothing uses
    ("G0 X1 P1\n", [(1, 36)]),
    ("G1 X1 F100 R5\n", [(1, 36)]),
    ("F100\nG2 X10 Y0 R5 I5\n", [(2, 36)]),  # R wins, I is left over
    ("L2\n", [(1, 36)]),
    ("G0 X1 I1\n", [(1, 36)]),
    ("G10 L20 P1 X0 R1\n", [(1, 36)]),
    # 37: G43.1 on an axis other than Z
    ("G43.1 X1\n", [(1, 37)]),
    ("G43.1\n", [(1, 37)]),
    ("G43.1 Z1 X1\n", [(1, 37)]),
    # 38: a tool past 255
    ("T256\n", [(1, 38)]),
    ("T255.5\n", [(1, 38)]),
]


@pytest.mark.parametrize(("program", "expected"), ERRORS, ids=[p for p, _ in ERRORS])
def test_error(program: str, expected: list[tuple[int, int]]) -> None:
    assert rejected(program) == expected


def test_every_error_of_the_g_code_parser_is_tested() -> None:
    tested = {code for _, found in ERRORS for _, code in found}
    assert tested == {1, 2, 4, *range(20, 39)}


def test_overflow_is_error_11() -> None:
    line = "G0X" + "1" * 76  # 79 characters kept
    assert len(line) == 79
    assert rejected(line + "\n" + line + "0\n") == [(2, 11)]
    # spaces, comments, block delete and real-time commands do not count; letters count the same
    roomy = "/ " + " ".join(line.lower()) + " (a comment) ?! ; and another"
    assert rejected(roomy + "\n") == []


def test_the_messages_are_grbls() -> None:
    [error] = check_text("G0 X1 X2\n")
    assert (error.line, error.code, error.text) == (1, 25, "G0 X1 X2")
    assert error.message == "Repeated g-code word found in block."
    assert codes.MESSAGES[33] == "Motion command target is invalid."
    assert codes.MESSAGES[11] == ("Max characters per line exceeded. Received command line was "
                                  "not executed.")


# -- programs Grbl accepts -----------------------------------------------------------------------------
CAM = """\
%
(typical job: every code Grbl 1.1 has)
(MSG, check the stock)
N10 G21 G17 G90 G94 G40 G49 G54 G61 G91.1
N20 T1 S12000 M3
M8
G10 L2 P1 X0 Y0 Z0
G10 L2 P2 X100 Y50 Z-20
G10 L2 P6 X1 Y2 Z3
G55
G0 Z5
G0 X0 Y0
G1 Z-1 F300
G1 X20 F800
G2 X30 Y10 I0 J10
G3 X20 Y20 R10
G2 X10 Y20 R-5
G18 G2 X0 Z-1 I-5 K0
G19 G3 Y10 Z-1 J-5 K0
G17
G91 G1 X5 Y5
G90
G20 G1 X1 Y1
G2 X1.5 Y1.5 I0.5 J0
G21
G93 G1 X30 F2
G94 G1 X40 F500
G4 P0.5
G92 X0 Y0
G1 X5
G92.1
G10 L20 P3 X0 Y0
G56
G0 X1
G43.1 Z2
G0 Z10
G49
G53 G0 Z-1
G53 G1 X10 F400
G28.1
G30.1
G0 X10 Y10
G28
G30 Z5
G28 X0 Y0
G38.2 Z-10 F100
G38.3 Z-11
G38.4 Z0
G38.5 Z5
M5
M4 S5000
M9
M0
M1
G80
G0 Z20 ; done
M30
"""


def test_a_typical_program_but_its_percent_lines() -> None:
    assert rejected(CAM) == [(1, 1)]
    assert rejected(CAM.removeprefix("%\n")) == []


def test_lowercase_comments_and_characters_grbl_drops() -> None:
    program = ("g21 g90 (mm, absolute)\nf100 ; feed\n\tg1 x1 y2\n/G1 X2\nG1 X3 ?\nG1 X4 !~\n"
               "G1 X5 (unclosed\nG1 X6 (café)\nG1 Xé7\n\n(only a comment)\n;\nG1 X1 Y1 (G2 !)\n")
    assert rejected(program) == []


def test_block_delete_is_not_a_skip() -> None:
    assert rejected("/G1 X1\n") == [(1, 22)]


def test_line_ends() -> None:
    assert rejected("G0 X1\r\nG1 X2\r\n") == [(2, 22)]
    assert rejected("G0 X1\rG1 X2\r") == [(2, 22)]
    checker = grbl_check.Checker()  # a line given with a lone \r in it: two lines for Grbl
    assert [(e.line, e.code) for e in checker.errors(["G0 X1\n", "G4 P1\rG1 X2\n"])] == [(2, 22)]
    assert rejected("G0 X1\nG1 X2") == [(2, 22)]  # no line end at the end


def test_system_commands_are_not_checked() -> None:
    checker = grbl_check.Checker()
    errors = list(checker.errors(["$H\n", "G0 X1\n", "$J=G91 X1 F100\n", "$$ \n", "G1 X1\n"]))
    assert [(e.line, e.code) for e in errors] == [(5, 22)]
    assert (checker.lines, checker.system_lines, checker.rejected) == (5, [1, 3, 4], 1)


def test_a_rejected_line_changes_nothing() -> None:
    assert rejected("G1 X10 F100 M6\nG1 X10\n") == [(1, 20), (2, 22)]  # F100 went with it
    assert rejected("G20 M6\nF100\nG1 X10\nG2 X20 Y0 I5 J0\n") == [(1, 20)]  # still in mm


# -- the state carried from line to line --------------------------------------------------------------
def test_inches() -> None:
    assert rejected("G20 F10\nG1 X1\nG2 X2 Y0 I0.5 J0\n") == []
    assert rejected("G20 F10\nG1 X1\nG2 X2 Y0 I12.7 J0\n") == [(3, 33)]
    assert rejected("G20 F10\nG2 X1 Y0 R0.5\nG2 X0 Y0 R0.4\n") == [(3, 34)]


def test_incremental() -> None:
    assert rejected("G91 G1 X10 F100\nG2 X10 Y0 I5 J0\n") == []
    assert rejected("G90 G1 X10 F100\nG2 X10 Y0 I5 J0\n") == []  # a full circle
    assert rejected("G90 G1 X10 F100\nG2 X20 Y0 I-5 J0\n") == [(2, 33)]


def test_g92_offsets_the_target() -> None:
    assert rejected("G0 X10\nG2 X20 Y0 I5 J0 F100\n") == []
    assert rejected("G0 X10\nG92 X0\nG2 X20 Y0 I5 J0 F100\n") == [(3, 33)]
    assert rejected("G0 X10\nG92 X0\nG2 X10 Y0 I5 J0 F100\n") == []
    assert rejected("G0 X10\nG92 X0\nG92.1\nG2 X20 Y0 I5 J0 F100\n") == []


def test_g10_offsets() -> None:
    assert rejected("G10 L2 P2 X10\nG2 X10 Y0 I5 J0 F100\n") == []  # G55 is not in use
    assert rejected("G10 L2 P1 X10\nG2 X10 Y0 I5 J0 F100\n") == [(2, 33)]
    assert rejected("G10 L2 P0 X10\nG2 X10 Y0 I5 J0 F100\n") == [(2, 33)]  # P0: in use
    assert rejected("G10 L2 X10\nG2 X10 Y0 I5 J0 F100\n") == [(2, 33)]  # no P: P0
    assert rejected("G10 L2 P2 X10\nG55\nG2 X10 Y0 I5 J0 F100\n") == [(3, 33)]
    assert rejected("G0 X5\nG10 L20 P1 X0\nG2 X10 Y0 I5 J0 F100\n") == []
    assert rejected("G0 X5\nG10 L2 P1 X0\nG2 X10 Y0 I5 J0 F100\n") == [(3, 33)]


def test_tool_length_offset() -> None:
    assert rejected("G19 G2 Y0 Z10 J0 K5 F100\n") == []
    assert rejected("G43.1 Z10\nG19 G2 Y0 Z10 J0 K5 F100\n") == [(2, 33)]
    assert rejected("G43.1 Z10\nG49\nG19 G2 Y0 Z10 J0 K5 F100\n") == []
    assert rejected("G43.1 Z10\nG49 Z3\nG19 G2 Y0 Z10 J0 K5 F100\n") == []  # G49 takes axes
    assert rejected("G49.5\n") == []  # Grbl drops G49's fraction


def test_g53_is_in_machine_coordinates() -> None:
    program = "G10 L2 P1 X10\nG53 G0 X0\nG2 X{} Y0 I5 J0 F100\n"
    assert rejected(program.format(0)) == []
    assert rejected(program.format(10)) == [(3, 33)]
    assert rejected(program.replace("G53 ", "").format(10)) == []


def test_g28_and_g30_go_to_the_stored_positions() -> None:
    assert rejected("G0 X5\nG28.1\nG0 X0\nG28\nG2 X15 Y0 I5 J0 F100\n") == []
    assert rejected("G0 X5\nG28.1\nG0 X0\nG2 X15 Y0 I5 J0 F100\n") == [(4, 33)]
    # only the axes given go home, through the point given
    assert rejected("G0 X5 Y5\nG28.1\nG0 X0 Y0\nG28 Y1\nG2 X10 Y5 I5 J0 F100\n") == []
    assert rejected("G0 X7\nG30.1\nG0 X0\nG30\nG2 X17 Y0 I5 J0 F100\n") == []
    assert rejected("G0 X7\nG30.1\nG0 X0\nG28\nG2 X17 Y0 I5 J0 F100\n") == [(5, 33)]


def test_a_probe_ends_at_its_target_in_check_mode() -> None:
    assert rejected("F100\nG38.2 X5\nG38.2 X5\nG38.3 X6\n") == [(3, 33)]
    probe_to_start = GRBL._replace(probe_to_start=True)
    assert rejected("F100\nG38.2 X5\nG38.2 X5\n", probe_to_start) == []


def test_program_end_resets_the_modes() -> None:
    assert rejected("G91 G1 X10 F100\nM2\nG1 X5\nG2 X15 Y0 I5 J0\n") == []
    assert rejected("G80 F100\nM30\nX1\n") == []  # G1 again, the feed rate kept
    assert rejected("G20\nM2\nG1 X1 F10\nG2 X2 Y0 I0.5 J0\n") == []  # not the units


def test_program_end_keeps_the_work_offset_loaded_in_check_mode() -> None:
    # G55 (X10) is loaded when M2 selects G54: check mode does not load G54's offset again
    program = "G10 L2 P2 X10\nG55 G0 X0\nM2\nG54\nG2 X20 Y0 I5 J0 F100\n"
    assert rejected(program) == [(5, 33)]
    assert rejected(program.replace("M2\n", "")) == []


def test_g80_keeps_no_motion() -> None:
    assert rejected("G80\nG0 X1\nX2\n") == []


# -- numbers in single precision, as Grbl reads and computes them -----------------------------------
def test_the_arc_tolerance_in_single_precision() -> None:
    # 0.005 mm off in decimal: single precision decides, and how read_float scales the digits
    assert rejected("F100\nG2 X7.657 Y0 I3.826 J0\n") == [(2, 33)]  # (in doubles: accepted)
    assert rejected("F100\nG2 X9.019 Y0 I4.507 J0\n") == [(2, 33)]
    assert rejected("F100\nG2 X9.0190 Y0 I4.507 J0\n") == []  # 90190 * 0.01f * 0.01f


def test_the_arc_tolerance() -> None:
    assert rejected("F100\nG2 X20.004 Y0 I10 J0\n") == []  # within 0.005 mm
    assert rejected("F100\nG2 X2.006 Y0 I1 J0\n") == [(2, 33)]  # past 0.005 mm and 0.1%
    assert rejected("F100\nG2 X20.006 Y0 I10 J0\n") == []  # past 0.005 mm, within 0.1%
    assert rejected("F100\nG2 X2000.4 Y0 I1000 J0\n") == []  # within 0.1% and 0.5 mm
    assert rejected("F100\nG2 X2000.6 Y0 I1000 J0\n") == [(2, 33)]  # past 0.5 mm


def test_read_float() -> None:
    assert numbers.read_value("", "1", "5") == 1.5
    assert numbers.read_value("-", "", "5") == -0.5
    assert numbers.read_value("", "0", "000000012") == 0.0  # the 9th digit is dropped
    assert numbers.read_value("", "0", "00000012") == numbers.f32(1e-7)
    assert numbers.read_value("", "123456789", "9") == 123456784.0
    assert numbers.read_value("", "0", "1") == numbers.f32(0.1)
    assert numbers.read_value("", "1", "23") == numbers.f32(123 * numbers.HUNDREDTH)
    assert numbers.read_value("", "1" * 60, "") == float("inf")


def test_whole_and_hundredths() -> None:
    assert numbers.whole_and_hundredths(numbers.read_value("", "38", "2")) == (38, 20)
    assert numbers.whole_and_hundredths(numbers.read_value("", "59", "1")) == (59, 10)
    assert numbers.whole_and_hundredths(-1.0) == (255, 39936)
    assert numbers.whole_and_hundredths(float("inf")) == (255, 65535)


# -- what the line reader keeps ---------------------------------------------------------------------------
def test_kept() -> None:
    assert kept("g1 x1.5 (a (b) y2") == "G1X1.5Y2"  # a comment ends at the first ')'
    assert kept("G1 (a ; b) X2 ; c (d)") == "G1X2"
    assert kept("G1\tX1\x18\x7f") == "G1X1\x7f"
    assert kept("(all of it") == ""


def test_read_lines_bounds_a_long_line(tmp_path: Path) -> None:
    long_comment = "G0 X1 (" + "x" * (3 * PIECE_CHARS) + ") Y2\n"
    long_code = "G0 X" + "1" * (2 * PIECE_CHARS) + "\n"
    text = "G0 X0\n" + long_comment + long_code + "G1 X1\n"
    got = list(read_lines(io.StringIO(text, newline=""), 79))
    assert got[0] == "G0 X0\n" and got[3] == "G1 X1\n"
    assert max(len(line) for line in got) < 100
    assert kept(got[1]) == "G0X1Y2"
    assert len(kept(got[2])) == 80
    checker = grbl_check.Checker()
    found = [(e.line, e.code) for e in checker.errors(got)]
    assert found == [(3, 11), (4, 22)] == rejected(text)


def test_read_lines_keeps_an_open_comment_open() -> None:
    text = "G0 X1 ;" + "y" * PIECE_CHARS + "\nG0 X2 (" + "z" * PIECE_CHARS + "\nG0 X3\n"
    got = list(read_lines(io.StringIO(text, newline=""), 79))
    assert [kept(line) for line in got] == ["G0X1", "G0X2", "G0X3"]


# -- the tables and the library ----------------------------------------------------------------------------
def test_m7_with_mist_coolant() -> None:
    assert rejected("M7\n", GRBL._replace(mist_coolant=True)) == []
    assert rejected("M7 M8\n", GRBL._replace(mist_coolant=True)) == [(1, 21)]


def test_a_build_with_other_limits() -> None:
    small = GRBL._replace(line_chars=10, max_tool=9, max_line_number=99)
    assert rejected("G0 X123456789\nT10\nN100\nT9 N99\n", small) == [(1, 11), (2, 38), (3, 27)]


def test_two_controllers_share_nothing() -> None:
    first, second = Grbl(), Grbl()
    assert first.send("G20") == 0
    assert first.send("F100") == 0
    assert second.send("G1 X1") == 22
    assert first.send("G1 X1") == 0
    assert second.state.modes[codes.UNITS] == codes.MILLIMETRES


def test_the_dialects_table() -> None:
    assert ngc.grbl.DIALECTS["grbl"] is GRBL
    assert (GRBL.line_chars, GRBL.axes, GRBL.mist_coolant, GRBL.max_tool) == (79, "XYZ", False, 255)


@pytest.mark.parametrize("module", [ngc.grbl, grbl_check, codes, lines, numbers],
                         ids=lambda m: m.__name__)
def test_doctests(module: object) -> None:
    failed, attempted = doctest.testmod(module)  # type: ignore[arg-type]
    assert attempted and not failed


# -- the command line --------------------------------------------------------------------------------
REJECTS = "G21 G90\nG1 X10 Y0\nF300\nG1 X10 Y0\nG2 X20 Y0 I3 J0\nM6\nM2\n"


def test_cli_accepts(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    path = write(tmp_path, "job.ngc", CAM.removeprefix("%\n"))
    code, out, err = run(capsys, "check", "--dialect", "grbl", path)
    assert (code, err) == (0, "")
    assert out == f"{path}: 56 lines, Grbl 1.1 accepts all\n"


def test_cli_rejects(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    path = write(tmp_path, "bad.ngc", REJECTS)
    code, out, err = run(capsys, "check", "--dialect", "grbl", path)
    assert code == 1
    assert err.splitlines() == [
        f"{path}:2: error:22 Feed rate has not yet been set or is undefined. (G1 X10 Y0)",
        f"{path}:5: error:33 Motion command target is invalid. (G2 X20 Y0 I3 J0)",
        f"{path}:6: error:20 Unsupported or invalid g-code command found in block. (M6)",
    ]
    assert out == f"{path}: 7 lines, Grbl 1.1 rejects 3\n"


def test_cli_json(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    path = write(tmp_path, "bad.ngc", "$H\n" + REJECTS)
    code, out, _ = run(capsys, "check", "--dialect", "grbl", "--format", "json", path)
    assert code == 1
    record = json.loads(out)
    assert record["errors"][0] == {"line": 3, "code": 22, "text": "G1 X10 Y0",
                                   "message": "Feed rate has not yet been set or is undefined."}
    del record["errors"]
    assert record == {"file": path, "dialect": "grbl", "controller": "Grbl 1.1", "ok": False,
                      "lines": 8, "rejected": 3, "system_lines": [1]}


def test_cli_system_commands(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    path = write(tmp_path, "homed.ngc", "$H\n$X\nG0 X1\n")
    code, out, _ = run(capsys, "check", "--dialect", "grbl", path)
    assert code == 0
    assert out == (f"{path}: 3 lines, Grbl 1.1 accepts all; 2 lines of $ system commands not "
                   "checked\n")


def test_cli_several_files(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    good = write(tmp_path, "good.ngc", "G0 X1\n")
    bad = write(tmp_path, "bad.ngc", "G1 X1\n")
    for jobs in ("1", "2"):
        code, out, err = run(capsys, "check", "--dialect", "grbl", "-j", jobs, bad, good)
        assert code == 1
        assert out.splitlines() == [f"{bad}: 1 lines, Grbl 1.1 rejects 1",
                                    f"{good}: 1 lines, Grbl 1.1 accepts all"]
        assert err.count("error:22") == 1


def test_cli_unreadable(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    good = write(tmp_path, "good.ngc", "G0 X1\n")
    missing = str(tmp_path / "missing.ngc")
    code, out, err = run(capsys, "check", "--dialect", "grbl", missing, good)
    assert code == 2
    assert f"ngc check: cannot open {missing}: No such file or directory" in err.splitlines()
    assert out == f"{good}: 1 lines, Grbl 1.1 accepts all\n"
    code, out, _ = run(capsys, "check", "--dialect", "grbl", "--format", "json", missing)
    assert code == 2
    record = json.loads(out)
    assert (record["lines"], record["ok"]) == (None, False)
    assert record["error"]["message"] == "cannot open: No such file or directory"


def test_cli_stdin(capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch,
                   tmp_path: Path) -> None:
    path = write(tmp_path, "in.ngc", "G0 X1\nG1 X2\n")
    with open(path, "rb") as handle:
        monkeypatch.setattr("sys.stdin", io.TextIOWrapper(handle))
        code, out, err = run(capsys, "check", "--dialect", "grbl", "-")
    assert code == 1
    assert out == "<stdin>: 2 lines, Grbl 1.1 rejects 1\n"
    assert err.startswith("<stdin>:2: error:22 ")


@pytest.mark.parametrize("flags", [["-i", "machine.ini"], ["-t", "tools.tbl"],
                                   ["--setup", "setup.toml"], ["--machine", "m.toml"],
                                   ["--any-tool"]])
def test_cli_refuses_machine_inputs(capsys: pytest.CaptureFixture[str], tmp_path: Path,
                                    flags: list[str]) -> None:
    path = write(tmp_path, "job.ngc", "G0 X1\n")
    code, out, err = run(capsys, "check", "--dialect", "grbl", *flags, path)
    assert (code, out) == (2, "")
    assert err.startswith(f"ngc check: {flags[0]} is a machine input of the other dialects")


@pytest.mark.parametrize("command", [["canon"], ["time"], ["plot", "-o", "x.svg"], ["view"],
                                     ["flatten"]])
def test_other_commands_refuse_grbl(capsys: pytest.CaptureFixture[str], tmp_path: Path,
                                    command: list[str]) -> None:
    path = write(tmp_path, "job.ngc", "G0 X1\n")
    code, out, err = run(capsys, *command, "--dialect", "grbl", path)
    assert (code, out) == (2, "")
    assert "argument --dialect: invalid choice: 'grbl'" in err


def test_the_example_is_accepted(capsys: pytest.CaptureFixture[str]) -> None:
    path = str(ROOT / "examples" / "grbl-job.ngc")
    code, out, _ = run(capsys, "check", "--dialect", "grbl", path)
    assert (code, out) == (0, f"{path}: 24 lines, Grbl 1.1 accepts all\n")


def test_an_endless_line_is_not_a_program(capsys: pytest.CaptureFixture[str], tmp_path: Path,
                                          monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(lines, "MAX_PIECES", 2)
    path = write(tmp_path, "zero.ngc", b"\0" * (4 * PIECE_CHARS))
    code, out, err = run(capsys, "check", "--dialect", "grbl", path)
    assert (code, out) == (2, "")
    assert err == (f"ngc check: cannot read {path}: line 1 goes on for more than "
                   f"{2 * PIECE_CHARS} characters with no line end: not a program\n")


# -- whatever the lines: an answer Grbl has, and a rejected line leaves no trace -----------------
CODES = ["G0", "G1", "G2", "G3", "G4", "G10", "G17", "G18", "G19", "G20", "G21", "G28", "G28.1",
         "G30", "G30.1", "G38.2", "G38.5", "G43.1", "G49", "G53", "G55", "G59.1", "G80", "G90",
         "G91", "G92", "G92.1", "G93", "G94", "M2", "M3", "M6", "M8", "%", "(c)", ";", "$H"]
NUMBERS = st.one_of(st.integers(-300, 300).map(str), st.sampled_from(["", "-", ".", "1.2.3",
                    "0.000000009", "1" * 40, "-0", "2.5", "255.5", "10000001"]),
                    st.floats(-500, 500).map(lambda v: f"{v:.4f}"))
WORDS = st.tuples(st.sampled_from("XYZIJKFRPLNSTA"), NUMBERS).map("".join)
LINES = st.lists(st.lists(st.one_of(st.sampled_from(CODES), WORDS), max_size=6).map(" ".join),
                 max_size=25)


def _snapshot(grbl: Grbl) -> tuple[object, ...]:
    state = grbl.state
    return (list(state.modes), state.feed_rate, state.spindle_speed, list(state.position),
            list(state.coord_system), list(state.coord_offset), state.tool_length_offset,
            [list(v) for v in state.stored])


@settings(deadline=None, derandomize=True, database=None, max_examples=300,
          phases=(Phase.explicit, Phase.generate))
@given(LINES)
def test_a_rejected_line_leaves_no_trace(program: list[str]) -> None:
    grbl = Grbl()
    for line in program:
        before = _snapshot(grbl)
        answer = grbl.send(line)
        assert answer is None or answer == 0 or answer in codes.MESSAGES
        if answer != 0:
            assert _snapshot(grbl) == before, line
