"""The modal state M70 / M73 save, and the saved state of one call level (see
:mod:`.context` for how it is restored)."""

from __future__ import annotations

from typing import NamedTuple


class Snapshot(NamedTuple):
    """The modal state M70 / M73 save (m-code.adoc, "M70 Saved state")."""

    metric: bool
    plane: int
    ccomp: int
    absolute: bool
    feed_mode: int
    coord_index: int
    tool_offset: bool  # a tool length offset in effect (G43) or not (G49)
    retract_r: bool
    control_mode: int
    path_tolerance: float
    naive_tolerance: float
    css: bool  # spindle mode: G96 (constant surface speed) or G97
    arc_absolute: bool
    lathe_diameter: bool
    feed: float
    speed: float
    spindle: int
    mist: bool
    flood: bool
    feed_override: bool
    adaptive_feed: bool
    feed_hold: bool


class Context:
    """The saved state of one call level."""

    __slots__ = ("auto", "saved")

    def __init__(self) -> None:
        self.saved: Snapshot | None = None
        self.auto = False  # M73: a return from this level restores ``saved``
