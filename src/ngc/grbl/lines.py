"""A line as Grbl receives it: what its serial port and its line reader keep of the characters
sent, before the G-code parser sees them (Grbl 1.1h ``serial.c`` and ``protocol.c``).

* The serial port picks off the real-time commands ``?`` ``~`` ``!`` and Ctrl-X, and every
  byte past 0x7F (the override commands; a UTF-8 character is such bytes, so it vanishes).
* The line reader ends a line at ``\\n`` or ``\\r``; drops spaces and control characters, and
  ``/`` (block delete is not supported: the character is ignored wherever it is); drops a
  ``(...)`` comment (to its ``)``, or to the end of the line) and a ``;`` comment (to the end of
  the line), without looking inside them; upper-cases letters; and keeps at most
  ``LINE_BUFFER_SIZE - 1`` characters: a line with more is error 11 and not parsed.
* ``%`` is not special: it reaches the parser, which rejects it (error 1).

The real-time commands do what they do on the machine (a status report, a feed hold, a reset);
here they are only removed.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from typing import TextIO

_COMMENT = re.compile(r"\([^)]*\)?|;.*", re.S)
# control characters and space, ? ~ ! (real-time), / (block delete), and past 0x7F
_DROPPED = re.compile(r"[^\x21-\x7f]|[?~!/]")
_LINE_ENDS = re.compile(r"\r\n?|\n")


def kept(line: str) -> str:
    """What Grbl keeps of one line (no line end in it): comments, spaces, real-time commands,
    block delete and characters past 0x7F dropped, letters upper-cased.  Its length says
    whether the line overflows.

    >>> kept("g1 x1.5 (move; fast) y-2 ; done"), kept("/G0 X1 ? (unclosed"), kept("Café%")
    ('G1X1.5Y-2', 'G0X1', 'CAF%')
    """
    if "(" in line or ";" in line:
        line = _COMMENT.sub("", line)
    line = line.replace(" ", "")  # (the commonest dropped character, dropped faster)
    if _DROPPED.search(line):
        line = _DROPPED.sub("", line)
    return line.upper()


def grbl_lines(line: str) -> list[str]:
    """The lines Grbl reads in one line of a file (without its line end): one, or more where a
    lone ``\\r`` ends a line within it.

    >>> grbl_lines("G0 X1"), grbl_lines("G0 X1\\rG1 X2")
    (['G0 X1'], ['G0 X1', 'G1 X2'])
    """
    if "\r" in line or "\n" in line:
        return _LINE_ENDS.split(line)
    return [line]


def without_end(line: str) -> str:
    """A line without its line end (``\\r\\n``, ``\\n`` or ``\\r``)."""
    if line.endswith("\n"):
        line = line[:-1]
    return line[:-1] if line.endswith("\r") else line


# a line longer than this is read in pieces of this size, keeping what Grbl would keep of it
PIECE_CHARS = 1 << 16
# pieces of one line after which it is given up on (the zero device has no line end)
MAX_PIECES = 256


class EndlessLine(Exception):
    """A line with no end in sight: :data:`MAX_PIECES` pieces and still no line end."""

    def __init__(self, line: int) -> None:
        super().__init__(f"line {line} goes on for more than {MAX_PIECES * PIECE_CHARS} "
                         "characters with no line end: not a program")
        self.line = line


def read_lines(stream: TextIO, line_chars: int) -> Iterator[str]:
    """The lines of a text stream opened with ``newline=""``, with their line ends; memory
    bounded by :data:`PIECE_CHARS` whatever the file (one with no line end at all, say).

    A line longer than that is given as what Grbl keeps of it (its comments and spaces gone,
    its kept characters cut after ``line_chars + 1``: it overflows as it did), with a ``(`` or
    ``;`` where a comment is still open, so that the next piece is read as Grbl reads it.
    Raises :class:`EndlessLine` past :data:`MAX_PIECES` pieces.
    """
    number = 0
    while True:
        piece = stream.readline(PIECE_CHARS)
        if not piece:
            return
        number += 1
        if len(piece) < PIECE_CHARS or piece.endswith(("\n", "\r")):
            yield piece
            continue
        line = _reduced(piece, line_chars)
        for _ in range(MAX_PIECES):
            piece = stream.readline(PIECE_CHARS)
            line = _reduced(line + without_end(piece), line_chars)
            if len(piece) < PIECE_CHARS or piece.endswith(("\n", "\r")):
                break
        else:
            raise EndlessLine(number)
        yield line + "\n"


def _reduced(text: str, line_chars: int) -> str:
    """``text`` as Grbl holds it so far: its kept characters (cut after ``line_chars + 1``)
    and a ``(`` or ``;`` if it ends in a comment that is still open."""
    last = None
    for last in _COMMENT.finditer(text):  # noqa: B007 (the last one is wanted)
        pass
    open_comment = ""
    if last is not None and last.end() == len(text):
        comment = last.group()
        if comment.startswith(";") or not comment.endswith(")"):
            open_comment = comment[0]
    return kept(text)[: line_chars + 1] + open_comment
