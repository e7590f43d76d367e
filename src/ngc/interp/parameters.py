"""Numbered, named and predefined parameters (overview.adoc, "Parameters").

Numbered parameters live in one array; lengths stored by the interpreter in system parameters
(offsets, G28/G30 positions) are in inches, rs274's user units, whatever the program units.
Named parameters are local (``#<name>``, per call frame) or global (``#<_name>``).  The predefined
read-only names (``#<_x>``, ``#<_metric>``, ...) and the position parameters 5420-5428 are computed
from the interpreter state when read.
"""

from __future__ import annotations

from collections.abc import Callable

from ..config.ini import Ini, ini_parameter
from ..config.tooltable import ToolEntry
from ..errors import NgcRuntimeError
from ..language.codes import G_NURBS_END
from ..language.parser import MAX_PARAMETER
from .frames import to_machine
from .state import AXES, State

# System parameter numbers (overview.adoc, "Numbered Parameters").
G28_HOME = 5161
G30_HOME = 5181
G92_APPLIED = 5210
G92_OFFSET = 5211
COORD_SYSTEM = 5220
G54_ORIGIN = 5221  # G54 X; each system takes 20 numbers, rotation at +9
COORD_STRIDE = 20
CURRENT_POSITION = 5420
TOOL_DATA = 5400  # 5400 tool number, 5401-5409 offsets, 5410 diameter, 5411-5413 angles, orientation
DEBUG_ENABLE = 5599  # 0 silences (DEBUG,...) comments
# Tool-changer fault parameters: rs274 accepts the setting and keeps 0.
IGNORED_WRITES = frozenset({5600, 5601})

Getter = Callable[[State], float]
# Named parameters that read the INI file: #<_ini[section]name>.
INI_PREFIX = "_ini["


def _flag(attr: str, value: object) -> Getter:
    return lambda s: 1.0 if getattr(s, attr) == value else 0.0


def _pos(axis: int) -> Getter:
    return lambda s: s.pos[axis]


def _machine(s: State, axis: int) -> float:
    return to_machine(s, s.pos, rotary=True)[axis]


# Predefined read-only named parameters (overview.adoc, "Predefined Named Parameters").
PREDEFINED: dict[str, Getter] = {
    "_vmajor": lambda s: 2.9,
    "_vminor": lambda s: 0.0,
    "_line": lambda s: float(s.line),
    # (after G5.3 the mode is none: rs274 reads -1)
    "_motion_mode": lambda s: -1.0 if s.motion == G_NURBS_END else float(s.motion),
    "_plane": lambda s: float(s.plane),
    "_ccomp": lambda s: float(s.ccomp),
    "_metric": _flag("metric", True),
    "_imperial": _flag("metric", False),
    "_absolute": _flag("absolute", True),
    "_incremental": _flag("absolute", False),
    "_inverse_time": _flag("feed_mode", 930),
    "_units_per_minute": _flag("feed_mode", 940),
    "_units_per_rev": _flag("feed_mode", 950),
    "_coord_system": lambda s: float(530 + 10 * s.coord_index if s.coord_index <= 6 else 584 + s.coord_index),
    "_tool_offset": lambda s: 1.0 if any(s.tlo) else 0.0,  # an offset not all zero in effect
    "_retract_r_plane": _flag("retract_r", True),
    "_retract_old_z": _flag("retract_r", False),
    "_spindle_rpm_mode": lambda s: 1.0,
    "_spindle_css_mode": lambda s: 0.0,
    "_ijk_absolute_mode": _flag("arc_absolute", True),
    "_lathe_diameter_mode": _flag("lathe_diameter", True),
    "_lathe_radius_mode": _flag("lathe_diameter", False),
    "_spindle_on": lambda s: 1.0 if s.spindle != 0 else 0.0,
    "_spindle_cw": lambda s: 1.0 if s.spindle == 1 else 0.0,
    "_mist": _flag("mist", True),
    "_flood": _flag("flood", True),
    "_speed_override": _flag("speed_override", True),
    "_feed_override": _flag("feed_override", True),
    "_adaptive_feed": _flag("adaptive_feed", True),
    "_feed_hold": _flag("feed_hold", True),
    "_feed": lambda s: s.feed,
    "_rpm": lambda s: s.speed,
    "_x": _pos(0),
    "_y": _pos(1),
    "_z": _pos(2),
    "_a": _pos(3),
    "_b": _pos(4),
    "_c": _pos(5),
    "_abs_x": lambda s: _machine(s, 0),
    "_abs_y": lambda s: _machine(s, 1),
    "_abs_z": lambda s: _machine(s, 2),
    "_abs_a": lambda s: _machine(s, 3),
    "_abs_b": lambda s: _machine(s, 4),
    "_abs_c": lambda s: _machine(s, 5),
    "_u": lambda s: 0.0,
    "_v": lambda s: 0.0,
    "_w": lambda s: 0.0,
    "_current_tool": lambda s: float(s.tools.spindle.number),
    "_current_pocket": lambda s: float(s.tools.pocket(s.tool_index)),
    "_selected_tool": lambda s: float(s.selected_tool),
    "_selected_pocket": lambda s: float(s.tools.pocket(s.selected_index) or -1),  # P0: -1
    "_value": lambda s: s.value,
    "_value_returned": lambda s: s.value_returned,
    "_task": lambda s: 0.0,
    "_call_level": lambda s: float(s.call_level),
    "_remap_level": lambda s: 0.0,
}


