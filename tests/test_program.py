"""``ngc.Program``, the library's front door: load from a file or text, with machine inputs, and
ask it for its check, moves, time and drawing."""

from __future__ import annotations

import doctest
from pathlib import Path

import pytest

import ngc
from ngc import program as program_module
from ngc.errors import NgcConfigError, NgcError
from ngc.toolpath.moves import Event, Move

TEXT = "G21 G10 L2 P1 X100\nG54 G0 X1 Y2\nT1 M6\nG1 X5 F300\nG4 P0.5\nM2\n"


def test_doctests() -> None:
    failed, attempted = doctest.testmod(program_module)
    assert attempted > 0 and failed == 0


def test_listed_by_help() -> None:
    assert "Program" in dir(ngc) and "Program" in ngc.__all__
    assert ngc.Program is program_module.Program


def test_moves_in_machine_coordinates_with_lines() -> None:
    moves = ngc.Program.load(TEXT).moves()
    assert [(m.line, m.kind) for m in moves if isinstance(m, Move)] == [(2, "rapid"), (4, "feed")]
    feed = moves[-1]
    assert isinstance(feed, Move)
    assert feed.end[:3] == (105.0, 2.0, 0.0) and feed.prog_end[:3] == (5.0, 2.0, 0.0)
    assert feed.tool == 1 and feed.feed == 300.0


def test_events_when_asked() -> None:
    kinds = [e.kind for e in ngc.Program.load(TEXT).moves(events=True) if isinstance(e, Event)]
    assert "tool change" in kinds and "dwell" in kinds and kinds[-1] == "end"


def test_from_a_file_with_a_tool_table(tmp_path: Path) -> None:
    (tmp_path / "p.ngc").write_text("G21 T7 M6 G43\nG0 Z0\nM2\n")
    (tmp_path / "t.tbl").write_text("T7 P1 Z10 D6\n")
    p = ngc.Program.load(tmp_path / "p.ngc", tools=str(tmp_path / "t.tbl"))
    move = p.moves()[0]
    # (rs274's tool table is in inches, as its standalone machine is: Z10 is 254 mm)
    assert isinstance(move, Move) and move.end[2] == pytest.approx(254.0)
    assert move.file == str(tmp_path / "p.ngc")
    same = ngc.Program.load(str(tmp_path / "p.ngc"), tools=str(tmp_path / "t.tbl"))
    assert same.moves() == p.moves()


def test_check_time_and_plot(tmp_path: Path) -> None:
    p = ngc.Program.load(TEXT)
    result = p.check()
    assert result.ok and result.summary.feeds == 1
    assert p.time().total_s > 0.5  # the dwell at least
    svg = p.plot()
    assert svg.startswith("<svg") and 'id="toolpath"' in svg
    assert p._repr_svg_().startswith("<svg")
    out = p.plot(str(tmp_path / "p.svg"), view="iso")
    assert Path(out).read_text().startswith("<svg")


def test_a_program_error_is_raised_where_it_stops() -> None:
    p = ngc.Program.load("G1 X1 F100\nG2 X0 Y0 R0.1\nM2\n")
    with pytest.raises(NgcError) as caught:
        p.moves()
    assert caught.value.line == 2
    seen: list[object] = []
    with pytest.raises(NgcError):
        p.walk(seen.append)
    assert any(isinstance(m, Move) and m.line == 1 for m in seen)
    assert not p.check().ok
    assert "stopped at line 2" in p.plot()


def test_bad_inputs_are_named() -> None:
    with pytest.raises(NgcConfigError, match=r"nowhere\.tbl"):
        ngc.Program.load("M2\n", tools="nowhere.tbl")
    with pytest.raises(ValueError, match="unknown dialect"):
        ngc.Program.load("M2\n", dialect="fanuc")


def test_engine_programs() -> None:
    p = ngc.Program.load("(dialect: engine)\nF10\nfeed X2\n")
    assert p.dialect == "engine" and p.check().ok
    (move,) = p.moves()
    assert isinstance(move, Move) and move.kind == "bezier" and move.end[0] == 2.0
    assert p._repr_svg_().startswith("<svg")
    with pytest.raises(ValueError, match="engine dialect"):
        p.time()


def test_help_lists_the_whole_public_api() -> None:
    import pydoc

    text = pydoc.render_doc(ngc, renderer=pydoc.plaintext)
    for name in ngc.__all__:
        assert name in text, name
        assert getattr(ngc, name) is not None
    assert "time_text" in ngc.__all__ and "Program" in ngc.__all__
