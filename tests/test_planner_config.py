"""The machine ``ngc time`` plans on: the default, LinuxCNC INI files, ngc's TOML machine file, the
TOML file over an INI file, and every way a file can be wrong (docs/machine.md)."""

from __future__ import annotations

import doctest
import os
from pathlib import Path

import pytest

from cli_helpers import write
from ngc.config.ini import Ini
from ngc.errors import NgcConfigError
from ngc.planner import config
from ngc.planner.config import load_machine, machine_from_ini, machine_from_toml
from ngc.planner.machine import DEFAULT_MACHINE, AxisLimits, Machine

ROOT = Path(__file__).resolve().parent.parent
EXAMPLE = ROOT / "examples" / "machine.toml"

FULL_INI = """\
[KINS]
KINEMATICS = trivkins
JOINTS = 3

[TRAJ]
COORDINATES = X Y Z
LINEAR_UNITS = inch
MAX_LINEAR_VELOCITY = 4
MAX_LINEAR_ACCELERATION = 40
ARC_BLEND_ENABLE = 0
ARC_BLEND_FALLBACK_ENABLE = YES
ARC_BLEND_OPTIMIZATION_DEPTH = 80
ARC_BLEND_GAP_CYCLES = 2
ARC_BLEND_RAMP_FREQ = 20
ARC_BLEND_KINK_RATIO = 0.25

[EMCMOT]
SERVO_PERIOD = 250000

[TASK]
CYCLE_TIME = 0.010

[EMCIO]
CYCLE_TIME = 0.100

[AXIS_X]
MAX_VELOCITY = 3
MAX_ACCELERATION = 30

[AXIS_Y]
MAX_VELOCITY = 3
MAX_ACCELERATION = 30

[AXIS_Z]
MAX_VELOCITY = 2
MAX_ACCELERATION = 20

[JOINT_0]
MAX_VELOCITY = 3.5
MAX_ACCELERATION = 25

[JOINT_1]
MAX_VELOCITY = 2.5
MAX_ACCELERATION = 35

[JOINT_2]
MAX_VELOCITY = 2
MAX_ACCELERATION = 20
"""

XYZ_LIMITS = ("[AXIS_X]\nMAX_VELOCITY = 10\nMAX_ACCELERATION = 100\n"
              "[AXIS_Y]\nMAX_VELOCITY = 10\nMAX_ACCELERATION = 100\n"
              "[AXIS_Z]\nMAX_VELOCITY = 5\nMAX_ACCELERATION = 50\n")


def ini_file(tmp_path: Path, text: str) -> Ini:
    return Ini.read(write(tmp_path, "machine.ini", text))


def toml_error(tmp_path: Path, text: str, base: Machine = DEFAULT_MACHINE) -> str:
    path = write(tmp_path, "machine.toml", text)
    with pytest.raises(NgcConfigError) as caught:
        machine_from_toml(path, base)
    assert caught.value.file == path
    prefix = f"machine file {path}: "
    assert caught.value.message.startswith(prefix)
    return caught.value.message[len(prefix):]


def ini_error(tmp_path: Path, text: str) -> str:
    ini = ini_file(tmp_path, text)
    with pytest.raises(NgcConfigError) as caught:
        machine_from_ini(ini)
    assert caught.value.file == ini.path
    prefix = f"INI file {ini.path}: "
    assert caught.value.message.startswith(prefix)
    return caught.value.message[len(prefix):]


# -- the default machine -------------------------------------------------------------------------


def test_the_default_machine() -> None:
    assert load_machine(None, None) is DEFAULT_MACHINE
    assert dict(DEFAULT_MACHINE.axes) == {
        "X": AxisLimits(200.0, 1000.0), "Y": AxisLimits(200.0, 1000.0), "Z": AxisLimits(100.0, 500.0)}
    assert DEFAULT_MACHINE.linear_units == "mm"
    assert DEFAULT_MACHINE.servo_period == 0.001
    assert DEFAULT_MACHINE.max_linear_velocity is None
    assert (DEFAULT_MACHINE.arc_blend_enable, DEFAULT_MACHINE.arc_blend_fallback_enable) == (True, False)
    assert DEFAULT_MACHINE.arc_blend_optimization_depth == 50
    assert (DEFAULT_MACHINE.arc_blend_gap_cycles, DEFAULT_MACHINE.arc_blend_ramp_freq) == (4.0, 100.0)
    assert DEFAULT_MACHINE.tool_change_time == 0.0
    assert dict(DEFAULT_MACHINE.start_position) == {}


