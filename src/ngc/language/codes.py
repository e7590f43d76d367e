"""THE code table: every G and M code ngc knows, with its modal group and execution step.

G codes are integers: the G number times ten (G38.2 -> 382, G0 -> 0), as LinuxCNC does, so no float is
ever compared.  Modal groups follow overview.adoc, "Modal Groups"; the order of execution is
``Interpreter.convert`` (overview.adoc, "G-code Order of Execution").  ``implemented`` marks codes
whose handlers exist; the others are known to the language (so a line using them reads fine) but
rejected with a clear error when executed.
"""

from __future__ import annotations

from typing import NamedTuple


class Code(NamedTuple):
    """One G or M code: its modal group and whether its handler exists yet."""

    group: int
    implemented: bool = True


# G-code modal groups (overview.adoc table "G-code Modal Groups").
G_NON_MODAL = 0
G_MOTION = 1
G_PLANE = 2
G_DISTANCE = 3
G_ARC_DISTANCE = 4
G_FEED_MODE = 5
G_UNITS = 6
G_CUTTER_COMP = 7
G_TOOL_LENGTH = 8
G_RETRACT = 10
G_COORD_SYSTEM = 12
G_CONTROL = 13
G_SPINDLE_MODE = 14
G_LATHE = 15

# M-code modal groups (overview.adoc table "M-code Modal Groups").
M_STOP = 4
M_IO = 5
M_TOOL = 6
M_SPINDLE = 7
M_COOLANT = 8
M_OVERRIDE = 9
M_USER = 10
M_STATE = 11

_NO = False

G_CODES: dict[int, Code] = {
    # group 0: non-modal
    40: Code(G_NON_MODAL),  # G4 dwell
    100: Code(G_NON_MODAL),  # G10 set coordinate data / tools
    280: Code(G_NON_MODAL),  # G28
    281: Code(G_NON_MODAL),  # G28.1
    300: Code(G_NON_MODAL),  # G30
    301: Code(G_NON_MODAL),  # G30.1
    520: Code(G_NON_MODAL),  # G52
    530: Code(G_NON_MODAL),  # G53
    920: Code(G_NON_MODAL),  # G92
    921: Code(G_NON_MODAL),  # G92.1
    922: Code(G_NON_MODAL),  # G92.2
    923: Code(G_NON_MODAL),  # G92.3
    # group 1: motion
    0: Code(G_MOTION),
    10: Code(G_MOTION),
    20: Code(G_MOTION),
    30: Code(G_MOTION),
    50: Code(G_MOTION, _NO),  # G5 cubic spline
    51: Code(G_MOTION, _NO),  # G5.1 quadratic spline
    52: Code(G_MOTION, _NO),  # G5.2 NURBS
    330: Code(G_MOTION, _NO),  # G33 spindle synchronized
    331: Code(G_MOTION, _NO),  # G33.1 rigid tap
    382: Code(G_MOTION, _NO),
    383: Code(G_MOTION, _NO),
    384: Code(G_MOTION, _NO),
    385: Code(G_MOTION, _NO),
    730: Code(G_MOTION, _NO),
    760: Code(G_MOTION, _NO),
    800: Code(G_MOTION),  # G80 cancel motion
    810: Code(G_MOTION, _NO),
    820: Code(G_MOTION, _NO),
    830: Code(G_MOTION, _NO),
    840: Code(G_MOTION, _NO),
    850: Code(G_MOTION, _NO),
    860: Code(G_MOTION, _NO),
    870: Code(G_MOTION, _NO),
    880: Code(G_MOTION, _NO),
    890: Code(G_MOTION, _NO),
    # group 2: plane
    170: Code(G_PLANE),
    171: Code(G_PLANE),
    180: Code(G_PLANE),
    181: Code(G_PLANE),
    190: Code(G_PLANE),
    191: Code(G_PLANE),
    # group 3 / 4: distance modes
    900: Code(G_DISTANCE),
    910: Code(G_DISTANCE),
    901: Code(G_ARC_DISTANCE),
    911: Code(G_ARC_DISTANCE),
    # group 5: feed mode
    930: Code(G_FEED_MODE),
    940: Code(G_FEED_MODE),
    950: Code(G_FEED_MODE),
    # group 6: units
    200: Code(G_UNITS),
    210: Code(G_UNITS),
    # group 7: cutter radius compensation
    400: Code(G_CUTTER_COMP),
    410: Code(G_CUTTER_COMP, _NO),
    411: Code(G_CUTTER_COMP, _NO),
    420: Code(G_CUTTER_COMP, _NO),
    421: Code(G_CUTTER_COMP, _NO),
    # group 8: tool length offset
    430: Code(G_TOOL_LENGTH, _NO),
    431: Code(G_TOOL_LENGTH, _NO),
    432: Code(G_TOOL_LENGTH, _NO),
    490: Code(G_TOOL_LENGTH, _NO),
    # group 10: canned-cycle return mode
    980: Code(G_RETRACT),
    990: Code(G_RETRACT),
    # group 12: coordinate system
    540: Code(G_COORD_SYSTEM),
    550: Code(G_COORD_SYSTEM),
    560: Code(G_COORD_SYSTEM),
    570: Code(G_COORD_SYSTEM),
    580: Code(G_COORD_SYSTEM),
    590: Code(G_COORD_SYSTEM),
    591: Code(G_COORD_SYSTEM),
    592: Code(G_COORD_SYSTEM),
    593: Code(G_COORD_SYSTEM),
    # group 13: path control
    610: Code(G_CONTROL),
    611: Code(G_CONTROL),
    640: Code(G_CONTROL),
    # group 14: spindle speed mode
    960: Code(G_SPINDLE_MODE, _NO),
    970: Code(G_SPINDLE_MODE),
    # group 15: lathe diameter / radius mode
    70: Code(G_LATHE, _NO),
    80: Code(G_LATHE, _NO),
}

