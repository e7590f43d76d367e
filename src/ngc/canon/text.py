"""The rs274 text sink: canonical operations printed exactly as LinuxCNC's ``rs274 -g`` prints them.

Each line is a running counter (``%5d ``), the block's N column, then the call in C printf format.

Formatting numbers is most of the sink's work.  A move's last four fields (Z A B C, or the helix
end and A B C of an arc) are most often the very objects the move before of its sort carried (an
axis not programmed keeps its value; traverses run at a clearance height, feeds and arcs at a
cutting depth): when they are, the text made for them is used again.  The test is identity, not
equality, so -0.0 never takes the text of 0.0.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, TextIO

from .ops import SHOWN, TEMPLATES, ArcFeed, Op, StraightFeed, StraightTraverse

_TAIL = "%.4f, %.4f, %.4f, %.4f"
# A move's whole line, and its line with the tail as one %s (see the module docstring).
_MOVES = (StraightTraverse, StraightFeed, ArcFeed)
_LINES: dict[type, str] = {kind: "%5d %s" + TEMPLATES[kind] + "\n" for kind in _MOVES}
_HEADS: dict[type, str] = {kind: template[:template.rindex(", " + _TAIL)] + ", %s)\n"
          for kind, template in _LINES.items()}
_ARC_LINE = _LINES[ArcFeed]
_ARC_HEAD = _HEADS[ArcFeed]


_ENGINE = -1  # the "fields shown" of an engine-dialect operation: written as its own text


def _format(kind: type) -> tuple[str, int]:
    """The line template of an op other than a move, and how many of its fields it shows (0:
    all; :data:`_ENGINE`: not a canonical operation, see :meth:`TextSink._engine_line`)."""
    if kind not in TEMPLATES:
        return "", _ENGINE
    return "%5d %s" + TEMPLATES[kind] + "\n", SHOWN.get(kind, 0)


class _Tail:
    """The tail of the last move of a sort that missed (its Z A B C objects), and its text once
    a move had the same tail again (None until then)."""

    __slots__ = ("a", "b", "c", "text", "z")

    def __init__(self) -> None:
        self.z: object = None
        self.a: object = None
        self.b: object = None
        self.c: object = None
        self.text: str | None = None


class TextSink:
    """Writes the rs274 transcript to a text stream.  An engine-dialect operation
    (:mod:`ngc.engine`) is written as ``ngc canon --dialect engine`` writes it.

    Lines are collected and written in batches (``flush`` writes the rest; call it at the end).
    """

    __slots__ = ("_append", "_count", "_cut", "_formats", "_lines", "_prints", "_stream",
                 "_traverse")

    BATCH_MASK = 4095  # write every 4096 operations

    def __init__(self, stream: TextIO, prints: TextIO | None = None) -> None:
        """``prints``: where ``(print,...)`` text goes when not into the transcript (rs274's stdout
        when the transcript goes to an output file)."""
        self._stream = stream
        self._prints = prints
        self._lines: list[str] = []
        self._append = self._lines.append
        self._count = 0
        # op type (not a move) -> its template and the number of fields shown
        self._formats: dict[type, tuple[str, int]] = {}
        # the tails kept: of the traverses, and of the feeds and arcs
        self._traverse = _Tail()
        self._cut = _Tail()

    def emit(self, op: Op, label: str, line: int) -> None:
        kind = type(op)
        if kind in _LINES:
            self.emit_move(kind, op, label, line)  # type: ignore[arg-type]
            return
        try:
            template, shown = self._formats[kind]
        except KeyError:
            template, shown = self._formats[kind] = _format(kind)
        if shown:
            if shown == _ENGINE:
                self._engine_line(op)
                return
            op = op[:shown]  # type: ignore[index]
        count = self._count = self._count + 1
        # (a tuple concatenation is cheaper than unpacking into a new tuple)
        self._append(template % ((count, label) + op))  # type: ignore[operator]  # noqa: RUF005
        if not count & self.BATCH_MASK:
            self.flush()

    def emit_move(self, kind: type, fields: Sequence[Any], label: str, line: int) -> None:
        """``emit(kind(*fields), label, line)`` for a move (see :func:`ngc.canon.ops.mover`),
        without making the op."""
        count = self._count = self._count + 1
        if kind is ArcFeed:
            x, y, i, j, turn, z, a, b, c = fields
            kept = self._cut
            if z is not kept.z:
                kept.z = z  # (the A B C kept may be older: the text waits for a match)
                kept.text = None
                self._append(_ARC_LINE % (count, label, x, y, i, j, turn, z, a, b, c))
            elif a is kept.a and b is kept.b and c is kept.c:
                text = kept.text
                if text is None:
                    text = kept.text = _TAIL % (z, a, b, c)
                self._append(_ARC_HEAD % (count, label, x, y, i, j, turn, text))
            else:
                kept.a, kept.b, kept.c, kept.text = a, b, c, None
                self._append(_ARC_LINE % (count, label, x, y, i, j, turn, z, a, b, c))
        else:
            x, y, z, a, b, c = fields
            kept = self._traverse if kind is StraightTraverse else self._cut
            if z is not kept.z:
                kept.z = z  # (the A B C kept may be older: the text waits for a match)
                kept.text = None
                self._append(_LINES[kind] % (count, label, x, y, z, a, b, c))
            elif a is kept.a and b is kept.b and c is kept.c:
                text = kept.text
                if text is None:
                    text = kept.text = _TAIL % (z, a, b, c)
                self._append(_HEADS[kind] % (count, label, x, y, text))
            else:
                kept.a, kept.b, kept.c, kept.text = a, b, c, None
                self._append(_LINES[kind] % (count, label, x, y, z, a, b, c))
        if not count & self.BATCH_MASK:
            self.flush()

    def _engine_line(self, op: object) -> None:
        """An engine-dialect operation (:mod:`ngc.engine`), as ``ngc canon --dialect engine``
        prints it (no counter, no N column); anything else is a ``TypeError``."""
        from ..dialects import engine_text

        self._append(engine_text(op) + "\n")
        if len(self._lines) > self.BATCH_MASK:
            self.flush()

    def print_text(self, text: str) -> None:
        if self._prints is not None:
            self._prints.write(text + "\n")
        else:
            self._append(text + "\n")

    def flush(self) -> None:
        """Write what is collected."""
        self._stream.write("".join(self._lines))
        self._lines.clear()