def test_doctests() -> None:
    failed, attempted = doctest.testmod(config)
    assert attempted > 0
    assert failed == 0


# -- INI files -------------------------------------------------------------------------------------


def test_a_full_ini_file(tmp_path: Path) -> None:
    machine = machine_from_ini(ini_file(tmp_path, FULL_INI))
    assert dict(machine.axes) == {
        "X": AxisLimits(3.0, 25.0),  # joint 0 accelerates slower than the axis
        "Y": AxisLimits(2.5, 30.0),  # joint 1 is slower than the axis
        "Z": AxisLimits(2.0, 20.0),
    }
    assert machine.linear_units == "inch"
    assert (machine.max_linear_velocity, machine.max_linear_acceleration) == (4.0, 40.0)
    assert machine.servo_period == pytest.approx(0.00025)  # ns -> s
    assert (machine.task_cycle, machine.io_cycle) == (0.01, 0.1)
    assert (machine.arc_blend_enable, machine.arc_blend_fallback_enable) == (False, True)
    assert machine.arc_blend_optimization_depth == 80
    assert (machine.arc_blend_gap_cycles, machine.arc_blend_ramp_freq) == (2.0, 20.0)
    assert machine.arc_blend_kink_ratio == 0.25
    assert machine.tool_change_time == 0.0  # not in an INI file: the default
    assert load_machine(Ini.parse(FULL_INI), None) == machine


def test_missing_keys_keep_the_defaults() -> None:
    machine = machine_from_ini(Ini.parse(XYZ_LIMITS))
    assert machine.axes["Z"] == AxisLimits(5.0, 50.0)
    assert machine == Machine(axes=machine.axes)


def test_servo_period_is_read_in_nanoseconds() -> None:
    machine = machine_from_ini(Ini.parse(XYZ_LIMITS + "[EMCMOT]\nSERVO_PERIOD = 1000000\n"))
    assert machine.servo_period == 0.001


@pytest.mark.parametrize(("value", "units"), [
    ("mm", "mm"), ("MM", "mm"), ("metric", "mm"), ("inch", "inch"), ("in", "inch"),
    ("Imperial", "inch"), ("1.0", "mm"), ("1", "mm"), ("0.03937", "inch"),
    ("0.03937007874", "inch"),
])
def test_linear_units(value: str, units: str) -> None:
    machine = machine_from_ini(Ini.parse(f"[TRAJ]\nLINEAR_UNITS = {value}\n" + XYZ_LIMITS))
    assert machine.linear_units == units


def test_joints_follow_the_coordinates_in_order() -> None:
    # trivkins coordinates=XZ: joint 0 is X, joint 1 is Z (ini-config.adoc)
    machine = machine_from_ini(Ini.parse(
        "[TRAJ]\nCOORDINATES = XZ\n"
        "[JOINT_0]\nMAX_VELOCITY = 4\nMAX_ACCELERATION = 40\n"
        "[JOINT_1]\nMAX_VELOCITY = 2\nMAX_ACCELERATION = 20\n"))
    assert dict(machine.axes) == {"X": AxisLimits(4.0, 40.0), "Z": AxisLimits(2.0, 20.0)}


def test_a_gantry_axis_is_as_slow_as_its_slowest_joint() -> None:
    machine = machine_from_ini(Ini.parse(
        "[TRAJ]\nCOORDINATES = X Y Y Z\n" + XYZ_LIMITS
        + "[JOINT_1]\nMAX_VELOCITY = 9\n[JOINT_2]\nMAX_VELOCITY = 8\nMAX_ACCELERATION = 70\n"
        + "[JOINT_3]\nMAX_VELOCITY = 4\n"))
    assert dict(machine.axes) == {
        "X": AxisLimits(10.0, 100.0), "Y": AxisLimits(8.0, 70.0), "Z": AxisLimits(4.0, 50.0)}


