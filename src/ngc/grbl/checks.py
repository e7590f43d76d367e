"""Checking a block read by :mod:`ngc.grbl.block` against Grbl's parser state, as Grbl's parser
does (``gc_execute_line``, step 3, in its order): the first rule broken rejects the line.

Along the way the values are worked out as Grbl works them out, in single precision: inches to
millimetres, the target in machine coordinates (work offset, G92, tool length offset, or the
position for G91), a G10's new offset, the position G28/G30 go to; the arc checks need them.
"""

from __future__ import annotations

import math
import struct

from .block import Block, NotChecked, Rejected
from .codes import (
    ABSOLUTE,
    ABSOLUTE_OVERRIDE,
    ARC_RADIUS_ERROR,
    AXIS_MOTION,
    AXIS_NON_MODAL,
    AXIS_NONE,
    AXIS_TOOL_LENGTH,
    AXIS_WORDS_EXIST,
    CCW_ARC,
    COMMAND_VALUE_NOT_INTEGER,
    COORD_SYSTEM,
    CW_ARC,
    DISTANCE,
    DWELL,
    FEED_MODE,
    G43_DYNAMIC_AXIS_ERROR,
    G53_INVALID_MOTION_MODE,
    GO_HOME_0,
    GO_HOME_1,
    GROUP_COORD_SYSTEM,
    GROUP_TOOL_LENGTH,
    INCHES,
    INVALID_LINE_NUMBER,
    INVALID_TARGET,
    INVERSE_TIME,
    LENGTH_CANCEL,
    LINEAR,
    MOTION,
    MOTION_NONE,
    NEGATIVE_VALUE,
    NO_AXIS_WORDS,
    NO_AXIS_WORDS_IN_PLANE,
    NO_OFFSETS_IN_PLANE,
    NON_MODAL,
    PLANE,
    SEEK,
    SET_COORDINATE_DATA,
    SET_COORDINATE_OFFSET,
    TOOL_LENGTH,
    UNDEFINED_FEED_RATE,
    UNITS,
    UNITS_PER_MINUTE,
    UNSUPPORTED_COMMAND,
    UNSUPPORTED_COORD_SYS,
    UNUSED_WORDS,
    VALUE_OUT_OF_RANGE,
    VALUE_WORD_MISSING,
    word_bits,
)
from .numbers import MM_PER_INCH, add, arm_unsigned, c_unsigned, f32, hypot
from .rules import Rules
from .state import GrblState, Plan, home_index

# arc end radius tolerances (gcode.c): the radius from the centre to the end may differ from
# the one to the start by 0.005 mm, or by 0.1% of it up to 0.5 mm; float constants on the AVR
ARC_ABSOLUTE_MM = f32(0.005)
ARC_MOST_MM = f32(0.5)
ARC_RELATIVE = f32(0.001)
# grblHAL's isintf (nuts_bolts.c): a value within 0.001 of its whole part is whole
WHOLE_WITHIN = f32(0.001)

# the first and second axis of an arc, by plane (PLANE_XY G17: X Y, PLANE_ZX G18: Z X,
# PLANE_YZ G19: Y Z)
PLANE_AXES = ((0, 1), (2, 0), (1, 2))


