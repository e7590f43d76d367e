"""The interpreter's modal state and machine position.

Lengths are in the current program units (G20 inch / G21 mm), as rs274's canon speaks; the position
is in program coordinates (the active G5x and G92 offsets removed, rotation undone).  Each modal field
names the codes that set it.  Codes are integers, the G number times ten.
"""

from __future__ import annotations

from ..config.tooltable import Tools

AXES = 6  # X Y Z A B C: the standalone machine's axes
LINEAR = (True, True, True, False, False, False)
MM_PER_INCH = 25.4


class State:
    """Everything a block can read or change, except parameters."""

    __slots__ = (
        "absolute",
        "adaptive_feed",
        "arc_absolute",
        "blocks_deleted",
        "call_level",
        "canon_anchor",
        "canon_pos",
        "ccomp",
        "control_mode",
        "coord_index",
        "css",
        "css_max",
        "cycle_code",
        "cycle_level",
        "cycle_offsets",
        "cycle_p",
        "cycle_q",
        "cycle_r",
        "cycle_z",
        "feed",
        "feed_hold",
        "feed_mode",
        "feed_override",
        "flood",
        "g5x",
        "g92",
        "g92_applied",
        "lathe_diameter",
        "line",
        "metric",
        "mist",
        "motion",
        "naive_tolerance",
        "nurbs",
        "nurbs_order",
        "orient_offset",
        "path_tolerance",
        "plane",
        "pos",
        "retract_r",
        "rotation",
        "selected_index",
        "selected_tool",
        "speed",
        "speed_override",
        "spindle",
        "spline_pq",
        "tlo",
        "tool_changed",
        "tool_index",
        "tools",
        "value",
        "value_returned",
)

    def __init__(self) -> None:
        self.pos = [0.0] * AXES  # current point, program coordinates
        self.g5x = [0.0] * AXES  # active G54..G59.3 origin (program units)
        self.g92 = [0.0] * AXES  # G52 / G92 axis offset (program units)
        self.g92_applied = False  # G92 set (#5210); G92.1 / G92.2 clear it, G92.3 restores
        self.rotation = 0.0  # degrees, G10 L2 R of the active system
        self.coord_index = 1  # G54=1 ... G59.3=9
        self.metric = True  # G21 True, G20 False
        self.plane = 170  # G17 170, G18 180, G19 190, G17.1 171, G18.1 181, G19.1 191
        self.absolute = True  # G90 True, G91 False
        self.arc_absolute = False  # G90.1 True, G91.1 False
        self.feed_mode = 940  # G93 930, G94 940, G95 950
        self.motion = 800  # G0 0, G1 10, G2 20, G3 30, G80 800
        # rs274 starts in continuous mode, tolerance 0 (what a canned cycle restores after it)
        self.control_mode = 640  # G61 610, G61.1 611, G64 640
        self.path_tolerance = 0.0  # G64 P
        self.naive_tolerance = 0.0  # G64 Q
        self.retract_r = True  # G99 True (R plane, as rs274 starts), G98 False
        self.ccomp = 400  # G40 400
        # Splines (handlers/splines.py): the control points (X, Y, weight) of the G5.2 block
        # being read and its order (L); the P and Q of the last G5, which a G5 without I and J
        # continues from.
        self.nurbs: list[tuple[float, float, float]] = []
        self.nurbs_order = 3
        self.spline_pq = (0.0, 0.0)
        # Canned cycles (handlers/cycles.py): the sticky R, Z and P words of the last cycle, as
        # given (relative in G91; not converted by G20 / G21), and the drill axis' initial level
        # of a series of cycles, which holds while the motion mode stays ``cycle_code``, the last
        # cycle run.
        self.cycle_r = 0.0
        self.cycle_z = 0.0
        self.cycle_p = 0.0
        self.cycle_q = 0.0
        self.cycle_level = 0.0
        self.cycle_offsets = (0.0, 0.0, 0.0)  # G87's sticky I J K
        self.cycle_code = -1  # none
        # Tools.  ``tools`` is the machine's tool data (slot 0: the spindle's entry).
        self.tools = Tools()
        self.tlo = [0.0] * 9  # tool length offset X Y Z A B C U V W in effect, program units
        # The slot the spindle holds (M6, M61).  rs274 starts with 1, the first entry's slot,
        # though the spindle's entry is empty: #<_current_pocket> reads that entry's pocket.
        self.tool_index = 1
        self.selected_index = 0  # the slot the last T word selected (0: none / T0)
        self.selected_tool = 0  # the last T word
        # Where the canon thinks the current point is, when a tool length offset or rotation
        # change moved the interpreter's current point but not the canon's: the point plus the
        # G5x and G92 offsets, in millimetres (see tools.hold_canon); ``canon_anchor`` is the
        # ``pos`` list it belongs to (a move replaces it).  M6 and M61 take the canon's point
        # back.
        self.canon_pos: list[float] | None = None
        self.canon_anchor: list[float] | None = None
        self.tool_changed = False  # M6 or M61 ran in the line being executed
        self.lathe_diameter = False  # G7
        self.feed = 0.0  # F
        self.speed = 0.0  # S
        self.spindle = 0  # M3 1, M4 -1, M5 0 (and M19: orienting, not turning)
        self.css = False  # G96 True, G97 False
        self.css_max = 0.0  # G96 D: the maximum rpm in constant surface speed
        self.orient_offset = 0.0  # M19: [RS274NGC]ORIENT_OFFSET, degrees added to R
        self.mist = False  # M7 / M9
        self.flood = False  # M8 / M9
        self.feed_override = True  # M48 / M49 / M50
        self.speed_override = True  # M48 / M49 / M51
        self.adaptive_feed = False  # M52
        self.feed_hold = True  # M53
        self.line = 0  # source line being executed (#<_line>)
        self.blocks_deleted = False  # block delete switch (rs274 -b)
        self.value = 0.0  # #<_value>: the last subroutine's return value
        self.value_returned = 0.0  # #<_value_returned>: 1 if it returned one
        self.call_level = 0  # #<_call_level>: subroutine calls under way
