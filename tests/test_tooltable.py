"""Tool table files: the parser, the default table, and how each command takes a bad table."""

from __future__ import annotations

from pathlib import Path

import pytest

from ngc.config.tooltable import (
    DEFAULT_TABLE,
    UNREAD,
    Tools,
    length_from_program,
    length_to_program,
    parse_tool_table,
    read_tool_table,
)
from ngc.errors import NgcConfigError
from ngc.options import MachineOptions, load_setup


def test_entries_in_file_order_with_every_field() -> None:
    table = parse_tool_table(
        "T7 P3 Z1 D0.5 ;first\n"
        "t5 p9 x0.1 y0.2 z0.3 a0.4 b0.5 c0.6 u0.7 v0.8 w0.9 d0.25 i10 j20 q3 ; second\n"
        "\n;comment only\n"
    )
    assert [e.number for e in table.entries] == [7, 5]
    second = table.entries[1]
    assert second.pocket == 9
    assert second.offsets == (0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9)
    assert (second.diameter, second.frontangle, second.backangle, second.orientation) == (0.25, 10, 20, 3)
    assert second.comment == "second"
    assert table.skipped == ()


def test_skipped_lines_and_their_slots() -> None:
    table = parse_tool_table("T1 P1\ngarbage\nT2 P2 K1;x\nT3 P3\n")
    assert table.skipped == ("garbage", "T2 P2 K1;x")
    assert [e.number for e in table.entries] == [1, -1, 3]  # the T2 line keeps its slot
    assert table.entries[1] is UNREAD
    assert table.find(2) is None
    assert table.skipped_report("t.tbl") == (
        "File: t.tbl Unrecognized line skipped:\n    garbage\n"
        "File: t.tbl Unrecognized line skipped:\n    T2 P2 K1;x\n"
    )


@pytest.mark.parametrize("line", ["T9 P" + "9" * 400 + " D0.032", "T" + "9" * 400 + " P3",
                                  "T9 P3 Q" + "9" * 400])
def test_a_number_past_a_float_in_t_p_or_q_skips_the_line(line: str) -> None:
    # rs274 skips the line with a 400-digit P; its number was turned into an int: OverflowError
    table = parse_tool_table(f"T1 P1\n{line}\nT3 P3\n")
    assert table.skipped == (line,)
    assert [e.number for e in table.entries] == [1, -1, 3]


def test_first_entry_of_a_number_wins() -> None:
    tools = Tools(parse_tool_table("T1 P1 Z1\nT1 P2 Z2\n"))
    entry = tools.find(1)
    assert entry is not None and entry.offsets[2] == 1.0
    assert tools.index(1) == 1
    assert tools.index(-1) is None
    assert tools.pocket(5) == -1


def test_a_line_without_pocket_is_the_tool_in_the_spindle() -> None:
    table = parse_tool_table("T1 P1 Z1\nT5 Z5\nT2 Z2\nT3 P0 Z3\n")
    assert [e.number for e in table.entries] == [1, 3]  # P0 is an ordinary slot
    assert table.spindle is not None and table.spindle.number == 2  # the last line without P
    assert table.find(2) is table.spindle and table.find(5) is None
    tools = Tools(table)
    assert tools.spindle.number == 2 and tools.index(2) == 0 and tools.index(3) == 2
    tools.slots[0] = tools.slots[1]  # M6 T1: tool 2 was only in the spindle
    assert tools.index(1) == 1 and tools.index(2) is None


def test_tool_lengths_in_program_units() -> None:
    assert length_to_program(0.12345, metric=False) < 0.12345  # rs274 shows 0.1234
    assert f"{length_to_program(0.00025, metric=True):.4f}" == "0.0063"
    assert length_to_program(length_from_program(1.23455, True), True) == 1.23455


def test_default_table() -> None:
    assert [(e.number, e.pocket, e.diameter, e.offsets[2]) for e in DEFAULT_TABLE.entries] == [
        (1, 1, 0.125, 0.511), (2, 2, 0.0625, 0.1), (3, 3, 0.201, 1.273), (99999, 123, 0.0, 0.1),
    ]
    assert Tools().spindle.number == 0


def test_missing_file_is_an_empty_table_for_rs274(tmp_path: Path) -> None:
    assert read_tool_table(str(tmp_path / "missing.tbl")).entries == ()
    with pytest.raises(NgcConfigError):
        read_tool_table(str(tmp_path / "missing.tbl"), strict=True)


def test_canon_and_check_refuse_a_line_rs274_skips(tmp_path: Path) -> None:
    path = tmp_path / "bad.tbl"
    path.write_text("T1 P1 Z1\nT2 P2 K1\n")
    with pytest.raises(NgcConfigError) as caught:
        load_setup(MachineOptions(tool_table=str(path)))
    assert "unrecognized line: T2 P2 K1" in caught.value.message
    assert ", line 2: " in caught.value.message


def test_setup_reads_the_table(tmp_path: Path) -> None:
    path = tmp_path / "t.tbl"
    path.write_text("T4 P4 Z0.7 D1.0;\n")
    setup = load_setup(MachineOptions(tool_table=str(path)))
    assert [e.number for e in setup.tools.entries] == [4]
    assert load_setup(MachineOptions()).tools is DEFAULT_TABLE