def test_kinematics_coordinates_order_the_joints() -> None:
    machine = machine_from_ini(Ini.parse(
        "[KINS]\nKINEMATICS = trivkins coordinates=zx kinstype=b\n"
        "[TRAJ]\nCOORDINATES = X Z\n"
        "[JOINT_0]\nMAX_VELOCITY = 2\nMAX_ACCELERATION = 20\n"
        "[JOINT_1]\nMAX_VELOCITY = 4\nMAX_ACCELERATION = 40\n"))
    assert dict(machine.axes) == {"X": AxisLimits(4.0, 40.0), "Z": AxisLimits(2.0, 20.0)}


def test_kins_joints_limits_the_joints() -> None:
    text = ("[KINS]\nJOINTS = 2\n[TRAJ]\nCOORDINATES = XYZ\n" + XYZ_LIMITS
            + "[JOINT_1]\nMAX_VELOCITY = 1\n[JOINT_2]\nMAX_VELOCITY = 1\n")
    machine = machine_from_ini(Ini.parse(text))
    assert machine.axes["Y"].max_velocity == 1.0
    assert machine.axes["Z"].max_velocity == 5.0  # there is no joint 2


def test_without_coordinates_the_axis_sections_are_the_axes() -> None:
    machine = machine_from_ini(Ini.parse(
        "[AXIS_X]\nMAX_VELOCITY = 3\nMAX_ACCELERATION = 30\n"
        "[AXIS_A]\nMAX_VELOCITY = 90\nMAX_ACCELERATION = 900\n"
        "[JOINT_1]\nMAX_VELOCITY = 45\n"))
    assert dict(machine.axes) == {"X": AxisLimits(3.0, 30.0), "A": AxisLimits(45.0, 900.0)}


def test_axes_outside_the_coordinates_are_not_read() -> None:
    machine = machine_from_ini(Ini.parse(
        "[TRAJ]\nCOORDINATES = X\n[AXIS_X]\nMAX_VELOCITY = 3\nMAX_ACCELERATION = 30\n"
        "[AXIS_Y]\nMAX_VELOCITY = fast\n"))
    assert list(machine.axes) == ["X"]


def test_the_documented_ini_example() -> None:
    text = (ROOT / "docs" / "machine.md").read_text()
    example = text.split("```ini\n", 1)[1].split("```", 1)[0]
    machine = machine_from_ini(Ini.parse(example))
    assert dict(machine.axes) == {
        "X": AxisLimits(3.0, 30.0), "Y": AxisLimits(2.5, 20.0), "Z": AxisLimits(1.0, 10.0)}
    assert (machine.linear_units, machine.max_linear_velocity) == ("inch", 4.0)
    assert machine.servo_period == 0.001