class Check:
    """The checks of one build (:class:`Rules`): its word bits and axes, worked out once."""

    def __init__(self, rules: Rules) -> None:
        self.rules = rules
        bits = word_bits(rules.axes, rules.extra_words)
        self.bits = bits
        self.axes = tuple(enumerate(rules.axes))
        self.axis_bits = sum(bits[a] for a in rules.axes)
        # the axes a tool length offset applies to, and the axis words G43.1 must have
        # exactly (0: any, at least one)
        if rules.tool_length_axis:
            self.length_axes = frozenset({rules.axes.index(rules.tool_length_axis)})
            self.length_words = 1 << rules.axes.index(rules.tool_length_axis)
        else:
            self.length_axes, self.length_words = frozenset(range(len(rules.axes))), 0
        self.always_used = bits["N"] | bits["F"] | bits["S"] | bits["T"]
        self.same = struct.Struct(f"<{len(rules.axes)}f").pack

    def block(self, block: Block, state: GrblState) -> Plan:
        """The block checked against ``state``, as a :class:`Plan`; raises :class:`Rejected`.
        In Grbl's order (its numbers in ``gcode.c``): line number [0], feed rate [2, 3],
        spindle speed [4], dwell [10], units [12], G43.1 [14], coordinate system [15], the
        non-modal commands [19], the motion [20], the words left unused [0].  A block with a
        code or word no check models raises :class:`NotChecked`."""
        if block.unchecked:
            raise NotChecked(block.unchecked)
        modes = block.modes
        axis_command = block.axis_command
        if block.axis_words and axis_command == AXIS_NONE:
            axis_command = AXIS_MOTION  # axis words alone: the motion mode uses them
        plan = Plan(modes, axis_command, state.coord_system)
        unused = block.value_words
        self._line_number(block)
        plan.feed_rate = _feed_rate(block, state, axis_command)
        plan.spindle_speed = block.values.get("S", state.spindle_speed)
        if modes[NON_MODAL] == DWELL:
            unused = self._used(block, unused, "P")
            _not_negative_p(block)
        xyz = self._axis_values(block)
        self._tool_length(block, state, plan, xyz)
        if (block.command_words & (1 << GROUP_COORD_SYSTEM)
                and state.modes[COORD_SYSTEM] != modes[COORD_SYSTEM]):
            plan.coord_system = list(state.stored[modes[COORD_SYSTEM]])
        if modes[NON_MODAL] == SET_COORDINATE_DATA:
            unused = self._set_coordinate_data(block, state, plan, xyz, unused)
        elif modes[NON_MODAL] == SET_COORDINATE_OFFSET:
            self._set_offset(block, state, plan, xyz)
        else:
            self._target(block, state, plan, xyz)
        unused = self._motion(block, state, plan, unused)
        unused &= ~self.always_used
        if plan.axis_command != AXIS_NONE:
            unused &= ~self.axis_bits
        if unused:
            raise Rejected(UNUSED_WORDS)
        return plan

    def _used(self, block: Block, unused: int, letter: str) -> int:
        """A value word a command needs: error 28 without it; else it is used."""
        if letter not in block.values:
            raise Rejected(VALUE_WORD_MISSING)
        return unused & ~self.bits[letter]

    def _line_number(self, block: Block) -> None:
        number = block.values.get("N")
        if number is not None and not number < self.rules.max_line_number + 1:
            raise Rejected(INVALID_LINE_NUMBER)

    def _axis_values(self, block: Block) -> list[float]:
        """The axis words in millimetres (0 for an axis not given)."""
        values = block.values
        inches = block.modes[UNITS] == INCHES
        xyz = [0.0] * len(self.axes)
        for n, letter in self.axes:
            value = values.get(letter)
            if value is not None:
                xyz[n] = f32(value * MM_PER_INCH) if inches else value
        return xyz

    def _tool_length(self, block: Block, state: GrblState, plan: Plan,
                     xyz: list[float]) -> None:
        """G43.1 takes exactly one axis word, the tool length axis's (error 37), or with any
        axis (grblHAL's TOOL_LENGTH_OFFSET_AXIS -1) at least one; the offsets a G43.1 or G49
        leaves (``plan.tool_length``: G43.1 sets the axes given, G49 clears all)."""
        if not block.command_words & (1 << GROUP_TOOL_LENGTH):
            return
        if block.modes[TOOL_LENGTH] == LENGTH_CANCEL:
            plan.tool_length = [0.0] * len(xyz)
            return
        words = block.axis_words
        if (words != self.length_words) if self.length_words else not words:
            raise Rejected(G43_DYNAMIC_AXIS_ERROR)
        plan.tool_length = [xyz[n] if words & (1 << n) else offset
                            for n, offset in enumerate(state.tool_length_offset)]

    def _set_coordinate_data(self, block: Block, state: GrblState, plan: Plan,
                             xyz: list[float], unused: int) -> int:
        """G10 L2 / L20 P0-P6: axis words (26), P or L (28: only when both are missing), P up
        to the number of systems (29; P0 is the system in use), L 2 or 20 (20), no R with L2
        (20); the new offset in ``plan.data``."""
        values = block.values
        l_value = c_unsigned(values.get("L", 0.0), 8)
        hal = self.rules.g10_hal_order
        if not block.axis_words and not (hal and l_value != 20 and "R" in values):
            raise Rejected(NO_AXIS_WORDS)
        if "P" not in values and "L" not in values:
            raise Rejected(VALUE_WORD_MISSING)
        _not_negative_p(block)
        index = c_unsigned(values.get("P", 0.0), 8)
        if hal:
            _g10_l(l_value, values)
        if index > self.rules.coordinate_systems:
            raise Rejected(UNSUPPORTED_COORD_SYS)
        _g10_l(l_value, values)
        index = index - 1 if index > 0 else block.modes[COORD_SYSTEM]
        data = list(state.stored[index])
        for n, _ in self.axes:
            if block.axis_words & (1 << n):
                if l_value == 20:  # the offset that makes the current position the value given
                    data[n] = f32(f32(state.position[n] - state.coord_offset[n]) - xyz[n])
                    if n in self.length_axes:
                        data[n] = f32(data[n] - state.tool_length_offset[n])
                else:
                    data[n] = xyz[n]
        plan.data, plan.data_index = data, index
        return unused & ~(self.bits["L"] | self.bits["P"])

    def _set_offset(self, block: Block, state: GrblState, plan: Plan, xyz: list[float]) -> None:
        """G92: axis words (26); the new G92 offset in ``plan.target``."""
        if not block.axis_words:
            raise Rejected(NO_AXIS_WORDS)
        offset = list(state.coord_offset)
        for n, _ in self.axes:
            if block.axis_words & (1 << n):
                offset[n] = f32(f32(state.position[n] - plan.coord_system[n]) - xyz[n])
                if n in self.length_axes:
                    offset[n] = f32(offset[n] - state.tool_length_offset[n])
        plan.target = offset

    def _target(self, block: Block, state: GrblState, plan: Plan, xyz: list[float]) -> None:
        """The target in machine coordinates; G28/G30's position (``plan.data``); G53 only
        with G0 or G1 (30)."""
        command = block.modes[NON_MODAL]
        plan.target = xyz
        if plan.axis_command != AXIS_TOOL_LENGTH and block.axis_words:
            plan.target = self._machine_target(block, state, plan.coord_system, xyz)
        if command in (GO_HOME_0, GO_HOME_1):
            plan.data = list(state.stored[home_index(self.rules, command)])
            if block.axis_words:  # only the axes given go home, through the target
                for n, _ in self.axes:
                    if not block.axis_words & (1 << n):
                        plan.data[n] = state.position[n]
            else:
                plan.axis_command = AXIS_NONE
        elif command == ABSOLUTE_OVERRIDE and block.modes[MOTION] not in (SEEK, LINEAR):
            raise Rejected(G53_INVALID_MOTION_MODE)

    def _machine_target(self, block: Block, state: GrblState, system: list[float],
                        xyz: list[float]) -> list[float]:
        position = state.position
        absolute = block.modes[DISTANCE] == ABSOLUTE
        override = block.modes[NON_MODAL] == ABSOLUTE_OVERRIDE
        target = list(position)
        for n, _ in self.axes:
            if not block.axis_words & (1 << n):
                continue
            if override:  # G53: machine coordinates as given
                target[n] = xyz[n]
            elif absolute:
                target[n] = add(xyz[n], add(system[n], state.coord_offset[n]))
                if n in self.length_axes:
                    target[n] = add(target[n], state.tool_length_offset[n])
            else:
                target[n] = add(xyz[n], position[n])
        return target

    def _motion(self, block: Block, state: GrblState, plan: Plan, unused: int) -> int:
        """The motion mode: no axis words under G80 (31), a feed rate for all but G0 (22), the
        arc and probe checks."""
        motion = block.modes[MOTION]
        if motion == MOTION_NONE:
            if block.axis_words and not (self.rules.g80_non_modal_axes
                                         and plan.axis_command == AXIS_NON_MODAL):
                raise Rejected(AXIS_WORDS_EXIST)
        elif plan.axis_command == AXIS_MOTION:
            if motion in (SEEK, LINEAR) and not block.axis_words:
                plan.axis_command = AXIS_NONE  # (after G1's feed rate check)
            if motion != SEEK and plan.feed_rate == 0.0:
                raise Rejected(UNDEFINED_FEED_RATE)
            if motion in (CW_ARC, CCW_ARC):
                return self._arc(block, state, plan, unused)
            if motion != SEEK and motion != LINEAR:
                self._probe(block, state, plan)
        return unused

    def _arc(self, block: Block, state: GrblState, plan: Plan, unused: int) -> int:
        """G2/G3: axis words (26), one in the plane (32); then by radius or by centre."""
        if not block.axis_words:
            raise Rejected(NO_AXIS_WORDS)
        first, second = PLANE_AXES[block.modes[PLANE]]
        if not block.axis_words & ((1 << first) | (1 << second)):
            raise Rejected(NO_AXIS_WORDS_IN_PLANE)
        if self.rules.arc_turns and "P" in block.values:
            _turns(block.values["P"])
            unused &= ~self.bits["P"]
        position, target = state.position, plan.target
        x = f32(target[first] - position[first])
        y = f32(target[second] - position[second])
        if "R" in block.values:
            self._radius_arc(block, state, plan, x, y)
            return unused & ~self.bits["R"]
        _centre_arc(block, first, second, x, y)
        return unused & ~(self.bits["I"] | self.bits["J"] | self.bits["K"])

    def _radius_arc(self, block: Block, state: GrblState, plan: Plan, x: float, y: float) -> None:
        """An arc by R: a target that is not the position (33; compared bit for bit, as Grbl
        compares them), a radius that reaches it (34: 4 r^2 < x^2 + y^2)."""
        if self.same(*state.position) == self.same(*plan.target):
            raise Rejected(INVALID_TARGET)
        radius = block.values["R"]
        if block.modes[UNITS] == INCHES:
            radius = f32(radius * MM_PER_INCH)
        squared = f32(f32(f32(4.0 * radius) * radius) - f32(x * x))
        if f32(squared - f32(y * y)) < 0.0:
            raise Rejected(ARC_RADIUS_ERROR)

    def _probe(self, block: Block, state: GrblState, plan: Plan) -> None:
        """G38.2-G38.5: axis words (26) and a target that is not the position (33)."""
        if not block.axis_words:
            raise Rejected(NO_AXIS_WORDS)
        if self.same(*state.position) == self.same(*plan.target):
            raise Rejected(INVALID_TARGET)


