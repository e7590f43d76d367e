"""Canonical machine operations as types, and the sink protocol.

The interpreter describes what the machine does as a stream of these operations, LinuxCNC's
"canonical machining functions" (rs274ngc.adoc).  Each operation is an immutable tuple whose fields
are exactly the arguments rs274 prints, and whose ``TEXT`` is the printf template rs274 uses, so the
text sink is one ``%`` per operation.  Lengths are in the program's current units, angles in degrees.
"""

from __future__ import annotations

from typing import ClassVar, NamedTuple, Protocol


class Op(Protocol):
    """What every canonical operation offers."""

    TEXT: ClassVar[str]

    def _asdict(self) -> dict[str, object]: ...


class Sink(Protocol):
    """Where canonical operations go.  ``label`` is the block's N column (``N..... `` if none);
    ``line`` is the 1-based source line the operation comes from (0 outside the program)."""

    def emit(self, op: Op, label: str, line: int) -> None: ...

    def print_text(self, text: str) -> None: ...


# -- motion ---------------------------------------------------------------------------------------
class StraightTraverse(NamedTuple):
    x: float
    y: float
    z: float
    a: float
    b: float
    c: float
    TEXT = "STRAIGHT_TRAVERSE(%.4f, %.4f, %.4f, %.4f, %.4f, %.4f)"


class StraightFeed(NamedTuple):
    x: float
    y: float
    z: float
    a: float
    b: float
    c: float
    TEXT = "STRAIGHT_FEED(%.4f, %.4f, %.4f, %.4f, %.4f, %.4f)"


class ArcFeed(NamedTuple):
    first_end: float
    second_end: float
    first_axis: float
    second_axis: float
    rotation: int
    axis_end_point: float
    a: float
    b: float
    c: float
    TEXT = "ARC_FEED(%.4f, %.4f, %.4f, %.4f, %d, %.4f, %.4f, %.4f, %.4f)"


class Dwell(NamedTuple):
    seconds: float
    TEXT = "DWELL(%.4f)"


# -- modes ----------------------------------------------------------------------------------------
class UseLengthUnits(NamedTuple):
    units: str  # CANON_UNITS_MM | CANON_UNITS_INCHES
    TEXT = "USE_LENGTH_UNITS(%s)"


class SelectPlane(NamedTuple):
    plane: str  # CANON_PLANE_XY | _XZ | _YZ | _UNKNOWN
    TEXT = "SELECT_PLANE(%s)"


class SetFeedRate(NamedTuple):
    rate: float
    TEXT = "SET_FEED_RATE(%.4f)"


class SetFeedMode(NamedTuple):
    spindle: int
    mode: int  # 0 units/minute or inverse time, 1 units/revolution
    TEXT = "SET_FEED_MODE(%d, %d)"


class SetFeedReference(NamedTuple):
    reference: str
    TEXT = "SET_FEED_REFERENCE(%s)"


class SetMotionControlMode(NamedTuple):
    mode: str  # CANON_EXACT_STOP | CANON_EXACT_PATH
    TEXT = "SET_MOTION_CONTROL_MODE(%s)"


class SetMotionControlContinuous(NamedTuple):
    tolerance: float
    TEXT = "SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS, %f)"


class SetNaivecamTolerance(NamedTuple):
    tolerance: float
    TEXT = "SET_NAIVECAM_TOLERANCE(%.4f)"


# -- offsets --------------------------------------------------------------------------------------
class SetG5xOffset(NamedTuple):
    index: int
    x: float
    y: float
    z: float
    a: float
    b: float
    c: float
    TEXT = "SET_G5X_OFFSET(%d, %.4f, %.4f, %.4f, %.4f, %.4f, %.4f)"


class SetG92Offset(NamedTuple):
    x: float
    y: float
    z: float
    a: float
    b: float
    c: float
    TEXT = "SET_G92_OFFSET(%.4f, %.4f, %.4f, %.4f, %.4f, %.4f)"


class SetXYRotation(NamedTuple):
    degrees: float
    TEXT = "SET_XY_ROTATION(%.4f)"


# -- spindle and coolant --------------------------------------------------------------------------
class SetSpindleSpeed(NamedTuple):
    spindle: int
    rpm: float
    TEXT = "SET_SPINDLE_SPEED(%d, %.4f)"


class StartSpindleClockwise(NamedTuple):
    spindle: int
    TEXT = "START_SPINDLE_CLOCKWISE(%d)"


class StartSpindleCounterclockwise(NamedTuple):
    spindle: int
    TEXT = "START_SPINDLE_COUNTERCLOCKWISE(%d)"


class StopSpindleTurning(NamedTuple):
    spindle: int
    TEXT = "STOP_SPINDLE_TURNING(%d)"


class SetSpindleMode(NamedTuple):
    spindle: int
    css_max: float
    TEXT = "SET_SPINDLE_MODE(%d %.4f)"


class MistOn(NamedTuple):
    TEXT = "MIST_ON()"


class MistOff(NamedTuple):
    TEXT = "MIST_OFF()"


class FloodOn(NamedTuple):
    TEXT = "FLOOD_ON()"


class FloodOff(NamedTuple):
    TEXT = "FLOOD_OFF()"


# -- overrides ------------------------------------------------------------------------------------
class EnableFeedOverride(NamedTuple):
    TEXT = "ENABLE_FEED_OVERRIDE()"


class DisableFeedOverride(NamedTuple):
    TEXT = "DISABLE_FEED_OVERRIDE()"


class EnableSpeedOverride(NamedTuple):
    spindle: int
    TEXT = "ENABLE_SPEED_OVERRIDE(%d)"


class DisableSpeedOverride(NamedTuple):
    spindle: int
    TEXT = "DISABLE_SPEED_OVERRIDE(%d)"


class EnableAdaptiveFeed(NamedTuple):
    TEXT = "ENABLE_ADAPTIVE_FEED()"


class DisableAdaptiveFeed(NamedTuple):
    TEXT = "DISABLE_ADAPTIVE_FEED()"


class EnableFeedHold(NamedTuple):
    TEXT = "ENABLE_FEED_HOLD()"


class DisableFeedHold(NamedTuple):
    TEXT = "DISABLE_FEED_HOLD()"


# -- program --------------------------------------------------------------------------------------
class Comment(NamedTuple):
    text: str
    TEXT = 'COMMENT("%s")'


class Message(NamedTuple):
    text: str
    TEXT = 'MESSAGE("%s")'


class ProgramStop(NamedTuple):
    TEXT = "PROGRAM_STOP()"


class OptionalProgramStop(NamedTuple):
    TEXT = "OPTIONAL_PROGRAM_STOP()"


class PalletShuttle(NamedTuple):
    TEXT = "PALLET_SHUTTLE()"


class ProgramEnd(NamedTuple):
    TEXT = "PROGRAM_END()"


class Finish(NamedTuple):
    TEXT = "FINISH()"


class OnReset(NamedTuple):
    TEXT = "ON_RESET()"