@pytest.mark.parametrize(("text", "message"), [
    ("[TRAJ]\nLINEAR_UNITS = furlong\n",
     "[TRAJ]LINEAR_UNITS is 'furlong', not mm, inch (or in, metric, imperial) or the machine units "
     "per mm (1.0 for mm, 0.03937 for inch)"),
    ("[TRAJ]\nLINEAR_UNITS = 0.1\n", "[TRAJ]LINEAR_UNITS is '0.1', not mm, inch"),
    ("[TRAJ]\nMAX_LINEAR_VELOCITY = 4 in/s\n",
     "[TRAJ]MAX_LINEAR_VELOCITY is '4 in/s', not a number from 0.000001 to 1000000"),
    ("[TRAJ]\nMAX_LINEAR_ACCELERATION = -1\n",
     "[TRAJ]MAX_LINEAR_ACCELERATION is '-1', not a number from 0.000001 to 1000000000"),
    ("[TRAJ]\nMAX_LINEAR_VELOCITY = inf\n",
     "[TRAJ]MAX_LINEAR_VELOCITY is 'inf', not a number from 0.000001 to 1000000"),
    ("[TRAJ]\nMAX_LINEAR_VELOCITY =\n",
     "[TRAJ]MAX_LINEAR_VELOCITY is '', not a number from 0.000001 to 1000000"),
    ("[TRAJ]\nARC_BLEND_ENABLE = maybe\n",
     "[TRAJ]ARC_BLEND_ENABLE is 'maybe', not a boolean (1, 0, TRUE, FALSE, YES, NO, ON, OFF)"),
    ("[TRAJ]\nARC_BLEND_FALLBACK_ENABLE = 2\n", "[TRAJ]ARC_BLEND_FALLBACK_ENABLE is '2', not a boolean"),
    ("[TRAJ]\nARC_BLEND_OPTIMIZATION_DEPTH = 5.5\n",
     "[TRAJ]ARC_BLEND_OPTIMIZATION_DEPTH is '5.5', not a whole number from 0 to 1000"),
    ("[TRAJ]\nARC_BLEND_OPTIMIZATION_DEPTH = -1\n",
     "[TRAJ]ARC_BLEND_OPTIMIZATION_DEPTH is '-1', not a whole number from 0 to 1000"),
    ("[TRAJ]\nARC_BLEND_GAP_CYCLES = -4\n",
     "[TRAJ]ARC_BLEND_GAP_CYCLES is '-4', not a number from 0 to 1000000"),
    ("[TRAJ]\nARC_BLEND_RAMP_FREQ = 0\n",
     "[TRAJ]ARC_BLEND_RAMP_FREQ is '0', not a number from 0.000001 to 1000000 Hz"),
    ("[TRAJ]\nARC_BLEND_KINK_RATIO = x\n",
     "[TRAJ]ARC_BLEND_KINK_RATIO is 'x', not a number from 0 to 1000000"),
    ("[EMCMOT]\nSERVO_PERIOD = 0.001\n",
     "[EMCMOT]SERVO_PERIOD is '0.001', not a whole number from 1000 to 1000000000 nanoseconds"),
    ("[EMCMOT]\nSERVO_PERIOD = 0\n",
     "[EMCMOT]SERVO_PERIOD is '0', not a whole number from 1000 to 1000000000 nanoseconds"),
    ("[EMCMOT]\nSERVO_PERIOD = -1000000\n",
     "[EMCMOT]SERVO_PERIOD is '-1000000', not a whole number from 1000 to 1000000000 nanoseconds"),
    ("[TASK]\nCYCLE_TIME = 0\n", "[TASK]CYCLE_TIME is '0', not a number from 0.000001 to 10 seconds"),
    ("[EMCIO]\nCYCLE_TIME = soon\n", "[EMCIO]CYCLE_TIME is 'soon', not a number from 0.000001 to 10 seconds"),
    ("[KINS]\nJOINTS = 0\n", "[KINS]JOINTS is '0', not a whole number from 1 to 16"),
    ("[KINS]\nJOINTS = three\n", "[KINS]JOINTS is 'three', not a whole number from 1 to 16"),
    ("[KINS]\nKINEMATICS = trivkins coordinates=XQ\n",
     "[KINS]KINEMATICS is 'trivkins coordinates=XQ', not axis letters (X Y Z A B C U V W)"),
])
def test_bad_ini_values(tmp_path: Path, text: str, message: str) -> None:
    found = ini_error(tmp_path, text + XYZ_LIMITS)
    assert found.startswith(message)


