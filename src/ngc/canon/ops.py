"""Canonical machine operations as types, and the sink protocol.

The interpreter describes what the machine does as a stream of these operations, LinuxCNC's
"canonical machining functions" (rs274ngc.adoc).  Each operation is an immutable tuple whose fields
are exactly the arguments rs274 prints; ``TEMPLATES`` gives the printf template rs274 prints each
with, so the text sink is one ``%`` per operation.  Lengths are in the program's current units,
angles in degrees.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping, Sequence
from types import MappingProxyType
from typing import Any, NamedTuple, Protocol


class Op(Protocol):
    """What every canonical operation offers (each is a NamedTuple)."""

    def _asdict(self) -> dict[str, Any]: ...

    def __iter__(self) -> Iterator[Any]: ...


class Sink(Protocol):
    """Where canonical operations go.  ``label`` is the block's N column (``N..... `` if none);
    ``line`` is the 1-based source line the operation comes from (0 outside the program).

    A sink may also offer ``emit_move(kind, fields, label, line)``, taking a move
    (:class:`StraightTraverse`, :class:`StraightFeed` or :class:`ArcFeed`) as its type and a
    sequence of its fields, to the same effect as ``emit(kind(*fields), label, line)``: the
    interpreter then sends moves that way (see :func:`mover`)."""

    def emit(self, op: Op, label: str, line: int) -> None: ...

    def print_text(self, text: str) -> None: ...

    def flush(self) -> None: ...


# -- motion ---------------------------------------------------------------------------------------
class StraightTraverse(NamedTuple):
    x: float
    y: float
    z: float
    a: float
    b: float
    c: float


class StraightFeed(NamedTuple):
    x: float
    y: float
    z: float
    a: float
    b: float
    c: float


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


class NurbsFeed(NamedTuple):
    """A feed along a NURBS curve in the XY plane (G5, G5.1, a G5.2 ... G5.3 block), from the
    current point.  rs274 prints only the number of control points; the op carries the whole
    curve, for the consumers of canon: the control points in program coordinates (the first is the
    start, the last the end), their weights, the order and the knot vector."""

    size: int  # the number of control points
    order: int
    points: tuple[tuple[float, float], ...]
    weights: tuple[float, ...]
    knots: tuple[float, ...]


class Dwell(NamedTuple):
    seconds: float


class StraightProbe(NamedTuple):
    """G38.2-G38.5: a straight move toward the programmed point that stops when the probe input
    changes (the point where it stops is not part of the call)."""

    x: float
    y: float
    z: float
    a: float
    b: float
    c: float


class TurnProbeOn(NamedTuple):
    """No arguments."""


class TurnProbeOff(NamedTuple):
    """No arguments."""


# -- modes ----------------------------------------------------------------------------------------
class UseLengthUnits(NamedTuple):
    units: str  # CANON_UNITS_MM | CANON_UNITS_INCHES


class SelectPlane(NamedTuple):
    plane: str  # CANON_PLANE_XY | _XZ | _YZ | _UNKNOWN


class SetFeedRate(NamedTuple):
    rate: float


class SetFeedMode(NamedTuple):
    spindle: int
    mode: int  # 0 units/minute or inverse time, 1 units/revolution


class SetFeedReference(NamedTuple):
    reference: str


class SetMotionControlMode(NamedTuple):
    mode: str  # CANON_EXACT_STOP | CANON_EXACT_PATH


class SetMotionControlContinuous(NamedTuple):
    tolerance: float


class SetNaivecamTolerance(NamedTuple):
    tolerance: float


class UseToolLengthOffset(NamedTuple):
    x: float
    y: float
    z: float
    a: float
    b: float
    c: float
    u: float
    v: float
    w: float


# -- tools ----------------------------------------------------------------------------------------
class SelectTool(NamedTuple):
    tool: int  # the tool number of the T word


class StartChange(NamedTuple):
    """No arguments."""


class ChangeTool(NamedTuple):
    slot: int  # the selected tool's slot in the tool table (1-based, file order; 0: none)


class ChangeToolNumber(NamedTuple):
    slot: int  # M61: the slot of the tool now in the spindle


class SetToolTableEntry(NamedTuple):
    """G10 L1/L10/L11: a tool's new data, in inches (rs274 prints no diameter)."""

    slot: int
    tool: int
    x: float
    y: float
    z: float
    a: float
    b: float
    c: float
    u: float
    v: float
    w: float
    frontangle: float
    backangle: float
    orientation: int


class ReloadTooldata(NamedTuple):
    """No arguments (G10 L0)."""


# -- offsets --------------------------------------------------------------------------------------
class SetG5xOffset(NamedTuple):
    system: int
    x: float
    y: float
    z: float
    a: float
    b: float
    c: float


class SetG92Offset(NamedTuple):
    x: float
    y: float
    z: float
    a: float
    b: float
    c: float


