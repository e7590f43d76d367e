"""Loading the machine a program is timed on: from LinuxCNC's INI file, from ngc's TOML machine
file, or both (the TOML file over the INI file's machine).  ``docs/machine.md`` documents both
formats key by key.

Every value is checked where it is read: a value that is not a number, a number outside the
key's range (:data:`RANGES`, listed in ``docs/machine.md``), an unknown key or a missing axis
limit raises :class:`NgcConfigError` with a message that names the file, the key, the value and
the range it must be in.  The ranges keep the planner's arithmetic finite: within them every
time it works out is a number.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import replace
from types import MappingProxyType
from typing import Any, NamedTuple, TypeVar

from ..config.ini import BLANKS, Ini, parse_int, parse_real
from ..config.tomlfile import read_toml
from ..config.units import UNITS_EXPECTED, linear_units
from ..config.units import read_linear_units as _linear_units
from ..errors import NgcConfigError
from .machine import ALL_AXES, DEFAULT_MACHINE, MAX_COORDINATE, AxisLimits, Machine

__all__ = ["load_machine", "machine_from_ini", "machine_from_toml"]

T = TypeVar("T")

NANOSECONDS_PER_SECOND = 1e9  # [EMCMOT]SERVO_PERIOD is in ns
# Boolean INI values (ini-config.adoc, "INI File Components": case-insensitive words).
INI_BOOLEANS = {"1": True, "TRUE": True, "YES": True, "ON": True,
                "0": False, "FALSE": False, "NO": False, "OFF": False}
LIMIT_KEYS = ("MAX_VELOCITY", "MAX_ACCELERATION")
AXIS_LIST = " ".join(ALL_AXES)
TOML_UNITS = ("mm", "inch")


class Range(NamedTuple):
    """The values a key accepts, both ends included."""

    low: float
    high: float
    integer: bool = False

    def holds(self, value: float) -> bool:
        return self.low <= value <= self.high  # (a NaN is not held)

    def text(self, unit: str = "") -> str:
        kind = "a whole number" if self.integer else "a number"
        unit = f" {unit}" if unit else ""
        return f"{kind} from {_decimal(self.low)} to {_decimal(self.high)}{unit}"


def _decimal(value: float) -> str:
    """``value`` written out in decimals (1000000, 0.000001), as a person types it."""
    if value == int(value):
        return str(int(value))
    return f"{value:.12f}".rstrip("0")


# The range of each kind of value, in machine units (degrees for A, B, C) and seconds.
VELOCITY = Range(1e-6, 1e6)  # units/s
ACCELERATION = Range(1e-6, 1e9)  # units/s²
PERIOD = Range(1e-6, 1.0)  # s: the servo period
CYCLE = Range(1e-6, 10.0)  # s: the task's and the I/O controller's cycle
STANDSTILL = Range(0.0, 1e6)  # s: a tool change, a spindle start or stop
DEPTH = Range(0, 1000, integer=True)  # moves: the planner's work grows with its look-ahead
GAP_CYCLES = Range(0.0, 1e6)  # servo periods
RAMP_FREQ = Range(1e-6, 1e6)  # Hz
KINK_RATIO = Range(0.0, 1e6)  # a share of the acceleration (above 0.999 it acts as 0.999)
POSITION = Range(-MAX_COORDINATE, MAX_COORDINATE)
NANOSECONDS = Range(1000, 1_000_000_000, integer=True)  # [EMCMOT]SERVO_PERIOD: PERIOD in ns
JOINTS = Range(1, 16, integer=True)  # [KINS]JOINTS (LinuxCNC's EMCMOT_MAX_JOINTS)
RANGES: Mapping[str, Range] = MappingProxyType({
    "max_velocity": VELOCITY, "max_acceleration": ACCELERATION,
    "max_linear_velocity": VELOCITY, "max_linear_acceleration": ACCELERATION,
    "servo_period": PERIOD, "task_cycle_time": CYCLE, "io_cycle_time": CYCLE,
    "tool_change_time": STANDSTILL, "spindle_start_time": STANDSTILL,
    "spindle_stop_time": STANDSTILL, "optimization_depth": DEPTH, "gap_cycles": GAP_CYCLES,
    "ramp_freq": RAMP_FREQ, "kink_ratio": KINK_RATIO, "start": POSITION,
})


# --- LinuxCNC's INI file -------------------------------------------------------------------------


def _real_in(limits: Range) -> Callable[[str], float | None]:
    """A converter: the INI value as a real number within ``limits``, else None."""
    def convert(text: str) -> float | None:
        value = parse_real(text)
        return value if value is not None and limits.holds(value) else None
    return convert


def _int_in(limits: Range) -> Callable[[str], int | None]:
    """A converter: the INI value as a whole number within ``limits``, else None."""
    def convert(text: str) -> int | None:
        value = parse_int(text)
        return value if value is not None and limits.holds(value) else None
    return convert


def _nanoseconds(text: str) -> float | None:
    value = _int_in(NANOSECONDS)(text)
    return None if value is None else value / NANOSECONDS_PER_SECOND


def _boolean(text: str) -> bool | None:
    return INI_BOOLEANS.get(text.strip(BLANKS).upper())


class IniKey(NamedTuple):
    """A value of the INI file: where it is, how it is read, and what it must be (for messages)."""

    section: str
    key: str
    convert: Callable[[str], object]  # the value, or None when the text is not one
    expected: str


def _ini_real(section: str, key: str, limits: Range, unit: str = "") -> IniKey:
    return IniKey(section, key, _real_in(limits), limits.text(unit))


BOOLEAN = "a boolean (1, 0, TRUE, FALSE, YES, NO, ON, OFF)"
# The Machine fields read from the INI file (the axes are read by _ini_axes).
INI_FIELDS: Mapping[str, IniKey] = MappingProxyType({
    "linear_units": IniKey("TRAJ", "LINEAR_UNITS", _linear_units, UNITS_EXPECTED),
    "max_linear_velocity": _ini_real("TRAJ", "MAX_LINEAR_VELOCITY", VELOCITY),
    "max_linear_acceleration": _ini_real("TRAJ", "MAX_LINEAR_ACCELERATION", ACCELERATION),
    "servo_period": IniKey("EMCMOT", "SERVO_PERIOD", _nanoseconds,
                           NANOSECONDS.text("nanoseconds")),
    "task_cycle": _ini_real("TASK", "CYCLE_TIME", CYCLE, "seconds"),
    "io_cycle": _ini_real("EMCIO", "CYCLE_TIME", CYCLE, "seconds"),
    "arc_blend_enable": IniKey("TRAJ", "ARC_BLEND_ENABLE", _boolean, BOOLEAN),
    "arc_blend_fallback_enable": IniKey("TRAJ", "ARC_BLEND_FALLBACK_ENABLE", _boolean, BOOLEAN),
    "arc_blend_optimization_depth": IniKey("TRAJ", "ARC_BLEND_OPTIMIZATION_DEPTH",
                                           _int_in(DEPTH), DEPTH.text()),
    "arc_blend_gap_cycles": _ini_real("TRAJ", "ARC_BLEND_GAP_CYCLES", GAP_CYCLES),
    "arc_blend_ramp_freq": _ini_real("TRAJ", "ARC_BLEND_RAMP_FREQ", RAMP_FREQ, "Hz"),
    "arc_blend_kink_ratio": _ini_real("TRAJ", "ARC_BLEND_KINK_RATIO", KINK_RATIO),
})


def _ini_error(ini: Ini, message: str) -> NgcConfigError:
    where = f"INI file {ini.path}" if ini.path else "INI file"
    return NgcConfigError(f"{where}: {message}", file=ini.path)


def _ini_value(ini: Ini, section: str, key: str, convert: Callable[[str], T | None],
               expected: str) -> T | None:
    """``[section]key`` converted, ``None`` when absent; a value ``convert`` refuses is an error."""
    text = ini.get(section, key)
    if text is None:
        return None
    value = convert(text)
    if value is None:
        raise _ini_error(ini, f"[{section}]{key} is '{text}', not {expected}")
    return value


def _letters(ini: Ini, section: str, key: str, text: str, letters: str) -> str:
    """Axis letters, blanks between them allowed, any case; anything else is an error."""
    found = "".join(letters.split()).upper()
    if not found or any(letter not in ALL_AXES for letter in found):
        raise _ini_error(ini, f"[{section}]{key} is '{text}', not axis letters ({AXIS_LIST})")
    return found


def _ini_coordinates(ini: Ini) -> str:
    """The axes: [TRAJ]COORDINATES (a letter may repeat, "X Y Y Z" for a gantry), or without it
    the axes that have an [AXIS_<letter>] section."""
    text = ini.get("TRAJ", "COORDINATES")
    if text is None:
        return "".join(axis for axis in ALL_AXES if ini.has_section(f"AXIS_{axis}"))
    return _letters(ini, "TRAJ", "COORDINATES", text, text)


def _kins_coordinates(ini: Ini) -> str | None:
    """The ``coordinates=`` parameter of [KINS]KINEMATICS (``trivkins coordinates=XZ``), if any."""
    text = ini.get("KINS", "KINEMATICS")
    for word in (text or "").split():
        name, _, value = word.partition("=")
        if name.lower() == "coordinates":
            return _letters(ini, "KINS", "KINEMATICS", text or "", value)
    return None


def _ini_joints(ini: Ini, coordinates: str) -> str:
    """The axis of each joint, joint 0 first.  Trivkins assigns joints in the order of its
    coordinates (ini-config.adoc, [TRAJ]COORDINATES; "coordinates=xz": joint 0 is X, joint 1 Z):
    the ``coordinates=`` of [KINS]KINEMATICS, else [TRAJ]COORDINATES; [KINS]JOINTS, when given,
    says how many of them there are."""
    order = _kins_coordinates(ini) or coordinates
    count = _ini_value(ini, "KINS", "JOINTS", _int_in(JOINTS), JOINTS.text())
    return order if count is None else order[:count]


def _limit_sections(axis: str, joints: str) -> list[str]:
    return [f"AXIS_{axis}", *(f"JOINT_{n}" for n, letter in enumerate(joints) if letter == axis)]


def _smallest(ini: Ini, sections: list[str], key: str) -> float | None:
    """The smallest ``key`` of the sections that set it: an axis is as slow as its slowest part."""
    limits = RANGES[key.lower()]
    values = [_ini_value(ini, section, key, _real_in(limits), limits.text())
              for section in sections]
    found = [value for value in values if value is not None]
    return min(found) if found else None


def _ini_axes(ini: Ini) -> Mapping[str, AxisLimits]:
    """Each axis's limits: the smaller of its [AXIS_<letter>] and its joints' [JOINT_<n>] values."""
    coordinates = _ini_coordinates(ini)
    joints = _ini_joints(ini, coordinates)
    sections = {axis: _limit_sections(axis, joints) for axis in ALL_AXES if axis in coordinates}
    found = {axis: [_smallest(ini, where, key) for key in LIMIT_KEYS]
             for axis, where in sections.items()}
    if not any(value is not None for limits in found.values() for value in limits):
        raise _ini_error(ini, "no axis limits: MAX_VELOCITY and MAX_ACCELERATION are set in "
                         f"no [AXIS_<letter>] or [JOINT_<n>] section of the axes "
                         f"({' '.join(coordinates) or 'none'})")
    axes: dict[str, AxisLimits] = {}
    for axis, (velocity, acceleration) in found.items():
        if velocity is None or acceleration is None:
            key = LIMIT_KEYS[0] if velocity is None else LIMIT_KEYS[1]
            where = " or ".join(f"[{section}]" for section in sections[axis])
            raise _ini_error(ini, f"axis {axis} has no {key} (in {where})")
        axes[axis] = AxisLimits(velocity, acceleration)
    return MappingProxyType(axes)


def machine_from_ini(ini: Ini) -> Machine:
    """The machine of a LinuxCNC INI file; keys it does not set keep :class:`Machine`'s defaults.

    The axes are those of [TRAJ]COORDINATES, each limited by the smaller of its [AXIS_<letter>]
    and its joints' [JOINT_<n>] MAX_VELOCITY and MAX_ACCELERATION; an INI file that sets no axis
    limits at all is an error.

    >>> ini = Ini.parse("[TRAJ]\\nCOORDINATES = X Z\\nLINEAR_UNITS = inch\\n"
    ...                 "[AXIS_X]\\nMAX_VELOCITY = 4\\nMAX_ACCELERATION = 30\\n"
    ...                 "[JOINT_1]\\nMAX_VELOCITY = 2\\nMAX_ACCELERATION = 20\\n"
    ...                 "[EMCMOT]\\nSERVO_PERIOD = 500000\\n")
    >>> machine = machine_from_ini(ini)
    >>> dict(machine.axes), machine.linear_units, machine.servo_period
    ({'X': AxisLimits(max_velocity=4.0, max_acceleration=30.0), \
'Z': AxisLimits(max_velocity=2.0, max_acceleration=20.0)}, 'inch', 0.0005)
    """
    fields: dict[str, Any] = {"axes": _ini_axes(ini), "travel": soft_limits(ini)}
    for name, spec in INI_FIELDS.items():
        value = _ini_value(ini, *spec)
        if value is not None:
            fields[name] = value
    return replace(DEFAULT_MACHINE, **fields)


# --- ngc's TOML machine file ---------------------------------------------------------------------


def _number(value: object, where: str, limits: Range) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float) or not limits.holds(value):
        raise ValueError(f"{where} must be {limits.text()}, not {value!r}")
    return float(value)


def _ranged(limits: Range) -> Check:
    """A check: a number (an integer for an integer range) within ``limits``."""
    def check(value: object, where: str) -> object:
        if limits.integer:
            return _count(value, where, limits)
        return _number(value, where, limits)
    return check


def _count(value: object, where: str, limits: Range) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or not limits.holds(value):
        raise ValueError(f"{where} must be {limits.text()}, not {value!r}")
    return value


def _flag(value: object, where: str) -> object:
    if not isinstance(value, bool):
        raise ValueError(f"{where} must be true or false, not {value!r}")
    return value


def _units(value: object, where: str) -> object:
    if value not in TOML_UNITS:
        raise ValueError(f"{where} must be \"mm\" or \"inch\", not {value!r}")
    return str(value)


Check = Callable[[object, str], object]

# Top-level keys: TOML key -> (Machine field, check).
TOML_SCALARS: Mapping[str, tuple[str, Check]] = MappingProxyType({
    "units": ("linear_units", _units),
    "max_linear_velocity": ("max_linear_velocity", _ranged(VELOCITY)),
    "max_linear_acceleration": ("max_linear_acceleration", _ranged(ACCELERATION)),
    "servo_period": ("servo_period", _ranged(PERIOD)),
    "task_cycle_time": ("task_cycle", _ranged(CYCLE)),
    "io_cycle_time": ("io_cycle", _ranged(CYCLE)),
    "tool_change_time": ("tool_change_time", _ranged(STANDSTILL)),
    "spindle_start_time": ("spindle_start_time", _ranged(STANDSTILL)),
    "spindle_stop_time": ("spindle_stop_time", _ranged(STANDSTILL)),
})
TOML_TABLES = ("coordinates", "axes", "blending", "start")
TOML_BLENDING: Mapping[str, tuple[str, Check]] = MappingProxyType({
    "enable": ("arc_blend_enable", _flag),
    "fallback_enable": ("arc_blend_fallback_enable", _flag),
    "optimization_depth": ("arc_blend_optimization_depth", _ranged(DEPTH)),
    "gap_cycles": ("arc_blend_gap_cycles", _ranged(GAP_CYCLES)),
    "ramp_freq": ("arc_blend_ramp_freq", _ranged(RAMP_FREQ)),
    "kink_ratio": ("arc_blend_kink_ratio", _ranged(KINK_RATIO)),
})
TOML_AXIS_KEYS = ("max_velocity", "max_acceleration", "travel")
TOML_AXIS_LIMITS = ("max_velocity", "max_acceleration")


def _unknown(where: str, key: str, allowed: tuple[str, ...] | Mapping[str, object]) -> ValueError:
    prefix = f"{where}: " if where else ""
    return ValueError(f"{prefix}unknown key '{key}' (allowed: {', '.join(allowed)})")


def _table(value: object, where: str) -> Mapping[str, object]:
    if not isinstance(value, dict):
        raise ValueError(f"{where} must be a table, not {value!r}")
    return value


def _axis_letter(name: str, where: str) -> str:
    if name not in ALL_AXES:
        raise ValueError(f"{where}: '{name}' is not an axis (allowed: {', '.join(ALL_AXES)})")
    return name


def _fields(data: Mapping[str, object], where: str,
            known: Mapping[str, tuple[str, Check]]) -> dict[str, Any]:
    """The Machine fields of a table whose keys all map to one field each."""
    fields: dict[str, Any] = {}
    for key, value in data.items():
        if key not in known:
            raise _unknown(where, key, known)
        name, check = known[key]
        fields[name] = check(value, f"{where}.{key}" if where else key)
    return fields


def _toml_axis(name: str, entry: object, base: AxisLimits | None) -> AxisLimits:
    """``[axes.<name>]``: a new axis needs both limits, an axis of ``base`` may change one."""
    where = f"axes.{name}"
    given: dict[str, float] = {}
    for key, value in _table(entry, where).items():
        if key not in TOML_AXIS_KEYS:
            raise _unknown(where, key, TOML_AXIS_KEYS)
        if key != "travel":  # (read by _travel)
            given[key] = _number(value, f"{where}.{key}", RANGES[key])
    if base is None and len(given) < len(TOML_AXIS_LIMITS):
        missing = ", ".join(key for key in TOML_AXIS_LIMITS if key not in given)
        raise ValueError(f"{where}: a new axis needs max_velocity and max_acceleration "
                         f"(missing: {missing})")
    if base is not None:
        given = {"max_velocity": base.max_velocity, "max_acceleration": base.max_acceleration,
                 **given}
    return AxisLimits(given["max_velocity"], given["max_acceleration"])


def _travel(data: Mapping[str, object], base: Mapping[str, tuple[float, float]],
            axes: Mapping[str, AxisLimits]) -> dict[str, tuple[float, float]]:
    """The axes' travel: ``base``'s (for axes that stay), with ``[axes.<letter>] travel = [min,
    max]`` over it."""
    travel = {axis: limits for axis, limits in base.items() if axis in axes}
    for name, entry in _table(data.get("axes", {}), "axes").items():
        if not isinstance(entry, dict) or "travel" not in entry:
            continue
        where = f"axes.{name}.travel"
        value = entry["travel"]
        if not isinstance(value, list) or len(value) != 2:
            raise ValueError(f"{where} must be [min, max], not {value!r}")
        low, high = (_number(v, where, POSITION) for v in value)
        if not low < high:
            raise ValueError(f"{where}: the minimum {low:g} is not below the maximum {high:g}")
        travel[name] = (low, high)
    return {axis: travel[axis] for axis in ALL_AXES if axis in travel}


def _coordinates(value: object) -> str:
    letters = "".join(value.split()) if isinstance(value, str) else ""
    if not letters or any(letter not in ALL_AXES for letter in letters):
        raise ValueError(f"coordinates must be axis letters ({AXIS_LIST}), not {value!r}")
    repeated = sorted({letter for letter in letters if letters.count(letter) > 1})
    if repeated:
        raise ValueError(f"coordinates names {', '.join(repeated)} more than once: {value!r}")
    return letters


def _toml_axes(data: Mapping[str, object], base: Mapping[str, AxisLimits]) -> dict[str, AxisLimits]:
    """The axes: ``base``'s, with ``[axes]`` entries replacing or adding single axes, and only
    those of ``coordinates`` when it is given."""
    axes = dict(base)
    entries = _table(data.get("axes", {}), "axes")
    for name, entry in entries.items():
        axis = _axis_letter(name, "axes")
        axes[axis] = _toml_axis(axis, entry, base.get(axis))
    if "coordinates" not in data:
        return {axis: axes[axis] for axis in ALL_AXES if axis in axes}
    coordinates = _coordinates(data["coordinates"])
    for name in entries:
        if name not in coordinates:
            raise ValueError(f"axes.{name}: {name} is not in coordinates {coordinates!r}")
    for axis in coordinates:
        if axis not in axes:
            raise ValueError(f"coordinates: axis {axis} has no limits (add [axes.{axis}] with "
                             "max_velocity and max_acceleration)")
    return {axis: axes[axis] for axis in ALL_AXES if axis in coordinates}


def _start(value: object, base: Mapping[str, float], axes: Mapping[str, AxisLimits]
           ) -> dict[str, float]:
    """``[start]``: the start position, axis by axis, over ``base``'s (kept for axes that stay)."""
    start = {axis: position for axis, position in base.items() if axis in axes}
    for name, position in _table(value, "start").items():
        if _axis_letter(name, "start") not in axes:
            raise ValueError(f"start.{name}: the machine has no {name} axis "
                             f"(its axes: {', '.join(axes)})")
        start[name] = _number(position, f"start.{name}", POSITION)
    return {axis: start[axis] for axis in ALL_AXES if axis in start}


