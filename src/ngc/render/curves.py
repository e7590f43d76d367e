"""Arcs and helices as a drawing needs them: their frame, cubic Béziers that follow them within
a tolerance, and their extremes along a direction.

An arc here is ``ARC_FEED``'s, in machine coordinates: from ``start`` to ``end`` about the axis
through ``centre`` along the unit ``normal``, ``turns`` > 0 counterclockwise seen from the
normal's tip, |turns| - 1 extra full turns; the end may rise along the normal (a helix) and lie
at a slightly different radius (the radius then changes linearly with the angle).
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from typing import NamedTuple

Vec = tuple[float, float, float]

TAU = 2.0 * math.pi
BEZIER_TOLERANCE = 0.0005  # mm: how far a drawn Bézier may leave the arc (under 1 µm)


def _sub(p: Sequence[float], q: Sequence[float]) -> Vec:
    return (p[0] - q[0], p[1] - q[1], p[2] - q[2])


def _dot(p: Sequence[float], q: Sequence[float]) -> float:
    return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]


def _cross(p: Vec, q: Vec) -> Vec:
    return (p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0])


class Frame(NamedTuple):
    """An arc as ``centre + r(t) (cos(t) e1 + sin(t) e2) + rise t / sweep n`` for t in
    [0, sweep], with ``r(t)`` going from ``r0`` to ``r1``."""

    centre: Vec
    e1: Vec
    e2: Vec
    n: Vec
    r0: float
    r1: float
    sweep: float
    rise: float

    def point(self, t: float) -> Vec:
        r = self.r0 + (self.r1 - self.r0) * t / self.sweep if self.sweep else self.r0
        c, s = math.cos(t) * r, math.sin(t) * r
        h = self.rise * t / self.sweep if self.sweep else 0.0
        return (self.centre[0] + c * self.e1[0] + s * self.e2[0] + h * self.n[0],
                self.centre[1] + c * self.e1[1] + s * self.e2[1] + h * self.n[1],
                self.centre[2] + c * self.e1[2] + s * self.e2[2] + h * self.n[2])

    @property
    def flat(self) -> bool:
        """A circular arc: no rise, one radius."""
        return abs(self.rise) <= 1e-12 and abs(self.r1 - self.r0) <= 1e-12 * max(1.0, self.r0)


def frame(start: Sequence[float], end: Sequence[float], centre: Sequence[float], normal: Vec,
          turns: int) -> Frame:
    """The arc's frame (as the planner's ``arc_from_canon`` measures it)."""
    p0 = (start[0], start[1], start[2])
    rise = _dot(_sub(end, p0), normal)
    off_n = _dot(_sub(p0, centre), normal)
    c0 = (centre[0] + normal[0] * off_n, centre[1] + normal[1] * off_n,
          centre[2] + normal[2] * off_n)
    r_vec = _sub(p0, c0)
    r0 = math.sqrt(_dot(r_vec, r_vec))
    if r0 > 0.0:
        e1 = (r_vec[0] / r0, r_vec[1] / r0, r_vec[2] / r0)
    else:  # (an arc of no radius: any direction in the plane)
        e1 = _cross(normal, (1.0, 0.0, 0.0) if abs(normal[0]) < 0.9 else (0.0, 1.0, 0.0))
        k = math.sqrt(_dot(e1, e1))
        e1 = (e1[0] / k, e1[1] / k, e1[2] / k)
    e2 = _cross(normal, e1)
    if turns < 0:
        e2 = (-e2[0], -e2[1], -e2[2])
    d = _sub(_sub(end, c0), (normal[0] * rise, normal[1] * rise, normal[2] * rise))
    ang = math.atan2(_dot(d, e2), _dot(d, e1))
    if ang <= 1e-12:
        ang += TAU
    sweep = ang + TAU * (max(abs(turns), 1) - 1)
    r1 = math.sqrt(_dot(d, d))
    return Frame(c0, e1, e2, normal, r0, r1, sweep, rise)


def _pieces(f: Frame, tolerance: float) -> int:
    """How many Béziers follow the arc within ``tolerance``: a cubic over an angle p leaves a
    circle of radius r by r 2/27 sin(p/4)^6 / cos(p/4)^2 at most."""
    r = max(f.r0, f.r1)
    n = max(1, math.ceil(f.sweep / (0.5 * math.pi) - 1e-9))
    while n < 100000:
        q = f.sweep / n / 4.0
        if r * 2.0 / 27.0 * math.sin(q) ** 6 / math.cos(q) ** 2 <= tolerance:
            break
        n *= 2
    return n


def beziers(f: Frame, tolerance: float = BEZIER_TOLERANCE) -> Iterator[tuple[Vec, Vec, Vec]]:
    """Cubic Béziers along the arc, each as its two control points and its end (the first
    starts at the arc's start): the circular part with the control length 4/3 tan(p/4) r of
    a circle, the rise and the change of radius (linear in the angle) exactly."""
    n = _pieces(f, tolerance)
    p = f.sweep / n
    k = 4.0 / 3.0 * math.tan(p / 4.0)
    dr = (f.r1 - f.r0) / f.sweep if f.sweep else 0.0  # radius per radian
    dh = f.rise / f.sweep if f.sweep else 0.0  # rise per radian
    e1, e2, nn = f.e1, f.e2, f.n

    def tangent(t: float) -> tuple[Vec, Vec]:
        """(the circular part of d/dt, the linear part), at t."""
        r = f.r0 + dr * t
        c, s = math.cos(t), math.sin(t)
        circ = (r * (-s * e1[0] + c * e2[0]), r * (-s * e1[1] + c * e2[1]),
                r * (-s * e1[2] + c * e2[2]))
        lin = (dr * (c * e1[0] + s * e2[0]) + dh * nn[0], dr * (c * e1[1] + s * e2[1]) + dh * nn[1],
               dr * (c * e1[2] + s * e2[2]) + dh * nn[2])
        return circ, lin

    a = p / 3.0
    t0 = 0.0
    p0 = f.point(0.0)
    for i in range(1, n + 1):
        t1 = f.sweep * i / n
        p1 = f.point(t1)
        c0, l0 = tangent(t0)
        c1, l1 = tangent(t1)
        q1 = (p0[0] + k * c0[0] + a * l0[0], p0[1] + k * c0[1] + a * l0[1],
              p0[2] + k * c0[2] + a * l0[2])
        q2 = (p1[0] - k * c1[0] - a * l1[0], p1[1] - k * c1[1] - a * l1[1],
              p1[2] - k * c1[2] - a * l1[2])
        yield q1, q2, p1
        t0, p0 = t1, p1


def extremes(f: Frame, v: Vec) -> tuple[float, float]:
    """The least and greatest of ``v . P`` over the arc (the angles where the circular part
    turns along ``v``, and the ends; a helix's rise moves its extremes a little, not its
    ends)."""
    values = [_dot(f.point(0.0), v), _dot(f.point(f.sweep), v)]
    a, b = _dot(f.e1, v), _dot(f.e2, v)
    if a or b:
        base = math.atan2(b, a)
        for k in range(-1, 2 * (int(f.sweep / TAU) + 2)):
            t = base + math.pi * k
            if 0.0 < t < f.sweep:
                values.append(_dot(f.point(t), v))
    return min(values), max(values)


def cubic_range(c: Sequence[float]) -> tuple[float, float]:
    """The least and greatest value of the one-dimensional cubic Bézier ``c`` (its ends and
    where its derivative is zero)."""
    p0, p1, p2, p3 = c
    a = -p0 + 3.0 * p1 - 3.0 * p2 + p3  # B'(t) / 3 = a t^2 + b t + k
    b = 2.0 * (p0 - 2.0 * p1 + p2)
    k = p1 - p0
    ts: list[float] = []
    if abs(a) < 1e-15:
        if b != 0.0:
            ts.append(-k / b)
    else:
        disc = b * b - 4.0 * a * k
        if disc >= 0.0:
            root = math.sqrt(disc)
            ts += [(-b - root) / (2.0 * a), (-b + root) / (2.0 * a)]
    values = [p0, p3]
    for t in ts:
        if 0.0 < t < 1.0:
            u = 1.0 - t
            values.append(u * u * u * p0 + 3.0 * u * u * t * p1 + 3.0 * u * t * t * p2 + t * t * t * p3)
    return min(values), max(values)


def cubic_point(c: Sequence[Sequence[float]], t: float) -> Vec:
    """The point at ``t`` of a cubic Bézier in space (four control points)."""
    u = 1.0 - t
    w = (u * u * u, 3.0 * u * u * t, 3.0 * u * t * t, t * t * t)
    return (sum(w[i] * c[i][0] for i in range(4)), sum(w[i] * c[i][1] for i in range(4)),
            sum(w[i] * c[i][2] for i in range(4)))
