"""The shapes the planner moves along: straight lines and circular arcs (helices), in machine
coordinates, each measured by its path length.

A position is a 6-tuple ``(x, y, z, a, b, c)``.  A path's length is its length in X Y Z, or, for a
move of A B C alone, its angular length.  :func:`blend_arc` finds the arc that rounds the corner
between two lines.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from itertools import pairwise
from typing import NamedTuple

Vec = tuple[float, float, float]
Pos = tuple[float, float, float, float, float, float]

EPS = 1e-12

# A NamedTuple made without its Python __new__ (three times faster): _new(Line, (p, q, n)).
_new = tuple.__new__


def sub(p: Vec, q: Vec) -> Vec:
    return (p[0] - q[0], p[1] - q[1], p[2] - q[2])


def dot(p: Vec, q: Vec) -> float:
    return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]


def cross(p: Vec, q: Vec) -> Vec:
    return (p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0])


def norm(p: Vec) -> float:
    return math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2])


def unit(p: Vec) -> Vec:
    n = norm(p)
    if n < EPS:
        return (0.0, 0.0, 0.0)
    return (p[0] / n, p[1] / n, p[2] / n)


def angle_between(u: Vec, v: Vec) -> float:
    """The angle between two unit vectors, accurate for small and large angles."""
    return 2.0 * math.atan2(norm(sub(u, v)), norm((u[0] + v[0], u[1] + v[1], u[2] + v[2])))


class Line(NamedTuple):
    """A straight move from ``start`` to ``end``; ``length`` as defined above."""

    start: Pos
    end: Pos
    length: float

    def point(self, s: float) -> Pos:
        f = s / self.length if self.length > 0.0 else 1.0
        p, q = self.start, self.end
        return (p[0] + (q[0] - p[0]) * f, p[1] + (q[1] - p[1]) * f, p[2] + (q[2] - p[2]) * f,
                p[3] + (q[3] - p[3]) * f, p[4] + (q[4] - p[4]) * f, p[5] + (q[5] - p[5]) * f)

    def start_direction(self) -> Vec:
        p, q = self.start, self.end
        return unit((q[0] - p[0], q[1] - p[1], q[2] - p[2]))

    def end_direction(self) -> Vec:
        return self.start_direction()


class Arc(NamedTuple):
    """A circular arc, or a helix along the plane's normal: ``center`` (X Y Z of the circle's
    centre at the start), the orthonormal in-plane directions ``e1`` (centre to start) and ``e2``
    (the way the arc turns at the start), ``radius``, the angle ``sweep`` (> 0, radians), the
    ``rise`` along ``normal`` over the whole arc, the A B C at the start and at the end."""

    center: Vec
    e1: Vec
    e2: Vec
    normal: Vec
    radius: float
    sweep: float
    rise: float
    abc0: Vec
    abc1: Vec
    length: float

    def point(self, s: float) -> Pos:
        f = s / self.length if self.length > 0.0 else 1.0
        ang = self.sweep * f
        c, s_ = math.cos(ang) * self.radius, math.sin(ang) * self.radius
        h = self.rise * f
        o, e1, e2, n = self.center, self.e1, self.e2, self.normal
        a0, a1 = self.abc0, self.abc1
        return (o[0] + c * e1[0] + s_ * e2[0] + h * n[0],
                o[1] + c * e1[1] + s_ * e2[1] + h * n[1],
                o[2] + c * e1[2] + s_ * e2[2] + h * n[2],
                a0[0] + (a1[0] - a0[0]) * f, a0[1] + (a1[1] - a0[1]) * f,
                a0[2] + (a1[2] - a0[2]) * f)

    def direction(self, ang: float) -> Vec:
        arc = self.radius * self.sweep
        c, s = math.cos(ang), math.sin(ang)
        e1, e2, n = self.e1, self.e2, self.normal
        return unit((arc * (-s * e1[0] + c * e2[0]) + self.rise * n[0],
                     arc * (-s * e1[1] + c * e2[1]) + self.rise * n[1],
                     arc * (-s * e1[2] + c * e2[2]) + self.rise * n[2]))

    def start_direction(self) -> Vec:
        return self.direction(0.0)

    def end_direction(self) -> Vec:
        return self.direction(self.sweep)


def arc_from_canon(start: Pos, end: Pos, center: Vec, normal: Vec, turns: int) -> Arc:
    """The arc LinuxCNC's ``ARC_FEED`` describes: from ``start`` to ``end`` about the axis through
    ``center`` along ``normal`` (a unit axis vector: the plane's normal), ``turns`` > 0
    counterclockwise seen from the normal's tip, < 0 clockwise, |turns| - 1 extra full turns."""
    p0 = start[:3]
    rise_vec = sub(end[:3], p0)
    rise = dot(rise_vec, normal)
    # project the centre into the start's plane
    off = sub(p0, center)
    off_n = dot(off, normal)
    c0 = (center[0] + normal[0] * off_n, center[1] + normal[1] * off_n,
          center[2] + normal[2] * off_n)
    r_vec = sub(p0, c0)
    radius = norm(r_vec)
    e1 = unit(r_vec)
    e2 = cross(normal, e1)
    if turns < 0:
        e2 = (-e2[0], -e2[1], -e2[2])
    end_in_plane = sub(sub(end[:3], c0), (normal[0] * rise, normal[1] * rise,
                                          normal[2] * rise))
    ang = math.atan2(dot(end_in_plane, e2), dot(end_in_plane, e1))
    if ang <= 1e-12:
        ang += 2.0 * math.pi
    sweep = ang + 2.0 * math.pi * (abs(turns) - 1)
    arc_len = radius * sweep
    length = math.hypot(arc_len, rise)
    if length < EPS:
        length = norm(sub(end[3:], start[3:]))
    return Arc(c0, e1, e2, normal, radius, sweep, rise, start[3:], end[3:], length)


class Blend(NamedTuple):
    """The arc that rounds a corner: its radius, the length cut from each line, its length and
    the greatest speed it allows."""

    radius: float
    trim: float
    length: float
    speed: float


def blend_arc(theta: float, goal: float, room: float, tolerance: float,
              tangential: float, normal: float) -> Blend | None:
    """The corner arc for a turn of ``theta`` radians between two lines, for a wanted speed
    ``goal``; ``room`` is the most each line may give, ``tolerance`` how far the arc may pass from
    the corner (0: no limit); ``tangential`` and ``normal`` are the arc's acceleration limits.

    The radius is the smallest that keeps the goal speed within the normal limit and makes the
    arc at least goal² / tangential long, unless room or tolerance allow less."""
    if theta <= 0.0 or theta >= math.pi - 1e-6:
        return None
    half = 0.5 * theta
    tan_half = math.tan(half)
    g2 = goal * goal
    r = g2 / normal
    if tangential * theta * r < g2:  # (min and max written out: a corner of every G64 move)
        r = g2 / (tangential * theta)
    if r * tan_half > room:
        r = room / tan_half
    if tolerance > 0.0:
        # 1 - cos(θ/2) written as 2·sin²(θ/4): a turn of a few 1e-9 rad leaves cos(θ/2) at 1.0
        sin_quarter = math.sin(0.5 * half)
        r_tol = tolerance * math.cos(half) / (2.0 * sin_quarter * sin_quarter)
        if r_tol < r:
            r = r_tol
    if r <= EPS:
        return None
    speed = math.sqrt(normal * r)
    if goal < speed:
        speed = goal
    return _new(Blend, (r, r * tan_half, r * theta, speed))


def corner_reach(theta: float, tolerance: float, radius: float) -> float:
    """How far from a join a blend drawn as a :class:`Corner` may start and end and still stay
    within ``tolerance`` of the path, where the moves turn by ``theta`` and the tighter of them
    curves with ``radius`` (``math.inf``: both straight).

    Such a blend is within d·sin(θ/2)/2 of the tangent lines at the join, and each move within
    d²/(2·radius) of its tangent line over a length d: d²/radius + d·sin(θ/2)/2 is kept within
    the tolerance.

    >>> round(corner_reach(0.5, 0.01, math.inf), 4), round(corner_reach(0.0, 0.01, 2.5), 4)
    (0.0808, 0.1581)
    """
    s = 0.5 * math.sin(0.5 * theta)
    if radius == math.inf:
        return tolerance / s if s > 0.0 else math.inf
    k = 1.0 / radius
    return (math.sqrt(s * s + 4.0 * k * tolerance) - s) / (2.0 * k)


def radius_of(shape: object) -> float:
    """The radius a shape curves with (``math.inf`` for a line)."""
    if isinstance(shape, Piece):
        shape = shape.base
    return shape.radius if isinstance(shape, Arc) else math.inf


class Piece(NamedTuple):
    """The part of a ``base`` shape from path length ``s0`` on, ``length`` long (an arc with its
    ends given to corner blends)."""

    base: Line | Arc
    s0: float
    length: float

    def point(self, s: float) -> Pos:
        return self.base.point(self.s0 + s)

    def start_direction(self) -> Vec:
        return _direction_at(self.base, self.s0)

    def end_direction(self) -> Vec:
        return _direction_at(self.base, self.s0 + self.length)


def _direction_at(shape: Line | Arc, s: float) -> Vec:
    if isinstance(shape, Line):
        return shape.start_direction()
    return shape.direction(shape.sweep * s / shape.length if shape.length > 0.0 else 0.0)


class Corner(NamedTuple):
    """A blend that is drawn as the quadratic Bézier from ``p0`` through the control point
    ``corner`` to ``p1`` (where an arc meets a line or another arc), timed as ``length`` long."""

    p0: Pos
    corner: Pos
    p1: Pos
    length: float
    u0: Vec
    u1: Vec

    def point(self, s: float) -> Pos:
        t = s / self.length if self.length > 0.0 else 1.0
        a, b, c = (1.0 - t) * (1.0 - t), 2.0 * t * (1.0 - t), t * t
        p, q, r = self.p0, self.corner, self.p1
        return tuple(a * p[i] + b * q[i] + c * r[i] for i in range(6))  # type: ignore[return-value]

    def start_direction(self) -> Vec:
        return self.u0

    def end_direction(self) -> Vec:
        return self.u1


class BlendArc(NamedTuple):
    """The arc that rounds the corner ``corner`` between a line arriving along ``u1`` and one
    leaving along ``u2``: it leaves the first line ``trim`` before the corner and turns by
    ``theta`` with ``radius``.  Its points are worked out only when asked for."""

    corner: Pos
    u1: Vec
    u2: Vec
    radius: float
    trim: float
    theta: float
    length: float

    def arc(self) -> Arc:
        u1, u2, c, d, r = self.u1, self.u2, self.corner, self.trim, self.radius
        cos_t = dot(u1, u2)
        w = unit((u2[0] - cos_t * u1[0], u2[1] - cos_t * u1[1], u2[2] - cos_t * u1[2]))
        center = (c[0] - u1[0] * d + w[0] * r, c[1] - u1[1] * d + w[1] * r,
                  c[2] - u1[2] * d + w[2] * r)
        e1 = (-w[0], -w[1], -w[2])
        abc = (c[3], c[4], c[5])
        return Arc(center, e1, u1, cross(e1, u1), r, self.theta, 0.0, abc, abc, self.length)

    def point(self, s: float) -> Pos:
        return self.arc().point(s)

    def start_direction(self) -> Vec:
        return self.u1

    def end_direction(self) -> Vec:
        return self.u2


def nurbs_point(points: Sequence[tuple[float, float]], weights: Sequence[float],
                knots: Sequence[float], order: int, u: float) -> tuple[float, float]:
    """The point of the NURBS curve at parameter ``u`` (de Boor's algorithm on the weighted
    control points)."""
    n = len(points)
    degree = order - 1
    k = degree
    while k < n - 1 and knots[k + 1] <= u:
        k += 1
    d = [(points[j][0] * weights[j], points[j][1] * weights[j], weights[j])
         for j in range(k - degree, k + 1)]
    for r in range(1, degree + 1):
        for j in range(degree, r - 1, -1):
            i = j + k - degree
            span = knots[i + degree - r + 1] - knots[i]
            t = (u - knots[i]) / span if span > 0.0 else 0.0
            a, b = d[j - 1], d[j]
            d[j] = (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2]))
    x, y, w = d[degree]
    return (x / w, y / w) if w != 0.0 else (x, y)