class SetXYRotation(NamedTuple):
    degrees: float


# -- spindle and coolant --------------------------------------------------------------------------
class SetSpindleSpeed(NamedTuple):
    spindle: int
    rpm: float


class StartSpindleClockwise(NamedTuple):
    spindle: int


class StartSpindleCounterclockwise(NamedTuple):
    spindle: int


class StopSpindleTurning(NamedTuple):
    spindle: int


class SetSpindleMode(NamedTuple):
    spindle: int
    css_max: float


class OrientSpindle(NamedTuple):
    spindle: int
    degrees: float
    direction: int  # M19's P (0 shortest, 1 clockwise, 2 counterclockwise); G87 gives 2 or 3


class WaitOrientComplete(NamedTuple):
    spindle: int
    seconds: float


class StartSpeedFeedSync(NamedTuple):
    """Spindle-synchronized motion (G33, G33.1, G76): ``per_rev`` units per revolution."""

    per_rev: float
    css: int  # 1 in G96 constant surface speed


class StopSpeedFeedSynch(NamedTuple):
    """No arguments."""


class RigidTap(NamedTuple):
    """G33.1: synchronized to the point and back."""

    x: float
    y: float
    z: float


class MistOn(NamedTuple):
    """No arguments."""


class MistOff(NamedTuple):
    """No arguments."""


class FloodOn(NamedTuple):
    """No arguments."""


class FloodOff(NamedTuple):
    """No arguments."""


# -- overrides ------------------------------------------------------------------------------------
class EnableFeedOverride(NamedTuple):
    """No arguments."""


class DisableFeedOverride(NamedTuple):
    """No arguments."""


class EnableSpeedOverride(NamedTuple):
    spindle: int


class DisableSpeedOverride(NamedTuple):
    spindle: int


class EnableAdaptiveFeed(NamedTuple):
    """No arguments."""


class DisableAdaptiveFeed(NamedTuple):
    """No arguments."""


class EnableFeedHold(NamedTuple):
    """No arguments."""


class DisableFeedHold(NamedTuple):
    """No arguments."""


# -- program --------------------------------------------------------------------------------------
class Comment(NamedTuple):
    text: str


class Message(NamedTuple):
    text: str


class LogOpen(NamedTuple):
    file: str


class LogAppend(NamedTuple):
    file: str


class Log(NamedTuple):
    text: str


class LogClose(NamedTuple):
    """No arguments."""


# -- digital and analog outputs (M62-M65, M67, M68) ---------------------------------------------
class SetMotionOutputBit(NamedTuple):
    bit: int


class ClearMotionOutputBit(NamedTuple):
    bit: int


class SetAuxOutputBit(NamedTuple):
    bit: int


class ClearAuxOutputBit(NamedTuple):
    bit: int


class SetMotionOutputValue(NamedTuple):
    channel: int
    value: float


class SetAuxOutputValue(NamedTuple):
    channel: int
    value: float


class ProgramStop(NamedTuple):
    """No arguments."""


class OptionalProgramStop(NamedTuple):
    """No arguments."""


class PalletShuttle(NamedTuple):
    """No arguments."""


class ProgramEnd(NamedTuple):
    """No arguments."""


class Finish(NamedTuple):
    """No arguments."""


class OnReset(NamedTuple):
    """No arguments."""