def _machine_from_data(data: Mapping[str, object], base: Machine) -> Machine:
    """``base`` with what the TOML file's tables say; ``ValueError`` names what is wrong."""
    for key in data:
        if key not in TOML_SCALARS and key not in TOML_TABLES:
            raise _unknown("", key, (*TOML_SCALARS, *TOML_TABLES))
    fields = _fields({k: v for k, v in data.items() if k in TOML_SCALARS}, "", TOML_SCALARS)
    fields.update(_fields(_table(data.get("blending", {}), "blending"), "blending", TOML_BLENDING))
    axes = _toml_axes(data, base.axes)
    start = _start(data.get("start", {}), base.start_position, axes)
    travel = _travel(data, base.travel, axes)
    return replace(base, axes=MappingProxyType(axes), start_position=MappingProxyType(start),
                   travel=MappingProxyType(travel), **fields)


def machine_from_toml(path: str, base: Machine = DEFAULT_MACHINE) -> Machine:
    """``base`` with what ngc's TOML machine file at ``path`` sets (``docs/machine.md``).

    The keys given replace ``base``'s values, ``[axes.<letter>]`` tables replace or add single
    axes, ``coordinates`` keeps only the axes it names.  A file that is not a regular file, cannot
    be read or parsed, or has an unknown key or a wrong value is an :class:`NgcConfigError` whose
    message names the file and the key.
    """
    from ..options import require_regular_file  # the loader of the other machine inputs

    require_regular_file(path, "machine file")
    return read_toml(path, "machine file", lambda data: _machine_from_data(data, base))


