"""The verification of a flattened program: the written program run again, as it is written,
and its machine path compared with the original's move by move (:func:`compare`).

:class:`Moves` reads a toolpath into the moves compared; :func:`check` runs the written program
from chunks of text, each with the original's moves that the chunk was written from, and
compares them chunk by chunk, so that neither path is ever held whole.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Iterator
from typing import NamedTuple, Protocol

from ..canon import ops
from ..canon.ops import Sink
from ..errors import NgcError
from ..interp.interpreter import Interpreter
from ..render.curves import Frame
from ..render.curves import frame as _frame
from ..toolpath.frame import Pos
from ..toolpath.held import Held, View
from ..toolpath.tracker import ARC, FEED, RAPID, SYNC, ArcMove, Cubics, Toolpath
from . import curves
from .curves import ArcShape


class Verified(NamedTuple):
    """The comparison of the written program's machine path with the original's: the moves
    compared, the largest distance between corresponding points (mm), and the first difference
    that is not a distance (a move of another kind, a missing move), if any."""

    moves: int
    deviation: float
    difference: str | None


# kind, end, an arc's centre, its turns, line, its axis (the normal, pointing so that the arc
# turns counterclockwise about it: an arc about -X turning one way is the same arc as one about
# +X turning the other), its shape (the arc, or the points of a curve) where a target may have
# written it as lines, its feed (machine units a minute, at the spindle speed for a feed per
# revolution; 0 for a rapid), and the moves written for it (1 for the written program's own)
Move = tuple[str, Pos, "tuple[float, ...] | None", int, int, "tuple[float, ...] | None",
             "tuple[Pos, Pos, tuple[float, float, float], tuple[float, float, float], int] "
             "| list[Pos] | None",
             float, int]
ONE = [1]
CURVE = "curve"
FINE = 0.02  # a curve's points for the verification: within this part of the tolerance
FEED_TOLERANCE = 1e-3  # mm a minute, and as much a thousand: feeds the same but for rounding


class Counted(Protocol):
    """What says how many moves were written for the last one (the writer)."""

    counts: list[int]


class _Once:
    """The written program's own moves: one each."""

    counts = ONE


class Moves:
    """A reader of the toolpath keeping each move's kind, end, and an arc's centre and turns;
    a G5 as its biarcs, a G5.1 / G5.2 curve as its points within ``fine`` mm.

    ``counts``, read after each move, says how many moves were written for it (for each of a
    G5's pieces): which of the written moves :func:`compare` holds against it.  The grouping
    cannot hide a difference, since every written move is measured against the move it is
    given to and the groups follow each other in order; a wrong one only fails."""

    def __init__(self, toolpath: Toolpath | View, fine: float,
                 counts: Counted | None = None) -> None:
        self.toolpath = toolpath
        self.fine = fine
        self.source = counts if counts is not None else _Once()
        self.moves: list[Move] = []
        self.rate = 0.0  # the feed as canon set it, in machine units
        self.per_rev = False
        self.rpm = 0.0
        self.feed = 0.0
        self.sync = 0.0
        self.css = False

    def straight(self, kind: str, start: Pos, end: Pos, line: int) -> None:
        self.moves.append((kind, end, None, 0, line, None, None,
                           0.0 if kind == RAPID else self.sync if kind == SYNC else self.feed,
                           self.source.counts[0]))

    def arc(self, arc: ArcMove, line: int) -> None:
        self._arc(arc, line, self.source.counts[0])

    def _arc(self, arc: ArcMove, line: int, count: int) -> None:
        n = arc.normal
        axis = n if arc.turns > 0 else (-n[0], -n[1], -n[2])
        self.moves.append((ARC, arc.end, arc.centre, abs(arc.turns), line, axis,
                           (arc.start, arc.end, arc.centre, arc.normal, arc.turns),
                           self.feed, count))

    def nurbs(self, curve: ops.NurbsFeed, start: Pos, line: int) -> None:
        to_machine = self.toolpath.frame.to_machine
        counts = self.source.counts
        if curves.is_cubic(curve):
            a = start
            pieces = curves.cubic_pieces(curve, start, to_machine)
            for (end, centre, turns), count in zip(pieces, _padded(counts, len(pieces)),
                                                   strict=True):
                if centre is None:
                    self.moves.append((FEED, end, None, 0, line, None, None, self.feed, count))
                else:
                    self._arc(ArcMove(a, end, centre, (0.0, 0.0, 1.0), turns, curves.NO_ARC, a),
                              line, count)
                a = end
            return
        points = curves.nurbs_points(curve, start, to_machine,
                                     self.fine / self.toolpath.frame.scale, pieces=64)
        self.moves.append((CURVE, points[-1] if points else start, None, 0, line, None,
                           [start, *points], self.feed, counts[0]))

    def tap(self, start: Pos, bottom: Pos, line: int) -> None:
        self.moves.append(("tap", bottom, None, 0, line, None, None, self.sync, 1))

    def bezier(self, cubics: Cubics, motion: str, start: Pos, line: int) -> None:
        self.moves.append(("bezier", start, None, 0, line, None, None, self.feed, 1))

    def other(self, op: ops.Op, line: int) -> None:
        """The feed each move runs at."""
        kind = type(op)
        if kind is ops.SetFeedRate:
            self.rate = op.rate * self.toolpath.frame.scale  # type: ignore[attr-defined]
        elif kind is ops.SetFeedMode:
            self.per_rev = op.mode == 1  # type: ignore[attr-defined]
        elif kind is ops.SetSpindleSpeed:
            # (under G96 a surface speed: in metres a minute, the same whatever the units)
            self.rpm = op.rpm * (0.3048 if self.css and self.toolpath.frame.inch_program  # type: ignore[attr-defined]
                                 else 1.0)
        elif kind is ops.SetSpindleMode:
            self.css = op.css_max > 0.0  # type: ignore[attr-defined]
            return
        elif kind is ops.StartSpeedFeedSync:  # (a distance a revolution, as a feed)
            self.sync = op.per_rev * self.toolpath.frame.scale  # type: ignore[attr-defined]
            return
        else:
            return
        self.feed = self.rate * self.rpm if self.per_rev else self.rate

    def finish(self) -> None:
        """Nothing is held back."""


