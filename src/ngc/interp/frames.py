"""Program <-> machine coordinates: the G92/G52 offset, the XY rotation and the G5x origin
(coordinates.adoc).  Pure functions of the :class:`~ngc.interp.state.State`."""

from __future__ import annotations

import math

from .state import AXES, State

Vec = list[float]


def to_machine(st: State, prog: Vec) -> Vec:
    """Program coordinates -> machine coordinates (G92 offset, XY rotation, G5x origin)."""
    p = [prog[i] + st.g92[i] for i in range(AXES)]
    if st.rotation:
        p[0], p[1] = rotate(p[0], p[1], st.rotation)
    return [p[i] + st.g5x[i] for i in range(AXES)]


def to_program(st: State, machine: Vec) -> Vec:
    """Machine coordinates -> program coordinates."""
    p = [machine[i] - st.g5x[i] for i in range(AXES)]
    # Rotated even by 0 degrees: rs274 does, which decides the sign of a zero (G53 X-0).
    p[0], p[1] = rotate(p[0], p[1], -st.rotation)
    return [p[i] - st.g92[i] for i in range(AXES)]


def rotate(x: float, y: float, degrees: float) -> tuple[float, float]:
    t = math.radians(degrees)
    c, s = math.cos(t), math.sin(t)
    return x * c - y * s, x * s + y * c
