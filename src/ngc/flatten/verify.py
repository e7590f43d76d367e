"""The verification of a flattened program: the written program run again, as it is written,
and its machine path compared with the original's move by move (:func:`compare`).

:class:`Moves` reads a toolpath into the moves compared; :func:`check` runs the written program
from chunks of text, each with the original's moves that the chunk was written from, and
compares them chunk by chunk, so that neither path is ever held whole.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from typing import NamedTuple

from ..canon import ops
from ..canon.ops import Sink
from ..errors import NgcError
from ..interp.interpreter import Interpreter
from ..render.curves import Frame
from ..render.curves import frame as _frame
from ..toolpath.frame import Pos
from ..toolpath.tracker import ARC, FEED, RAPID, SYNC, ArcMove, Cubics, Tee, Toolpath
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
# written it as lines, and its feed (machine units a minute, at the spindle speed for a feed per
# revolution; 0 for a rapid)
Move = tuple[str, Pos, "tuple[float, ...] | None", int, int, "tuple[float, ...] | None",
             "ArcShape | list[Pos] | None", float]
CURVE = "curve"
FINE = 0.02  # a curve's points for the verification: within this part of the tolerance
FEED_TOLERANCE = 1e-3  # mm a minute, and as much a thousand: feeds the same but for rounding


class Moves:
    """A reader of the toolpath keeping each move's kind, end, and an arc's centre and turns;
    a G5 as its biarcs, a G5.1 / G5.2 curve as its points within ``fine`` mm."""

    def __init__(self, toolpath: Toolpath, fine: float) -> None:
        self.toolpath = toolpath
        self.fine = fine
        self.moves: list[Move] = []
        self.rate = 0.0  # the feed as canon set it, in machine units
        self.per_rev = False
        self.rpm = 0.0
        self.feed = 0.0
        self.sync = 0.0

    def straight(self, kind: str, start: Pos, end: Pos, line: int) -> None:
        self.moves.append((kind, end, None, 0, line, None, None,
                           0.0 if kind == RAPID else self.sync if kind == SYNC else self.feed))

    def arc(self, arc: ArcMove, line: int) -> None:
        sign = 1.0 if arc.turns > 0 else -1.0
        axis = tuple(sign * v for v in arc.normal)
        self.moves.append((ARC, arc.end, arc.centre, abs(arc.turns), line, axis,
                           ArcShape(arc.start, arc.end, arc.centre, arc.normal, arc.turns),
                           self.feed))

    def nurbs(self, curve: ops.NurbsFeed, start: Pos, line: int) -> None:
        to_machine = self.toolpath.frame.to_machine
        if curves.is_cubic(curve):
            a = start
            for end, centre, turns in curves.cubic_pieces(curve, start, to_machine):
                if centre is None:
                    self.straight(FEED, a, end, line)
                else:
                    self.arc(ArcMove(a, end, centre, (0.0, 0.0, 1.0), turns, curves.NO_ARC, a),
                             line)
                a = end
            return
        points = curves.nurbs_points(curve, start, to_machine,
                                     self.fine / self.toolpath.frame.scale, pieces=64)
        self.moves.append((CURVE, points[-1] if points else start, None, 0, line, None,
                           [start, *points], self.feed))

    def tap(self, start: Pos, bottom: Pos, line: int) -> None:
        self.moves.append(("tap", bottom, None, 0, line, None, None, self.sync))

    def bezier(self, cubics: Cubics, motion: str, start: Pos, line: int) -> None:
        self.moves.append(("bezier", start, None, 0, line, None, None, self.feed))

    def other(self, op: ops.Op, line: int) -> None:
        """The feed each move runs at."""
        kind = type(op)
        if kind is ops.SetFeedRate:
            self.rate = op.rate * self.toolpath.frame.scale  # type: ignore[attr-defined]
        elif kind is ops.SetFeedMode:
            self.per_rev = op.mode == 1  # type: ignore[attr-defined]
        elif kind is ops.SetSpindleSpeed:
            self.rpm = op.rpm  # type: ignore[attr-defined]
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
    gap = [c[i] - d[i] for i in range(3)]
    along = sum(gap[i] * axis[i] for i in range(3))
    return math.sqrt(sum((gap[i] - along * axis[i]) ** 2 for i in range(3)))


def check(chunks: Iterator[tuple[str, list[Move]]],
          new_interpreter: Callable[[Sink], Interpreter], tolerance: float) -> Verified:
    """Run the written program, chunk by chunk of ``chunks`` (its text, and the original's moves
    that text was written from), on the machine inputs of ``new_interpreter``; after each chunk
    its moves are compared with the original's.  ``chunks`` is read to its end whatever
    happens."""
    tee = Tee()
    toolpath = Toolpath(tee)
    again = Moves(toolpath, tolerance * FINE)
    tee.readers.append(again)
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
            settle()  # (every line before this chunk has run: its moves are all there)
            pending.extend(moves)
            yield from text.splitlines()

    try:
        interp.startup()
        interp.run(lines(), file="<flattened>")
    except NgcError as exc:
        found.append(f"the program written stops at its line {exc.line}: {exc.explained()}")
    for _text, moves in chunks:  # (what is left after the program's end)
        pending.extend(moves)
    settle()
    return Verified(int(state[0]), math.inf if found and found[0].startswith("the program "
                    "written stops") else state[1], found[0] if found else None)


def compare(a: list[Move], b: list[Move], tolerance: float, start: int = 0) -> Verified:
    """The moves ``b`` against the moves ``a`` they should make: one to one, but for an arc of
    several turns written one turn an arc, and a curve or an arc written as straight lines
    (followed along its points).  Moves are counted in messages from ``start``."""
    worst = 0.0
    i = j = 0
    while i < len(a) and j < len(b):
        m, n = a[i], b[j]
        if m[0] == CURVE or (m[0] == ARC and n[0] == FEED):
            shape = m[6]
            if isinstance(shape, ArcShape):
                shape = [shape.start, *curves.arc_points(shape, tolerance * FINE)]
            assert shape is not None
            j, deviation, difference = _follow(shape, m[7], b, j, tolerance)
            worst = max(worst, deviation)
            if difference is not None:
                return Verified(i, worst, f"move {start + i + 1} (line {m[4]}): {difference}")
            i += 1
            continue
        k = m[3]
        if m[0] == ARC and k > 1 and n[0] == ARC and n[3] == 1:
            run = b[j:j + k]
            if len(run) == k and all(r[0] == ARC and r[3] == 1 and r[5] == n[5]
                                     and _axis_gap(r, n) < 1e-6 for r in run):
                n = (ARC, run[-1][1], n[2], k, n[4], n[5], None, n[7])
                j += k - 1
        if m[0] != n[0] or m[3] != n[3]:
            return Verified(i, worst, f"move {start + i + 1} (line {m[4]}): a {m[0]} became a "
                            f"{n[0]}")
        if not _same_feed(m[7], n[7]):
            return Verified(i, worst, f"move {start + i + 1} (line {m[4]}): the feed "
                            f"{m[7]:.6g} became {n[7]:.6g}")
        worst = max(worst, math.dist(m[1][:3], n[1][:3]),
                    max(abs(x - y) for x, y in zip(m[1][3:], n[1][3:], strict=True)))
        if m[2] is not None and n[2] is not None and m[5] is not None and n[5] is not None:
            if math.dist(m[5], n[5]) > 1e-9:
                return Verified(i, worst, f"move {start + i + 1} (line {m[4]}): the arc turns the "
                                "other way")
            gap = _axis_gap(m, n)
            shapes = m[6], n[6]
            if (gap > 0.25 * tolerance and isinstance(shapes[0], ArcShape)
                    and isinstance(shapes[1], ArcShape)):
                gap = min(gap, _arc_gap(shapes[0], shapes[1]))  # (a nearly straight arc)
            worst = max(worst, gap)
        i += 1
        j += 1
    if i < len(a) or j < len(b):
        return Verified(i, worst, f"the moves differ in number after move {start + i}: "
                        f"{len(a) - i} more of the original's, {len(b) - j} more of the written")
    return Verified(len(a), worst, None)


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


def _follow(points: list[Pos], feed: float, b: list[Move], j: int,
            tolerance: float) -> tuple[int, float, str | None]:
    """Follow the curve through ``points`` (its start first) along the straight feeds of ``b``
    from ``j``: each line's end is taken at the first point from the last end on that comes
    within the tolerance (then the nearest in that run), and the curve's points between are
    measured to the line.  The index after the last line, the largest distance, and what went
    wrong if anything."""
    last = len(points) - 1
    at = 0
    worst = 0.0
    previous = points[0]
    while at < last:
        if j >= len(b) or b[j][0] != FEED:
            kind = "nothing" if j >= len(b) else f"a {b[j][0]}"
            return j, worst, f"a curve became {kind} before its end"
        if not _same_feed(feed, b[j][7]):
            return j, worst, f"the feed {feed:.6g} became {b[j][7]:.6g}"
        q = b[j][1]
        k = _nearest(points, at, q, tolerance)
        if k < last and all(math.dist(p[:3], q[:3]) <= tolerance for p in points[k:]):
            k = last  # (the rest of the curve is within the tolerance of this end)
        gap = min(_to_segment(q, points[max(k - 1, 0)], points[k]),
                  _to_segment(q, points[k], points[min(k + 1, last)]))
        for p in points[at + 1:k]:  # (the curve's points the line passes; the nearest to
            gap = max(gap, _to_segment(p, previous, q))  # its ends are measured as ends)
        worst = max(worst, gap)
        j += 1
        if k == at and gap > tolerance:
            return j, worst, "a line leaves the curve"
        previous, at = q, k
    return j, worst, None


def _nearest(points: list[Pos], at: int, q: Pos, tolerance: float) -> int:
    """The point from ``at`` on that ``q`` stands at: the first run of points within the
    tolerance of it, its nearest; else the nearest of all."""
    best, best_d = at, math.inf
    inside = False
    for k in range(at, len(points)):
        d = math.dist(points[k][:3], q[:3])
        if d <= tolerance:
            inside = True
            if d <= best_d:  # (the later of points alike: a curve that stands still)
                best, best_d = k, d
        elif inside:
            break
        elif d < best_d and not inside:
            best, best_d = k, d
    return best


def _to_segment(p: Pos, a: Pos, b: Pos) -> float:
    """The distance of ``p`` from the segment ``a`` ``b`` (X Y Z)."""
    d = (b[0] - a[0], b[1] - a[1], b[2] - a[2])
    w = (p[0] - a[0], p[1] - a[1], p[2] - a[2])
    dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2]
    t = 0.0 if dd == 0.0 else max(0.0, min(1.0, (w[0] * d[0] + w[1] * d[1] + w[2] * d[2]) / dd))
    return math.dist(p[:3], (a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]))