def _axis_gap(m: Move, n: Move) -> float:
    """How far apart the axes of two arcs about parallel axes are (their centres, less the part
    along the axis: a helix's centre may be given at any height)."""
    c, d, axis = m[2], n[2], m[5]
    if c is None or d is None or axis is None:
        return 0.0
    x, y, z = c[0] - d[0], c[1] - d[1], c[2] - d[2]
    along = x * axis[0] + y * axis[1] + z * axis[2]
    return math.hypot(x - along * axis[0], y - along * axis[1], z - along * axis[2])


def check(chunks: Iterator[tuple[str, list[Move]]],
          new_interpreter: Callable[[Sink], Interpreter], tolerance: float) -> Verified:
    """Run the written program, chunk by chunk of ``chunks`` (its text, and the original's moves
    that text was written from), on the machine inputs of ``new_interpreter``; after each chunk
    its moves are compared with the original's.  ``chunks`` is read to its end whatever
    happens."""
    held = Held()
    toolpath = Toolpath(held)
    again = Moves(held.follow(toolpath), tolerance * FINE)
    held.add(again)
    interp = new_interpreter(toolpath)
    pending: list[Move] = []
    state = [0, 0.0]  # moves compared, the largest deviation
    found: list[str] = []

    def settle() -> None:
        if not found and (pending or again.moves):
            done = compare(pending, again.moves, tolerance, int(state[0]))
            state[1] = max(state[1], done.deviation)
            if done.difference is not None:
                found.append(done.difference)
            state[0] += done.moves
        pending.clear()
        again.moves.clear()

    def lines() -> Iterator[str]:
        for text, moves in chunks:
            held.settle()
            settle()  # (every line before this chunk has run: its moves are all there)
            pending.extend(moves)
            yield from text.splitlines()

    try:
        interp.startup()
        interp.run(lines(), file="<flattened>")
    except NgcError as exc:
        found.append(f"the program written stops at its line {exc.line}: {exc.explained()}")
    held.settle()
    for _text, moves in chunks:  # (what is left after the program's end)
        pending.extend(moves)
    settle()
    return Verified(int(state[0]), math.inf if found and found[0].startswith("the program "
                    "written stops") else state[1], found[0] if found else None)


