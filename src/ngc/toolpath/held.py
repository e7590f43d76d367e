"""A toolpath reader that holds the calls back and hands them on a batch at a time.

Interleaved call by call, the interpreter and a costly reader (``ngc flatten``'s writer) each
run slower than alone, as each pushes the other's work out of the processor's caches: on the
200,000-line contour benchmark, 0.6 s of 2.0.  :class:`Held` lets the interpreter run a
stretch of the program, then the readers take the calls it made, in order.

A held call is handed on after the toolpath has moved on, so its readers do not read the
toolpath's state: they read :class:`View`, a copy of it as it was when the call was made (all
but the position, which every move carries).  The copy is taken again at each operation that
changes what it holds, after the calls before it are handed on.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from ..canon import ops
from .frame import Frame, Pos
from .tracker import ArcMove, Consumer, Cubics, Toolpath

BATCH = 512  # calls held before they are handed on
# The operations after which the toolpath's frame, plane or tool are not what they were.
CHANGES = frozenset({
    ops.UseLengthUnits, ops.SetG5xOffset, ops.SetG92Offset, ops.SetXYRotation,
    ops.UseToolLengthOffset, ops.SelectPlane, ops.SelectTool, ops.ChangeTool,
    ops.ChangeToolNumber,
})


class View:
    """The toolpath's state (:class:`~ngc.toolpath.tracker.Toolpath`) as the held calls being
    handed on saw it: ``frame``, ``plane``, ``tool``, ``selected``."""

    __slots__ = ("frame", "plane", "selected", "tool")

    def __init__(self, toolpath: Toolpath) -> None:
        self.frame: Frame = toolpath.frame.copy()
        self.plane = toolpath.plane
        self.tool = toolpath.tool
        self.selected = toolpath.selected

    def take(self, toolpath: Toolpath) -> None:
        """The toolpath's state now."""
        self.frame = toolpath.frame.copy()
        self.plane = toolpath.plane
        self.tool = toolpath.tool
        self.selected = toolpath.selected


class Held:
    """A consumer of a toolpath that hands its calls on to ``readers`` (made with
    :meth:`follow`'s view) a batch at a time, each call to each reader in turn; ``after`` is
    called once a batch is handed on.  :meth:`settle` hands on what is held (call it before
    reading what the readers made, and when the program stops on an error, so that a reader's
    complaint about an earlier line comes first)."""

    def __init__(self, size: int = BATCH) -> None:
        self.size = size
        self.calls: list[tuple[Sequence[Callable[..., Any]], tuple[Any, ...]]] = []
        self.readers: list[Consumer] = []
        self.after: Callable[[], None] = _nothing
        self._toolpath: Toolpath | None = None
        self._view: View | None = None
        self._straight: tuple[Callable[..., Any], ...] = ()
        self._arc: tuple[Callable[..., Any], ...] = ()
        self._other: tuple[Callable[..., Any], ...] = ()

    def follow(self, toolpath: Toolpath) -> View:
        """The view of ``toolpath`` (whose consumer this is) for the readers to read."""
        self._toolpath = toolpath
        self._view = View(toolpath)
        return self._view

    def add(self, *readers: Consumer) -> None:
        """Readers, handed each call in the order they are added."""
        self.readers.extend(readers)
        self._straight = tuple(r.straight for r in self.readers)
        self._arc = tuple(r.arc for r in self.readers)
        self._other = tuple(r.other for r in self.readers)

    def settle(self) -> None:
        """Hand on the calls held."""
        calls = self.calls
        if not calls:
            return
        self.calls = []
        for readers, args in calls:
            for reader in readers:
                reader(*args)
        self.after()

    # -- the consumer protocol ------------------------------------------------------------------
    def straight(self, kind: str, start: Pos, end: Pos, line: int) -> None:
        self.calls.append((self._straight, (kind, start, end, line)))
        if len(self.calls) >= self.size:
            self.settle()

    def arc(self, arc: ArcMove, line: int) -> None:
        self.calls.append((self._arc, (arc, line)))
        if len(self.calls) >= self.size:
            self.settle()

    def nurbs(self, curve: ops.NurbsFeed, start: Pos, line: int) -> None:
        self.calls.append((tuple(r.nurbs for r in self.readers), (curve, start, line)))
        self.settle()  # (a curve may make many moves)

    def tap(self, start: Pos, bottom: Pos, line: int) -> None:
        self.calls.append((tuple(r.tap for r in self.readers), (start, bottom, line)))
        if len(self.calls) >= self.size:
            self.settle()

    def bezier(self, cubics: Cubics, motion: str, start: Pos, line: int) -> None:
        self.calls.append((tuple(r.bezier for r in self.readers), (cubics, motion, start, line)))
        if len(self.calls) >= self.size:
            self.settle()

    def other(self, op: ops.Op, line: int) -> None:
        if type(op) in CHANGES:  # (the toolpath has changed already: what came before first)
            self.settle()
            if self._view is not None and self._toolpath is not None:
                self._view.take(self._toolpath)
        self.calls.append((self._other, (op, line)))
        if len(self.calls) >= self.size:
            self.settle()

    def finish(self) -> None:
        self.settle()
        for reader in self.readers:
            reader.finish()


def _nothing() -> None:
    """No hook."""