def cubic_biarcs(points: Sequence[tuple[float, float]], pieces: int
                 ) -> list[tuple[tuple[float, float], tuple[float, float] | None, int]]:
    """The arcs that run the cubic Bézier curve of ``points`` (a G5) as LinuxCNC runs it: the
    curve cut at ``pieces`` equal steps of its parameter, each piece a biarc from its start to its
    end with the curve's tangents there, the two arcs meeting where their tangent lengths are
    equal (the joint halfway between the start pushed forward and the end pushed back along the
    tangents by that length).  Each arc as (end, centre, +1 counterclockwise / -1 clockwise); a
    piece with no bend, or whose tangents leave no such joint, as (end, None, 0), a line.

    Measured under G61.1, where each arc ends with a stop: a G5 from (5, 0) to (25, 3) stopped at
    the curve's points of parameter k/16 and at the joints of this rule, within 1e-5 mm."""
    (ax, ay), (bx, by), (cx, cy), (dx, dy) = points[0], points[1], points[2], points[3]

    def point(u: float) -> tuple[float, float]:
        m = 1.0 - u
        k0, k1, k2, k3 = m * m * m, 3.0 * m * m * u, 3.0 * m * u * u, u * u * u
        return (k0 * ax + k1 * bx + k2 * cx + k3 * dx, k0 * ay + k1 * by + k2 * cy + k3 * dy)

    def tangent(u: float, p: tuple[float, float], q: tuple[float, float]) -> tuple[float, float]:
        m = 1.0 - u
        tx = 3.0 * (m * m * (bx - ax) + 2.0 * m * u * (cx - bx) + u * u * (dx - cx))
        ty = 3.0 * (m * m * (by - ay) + 2.0 * m * u * (cy - by) + u * u * (dy - cy))
        n = math.hypot(tx, ty)
        if n < 1e-12:  # no tangent there (a control point on the end): the chord's way
            tx, ty = q[0] - p[0], q[1] - p[1]
            n = math.hypot(tx, ty)
            if n < 1e-12:
                return (0.0, 0.0)
        return (tx / n, ty / n)

    out: list[tuple[tuple[float, float], tuple[float, float] | None, int]] = []
    p0 = point(0.0)
    for k in range(pieces):
        u0, u1 = k / pieces, (k + 1) / pieces
        p1 = point(u1)
        t0, t1 = tangent(u0, p0, p1), tangent(u1, p0, p1)
        vx, vy = p1[0] - p0[0], p1[1] - p0[1]
        sx, sy = t0[0] + t1[0], t0[1] + t1[1]
        vt, vv, a = vx * sx + vy * sy, vx * vx + vy * vy, sx * sx + sy * sy - 4.0
        if abs(a) < 1e-12:
            d = vv / (4.0 * vt) if vt > 0.0 else -1.0
        else:
            disc = vt * vt - a * vv
            d = (vt - math.sqrt(disc)) / a if disc >= 0.0 else -1.0
        if not d > 0.0 or vv < 1e-24:
            out.append((p1, None, 0))
            p0 = p1
            continue
        q0 = (p0[0] + d * t0[0], p0[1] + d * t0[1])
        q1 = (p1[0] - d * t1[0], p1[1] - d * t1[1])
        joint = (0.5 * (q0[0] + q1[0]), 0.5 * (q0[1] + q1[1]))
        tj = (q1[0] - q0[0], q1[1] - q0[1])
        n = math.hypot(tj[0], tj[1])
        tj = (tj[0] / n, tj[1] / n) if n > 1e-12 else t0
        for start, t, end in ((p0, t0, joint), (joint, tj, p1)):
            wx, wy = end[0] - start[0], end[1] - start[1]
            side = wx * -t[1] + wy * t[0]  # along the left normal of the tangent
            ww = wx * wx + wy * wy
            if abs(side) <= 1e-9 * ww or ww < 1e-24:
                out.append((end, None, 0))
                continue
            r = ww / (2.0 * side)  # > 0: the centre on the left, counterclockwise
            out.append((end, (start[0] - t[1] * r, start[1] + t[0] * r), 1 if r > 0.0 else -1))
        p0 = p1
    return out