class Parameters:
    """All parameters of one interpreter; the expression context (``num``/``named``/``exists``)."""

    __slots__ = ("globals", "ini", "locals", "numbered", "state")

    def __init__(self, state: State) -> None:
        self.state = state
        self.numbered = [0.0] * (MAX_PARAMETER + 1)
        self.numbered[DEBUG_ENABLE] = 1.0
        self.globals: dict[str, float] = {}
        self.locals: list[dict[str, float]] = [{}]
        # The INI file behind ``#<_ini[section]name>`` (rs274 -i), if any.
        self.ini: Ini | None = None

    # -- reading (expression context) ---------------------------------------------------------
    def num(self, index: int) -> float:
        if index < TOOL_DATA:
            return self.numbered[index]  # no parameter below the tool data is computed
        if CURRENT_POSITION <= index < CURRENT_POSITION + 9 and self.state.ccomp != 400:
            raise NgcRuntimeError("Cannot read current position with cutter radius compensation on")
        return self.shown(index)

    def shown(self, index: int) -> float:
        """A numbered parameter as a comment shows it (the position even with compensation on)."""
        if CURRENT_POSITION <= index < CURRENT_POSITION + 9:
            axis = index - CURRENT_POSITION
            return self.state.pos[axis] if axis < AXES else 0.0
        if TOOL_DATA <= index < TOOL_DATA + 14:
            return tool_parameter(self.state.tools.spindle, index - TOOL_DATA)
        return self.numbered[index]

    def named(self, name: str) -> float:
        if name[:1] != "_":
            value = self.locals[-1].get(name)
        else:
            getter = PREDEFINED.get(name)
            if getter is not None:
                return getter(self.state)
            value = self.globals.get(name)
            if value is None and name.startswith(INI_PREFIX):
                value = ini_parameter(self.ini, name)
        if value is None:
            raise NgcRuntimeError(f"Named parameter #<{name}> not defined")
        return value

    def local(self, name: str) -> float:
        value = self.locals[-1].get(name)
        if value is None:
            raise NgcRuntimeError(f"Named parameter #<{name}> not defined")
        return value

    def exists(self, name: str) -> bool:
        if name.startswith("_"):
            if name.startswith(INI_PREFIX) and name not in self.globals:
                return ini_parameter(self.ini, name) is not None
            return name in PREDEFINED or name in self.globals
        return name in self.locals[-1]

    def index(self, value: float) -> int:
        return int(value)

    # -- writing ------------------------------------------------------------------------------
    def declare(self, name: str) -> None:
        """A named parameter exists (reading 0) from the moment its setting is read (rs274).

        An INI value (``#<_ini[section]name>`` that the INI file defines) is read-only.
        """
        if name.startswith(INI_PREFIX) and ini_parameter(self.ini, name) is not None:
            raise NgcRuntimeError(f"Cannot assign to read-only parameter #<{name}>")
        scope = self.globals if name.startswith("_") else self.locals[-1]
        scope.setdefault(name, 0.0)

    def assign(self, target: int | str, value: float) -> None:
        """Set a numbered or named parameter (the queued settings of a block)."""
        if isinstance(target, int):
            if target not in IGNORED_WRITES:
                self.numbered[target] = value
        elif target.startswith("_"):
            self.globals[target] = value
        else:
            self.locals[-1][target] = value



def tool_parameter(entry: ToolEntry, k: int) -> float:
    """#5400+k of the tool in the spindle: number, offsets X..W, diameter, front angle, back
    angle, orientation (inches, as the table holds them); all 0 for tool 0, even when the
    table gives tool 0 data (a line ``T0`` without P)."""
    if k == 0 or entry.number == 0:
        return float(entry.number)
    if k <= 9:
        return entry.offsets[k - 1]
    return (entry.diameter, entry.frontangle, entry.backangle, float(entry.orientation))[k - 10]


def check_writable(name: str) -> None:
    """Predefined named parameters are read-only."""
    if name in PREDEFINED:
        raise NgcRuntimeError(f"Cannot assign to read-only parameter #<{name}>")