def load_machine(ini: Ini | None, toml_path: str | None) -> Machine:
    """The machine of ``ngc time``: :data:`DEFAULT_MACHINE`, or the INI file's machine, with the
    TOML machine file (if any) over it.

    >>> load_machine(None, None) == DEFAULT_MACHINE
    True
    """
    machine = DEFAULT_MACHINE if ini is None else machine_from_ini(ini)
    return machine if toml_path is None else machine_from_toml(toml_path, machine)


def axis_speeds(ini: Ini) -> tuple[Mapping[str, float], float | None]:
    """The speeds an INI file states: each axis's MAX_VELOCITY where its [AXIS_<letter>] or
    joints' sections give one (the smallest), and [TRAJ]MAX_LINEAR_VELOCITY (None if unset); in
    machine units per second.  Unlike :func:`machine_from_ini`, nothing is required.

    >>> axis_speeds(Ini.parse("[AXIS_X]\\nMAX_VELOCITY = 30\\n[TRAJ]\\nMAX_LINEAR_VELOCITY = 50\\n"))
    ({'X': 30.0}, 50.0)
    """
    coordinates = _ini_coordinates(ini)
    joints = _ini_joints(ini, coordinates)
    speeds = {}
    for axis in ALL_AXES:
        if axis in coordinates:
            velocity = _smallest(ini, _limit_sections(axis, joints), "MAX_VELOCITY")
            if velocity is not None:
                speeds[axis] = velocity
    cap = _ini_value(ini, *INI_FIELDS["max_linear_velocity"])
    return speeds, None if cap is None else float(cap)  # type: ignore[arg-type]


