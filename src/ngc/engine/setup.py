"""The engine dialect's machine setup sheet: fixtures, tool lengths, the selected tool and the
motors' maximum speeds, read from a TOML file (``ngc canon --dialect engine --setup FILE``).

The seed: "Fixture offsets are configured using a machine setup sheet"; "the tool offset can only
be applied for the selected tool"; G100 speeds are "a percentage of the configured maximum motor
speed".  Lengths are millimetres, angles degrees, speeds per second::

    tool = 2                  # the selected tool (G43); none by default

    [tools.2]
    length = 42.5             # its length offset (G43)

    [fixtures.1]              # G54; fixtures 0 (G53, the default) to 6 (G59)
    X = 100.0                 # the fixture's offsets: its zero in machine coordinates
    Y = 50.0
    tool_axis = "Z"           # the axis tool lengths apply along: X Y Z A B C U V W, optionally
                              # with a sign ("-Z"); "Z" by default

    [axes.Z]                  # a motor's maximum speed (rapids run at it; G100 is a share of it)
    max_speed = 10.0          # mm/s (degrees/s for A B C); 25 mm/s and 360 degrees/s by default

Every fixture starts with no offsets.  An unknown key, table or value is an error that names it,
and so is a number out of its range: offsets and lengths within 1e9 (mm or degrees) either way,
speeds from 1e-6 to 1e6.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from ..config.tomlfile import read_toml

AXES = "XYZABCUVW"
ROTARY = frozenset("ABC")
DEFAULT_LINEAR_SPEED = 25.0
DEFAULT_ROTARY_SPEED = 360.0
FIXTURES = range(7)
# The ranges of the sheet's values.  Offsets and tool lengths (mm, or degrees): a thousand
# kilometres is past any machine (the planner's MAX_COORDINATE).  Speeds (mm/s, degrees/s): the
# machine files' range of velocities (docs/machine.md).  Within them every position and duration
# a program of finite numbers gives stays finite.
MAX_OFFSET = 1e9
MIN_SPEED, MAX_SPEED = 1e-6, 1e6


@dataclass(frozen=True)
class Fixture:
    offsets: tuple[float, ...] = (0.0,) * 9
    tool_axis: tuple[int, float] = (2, 1.0)  # (axis index, sign)


@dataclass(frozen=True)
class Setup:
    fixtures: tuple[Fixture, ...] = (Fixture(),) * 7
    tool: int | None = None
    lengths: Mapping[int, float] = field(default_factory=dict)
    max_speed: tuple[float, ...] = tuple(
        DEFAULT_ROTARY_SPEED if a in ROTARY else DEFAULT_LINEAR_SPEED for a in AXES)


def _number(value: object, where: str, low: float, high: float) -> float:
    """A number from ``low`` to ``high`` (so not infinite, nor NaN)."""
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise ValueError(f"{where} must be a number, not {value!r}")
    number = float(value)
    if not low <= number <= high:  # (a NaN is not within)
        raise ValueError(f"{where} must be a number from {_decimal(low)} to {_decimal(high)}, "
                         f"not {value!r}")
    return number


def _decimal(value: float) -> str:
    """``value`` written out in decimals (1000000000, 0.000001), as a person types it."""
    return str(int(value)) if value == int(value) else f"{value:.12f}".rstrip("0")


def _table(value: object, where: str) -> dict[str, object]:
    if not isinstance(value, dict):
        raise ValueError(f"{where} must be a table")
    return value


def _index(key: str, where: str, allowed: range | None = None) -> int:
    try:
        n = int(key)
    except ValueError:
        raise ValueError(f"{where}: '{key}' is not a number") from None
    if allowed is not None and n not in allowed:
        raise ValueError(f"{where}: there is no fixture {n} (0 to 6)")
    return n


def _tool_axis(value: object, where: str) -> tuple[int, float]:
    text = value.strip().upper() if isinstance(value, str) else ""
    sign = -1.0 if text.startswith("-") else 1.0
    letter = text.lstrip("+-")
    if len(letter) != 1 or letter not in AXES:
        raise ValueError(f"{where} must be an axis letter (X ... W, optionally signed), "
                         f"not {value!r}")
    return AXES.index(letter), sign


def parse(data: Mapping[str, object]) -> Setup:
    """A setup from the file's tables; ``ValueError`` names what is wrong."""
    fixtures = [Fixture()] * 7
    lengths: dict[int, float] = {}
    speeds = list(Setup().max_speed)
    tool: int | None = None
    for key, value in data.items():
        if key == "tool":
            if isinstance(value, bool) or not isinstance(value, int):
                raise ValueError(f"tool must be a whole number, not {value!r}")
            tool = value
        elif key == "tools":
            for name, entry in _table(value, "tools").items():
                where = f"tools.{name}"
                for k, v in _table(entry, where).items():
                    if k != "length":
                        raise ValueError(f"{where}: unknown key '{k}' (length)")
                    lengths[_index(name, "tools")] = _number(v, f"{where}.length",
                                                             -MAX_OFFSET, MAX_OFFSET)
        elif key == "fixtures":
            for name, entry in _table(value, "fixtures").items():
                where = f"fixtures.{name}"
                offsets = [0.0] * 9
                axis = (2, 1.0)
                for k, v in _table(entry, where).items():
                    if k == "tool_axis":
                        axis = _tool_axis(v, f"{where}.tool_axis")
                    elif k in AXES:
                        offsets[AXES.index(k)] = _number(v, f"{where}.{k}", -MAX_OFFSET,
                                                         MAX_OFFSET)
                    else:
                        raise ValueError(f"{where}: unknown key '{k}' (X ... W, tool_axis)")
                fixtures[_index(name, "fixtures", FIXTURES)] = Fixture(tuple(offsets), axis)
        elif key == "axes":
            for name, entry in _table(value, "axes").items():
                where = f"axes.{name}"
                if name not in AXES:
                    raise ValueError(f"axes: '{name}' is not an axis (X ... W)")
                for k, v in _table(entry, where).items():
                    if k != "max_speed":
                        raise ValueError(f"{where}: unknown key '{k}' (max_speed)")
                    speeds[AXES.index(name)] = _number(v, f"{where}.max_speed", MIN_SPEED,
                                                       MAX_SPEED)
        else:
            raise ValueError(f"unknown key '{key}' (tool, tools, fixtures, axes)")
    return Setup(tuple(fixtures), tool, lengths, tuple(speeds))


def read_setup(path: str) -> Setup:
    """Read a setup sheet (module docstring); :class:`NgcConfigError` names what is wrong."""
    return read_toml(path, "setup file", parse)