# How rs274 prints each operation (C printf templates).
TEMPLATES: Mapping[type, str] = MappingProxyType(
    {
        StraightTraverse: "STRAIGHT_TRAVERSE(%.4f, %.4f, %.4f, %.4f, %.4f, %.4f)",
        StraightFeed: "STRAIGHT_FEED(%.4f, %.4f, %.4f, %.4f, %.4f, %.4f)",
        ArcFeed: "ARC_FEED(%.4f, %.4f, %.4f, %.4f, %d, %.4f, %.4f, %.4f, %.4f)",
        NurbsFeed: "NURBS_FEED(%d, ...)",
        Dwell: "DWELL(%.4f)",
        StraightProbe: "STRAIGHT_PROBE(%.4f, %.4f, %.4f, %.4f, %.4f, %.4f)",
        TurnProbeOn: "TURN_PROBE_ON()",
        TurnProbeOff: "TURN_PROBE_OFF()",
        UseLengthUnits: "USE_LENGTH_UNITS(%s)",
        SelectPlane: "SELECT_PLANE(%s)",
        SetFeedRate: "SET_FEED_RATE(%.4f)",
        SetFeedMode: "SET_FEED_MODE(%d, %d)",
        SetFeedReference: "SET_FEED_REFERENCE(%s)",
        SetMotionControlMode: "SET_MOTION_CONTROL_MODE(%s)",
        SetMotionControlContinuous: "SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS, %f)",
        SetNaivecamTolerance: "SET_NAIVECAM_TOLERANCE(%.4f)",
        UseToolLengthOffset: "USE_TOOL_LENGTH_OFFSET(%.4f %.4f %.4f, %.4f %.4f %.4f, %.4f %.4f %.4f)",
        SelectTool: "SELECT_TOOL(%d)",
        StartChange: "START_CHANGE()",
        ChangeTool: "CHANGE_TOOL(%d)",
        ChangeToolNumber: "CHANGE_TOOL_NUMBER(%d)",
        SetToolTableEntry: "SET_TOOL_TABLE_ENTRY(%d, %d, %.4f %.4f %.4f %.4f %.4f %.4f %.4f %.4f %.4f, "
                           "%.4f, %.4f, %d)",
        ReloadTooldata: "RELOAD_TOOLDATA()",
        SetG5xOffset: "SET_G5X_OFFSET(%d, %.4f, %.4f, %.4f, %.4f, %.4f, %.4f)",
        SetG92Offset: "SET_G92_OFFSET(%.4f, %.4f, %.4f, %.4f, %.4f, %.4f)",
        SetXYRotation: "SET_XY_ROTATION(%.4f)",
        SetSpindleSpeed: "SET_SPINDLE_SPEED(%d, %.4f)",
        StartSpindleClockwise: "START_SPINDLE_CLOCKWISE(%d)",
        StartSpindleCounterclockwise: "START_SPINDLE_COUNTERCLOCKWISE(%d)",
        StopSpindleTurning: "STOP_SPINDLE_TURNING(%d)",
        SetSpindleMode: "SET_SPINDLE_MODE(%d %.4f)",
        OrientSpindle: "ORIENT_SPINDLE(%d, %.4f, %d)",
        WaitOrientComplete: "SPINDLE.%d.WAIT_ORIENT_COMPLETE(%.4f)",
        StartSpeedFeedSync: "START_SPEED_FEED_SYNC(%f,%d)",
        StopSpeedFeedSynch: "STOP_SPEED_FEED_SYNCH()",
        RigidTap: "RIGID_TAP(%.4f, %.4f, %.4f)",
        MistOn: "MIST_ON()",
        MistOff: "MIST_OFF()",
        FloodOn: "FLOOD_ON()",
        FloodOff: "FLOOD_OFF()",
        EnableFeedOverride: "ENABLE_FEED_OVERRIDE()",
        DisableFeedOverride: "DISABLE_FEED_OVERRIDE()",
        EnableSpeedOverride: "ENABLE_SPEED_OVERRIDE(%d)",
        DisableSpeedOverride: "DISABLE_SPEED_OVERRIDE(%d)",
        EnableAdaptiveFeed: "ENABLE_ADAPTIVE_FEED()",
        DisableAdaptiveFeed: "DISABLE_ADAPTIVE_FEED()",
        EnableFeedHold: "ENABLE_FEED_HOLD()",
        DisableFeedHold: "DISABLE_FEED_HOLD()",
        Comment: 'COMMENT("%s")',
        Message: 'MESSAGE("%s")',
        LogOpen: 'LOGOPEN("%s")',
        LogAppend: 'LOGAPPEND("%s")',
        Log: 'LOG("%s")',
        LogClose: "LOGCLOSE()",
        SetMotionOutputBit: "SET_MOTION_OUTPUT_BIT(%d)",
        ClearMotionOutputBit: "CLEAR_MOTION_OUTPUT_BIT(%d)",
        SetAuxOutputBit: "SET_AUX_OUTPUT_BIT(%d)",
        ClearAuxOutputBit: "CLEAR_AUX_OUTPUT_BIT(%d)",
        SetMotionOutputValue: "SET_MOTION_OUTPUT_VALUE(%d,%f)",
        SetAuxOutputValue: "SET_AUX_OUTPUT_VALUE(%d,%f)",
        ProgramStop: "PROGRAM_STOP()",
        OptionalProgramStop: "OPTIONAL_PROGRAM_STOP()",
        PalletShuttle: "PALLET_SHUTTLE()",
        ProgramEnd: "PROGRAM_END()",
        Finish: "FINISH()",
        OnReset: "ON_RESET()",
    }
)


# The ops whose text shows only their first fields: how many.
SHOWN: Mapping[type, int] = MappingProxyType({NurbsFeed: 1})


def op_name(op: Op) -> str:
    """The canonical call's name, e.g. ``STRAIGHT_FEED``."""
    return TEMPLATES[type(op)].split("(", 1)[0]


Mover = Callable[[type, Sequence[Any], str, int], None]


def mover(sink: Sink) -> Mover:
    """How moves go to ``sink``: its ``emit_move`` if it has one (see :class:`Sink`), else each
    made into its op and emitted."""
    fast: Mover | None = getattr(sink, "emit_move", None)
    if fast is not None:
        return fast
    emit = sink.emit
    new = tuple.__new__

    def emit_move(kind: type, fields: Sequence[Any], label: str, line: int) -> None:
        emit(new(kind, fields), label, line)

    return emit_move
