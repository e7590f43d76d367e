"""A lathe cycle's profile: the moves of its subroutine as segments in the XZ plane.

Coordinates are program coordinates, X a radius (diameter mode halves it as read), in the
program's units.  The first segment starts at the cycle's start point.
"""

from __future__ import annotations

from typing import NamedTuple

LINE = 1
CW = 2  # G2
CCW = 3  # G3


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


Profile = list[Seg]
