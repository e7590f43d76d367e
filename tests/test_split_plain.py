"""split_plain: the fast reader of plain lines takes exactly the lines it can read alone."""

from __future__ import annotations

import pytest

from ngc.language.parser import split_plain


@pytest.mark.parametrize(("text", "expected"), [
    ("g1x10.4162y-175.8265", ({"x": 10.4162, "y": -175.8265}, 1.0, None)),
    ("g2x1y2i0.5j-0.5f100", ({"x": 1.0, "y": 2.0, "i": 0.5, "j": -0.5, "f": 100.0}, 2.0, None)),
    ("n0010g0z5", ({"z": 5.0}, 0.0, "0010")),
    ("n12.5x1", ({"x": 1.0}, None, "12")),
    ("x-0", ({"x": -0.0}, None, None)),
    ("x.5y+2.", ({"x": 0.5, "y": 2.0}, None, None)),
    ("", ({}, None, None)),
    ("x1e3", ({"x": 1.0, "e": 3.0}, None, None)),  # E is a word of its own
    ("x1\t", ({"x": 1.0}, None, None)),  # white space to rs274 too
    ("x1\r", ({"x": 1.0}, None, None)),
    ("G1 X 1 0.5 y2", ({"x": 10.5, "y": 2.0}, 1.0, None)),  # spaces dropped, letters lowered
    ("N10 G0 Z5", ({"z": 5.0}, 0.0, "10")),
])
def test_reads_plain_lines(text: str, expected: object) -> None:
    found = split_plain(text)
    assert repr(found) == repr(expected)  # repr: -0.0 is not 0.0


@pytest.mark.parametrize("text", [
    "x1x2",  # a letter twice
    "1x2",  # not a letter first
    "x",  # a letter without a number
    "xy1",
    "g x1",  # a letter whose number is only spaces
    "m3",  # an M word has rules of its own
    "t1",  # an integer word
    "nx1",  # a bad line number
    "x1n2",  # N not first
    "g1x1h2",  # an integer word after plain ones
    "n1a",  # N ... then A without a number
    "x#1",
    "x[1]",
    "x1(c)",
    "x1\x0b",  # float() takes \v as white space; rs274 does not
    "x1\x0c",
    "x1\x00",
    "x1_0",  # float() takes underscores in numbers
    "x1é",
    "x1\udcff",  # a byte that is not UTF-8, kept as a surrogate
    "X1\xc9",  # a byte past ASCII
    "xinf",  # read as I N F
])
def test_leaves_the_rest_to_the_general_reader(text: str) -> None:
    assert split_plain(text) is None
