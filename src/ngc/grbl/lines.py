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


# -- grblHAL's line reader (grblHAL/core protocol.c, protocol_main_loop, and gcode.c,
#    gc_normalize_block, at commit 04ce2c5c) -----------------------------------------------------
_HAL_CONTROL = re.compile(r"[\x00-\x1f]")
_HAL_REALTIME = frozenset("?!~\x7f")  # the stream's real-time characters, and DEL
_HAL_DROPPED = re.compile(r"[\x00-\x20)]")  # blanks, and a ")" that closes no comment
DEL = "\x7f"


def past_ascii(line: str) -> bool:
    """A character past 0x7F: what grblHAL keeps of it is its driver's stream's (the real-time
    override commands are such bytes), so the grblHAL row does not check such a line."""
    return not line.isascii()


def hal_received(line: str) -> str:
    """What grblHAL's ``protocol.c`` puts in its line buffer (its length is held against
    ``LINE_BUFFER_SIZE``): the leading blanks and control characters dropped, control
    characters dropped anywhere, spaces and comments kept; the real-time ``?`` ``!`` ``~``
    taken by the stream except in a ``(`` comment or a line that starts with ``$`` or ``[``
    (``keep_rt_commands``); DEL takes back the character before it.

    >>> hal_received("  G0 X1 ? (a?) ; b?"), hal_received("\\tG1\\x01X2")
    ('G0 X1  (a?) ; b', 'G1X2')
    """
    start = 0
    while start < len(line) and line[start] <= " ":
        start += 1
    line = line[start:]
    if _HAL_CONTROL.search(line):
        line = _HAL_CONTROL.sub("", line)
    if _HAL_REALTIME.isdisjoint(line):
        return line
    kept: list[str] = []
    for char in line:
        if char == DEL:
            if kept:
                kept.pop()
        elif char == "~" or char == "!" or char == "?":
            if _keeps_realtime(kept):
                kept.append(char)
        else:
            kept.append(char)
    return "".join(kept)


def _keeps_realtime(kept: list[str]) -> bool:
    """``keep_rt_commands`` after the characters ``kept`` (``protocol.c``: set by a ``$`` or
    ``[`` first and by a ``(`` outside a ``;`` comment, cleared by ``)`` and ``;``)."""
    keep = bool(kept) and kept[0] in "$["
    parentheses = semicolon = False
    for char in kept:
        if char == "(" and not keep:
            parentheses = not semicolon
            keep = parentheses
        elif char == ")" and not semicolon:
            parentheses = keep = False
        elif char == ";" and not parentheses:
            keep, semicolon = False, True
    return keep


def hal_normalized(received: str) -> str:
    """What grblHAL's parser reads of a line (``gc_normalize_block``): a ``/`` that starts it
    dropped (block delete is off at power-up; elsewhere ``/`` stays, and is error 1), ``(...)``
    and ``;`` comments dropped, a ``)`` that closes none dropped, blanks dropped, letters
    upper-cased.

    >>> hal_normalized("/g0 x1 (a) ; b"), hal_normalized("G0 X1)/"), hal_normalized("%")
    ('G0X1', 'G0X1/', '%')
    """
    if received.startswith("/"):
        received = received[1:]
    if "(" in received or ";" in received:
        received = _COMMENT.sub("", received)
    return _HAL_DROPPED.sub("", received).upper()
