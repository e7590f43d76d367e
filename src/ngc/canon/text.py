"""The rs274 text sink: canonical operations printed exactly as LinuxCNC's ``rs274 -g`` prints them.

Each line is a running counter (``%5d ``), the block's N column, then the call in C printf format.

Formatting numbers is most of the sink's work.  A move's last four fields (Z A B C, or the helix
end and A B C of an arc) are most often the very objects the move before carried (an axis not
programmed keeps its value): when they are, the text made for them is used again.  The test is
identity, not equality, so -0.0 never takes the text of 0.0.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, TextIO

from .ops import SHOWN, TEMPLATES, ArcFeed, Op, StraightFeed, StraightTraverse

# The ops whose last four fields are the tail kept (see the module docstring): the moves, whose
# tail starts at field 2 (a straight move) or 5 (an arc).
_TAILED = (StraightTraverse, StraightFeed, ArcFeed)
_TAIL = "%.4f, %.4f, %.4f, %.4f"
_Format = tuple[str, str, int, list[Any]]


def _format(kind: type) -> _Format:
    template = "%5d %s" + TEMPLATES[kind] + "\n"
    if kind in SHOWN:  # (a negative start: the number of fields shown)
        return template, "", -SHOWN[kind], []
    if kind not in _TAILED:
        return template, "", 0, []
    head = template[:template.rindex(", " + _TAIL)] + ", %s)\n"
    return template, head, len(kind._fields) - 4, [None, (None,) * 4, None]


class TextSink:
    """Writes the rs274 transcript to a text stream.

    Lines are collected and written in batches (``flush`` writes the rest; call it at the end).
    """

    __slots__ = ("_count", "_formats", "_lines", "_prints", "_stream")

    BATCH_MASK = 4095  # write every 4096 operations

    def __init__(self, stream: TextIO, prints: TextIO | None = None) -> None:
        """``prints``: where ``(print,...)`` text goes when not into the transcript (rs274's stdout
        when the transcript goes to an output file)."""
        self._stream = stream
        self._prints = prints
        self._lines: list[str] = []
        self._count = 0
        # op type -> its template, and for a move: the template with the tail as one %s, where
        # the tail starts, and [the last move's first tail field, a tail, that tail's text once a
        # move had it again]
        self._formats: dict[type, _Format] = {}

    def emit(self, op: Op, label: str, line: int) -> None:
        try:
            template, _, i, _ = self._formats[type(op)]
        except KeyError:
            template, _, i, _ = self._formats[type(op)] = _format(type(op))
        if i:
            if i < 0:
                op = op[:-i]  # type: ignore[index]
            else:
                self.emit_move(type(op), op, label, line)  # type: ignore[arg-type]
                return
        count = self._count = self._count + 1
        # (a tuple concatenation is cheaper than unpacking into a new tuple)
        self._lines.append(template % ((count, label) + op))  # type: ignore[operator]  # noqa: RUF005
        if not count & self.BATCH_MASK:
            self.flush()

    def emit_move(self, kind: type, fields: Sequence[Any], label: str, line: int) -> None:
        """``emit(kind(*fields), label, line)`` for a move (see :func:`ngc.canon.ops.mover`),
        without making the op."""
        count = self._count = self._count + 1
        try:
            template, head, i, memo = self._formats[kind]
        except KeyError:
            template, head, i, memo = self._formats[kind] = _format(kind)
        z = fields[i]
        if z is memo[0]:
            last = memo[1]
            a, b, c = fields[i + 1], fields[i + 2], fields[i + 3]
            if a is last[1] and b is last[2] and c is last[3]:
                text = memo[2]
                if text is None:
                    text = memo[2] = _TAIL % (z, a, b, c)
                if i == 2:
                    line_text = head % (count, label, fields[0], fields[1], text)
                else:
                    line_text = head % (count, label, fields[0], fields[1], fields[2], fields[3],
                                        fields[4], text)
                self._lines.append(line_text)
                if not count & self.BATCH_MASK:
                    self.flush()
                return
            memo[1] = (z, a, b, c)
        else:
            memo[0] = z  # (the A B C kept may be older: the text waits for a match)
        memo[2] = None
        self._lines.append(template % (count, label, *fields))
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