M_CODES: dict[int, Code] = {
    0: Code(M_STOP),
    1: Code(M_STOP),
    2: Code(M_STOP),
    30: Code(M_STOP),
    60: Code(M_STOP),
    3: Code(M_SPINDLE),
    4: Code(M_SPINDLE),
    5: Code(M_SPINDLE),
    19: Code(M_SPINDLE, _NO),
    6: Code(M_TOOL, _NO),
    61: Code(M_TOOL, _NO),
    7: Code(M_COOLANT),
    8: Code(M_COOLANT),
    9: Code(M_COOLANT),
    48: Code(M_OVERRIDE),
    49: Code(M_OVERRIDE),
    50: Code(M_OVERRIDE),
    51: Code(M_OVERRIDE),
    52: Code(M_OVERRIDE),
    53: Code(M_OVERRIDE),
    62: Code(M_IO, _NO),
    63: Code(M_IO, _NO),
    64: Code(M_IO, _NO),
    65: Code(M_IO, _NO),
    66: Code(M_IO, _NO),
    67: Code(M_IO, _NO),
    68: Code(M_IO, _NO),
    70: Code(M_STATE, _NO),
    71: Code(M_STATE, _NO),
    72: Code(M_STATE, _NO),
    73: Code(M_STATE, _NO),
    98: Code(M_USER, _NO),
    99: Code(M_USER, _NO),
}

# G codes whose axis words are theirs (overview.adoc, "Modal Groups": group 0 codes that use axis
# words suspend the motion mode for the line).
G_AXIS_USERS_NON_MODAL = frozenset({100, 280, 300, 520, 920})

AXIS_LETTERS = "xyzabc"

# Polar coordinate words: distance @ and angle ^ in the XY plane (overview.adoc, "Polar
# Coordinates").
POLAR_LETTERS = "@^"


def g_name(code: int) -> str:
    """``G2`` / ``G38.2`` from the integer form (G number times ten)."""
    whole, tenth = divmod(code, 10)
    return f"G{whole}.{tenth}" if tenth else f"G{whole}"
