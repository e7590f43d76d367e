"""hypot as rs274's C library computes it, to the last bit.

rs274 takes the distance of the current point from the origin with the C library's ``hypot``
(polar coordinates, overview.adoc "Polar Coordinates").  GNU libc's (2.35 and later) is not
correctly rounded: about one result in two hundred is one unit in the last place away from the
exact distance rounded, where Python's ``math.hypot`` is (almost always) correctly rounded.  The
last bit shows: a polar move that ends on an axis prints -0.0000 or 0.0000 by it.  This is that
algorithm (without fused multiply-add, as the x86-64 library runs it): the square root of the
sum of squares, corrected once by the rounding error of the squares, with the inputs scaled
where a square would overflow or underflow.
"""

from __future__ import annotations

import math

_SCALE = 2.0**-600
_LARGE = 2.0**511
_TINY = 2.0**-459  # below this the correction terms would lose bits to subnormals
_EPS = 2.0**-54


def _kernel(ax: float, ay: float) -> float:
    """sqrt(ax² + ay²) for ax >= ay > 0, neither huge nor tiny, corrected by the squares' error."""
    h = math.sqrt(ax * ax + ay * ay)
    if h <= 2.0 * ay:
        delta = h - ay
        t1 = ax * (2.0 * delta - ax)
        t2 = (delta - 2.0 * (ax - ay)) * delta
    else:
        delta = h - ax
        t1 = 2.0 * delta * (ax - 2.0 * ay)
        t2 = (4.0 * delta - ay) * ay + delta * delta
    return h - (t1 + t2) / (2.0 * h)


def hypot(x: float, y: float) -> float:
    """The distance of (x, y) from the origin, as GNU libc's ``hypot`` gives it.

    >>> hypot(3.0, 4.0)
    5.0
    >>> hypot(-2.5756, -2.5413) == math.hypot(-2.5756, -2.5413)  # one unit apart
    False
    """
    if math.isinf(x) or math.isinf(y):
        return math.inf
    if math.isnan(x) or math.isnan(y):
        return x + y
    ax, ay = abs(x), abs(y)
    if ax < ay:
        ax, ay = ay, ax
    if ax > _LARGE:
        if ay <= ax * _EPS:
            return ax + ay
        return _kernel(ax * _SCALE, ay * _SCALE) / _SCALE
    if ay < _TINY:
        if ax >= ay / _EPS:
            return ax + ay
        return _kernel(ax / _SCALE, ay / _SCALE) * _SCALE
    if ay <= ax * _EPS:
        return ax + ay
    return _kernel(ax, ay)