def machine_travel(ini: Ini | None, toml_path: str | None) -> tuple[SoftLimits, str]:
    """The travel of the machine the INI and TOML files describe, and its units, for the
    commands that hold the moves against it without timing them (``check``, ``plot``): the INI
    file's soft limits and units, the TOML file's ``travel`` and ``units`` over them.  Unlike
    :func:`load_machine`, the INI file need not give the axes' speeds."""
    base = DEFAULT_MACHINE
    if ini is not None:
        base = replace(base, travel=soft_limits(ini), linear_units=linear_units(ini))
    if toml_path is not None:
        base = machine_from_toml(toml_path, base)
    return base.travel, base.linear_units


# A machine's travel: the soft limits of each axis, in machine units (degrees for A, B, C).
SoftLimits = Mapping[str, tuple[float, float]]


def soft_limits(ini: Ini) -> SoftLimits:
    """Each axis's soft limits (ini-config.adoc, [AXIS_<letter>] and [JOINT_<n>] MIN_LIMIT and
    MAX_LIMIT, in machine units): the narrower of its axis section's and its joints' where
    several set them; an axis none of whose sections sets a limit has none (-inf or inf).

    >>> ini = Ini.parse("[TRAJ]\\nCOORDINATES = X Y Z\\n[AXIS_X]\\nMIN_LIMIT = -10\\n"
    ...                 "MAX_LIMIT = 100\\n[JOINT_0]\\nMAX_LIMIT = 90\\n[AXIS_Z]\\nMIN_LIMIT = -50\\n")
    >>> dict(soft_limits(ini))
    {'X': (-10.0, 90.0), 'Z': (-50.0, inf)}
    """
    coordinates = _ini_coordinates(ini)
    joints = _ini_joints(ini, coordinates)
    found: dict[str, tuple[float, float]] = {}
    for axis in ALL_AXES:
        if axis not in coordinates:
            continue
        sections = _limit_sections(axis, joints)
        lows = [v for v in (_ini_value(ini, s, "MIN_LIMIT", parse_real, "a number")
                            for s in sections) if v is not None]
        highs = [v for v in (_ini_value(ini, s, "MAX_LIMIT", parse_real, "a number")
                             for s in sections) if v is not None]
        if lows or highs:
            found[axis] = (max(lows) if lows else -math.inf, min(highs) if highs else math.inf)
    return MappingProxyType(found)


def ini_linear_units(ini: Ini) -> str:
    """The machine's linear units, ``mm`` or ``inch`` ([TRAJ]LINEAR_UNITS; mm without it)."""
    return linear_units(ini)
