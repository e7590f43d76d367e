"""Program <-> machine coordinates: the G92/G52 offset, the XY rotation and the G5x origin
and the tool length offset (coordinates.adoc).  Pure functions of the :class:`~ngc.interp.state.State`."""

from __future__ import annotations

import math
from collections.abc import Sequence

from ..config.tooltable import length_from_program, length_to_program
from .state import AXES, LINEAR, State

Vec = list[float]
_NO_TLO = (0.0,) * AXES


def to_machine(st: State, prog: Vec, tlo: bool = True, rotary: bool = False) -> Vec:
    """Program coordinates -> machine coordinates (G92 offset, XY rotation, G5x origin, tool
    length offset of X Y Z; ``tlo=False``: without the tool length offset).

    ``rotary``: with the rotary axes' tool length offset too, which rs274 adds where it reads a
    machine position (G28.1/G30.1, #<_abs_a>, G10 L10/L11) though :func:`to_program` does not
    take it off; not where it goes there and back (G54-G59.3)."""
    p = [prog[i] + st.g92[i] for i in range(AXES)]
    if st.rotation:
        p[0], p[1] = rotate(p[0], p[1], st.rotation)
    t = st.tlo if tlo else _NO_TLO
    return [p[i] + st.g5x[i] + (t[i] if i < 3 or rotary else 0.0) for i in range(AXES)]


def to_program(st: State, machine: Vec, tlo: Sequence[float] | None = None) -> Vec:
    """Machine coordinates -> program coordinates (``tlo``: with that tool length offset instead
    of the one in effect).  rs274 takes the tool length offset off X Y Z only (the rotary axes'
    offset counts only in :func:`to_machine` with ``rotary``)."""
    t = st.tlo if tlo is None else tlo
    p = [machine[i] - st.g5x[i] - (t[i] if i < 3 else 0.0) for i in range(AXES)]
    # Rotated even by 0 degrees: rs274 does, which decides the sign of a zero (G53 X-0).
    p[0], p[1] = rotate(p[0], p[1], -st.rotation)
    return [p[i] - st.g92[i] for i in range(AXES)]


def machine_target(st: State, prog: Vec, given: dict[int, float]) -> Vec:
    """The program point of a G53 move: the axes ``given`` (index -> value) are machine
    coordinates, the others stay.

    As rs274 computes it, to the last bit: an axis given loses the G5x origin and the tool
    length offset, then (X and Y turned back by the rotation) the G92 offset; X and Y not given
    get the G92 offset and the rotation and lose them again (which may move them by a last bit
    or change the sign of a zero), the other axes not given stay as they are."""
    t = st.tlo
    out = list(prog)
    for i, v in given.items():
        if i > 1:
            out[i] = v - st.g5x[i] - (t[i] if i < 3 else 0.0) - st.g92[i]
    x, y = rotate(prog[0] + st.g92[0], prog[1] + st.g92[1], st.rotation)
    if 0 in given:
        x = given[0] - st.g5x[0] - t[0]
    if 1 in given:
        y = given[1] - st.g5x[1] - t[1]
    x, y = rotate(x, y, -st.rotation)
    out[0], out[1] = x - st.g92[0], y - st.g92[1]
    return out


def rotate(x: float, y: float, degrees: float) -> tuple[float, float]:
    t = math.radians(degrees)
    c, s = math.cos(t), math.sin(t)
    return x * c - y * s, x * s + y * c


def from_parameters(st: State, values: Sequence[float]) -> Vec:
    """Axis values as parameters keep them (origins, offsets, home positions: lengths in inches,
    through rs274's inch-per-mm factor, as tool lengths) in program units."""
    metric = st.metric
    return [length_to_program(v, metric) if LINEAR[i] else v for i, v in enumerate(values)]


def to_parameter(st: State, axis: int, value: float) -> float:
    """An axis value in program units as a parameter keeps it (see :func:`from_parameters`)."""
    return length_from_program(value, st.metric) if LINEAR[axis] else value
