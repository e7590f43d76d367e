"""Curves as the moves a simpler controller runs, in machine coordinates: a G5 cubic as the
biarcs LinuxCNC runs it as, a G5.1 / G5.2 curve and an arc the target cannot cut as straight
lines within a chord tolerance; and the dense points of a curve that the verification measures
the written lines against.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable
from typing import NamedTuple

from ..canon import ops
from ..planner.geometry import cubic_biarcs, nurbs_point
from ..planner.moves import G5_PIECES
from ..render import curves
from ..toolpath.frame import Pos
from ..toolpath.tracker import ArcMove

ToMachine = Callable[[Pos], Pos]
NO_ARC = ops.ArcFeed(0.0, 0.0, 0.0, 0.0, 0, 0.0, 0.0, 0.0, 0.0)  # (a G5's biarcs have no call)


class ArcShape(NamedTuple):
    """An arc as the verification needs it (what :class:`ArcMove` says of its shape)."""

    start: Pos
    end: Pos
    centre: tuple[float, float, float]
    normal: tuple[float, float, float]
    turns: int


# A piece of a curve: its end, and an arc's centre and turns (None, 0: a straight line).
Piece = tuple[Pos, "tuple[float, float, float] | None", int]


def is_cubic(curve: ops.NurbsFeed) -> bool:
    """A G5: one cubic Bézier (four control points of weight 1), which LinuxCNC runs as arcs."""
    return curve.order == 4 and curve.size == 4 and all(w == 1.0 for w in curve.weights)


def cubic_pieces(curve: ops.NurbsFeed, start: Pos, to_machine: ToMachine) -> list[Piece]:
    """A G5's biarcs (as the planner runs them) in machine coordinates, at the start's Z A B C."""
    out: list[Piece] = []
    for end, centre, turns in cubic_biarcs(curve.points, G5_PIECES):
        e = to_machine((end[0], end[1], 0.0, 0.0, 0.0, 0.0))
        point = (e[0], e[1], start[2], start[3], start[4], start[5])
        if centre is None:
            out.append((point, None, 0))
            continue
        c = to_machine((centre[0], centre[1], 0.0, 0.0, 0.0, 0.0))
        out.append((point, (c[0], c[1], start[2]), turns))
    return out


def nurbs_points(curve: ops.NurbsFeed, start: Pos, to_machine: ToMachine,
                 tolerance: float, pieces: int = 16) -> list[Pos]:
    """Points along a G5.1 / G5.2 curve, after its start and up to its end, the lines between
    them within ``tolerance`` (program units) of it: each knot span cut in ``pieces``, each piece
    halved while the curve at any eighth of it is farther from its chord (a weight pulls the
    curve to a sharp turn that fewer looks can miss); machine coordinates at the start's Z A B
    C."""
    points, weights, knots, order = curve.points, curve.weights, curve.knots, curve.order
    out: list[Pos] = []
    if len(points) < 2 or order < 2:
        xy = [points[-1]] if points else []
    else:
        def at(u: float) -> tuple[float, float]:
            return nurbs_point(points, weights, knots, order, u)

        xy = []

        def piece(u0: float, p0: tuple[float, float], u1: float, p1: tuple[float, float],
                  depth: int) -> None:
            dx, dy = p1[0] - p0[0], p1[1] - p0[1]
            dd = dx * dx + dy * dy
            mids = [(u0 + (u1 - u0) * k / 8, at(u0 + (u1 - u0) * k / 8)) for k in range(1, 8)]
            off = 0.0
            for _u, m in mids:  # (from the chord itself: a turn may overshoot its end)
                wx, wy = m[0] - p0[0], m[1] - p0[1]
                t = 0.0 if dd == 0.0 else min(1.0, max(0.0, (wx * dx + wy * dy) / dd))
                off = max(off, math.hypot(wx - t * dx, wy - t * dy))
            if depth < 20 and off > tolerance:
                um, pm = mids[3]
                piece(u0, p0, um, pm, depth + 1)
                piece(um, pm, u1, p1, depth + 1)
            else:
                xy.append(p1)

        spans = sorted(set(knots[order - 1:len(points) + 1]))
        u0, p0 = spans[0], at(spans[0])
        for a, b in itertools.pairwise(spans):
            for k in range(1, pieces + 1):
                u1 = a + (b - a) * k / pieces
                p1 = tuple(points[-1]) if (k == pieces and b == spans[-1]) else at(u1)
                piece(u0, p0, u1, p1, 0)  # type: ignore[arg-type]
                u0, p0 = u1, p1  # type: ignore[assignment]
    for x, y in xy:
        p = to_machine((x, y, 0.0, 0.0, 0.0, 0.0))
        out.append((p[0], p[1], start[2], start[3], start[4], start[5]))
    return out


def arc_points(arc: ArcMove | ArcShape, tolerance: float) -> list[Pos]:
    """Points along an arc (or helix), after its start and up to its end, the lines between
    them within ``tolerance`` of it (the chord's sagitta); A B C move with it in proportion."""
    f = curves.frame(arc.start, arc.end, arc.centre, arc.normal, arc.turns)
    r = max(f.r0, f.r1)
    if 2.0 * r <= tolerance:  # (all of it within the tolerance of either end: one line)
        return [arc.end]
    if r <= tolerance:
        step = math.pi / 2.0
    else:
        step = min(math.pi / 2.0, 2.0 * math.acos(1.0 - tolerance / r))
    n = max(1, math.ceil(f.sweep / step - 1e-9)) if f.sweep > 0.0 else 1
    a, b = arc.start, arc.end
    out: list[Pos] = []
    for k in range(1, n + 1):
        if k == n:
            out.append(b)
            continue
        t = f.sweep * k / n
        p = f.point(t)
        u = k / n
        out.append((p[0], p[1], p[2], a[3] + (b[3] - a[3]) * u, a[4] + (b[4] - a[4]) * u,
                    a[5] + (b[5] - a[5]) * u))
    return out