def _not_negative_p(block: Block) -> None:
    """G4's and G10's P may not be negative (error 4): grblHAL tests it here (its P may be
    negative as read); Grbl has rejected a negative P as it read it."""
    if block.values.get("P", 0.0) < 0.0:
        raise Rejected(NEGATIVE_VALUE)


def _g10_l(l_value: int, values: dict[str, float]) -> None:
    """G10's L: 2 (without R) or 20 (error 20)."""
    if l_value != 20 and (l_value != 2 or "R" in values):
        raise Rejected(UNSUPPORTED_COMMAND)


def _turns(p_value: float) -> None:
    """An arc's P, its turns (grblHAL): whole (error 23, by ``isintf``), and not 0 once made a
    32-bit unsigned integer (error 39; a negative P is 0 on an ARM)."""
    if not abs(f32(p_value - math.trunc(p_value))) < WHOLE_WITHIN:
        raise Rejected(COMMAND_VALUE_NOT_INTEGER)
    if arm_unsigned(p_value) == 0:
        raise Rejected(VALUE_OUT_OF_RANGE)


def _feed_rate(block: Block, state: GrblState, axis_command: int) -> float:
    """The feed rate of the block: under G93, its F (a motion but G0 without one is error 22);
    under G94 after G94, its F in mm/min or the one before; after a switch from G93 to G94,
    its F or none (0: undefined)."""
    modes = block.modes
    feed = block.values.get("F")
    if modes[FEED_MODE] == INVERSE_TIME:
        if feed is None and axis_command == AXIS_MOTION and modes[MOTION] not in (MOTION_NONE,
                                                                                  SEEK):
            raise Rejected(UNDEFINED_FEED_RATE)
    elif state.modes[FEED_MODE] == UNITS_PER_MINUTE:
        if feed is None:
            return state.feed_rate
        if modes[UNITS] == INCHES:
            return f32(feed * MM_PER_INCH)
    return 0.0 if feed is None else feed


def _centre_arc(block: Block, first: int, second: int, x: float, y: float) -> None:
    """An arc by I J K: an offset in the plane (35); the radius to the end within 0.005 mm of
    the radius to the start, or past that within 0.1% of it and 0.5 mm (33)."""
    values = block.values
    if not block.offset_words & ((1 << first) | (1 << second)):
        raise Rejected(NO_OFFSETS_IN_PLANE)
    centre = [values.get(letter, 0.0) for letter in ("IJK"[first], "IJK"[second])]
    if block.modes[UNITS] == INCHES:
        centre = [f32(v * MM_PER_INCH) for v in centre]
    end_radius = hypot(f32(x - centre[0]), f32(y - centre[1]))
    radius = hypot(centre[0], centre[1])
    delta = abs(f32(end_radius - radius))
    if delta > ARC_ABSOLUTE_MM and (delta > ARC_MOST_MM or delta > f32(ARC_RELATIVE * radius)):
        raise Rejected(INVALID_TARGET)

