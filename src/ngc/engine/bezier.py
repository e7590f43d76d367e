"""Cubic Bézier pieces of displacement over normalised time, one axis at a time.

A piece is four control points ``(p0, p1, p2, p3)`` of a cubic in t over its interval."""

from __future__ import annotations

import math

Cubic = tuple[float, float, float, float]

# Gauss-Legendre nodes and weights on [0, 1] (8 points): arc lengths of the pieces
_GL = (
    (0.019855071751231856, 0.05061426814518813),
    (0.10166676129318664, 0.11119051722668724),
    (0.2372337950418355, 0.15685332293894363),
    (0.4082826787521751, 0.18134189168918100),
    (0.5917173212478249, 0.18134189168918100),
    (0.7627662049581645, 0.15685332293894363),
    (0.8983332387068134, 0.11119051722668724),
    (0.9801449282487681, 0.05061426814518813),
)


def line(d: float, t0: float, t1: float) -> Cubic:
    """``d * t`` (constant speed to ``d``) over [t0, t1]."""
    a, b = d * t0, d * t1
    return (a, a + (b - a) / 3.0, a + 2.0 * (b - a) / 3.0, b)


def point(c: Cubic, t: float) -> float:
    p0, p1, p2, p3 = c
    s = 1.0 - t
    return s * s * s * p0 + 3.0 * s * s * t * p1 + 3.0 * s * t * t * p2 + t * t * t * p3


def slope(c: Cubic, t: float) -> float:
    p0, p1, p2, p3 = c
    s = 1.0 - t
    return 3.0 * (s * s * (p1 - p0) + 2.0 * s * t * (p2 - p1) + t * t * (p3 - p2))


def part(c: Cubic, t0: float, t1: float) -> Cubic:
    """The same curve over [t0, t1] of its own interval [0, 1], as a cubic of its own."""
    p0, p3 = point(c, t0), point(c, t1)
    h = t1 - t0
    return (p0, p0 + h * slope(c, t0) / 3.0, p3 - h * slope(c, t1) / 3.0, p3)


def length(axes: list[Cubic]) -> float:
    """The length of the path the axes draw together over the piece."""
    total = 0.0
    for t, w in _GL:
        # (s * s, not s ** 2: a slope past 1e154 squares to infinity instead of raising)
        total += w * math.sqrt(sum(s * s for s in (slope(c, t) for c in axes)))
    return total


def quarter_factor(sweep: float) -> float:
    """The tangent length, as a fraction of the radius, of the cubic closest to a circular arc of
    ``sweep`` radians (at most a quarter turn): 4/3 tan(sweep/4)."""
    return 4.0 / 3.0 * math.tan(sweep / 4.0)