@pytest.mark.parametrize(("text", "message"), [
    ("[TRAJ]\nCOORDINATES = X Q\n", "[TRAJ]COORDINATES is 'X Q', not axis letters (X Y Z A B C U V W)"),
    ("[TRAJ]\nCOORDINATES =\n", "[TRAJ]COORDINATES is '', not axis letters"),
    ("[TRAJ]\nCOORDINATES = XZ\n[AXIS_X]\nMAX_VELOCITY = 0\n",
     "[AXIS_X]MAX_VELOCITY is '0', not a number from 0.000001 to 1000000"),
    ("[TRAJ]\nCOORDINATES = XZ\n[AXIS_X]\nMAX_ACCELERATION = fast\n",
     "[AXIS_X]MAX_ACCELERATION is 'fast', not a number from 0.000001 to 1000000000"),
    ("[TRAJ]\nCOORDINATES = XZ\n[JOINT_1]\nMAX_VELOCITY = -2\n",
     "[JOINT_1]MAX_VELOCITY is '-2', not a number from 0.000001 to 1000000"),
    ("[TRAJ]\nCOORDINATES = XZ\n[JOINT_1]\nMAX_ACCELERATION = nan\n",
     "[JOINT_1]MAX_ACCELERATION is 'nan', not a number from 0.000001 to 1000000000"),
    ("[TRAJ]\nCOORDINATES = XZ\n[DISPLAY]\nMAX_LINEAR_VELOCITY = 5\n",
     "no axis limits: MAX_VELOCITY and MAX_ACCELERATION are set in no [AXIS_<letter>] or "
     "[JOINT_<n>] section of the axes (X Z)"),
    ("[TRAJ]\nLINEAR_UNITS = mm\n", "no axis limits"),
    ("", "no axis limits: MAX_VELOCITY and MAX_ACCELERATION are set in no [AXIS_<letter>] or "
     "[JOINT_<n>] section of the axes (none)"),
    ("[TRAJ]\nCOORDINATES = XZ\n[AXIS_X]\nMAX_VELOCITY = 3\nMAX_ACCELERATION = 30\n",
     "axis Z has no MAX_VELOCITY (in [AXIS_Z] or [JOINT_1])"),
    ("[TRAJ]\nCOORDINATES = XZ\n[AXIS_X]\nMAX_VELOCITY = 3\nMAX_ACCELERATION = 30\n"
     "[JOINT_1]\nMAX_VELOCITY = 3\n", "axis Z has no MAX_ACCELERATION (in [AXIS_Z] or [JOINT_1])"),
])
def test_bad_ini_axes(tmp_path: Path, text: str, message: str) -> None:
    assert ini_error(tmp_path, text).startswith(message)


def test_an_ini_text_without_a_file_is_named_as_such() -> None:
    with pytest.raises(NgcConfigError, match=r"^INI file: no axis limits"):
        machine_from_ini(Ini.parse(""))


# -- TOML machine files ----------------------------------------------------------------------------


def test_the_example_file_loads() -> None:
    machine = machine_from_toml(str(EXAMPLE))
    assert dict(machine.axes) == {
        "X": AxisLimits(200.0, 1000.0), "Y": AxisLimits(200.0, 1000.0),
        "Z": AxisLimits(100.0, 500.0), "A": AxisLimits(360.0, 1800.0)}
    assert machine.linear_units == "mm"
    assert (machine.max_linear_velocity, machine.max_linear_acceleration) == (250.0, 2000.0)
    assert (machine.servo_period, machine.task_cycle, machine.io_cycle) == (0.001, 0.001, 0.001)
    assert (machine.tool_change_time, machine.spindle_start_time, machine.spindle_stop_time) == (
        6.0, 1.5, 1.0)
    assert machine.arc_blend_enable and not machine.arc_blend_fallback_enable
    assert machine.arc_blend_optimization_depth == 50
    assert (machine.arc_blend_gap_cycles, machine.arc_blend_ramp_freq) == (4.0, 100.0)
    assert machine.arc_blend_kink_ratio == 0.1
    assert dict(machine.start_position) == {"X": 0.0, "Y": 0.0, "Z": 50.0, "A": 0.0}


def test_the_documented_example_is_the_example_file() -> None:
    text = (ROOT / "docs" / "machine.md").read_text()
    assert "```toml\n" + EXAMPLE.read_text() + "```" in text


def test_an_empty_file_is_the_base(tmp_path: Path) -> None:
    assert machine_from_toml(write(tmp_path, "m.toml", "")) == DEFAULT_MACHINE