def nurbs_polyline(points: Sequence[tuple[float, float]], weights: Sequence[float],
                   knots: Sequence[float], order: int,
                   tolerance: float) -> list[tuple[float, float]]:
    """Points along a NURBS curve, after its start and up to its end, such that the straight
    lines between them stay within about ``tolerance`` of the curve (each span is halved until
    the curve's point halfway is that close to the chord).

    >>> pts = nurbs_polyline([(0, 0), (1, 1), (2, 0)], [1, 1, 1], [0, 0, 0, 1, 1, 1], 3, 0.01)
    >>> pts[-1], len(pts)
    ((2.0, 0.0), 8)
    """
    if len(points) < 2 or order < 2:
        return [tuple(points[-1])] if points else []  # type: ignore[list-item]
    lo, hi = knots[order - 1], knots[len(points)]
    out: list[tuple[float, float]] = []

    def chord(u0: float, p0: tuple[float, float], u1: float, p1: tuple[float, float],
              depth: int) -> None:
        um = 0.5 * (u0 + u1)
        pm = nurbs_point(points, weights, knots, order, um)
        dx, dy = p1[0] - p0[0], p1[1] - p0[1]
        length = math.hypot(dx, dy)
        if length > 0.0:
            off = abs((pm[0] - p0[0]) * dy - (pm[1] - p0[1]) * dx) / length
        else:
            off = math.hypot(pm[0] - p0[0], pm[1] - p0[1])
        if depth < 16 and off > tolerance:
            chord(u0, p0, um, pm, depth + 1)
            chord(um, pm, u1, p1, depth + 1)
        else:
            out.append(p1)

    spans = sorted(set(knots[order - 1:len(points) + 1]))
    start = nurbs_point(points, weights, knots, order, lo)
    for u0, u1 in pairwise(spans):
        if u1 > u0:
            # a span is cut in four at least: a curve can come back to its chord halfway
            steps = [u0 + (u1 - u0) * i / 4.0 for i in range(5)]
            for a, b in pairwise(steps):
                end = nurbs_point(points, weights, knots, order, b) if b < hi else \
                    (float(points[-1][0]), float(points[-1][1]))
                chord(a, start, b, end, 0)
                start = end
    return out

