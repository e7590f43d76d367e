"""THE code table: every G and M code of a dialect, one row each.

A row says everything the interpreter needs to know about a code: its modal group, its step in the
order of execution (overview.adoc, "G-code Order of Execution"), the words it gives a use to, the
words it requires, and the name of its handler.  Reading (``words.add_word``), checking
(``interp/check.py``) and dispatch (``interp/dispatch.py``) are loops over the rows, so adding a
code is one row here and one handler in ``interp/handlers``.

The table is a value (:class:`CodeTable`): the interpreter is given one (:data:`LINUXCNC` by
default); another dialect brings its own.  G codes are integers, the G number times ten (G38.2 ->
382, G0 -> 0), as LinuxCNC does, so no float is ever compared.  A row whose handler is ``None`` is
a code the language knows but ngc does not run yet: a line using it reads fine and is refused as
"G41 is not supported yet" before anything on it executes.
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType
from typing import NamedTuple


class Code(NamedTuple):
    """One G or M code."""

    group: int
    step: int
    handler: str | None  # name in the interpreter's handler registry; None: not supported yet
    uses: str = ""  # letters (beyond X Y Z A B C F S) this code gives a use to
    axes: bool = False  # a group-0 code that takes the line's axis words (motion is suspended)
    requires: str = ""  # the line must hold one of these letters ("xyzabc": an axis word) ...
    missing: str = ""  # ... or this is the error
    # rs274's refusal of this code while cutter radius compensation is on, raised at its step
    # (before "not supported yet" for a code ngc does not run yet)
    comp_refusal: str = ""
    cycle: bool = False  # a canned cycle (g-code.adoc, "G80-G89 Canned Cycles")


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
# G92.1 / G92.2 / G92.3: listed in group 0, but rs274 lets them share a line with another
# group-0 code (G4, G10, G28, G92 ...) and runs them after it.
G_OFFSET_RESET = 16

# M-code modal groups (overview.adoc table "M-code Modal Groups").
M_STOP = 4
M_IO = 5
M_TOOL = 6
M_SPINDLE = 7
M_COOLANT = 8
M_OVERRIDE = 9
M_USER = 10
M_STATE = 11

G_CANCEL_MOTION = 800  # G80: gives way to another motion code on its line
G_MACHINE_COORDINATES = 530  # G53: modifies the line's motion
G_NURBS_END = 53  # G5.3: ends a G5.2 NURBS block; the motion mode after it is none (rs274's -1)

# Steps of the order of execution (overview.adoc, "G-code Order of Execution"); the words F, S
# and T and the comment have theirs too (WORD_STEPS).
STEP_COMMENT = 1
STEP_FEED_MODE = 2
STEP_FEED = 3
STEP_SPEED = 4
STEP_TOOL = 5
STEP_IO = 6
STEP_TOOL_CHANGE = 7
STEP_SPINDLE = 8
STEP_STATE = 9
STEP_COOLANT = 10
STEP_OVERRIDE = 11
STEP_USER_M = 12
STEP_DWELL = 13
STEP_PLANE = 14
STEP_UNITS = 15
STEP_LATHE = 16
STEP_CUTTER_COMP = 17
STEP_TOOL_LENGTH = 18
# G96 / G97 run right after the comment, before the feed mode (as rs274 runs them; the list's
# place for them is wrong): a step shared with the comment, which is planned first.
STEP_SPINDLE_MODE = STEP_COMMENT
STEP_COORD_SYSTEM = 20
STEP_CONTROL = 21
STEP_DISTANCE = 22
STEP_ARC_DISTANCE = 23
STEP_RETRACT = 24
STEP_NON_MODAL = 25
STEP_OFFSET_RESET = 26
STEP_MOTION = 27
STEP_STOP = 28

_ARC_WORDS = "ijkrp"
_AXES = "xyzabc"


def _motion(handler: str | None, uses: str = "") -> Code:
    return Code(G_MOTION, STEP_MOTION, handler, uses)


def _no(group: int, step: int, uses: str = "", comp_refusal: str = "") -> Code:
    """A code the language knows and ngc does not run yet."""
    return Code(group, step, None, uses, comp_refusal=comp_refusal)


def _no_motion(uses: str, comp_refusal: str) -> Code:
    """A motion ngc does not run yet that needs an axis word and is refused with compensation on."""
    return Code(G_MOTION, STEP_MOTION, None, uses, requires=_AXES,
                missing="All axes missing with motion code", comp_refusal=comp_refusal)


CYCLE_COMP = "Cannot use canned cycles with cutter compensation on"


def _cycle(handler: str | None, uses: str) -> Code:
    """A canned cycle: it needs an axis word, and no rotary one (see interp/check.py)."""
    return Code(G_MOTION, STEP_MOTION, handler, uses, requires=_AXES,
                missing="All axes missing with motion code", comp_refusal=CYCLE_COMP, cycle=True)
SPLINE_COMP = "Cannot convert spline with cutter radius compensation"


def _spline(handler: str, uses: str) -> Code:
    """G5 / G5.1: a motion that needs an axis word and is refused with compensation on."""
    return Code(G_MOTION, STEP_MOTION, handler, uses, requires=_AXES,
                missing="All axes missing with motion code", comp_refusal=SPLINE_COMP)


_PROBE_COMP = "Cannot probe with cutter radius comp on"


def _probe() -> Code:
    """G38.2-G38.5 straight probes (interp/handlers/probe.py); polar words count as axis words."""
    return Code(G_MOTION, STEP_MOTION, "probe", requires=_AXES + "@^",
                missing="All axes missing with motion code", comp_refusal=_PROBE_COMP)


WAIT_COMP = "Cannot wait for digital input with cutter radius compensation on"


def _io(uses: str, what: str, handler: str) -> Code:
    return Code(M_IO, STEP_IO, handler, uses,
                comp_refusal=f"Cannot {what} with cutter radius compensation on")


_G: dict[int, Code] = {
    # group 0: non-modal
    40: Code(G_NON_MODAL, STEP_DWELL, "dwell", "p", requires="p", missing="Dwell time missing with g4"),
    100: Code(G_NON_MODAL, STEP_NON_MODAL, "g10", "ijklpqr", axes=True),
    280: Code(G_NON_MODAL, STEP_NON_MODAL, "home", axes=True),
    281: Code(G_NON_MODAL, STEP_NON_MODAL, "home_store"),
    300: Code(G_NON_MODAL, STEP_NON_MODAL, "home", axes=True),
    301: Code(G_NON_MODAL, STEP_NON_MODAL, "home_store"),
    520: Code(G_NON_MODAL, STEP_NON_MODAL, "g52", axes=True, requires=_AXES,
              missing="All axes missing with g52 or g92"),
    530: Code(G_NON_MODAL, STEP_MOTION, ""),  # G53: read by the motion handlers
    920: Code(G_NON_MODAL, STEP_NON_MODAL, "g92", axes=True, requires=_AXES,
              missing="All axes missing with g52 or g92"),
    921: Code(G_OFFSET_RESET, STEP_OFFSET_RESET, "g92_reset"),
    922: Code(G_OFFSET_RESET, STEP_OFFSET_RESET, "g92_reset"),
    923: Code(G_OFFSET_RESET, STEP_OFFSET_RESET, "g92_reset"),
    # group 1: motion
    0: _motion("traverse"),
    10: _motion("feed"),
    20: _motion("arc", _ARC_WORDS),
    30: _motion("arc", _ARC_WORDS),
    50: _spline("cubic_spline", "ijpq"),  # G5 cubic spline
    51: _spline("quadratic_spline", "ij"),  # G5.1 quadratic spline
    52: _motion("nurbs", "pl"),  # G5.2 NURBS block: its lines, the control points
    53: _motion("nurbs_end"),  # G5.3 ends it (checked as if not on its line: see interp/check.py)
    330: Code(G_MOTION, STEP_MOTION, "sync_feed", "k$", requires=_AXES,  # G33
              missing="All axes missing with motion code"),
    331: Code(G_MOTION, STEP_MOTION, "rigid_tap", "ik$", requires=_AXES,  # G33.1 rigid tap
              missing="All axes missing with motion code"),
    382: _probe(),
    383: _probe(),
    384: _probe(),
    385: _probe(),
    730: _cycle("chip_break", "rlq"),
    740: _cycle("tap_left", "rp"),  # no L: rs274 refuses it with G74
    760: Code(G_MOTION, STEP_MOTION, "threading_cycle", "ijklpqrhe$", requires=_AXES,  # G76
              missing="All axes missing with motion code"),
    700: _motion("lathe_cycle", "qdep"),  # G70 lathe finishing cycle
    710: _motion("lathe_cycle", "qdir"),  # G71, G71.1, G71.2 lathe roughing cycles
    711: _motion("lathe_cycle", "qdir"),
    712: _motion("lathe_cycle", "qdir"),
    720: _motion("lathe_cycle", "qdir"),  # G72, G72.1, G72.2 lathe facing cycles
    721: _motion("lathe_cycle", "qdir"),
    722: _motion("lathe_cycle", "qdir"),
    800: _motion("cancel_motion"),
    810: _cycle("drill", "rl"),
    820: _cycle("drill_dwell", "rlp"),
    830: _cycle("peck", "rlq"),
    840: _cycle("tap", "rlp"),
    850: _cycle("bore", "rl"),
    860: _cycle("bore_stop", "rlp"),
    870: _cycle("back_bore", "rlijk"),
    880: _cycle("bore_manual", "rlp"),
    890: _cycle("bore_dwell", "rlp"),
    # group 2: plane
    170: Code(G_PLANE, STEP_PLANE, "plane"),
    171: Code(G_PLANE, STEP_PLANE, "plane"),
    180: Code(G_PLANE, STEP_PLANE, "plane"),
    181: Code(G_PLANE, STEP_PLANE, "plane"),
    190: Code(G_PLANE, STEP_PLANE, "plane"),
    191: Code(G_PLANE, STEP_PLANE, "plane"),
    # group 3 / 4: distance modes
    900: Code(G_DISTANCE, STEP_DISTANCE, "distance_mode"),
    910: Code(G_DISTANCE, STEP_DISTANCE, "distance_mode"),
    901: Code(G_ARC_DISTANCE, STEP_ARC_DISTANCE, "arc_distance_mode"),
    911: Code(G_ARC_DISTANCE, STEP_ARC_DISTANCE, "arc_distance_mode"),
    # group 5: feed mode
    930: Code(G_FEED_MODE, STEP_FEED_MODE, "feed_mode"),
    940: Code(G_FEED_MODE, STEP_FEED_MODE, "feed_mode"),
    950: Code(G_FEED_MODE, STEP_FEED_MODE, "feed_mode"),
    # group 6: units
    200: Code(G_UNITS, STEP_UNITS, "units"),
    210: Code(G_UNITS, STEP_UNITS, "units"),
    # group 7: cutter radius compensation
    400: Code(G_CUTTER_COMP, STEP_CUTTER_COMP, "cutter_comp_off"),
    410: Code(G_CUTTER_COMP, STEP_CUTTER_COMP, "cutter_comp", "dl"),
    411: Code(G_CUTTER_COMP, STEP_CUTTER_COMP, "cutter_comp_dynamic", "dl"),
    420: Code(G_CUTTER_COMP, STEP_CUTTER_COMP, "cutter_comp", "dl"),
    421: Code(G_CUTTER_COMP, STEP_CUTTER_COMP, "cutter_comp_dynamic", "dl"),
    # group 8: tool length offset
    430: Code(G_TOOL_LENGTH, STEP_TOOL_LENGTH, "tool_length", "h"),
    # G43.1 / G43.2 take the line's axis words (an explicit motion code on the line uses them
    # too; the modal motion does not run).
    431: Code(G_TOOL_LENGTH, STEP_TOOL_LENGTH, "tool_length", axes=True),
    432: Code(G_TOOL_LENGTH, STEP_TOOL_LENGTH, "tool_length", "h", axes=True),
    490: Code(G_TOOL_LENGTH, STEP_TOOL_LENGTH, "tool_length_off"),
    # group 10: canned-cycle return mode
    980: Code(G_RETRACT, STEP_RETRACT, "retract_mode"),
    990: Code(G_RETRACT, STEP_RETRACT, "retract_mode"),
    # group 12: coordinate system
    540: Code(G_COORD_SYSTEM, STEP_COORD_SYSTEM, "select_system"),
    550: Code(G_COORD_SYSTEM, STEP_COORD_SYSTEM, "select_system"),
    560: Code(G_COORD_SYSTEM, STEP_COORD_SYSTEM, "select_system"),
    570: Code(G_COORD_SYSTEM, STEP_COORD_SYSTEM, "select_system"),
    580: Code(G_COORD_SYSTEM, STEP_COORD_SYSTEM, "select_system"),
    590: Code(G_COORD_SYSTEM, STEP_COORD_SYSTEM, "select_system"),
    591: Code(G_COORD_SYSTEM, STEP_COORD_SYSTEM, "select_system"),
    592: Code(G_COORD_SYSTEM, STEP_COORD_SYSTEM, "select_system"),
    593: Code(G_COORD_SYSTEM, STEP_COORD_SYSTEM, "select_system"),
    # group 13: path control
    610: Code(G_CONTROL, STEP_CONTROL, "control_mode"),
    611: Code(G_CONTROL, STEP_CONTROL, "control_mode"),
    640: Code(G_CONTROL, STEP_CONTROL, "control_mode", "pq"),
    # group 14: spindle speed mode
    960: Code(G_SPINDLE_MODE, STEP_SPINDLE_MODE, "speed_mode", "d$", requires="s",
              missing="S word missing with G96"),
    970: Code(G_SPINDLE_MODE, STEP_SPINDLE_MODE, "speed_mode"),  # G97: the mode rs274 starts in
    # group 15: lathe diameter / radius mode
    70: Code(G_LATHE, STEP_LATHE, "lathe_mode"),
    80: Code(G_LATHE, STEP_LATHE, "lathe_mode"),
}

M_USER_LAST = 199

_M: dict[int, Code] = {
    0: Code(M_STOP, STEP_STOP, "stop"),
    1: Code(M_STOP, STEP_STOP, "stop"),
    2: Code(M_STOP, STEP_STOP, "stop"),
    30: Code(M_STOP, STEP_STOP, "stop"),
    60: Code(M_STOP, STEP_STOP, "stop"),
    3: Code(M_SPINDLE, STEP_SPINDLE, "spindle", "$"),
    4: Code(M_SPINDLE, STEP_SPINDLE, "spindle", "$"),
    5: Code(M_SPINDLE, STEP_SPINDLE, "spindle", "$"),
    19: Code(M_SPINDLE, STEP_SPINDLE, "orient", "rpq$"),
    6: Code(M_TOOL, STEP_TOOL_CHANGE, "change_tool"),
    61: Code(M_TOOL, STEP_TOOL_CHANGE, "set_tool_number", "q"),
    7: Code(M_COOLANT, STEP_COOLANT, "coolant"),
    8: Code(M_COOLANT, STEP_COOLANT, "coolant"),
    9: Code(M_COOLANT, STEP_COOLANT, "coolant"),
    48: Code(M_OVERRIDE, STEP_OVERRIDE, "overrides"),
    49: Code(M_OVERRIDE, STEP_OVERRIDE, "overrides"),
    50: Code(M_OVERRIDE, STEP_OVERRIDE, "overrides", "p"),
    51: Code(M_OVERRIDE, STEP_OVERRIDE, "overrides", "p$"),
    52: Code(M_OVERRIDE, STEP_OVERRIDE, "overrides", "p"),
    53: Code(M_OVERRIDE, STEP_OVERRIDE, "overrides", "p"),
    62: _io("p", "set motion output", "output_bit"),
    63: _io("p", "set motion digital output", "output_bit"),
    64: _io("p", "set auxiliary digital output", "output_bit"),
    65: _io("p", "set auxiliary digital output", "output_bit"),
    66: Code(M_IO, STEP_IO, "wait_input", "plqe", comp_refusal=WAIT_COMP),
    67: _io("eq", "set motion analog output", "output_value"),
    68: _io("eq", "set auxiliary analog output", "output_value"),
    70: Code(M_STATE, STEP_STATE, "modal_state"),
    71: Code(M_STATE, STEP_STATE, "modal_state"),
    72: Code(M_STATE, STEP_STATE, "modal_state"),
    73: Code(M_STATE, STEP_STATE, "modal_state"),
    98: Code(M_USER, STEP_USER_M, "subprogram", "pl"),  # run by the control flow
    99: Code(M_USER, STEP_USER_M, "subprogram"),
    # M100-M199: user M codes, read as codes of their group; with no user M file they fail at
    # their step (after the line's comment, F and S have run)
    **{code: Code(M_USER, STEP_USER_M, "user_m", "pq") for code in range(100, M_USER_LAST + 1)},
}

# The words that take a step of their own (and a handler), as codes do.
WORD_STEPS: Mapping[str, tuple[int, str | None]] = MappingProxyType({
    "f": (STEP_FEED, "feed_rate"),
    "s": (STEP_SPEED, "spindle_speed"),
    "t": (STEP_TOOL, "select_tool"),
})

# A word that no code on its line gives a use to: rs274's message, in the order rs274 checks.
UNUSED_WORD_MESSAGES: tuple[tuple[str, str], ...] = (
    ("d", "D word with no G41, G41.1, G42, G42.1, G71, G71.1, G71.2 or G96 to use it"),
    ("$", "$ (spindle selection) word with no M3, M4, M5, M19, M51, G33, G33.1, G76, G95, G96 or "
          "G97 to use it"),
    ("e", "E word with no G70, G76, M66, M67 or M68 to use it"),
    ("h", "H word with no G43 or G76 to use it"),
    ("i", "I word with no G2, G3, G5, G5.1, G10, G33.1, G76, or G87 to use it"),
    ("j", "J word with no G2, G3, G5, G5.1, G10, G76 or G87 to use it"),
    ("k", "K word with no G2, G3, G33, G33.1, G76, or G87 to use it"),
    ("l", "L word with no G10, cutter compensation, canned cycle, digital/analog input, M98 or "
          "NURBS code"),
    ("p", "P word with no G2 G3 G4 G10 G64 G5 G5.2 G76 G82 G86 G88 G89 or M50 M51 M52 M53 M62 M63 "
          "M64 M65 M66 M98 or user M code to use it"),
    ("q", "Q word with no G5, G10, G64, G73, G76, G83, M19, M66, M67, M68 or user M code that "
          "uses it"),
    ("r", "R word with no g code that uses it"),
)

AXIS_LETTERS = _AXES

# Polar coordinate words: distance @ and angle ^ in the XY plane (overview.adoc, "Polar
# Coordinates").
POLAR_LETTERS = "@^"

# Letters that every block may carry without a code that uses them.
FREE_LETTERS = frozenset(AXIS_LETTERS + "fs")


class CodeTable:
    """A dialect's G and M codes, and what is derived from them once."""

    __slots__ = ("axis_users", "g", "g_by_value", "m", "modal_axis_users")

    def __init__(self, g: Mapping[int, Code], m: Mapping[int, Code]) -> None:
        self.g = MappingProxyType(dict(g))
        self.m = MappingProxyType(dict(m))
        # Every G code by its value as read (1.0 -> (group, 10)), for the common exact values.
        self.g_by_value: Mapping[float, tuple[int, int]] = MappingProxyType(
            {code / 10: (row.group, code) for code, row in g.items()}
        )
        self.axis_users = frozenset(code for code, row in g.items()
                                    if row.axes and row.group == G_NON_MODAL)
        # Modal codes that take the line's axis words (G43.1, G43.2): no modal motion runs.
        self.modal_axis_users = frozenset(code for code, row in g.items()
                                          if row.axes and row.group != G_NON_MODAL)


LINUXCNC = CodeTable(_G, _M)


def g_name(code: int) -> str:
    """``G2`` / ``G38.2`` from the integer form (G number times ten)."""
    whole, tenth = divmod(code, 10)
    return f"G{whole}.{tenth}" if tenth else f"G{whole}"
