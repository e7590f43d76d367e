"""Will it fit the machine: a reader of the toolpath that finds where the moves go past the soft
limits of the machine's axes (``[AXIS_<letter>]``/``[JOINT_<n>]`` MIN_LIMIT and MAX_LIMIT), as
AXIS warns when it loads a program ("Program exceeds machine maximum on axis X").

Positions are the toolpath's machine coordinates, in the machine's units, the tool length offset
included (the axes' own positions); an arc counts with its extremes.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import NamedTuple

from ..canon import ops
from ..render import curves
from .frame import Pos
from .tracker import FEED, ArcMove, Cubics, Toolpath

AXES = "XYZABC"
UNIT_VECTORS = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))


class Excess(NamedTuple):
    """An axis going past one of its soft limits: ``side`` ``"minimum"`` or ``"maximum"``, the
    limit, by how much at most (machine units), and the first line that goes past."""

    axis: str
    side: str
    limit: float
    by: float
    line: int

    def text(self, units: str) -> str:
        unit = "deg" if self.axis in "ABC" else units
        return (f"Program exceeds machine {self.side} on axis {self.axis}: {self.by:.4f} {unit} "
                f"past {self.limit:g}, first at line {self.line}")


class LimitWatch:
    """A toolpath reader keeping, for each axis and side, the first line past the limit and the
    greatest excess; ``excesses()`` lists them in axis order."""

    def __init__(self, limits: Mapping[str, tuple[float, float]], toolpath: Toolpath) -> None:
        self.toolpath = toolpath
        self.limits = [(i, limits[a][0], limits[a][1]) for i, a in enumerate(AXES) if a in limits]
        self.found: dict[tuple[int, int], tuple[float, int]] = {}  # (axis, side) -> (by, line)

    def _see(self, i: int, lo_value: float, hi_value: float, line: int) -> None:
        for axis, lo, hi in self.limits:
            if axis != i:
                continue
            if lo_value < lo:
                self._past(axis, 0, lo - lo_value, line)
            if hi_value > hi:
                self._past(axis, 1, hi_value - hi, line)

    def _past(self, axis: int, side: int, by: float, line: int) -> None:
        key = (axis, side)
        held = self.found.get(key)
        if held is None:
            self.found[key] = (by, line)
        elif by > held[0]:
            self.found[key] = (by, held[1])

    def _point(self, p: Sequence[float], line: int) -> None:
        for axis, lo, hi in self.limits:
            v = p[axis]
            if v < lo:
                self._past(axis, 0, lo - v, line)
            elif v > hi:
                self._past(axis, 1, v - hi, line)

    def excesses(self) -> list[Excess]:
        out = []
        for (axis, side), (by, line) in sorted(self.found.items()):
            limit = next(lim for i, *lim in self.limits if i == axis)[side]
            out.append(Excess(AXES[axis], ("minimum", "maximum")[side], limit, by, line))
        return out

    # -- the toolpath's consumer protocol -----------------------------------------------------
    def straight(self, kind: str, start: Pos, end: Pos, line: int) -> None:
        self._point(end, line)

    def arc(self, arc: ArcMove, line: int) -> None:
        f = curves.frame(arc.start, arc.end, arc.centre, arc.normal, arc.turns)
        for i, v in enumerate(UNIT_VECTORS):
            lo, hi = curves.extremes(f, v)
            self._see(i, lo, hi, line)
        self._point(arc.end, line)

    def nurbs(self, curve: ops.NurbsFeed, start: Pos, line: int) -> None:
        """A curve counts with its control points (it lies within them)."""
        tp = self.toolpath
        p = tp.prog
        for x, y in curve.points:
            self._point(tp.frame.to_machine((x, y, p[2], p[3], p[4], p[5])), line)

    def tap(self, start: Pos, bottom: Pos, line: int) -> None:
        self._point(bottom, line)

    def bezier(self, cubics: Cubics, motion: str, start: Pos, line: int) -> None:
        for i, c in enumerate(cubics):
            lo, hi = curves.cubic_range(c)
            self._see(i, lo, hi, line)

    def other(self, op: ops.Op, line: int) -> None:
        """Nothing else moves the machine."""

    def finish(self) -> None:
        """Nothing is held back."""


class FastFeed(NamedTuple):
    """Feeds that ask an axis (or the path, ``axis`` ``"path"``: [TRAJ]MAX_LINEAR_VELOCITY) for
    more than its MAX_VELOCITY: the greatest speed asked (machine units/s), the limit, and the
    first line that asks too much.  Not an error: the machine runs such moves slower."""

    axis: str
    asked: float
    limit: float
    line: int

    def text(self, units: str) -> str:
        what = "the path" if self.axis == "path" else f"axis {self.axis}"
        key = "MAX_LINEAR_VELOCITY" if self.axis == "path" else "MAX_VELOCITY"
        return (f"Feed faster than the machine: {what} asked for up to {self.asked:.4f} "
                f"{units}/s, past its {key} of {self.limit:g} {units}/s, first at line "
                f"{self.line} (the machine runs those moves slower)")


class FeedWatch:
    """A toolpath reader that finds the feeds (per minute: G94, and G93's, which canon gives per
    minute) that ask a linear axis for more than its MAX_VELOCITY or the path for more than
    [TRAJ]MAX_LINEAR_VELOCITY: a straight move asks each axis for its share of the feed, an arc
    asks the axes of its plane for the whole feed (at the points of the circle that run along
    them).  Speeds are in machine units per second."""

    def __init__(self, speeds: Mapping[str, float], max_linear: float | None,
                 toolpath: Toolpath) -> None:
        self.toolpath = toolpath
        self.speeds = [(i, speeds[a]) for i, a in enumerate("XYZ") if a in speeds]
        self.max_linear = max_linear
        self.per_second = 0.0  # the feed, machine units per second (0: none, or per revolution)
        self.found: dict[str, list[float]] = {}  # axis -> [asked, limit, line]

    def _ask(self, axis: str, asked: float, limit: float, line: int) -> None:
        if asked <= limit * (1.0 + 1e-9):
            return
        held = self.found.get(axis)
        if held is None:
            self.found[axis] = [asked, limit, float(line)]
        elif asked > held[0]:
            held[0] = asked

    def excesses(self) -> list[FastFeed]:
        order = {a: i for i, a in enumerate("XYZ")} | {"path": 3}
        return [FastFeed(axis, asked, limit, int(line))
                for axis, (asked, limit, line) in sorted(self.found.items(),
                                                          key=lambda item: order[item[0]])]

    # -- the toolpath's consumer protocol -----------------------------------------------------
    def straight(self, kind: str, start: Pos, end: Pos, line: int) -> None:
        v = self.per_second
        if kind != FEED or v <= 0.0:
            return
        d = [end[i] - start[i] for i in range(3)]
        length = math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2])
        if length <= 0.0:
            return
        for i, limit in self.speeds:
            self._ask("XYZ"[i], v * abs(d[i]) / length, limit, line)
        if self.max_linear is not None:
            self._ask("path", v, self.max_linear, line)

    def arc(self, arc: ArcMove, line: int) -> None:
        v = self.per_second
        if v <= 0.0:
            return
        first, second, _ = self.toolpath.plane
        for i, limit in self.speeds:
            if i in (first, second):
                self._ask("XYZ"[i], v, limit, line)
        if self.max_linear is not None:
            self._ask("path", v, self.max_linear, line)

    def nurbs(self, curve: ops.NurbsFeed, start: Pos, line: int) -> None:
        """Not followed."""

    def tap(self, start: Pos, bottom: Pos, line: int) -> None:
        """Synchronised to the spindle: not a feed."""

    def bezier(self, cubics: Cubics, motion: str, start: Pos, line: int) -> None:
        """Engine programs: not followed."""

    def other(self, op: ops.Op, line: int) -> None:
        kind = type(op)
        if kind is ops.SetFeedRate:
            # (in machine units, as the feed was set: the frame's scale then)
            self.per_second = op.rate * self.toolpath.frame.scale / 60.0  # type: ignore[attr-defined]
        elif kind is ops.SetFeedMode and op.mode == 1:  # type: ignore[attr-defined]
            self.per_second = 0.0  # (per revolution: the spindle's speed decides)

    def finish(self) -> None:
        """Nothing is held back."""
