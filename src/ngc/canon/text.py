"""The rs274 text sink: canonical operations printed exactly as LinuxCNC's ``rs274 -g`` prints them.

Each line is a running counter (``%5d ``), the block's N column, then the call in C printf format.
"""

from __future__ import annotations

from typing import TextIO

from .ops import Op


class TextSink:
    """Writes the rs274 transcript to a text stream."""

    __slots__ = ("_count", "_write")

    def __init__(self, stream: TextIO) -> None:
        self._write = stream.write
        self._count = 0

    def emit(self, op: Op, label: str, line: int) -> None:
        self._count += 1
        self._write("%5d %s%s\n" % (self._count, label, op.TEXT % op))  # noqa: UP031

    def print_text(self, text: str) -> None:
        self._write(text + "\n")
