"""Hostile input on the engine dialect: lines of stray separators, and moves whose numbers ask
for more segments than a run may make (``--max-iterations``), which stream in flat memory."""

from __future__ import annotations

import pytest

from ngc.engine import run

PROGRAM = "G21\nF 10\nG1 X 1 Y 2\nmove PZ 0 90 1 0\nM2\n"


@pytest.mark.parametrize("separators", [",", ", ,", ",,,", "\t,", " , ", "(a comment),",
                                        ", (a comment) ,", ",; a comment", ", \t ,"])
def test_a_line_of_separators_is_empty(separators: str) -> None:
    lines = PROGRAM.splitlines()
    with_separators = "\n".join([separators, *lines[:2], separators, *lines[2:]])
    ops = list(run(with_separators))
    shifted = [op._replace(line=op.line - 2 if op.line > 3 else op.line - 1) for op in ops]
    assert shifted == list(run(PROGRAM))


@pytest.mark.parametrize("text", [",", "G90 ,", ", G90", "M2 ,", ", M2", "F 1 ,", "move X1 ,"])
def test_stray_separators_around_words(text: str) -> None:
    """A separator before or after a line's words changes nothing."""
    assert list(run(text)) == list(run(text.replace(",", " ")))
