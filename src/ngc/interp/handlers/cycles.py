"""Canned cycles: G73 drilling with chip breaking, G74 left-hand tapping, G81 drilling, G82
drilling with dwell, G83 peck drilling, G84 right-hand tapping, G85 boring with feed out, G86
boring with spindle stop and rapid out, G87 back boring, G88 boring with spindle stop and manual
out, G89 boring with dwell and feed out (g-code.adoc, "G80-G89 Canned Cycles"), in the XY, XZ and
YZ planes.

What rs274 does, as it shows it:

* Checks, in this order: a zero feed rate, inverse time, cutter compensation on, no R word
  (R is sticky: taken from the last cycle if the same cycle is the motion mode), L0, then by
  plane: an X, Y or Z word in a UVW plane; no word for the drill axis (sticky as R); the R plane
  below the bottom.
* The *initial level* is the drill axis' position when a series of cycles began; the series
  lasts while the motion mode stays a canned cycle (another motion code, G80 included, ends it),
  through changes of plane (the level is then a number taken on another axis).  In G91, R is
  relative to that level and the bottom relative to R.  If the level is below R, the drill axis
  first goes (up or down) to R at the current point, once, whatever L.  Then the drill goes across
  at the height it is at, if that is above R; else at the retract height.
* Retract height ("clear"): R in G99; in G98, the level (R if that is higher).
* Unless the path mode is G61, the cycle runs in exact-path mode and the mode in force is given
  back after it (with the naive-CAM tolerance).
* Each of the L repeats: a traverse in the plane at the level, a traverse to R if the level is not
  R, the cycle's own moves, and the level becomes the clear height.  In G91 the plane's axis words
  are offsets added on each repeat.
* The dwell's P (G82, G86, G88, G89) is sticky too; P-1 counts as no P.  It is checked after the
  move up to R and the switch to exact-path mode.  G84's P may be left out, even on its first
  cycle: the last P of any cycle is used (0 at first).
* The peck depth's Q (G73, G83) is sticky as P is, Q-1 counting as no Q ("Q word missing with
  g83", checked where P is).  At each hole, after the moves to it, Q must be above 0 ("Negative or
  zero q value used").  From R, each depth is the last one less Q (in floating point, one after
  the other) while it is above the bottom: a feed to it, then (G83) a traverse out to R, and a
  traverse to that depth plus 0.01 in or 0.254 mm.  The last feed goes to the bottom, then a
  traverse to clear.
* G86 and G88, at each hole after the moves to it: the spindle must turn ("Spindle not turning in
  g86"), either way.  The feed to the bottom, the dwell, the spindle stops; G86 traverses to
  clear, G88 stops the program (the tool is taken out by hand, no move: rs274 then has it at
  clear); the spindle starts again the way it turned.
* G84, at each hole after the moves to it: the spindle must turn clockwise ("Spindle not turning in
  G84", "Spindle turning counterclockwise in G84"; its speed may be 0).  Both overrides are turned
  off, the feed in goes to the bottom, the spindle stops and turns counterclockwise, the dwell, the
  feed out goes to clear, the spindle stops and turns clockwise, and each override that was on is
  turned back on.  rs274 writes the two feeds' X, Y, Z turned round in the XZ and YZ planes.
  G74 is G84 with the spindle turning the other way ("Spindle turning clockwise in G74"); it
  takes no L word.
* G87, the I J K words (each sticky as P; "I word missing with g87", checked where P is) are, on
  the plane's two axes, the offset of the point where the tool goes down through the hole with
  the spindle stopped and oriented, and on the drill axis the height it bores back up to
  (absolute in G90, from the bottom in G91).  At each hole the spindle must turn ("Spindle not
  turning in g87").
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from ...canon import ops
from ...errors import NgcSemanticError
from ...language.codes import CYCLE_COMP
from .. import comp
from . import ccomp, motion

if TYPE_CHECKING:
    from ..machine import Machine
    from ..resolve import Resolved

# plane code -> (index of the drill axis, its letter, the plane's name in rs274's messages)
_DRILL_AXES = {170: (2, "z", "xy"), 180: (1, "y", "xz"), 190: (0, "x", "yz")}
# the UVW planes, by their names in rs274's messages
_UVW_PLANES = {171: "UV", 181: "UW", 191: "VW"}
_ARTICLES = {"x": "an", "y": "a", "z": "a"}

# What a cycle does at the hole, given (machine, point, drill axis, bottom, R, clear, dwell or peck
# depth); the moves start at R.
Body = Callable[["Machine", list[float], int, float, float, float, float], None]


def _drill(it: Machine, at: list[float], axis: int, bottom: float, rr: float, clear: float,
           dwell: float) -> None:
    """G81: feed to the bottom, traverse to clear."""
    _feed(it, _at(at, axis, bottom))
    motion.traverse(it, _at(at, axis, clear))


def _drill_dwell(it: Machine, at: list[float], axis: int, bottom: float, rr: float, clear: float,
                 dwell: float) -> None:
    """G82: feed to the bottom, dwell, traverse to clear."""
    _feed(it, _at(at, axis, bottom))
    it.emit(ops.Dwell(dwell))
    motion.traverse(it, _at(at, axis, clear))


def _chip_break(it: Machine, at: list[float], axis: int, bottom: float, rr: float, clear: float,
                delta: float) -> None:
    """G73: feed down by Q at a time, backing off a little between the pecks."""
    _pecks(it, at, axis, bottom, rr, clear, delta, out=False)


def _peck(it: Machine, at: list[float], axis: int, bottom: float, rr: float, clear: float,
          delta: float) -> None:
    """G83: feed down by Q at a time, out to R and back down near the last depth between pecks."""
    _pecks(it, at, axis, bottom, rr, clear, delta, out=True)


def _pecks(it: Machine, at: list[float], axis: int, bottom: float, rr: float, clear: float,
           delta: float, out: bool) -> None:
    """Feeds down ``delta`` at a time from R (each depth the last less ``delta``, while above the
    bottom); after each but the last, a traverse out to R if ``out``, and one to the depth plus the
    peck clearance; the last feed goes to the bottom, then a traverse to clear."""
    if delta <= 0.0:
        raise NgcSemanticError("Negative or zero q value used")
    back = _PECK_CLEARANCE_MM if it.state.metric else _PECK_CLEARANCE_INCH
    depth = rr - delta
    while depth > bottom:
        it.work()  # (Q sets how many pecks there are)
        _feed(it, _at(at, axis, depth))
        if out:
            motion.traverse(it, _at(at, axis, rr))
        motion.traverse(it, _at(at, axis, depth + back))
        depth -= delta
    _feed(it, _at(at, axis, bottom))
    motion.traverse(it, _at(at, axis, clear))


def _tap(it: Machine, at: list[float], axis: int, bottom: float, rr: float, clear: float,
         dwell: float) -> None:
    """G84: feed to the bottom, reverse the spindle, dwell, feed out to clear, overrides off."""
    _tapping(it, at, axis, bottom, clear, dwell, 1)


def _tap_left(it: Machine, at: list[float], axis: int, bottom: float, rr: float, clear: float,
              dwell: float) -> None:
    """G74: G84 with the spindle turning the other way (in counterclockwise, out clockwise)."""
    _tapping(it, at, axis, bottom, clear, dwell, -1)


_TURNS: dict[int, ops.StartSpindleClockwise | ops.StartSpindleCounterclockwise] = {
    1: ops.StartSpindleClockwise(0), -1: ops.StartSpindleCounterclockwise(0)}
_TURN_NAMES = {1: "clockwise", -1: "counterclockwise"}


def _tapping(it: Machine, at: list[float], axis: int, bottom: float, clear: float, dwell: float,
             way: int) -> None:
    """G84 (``way`` 1: the spindle turns clockwise going in) and G74 (``way`` -1)."""
    st = it.state
    name = "G84" if way > 0 else "G74"
    if st.spindle == 0:
        raise NgcSemanticError(f"Spindle not turning in {name}")
    if st.spindle * way < 0:
        raise NgcSemanticError(f"Spindle turning {_TURN_NAMES[-way]} in {name}")
    it.emit(ops.DisableFeedOverride())
    it.emit(ops.DisableSpeedOverride(0))
    _tap_feed(it, _at(at, axis, bottom), axis)
    it.emit(ops.StopSpindleTurning(0))
    it.emit(_TURNS[-way])
    it.emit(ops.Dwell(dwell))
    _tap_feed(it, _at(at, axis, clear), axis)
    it.emit(ops.StopSpindleTurning(0))
    it.emit(_TURNS[way])
    if st.feed_override:  # the overrides come back as they were
        it.emit(ops.EnableFeedOverride())
    if st.speed_override:
        it.emit(ops.EnableSpeedOverride(0))


def _bore_stop(it: Machine, at: list[float], axis: int, bottom: float, rr: float, clear: float,
               dwell: float) -> None:
    """G86: feed to the bottom, dwell, stop the spindle, traverse to clear, restart the spindle."""
    restart = _turning(it, "g86")
    _feed(it, _at(at, axis, bottom))
    it.emit(ops.Dwell(dwell))
    it.emit(ops.StopSpindleTurning(0))
    motion.traverse(it, _at(at, axis, clear))
    it.emit(restart)


def _bore_manual(it: Machine, at: list[float], axis: int, bottom: float, rr: float, clear: float,
                 dwell: float) -> None:
    """G88: feed to the bottom, dwell, stop the spindle, program stop (out by hand), restart it."""
    restart = _turning(it, "g88")
    _feed(it, _at(at, axis, bottom))
    it.emit(ops.Dwell(dwell))
    it.emit(ops.StopSpindleTurning(0))
    it.emit(ops.ProgramStop())
    it.emit(restart)
    it.state.pos = _at(at, axis, clear)  # the operator took the tool out: rs274 has it at clear


def _turning(it: Machine, name: str) -> ops.StartSpindleClockwise | ops.StartSpindleCounterclockwise:
    """The call that starts the spindle the way it turns; it must be turning."""
    if it.state.spindle == 0:
        raise NgcSemanticError(f"Spindle not turning in {name}")
    if it.state.spindle > 0:
        return ops.StartSpindleClockwise(0)
    return ops.StartSpindleCounterclockwise(0)


def _back_bore(it: Machine, at: list[float], axis: int, bottom: float, rr: float, clear: float,
               dwell: float) -> None:
    """G87: from R, out to the offset point (the plane's I J K words), stop and orient the
    spindle, down to the bottom there, back to the hole's axis, restart the spindle, feed up to
    the back-bore height and back down, stop and orient again, out to the offset point, up to
    clear, back to the hole's axis, restart the spindle."""
    st = it.state
    restart = _turning(it, "g87")
    orient = ops.OrientSpindle(0, 0.0, 2 if st.spindle > 0 else 3)
    side = [a + st.cycle_offsets[i] if i != axis and i < 3 else a for i, a in enumerate(at)]
    motion.traverse(it, _at(side, axis, rr))
    it.emit(ops.StopSpindleTurning(0))
    it.emit(orient)
    motion.traverse(it, _at(side, axis, bottom))
    motion.traverse(it, _at(at, axis, bottom))
    it.emit(restart)
    height = st.cycle_offsets[axis] + (0.0 if st.absolute else bottom)
    _feed(it, _at(at, axis, height))
    _feed(it, _at(at, axis, bottom))
    it.emit(ops.StopSpindleTurning(0))
    it.emit(orient)
    motion.traverse(it, _at(side, axis, bottom))
    motion.traverse(it, _at(side, axis, clear))
    motion.traverse(it, _at(at, axis, clear))
    it.emit(restart)


def _bore(it: Machine, at: list[float], axis: int, bottom: float, rr: float, clear: float,
          dwell: float) -> None:
    """G85: feed to the bottom, feed back to R, traverse to clear."""
    _feed(it, _at(at, axis, bottom))
    _feed(it, _at(at, axis, rr))
    motion.traverse(it, _at(at, axis, clear))


def _bore_dwell(it: Machine, at: list[float], axis: int, bottom: float, rr: float, clear: float,
                dwell: float) -> None:
    """G89: feed to the bottom, dwell, feed out to clear."""
    _feed(it, _at(at, axis, bottom))
    it.emit(ops.Dwell(dwell))
    _feed(it, _at(at, axis, clear))


_NO_DWELL = -1.0  # rs274 reads P-1 as no P, and Q-1 as no Q
# How far above the last depth G73 and G83 go back down: rs274's defaults, which it keeps even when
# its INI file (-i) sets G73_PECK_CLEARANCE or G83_PECK_CLEARANCE
_PECK_CLEARANCE_INCH = 0.01
_PECK_CLEARANCE_MM = 0.254
# ``dwells``: no dwell; a dwell whose P is needed unless the same cycle ran last; a dwell whose P
# may be left out (the last P is used, 0 at first)
_P_NONE, _P_REQUIRED, _P_OPTIONAL = 0, 1, 2


def _cycle(it: Machine, r: Resolved, code: int, body: Body, dwells: int,
           pecks: bool, offsets: bool) -> None:
    st = it.state
    w = r.w
    if st.feed == 0.0:
        raise NgcSemanticError("Cannot feed with zero feed rate")
    if st.feed_mode == 930:
        raise NgcSemanticError("Cannot use inverse time feed with canned cycles")
    ccomp.refuse(it, CYCLE_COMP)
    same = st.motion == code  # the same cycle again: its R, Z and P words are sticky
    if "r" in w:
        r_word = w["r"]
    elif same:
        r_word = st.cycle_r
    else:
        raise NgcSemanticError("R clearance plane unspecified in cycle")
    repeats = int(w.get("l", 1.0))
    if repeats == 0:
        raise NgcSemanticError("Cannot do zero repeats of cycle")
    uvw = _UVW_PLANES.get(st.plane)
    if uvw is not None:
        for letter in "xyz":
            if letter in w:
                raise NgcSemanticError(f"Cannot put {_ARTICLES[letter]} {letter.upper()} in a canned "
                                       f"cycle in the {uvw} plane")
        raise NgcSemanticError("All axes missing with motion code")
    axis, letter, plane = _DRILL_AXES[st.plane]
    if letter in w:
        depth = w[letter]
    elif same:
        depth = st.cycle_z
    else:
        raise NgcSemanticError(f"{letter.upper()} value unspecified in {plane} plane canned cycle")
    pos = st.pos if it.comp is None else it.comp.prog
    series = st.motion == st.cycle_code  # a cycle follows a cycle
    initial = st.cycle_level if series else pos[axis]
    at = list(pos)
    steps = [0.0] * len(pos)
    if st.absolute:
        rr, bottom = r_word, depth
        for i, a in enumerate("xyz"):
            if i != axis and a in w:
                at[i] = w[a]
    else:
        rr = r_word + initial
        bottom = rr + depth
        for i, a in enumerate("xyz"):
            if i != axis:
                steps[i] = w.get(a, 0.0)
    if rr < bottom:
        raise NgcSemanticError(f"R less than {letter} in cycle in {plane} plane")
    st.cycle_code = code
    st.cycle_level = initial
    level = pos[axis]  # where the drill is (on a new plane's axis, too)
    if initial < rr:
        motion.traverse(it, _at(pos, axis, rr))
        level = rr
    clear = rr if st.retract_r else max(initial, rr)
    if level <= rr:
        level = clear
    framed = st.control_mode != 610
    if framed:
        it.emit(ops.SetMotionControlMode("CANON_EXACT_PATH"))
    dwell = _NO_DWELL
    if dwells != _P_NONE:
        dwell = w.get("p", _NO_DWELL)
        if dwell == _NO_DWELL:
            if not same and dwells != _P_OPTIONAL:
                raise NgcSemanticError(f"Dwell time p word missing with g{code // 10}")
            dwell = st.cycle_p
        st.cycle_p = dwell
    if offsets:  # G87's I J K, each sticky as P
        st.cycle_offsets = _offsets(st.cycle_offsets, w, same, code)
    if pecks:  # the peck depth, Q, sticky as P; the body gets it instead of a dwell
        dwell = w.get("q", _NO_DWELL)
        if dwell == _NO_DWELL:
            if not same:
                raise NgcSemanticError(f"Q word missing with g{code // 10}")
            dwell = st.cycle_q
        st.cycle_q = dwell
    polar = "@" in w or "^" in w
    for _ in range(repeats):
        it.work()
        if polar:  # the XY point from its distance and angle (in G91: added to the current ones)
            at[0], at[1] = motion.polar_end(at, w, st.absolute)[:2]
        for i in range(len(at)):
            at[i] += steps[i]
        motion.traverse(it, _at(at, axis, level))
        if level != rr:
            motion.traverse(it, _at(at, axis, rr))
        body(it, at, axis, bottom, rr, clear, dwell)
        level = clear
    if framed:
        _restore_mode(it)
    st.cycle_r = r_word
    st.cycle_z = depth
    st.motion = code


def _offsets(last: tuple[float, float, float], w: dict[str, float], same: bool,
             code: int) -> tuple[float, float, float]:
    """The I J K words of G87 (each the last one's if left out in a series of G87)."""
    values = list(last)
    for i, letter in enumerate("ijk"):
        if letter in w:
            values[i] = w[letter]
        elif not same:
            raise NgcSemanticError(f"{letter.upper()} word missing with g{code // 10}")
    return values[0], values[1], values[2]


def _restore_mode(it: Machine) -> None:
    st = it.state
    if st.control_mode == 611:
        it.emit(ops.SetMotionControlMode("CANON_EXACT_STOP"))
    else:
        it.emit(ops.SetMotionControlContinuous(st.path_tolerance))
    it.emit(ops.SetNaivecamTolerance(st.naive_tolerance))


def _at(point: list[float], axis: int, value: float) -> list[float]:
    """``point`` with the drill axis at ``value`` (a new list: a move keeps its end)."""
    end = list(point)
    end[axis] = value
    return end


def _feed(it: Machine, end: list[float]) -> None:
    if it.comp is not None:
        comp.straight(it, ops.StraightFeed, end)
        return
    it.move(ops.StraightFeed, end, it.label, it.line)
    it.state.pos = end


def _tap_feed(it: Machine, end: list[float], axis: int) -> None:
    """G84's feeds: rs274 writes their X, Y, Z turned round in the XZ plane (Y, Z, X) and the YZ
    plane (Z, X, Y), though the tool is where it should be (the next moves start from ``end``)."""
    shown = list(end)
    if axis != 2:
        turn = (1, 2, 0) if axis == 1 else (2, 0, 1)
        shown[0:3] = [end[i] for i in turn]
    it.move(ops.StraightFeed, shown, it.label, it.line)
    it.state.pos = end


# The handler of each cycle in the code table: what it does at the hole, how it takes P, whether
# it takes Q, whether it takes I J K.
CYCLES: dict[str, tuple[Body, int, bool, bool]] = {
    "chip_break": (_chip_break, _P_NONE, True, False),  # G73
    "tap_left": (_tap_left, _P_OPTIONAL, False, False),  # G74
    "drill": (_drill, _P_NONE, False, False),  # G81
    "drill_dwell": (_drill_dwell, _P_REQUIRED, False, False),  # G82
    "peck": (_peck, _P_NONE, True, False),  # G83
    "tap": (_tap, _P_OPTIONAL, False, False),  # G84
    "bore": (_bore, _P_NONE, False, False),  # G85
    "bore_stop": (_bore_stop, _P_REQUIRED, False, False),  # G86
    "back_bore": (_back_bore, _P_NONE, False, True),  # G87
    "bore_manual": (_bore_manual, _P_REQUIRED, False, False),  # G88
    "bore_dwell": (_bore_dwell, _P_REQUIRED, False, False),  # G89
}


def handler(name: str) -> Callable[[Machine, Resolved, int], None]:
    """The step of the cycle ``name`` names in the code table (see :data:`CYCLES`)."""
    body, dwells, pecks, offsets = CYCLES[name]

    def run(it: Machine, r: Resolved, code: int) -> None:
        _cycle(it, r, code, body, dwells, pecks, offsets)

    return run
