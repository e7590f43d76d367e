"""Program coordinates to machine coordinates: the one place that applies units, the G5x work
offset, the G92 (and G52) offset, the XY rotation and the tool length offset.

Canon speaks program units and program coordinates (as rs274 prints it); ``SET_G5X_OFFSET``,
``SET_G92_OFFSET``, ``SET_XY_ROTATION``, ``USE_TOOL_LENGTH_OFFSET`` and ``USE_LENGTH_UNITS`` say
how they relate to the machine (``coordinates.adoc``, "Coordinate Systems"):

    machine = rotate(program + G92) + G5x + tool length offset

with X Y Z scaled from program to machine units and A B C (degrees in every unit system) as
they are.  An offset is given in the program units in effect when it is set and kept here in
machine units: a later change of units leaves the physical offset where it was.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

Pos = tuple[float, float, float, float, float, float]

MM_PER_INCH = 25.4
ZERO6: Pos = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)


class Frame:
    """The relation between program and machine coordinates, as canon last set it.

    ``scale`` turns program units into machine units; ``g5x``, ``g92`` and ``tlo`` are in
    machine units; ``rotation`` in degrees about Z (G10 L2 R).  ``identity`` says a program
    point is its machine point (no offsets, no rotation, the same units), the common case that
    :meth:`to_machine` skips."""

    __slots__ = ("cos_r", "g5x", "g92", "identity", "inch_machine", "inch_program",
                 "rotation", "scale", "shift", "sin_r", "tlo")

    def __init__(self, inch_machine: bool = False) -> None:
        self.inch_machine = inch_machine
        self.inch_program = inch_machine
        self.scale = 1.0
        self.g5x: Pos = ZERO6
        self.g92: Pos = ZERO6
        self.tlo: Pos = ZERO6
        self.rotation = 0.0
        self.cos_r, self.sin_r = 1.0, 0.0
        self.shift: Pos = ZERO6  # g5x + g92 + tlo, used when there is no rotation
        self.identity = True

    def copy(self) -> Frame:
        """A frame the same as this one now."""
        frame = Frame.__new__(Frame)
        for name in Frame.__slots__:
            setattr(frame, name, getattr(self, name))
        return frame

    # -- what canon sets ----------------------------------------------------------------------
    def set_units(self, inch: bool) -> None:
        """``USE_LENGTH_UNITS``: the program's units from now on."""
        self.inch_program = inch
        if inch == self.inch_machine:
            self.scale = 1.0
        else:
            self.scale = MM_PER_INCH if inch else 1.0 / MM_PER_INCH
        self._changed()

    def machine_units(self, values: Sequence[float]) -> Pos:
        """An offset given in program units, in machine units."""
        s = self.scale
        return (values[0] * s, values[1] * s, values[2] * s, values[3], values[4], values[5])

    def set_g5x(self, values: Sequence[float]) -> None:
        self.g5x = self.machine_units(values)
        self._changed()

    def set_g92(self, values: Sequence[float]) -> None:
        self.g92 = self.machine_units(values)
        self._changed()

    def set_tool_offset(self, values: Sequence[float]) -> None:
        self.tlo = self.machine_units(values)
        self._changed()

    def set_rotation(self, degrees: float) -> None:
        self.rotation = degrees
        rad = math.radians(degrees)
        self.cos_r, self.sin_r = math.cos(rad), math.sin(rad)
        self._changed()

    def _changed(self) -> None:
        g5, g9, t = self.g5x, self.g92, self.tlo
        self.shift = (g5[0] + g9[0] + t[0], g5[1] + g9[1] + t[1], g5[2] + g9[2] + t[2],
                      g5[3] + g9[3] + t[3], g5[4] + g9[4] + t[4], g5[5] + g9[5] + t[5])
        self.identity = self.scale == 1.0 and not self.rotation and not any(self.shift)

    # -- points -------------------------------------------------------------------------------
    def to_machine(self, p: Sequence[float]) -> Pos:
        """A point in program units and coordinates (x y z a b c), in machine ones."""
        s = self.scale
        if not self.rotation:
            o = self.shift
            return (p[0] * s + o[0], p[1] * s + o[1], p[2] * s + o[2], p[3] + o[3],
                    p[4] + o[4], p[5] + o[5])
        g5, g9, t = self.g5x, self.g92, self.tlo
        x = p[0] * s + g9[0]
        y = p[1] * s + g9[1]
        x, y = x * self.cos_r - y * self.sin_r, x * self.sin_r + y * self.cos_r
        return (x + g5[0] + t[0], y + g5[1] + t[1], p[2] * s + g9[2] + g5[2] + t[2],
                p[3] + g9[3] + g5[3] + t[3], p[4] + g9[4] + g5[4] + t[4],
                p[5] + g9[5] + g5[5] + t[5])

    def to_program(self, m: Sequence[float]) -> Pos:
        """A machine point in program units and coordinates (the inverse of
        :meth:`to_machine`)."""
        if self.identity:
            return (m[0], m[1], m[2], m[3], m[4], m[5])
        s = self.scale
        g5, g9, t = self.g5x, self.g92, self.tlo
        x, y = m[0] - g5[0] - t[0], m[1] - g5[1] - t[1]
        if self.rotation:
            x, y = x * self.cos_r + y * self.sin_r, -x * self.sin_r + y * self.cos_r
        return ((x - g9[0]) / s, (y - g9[1]) / s, (m[2] - g5[2] - t[2] - g9[2]) / s,
                m[3] - g5[3] - t[3] - g9[3], m[4] - g5[4] - t[4] - g9[4],
                m[5] - g5[5] - t[5] - g9[5])

    def turn(self, v: tuple[float, float, float]) -> tuple[float, float, float]:
        """A direction (an arc's normal) turned by the XY rotation."""
        if not self.rotation:
            return v
        c, s = self.cos_r, self.sin_r
        return (v[0] * c - v[1] * s, v[0] * s + v[1] * c, v[2])