def test_keys_override_the_base(tmp_path: Path) -> None:
    path = write(tmp_path, "m.toml", 'units = "inch"\nservo_period = 0.0005\ntool_change_time = 7\n'
                 "[blending]\nenable = false\noptimization_depth = 10\n")
    machine = machine_from_toml(path)
    assert machine.linear_units == "inch"
    assert machine.servo_period == 0.0005
    assert machine.tool_change_time == 7.0
    assert isinstance(machine.tool_change_time, float)
    assert (machine.arc_blend_enable, machine.arc_blend_optimization_depth) == (False, 10)
    assert machine.axes == DEFAULT_MACHINE.axes
    assert machine.arc_blend_ramp_freq == DEFAULT_MACHINE.arc_blend_ramp_freq


def test_axes_are_replaced_added_or_changed_one_by_one(tmp_path: Path) -> None:
    path = write(tmp_path, "m.toml", "[axes.Z]\nmax_velocity = 50\n"
                 "[axes.C]\nmax_velocity = 720\nmax_acceleration = 3600\n"
                 "[axes.X]\nmax_velocity = 300\nmax_acceleration = 3000\n")
    machine = machine_from_toml(path)
    assert dict(machine.axes) == {
        "X": AxisLimits(300.0, 3000.0), "Y": AxisLimits(200.0, 1000.0),
        "Z": AxisLimits(50.0, 500.0), "C": AxisLimits(720.0, 3600.0)}
    assert list(machine.axes) == ["X", "Y", "Z", "C"]


def test_coordinates_keep_only_the_axes_named(tmp_path: Path) -> None:
    base = Machine(start_position={"X": 1.0, "Y": 2.0})
    machine = machine_from_toml(write(tmp_path, "m.toml", 'coordinates = "Z X"\n[start]\nZ = 5\n'),
                                base)
    assert dict(machine.axes) == {"X": AxisLimits(200.0, 1000.0), "Z": AxisLimits(100.0, 500.0)}
    assert dict(machine.start_position) == {"X": 1.0, "Z": 5.0}


def test_the_start_position_is_merged(tmp_path: Path) -> None:
    base = Machine(start_position={"X": 1.0, "Y": 2.0})
    machine = machine_from_toml(write(tmp_path, "m.toml", "[start]\nY = -3\nZ = 10.5\n"), base)
    assert dict(machine.start_position) == {"X": 1.0, "Y": -3.0, "Z": 10.5}


def test_toml_over_ini(tmp_path: Path) -> None:
    ini = ini_file(tmp_path, FULL_INI)
    toml = write(tmp_path, "m.toml", "tool_change_time = 6.0\nspindle_start_time = 1.5\n"
                 "[axes.Z]\nmax_acceleration = 10\n")
    machine = load_machine(ini, toml)
    from_ini = machine_from_ini(ini)
    assert machine.tool_change_time == 6.0
    assert machine.spindle_start_time == 1.5
    assert machine.axes["Z"] == AxisLimits(2.0, 10.0)
    assert machine.axes["X"] == from_ini.axes["X"]
    assert machine.linear_units == "inch"
    assert machine.servo_period == from_ini.servo_period
    assert machine.arc_blend_enable is False
    assert load_machine(None, toml).axes["Z"] == AxisLimits(100.0, 10.0)


TOP_KEYS = ("units, max_linear_velocity, max_linear_acceleration, servo_period, task_cycle_time, "
            "io_cycle_time, tool_change_time, spindle_start_time, spindle_stop_time, coordinates, "
            "axes, blending, start")


