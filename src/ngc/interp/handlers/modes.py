"""Modes: feed mode and rate, spindle, coolant, overrides, dwell, plane, units, path control,
distance modes.  Canon calls and comments are rs274's (verified against rs274 2.9.0~pre1)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ...canon import ops
from ...errors import NgcSemanticError
from ..state import AXES, LINEAR, MM_PER_INCH
from . import ccomp, tools

if TYPE_CHECKING:
    from ..machine import Machine
    from ..resolve import Resolved

MOTION_NONE = ops.Comment("interpreter: motion mode set to none")
_FEED_MODE_COMMENTS = {
    930: "interpreter: feed mode set to inverse time",
    940: "interpreter: feed mode set to units per minute",
    950: "interpreter: feed mode set to units per revolution",
}
PLANE_NAMES = {
    170: "CANON_PLANE_XY",
    180: "CANON_PLANE_XZ",
    190: "CANON_PLANE_YZ",
    171: "CANON_PLANE_UNKNOWN",
    181: "CANON_PLANE_UNKNOWN",
    191: "CANON_PLANE_UNKNOWN",
}


def feed_mode(it: Machine, code: int) -> None:
    """G93 / G94 / G95 (G93 sets no rate: each inverse-time move does)."""
    it.emit(ops.Comment(_FEED_MODE_COMMENTS[code]))
    it.state.feed_mode = code
    it.emit(ops.SetFeedMode(0, 1 if code == 950 else 0))
    if code != 930:
        it.state.feed = 0.0
        it.emit(ops.SetFeedRate(0.0))


def feed_rate(it: Machine, f: float) -> None:
    """F: the rate is given to the machine now, except in inverse time (per move)."""
    if f < 0.0:
        raise NgcSemanticError("Negative f word used")
    if it.state.feed_mode != 930:  # in inverse time the F word is per move (see motion.feed)
        it.state.feed = f
        it.emit(ops.SetFeedRate(f))


def spindle_speed(it: Machine, s: float) -> None:
    if s < 0.0:
        raise NgcSemanticError("Negative spindle speed used")
    it.state.speed = s
    it.emit(ops.SetSpindleSpeed(0, s))


def spindle(it: Machine, code: int) -> None:
    """M3 / M4 / M5."""
    if code == 3:
        it.state.spindle = 1
        it.emit(ops.StartSpindleClockwise(0))
    elif code == 4:
        it.state.spindle = -1
        it.emit(ops.StartSpindleCounterclockwise(0))
    else:
        it.state.spindle = 0
        it.emit(ops.StopSpindleTurning(0))


def coolant(it: Machine, code: int) -> None:
    """M7 mist, M8 flood, M9 both off."""
    st = it.state
    if code == 7:
        st.mist = True
        it.emit(ops.MistOn())
    elif code == 8:
        st.flood = True
        it.emit(ops.FloodOn())
    else:
        st.mist = st.flood = False
        it.emit(ops.MistOff())
        it.emit(ops.FloodOff())


def overrides(it: Machine, code: int, p: float | None) -> None:
    """M48 / M49 both overrides; M50 feed, M51 speed, M52 adaptive feed, M53 feed hold (P0 off)."""
    st = it.state
    on = p is None or p != 0.0
    if code == 48:
        st.feed_override = st.speed_override = True
        it.emit(ops.EnableFeedOverride())
        it.emit(ops.EnableSpeedOverride(0))
    elif code == 49:
        st.feed_override = st.speed_override = False
        it.emit(ops.DisableFeedOverride())
        it.emit(ops.DisableSpeedOverride(0))
    elif code == 50:
        st.feed_override = on
        it.emit(ops.EnableFeedOverride() if on else ops.DisableFeedOverride())
    elif code == 51:
        st.speed_override = on
        it.emit(ops.EnableSpeedOverride(0) if on else ops.DisableSpeedOverride(0))
    elif code == 52:
        st.adaptive_feed = on
        it.emit(ops.EnableAdaptiveFeed() if on else ops.DisableAdaptiveFeed())
    else:
        st.feed_hold = on
        it.emit(ops.EnableFeedHold() if on else ops.DisableFeedHold())


def dwell(it: Machine, r: Resolved) -> None:
    """G4 P seconds."""
    p = r.w.get("p")
    if p is None or p < 0.0:
        raise NgcSemanticError("Dwell time missing with g4")
    it.emit(ops.Dwell(p))


def plane(it: Machine, code: int) -> None:
    it.state.plane = code
    it.emit(ops.SelectPlane(PLANE_NAMES[code]))


def units(it: Machine, code: int) -> None:
    """G20 / G21: position and offsets are converted; stored parameters are not (inches)."""
    st = it.state
    metric = code == 210
    if metric != st.metric:
        if not metric:
            # rs274's canon divides its point by 25.4 where the interpreter multiplies by
            # 1/25.4: the last bit may differ, which a probe (or M6) taking the canon's point shows
            tools.hold_canon(st)
        k = MM_PER_INCH if metric else 1.0 / MM_PER_INCH
        for vec in (st.pos, st.g5x, st.g92):
            for i in range(AXES):
                if LINEAR[i]:
                    vec[i] *= k
        st.metric = metric
        if not metric:
            tools.held(st)
    it.emit(ops.UseLengthUnits("CANON_UNITS_MM" if metric else "CANON_UNITS_INCHES"))


def control_mode(it: Machine, code: int, r: Resolved) -> None:
    """G61 exact path, G61.1 exact stop, G64 [P tolerance [Q naive-cam tolerance]]."""
    st = it.state
    st.control_mode = code
    if code == 610:
        it.emit(ops.SetMotionControlMode("CANON_EXACT_PATH"))
    elif code == 611:
        it.emit(ops.SetMotionControlMode("CANON_EXACT_STOP"))
    else:
        p = max(r.w.get("p", 0.0), 0.0)
        q = max(r.w.get("q", p), 0.0)
        st.path_tolerance = p
        st.naive_tolerance = q
        it.emit(ops.SetMotionControlContinuous(p))
        it.emit(ops.SetNaivecamTolerance(q))


def distance_mode(it: Machine, code: int) -> None:
    """G90 / G91."""
    _announce_distance(it, "distance", it.state.absolute, code == 900)
    it.state.absolute = code == 900


def arc_distance_mode(it: Machine, code: int) -> None:
    """G90.1 / G91.1: arc centers absolute or relative to the start point."""
    _announce_distance(it, "IJK distance", it.state.arc_absolute, code == 901)
    it.state.arc_absolute = code == 901


def _announce_distance(it: Machine, what: str, was_absolute: bool, absolute: bool) -> None:
    """rs274 comments on a change of a distance mode (not on a repeat)."""
    if absolute != was_absolute:
        word = "absolute" if absolute else "incremental"
        it.emit(ops.Comment(f"interpreter: {what} mode changed to {word}"))


def cutter_comp_off(it: Machine) -> None:
    """G40 (see handlers/ccomp.py)."""
    ccomp.stop(it)


def retract_mode(it: Machine, code: int) -> None:
    """G98 / G99: where canned cycles retract to (rs274 comments on each)."""
    it.state.retract_r = code == 990
    it.emit(ops.Comment(
        "interpreter: retract mode set to " + ("r_plane" if code == 990 else "old_z")
    ))
