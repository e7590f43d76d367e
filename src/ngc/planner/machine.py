"""The machine a program is timed on: axis limits, the trajectory planner's settings, the servo
period and the time the machine spends on tool changes and spindle starts and stops.

:data:`DEFAULT_MACHINE` is the embedded default (a 3-axis mill in mm: X and Y 200 mm/s and
1000 mm/s², Z 100 mm/s and 500 mm/s², a 1 ms servo period, LinuxCNC's blending defaults).
:func:`ngc.planner.config.machine_from_ini` reads LinuxCNC's own INI file and
:func:`ngc.planner.config.machine_from_toml` ngc's TOML machine file.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

LINEAR_AXES = "XYZUVW"
ANGULAR_AXES = "ABC"
ALL_AXES = "XYZABCUVW"  # the order of LinuxCNC's canon positions
# machine units (degrees for A, B, C): the farthest a move (or the start position) may be from
# the origin.  A thousand kilometres (or turns by the million) is past any machine, and keeps every
# length, speed and time the planner works out finite (a coordinate of 1e160 squared is not).
MAX_COORDINATE = 1e9


@dataclass(frozen=True)
class AxisLimits:
    """One axis: its maximum velocity (units/s) and acceleration (units/s²), in machine units
    (degrees for A, B and C)."""

    max_velocity: float
    max_acceleration: float


def _default_axes() -> Mapping[str, AxisLimits]:
    return MappingProxyType({"X": AxisLimits(200.0, 1000.0), "Y": AxisLimits(200.0, 1000.0),
                             "Z": AxisLimits(100.0, 500.0)})


@dataclass(frozen=True)
class Machine:
    """Everything the planner needs to know about the machine.

    Lengths are in ``linear_units`` ("mm" or "inch"), times in seconds.  An axis absent from
    ``axes`` does not exist on the machine: a move that changes its position is an error.  The
    machine files' readers (:mod:`ngc.planner.config`) keep every value within the ranges
    ``docs/machine.md`` lists.
    """

    axes: Mapping[str, AxisLimits] = field(default_factory=_default_axes)
    linear_units: str = "mm"
    # [TRAJ]MAX_LINEAR_VELOCITY: caps every move's speed (feeds and rapids); None: no cap.
    max_linear_velocity: float | None = None
    # [TRAJ]MAX_LINEAR_ACCELERATION: read and kept, but LinuxCNC 2.9 does not apply it to moves.
    max_linear_acceleration: float | None = None
    servo_period: float = 0.001  # [EMCMOT]SERVO_PERIOD, in s (the INI gives ns)
    task_cycle: float = 0.001  # [TASK]CYCLE_TIME
    io_cycle: float = 0.001  # [EMCIO]CYCLE_TIME
    # The blending settings of [TRAJ], with LinuxCNC's defaults.
    arc_blend_enable: bool = True
    arc_blend_fallback_enable: bool = False
    arc_blend_optimization_depth: int = 50
    arc_blend_gap_cycles: float = 4.0
    arc_blend_ramp_freq: float = 100.0
    arc_blend_kink_ratio: float = 0.1
    # Time the machine stands still for, beyond the planner: a tool change (M6), and the
    # spindle coming to speed (M3, M4, or an S change while it turns) and stopping (M5).
    tool_change_time: float = 0.0
    spindle_start_time: float = 0.0
    spindle_stop_time: float = 0.0
    # Where the machine stands when the program starts, machine coordinates (axis -> position).
    start_position: Mapping[str, float] = field(default_factory=lambda: MappingProxyType({}))
    # The axes' travel, their soft limits (axis -> (min, max), machine coordinates): the INI
    # file's MIN_LIMIT/MAX_LIMIT or the TOML file's ``travel``; an axis not in it has none.
    travel: Mapping[str, tuple[float, float]] = field(default_factory=lambda: MappingProxyType({}))

    def limits(self, axis: str) -> AxisLimits | None:
        return self.axes.get(axis)


DEFAULT_MACHINE = Machine()
