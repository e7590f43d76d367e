"""What a picture of the toolpath shows, in one view: a reader of the toolpath that turns each
move into styled two-dimensional primitives (lines, exact circular arcs, cubic Béziers) and
marks (drill points, tool changes, the point where the program stopped), spooled so memory
stays flat in the program's length; a writer (:mod:`ngc.render.svg`) reads them back.

Coordinates are the view's (``right``, ``up``) in machine units; the view looks along
``-toward``.  An arc whose plane faces the view is an exact arc; any other arc or helix is
drawn as cubic Béziers within :data:`~ngc.render.curves.BEZIER_TOLERANCE` of it; a G5 curve is
its own cubic, a G5.1 its own quadratic; a NURBS curve is drawn as lines within the tolerance.
"""

from __future__ import annotations

import contextlib
import itertools
import math
import tempfile
from array import array
from collections.abc import Callable, Iterator, Sequence
from typing import IO, Any, NamedTuple

from ..canon import ops
from ..planner.geometry import nurbs_polyline
from ..toolpath.frame import Pos
from ..toolpath.tracker import (
    ARC,
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
from . import curves

Vec = tuple[float, float, float]

SQ2, SQ3, SQ6 = math.sqrt(2.0), math.sqrt(3.0), math.sqrt(6.0)


class View(NamedTuple):
    """A parallel projection: screen right and up as unit vectors in machine coordinates, and
    the direction toward the viewer (``right`` x ``up``); ``axes`` names the screen's axes
    where they are machine axes."""

    name: str
    right: Vec
    up: Vec
    toward: Vec
    axes: tuple[str, str] | None


VIEWS = {
    "top": View("top", (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0), ("X", "Y")),
    "front": View("front", (1.0, 0.0, 0.0), (0.0, 0.0, 1.0), (0.0, -1.0, 0.0), ("X", "Z")),
    "side": View("side", (0.0, 1.0, 0.0), (0.0, 0.0, 1.0), (1.0, 0.0, 0.0), ("Y", "Z")),
    "iso": View("iso", (1 / SQ2, 1 / SQ2, 0.0), (-1 / SQ6, 1 / SQ6, 2 / SQ6),
                (1 / SQ3, -1 / SQ3, 1 / SQ3), None),
    # a lathe's: Z to the right, X up (the XZ plane seen from -Y turned a quarter round)
    "lathe": View("lathe", (0.0, 0.0, 1.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), ("Z", "X")),
}

# primitive types
LINE, ARC_2D, CUBIC, QUAD, MARK = 0.0, 1.0, 2.0, 3.0, 4.0
# marks
DRILL, TOOL_CHANGE, STOPPED = 0.0, 1.0, 2.0

# what --color keys moves by
COLOR_KEYS = ("kind", "tool", "feed", "line")
KINDS = (RAPID, FEED, ARC, PROBE, SYNC, TAP, NURBS)
KIND_INDEX = {k: float(i) for i, k in enumerate(KINDS)}
KIND_INDEX[ARC] = KIND_INDEX[FEED]  # (an arc is a feed: one colour, one path for a contour)

QUADRANTS = ((0.0, 1.0, 0.0), (0.5 * math.pi, 0.0, 1.0), (math.pi, -1.0, 0.0),
             (1.5 * math.pi, 0.0, -1.0))  # (angle, cos, sin) where a circle is widest

HELD = 10000  # rapids of the approach held back at most

RECORD = 11  # doubles a record holds: type, key, dashed, then up to eight coordinates


class Spool:
    """Records of :data:`RECORD` doubles, in memory up to ``limit`` of them, then in a
    temporary file (removed when closed)."""

    def __init__(self, limit: int = 1 << 16) -> None:
        self.limit = limit
        self.buf = array("d")
        self.file: IO[bytes] | None = None
        self.count = 0

    def add(self, values: Sequence[float]) -> None:
        buf = self.buf
        buf.extend(values)
        if len(values) != RECORD:
            buf.extend((0.0,) * (RECORD - len(values)))
        self.count += 1
        if self.count % self.limit == 0:
            self._spill()

    def _spill(self) -> None:
        if self.file is None:
            self.file = tempfile.TemporaryFile()  # noqa: SIM115 (closed by close())
        self.buf.tofile(self.file)
        self.buf = array("d")

    def __iter__(self) -> Iterator[tuple[float, ...]]:
        if self.file is not None:
            self.file.flush()
            self.file.seek(0)
            size = self.limit * RECORD
            while True:
                chunk = array("d")
                with contextlib.suppress(EOFError):  # (a last, shorter chunk is read all the same)
                    chunk.fromfile(self.file, size)
                if not chunk:
                    break
                yield from _records(chunk)
                if len(chunk) < size:
                    break
        yield from _records(self.buf)

    def close(self) -> None:
        if self.file is not None:
            self.file.close()
            self.file = None


def _records(chunk: array[float]) -> Iterator[tuple[float, ...]]:
    return zip(*[iter(chunk)] * RECORD, strict=True)


class Box:
    """The least and greatest of each coordinate seen."""

    __slots__ = ("high", "low")

    def __init__(self, dims: int) -> None:
        self.low = [math.inf] * dims
        self.high = [-math.inf] * dims

    def add(self, i: int, lo: float, hi: float) -> None:
        if lo < self.low[i]:
            self.low[i] = lo
        if hi > self.high[i]:
            self.high[i] = hi

    @property
    def empty(self) -> bool:
        return not self.low[0] <= self.high[0]


class Scene:
    """A reader of the toolpath that draws it in ``view``, keyed for colour by ``color`` (one
    of :data:`COLOR_KEYS`).  Rapids before the first move that cuts are left out (as AXIS
    draws), unless ``approach``.  ``scene.toolpath`` is the canon sink to give an interpreter
    (``toolpath``: one made for several readers, see :class:`~ngc.toolpath.tracker.Tee`).

    After the run: ``box`` (the drawing's extents in the view), ``extents`` (machine X Y Z; the
    isometric view's dimensions: other views take arcs' extremes into ``box`` only),
    ``length`` (machine units, rapids and feeds), ``keys`` (the colour keys used),
    ``spool`` (the primitives), ``marks`` (the marks)."""

    def __init__(self, view: View, *, color: str = "kind", approach: bool = False,
                 inch_machine: bool = False, toolpath: Toolpath | None = None) -> None:
        if color not in COLOR_KEYS:
            raise ValueError(f"color must be one of {', '.join(COLOR_KEYS)}, not {color!r}")
        self.view = view
        self.color = color
        self.drawing = approach  # drawing rapids already
        self.held: list[tuple[Callable[..., None], tuple[Any, ...]]] = []  # the approach's rapids
        self.toolpath = Toolpath(self, inch_machine=inch_machine) if toolpath is None else toolpath
        self.spool = Spool()
        self.marks = Spool(limit=1 << 12)  # drill points, tool changes, the stop: drawn on top
        self.box = Box(2)
        self.extents = Box(3)
        self.length = 0.0
        self.rapid_length = 0.0
        self.keys: set[float] = set()
        self.key_lo, self.key_hi = math.inf, -math.inf
        self.feed = 0.0
        self.plunge: tuple[Pos, int] | None = None  # a straight feed down Z, and its line
        self.last_end: Sequence[float] | None = None  # the end of the last move drawn
        self.last_uv = (0.0, 0.0)  # its place in the view
        self.kind_keys = KIND_INDEX if color == "kind" else None
        self.top = view.right == (1.0, 0.0, 0.0) and view.up == (0.0, 1.0, 0.0)

    # -- helpers ------------------------------------------------------------------------------
    def _uv(self, p: Sequence[float]) -> tuple[float, float]:
        r, u = self.view.right, self.view.up
        return (p[0] * r[0] + p[1] * r[1] + p[2] * r[2], p[0] * u[0] + p[1] * u[1] + p[2] * u[2])

    def _key(self, kind: str, line: int) -> float:
        c = self.color
        if c == "kind":
            key = KIND_INDEX[kind]
        elif c == "tool":
            key = float(self.toolpath.tool)
        elif c == "feed":
            key = -1.0 if kind == RAPID else self.feed
        else:
            key = float(line)
        if c == "kind" or c == "tool":
            self.keys.add(key)
        elif key >= 0.0:
            if key < self.key_lo:
                self.key_lo = key
            if key > self.key_hi:
                self.key_hi = key
        return key

    @property
    def key_range(self) -> tuple[float, float]:
        """The least and greatest feed or line keyed (0, 0 if none)."""
        return (self.key_lo, self.key_hi) if self.key_lo <= self.key_hi else (0.0, 0.0)

    def _point(self, p: Sequence[float]) -> tuple[float, float]:
        """Take ``p`` into the extents; its place in the view."""
        x, y, z = p[0], p[1], p[2]
        if self.top:
            u, v = x, y
        else:
            r, w = self.view.right, self.view.up
            u = x * r[0] + y * r[1] + z * r[2]
            v = x * w[0] + y * w[1] + z * w[2]
        lo, hi = self.box.low, self.box.high
        if u < lo[0]:
            lo[0] = u
        if u > hi[0]:
            hi[0] = u
        if v < lo[1]:
            lo[1] = v
        if v > hi[1]:
            hi[1] = v
        lo, hi = self.extents.low, self.extents.high
        if x < lo[0]:
            lo[0] = x
        if x > hi[0]:
            hi[0] = x
        if y < lo[1]:
            lo[1] = y
        if y > hi[1]:
            hi[1] = y
        if z < lo[2]:
            lo[2] = z
        if z > hi[2]:
            hi[2] = z
        return u, v

    def mark(self, kind: float, p: Sequence[float], value: float = 0.0) -> None:
        u, v = self._uv(p)
        self.marks.add((MARK, kind, 0.0, u, v, value))

    # -- the toolpath's consumer protocol -----------------------------------------------------
    def straight(self, kind: str, start: Pos, end: Pos, line: int) -> None:
        if end[2] != start[2] or self.plunge is not None:
            self._plunged(start, end, line)
        if kind is RAPID:
            if not self.drawing:
                self._hold(self.straight, (kind, start, end, line))
                return
        elif not self.drawing:
            self._cutting()
        if start is not self.last_end or self.kind_keys is None:
            self._line(kind, start, end, line)
            return
        # (``_line`` written out for a move from the last one's end: the hot path)
        dx, dy, dz = end[0] - start[0], end[1] - start[1], end[2] - start[2]
        d = math.sqrt(dx * dx + dy * dy + dz * dz)
        self.length += d
        if kind is RAPID:
            self.rapid_length += d
        u0, v0 = self.last_uv
        u1, v1 = self.last_uv = self._point(end)
        self.last_end = end
        if u0 != u1 or v0 != v1:
            key = self.kind_keys[kind]
            self.keys.add(key)
            self.spool.add((LINE, key, 1.0 if kind is RAPID else 0.0, u0, v0, u1, v1,
                            0.0, 0.0, 0.0, 0.0))

    def _line(self, kind: str, start: Sequence[float], end: Sequence[float], line: int) -> None:
        # (the hot path of every drawing: written out)
        dx, dy, dz = end[0] - start[0], end[1] - start[1], end[2] - start[2]
        d = math.sqrt(dx * dx + dy * dy + dz * dz)
        self.length += d
        if kind is RAPID:
            self.rapid_length += d
        # (the start is the last move's end, already taken in, unless nothing was drawn since)
        u0, v0 = self.last_uv if start is self.last_end else self._point(start)
        u1, v1 = self.last_uv = self._point(end)
        self.last_end = end
        if u0 != u1 or v0 != v1:
            fast = self.kind_keys
            if fast is None:
                key = self._key(kind, line)
            else:
                key = fast[kind]
                self.keys.add(key)
            self.spool.add((LINE, key, 1.0 if kind is RAPID else 0.0, u0, v0, u1, v1,
                            0.0, 0.0, 0.0, 0.0))

    def _plunged(self, start: Pos, end: Pos, line: int) -> None:
        """A cycle's hole: a feed down Z and back up on the same line."""
        along = end[2] - start[2]
        held, self.plunge = self.plunge, None
        if abs(end[0] - start[0]) + abs(end[1] - start[1]) > 1e-9 or along == 0.0:
            return
        if along < 0.0:
            self.plunge = (end, line)
        elif held is not None and held[1] == line:
            self.mark(DRILL, held[0])

    def arc(self, arc: ArcMove, line: int) -> None:
        if not self.drawing:
            self._cutting()
        self.plunge = None
        if self._facing(arc, line):
            return
        self.last_end = None
        f = curves.frame(arc.start, arc.end, arc.centre, arc.normal, arc.turns)
        self.length += math.hypot(0.5 * (f.r0 + f.r1) * f.sweep, f.rise)
        view = self.view
        for i, axis in enumerate((view.right, view.up)):
            lo, hi = curves.extremes(f, axis)
            self.box.add(i, lo, hi)
        if view.axes is None:  # (else the box holds the extents the drawing shows)
            for i, axis in enumerate(((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))):
                lo, hi = curves.extremes(f, axis)
                self.extents.add(i, lo, hi)
        self.last_end = None
        key = self._key(ARC, line)
        facing = curves._dot(f.n, view.toward)
        if abs(abs(facing) - 1.0) <= 1e-12 and abs(f.r1 - f.r0) <= curves.BEZIER_TOLERANCE:
            # (seen along its axis: a circle, a helix's rise unseen; an end a little off the
            # start's circle, as rs274 allows, within the tolerance of one)
            self._exact(f, key, (arc.turns > 0) == (facing > 0.0))
            return
        u, v = self._uv(f.point(0.0))
        for q1, q2, p in curves.beziers(f):
            a1, b1 = self._uv(q1)
            a2, b2 = self._uv(q2)
            a3, b3 = self._uv(p)
            self.spool.add((CUBIC, key, 0.0, u, v, a1, b1, a2, b2, a3, b3))
            u, v = a3, b3

    def _facing(self, arc: ArcMove, line: int) -> bool:
        """An arc in a plane the view faces, drawn as SVG arcs straight from its ends and
        centre (the common case, kept quick); False for any other arc."""
        view = self.view
        n, t = arc.normal, view.toward
        facing = n[0] * t[0] + n[1] * t[1] + n[2] * t[2]
        if abs(abs(facing) - 1.0) > 1e-12 or view.axes is None:
            return False
        s, e, c = arc.start, arc.end, arc.centre
        if self.top:  # (u, v are x, y)
            u0, v0 = s[0], s[1]
            u1, v1, cu, cv = e[0], e[1], c[0], c[1]
        else:
            u0, v0 = self._uv(s)
            u1, v1 = self._uv(e)
            cu, cv = self._uv(c)
        r0 = math.hypot(u0 - cu, v0 - cv)
        r1 = math.hypot(u1 - cu, v1 - cv)
        if abs(r1 - r0) > curves.BEZIER_TOLERANCE:
            return False
        ccw = (arc.turns > 0) == (facing > 0.0)
        a0 = math.atan2(v0 - cv, u0 - cu)
        ang = math.atan2(v1 - cv, u1 - cu) - a0
        if not ccw:
            ang = -ang
        while ang <= 1e-12:
            ang += curves.TAU
        while ang > curves.TAU + 1e-12:
            ang -= curves.TAU
        turns = abs(arc.turns) - 1 if arc.turns else 0
        rad = 0.5 * (r0 + r1)
        rise = (e[0] - s[0]) * t[0] + (e[1] - s[1]) * t[1] + (e[2] - s[2]) * t[2]
        self.length += math.hypot(rad * (ang + curves.TAU * turns), rise)
        if s is not self.last_end:
            self._point(s)
        self.last_uv = self._point(e)
        self.last_end = e
        lo, hi = self.box.low, self.box.high
        sweep = ang if not turns else curves.TAU
        direction = 1.0 if ccw else -1.0
        for theta, cos_t, sin_t in QUADRANTS:
            if ((theta - a0) * direction) % curves.TAU < sweep:
                pu, pv = cu + rad * cos_t, cv + rad * sin_t
                if pu < lo[0]:
                    lo[0] = pu
                if pu > hi[0]:
                    hi[0] = pu
                if pv < lo[1]:
                    lo[1] = pv
                if pv > hi[1]:
                    hi[1] = pv
        fast = self.kind_keys
        if fast is None:
            key = self._key(ARC, line)
        else:
            key = fast[ARC]
            self.keys.add(key)
        flag = 1.0 if ccw else 0.0
        if sweep >= curves.TAU - 1e-9:  # whole turns: the circle, as two halves
            mu, mv = 2.0 * cu - u0, 2.0 * cv - v0
            self.spool.add((ARC_2D, key, 0.0, u0, v0, mu, mv, rad, 0.0, flag, 0.0))
            self.spool.add((ARC_2D, key, 0.0, mu, mv, u0, v0, rad, 0.0, flag, 0.0))
        else:
            self.spool.add((ARC_2D, key, 0.0, u0, v0, u1, v1, rad,
                            1.0 if sweep > math.pi else 0.0, flag, 0.0))
        return True

    def _exact(self, f: curves.Frame, key: float, ccw: bool) -> None:
        """An arc in the plane of the drawing: SVG arcs (two halves for a whole circle)."""
        r = 0.5 * (f.r0 + f.r1)
        sweep = min(f.sweep, curves.TAU)
        halves = 2 if sweep >= curves.TAU - 1e-9 else 1
        t0 = 0.0
        for i in range(1, halves + 1):
            t1 = sweep * i / halves
            u0, v0 = self._uv(f.point(t0))
            u1, v1 = self._uv(f.point(t1))
            large = 1.0 if (t1 - t0) > math.pi else 0.0
            self.spool.add((ARC_2D, key, 0.0, u0, v0, u1, v1, r, large, 1.0 if ccw else 0.0))
            t0 = t1

    def nurbs(self, curve: ops.NurbsFeed, start: Pos, line: int) -> None:
        if not self.drawing:
            self._cutting()
        self.plunge = None
        self.last_end = None
        to_machine = self.toolpath.frame.to_machine
        prog = self.toolpath.prog
        z, abc = prog[2], prog[3:]
        key = self._key(NURBS, line)

        def machine(x: float, y: float) -> Pos:
            return to_machine((x, y, z, abc[0], abc[1], abc[2]))

        pts = [machine(x, y) for x, y in curve.points]
        for p in pts:
            self._point(p)  # (a Bézier lies within its control points)
        if curve.order in (3, 4) and curve.size == curve.order and all(
                w == 1.0 for w in curve.weights):
            uv = [c for p in pts for c in self._uv(p)]
            self.spool.add((CUBIC if curve.order == 4 else QUAD, key, 0.0, *uv))
            self.length += _polyline_length(pts)
            return
        prev = start
        for x, y in nurbs_polyline(curve.points, curve.weights, curve.knots, curve.order,
                                   curves.BEZIER_TOLERANCE):
            p = machine(x, y)
            self._line(NURBS, prev, p, line)
            prev = p

    def bezier(self, cubics: Cubics, motion: str, start: Pos, line: int) -> None:
        """An engine-dialect segment: its projection is the cubic of the projected control
        points, drawn as it is."""
        kind = RAPID if motion == "rapid" else PROBE if motion == "probe" else FEED
        if kind is RAPID:
            if not self.drawing:
                self._hold(self.bezier, (cubics, motion, start, line))
                return
        elif not self.drawing:
            self._cutting()
        self.plunge = None
        self.last_end = None
        pts = [(cubics[0][k], cubics[1][k], cubics[2][k]) for k in range(4)]
        for i in range(3):
            lo, hi = curves.cubic_range(cubics[i])
            self.extents.add(i, lo, hi)
        for j, axis in enumerate((self.view.right, self.view.up)):
            lo, hi = curves.cubic_range([p[0] * axis[0] + p[1] * axis[1] + p[2] * axis[2]
                                         for p in pts])
            self.box.add(j, lo, hi)
        samples = [curves.cubic_point(pts, i / 16) for i in range(17)]
        d = sum(math.dist(a, b) for a, b in itertools.pairwise(samples))
        self.length += d
        if kind is RAPID:
            self.rapid_length += d
        uv = [self._uv(p) for p in pts]
        if uv[0] == uv[1] == uv[2] == uv[3]:
            return  # (no motion in the view: rotary axes alone, or along the view)
        self.spool.add((CUBIC, self._key(kind, line), 1.0 if kind is RAPID else 0.0,
                        *uv[0], *uv[1], *uv[2], *uv[3]))

    def tap(self, start: Pos, bottom: Pos, line: int) -> None:
        if not self.drawing:
            self._cutting()
        self._line(TAP, start, bottom, line)
        self.mark(DRILL, bottom)

    def other(self, op: ops.Op, line: int) -> None:
        kind = type(op)
        if kind is ops.SetFeedRate:
            self.feed = op.rate * self.toolpath.frame.scale  # type: ignore[attr-defined]
        elif kind is ops.ChangeTool:
            tool = self.toolpath.tool
            if self.drawing:
                self.mark(TOOL_CHANGE, self.toolpath.pos, float(tool))

    def finish(self) -> None:
        """The end of the run: a program that never cut is drawn with its rapids."""
        if not self.drawing and self.held:
            held, self.held = self.held, []
            self.drawing = True
            for method, args in held:
                method(*args)

    def _hold(self, method: Callable[..., None], args: tuple[Any, ...]) -> None:
        """Keep a rapid of the approach back: a program that never cuts draws it after all
        (``finish``); past :data:`HELD` of them, they are drawn."""
        self.held.append((method, args))
        if len(self.held) > HELD:
            self.finish()

    def _cutting(self) -> None:
        """The first move that cuts: the approach before it is left out."""
        self.drawing = True
        self.held = []

    def stop_at(self) -> Pos:
        """Mark where the machine is: the program stopped there."""
        self.mark(STOPPED, self.toolpath.pos)
        self._point(self.toolpath.pos)
        return self.toolpath.pos


def _polyline_length(pts: Sequence[Pos]) -> float:
    return sum(math.dist(a[:3], b[:3]) for a, b in itertools.pairwise(pts))
