"""The rows of ``ngc.grbl.DIALECTS`` other than Grbl 1.1h's: each difference shown by a program
one row accepts and another rejects, with the exact answers (docs/grbl.md, grblHAL)."""

from __future__ import annotations

import pathlib

import pytest

from ngc.grbl import DIALECTS, GRBL, Grbl, check_text
from ngc.grbl.check import NOT_CHECKED
from ngc.grbl.rules import GRBLHAL

GOLDEN = pathlib.Path(__file__).parent / "golden" / "flatten"


def answers(rules: object, *lines: str) -> list[int | None]:
    grbl = Grbl(rules)  # type: ignore[arg-type]
    return [grbl.send(line) for line in lines]


def errors(text: str, rules: object) -> list[tuple[int, int | None, str]]:
    return [(e.line, e.code, e.message) for e in check_text(text, rules)]  # type: ignore[arg-type]


def test_the_rows_by_name() -> None:
    assert DIALECTS["grbl"] is GRBL and DIALECTS["grblhal"] is GRBLHAL
    assert "fluidnc" not in DIALECTS


@pytest.mark.parametrize(("lines", "grbl", "grblhal"), [
    # G59.1-G59.3 and G10 P7-P9: nine work offsets (config.h N_WorkCoordinateSystems 9)
    (("G59.1", "G59.3", "G10 L2 P9 X1"), [23, 23, 29], [0, 0, 0]),
    (("G59.4",), [23], [20]),
    # M7 (ENABLE_M7 in Grbl; grblHAL's drivers with mist control)
    (("M7",), [20], [0]),
    # P on an arc: its turns (whole, not 0)
    (("G1 F100", "G2 X0 Y0 I1 J0 P2"), [0, 36], [0, 0]),
    (("G1 F100", "G2 X0 Y0 I1 J0 P1.5"), [0, 36], [0, 23]),
    (("G1 F100", "G2 X0 Y0 I1 J0 P0"), [0, 36], [0, 39]),
    # T up to 4294967294 (N_TOOLS 0); T must be whole
    (("T256",), [38], [0]),
    (("T1.5",), [0], [23]),
    # a negative P is read; G4 and G10 reject it later (error 4 either way)
    (("G4 P-1",), [4], [4]),
    (("G1 X1 F100 P-1",), [4], [36]),
    # G43.1 on any axis (TOOL_LENGTH_OFFSET_AXIS -1), at least one
    (("G43.1 X1 Y2",), [37], [0]),
    (("G43.1",), [37], [37]),
    # G49 is not an axis command: its axis words move
    (("G49 X1",), [0], [0]),
    # under G80, G10 G28 G30 G92 take axis words
    (("G80", "G92 X1"), [0, 31], [0, 0]),
    (("G80", "G43.1 Z1"), [0, 31], [0, 31]),
    # G10 L2 with R and no axis word: 20 (L2 R), not 26; an L but 2 and 20 before a P past 9
    (("G10 L2 P1 R5",), [26], [20]),
    (("G10 L3 P10 X1",), [29], [20]),
    # G98/G99 (retract mode) are taken; G43 and G38.1 are refused before the axis check
    (("G98", "G99"), [20, 20], [0, 0]),
    (("G0 G43 X1",), [24], [20]),
    (("G1 G38.1 X1",), [24], [20]),
    # G92.2 and a '%' line; a stray ')' is dropped; '/' only at the start of a line
    (("%",), [1], [0]),
    (("G0 X1)",), [1], [0]),
    (("G0 /X1",), [0], [1]),
    # read_float: 9 digits, leading zeros not counted (F0.000000009 is not F0)
    (("G1 X1 F0.000000009",), [22], [0]),
    # G-0.5: the word's whole number and hundredths converted saturating (an ARM): G0
    (("G-0.5 X1",), [23], [0]),
    # words grblHAL reads that Grbl does not know
    (("G1 X1 F100 Q1.5",), [20], [NOT_CHECKED]),
    (("H1.5",), [20], [23]),
    (("D-1",), [20], [4]),
])  # fmt: skip
def test_differences(lines: tuple[str, ...], grbl: list[int], grblhal: list[int]) -> None:
    assert answers(GRBL, *lines) == grbl
    assert answers(GRBLHAL, *lines) == grblhal


