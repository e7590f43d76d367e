"""The rs274 text sink: canonical operations printed exactly as LinuxCNC's ``rs274 -g`` prints them.

Each line is a running counter (``%5d ``), the block's N column, then the call in C printf format.
"""

from __future__ import annotations

from typing import TextIO

from .ops import TEMPLATES, Op


class TextSink:
    """Writes the rs274 transcript to a text stream.

    Lines are collected and written in batches (``flush`` writes the rest; call it at the end).
    """

    __slots__ = ("_count", "_lines", "_prints", "_stream", "_templates")

    BATCH_MASK = 4095  # write every 4096 operations

    def __init__(self, stream: TextIO, prints: TextIO | None = None) -> None:
        """``prints``: where ``(print,...)`` text goes when not into the transcript (rs274's stdout
        when the transcript goes to an output file)."""
        self._stream = stream
        self._prints = prints
        self._lines: list[str] = []
        self._count = 0
        self._templates: dict[type, str] = {}

    def emit(self, op: Op, label: str, line: int) -> None:
        count = self._count = self._count + 1
        try:
            template = self._templates[type(op)]
        except KeyError:
            template = self._templates[type(op)] = "%5d %s" + TEMPLATES[type(op)] + "\n"
        # (a tuple concatenation is cheaper than unpacking into a new tuple)
        self._lines.append(template % ((count, label) + op))  # type: ignore[operator]  # noqa: RUF005
        if not count & self.BATCH_MASK:
            self.flush()

    def print_text(self, text: str) -> None:
        if self._prints is not None:
            self._prints.write(text + "\n")
        else:
            self._lines.append(text + "\n")

    def flush(self) -> None:
        """Write what is collected."""
        self._stream.write("".join(self._lines))
        self._lines.clear()
