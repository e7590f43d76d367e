"""A lathe cycle's profile: the moves of its subroutine as segments in the XZ plane.

Coordinates are program coordinates, X a radius (diameter mode halves it as read), in the
program's units.  The first segment starts at the cycle's start point.
"""

from __future__ import annotations

import math
from typing import NamedTuple

LINE = 1
CW = 2  # G2
CCW = 3  # G3

NOT_MONOTONIC = "G7X error: Not monotonic"
PARALLEL = "G7X error: Cannot intersect parallel lines"
_EPS = 1e-9
_NEAR_END = 1e-3


class Seg(NamedTuple):
    """One move of the profile: a line (``kind`` LINE) or an arc (CW/CCW, as G2/G3 in G18)
    from (x0, z0) to (x1, z1), centre (cx, cz) for arcs (0 for lines).

    ``fillet`` and ``chamfer`` are the move's A and C words (0 when absent): a fillet or chamfer
    of that size at the move's end point.  ``line`` is the source line of the move.
    """

    kind: int
    x0: float
    z0: float
    x1: float
    z1: float
    cx: float = 0.0
    cz: float = 0.0
    fillet: float = 0.0
    chamfer: float = 0.0
    line: int = 0
    rounding: bool = False  # an arc put in to round an outside corner of a moved profile


Profile = list[Seg]


def steps(seg: Seg, axis: int) -> tuple[float, bool]:
    """The change of ``seg`` along X (``axis`` 0) or Z (1) and whether it goes one way there
    (an arc that turns back on that axis does not)."""
    v0, v1 = (seg.x0, seg.x1) if axis == 0 else (seg.z0, seg.z1)
    if seg.kind == LINE:
        return v1 - v0, True
    # the arc's extremes on the axis lie where its radius is parallel to the axis; one within
    # 0.001 of the arc's start or end turns nothing back (rs274: whatever the arc's radius)
    r = math.hypot(seg.x0 - seg.cx, seg.z0 - seg.cz)
    for extreme in (0.0, math.pi) if axis == 1 else (math.pi / 2, -math.pi / 2):
        if within(seg, extreme):
            px, pz = seg.cx + r * math.sin(extreme), seg.cz + r * math.cos(extreme)
            if (math.hypot(px - seg.x0, pz - seg.z0) > _NEAR_END
                    and math.hypot(px - seg.x1, pz - seg.z1) > _NEAR_END):
                return v1 - v0, False
    return v1 - v0, True


def within(seg: Seg, angle: float) -> bool:
    """Whether the direction ``angle`` (atan2(x, z) about the centre) lies strictly inside the
    arc ``seg``."""
    a0 = math.atan2(seg.x0 - seg.cx, seg.z0 - seg.cz)
    a1 = math.atan2(seg.x1 - seg.cx, seg.z1 - seg.cz)
    if seg.kind == CW:
        a0, a1 = a1, a0
    sweep = (a1 - a0) % (2 * math.pi)
    at = (angle - a0) % (2 * math.pi)
    return _EPS < at < sweep - _EPS