def test_line_length_counts_comments_in_grblhal() -> None:
    comment = "(" + "c" * 200 + ")"
    assert answers(GRBL, "G0 X1 " + comment, "G0 X" + "1" * 80) == [0, 11]
    assert answers(GRBLHAL, "G0 X1 " + comment + "c" * 60) == [11]
    assert answers(GRBLHAL, "G0 X1 " + comment, "G0 X" + "1" * 80) == [0, 0]


def test_grblhal_latches_an_error_until_an_empty_line() -> None:
    program = "G1 X1\nG0 X2\n(a comment)\n\nG0 X3\n"
    assert errors(program, GRBL) == [
        (1, 22, "Feed rate has not yet been set or is undefined.")]
    assert errors(program, GRBLHAL) == [
        (1, 22, "Feed rate has not yet been set or is undefined."),
        (2, 22, "Feed rate has not yet been set or is undefined."),
        (3, 22, "Feed rate has not yet been set or is undefined.")]


def test_grblhal_messages() -> None:
    assert errors("T4294967296\n", GRBLHAL) == [
        (1, 38, "Tool number greater than max supported value or undefined tool selected.")]
    assert errors("G1 F100\nG2 X0 Y0 I1 J0 P0\n", GRBLHAL) == [(2, 39, "Value out of range.")]


@pytest.mark.parametrize(("line", "what"), [
    ("G81 X1 Y1 Z-1 R1 F100", "a canned cycle (G73 G81-G83 G85 G86 G89)"),
    ("G33 Z-10 K1", "G33, spindle-synchronised motion (it needs a spindle with feedback)"),
    ("G5 X1 Y1 I1 J1 P1 Q1", "G5, a cubic spline"),
    ("G95", "G95, feed per revolution (it needs a spindle that reports its speed)"),
    ("M6 T2", "M6, a tool change (it depends on the driver and $341)"),
    ("M62 P1", "M62, the driver's ports"),
    ("G92.3", "G92.3 (G92 restored from storage)"),
    ("G0 X1 (caf\u00e9)", "a character past 0x7F (what is kept of it is the driver's stream's)"),
])  # fmt: skip
def test_codes_grblhal_takes_but_the_row_does_not_check(line: str, what: str) -> None:
    assert errors(line + "\n", GRBLHAL) == [(1, None, f"not checked: {what}")]
    assert all(code is not None for _, code, _ in errors(line + "\n", GRBL))


def test_an_unchecked_code_still_has_its_reading_errors() -> None:
    assert [answers(GRBLHAL, line) for line in ("G81 G1 X1", "G81 G81", "M6 M61")] == [
        [24], [24], [21]]


def test_grblhal_lathe_and_tool_table_codes_are_refused() -> None:
    # default settings: mill mode ($32=0), so G7 G8 G96 G97 are 20; N_TOOLS 0, so G43 is 20
    assert answers(GRBLHAL, "G7", "G96 S100", "G43 H1", "M56") == [20, 20, 20, 20]


def test_cli_grblhal(tmp_path: pathlib.Path, capsys: pytest.CaptureFixture[str]) -> None:
    from ngc.cli import main

    program = tmp_path / "p.nc"
    program.write_text("G59.1\nM7\nG81 X1 Y1 Z-1 R1 F100\n")
    assert main(["check", "--dialect", "grblhal", str(program)]) == 1
    out, err = capsys.readouterr()
    assert out == (f"{program}: 3 lines, grblHAL accepts all; 1 line with codes grblHAL takes "
                   "but this check does not model, not checked\n")
    assert err == (f"{program}:3: not checked: a canned cycle (G73 G81-G83 G85 G86 G89) "
                   "(G81 X1 Y1 Z-1 R1 F100)\n")
    assert main(["check", "--dialect", "grbl", str(program)]) == 1


@pytest.mark.parametrize("row", ["grblhal", "fluidnc"])
def test_flatten_goldens_pass_their_row(row: str) -> None:
    goldens = sorted(GOLDEN.glob(f"*.{row}.nc"))
    assert goldens
    rules = DIALECTS.get(row, GRBL)  # (FluidNC has no row: its goldens are Grbl 1.1's programs)
    for golden in goldens:
        assert check_text(golden.read_text(), rules) == [], golden.name
