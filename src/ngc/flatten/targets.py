"""The controllers ``ngc flatten`` writes for, each a table of what it accepts: a new controller
is a row, not a branch.

Only ``linuxcnc`` is written so far; the others are named so that asking for them says so.
"""

from __future__ import annotations

from types import MappingProxyType
from typing import NamedTuple


class Target(NamedTuple):
    """What a controller takes."""

    name: str
    arc_planes: frozenset[str]  # G17 G18 G19 where it cuts arcs
    helix: bool  # an arc may move along its axis
    turns: bool  # an arc may turn more than once (P)
    tool_length: str  # "G43 H": the table's length by number; "none": folded into coordinates
    tool_change: bool  # M6 T
    feed_per_rev: bool  # G95
    blending: bool  # G64 P Q, G61, G61.1
    decimals_mm: int
    decimals_inch: int
    max_line: int  # characters of a line (0: no limit)
    written: bool  # ngc flatten writes for it now


TARGETS = MappingProxyType({
    "linuxcnc": Target("linuxcnc", frozenset({"G17", "G18", "G19"}), True, True, "G43 H", True,
                       True, True, 4, 5, 0, True),
    "grbl": Target("grbl", frozenset({"G17", "G18", "G19"}), True, False, "none", False, False,
                   False, 3, 4, 79, False),
    "grblhal": Target("grblhal", frozenset({"G17", "G18", "G19"}), True, False, "none", False,
                      True, False, 3, 4, 255, False),
    "fluidnc": Target("fluidnc", frozenset({"G17", "G18", "G19"}), True, False, "none", False,
                      False, False, 3, 4, 255, False),
})
