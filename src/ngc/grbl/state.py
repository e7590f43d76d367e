"""Grbl's parser state, and a checked block carried out on it in check mode (``gc_execute_line``,
step 4): the modes, the feed rate, the position and the offsets change; nothing moves.

Positions and offsets are in millimetres in machine coordinates, single-precision values as
Grbl keeps them.  Check mode (``$C``) differs from a run in three places: a probe move ends at
its target (it touches nothing); M2 and M30 reset the modes, G54 among them, but leave the work
offset that was loaded (a run loads G54's); M0 does not pause.
"""

from __future__ import annotations

from .codes import (
    ABSOLUTE,
    AXIS_MOTION,
    COMPLETED,
    COOLANT,
    COOLANT_OFF,
    COORD_SYSTEM,
    DISTANCE,
    FEED_MODE,
    GO_HOME_0,
    GO_HOME_1,
    LINEAR,
    MOTION,
    MOTION_NONE,
    NON_MODAL,
    PLANE,
    PLANE_XY,
    POWER_UP_MODES,
    PROBES,
    PROGRAM_FLOW,
    RESET_COORDINATE_OFFSET,
    RUNNING,
    SET_COORDINATE_DATA,
    SET_COORDINATE_OFFSET,
    SET_HOME_0,
    SET_HOME_1,
    SPINDLE,
    SPINDLE_OFF,
    UNITS_PER_MINUTE,
)
from .rules import Rules


class GrblState:
    """Grbl's parser state at power-up, as check mode starts from it (``$C`` after a reset):
    G0 G54 G17 G21 G90 G94 M5 M9, no feed rate, at the machine origin, with every stored
    position zero: the work offsets G54-G59 and G28/G30 (stored in EEPROM and kept over a reset;
    taken as zero), G92 and the tool length offset.

    ``modes``: motion, feed mode, units, distance, plane, tool length, coordinate system,
    program flow, coolant, spindle (the slots of :mod:`ngc.grbl.codes`).  ``stored``: the work
    offsets of G54-G59, then the positions of G28 and G30.
    """

    __slots__ = ("coord_offset", "coord_system", "feed_rate", "modes", "position", "spindle_speed",
                 "stored", "tool_length_offset")

    def __init__(self, rules: Rules) -> None:
        axes = len(rules.axes)
        self.modes = list(POWER_UP_MODES)
        self.feed_rate = 0.0  # mm/min, or the inverse time of the last block under G93
        self.spindle_speed = 0.0
        self.position = [0.0] * axes
        self.stored = [[0.0] * axes for _ in range(rules.coordinate_systems + 2)]
        self.coord_system = list(self.stored[0])  # the offset of the system in use
        self.coord_offset = [0.0] * axes  # G92
        self.tool_length_offset = [0.0] * axes  # G43.1, by axis (Grbl: on its one axis)


def home_index(rules: Rules, code: int) -> int:
    """Where G28 (``GO_HOME_0``, ``SET_HOME_0``) or G30 keep their position in ``stored``."""
    return rules.coordinate_systems + (0 if code in (GO_HOME_0, SET_HOME_0) else 1)


class Plan:
    """A block that passed every check, with what its checks worked out: the feed rate and
    spindle speed it leaves, its axis command, the offset of its coordinate system, its
    ``target`` (machine mm; the new G92 offset for G92; the axis words in mm for G43.1), and
    ``data``: a G10's new work offset (for system ``data_index``) or the position G28/G30 go to;
    ``tool_length``: the tool length offsets a G43.1 or G49 leaves (None: the block has neither).
    """

    __slots__ = ("axis_command", "coord_system", "data", "data_index", "feed_rate", "modes",
                 "spindle_speed", "target", "tool_length")

    def __init__(self, modes: list[int], axis_command: int, coord_system: list[float]) -> None:
        self.modes = modes
        self.axis_command = axis_command
        self.coord_system = coord_system
        self.feed_rate = 0.0
        self.spindle_speed = 0.0
        self.target: list[float] = []
        self.data: list[float] = []
        self.data_index = 0
        self.tool_length: list[float] | None = None  # the offsets a G43.1 or G49 leaves


def execute(plan: Plan, state: GrblState, rules: Rules) -> None:
    """Carry out a checked block in check mode, in Grbl's order of execution."""
    modes = plan.modes
    state.feed_rate = plan.feed_rate
    state.spindle_speed = plan.spindle_speed
    if plan.tool_length is not None:
        state.tool_length_offset = plan.tool_length
    state.coord_system = plan.coord_system
    state.modes = modes[:NON_MODAL]
    state.modes[PROGRAM_FLOW] = RUNNING
    _non_modal(plan, state, rules)
    motion = modes[MOTION]
    if (motion != MOTION_NONE and plan.axis_command == AXIS_MOTION
            and not (motion in PROBES and rules.probe_to_start)):
        state.position = plan.target
    if modes[PROGRAM_FLOW] == COMPLETED:
        _program_end(state)


def _non_modal(plan: Plan, state: GrblState, rules: Rules) -> None:
    """G10, G28/G30 (and .1), G92 and G92.1."""
    command = plan.modes[NON_MODAL]
    if command == SET_COORDINATE_DATA:
        state.stored[plan.data_index] = plan.data
        if state.modes[COORD_SYSTEM] == plan.data_index:
            state.coord_system = list(plan.data)
    elif command in (GO_HOME_0, GO_HOME_1):
        state.position = plan.data
    elif command in (SET_HOME_0, SET_HOME_1):
        state.stored[home_index(rules, command)] = list(state.position)
    elif command == SET_COORDINATE_OFFSET:
        state.coord_offset = plan.target
    elif command == RESET_COORDINATE_OFFSET:
        state.coord_offset = [0.0] * len(state.coord_offset)


def _program_end(state: GrblState) -> None:
    """M2, M30: the modes LinuxCNC resets (gcode.c), not the units, the tool length offset or,
    in check mode, the offset of the coordinate system loaded."""
    modes = state.modes
    modes[MOTION] = LINEAR
    modes[PLANE] = PLANE_XY
    modes[DISTANCE] = ABSOLUTE
    modes[FEED_MODE] = UNITS_PER_MINUTE
    modes[COORD_SYSTEM] = 0
    modes[SPINDLE] = SPINDLE_OFF
    modes[COOLANT] = COOLANT_OFF
