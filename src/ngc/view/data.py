"""The toolpath as the page of ``ngc view`` draws it: polylines of points in machine coordinates
and, per segment, its line, kind, tool and feed, in flat typed arrays (one buffer for the page).

:class:`PathArrays` is a reader of the toolpath (:mod:`ngc.toolpath`): straight moves are one
segment each, arcs and helices are cut into chords within a tolerance, engine curves sampled, a
rigid tap goes down and back.  Consecutive moves share their points; a move that does not start
where the last one ended starts a new polyline.
"""

from __future__ import annotations

import math
from array import array
from collections.abc import Sequence

from ..canon import ops
from ..engine.bezier import point
from ..render import curves
from ..toolpath.frame import Pos
from ..toolpath.tracker import (
    ARC,
    BEZIER,
    FEED,
    NURBS,
    PROBE,
    RAPID,
    SYNC,
    TAP,
    ArcMove,
    Cubics,
    Toolpath,
)

# The kinds of segment, as the page numbers them (its legend names them).
KIND_CODES = {RAPID: 0, FEED: 1, ARC: 2, PROBE: 3, SYNC: 4, TAP: 5, NURBS: 6, BEZIER: 7}
CHORD_TOLERANCE = 0.002  # mm: how far a chord may leave an arc (0.00008 inch on an inch machine)
MAX_CHORDS = 4096  # per arc turn at most (a huge arc still draws in bounded memory)
CURVE_STEPS = 16  # chords of an engine cubic or a NURBS span


class PathArrays:
    """The toolpath's segments as flat arrays (see the module's doc)."""

    def __init__(self, toolpath: Toolpath, inch_machine: bool = False) -> None:
        self.toolpath = toolpath
        self.points = array("d")
        self.starts = array("I")
        self.line = array("I")
        self.feed = array("f")
        self.tool = array("H")
        self.kind = array("B")
        self.tolerance = CHORD_TOLERANCE / (25.4 if inch_machine else 1.0)
        self.inch_machine = inch_machine
        self._last: tuple[float, float, float] | None = None
        self._feed = 0.0  # machine units per minute
        self.rapid_length = 0.0
        self.cut_length = 0.0
        self.cut_by_tool: dict[int, float] = {}
        # The extents, as ngc check's: an axis enters them when a move changes it or a cut
        # starts with it where it is, not from the start position alone.
        self.low = [math.inf] * 3
        self.high = [-math.inf] * 3
        self._waiting = [True, True, True]

    @property
    def count(self) -> int:
        return len(self.line)

    def _begin(self, p: Sequence[float]) -> None:
        q = (p[0], p[1], p[2])
        if q != self._last:
            self.starts.append(len(self.points) // 3)
            self.points.extend(q)
            self._last = q

    def _to(self, p: Sequence[float], line: int, kind: int) -> None:
        q = (p[0], p[1], p[2])
        last = self._last
        assert last is not None
        d = math.dist(last, q)
        waiting = self._waiting
        for axis in range(3):
            if waiting[axis]:
                if kind != 0:
                    self._include(axis, last[axis])
                elif q[axis] == last[axis]:
                    continue
                waiting[axis] = False
            self._include(axis, q[axis])
        if kind == 0:
            self.rapid_length += d
        else:
            self.cut_length += d
            tool = self.toolpath.tool
            self.cut_by_tool[tool] = self.cut_by_tool.get(tool, 0.0) + d
        self.points.extend(q)
        self.line.append(line)
        self.feed.append(0.0 if kind == 0 else self._feed)
        self.tool.append(max(0, min(self.toolpath.tool, 65535)))
        self.kind.append(kind)
        self._last = q

    def _include(self, axis: int, v: float) -> None:
        if math.isfinite(v):
            if v < self.low[axis]:
                self.low[axis] = v
            if v > self.high[axis]:
                self.high[axis] = v

    # -- the toolpath's consumer protocol -----------------------------------------------------
    def straight(self, kind: str, start: Pos, end: Pos, line: int) -> None:
        self._begin(start)
        self._to(end, line, KIND_CODES.get(kind, 1))

    def arc(self, arc: ArcMove, line: int) -> None:
        self._begin(arc.start)
        f = curves.frame(arc.start, arc.end, arc.centre, arc.normal, arc.turns)
        r = max(f.r0, f.r1)
        n = 1
        if r > self.tolerance:
            step = 2.0 * math.acos(max(-1.0, 1.0 - self.tolerance / r))
            n = max(1, math.ceil(f.sweep / step))
        n = min(n, MAX_CHORDS * max(1, math.ceil(f.sweep / curves.TAU)))
        for k in range(1, n):
            self._to(f.point(f.sweep * k / n), line, 2)
        self._to(arc.end, line, 2)

    def nurbs(self, curve: ops.NurbsFeed, start: Pos, line: int) -> None:
        """Drawn through its control points to its end (the curve lies within them)."""
        self._begin(start)
        tp = self.toolpath
        p = tp.prog
        for x, y in curve.points[1:-1]:
            self._to(tp.frame.to_machine((x, y, p[2], p[3], p[4], p[5])), line, 6)
        self._to(tp.pos, line, 6)

    def tap(self, start: Pos, bottom: Pos, line: int) -> None:
        self._begin(start)
        self._to(bottom, line, 5)
        self._to(start, line, 5)

    def bezier(self, cubics: Cubics, motion: str, start: Pos, line: int) -> None:
        self._begin(start)
        kind = 0 if motion == RAPID else 7
        for k in range(1, CURVE_STEPS + 1):
            self._to([point(c, k / CURVE_STEPS) for c in cubics[:3]], line, kind)

    def other(self, op: ops.Op, line: int) -> None:
        kind = type(op)
        if kind is ops.SetFeedRate:
            # (in machine units, as the feed was set: the frame's scale then)
            self._feed = op.rate * self.toolpath.frame.scale  # type: ignore[attr-defined]
        elif kind is ops.SetFeedMode and op.mode == 1:  # type: ignore[attr-defined]
            self._feed = 0.0  # (per revolution)

    def finish(self) -> None:
        """Nothing is held back."""

    # -- what the page takes ------------------------------------------------------------------
    def extents(self) -> tuple[list[float], list[float]]:
        """The lowest and highest X, Y, Z where the program takes the tool (an axis no move
        changed: where it stayed; nothing moved: the origin)."""
        low, high = list(self.low), list(self.high)
        last = self._last or (0.0, 0.0, 0.0)
        for axis in range(3):
            if low[axis] > high[axis]:
                low[axis] = high[axis] = last[axis] if math.isfinite(last[axis]) else 0.0
        return low, high

    def relative_points(self, origin: Sequence[float]) -> array[float]:
        """The points less ``origin``, as 32-bit floats (a page's precision is the screen's)."""
        out = array("f", bytes(4 * len(self.points)))
        pts = self.points
        for axis in range(3):
            o = origin[axis]
            out[axis::3] = array("f", [_clamp(v - o) for v in pts[axis::3]])
        return out


def _clamp(v: float) -> float:
    """A coordinate a 32-bit float holds (past its range: its largest, not inf)."""
    if v != v:
        return 0.0
    return max(-3.0e38, min(3.0e38, v))