@pytest.mark.parametrize(("text", "message"), [
    # unknown keys, each naming the keys allowed there
    ("servo_time = 1\n", f"unknown key 'servo_time' (allowed: {TOP_KEYS})"),
    ("[spindle]\nstart = 1\n", "unknown key 'spindle' (allowed: units,"),
    ("[axes.X]\nmax_speed = 1\n",
     "axes.X: unknown key 'max_speed' (allowed: max_velocity, max_acceleration, travel)"),
    ("[blending]\narc_blend_enable = true\n",
     "blending: unknown key 'arc_blend_enable' (allowed: enable, fallback_enable, "
     "optimization_depth, gap_cycles, ramp_freq, kink_ratio)"),
    ("[axes.x]\nmax_velocity = 1\n",
     "axes: 'x' is not an axis (allowed: X, Y, Z, A, B, C, U, V, W)"),
    ("[start]\nQ = 1\n", "start: 'Q' is not an axis (allowed: X, Y, Z, A, B, C, U, V, W)"),
    # wrong types
    ('servo_period = "1ms"\n', "servo_period must be a number from 0.000001 to 1, not '1ms'"),
    ("tool_change_time = true\n", "tool_change_time must be a number from 0 to 1000000, not True"),
    ("max_linear_velocity = nan\n", "max_linear_velocity must be a number from 0.000001 to 1000000, not nan"),
    ("max_linear_velocity = inf\n", "max_linear_velocity must be a number from 0.000001 to 1000000, not inf"),
    ("units = \"furlong\"\n", "units must be \"mm\" or \"inch\", not 'furlong'"),
    ("units = 1\n", "units must be \"mm\" or \"inch\", not 1"),
    ("axes = 1\n", "axes must be a table, not 1"),
    ("axes = { X = 1 }\n", "axes.X must be a table, not 1"),
    ("blending = true\n", "blending must be a table, not True"),
    ("start = [1, 2]\n", "start must be a table, not [1, 2]"),
    ("[axes.X]\nmax_velocity = \"fast\"\n",
     "axes.X.max_velocity must be a number from 0.000001 to 1000000, not 'fast'"),
    ("[blending]\nenable = 1\n", "blending.enable must be true or false, not 1"),
    ("[blending]\noptimization_depth = 5.0\n",
     "blending.optimization_depth must be a whole number from 0 to 1000, not 5.0"),
    ("[blending]\nkink_ratio = \"0.1\"\n",
     "blending.kink_ratio must be a number from 0 to 1000000, not '0.1'"),
    ("[start]\nX = \"home\"\n", "start.X must be a number from -1000000000 to 1000000000, not 'home'"),
    ("coordinates = 3\n", "coordinates must be axis letters (X Y Z A B C U V W), not 3"),
    ("coordinates = \"XQ\"\n", "coordinates must be axis letters (X Y Z A B C U V W), not 'XQ'"),
    ("coordinates = \"\"\n", "coordinates must be axis letters (X Y Z A B C U V W), not ''"),
    # negative and zero values
    ("servo_period = 0\n", "servo_period must be a number from 0.000001 to 1, not 0"),
    ("task_cycle_time = -0.01\n", "task_cycle_time must be a number from 0.000001 to 10, not -0.01"),
    ("io_cycle_time = 0.0\n", "io_cycle_time must be a number from 0.000001 to 10, not 0.0"),
    ("max_linear_velocity = 0\n", "max_linear_velocity must be a number from 0.000001 to 1000000, not 0"),
    ("max_linear_acceleration = -5\n",
     "max_linear_acceleration must be a number from 0.000001 to 1000000000, not -5"),
    ("tool_change_time = -1\n", "tool_change_time must be a number from 0 to 1000000, not -1"),
    ("spindle_start_time = -0.5\n", "spindle_start_time must be a number from 0 to 1000000, not -0.5"),
    ("spindle_stop_time = -2\n", "spindle_stop_time must be a number from 0 to 1000000, not -2"),
    ("[axes.X]\nmax_velocity = 0\n", "axes.X.max_velocity must be a number from 0.000001 to 1000000, not 0"),
    ("[axes.X]\nmax_acceleration = -100\n",
     "axes.X.max_acceleration must be a number from 0.000001 to 1000000000, not -100"),
    ("[blending]\nramp_freq = 0\n", "blending.ramp_freq must be a number from 0.000001 to 1000000, not 0"),
    ("[blending]\ngap_cycles = -1\n", "blending.gap_cycles must be a number from 0 to 1000000, not -1"),
    ("[blending]\noptimization_depth = -1\n",
     "blending.optimization_depth must be a whole number from 0 to 1000, not -1"),
    # axes that do not fit together
    ("[axes.A]\nmax_velocity = 90\n",
     "axes.A: a new axis needs max_velocity and max_acceleration (missing: max_acceleration)"),
    ("[axes.A]\n", "axes.A: a new axis needs max_velocity and max_acceleration "
     "(missing: max_velocity, max_acceleration)"),
    ("coordinates = \"XYZA\"\n",
     "coordinates: axis A has no limits (add [axes.A] with max_velocity and max_acceleration)"),
    ("coordinates = \"XZX\"\n", "coordinates names X more than once: 'XZX'"),
    ("coordinates = \"XZ\"\n[axes.Y]\nmax_velocity = 5\n", "axes.Y: Y is not in coordinates 'XZ'"),
    ("[start]\nA = 0\n", "start.A: the machine has no A axis (its axes: X, Y, Z)"),
    ("coordinates = \"XZ\"\n[start]\nY = 0\n", "start.Y: the machine has no Y axis (its axes: X, Z)"),
])
def test_bad_toml_values(tmp_path: Path, text: str, message: str) -> None:
    assert toml_error(tmp_path, text).startswith(message)