def compare(a: list[Move], b: list[Move], tolerance: float, start: int = 0) -> Verified:
    """The moves ``b`` against the moves ``a`` they should make, each of ``a`` against the next
    as many of ``b`` as were written for it: one the same (an arc the same arc), an arc of
    several turns as one arc a turn, or a curve or an arc as straight lines (followed along its
    points).  Moves are counted in messages from ``start``."""
    worst = 0.0
    j = 0
    size = len(b)
    for i, m in enumerate(a):
        count = m[8]
        n = b[j] if count == 1 and j < size else None
        if n is None or n[0] != m[0] or n[3] != m[3]:  # (most moves: one for one, the same kind)
            group = b[j:j + count]
            if len(group) < count or count == 0:
                return Verified(i, worst, f"{_where(start, i, m)}: the program written has no "
                                "move for it")
            n = group[0]
            if (m[0] == ARC and count == m[3] and all(
                    r[0] == ARC and r[3] == 1 and r[5] == n[5] and _axis_gap(r, n) < 1e-6
                    for r in group)):
                n = (ARC, group[-1][1], n[2], count, n[4], n[5], None, n[7], 1)
            elif m[0] in (CURVE, ARC) and all(r[0] == FEED for r in group):
                shape = m[6]
                if isinstance(shape, tuple):  # (an arc: its start, end, centre, normal, turns)
                    shape = [shape[0], *curves.arc_points(ArcShape(*shape), tolerance * FINE)]
                assert shape is not None
                deviation, difference = _follow(shape, m[7], group, tolerance)
                worst = max(worst, deviation)
                if difference is not None:
                    return Verified(i, worst, f"{_where(start, i, m)}: {difference}")
                j += count
                continue
            else:
                return Verified(i, worst, f"{_where(start, i, m)}: a {m[0]} became a {n[0]}")
        if not _same_feed(m[7], n[7]):
            return Verified(i, worst, f"{_where(start, i, m)}: the feed {m[7]:.6g} became "
                            f"{n[7]:.6g}")
        p, q = m[1], n[1]
        worst = max(worst, math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]),
                    abs(p[3] - q[3]), abs(p[4] - q[4]), abs(p[5] - q[5]))
        if m[2] is not None and n[2] is not None and m[5] is not None and n[5] is not None:
            if math.dist(m[5], n[5]) > 1e-9:
                return Verified(i, worst, f"{_where(start, i, m)}: the arc turns the other way")
            gap = _axis_gap(m, n)
            shapes = m[6], n[6]
            if (gap > 0.25 * tolerance and isinstance(shapes[0], tuple)
                    and isinstance(shapes[1], tuple)):  # (a nearly straight arc)
                gap = min(gap, _arc_gap(ArcShape(*shapes[0]), ArcShape(*shapes[1])))
            worst = max(worst, gap)
        j += count
    if j < len(b):
        return Verified(len(a), worst, f"the program written has {len(b) - j} moves more, "
                        f"after move {start + len(a)}")
    return Verified(len(a), worst, None)


def _where(start: int, i: int, m: Move) -> str:
    """A move as messages name it."""
    return f"move {start + i + 1} (line {m[4]})"


def curve_frame(arc: ArcShape) -> Frame:
    """The arc's frame (centre, radii, sweep, rise)."""
    return _frame(arc.start, arc.end, arc.centre, arc.normal, arc.turns)


def _arc_gap(m: ArcShape, n: ArcShape) -> float:
    """How far apart two arcs between (nearly) the same ends run: their points at the same
    fractions of their sweeps (a nearly straight arc's centre may move far along the bisector
    for a small change of its ends, its path hardly)."""
    f, g = curve_frame(m), curve_frame(n)
    return max(math.dist(f.point(f.sweep * k / 8), g.point(g.sweep * k / 8)) for k in range(1, 8))


def _same_feed(f: float, g: float) -> bool:
    return abs(f - g) <= FEED_TOLERANCE * max(1.0, abs(f))


def _follow(points: list[Pos], feed: float, lines: list[Move],
            tolerance: float) -> tuple[float, str | None]:
    """Follow the curve through ``points`` (its start first) along the straight feeds
    ``lines``: each line's end is taken at the nearest of the curve's points from the last end
    on, no farther along the curve than the line is long (and half as much again, and four
    tolerances: a line stays within the tolerance of its piece of the curve), the last line's at
    the curve's end; the curve's points between are measured to the line.  The largest
    distance, and what went wrong if anything."""
    last = len(points) - 1
    along = [0.0]
    for p, q in itertools.pairwise(points):
        along.append(along[-1] + math.dist(p[:3], q[:3]))
    at = 0
    worst = 0.0
    previous = points[0]
    for index, n in enumerate(lines):
        if not _same_feed(feed, n[7]):
            return worst, f"the feed {feed:.6g} became {n[7]:.6g}"
        q = n[1]
        if index == len(lines) - 1:
            k = last
            gap = math.dist(points[last][:3], q[:3])
        else:
            reach = along[at] + 1.5 * math.dist(previous[:3], q[:3]) + 4.0 * tolerance
            k, gap = at, math.inf
            for h in range(at, last + 1):
                if along[h] > reach:
                    break
                d = math.dist(points[h][:3], q[:3])
                if d <= gap:
                    k, gap = h, d
            gap = min(_to_segment(q, points[max(k - 1, 0)], points[k]),
                      _to_segment(q, points[k], points[min(k + 1, last)]))
        for p in points[at + 1:k]:  # (the curve's points the line passes; the nearest to
            gap = max(gap, _to_segment(p, previous, q))  # its ends are measured as ends)
        worst = max(worst, gap)
        previous, at = q, k
    return worst, None


def _padded(counts: list[int], n: int) -> list[int]:
    """``counts`` for ``n`` pieces (a missing count: one move)."""
    return (counts + [1] * n)[:n]


def _to_segment(p: Pos, a: Pos, b: Pos) -> float:
    """The distance of ``p`` from the segment ``a`` ``b`` (X Y Z)."""
    d = (b[0] - a[0], b[1] - a[1], b[2] - a[2])
    w = (p[0] - a[0], p[1] - a[1], p[2] - a[2])
    dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2]
    t = 0.0 if dd == 0.0 else max(0.0, min(1.0, (w[0] * d[0] + w[1] * d[1] + w[2] * d[2]) / dd))
    return math.dist(p[:3], (a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]))
