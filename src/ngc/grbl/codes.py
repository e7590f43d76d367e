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
VALUE_OUT_OF_RANGE = 39  # grblHAL's (errors.h Status_GcodeValueOutOfRange): Grbl has no 39

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
# grblHAL's groups beyond Grbl's (its gcode.c modal_groups_t: G10, G11 and M6, M9, M10)
GROUP_RETURN = 14  # G98 G99
GROUP_SCALING = 15  # G50 G51
GROUP_TOOL_CHANGE = 16  # M6 M61
GROUP_OVERRIDE = 17  # M48-M51 M53
GROUP_IO = 18  # M62-M68

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
    and for coolant whether ``value`` is added to the bits already on (M7, M8) or replaces them.
    ``unchecked``: a code the controller's parser takes but whose checks no row models yet (what
    it is, for the report); a block with one is read (its word errors are exact) but not
    checked."""

    group: int
    slot: int | None
    value: int
    axis: int = AXIS_NONE
    adds: bool = False
    unchecked: str = ""


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


def word_bits(axes: str, extra: str = "") -> Mapping[str, int]:
    """The value words Grbl reads, each a bit of a block's value words: F, I J K, L, N, P, R,
    S, T, a build's ``extra`` words (``Rules.extra_words``) and the axes.

    >>> list(word_bits("XYZ"))
    ['F', 'I', 'J', 'K', 'L', 'N', 'P', 'R', 'S', 'T', 'X', 'Y', 'Z']
    """
    letters = "FIJKLNPRST" + extra + axes
    return MappingProxyType({letter: 1 << n for n, letter in enumerate(letters)})


# -- grblHAL's parser (grblHAL/core gcode.c, gc_execute_block, commit 04ce2c5c; the default build:
#    N_TOOLS 0, N_WorkCoordinateSystems 9, mill mode $32=0, TOOL_LENGTH_OFFSET_AXIS -1) -----------
CANNED_CYCLE = "a canned cycle (G73 G81-G83 G85 G86 G89)"
_HAL_UNCHECKED_MOTION = {
    (5, 0): "G5, a cubic spline", (5, 10): "G5.1, a quadratic spline",
    (33, 0): "G33, spindle-synchronised motion (it needs a spindle with feedback)",
    (76, 0): "G76, a threading cycle (it needs a spindle with feedback)",
    **{(n, 0): CANNED_CYCLE for n in (73, 81, 82, 83, 85, 86, 89)},
}  # fmt: skip
HAL_G_CODES: Mapping[tuple[int, int], Code] = MappingProxyType({
    **{key: code for key, code in G_CODES.items() if key not in ((49, 0), (43, 10))},
    # G43.1 and G49: "case 43: case 49" sets no axis command for G49 (its axis words are a
    # motion's); G43.1 is the only one that checks for a second axis command
    (43, 10): Code(GROUP_TOOL_LENGTH, TOOL_LENGTH, LENGTH_DYNAMIC, AXIS_TOOL_LENGTH),
    (49, 0): Code(GROUP_TOOL_LENGTH, TOOL_LENGTH, LENGTH_CANCEL),
    # G59.1-G59.3 "if(N_WorkCoordinateSystems == 9 ...)": systems 7 to 9
    **{(59, 10 * n): Code(GROUP_COORD_SYSTEM, COORD_SYSTEM, 5 + n) for n in (1, 2, 3)},
    # G98 G99, the canned cycles' retract mode: set, used by nothing this row checks
    (98, 0): Code(GROUP_RETURN, None, 0), (99, 0): Code(GROUP_RETURN, None, 0),
    # G92.2 (G92 off, not stored) and G92.3 (G92 back from storage)
    (92, 20): Code(GROUP_NON_MODAL, NON_MODAL, NO_ACTION, unchecked="G92.2 (G92 cleared, "
                   "not stored)"),
    (92, 30): Code(GROUP_NON_MODAL, NON_MODAL, NO_ACTION, unchecked="G92.3 (G92 restored from "
                   "storage)"),
    # "case 50: case 51": the axis command is set to scaling, without the conflict check
    (50, 0): Code(GROUP_SCALING, None, 0, unchecked="G50/G51, scaling"),
    (51, 0): Code(GROUP_SCALING, None, 0, unchecked="G50/G51, scaling"),
    # G95 is refused at step 4 unless the spindle reports its speed (the driver's)
    (95, 0): Code(GROUP_FEED_MODE, None, 0, unchecked="G95, feed per revolution (it needs a "
                  "spindle that reports its speed)"),
    **{key: Code(GROUP_MOTION, None, 0, AXIS_MOTION, unchecked=what)
       for key, what in _HAL_UNCHECKED_MOTION.items()},
})  # fmt: skip

HAL_G_FRACTIONS: Mapping[int, Fraction] = MappingProxyType({
    **{n: Fraction(AXIS_MOTION, COMMAND_VALUE_NOT_INTEGER)
       for n in (0, 1, 2, 3, 73, 81, 82, 83, 85, 86, 89)},
    5: Fraction(AXIS_MOTION, UNSUPPORTED_COMMAND),  # G5.x but G5.1: after the axis check
    49: Fraction(AXIS_NONE, 0),  # G49.x is G49
    # tested before any axis check: G38.x (but .2-.5), G43 and G43.x (but .1: N_TOOLS 0), G28.x
    # G30.x (but .1), G92.x (but .1-.3), G33.x, G76.x, G59.x (but .1-.3), G61.x, G90.x, G91.x
    **dict.fromkeys((38, 43, 28, 30, 92, 33, 76, 59, 61, 90, 91), _TESTED),
    **dict.fromkeys((4, 10, 53, 17, 18, 19, 93, 94, 95, 20, 21, 40, 80, 54, 55, 56, 57, 58, 98,
                     99, 50, 51), _WHOLE_ONLY),
})  # fmt: skip

_HAL_M_CODES = {
    **_M_CODES,
    # M60: a pause (pallet shuttle, not in check mode) that does not end the program
    60: Code(GROUP_STOPPING, PROGRAM_FLOW, PAUSED),
    # M6: refused unless the stream can be suspended or the driver changes tools, and ignored
    # with $341 "ignore"; M61 sets the tool (Q); M48-M53: override control (P); M62-M68: the
    # driver's outputs and inputs (refused without them)
    6: Code(GROUP_TOOL_CHANGE, None, 0, unchecked="M6, a tool change (it depends on the driver "
            "and $341)"),
    61: Code(GROUP_TOOL_CHANGE, None, 0, unchecked="M61, set the tool number"),
    **{n: Code(GROUP_OVERRIDE, None, 0, unchecked=f"M{n}, override control")
       for n in (48, 49, 50, 51, 53)},
    **{n: Code(GROUP_IO, None, 0, unchecked=f"M{n}, the driver's ports")
       for n in (62, 63, 64, 65, 66, 67, 68)},
}  # fmt: skip


class CodeTable(NamedTuple):
    """A parser's G codes (by whole number and hundredths), what it does with the fractions it
    does not list, and its M codes."""

    g_codes: Mapping[tuple[int, int], Code]
    g_fractions: Mapping[int, Fraction]
    m_codes: Mapping[int, Code]


def code_table(parser: str, mist_coolant: bool) -> CodeTable:
    """The codes of ``parser`` (``Rules.parser``: ``grbl`` or ``grblhal``), M7 only with mist
    coolant.

    >>> sorted(code_table("grblhal", True).m_codes)[:10]
    [0, 1, 2, 3, 4, 5, 6, 7, 8, 9]
    """
    if parser == "grbl":
        return CodeTable(G_CODES, G_FRACTIONS, m_codes(mist_coolant))
    m = MappingProxyType({n: c for n, c in _HAL_M_CODES.items() if n != MIST or mist_coolant})
    return CodeTable(HAL_G_CODES, HAL_G_FRACTIONS, m)
