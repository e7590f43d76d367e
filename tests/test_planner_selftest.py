"""The hand-computable cases of the measuring tool's self-test (``../shared/timing/lcnc-timing``):
each program, on the machine the tool was given, takes what LinuxCNC 2.9's planner was measured to
take (its README's table), to the servo cycle (1 ms)."""

from __future__ import annotations

from dataclasses import replace
from types import MappingProxyType as MP

import pytest

from ngc.planner.machine import DEFAULT_MACHINE, AxisLimits, Machine
from ngc.planner.timing import time_text

SQUARE = "G1 X100 Y0 F6000\nG1 X100 Y100\nG1 X0 Y100\nG1 X0 Y0\n"
all200 = MP({a: AxisLimits(200.0, 1000.0) for a in "XYZ"})
base = replace(DEFAULT_MACHINE, axes=all200)
slow_z = replace(base, axes=MP({"X": AxisLimits(200, 1000), "Y": AxisLimits(200, 1000),
                                            "Z": AxisLimits(20, 100)}))
inch = replace(base, linear_units="inch",
                           axes=MP({a: AxisLimits(4.0, 40.0) for a in "XYZ"}))

# name, program body, machine, LinuxCNC's measured time (s)
CASES: list[tuple[str, str, Machine, float]] = [
 ("line_exact_stop", "G61.1\nG1 X100 F6000\n", base, 1.100),
 ("line_G64", "G64\nG1 X100 F6000\n", base, 1.200),
 ("two_collinear_G61.1", "G61.1\nG1 X50 F6000\nG1 X100\n", base, 1.200),
 ("two_collinear_G64", "G64\nG1 X50 F6000\nG1 X100\n", base, 1.151),
 ("rapid", "G61.1\nG0 X100\n", base, 0.700),
 ("xz_diagonal", "G61.1\nG1 X100 Z10 F6000\n", slow_z, 1.105),
 ("full_circle", "G61.1\nG0 X50\nG2 X50 Y0 I-50 J0 F3000\n", base, 6.834),
 ("square_G61.1", "G61.1\n" + SQUARE, base, 4.400),
 ("square_G61", "G61\n" + SQUARE, base, 4.448),
 ("square_G61_kink0", "G61\n" + SQUARE, replace(base, arc_blend_kink_ratio=0.0), 4.404),
 ("square_G64_parabolic", "G64\n" + SQUARE, replace(base, arc_blend_enable=False), 4.200),
 ("square_G64_arcblend", "G64\n" + SQUARE, base, 3.987),
 ("dwell", "G61.1\nG1 X100 F6000\nG4 P0.5\nG1 X0\n", base, 2.702),
 ("traj_max_velocity", "G61.1\nG1 X100 F6000\n", replace(base, max_linear_velocity=50.0), 2.050),
 ("traj_max_accel_ignored", "G61.1\nG1 X100 F6000\n", replace(base, max_linear_acceleration=500.0), 1.100),
 ("inch", "G61.1\nG1 X4 F240\n", inch, 1.100),
 ("servo_0.5ms", "G61.1\nG1 X100 F6000\n", replace(base, servo_period=0.0005), 1.100),
]


@pytest.mark.parametrize(("name", "body", "machine", "measured"), CASES, ids=[c[0] for c in CASES])
def test_selftest_case(name: str, body: str, machine: Machine, measured: float) -> None:
    units = "G20" if machine.linear_units == "inch" else "G21"
    total = time_text(f"{units} G90 G17\n{body}M2\n", machine).total_s
    assert abs(total - measured) <= 0.001 + 1e-9, (name, total, measured)
