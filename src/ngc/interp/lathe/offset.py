"""Geometry for moving a lathe profile by a distance (``finishing.moved`` joins the moved
segments): a segment moved along its normal, tangents, and where carriers cross."""

from __future__ import annotations

import itertools
import math

from ...errors import NgcSemanticError
from .profile import CCW, LINE, PARALLEL, Seg

EPS = 1e-9


def _shift(seg: Seg, side: float, d: float) -> Seg:
    """The line ``seg`` moved ``d`` to its left (``side`` +1) or right (-1), in the (z, x)
    plane (arcs: ``finishing._move``)."""
    dx, dz = seg.x1 - seg.x0, seg.z1 - seg.z0
    n = math.hypot(dx, dz)
    if n == 0.0:
        return seg
    # left of the direction (dz, dx) in (z, x) coordinates is (-dx, dz)
    oz, ox = -dx / n * side * d, dz / n * side * d
    return seg._replace(x0=seg.x0 + ox, z0=seg.z0 + oz, x1=seg.x1 + ox, z1=seg.z1 + oz)


def tangent(seg: Seg, at_end: bool) -> tuple[float, float]:
    """The unit direction (dz, dx) of ``seg`` at its start or end."""
    if seg.kind == LINE:
        dz, dx = seg.z1 - seg.z0, seg.x1 - seg.x0
    else:
        pz, px = (seg.z1, seg.x1) if at_end else (seg.z0, seg.x0)
        rz, rx = pz - seg.cz, px - seg.cx
        # CCW in (z, x): direction is the radius turned left
        dz, dx = (-rx, rz) if seg.kind == CCW else (rx, -rz)
    n = math.hypot(dz, dx)
    return (dz / n, dx / n) if n else (0.0, 0.0)


def intersections(a: Seg, b: Seg) -> list[tuple[float, float]]:
    """Where the carriers of two segments cross (lines as infinite lines, arcs as circles),
    as (x, z) points."""
    if a.kind == LINE and b.kind == LINE:
        d1z, d1x = a.z1 - a.z0, a.x1 - a.x0
        d2z, d2x = b.z1 - b.z0, b.x1 - b.x0
        den = d1z * d2x - d1x * d2z
        if abs(den) < EPS:
            return []
        t = ((b.z0 - a.z0) * d2x - (b.x0 - a.x0) * d2z) / den
        return [(a.x0 + t * d1x, a.z0 + t * d1z)]
    if a.kind == LINE or b.kind == LINE:
        line, arc = (a, b) if a.kind == LINE else (b, a)
        return line_circle(line.x0, line.z0, line.x1, line.z1, arc.cx, arc.cz,
                           math.hypot(arc.x0 - arc.cx, arc.z0 - arc.cz))
    return circle_circle(a, b)


def line_circle(x0: float, z0: float, x1: float, z1: float, cx: float, cz: float,
                r: float) -> list[tuple[float, float]]:
    dx, dz = x1 - x0, z1 - z0
    fx, fz = x0 - cx, z0 - cz
    a = dx * dx + dz * dz
    if a == 0.0:
        return []
    b = 2 * (fx * dx + fz * dz)
    c = fx * fx + fz * fz - r * r
    disc = b * b - 4 * a * c
    if disc < 0:
        if disc > -EPS * max(1.0, b * b):
            disc = 0.0
        else:
            return []
    sq = math.sqrt(disc)
    return [(x0 + t * dx, z0 + t * dz) for t in ((-b - sq) / (2 * a), (-b + sq) / (2 * a))]


def circle_circle(a: Seg, b: Seg) -> list[tuple[float, float]]:
    r1 = math.hypot(a.x0 - a.cx, a.z0 - a.cz)
    r2 = math.hypot(b.x0 - b.cx, b.z0 - b.cz)
    dx, dz = b.cx - a.cx, b.cz - a.cz
    d = math.hypot(dx, dz)
    if d == 0.0 or d > r1 + r2 + EPS or d < abs(r1 - r2) - EPS:
        return []
    along = (d * d + r1 * r1 - r2 * r2) / (2 * d)
    h = math.sqrt(max(r1 * r1 - along * along, 0.0))
    mx, mz = a.cx + along * dx / d, a.cz + along * dz / d
    return [(mx - h * dz / d, mz + h * dx / d), (mx + h * dz / d, mz - h * dx / d)]


_SHORT = 1e-3 - 1e-12  # (see check_joinable)


def check_joinable(profile: list[Seg]) -> None:
    """G71/G72 with a D: rs274 cannot join two lines in a row that run along X, or along Z
    (slanted lines in line it joins).  A line shorter than 0.001 is left out first (as rs274
    measures it: 0.0009999999 is, the 0.00099999999999945 from X3.86 to X3.861 is not)."""
    moves = [seg for seg in profile
             if not (seg.kind == LINE and math.hypot(seg.x1 - seg.x0, seg.z1 - seg.z0) < _SHORT)]
    for a, b in itertools.pairwise(moves):
        if a.kind == LINE == b.kind and (a.x0 == a.x1 == b.x1 or a.z0 == a.z1 == b.z1):
            raise NgcSemanticError(PARALLEL)
