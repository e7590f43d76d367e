"""Coordinate systems and offsets: G54-G59.3, G10 L2/L20, G52, G92/G92.1/G92.2/G92.3, G28/G30
and their .1 forms, and the program <-> machine conversions G53 needs (coordinates.adoc).

The canon is told offsets and rotation (SET_G5X_OFFSET, SET_G92_OFFSET, SET_XY_ROTATION) and is
given positions in program coordinates; the interpreter keeps the current point in program
coordinates and recomputes it whenever an offset changes.  Offsets stored in parameters are in
inches (rs274's user units); rotary axes are never converted.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ...canon import ops
from ...errors import NgcSemanticError
from ...language.codes import AXIS_LETTERS
from ..frames import Vec, from_parameters, rotate, to_machine, to_parameter, to_program
from ..parameters import (
    COORD_STRIDE,
    G28_HOME,
    G30_HOME,
    G54_ORIGIN,
    G92_APPLIED,
    G92_OFFSET,
)
from ..state import AXES
from . import tools

if TYPE_CHECKING:
    from ..machine import Machine
    from ..resolve import Resolved

# -- conversions ------------------------------------------------------------------------------------
def _axis_words(r: Resolved) -> list[tuple[int, float]]:
    w = r.w
    return [(i, w[a]) for i, a in enumerate(AXIS_LETTERS) if a in w]


# -- emitting ---------------------------------------------------------------------------------------
def emit_g5x(it: Machine) -> None:
    st = it.state
    it.emit(ops.SetG5xOffset(st.coord_index, *st.g5x))


def emit_g92(it: Machine) -> None:
    it.emit(ops.SetG92Offset(*it.state.g92))


def emit_rotation(it: Machine) -> None:
    it.emit(ops.SetXYRotation(it.state.rotation))


def _keep_machine_position(it: Machine) -> Vec:
    return to_machine(it.state, it.state.pos, rotary=True)


# -- coordinate system selection ----------------------------------------------------------------
def load_system(it: Machine, index: int) -> None:
    """Make G54+index-1 the active origin from its parameters."""
    st = it.state
    base = G54_ORIGIN + COORD_STRIDE * (index - 1)
    numbered = it.params.numbered
    st.coord_index = index
    st.g5x = from_parameters(st, numbered[base:base + AXES])
    st.rotation = numbered[base + 9]


def _stored_g92(it: Machine) -> Vec:
    """The G92 offsets #5211-#5216 hold, in program units."""
    st = it.state
    return from_parameters(st, it.params.numbered[G92_OFFSET:G92_OFFSET + AXES])


def load_g92(it: Machine) -> None:
    """The G92 offsets from their parameters when #5210 says they apply (a parameter file)."""
    st = it.state
    st.g92_applied = it.params.numbered[G92_APPLIED] != 0.0
    if st.g92_applied:
        st.g92 = _stored_g92(it)


def select_system(it: Machine, code: int) -> None:
    """G54..G59.3."""
    index = code // 10 - 53 if code < 591 else code - 584
    st = it.state
    if index == st.coord_index:
        it.emit(ops.Comment("interpreter: continuing to use same coordinate system"))
        return
    machine = to_machine(st, st.pos)
    tools.hold_canon(st)
    load_system(it, index)
    it.params.numbered[5220] = float(index)
    # rs274 takes the G92 offset off as its parameters hold it (through inches); the offset
    # itself stays as it was
    offset = st.g92
    if st.g92_applied:
        st.g92 = _stored_g92(it)
    st.pos = to_program(st, machine)
    st.g92 = offset
    tools.held(st)
    emit_g5x(it)
    emit_g92(it)
    emit_rotation(it)


# -- G10 ----------------------------------------------------------------------------------------
def g10(it: Machine, r: Resolved) -> None:
    """G10 L2 P: set an origin; G10 L20 P: set it so the current point has the given coordinates;
    L0, L1, L10, L11: the tool table (:func:`tools.g10_tools`).  (L and P were checked before
    the line ran.)"""
    st = it.state
    w = r.w
    l_word = int(w["l"])
    if l_word not in (2, 20):
        tools.g10_tools(it, r, l_word)
        return
    p = w["p"]
    if "i" in w or "j" in w:
        raise NgcSemanticError(f"I J words not allowed with G10 L{l_word}")
    if l_word == 20 and "r" in w:
        raise NgcSemanticError("R not allowed in G10 L20")
    index = int(p) or st.coord_index
    base = G54_ORIGIN + COORD_STRIDE * (index - 1)
    numbered = it.params.numbered
    values = {i: v for i, v in _axis_words(r)}
    if l_word == 20:
        values = _l20_origin(it, values, index)
    for i, v in values.items():
        numbered[base + i] = to_parameter(st, i, v)
    if "r" in r.w:
        numbered[base + 9] = r.w["r"]
    if index != st.coord_index:
        it.emit(ops.Comment("interpreter: setting coordinate system origin"))
        return
    # rs274 carries the current point over to the new origin and rotation as if there were no
    # G92/G52 offset (with one, the machine position does not stay put).
    x, y = rotate(st.pos[0], st.pos[1], st.rotation) if st.rotation else (st.pos[0], st.pos[1])
    point = [x, y, *st.pos[2:]]
    old = st.g5x
    tools.hold_canon(st)
    load_system(it, index)
    # rs274 takes the axes the line sets as they are, in program units; the others come back
    # from their parameters (inches), which a value in inches does not always survive exactly
    # (G20 G10 L2 P1 X-0.27835 Z1 then G10 L2 P1 Z2: X -0.2783, then -0.2784).
    for i, v in values.items():
        st.g5x[i] = v
    point = [point[i] + old[i] - st.g5x[i] for i in range(AXES)]
    if st.rotation:
        point[0], point[1] = rotate(point[0], point[1], -st.rotation)
    st.pos = point
    tools.held(st)
    emit_g5x(it)
    emit_rotation(it)


