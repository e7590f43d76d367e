"""Codes ngc knows but does not run yet are refused as "G41 is not supported yet": before anything
on their line runs, and never with a message about their words."""

from __future__ import annotations

import pytest

import ngc
from ngc.canon.jsonl import ListSink
from ngc.language.codes import LINUXCNC, g_name

# A line using each code with the words it takes, after an S word and M8 that would run first if the block
# were executed in part.
LINES: dict[str, str] = {}  # every code of the table runs


def _unsupported() -> list[str]:
    names = [g_name(code) for code, row in LINUXCNC.g.items() if row.handler is None]
    names += [f"M{code}" for code, row in LINUXCNC.m.items() if row.handler is None]
    return sorted(names)


def test_every_unsupported_code_has_a_line() -> None:
    assert sorted(LINES) == _unsupported()


@pytest.mark.parametrize("name", sorted(LINES))
def test_refused_before_anything_runs(name: str) -> None:
    sink = ListSink()
    with pytest.raises(ngc.NgcError) as caught:
        ngc.interpret(f"F100\nS1000 M8 {LINES[name]}\nM2\n", sink)
    assert caught.value.message == f"{name} is not supported yet"
    assert caught.value.line == 2
    assert [line for _, _, line in sink.ops if line == 2] == []  # nothing of line 2 ran