def test_bad_toml_syntax(tmp_path: Path) -> None:
    found = toml_error(tmp_path, "units = mm\n")
    assert "(at line 1, column 9)" in found


def test_a_duplicate_toml_key(tmp_path: Path) -> None:
    assert toml_error(tmp_path, "servo_period = 1\nservo_period = 2\n").startswith("Cannot overwrite")


def test_a_missing_toml_file(tmp_path: Path) -> None:
    path = str(tmp_path / "absent.toml")
    with pytest.raises(NgcConfigError) as caught:
        machine_from_toml(path)
    assert caught.value.message == f"cannot open machine file {path}: No such file or directory"
    assert caught.value.file == path


def test_a_path_through_a_file_cannot_be_opened(tmp_path: Path) -> None:
    path = write(tmp_path, "m.toml", "") + "/inner.toml"
    with pytest.raises(NgcConfigError) as caught:
        machine_from_toml(path)
    assert caught.value.message == f"cannot open machine file {path}: Not a directory"


def test_a_directory_is_not_a_machine_file(tmp_path: Path) -> None:
    with pytest.raises(NgcConfigError) as caught:
        machine_from_toml(str(tmp_path))
    assert caught.value.message == f"machine file {tmp_path} is not a regular file"


def test_a_fifo_is_refused_without_waiting(tmp_path: Path) -> None:
    fifo = tmp_path / "fifo.toml"
    os.mkfifo(fifo)
    with pytest.raises(NgcConfigError, match="is not a regular file"):
        machine_from_toml(str(fifo))


@pytest.mark.skipif(os.geteuid() == 0, reason="root reads files whatever their mode")
def test_an_unreadable_toml_file(tmp_path: Path) -> None:
    path = write(tmp_path, "m.toml", "units = \"mm\"\n")
    os.chmod(path, 0)
    with pytest.raises(NgcConfigError) as caught:
        machine_from_toml(path)
    assert caught.value.message == f"cannot open machine file {path}: Permission denied"


def test_load_machine_reports_the_toml_file_over_an_ini(tmp_path: Path) -> None:
    toml = write(tmp_path, "m.toml", "[axes.A]\nmax_velocity = 90\n")
    with pytest.raises(NgcConfigError, match=r"axes\.A: a new axis needs"):
        load_machine(Ini.parse(XYZ_LIMITS), toml)


def test_load_machine_reports_the_ini_first(tmp_path: Path) -> None:
    ini = ini_file(tmp_path, "[TRAJ]\nLINEAR_UNITS = parsec\n" + XYZ_LIMITS)
    with pytest.raises(NgcConfigError, match=r"\[TRAJ\]LINEAR_UNITS is 'parsec'"):
        load_machine(ini, write(tmp_path, "m.toml", "bad key = 1\n"))
