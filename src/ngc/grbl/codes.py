"""Grbl's tables: the status codes and their messages, the G and M codes its parser accepts with
their modal groups and what each sets, and the value words.

The names follow Grbl 1.1h's parser (``gcode.h``): modal groups are bits of a block's command
words, and the modes a code sets are named as its parser state names them (``MOTION_MODE_*``,
``NON_MODAL_*``, ...; the numbers are this module's), so that the checks read like the rules
they follow.  The messages are the
``Error Description`` column of Grbl's ``error_codes_en_US.csv`` (spec/grbl/).
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType
from typing import NamedTuple

# -- status codes (the ``error:N`` of a rejected line) --------------------------------------------
EXPECTED_COMMAND_LETTER = 1
BAD_NUMBER_FORMAT = 2
NEGATIVE_VALUE = 4
LINE_OVERFLOW = 11
UNSUPPORTED_COMMAND = 20
MODAL_GROUP_VIOLATION = 21
UNDEFINED_FEED_RATE = 22
COMMAND_VALUE_NOT_INTEGER = 23
AXIS_COMMAND_CONFLICT = 24
WORD_REPEATED = 25
NO_AXIS_WORDS = 26
INVALID_LINE_NUMBER = 27
VALUE_WORD_MISSING = 28
UNSUPPORTED_COORD_SYS = 29
G53_INVALID_MOTION_MODE = 30
AXIS_WORDS_EXIST = 31
NO_AXIS_WORDS_IN_PLANE = 32
INVALID_TARGET = 33
ARC_RADIUS_ERROR = 34
NO_OFFSETS_IN_PLANE = 35
UNUSED_WORDS = 36
G43_DYNAMIC_AXIS_ERROR = 37
MAX_VALUE_EXCEEDED = 38

MESSAGES: Mapping[int, str] = MappingProxyType({
    1: "G-code words consist of a letter and a value. Letter was not found.",
    2: "Missing the expected G-code word value or numeric value format is not valid.",
    3: "Grbl '$' system command was not recognized or supported.",
    4: "Negative value received for an expected positive value.",
    5: "Homing cycle failure. Homing is not enabled via settings.",
    6: "Minimum step pulse time must be greater than 3usec.",
    7: "An EEPROM read failed. Auto-restoring affected EEPROM to default values.",
    8: "Grbl '$' command cannot be used unless Grbl is IDLE. Ensures smooth operation during a "
       "job.",
    9: "G-code commands are locked out during alarm or jog state.",
    10: "Soft limits cannot be enabled without homing also enabled.",
    11: "Max characters per line exceeded. Received command line was not executed.",
    12: "Grbl '$' setting value cause the step rate to exceed the maximum supported.",
    13: "Safety door detected as opened and door state initiated.",
    14: "Build info or startup line exceeded EEPROM line length limit. Line not stored.",
    15: "Jog target exceeds machine travel. Jog command has been ignored.",
    16: "Jog command has no '=' or contains prohibited g-code.",
    17: "Laser mode requires PWM output.",
    20: "Unsupported or invalid g-code command found in block.",
    21: "More than one g-code command from same modal group found in block.",
    22: "Feed rate has not yet been set or is undefined.",
    23: "G-code command in block requires an integer value.",
    24: "More than one g-code command that requires axis words found in block.",
    25: "Repeated g-code word found in block.",
    26: "No axis words found in block for g-code command or current modal state which requires "
        "them.",
    27: "Line number value is invalid.",
    28: "G-code command is missing a required value word.",
    29: "G59.x work coordinate systems are not supported.",
    30: "G53 only allowed with G0 and G1 motion modes.",
    31: "Axis words found in block when no command or current modal state uses them.",
    32: "G2 and G3 arcs require at least one in-plane axis word.",
    33: "Motion command target is invalid.",
    34: "Arc radius value is invalid.",
    35: "G2 and G3 arcs require at least one in-plane offset word.",
    36: "Unused value words found in block.",
    37: "G43.1 dynamic tool length offset is not assigned to configured tool length axis.",
    38: "Tool number greater than max supported value.",
})  # fmt: skip

# -- modal groups: a bit each in a block's command words (gcode.h MODAL_GROUP_*) -----------------
GROUP_NON_MODAL = 0  # G4 G10 G28 G28.1 G30 G30.1 G53 G92 G92.1
GROUP_MOTION = 1  # G0 G1 G2 G3 G38.2-G38.5 G80
GROUP_PLANE = 2  # G17 G18 G19
GROUP_DISTANCE = 3  # G90 G91
GROUP_ARC_DISTANCE = 4  # G91.1
GROUP_FEED_MODE = 5  # G93 G94
GROUP_UNITS = 6  # G20 G21
GROUP_CUTTER = 7  # G40
GROUP_TOOL_LENGTH = 8  # G43.1 G49
GROUP_COORD_SYSTEM = 9  # G54-G59
GROUP_CONTROL = 10  # G61
GROUP_STOPPING = 11  # M0 M1 M2 M30
GROUP_SPINDLE = 12  # M3 M4 M5
GROUP_COOLANT = 13  # M7 M8 M9

# -- the slots of a block's modes (a list: its copy of the parser state's modes, then the
#    non-modal command of the block) -------------------------------------------------------------
MOTION = 0  # G0 G1 G2 G3 G38.2-G38.5 G80
FEED_MODE = 1  # G93 G94
UNITS = 2  # G20 G21
DISTANCE = 3  # G90 G91
PLANE = 4  # G17 G18 G19
TOOL_LENGTH = 5  # G43.1 G49
COORD_SYSTEM = 6  # G54-G59: 0-5
PROGRAM_FLOW = 7  # M0 M1 M2 M30
COOLANT = 8  # M7 M8 M9: a set of bits
SPINDLE = 9  # M3 M4 M5
NON_MODAL = 10  # G4 G10 G28 G28.1 G30 G30.1 G53 G92 G92.1 (the block's own, never kept)
POWER_UP_MODES = (0, 0, 0, 0, 0, 0, 0, 0, 0, 0)  # G0 G94 G21 G90 G17 G49 G54 M5 M9

# MOTION values (MOTION_MODE_*)
SEEK, LINEAR, CW_ARC, CCW_ARC = 0, 1, 2, 3
PROBE_TOWARD, PROBE_TOWARD_NO_ERROR, PROBE_AWAY, PROBE_AWAY_NO_ERROR = 4, 5, 6, 7
MOTION_NONE = 8
PROBES = frozenset({PROBE_TOWARD, PROBE_TOWARD_NO_ERROR, PROBE_AWAY, PROBE_AWAY_NO_ERROR})
# NON_MODAL values (NON_MODAL_*)
NO_ACTION, DWELL, SET_COORDINATE_DATA, GO_HOME_0, SET_HOME_0 = 0, 1, 2, 3, 4
GO_HOME_1, SET_HOME_1, ABSOLUTE_OVERRIDE, SET_COORDINATE_OFFSET = 5, 6, 7, 8
RESET_COORDINATE_OFFSET = 9
# FEED_MODE, UNITS, DISTANCE, PLANE, TOOL_LENGTH, PROGRAM_FLOW, SPINDLE and COOLANT values
UNITS_PER_MINUTE, INVERSE_TIME = 0, 1
MILLIMETRES, INCHES = 0, 1
ABSOLUTE, INCREMENTAL = 0, 1
PLANE_XY, PLANE_ZX, PLANE_YZ = 0, 1, 2
LENGTH_CANCEL, LENGTH_DYNAMIC = 0, 1
RUNNING, PAUSED, COMPLETED = 0, 1, 2
SPINDLE_OFF, SPINDLE_CW, SPINDLE_CCW = 0, 1, 2
COOLANT_OFF, COOLANT_FLOOD, COOLANT_MIST = 0, 1, 2

# -- axis commands: a block has at most one (a second is error 24) --------------------------------
AXIS_NONE = 0
AXIS_NON_MODAL = 1  # G10 G28 G30 G92: they use the axis words their own way
AXIS_MOTION = 2  # G0 G1 G2 G3 G38.x, or axis words alone in the motion mode
AXIS_TOOL_LENGTH = 3  # G43.1 G49


class Code(NamedTuple):
    """A G or M code Grbl accepts: its modal group, the slot of the block's modes it sets
    (None: it sets nothing, as G40, G61, G91.1 and M1) to ``value``, the axis command it is,
    and for coolant whether ``value`` is added to the bits already on (M7, M8) or replaces them."""

    group: int
    slot: int | None
    value: int
    axis: int = AXIS_NONE
    adds: bool = False


# G codes by (whole number, hundredths), as Grbl's parser splits a G word's value
G_CODES: Mapping[tuple[int, int], Code] = MappingProxyType({
    (0, 0): Code(GROUP_MOTION, MOTION, SEEK, AXIS_MOTION),
    (1, 0): Code(GROUP_MOTION, MOTION, LINEAR, AXIS_MOTION),
    (2, 0): Code(GROUP_MOTION, MOTION, CW_ARC, AXIS_MOTION),
    (3, 0): Code(GROUP_MOTION, MOTION, CCW_ARC, AXIS_MOTION),
    (38, 20): Code(GROUP_MOTION, MOTION, PROBE_TOWARD, AXIS_MOTION),
    (38, 30): Code(GROUP_MOTION, MOTION, PROBE_TOWARD_NO_ERROR, AXIS_MOTION),
    (38, 40): Code(GROUP_MOTION, MOTION, PROBE_AWAY, AXIS_MOTION),
    (38, 50): Code(GROUP_MOTION, MOTION, PROBE_AWAY_NO_ERROR, AXIS_MOTION),
    (80, 0): Code(GROUP_MOTION, MOTION, MOTION_NONE),
    (4, 0): Code(GROUP_NON_MODAL, NON_MODAL, DWELL),
    (10, 0): Code(GROUP_NON_MODAL, NON_MODAL, SET_COORDINATE_DATA, AXIS_NON_MODAL),
    (28, 0): Code(GROUP_NON_MODAL, NON_MODAL, GO_HOME_0, AXIS_NON_MODAL),
    (28, 10): Code(GROUP_NON_MODAL, NON_MODAL, SET_HOME_0),
    (30, 0): Code(GROUP_NON_MODAL, NON_MODAL, GO_HOME_1, AXIS_NON_MODAL),
    (30, 10): Code(GROUP_NON_MODAL, NON_MODAL, SET_HOME_1),
    (53, 0): Code(GROUP_NON_MODAL, NON_MODAL, ABSOLUTE_OVERRIDE),
    (92, 0): Code(GROUP_NON_MODAL, NON_MODAL, SET_COORDINATE_OFFSET, AXIS_NON_MODAL),
    (92, 10): Code(GROUP_NON_MODAL, NON_MODAL, RESET_COORDINATE_OFFSET),
    (17, 0): Code(GROUP_PLANE, PLANE, PLANE_XY),
    (18, 0): Code(GROUP_PLANE, PLANE, PLANE_ZX),
    (19, 0): Code(GROUP_PLANE, PLANE, PLANE_YZ),
    (90, 0): Code(GROUP_DISTANCE, DISTANCE, ABSOLUTE),
    (91, 0): Code(GROUP_DISTANCE, DISTANCE, INCREMENTAL),
    (91, 10): Code(GROUP_ARC_DISTANCE, None, 0),  # incremental IJK: Grbl's only arc mode
    (93, 0): Code(GROUP_FEED_MODE, FEED_MODE, INVERSE_TIME),
    (94, 0): Code(GROUP_FEED_MODE, FEED_MODE, UNITS_PER_MINUTE),
    (20, 0): Code(GROUP_UNITS, UNITS, INCHES),
    (21, 0): Code(GROUP_UNITS, UNITS, MILLIMETRES),
    (40, 0): Code(GROUP_CUTTER, None, 0),  # compensation is never on: accepted for headers
    (43, 10): Code(GROUP_TOOL_LENGTH, TOOL_LENGTH, LENGTH_DYNAMIC, AXIS_TOOL_LENGTH),
    (49, 0): Code(GROUP_TOOL_LENGTH, TOOL_LENGTH, LENGTH_CANCEL, AXIS_TOOL_LENGTH),
    **{(54 + n, 0): Code(GROUP_COORD_SYSTEM, COORD_SYSTEM, n) for n in range(6)},
    (61, 0): Code(GROUP_CONTROL, None, 0),  # exact path: Grbl's only control mode
})  # fmt: skip


class Fraction(NamedTuple):
    """What Grbl's parser does with ``G<whole>.<fraction>`` for a fraction :data:`G_CODES` does
    not list: the axis command it checks first (a second axis command in the block is error 24
    before the fraction is looked at), then the error for the fraction (20 where the parser
    tests the fraction itself, 23 where it only finds a value that is not whole), or 0 where it
    drops the fraction (G49.x is G49)."""

    axis: int
    error: int


_WHOLE_ONLY = Fraction(AXIS_NONE, COMMAND_VALUE_NOT_INTEGER)
_TESTED = Fraction(AXIS_NONE, UNSUPPORTED_COMMAND)
G_FRACTIONS: Mapping[int, Fraction] = MappingProxyType({
    **{n: Fraction(AXIS_MOTION, COMMAND_VALUE_NOT_INTEGER) for n in (0, 1, 2, 3)},
    38: Fraction(AXIS_MOTION, UNSUPPORTED_COMMAND),
    43: Fraction(AXIS_TOOL_LENGTH, UNSUPPORTED_COMMAND),
    49: Fraction(AXIS_TOOL_LENGTH, 0),
    **dict.fromkeys((28, 30, 92, 61, 90, 91), _TESTED),
    **dict.fromkeys((4, 10, 53, 17, 18, 19, 93, 94, 20, 21, 40, 80, 54, 55, 56, 57, 58, 59),
                    _WHOLE_ONLY),
})  # fmt: skip

MIST = 7  # M7: accepted only in a build with ENABLE_M7 (Rules.mist_coolant)
_M_CODES = {
    0: Code(GROUP_STOPPING, PROGRAM_FLOW, PAUSED),
    1: Code(GROUP_STOPPING, None, 0),  # optional stop: not supported, ignored
    2: Code(GROUP_STOPPING, PROGRAM_FLOW, COMPLETED),
    30: Code(GROUP_STOPPING, PROGRAM_FLOW, COMPLETED),
    3: Code(GROUP_SPINDLE, SPINDLE, SPINDLE_CW),
    4: Code(GROUP_SPINDLE, SPINDLE, SPINDLE_CCW),
    5: Code(GROUP_SPINDLE, SPINDLE, SPINDLE_OFF),
    MIST: Code(GROUP_COOLANT, COOLANT, COOLANT_MIST, adds=True),
    8: Code(GROUP_COOLANT, COOLANT, COOLANT_FLOOD, adds=True),
    9: Code(GROUP_COOLANT, COOLANT, COOLANT_OFF),
}


def m_codes(mist_coolant: bool) -> Mapping[int, Code]:
    """The M codes a build accepts, by number: M7 only with mist coolant (``ENABLE_M7``).

    >>> sorted(m_codes(False)), 7 in m_codes(True)
    ([0, 1, 2, 3, 4, 5, 8, 9, 30], True)
    """
    return MappingProxyType({n: c for n, c in _M_CODES.items() if n != MIST or mist_coolant})


# -- value words: the letters other than G and M ---------------------------------------------------
OFFSETS = "IJK"  # arc centre offsets: an index each, as the axes X Y Z
NOT_NEGATIVE = frozenset("FNPTS")  # a negative value is error 4


def word_bits(axes: str) -> Mapping[str, int]:
    """The value words Grbl reads, each a bit of a block's value words: F, I J K, L, N, P, R,
    S, T and the axes.

    >>> list(word_bits("XYZ"))
    ['F', 'I', 'J', 'K', 'L', 'N', 'P', 'R', 'S', 'T', 'X', 'Y', 'Z']
    """
    return MappingProxyType({letter: 1 << n for n, letter in enumerate("FIJKLNPRST" + axes)})