def _l20_origin(it: Machine, values: dict[int, float], index: int) -> dict[int, float]:
    """Origins that make the current machine position read ``values`` in system ``index``.

    rs274 finds the current point in that system from the system's origin and the G92/G52
    offset as their parameters hold them (through inches: a value in inches may come back a
    little off), then moves the origin by the difference: ``(origin + point) - value``, in that
    order, which decides the last bit.  X and Y are set so always, those not given to keep their
    current coordinate (which moves their origin by a last bit now and then); other axes only
    when given.
    """
    st = it.state
    machine = to_machine(st, st.pos, tlo=False)  # the origin is set without the tool offset
    base = G54_ORIGIN + COORD_STRIDE * (index - 1)
    numbered = it.params.numbered
    rot = numbered[base + 9]
    origin = from_parameters(st, numbered[base:base + AXES])
    offset = _stored_g92(it) if st.g92_applied else [0.0] * AXES
    here = [machine[i] - origin[i] - offset[i] for i in range(AXES)]
    # X and Y are set again always (those not given to their current coordinate), the others
    # when given
    out = {i: (origin[i] + here[i]) - v for i, v in values.items() if i > 1}
    point = (here[0], here[1])
    there = (values.get(0, point[0]), values.get(1, point[1]))
    if rot:
        # the same in the rotated system: (origin + rotated point) - rotated new point
        x, y = rotate(machine[0] - origin[0], machine[1] - origin[1], -rot)
        point = (x - offset[0], y - offset[1])
        there = rotate(values.get(0, point[0]), values.get(1, point[1]), rot)
        point = rotate(*point, rot)
    out[0], out[1] = (origin[0] + point[0]) - there[0], (origin[1] + point[1]) - there[1]
    return out


# -- G92 / G52 ----------------------------------------------------------------------------------
def _store_g92(it: Machine) -> None:
    st = it.state
    numbered = it.params.numbered
    for i in range(AXES):
        numbered[G92_OFFSET + i] = to_parameter(st, i, st.g92[i])


def g92(it: Machine, r: Resolved) -> None:
    """G92: offsets so the current point has the given coordinates."""
    st = it.state
    for i, v in _axis_words(r):  # at least one (checked before the line ran)
        st.g92[i] = st.pos[i] + st.g92[i] - v
        st.pos[i] = v
    _offset_changed(it)


def g52(it: Machine, r: Resolved) -> None:
    """G52: local offset given directly (shares G92's offset)."""
    st = it.state
    for i, v in _axis_words(r):  # at least one (checked before the line ran)
        st.pos[i] += st.g92[i] - v
        st.g92[i] = v
    _offset_changed(it)


def _offset_changed(it: Machine) -> None:
    """G52 / G92 set the offset: flag it, store it (#5210-#5216) and tell the canon."""
    _applied(it, True)
    _store_g92(it)
    emit_g92(it)


def _applied(it: Machine, on: bool) -> None:
    it.state.g92_applied = on
    it.params.numbered[G92_APPLIED] = 1.0 if on else 0.0


def g92_reset(it: Machine, code: int) -> None:
    """G92.1 clear offsets and parameters, G92.2 clear offsets, G92.3 restore from parameters."""
    st = it.state
    numbered = it.params.numbered
    if code == 923:
        new = _stored_g92(it)
        _applied(it, True)
    else:
        new = [0.0] * AXES
        _applied(it, False)
        if code == 921:
            for i in range(AXES):
                numbered[G92_OFFSET + i] = 0.0
    for i in range(AXES):  # (point + old) - new, in that order (G52 is point + (old - new))
        st.pos[i] = (st.pos[i] + st.g92[i]) - new[i]
    st.g92 = new
    emit_g92(it)


# -- G28 / G30 ----------------------------------------------------------------------------------
def home_store(it: Machine, code: int) -> None:
    """G28.1 / G30.1: store the current machine position."""
    st = it.state
    base = G28_HOME if code == 281 else G30_HOME
    machine = _keep_machine_position(it)
    for i in range(AXES):
        it.params.numbered[base + i] = to_parameter(st, i, machine[i])


def home_targets(it: Machine, code: int, r: Resolved) -> tuple[Vec, Vec]:
    """G28 / G30: the intermediate point and the end point, in program coordinates.

    rs274 first moves to the point the axis words give (the current point without them), then
    sets the given axes (all axes without axis words) to the stored position, in program
    coordinates.
    """
    st = it.state
    base = G28_HOME if code == 280 else G30_HOME
    numbered = it.params.numbered
    words = _axis_words(r)
    home = to_program(st, from_parameters(st, numbered[base:base + AXES]))
    middle = list(st.pos)
    for i, v in words:
        middle[i] = v if st.absolute else st.pos[i] + v
    if not words:
        return middle, home
    target = list(middle)
    for i, _v in words:
        target[i] = home[i]
    return middle, target
