"""Machine files: every number is checked against its key's range when it is read (TOML and
INI), the message names the key, the value and the range, and docs/machine.md lists the ranges."""

from __future__ import annotations

from pathlib import Path

import pytest

from cli_helpers import write
from ngc.config.ini import Ini
from ngc.errors import NgcConfigError
from ngc.planner.config import (
    ACCELERATION,
    INI_FIELDS,
    RANGES,
    VELOCITY,
    Range,
    machine_from_ini,
    machine_from_toml,
)

TOML_KEYS = [  # (the TOML text before the value, the key's name in messages, its range's key)
    *((f"{key} = ", key, key) for key in (
        "max_linear_velocity", "max_linear_acceleration", "servo_period", "task_cycle_time",
        "io_cycle_time", "tool_change_time", "spindle_start_time", "spindle_stop_time")),
    *((f"[blending]\n{key} = ", f"blending.{key}", key) for key in (
        "optimization_depth", "gap_cycles", "ramp_freq", "kink_ratio")),
    *((f"[axes.X]\n{key} = ", f"axes.X.{key}", key)
      for key in ("max_velocity", "max_acceleration")),
    ("[start]\nZ = ", "start.Z", "start"),
]


def outside(limits: Range) -> list[float | int]:
    """Values just past each end of ``limits``, and far past."""
    if limits.integer:
        return [int(limits.low) - 1, int(limits.high) + 1, 2**62]
    below = limits.low - 1.0 if limits.low <= 0.0 else limits.low / 10.0
    return [below, limits.high * 1.5, 1e300, -1e300]


@pytest.mark.parametrize(("head", "where", "key"), TOML_KEYS)
def test_every_toml_number_is_checked_against_its_range(tmp_path: Path, head: str, where: str,
                                                        key: str) -> None:
    limits = RANGES[key]
    for value in outside(limits):
        path = write(tmp_path, "m.toml", f"{head}{value!r}\n")
        with pytest.raises(NgcConfigError) as caught:
            machine_from_toml(path)
        assert caught.value.message == (f"machine file {path}: {where} must be "
                                        f"{limits.text()}, not {value!r}")
    for value in (limits.low, limits.high):
        number = int(value) if limits.integer else float(value)
        machine_from_toml(write(tmp_path, "m.toml", f"{head}{number!r}\n"))  # both ends held


INI_KEYS = [(spec.section, spec.key, spec.expected) for spec in INI_FIELDS.values()
            if " from " in spec.expected]
XYZ = "".join(f"[AXIS_{axis}]\nMAX_VELOCITY = 10\nMAX_ACCELERATION = 100\n" for axis in "XYZ")


@pytest.mark.parametrize(("section", "key", "expected"), [
    *INI_KEYS,
    ("AXIS_X", "MAX_VELOCITY", VELOCITY.text()),
    ("JOINT_0", "MAX_ACCELERATION", ACCELERATION.text()),
    ("KINS", "JOINTS", "a whole number from 1 to 16"),
])
def test_every_ini_number_is_checked_against_its_range(tmp_path: Path, section: str, key: str,
                                                       expected: str) -> None:
    assert " from " in expected
    low, high = (float(part.split()[0]) for part in expected.split(" from ")[1].split(" to "))
    for value in (low - 1.0 if low <= 0.0 else low / 10.0, high * 1.5, 1e300):
        text = repr(int(value)) if "whole" in expected and value < 1e20 else repr(value)
        path = write(tmp_path, "m.ini", f"[{section}]\n{key} = {text}\n{XYZ}")
        with pytest.raises(NgcConfigError) as caught:
            machine_from_ini(Ini.read(path))
        assert caught.value.message == (f"INI file {path}: [{section}]{key} is '{text}', "
                                        f"not {expected}")


def test_the_ranges_are_documented() -> None:
    docs = (Path(__file__).resolve().parent.parent / "docs" / "machine.md").read_text()
    for key, limits in RANGES.items():
        span = limits.text().split(" from ")[1]
        rows = [line for line in docs.splitlines() if f"`{key}`" in line and span in line]
        assert rows or (key == "start" and f"({span})" in docs), key
