"""Cutter radius compensation: the geometry and the held moves (tool-compensation.adoc,
g-code.adoc G40-G42.1), as rs274 shows them.

While compensation is on, the tool runs beside the programmed path, one radius away, to its left
(G41) or right (G42) in the XY (G17) or XZ (G18) plane.  The end of a move depends on the next
move, so each move in the plane is *held* until the next one arrives: it is the first item of
``Machine.held``; the moves out of the plane (Z only in XY) and the canon calls that follow it
(comments, feed, spindle, coolant, dwell, stops: :data:`HELD`) queue behind it, and all are
emitted, under the label of the block that releases them, when the next move in the plane
decides the corner, at G40, or at M2/M30.

Corners, as rs274 turns them (angles in radians, measured between the tangents):

* within :data:`SMALL` of straight: the next move starts where the held one ends;
* outside (away from the compensation side): an arc of the tool radius around the programmed
  corner joins the two;
* inside: the held move's end becomes the intersection of the two offset paths; a held straight
  move that then runs backwards cannot be cut without gouging.

The first move after G41/G42 (the entry move) goes from the current point to the end offset
perpendicular to that move (a line) or radially (an arc, whose center moves along the end's radius
so that it still starts at the current point).  The move after G40 (the exit move) goes straight
from the compensated point to the programmed end; an arc there is an error.

Positions: ``State.pos`` is the compensated point (as #5420-#5428 show it); :attr:`prog` holds the
programmed one, from which the next block's end is computed.  Lathe tools (G41.1/G42.1 L1-L8 in
XZ) shift the whole compensated path by the radius toward the tool's orientation; the current
point shown (``State.pos``) is the compensated one before that shift.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, NoReturn, Protocol

from ..canon import ops
from ..errors import NgcSemanticError
from ..numeric.longdouble import HALF_PI_REST, PI_REST, TWO_PI_REST, long_sum

if TYPE_CHECKING:
    from ..canon.ops import Mover, Op, Sink
    from .state import State


class Machine(Protocol):
    """What compensation uses of the :class:`~ngc.interp.machine.Machine` (which holds it)."""

    comp: Compensation | None
    held: list[Any]
    state: State
    sink: Sink
    move: Mover
    label: str
    line: int

    def emit(self, op: Op) -> None: ...

SMALL = 0.05  # radians: a corner closer to straight than this is neither trimmed nor rounded
ARC_SLACK_MM = 0.0254  # see Compensation.slack
WHOLE_TURN_SLIP = 1e-12  # radians: an arc turning no more than this from start to end is whole
ENTRY_FLAT = 0.0001  # an entry arc whose chord is within this cosine of square to the radius
REVERSAL = math.pi - SMALL  # a turn beyond this is a reversal: the curvatures decide its side
PI = math.pi
HALF_PI = math.pi / 2
TWO_PI = 2 * math.pi

# The canon calls that wait behind a held move (everything else is emitted at once).
HELD = frozenset({
    ops.Comment, ops.SetFeedRate, ops.SetFeedMode, ops.SetSpindleSpeed, ops.StartSpindleClockwise,
    ops.StartSpindleCounterclockwise, ops.StopSpindleTurning, ops.MistOn, ops.MistOff, ops.FloodOn,
    ops.FloodOff, ops.Dwell, ops.ProgramStop, ops.OptionalProgramStop, ops.PalletShuttle,
})

# Lathe tool orientation (L word) -> the path's shift in (X, Z), in tool radii.
ORIENTATION_SHIFT: dict[int, tuple[float, float]] = {
    1: (-1.0, 1.0), 2: (-1.0, -1.0), 3: (1.0, -1.0), 4: (1.0, 1.0),
    5: (0.0, 1.0), 6: (-1.0, 0.0), 7: (0.0, -1.0), 8: (1.0, 0.0),
}

# plane code -> (first axis, second axis, helix axis)
PLANE_AXES = {170: (0, 1, 2), 180: (2, 0, 1)}

LINE = 1
ARC = 2

_atan2 = math.atan2
_cos = math.cos
_sin = math.sin
_hypot = math.hypot


def _turn_up(angle: float) -> float:
    """``angle + 2 pi``, summed in long double and stored as a double."""
    return long_sum(angle, TWO_PI, TWO_PI_REST)



class Compensation:
    """Compensation on (``side`` 1 left, -1 right) or just turned off (``side`` 0: the exit move
    is next)."""

    __slots__ = (
        "a",
        "b",
        "ca",
        "cb",
        "first",
        "h",
        "item",
        "ka",
        "kb",
        "kind",
        "kr",
        "pdir",
        "prog",
        "radius",
        "rot",
        "sa",
        "sb",
        "shift_a",
        "shift_b",
        "shifted",
        "side",
        "slack",
        "start",
        "sweep",
    )

    def __init__(self, side: int, radius: float, plane: int, pos: list[float],
                 orientation: int = 0, metric: bool = True) -> None:
        self.side = side
        self.radius = radius
        self.a, self.b, self.h = PLANE_AXES.get(plane, (0, 1, 2))
        self.prog = list(pos)  # the programmed point
        self.first = True  # the entry move is next
        shift = ORIENTATION_SHIFT.get(orientation) if plane == 180 else None
        # (first, second) = (Z, X) in XZ
        # (no shift is -0.0, which adds nothing: x + -0.0 is x, a -0.0 too)
        self.shift_a = -0.0 if shift is None else shift[1] * radius or -0.0
        self.shift_b = -0.0 if shift is None else shift[0] * radius or -0.0
        self.shifted = self.shift_a != 0.0 or self.shift_b != 0.0
        # the compensated point in the plane, before the orientation's shift
        self.ca = pos[self.a]
        self.cb = pos[self.b]
        # the held move: kind, its item in Machine.held ([canon type, fields]), its start, its
        # programmed direction at the end (a line) or its circle (an arc)
        self.kind = 0
        self.item: list[Any] = []
        self.sa = self.sb = 0.0
        self.pdir = 0.0
        self.ka = self.kb = self.kr = 0.0
        self.rot = 0
        self.start = pos  # the point the held move starts from (out of the plane)
        # the held arc's sweep (radians) before a corner moved its start or end (0.0: none did),
        # and how much further it may then turn: rs274 allows 0.001 inch in program units, taken
        # as an angle (0.001 in G20, 0.0254 in G21)
        self.sweep = 0.0
        self.slack = ARC_SLACK_MM if metric else ARC_SLACK_MM / 25.4

    @staticmethod
    def exit(plane: int, state: State, pos: list[float]) -> Compensation:
        """Just turned off at the compensated point ``pos``: the current point is the programmed
        one again (what G92, tool length offsets and #5420-#5428 then see); only the exit move
        remains."""
        return _Exit(plane, state, pos)


class _Exit(Compensation):
    """Compensation just turned off: the programmed point is the state's current point."""

    __slots__ = ("state",)

    def __init__(self, plane: int, state: State, pos: list[float]) -> None:
        Compensation.__init__(self, 0, 0.0, plane, pos)  # ca, cb: the compensated point, the canon's
        self.state = state

    @property
    def prog(self) -> list[float]:
        return self.state.pos

    @prog.setter
    def prog(self, value: list[float]) -> None:
        pass  # the state's point is the programmed one (units convert it already)


# -- the queue ------------------------------------------------------------------------------------
def flush(m: Machine) -> None:
    """Emit everything held, under the running block's label."""
    held = m.held
    if not held:
        return
    emit, move = m.sink.emit, m.move
    label, line = m.label, m.line
    for op in held:
        if type(op) is list:
            move(op[0], op[1], label, line)
        else:
            emit(op, label, line)
    held.clear()


def _shown(c: Compensation, out: list[float], na: float, nb: float) -> list[float]:
    """The current point as rs274 shows it (#5420-#5428, #<_x>...): the compensated end before
    a lathe orientation's shift."""
    if not c.shifted:
        return out
    pos = out.copy()
    pos[c.a] = na
    pos[c.b] = nb
    return pos


# -- straight moves -------------------------------------------------------------------------------
def straight(m: Machine, op_type: type, end: list[float], corner_refusal: str = "") -> None:
    """A G0 or G1 to the programmed ``end`` while compensation is on (or just turned off).
    ``corner_refusal``: the error of a move that may not go round an outside corner (G76)."""
    c: Compensation = m.comp  # type: ignore[assignment]
    prog = c.prog
    a, b = c.a, c.b
    ea, eb = end[a], end[b]
    side = c.side
    if side == 0:  # the exit move
        flush(m)
        m.comp = None
        m.move(op_type, end, m.label, m.line)
        m.state.pos = end
        return
    r = c.radius
    if c.first:
        ca, cb = c.ca, c.cb
        if _hypot(ea - ca, eb - cb) <= r and r > 0.0:  # a tool of no radius may stay put
            raise NgcSemanticError(
                "Length of cutter compensation entry move is not greater than the tool radius")
        t = _atan2(eb - cb, ea - ca)
        # the direction turned a quarter toward the side, summed in long double
        n = long_sum(t, side * HALF_PI, side * HALF_PI_REST)
        na, nb = (ea + r * _cos(n), eb + r * _sin(n)) if r else (ea, eb)
        c.first = False
        c.sa, c.sb = ca, cb
        c.pdir = t
        _take(m, c, LINE, op_type, None, end, na, nb)
        return
    pa, pb = prog[a], prog[b]
    if ea == pa and eb == pb:
        # Out of the plane: queued behind the held move, at its end (a tool of no radius at the
        # programmed point, whose zeros may have another sign).
        if not r:
            c.ca, c.cb = ea, eb
        out = end.copy()
        out[a] = c.ca + c.shift_a
        out[b] = c.cb + c.shift_b
        m.held.append([op_type, out])
        if r == 0.0:
            flush(m)
        m.state.pos = _shown(c, out, c.ca, c.cb)
        c.prog = end
        return
    t = _atan2(eb - pb, ea - pa)
    if side > 0:
        n = t + HALF_PI
    elif t < _atan2(c.cb - pb, c.ca - pa):
        # to the right, a direction below the angle of the current offset (the programmed point
        # to the compensated one) is taken a turn up, the sum rounded as rs274 rounds it
        n = _turn_up(t) - HALF_PI
    else:
        n = t - HALF_PI
    # (a tool of no radius runs the programmed path: adding nothing keeps the sign of a zero)
    dx, dy = (r * _cos(n), r * _sin(n)) if r else (-0.0, -0.0)
    turn = t - c.pdir
    if turn > PI or turn < -PI:
        turn = _turn(c.pdir, t)
    # A straight corner (or a tool of no radius, which turns on the spot) leaves the held move as
    # it is, and unchecked: rs274 finds no gouge there.
    if not (-SMALL <= turn <= SMALL or r == 0.0):
        _corner(m, c, t, turn, pa + dx, pb + dy, LINE, traverse=op_type is ops.StraightTraverse,
                refusal=corner_refusal)
    c.sa, c.sb = c.ca, c.cb
    c.pdir = t
    _take(m, c, LINE, op_type, None, end, ea + dx, eb + dy)


def _take(m: Machine, c: Compensation, kind: int, op_type: type, fields: list[Any] | None,
          end: list[float], na: float, nb: float) -> None:
    """Emit what is held and hold the next move, which starts at the current point and is
    programmed to ``end``, with its compensated end ``na, nb``: a line (``fields`` None: they
    are made here) or an arc (``fields``, whose end is set here)."""
    st = m.state
    c.start = st.pos
    held = m.held
    if held:
        item = c.item
        if len(held) == 1 and held[0] is item:  # the held move alone
            m.move(item[0], item[1], m.label, m.line)
            held.clear()
        else:
            flush(m)
    out = end.copy()
    oa = out[c.a] = na + c.shift_a  # (no shift adds -0.0: the point as it is)
    ob = out[c.b] = nb + c.shift_b
    if fields is None:
        fields = out
    else:
        fields[0] = oa
        fields[1] = ob
    c.ca = na
    c.cb = nb
    st.pos = _shown(c, out, na, nb) if c.shifted else out
    item = [op_type, fields]
    held.append(item)
    c.item = item
    c.kind = kind
    c.prog = end
    if c.radius == 0.0:  # a tool of no radius holds nothing back
        flush(m)


# -- arcs -----------------------------------------------------------------------------------------
def arc(m: Machine, end: list[float], c1: float, c2: float, rotation: int) -> None:
    """A G2/G3 (center ``c1, c2`` in the plane) while compensation is on (an arc as the exit
    move was refused before its checks, in ``motion.arc``)."""
    c: Compensation = m.comp  # type: ignore[assignment]
    side = c.side
    prog = c.prog
    a, b = c.a, c.b
    r = c.radius
    pa, pb = prog[a], prog[b]
    ea, eb = end[a], end[b]
    outward = (side > 0) == (rotation < 0)  # left of a clockwise arc, right of a counterclockwise
    sign = 1.0 if outward else -1.0
    big = _hypot(pa - c1, pb - c2)
    big_end = _hypot(ea - c1, eb - c2)
    # The compensated end: the programmed one moved by the radius at the angle of its radius,
    # taken from the center to the end (outward) or from the end to the center (inward).
    if r:
        th = _atan2(eb - c2, ea - c1) if outward else _atan2(c2 - eb, c1 - ea)
        ra, rb = ea + r * _cos(th), eb + r * _sin(th)
    else:
        ra, rb = ea, eb
    if c.first:
        ca, cb = c.ca, c.cb
        if _hypot(ea - ca, eb - cb) <= r and r > 0.0:
            raise NgcSemanticError(
                "Radius of cutter compensation entry arc is not greater than the tool radius")
        if not outward and big <= r:
            raise NgcSemanticError("Tool radius not less than arc radius with comp")
        if r:
            # The center moves along the line from the compensated end toward the programmed
            # center, to where it is as far from the current point as from that end: half the
            # chord over the cosine of the angle between the chord and that line.
            toward = _atan2(c2 - rb, c1 - ra)
            cos_a = _cos(_atan2(cb - rb, ca - ra) - toward)
            if -ENTRY_FLAT < cos_a < ENTRY_FLAT:
                raise NgcSemanticError("Tool radius not less than arc radius with comp")
            kr = _hypot(cb - rb, ca - ra) / 2.0 / cos_a
            k1, k2 = ra + kr * _cos(toward), rb + kr * _sin(toward)
        else:
            k1, k2, kr = c1, c2, big
        c.first = False
        c.sa, c.sb = ca, cb
        c.ka, c.kb, c.kr, c.rot = k1, k2, abs(kr), rotation
        c.sweep = 0.0
        # the corner after it turns from the programmed circle's direction (the moved center
        # may have crossed the end)
        c.pdir = _end_tangent(ra - c1, rb - c2, rotation)
        _take(m, c, ARC, ops.ArcFeed, _arc_fields(c, end, k1, k2, rotation), end, ra, rb)
        return
    if not outward and big <= r:
        raise NgcSemanticError("Tool radius not less than arc radius with comp")
    t0 = _atan2(pb - c2, pa - c1)
    kr = big_end + sign * r
    if r:
        # The compensated start: moved by the radius at the angle from the start to the center,
        # turned half a turn (summed in long double) when outward.
        th = _atan2(c2 - pb, c1 - pa)
        if outward:
            th = long_sum(th, PI, PI_REST)
        sa, sb = pa + r * _cos(th), pb + r * _sin(th)
    else:
        sa, sb = pa, pb
    tangent = t0 + HALF_PI if rotation > 0 else t0 - HALF_PI
    # rs274 meets a held line at the arc's start angle but the end's radius: the line moves
    # along the start's radius by the difference
    lift = (big_end - big) / big if big else 0.0  # (an arc starting at its centre: none)
    turn = tangent - c.pdir
    if turn > PI or turn < -PI:
        turn = _turn(c.pdir, tangent)
    if not (-SMALL <= turn <= SMALL or r == 0.0):  # (a straight corner: as for a line)
        _corner(m, c, tangent, turn, sa, sb, ARC, c1, c2, kr, rotation, False,
                lift * (pa - c1), lift * (pb - c2))
    # the corner moved the start (on, inside; or the held move ends a little off the circle):
    # the arc must not turn further when it goes out
    c.sweep = _sweep(c1, c2, sa, sb, ra, rb, rotation) if (c.ca != sa or c.cb != sb) else 0.0
    c.sa, c.sb = c.ca, c.cb
    c.ka, c.kb, c.kr, c.rot = c1, c2, big_end + sign * r, rotation  # its end is met at the end's radius
    c.pdir = _end_tangent(ra - c1, rb - c2, rotation)
    _take(m, c, ARC, ops.ArcFeed, _arc_fields(c, end, c1, c2, rotation), end, ra, rb)


def _end_tangent(ra: float, rb: float, rotation: int) -> float:
    """The direction of an arc at the end of its radius ``ra, rb``."""
    end_angle = _atan2(rb, ra)
    return end_angle + HALF_PI if rotation > 0 else end_angle - HALF_PI


def _arc_fields(c: Compensation, end: list[float], k1: float, k2: float,
                rotation: int) -> list[Any]:
    """An arc's fields around center ``k1, k2`` (its end is set by :func:`_take`)."""
    return [0.0, 0.0, k1 + c.shift_a, k2 + c.shift_b, rotation, end[c.h], end[3], end[4], end[5]]


# -- corners --------------------------------------------------------------------------------------
def _turn(before: float, tangent: float) -> float:
    """The turn from direction ``before`` to ``tangent``, within [-pi, pi] (a reversal keeps its
    sign)."""
    turn = tangent - before
    while turn > math.pi:
        turn -= TWO_PI
    while turn < -math.pi:
        turn += TWO_PI
    return turn


def _corner(m: Machine, c: Compensation, tangent: float, turn: float, sa: float, sb: float,
            kind: int = LINE, k1: float = 0.0, k2: float = 0.0, kr: float = 0.0, rot: int = 0,
            traverse: bool = False, la: float = 0.0, lb: float = 0.0, refusal: str = "") -> None:
    """Join the held move to the next one, which starts (offset) at ``sa, sb`` with direction
    ``tangent``, ``turn`` from the held one's (a line, or an arc of center ``k1, k2``,
    compensated radius ``kr`` and direction ``rot``), not within SMALL of straight.  Before a
    traverse, the corner is a traverse too; a ``refusal`` is raised instead of an outside
    corner, once the held move is out."""
    before = c.pdir
    side = c.side
    crossing = None
    inside = turn * side > 0
    if turn > REVERSAL or turn < -REVERSAL:
        inside = _bends_inside(c, before, kind, k1, k2)
    if inside:
        crossing = _crossing(c, before, tangent, turn, sa, sb, kind, k1, k2, kr, rot, la, lb)
    if crossing is None:  # outside: an arc around the corner
        if c.kind == LINE or kind == LINE:  # (not an arc held before an arc)
            check_held(c)
        # the held move ends at the compensated point, which a lathe cycle's profile may have
        # moved from where the move was held to (see ``lathe._move_to``)
        if c.kind != 0:
            end = c.item[1]
            ia, ib = (0, 1) if c.kind == ARC else (c.a, c.b)
            if end[ia] != c.ca + c.shift_a or end[ib] != c.cb + c.shift_b:
                move_held_end(m, c, c.ca, c.cb)
        flush(m)
        if refusal:
            raise NgcSemanticError(refusal)
        pos = m.state.pos
        if traverse:
            to = pos.copy()
            to[c.a] = sa + c.shift_a
            to[c.b] = sb + c.shift_b
            m.move(ops.StraightTraverse, to, m.label, m.line)
        else:
            h = c.h
            fields = [sa + c.shift_a, sb + c.shift_b, c.prog[c.a] + c.shift_a,
                      c.prog[c.b] + c.shift_b, -side, pos[h], pos[3], pos[4], pos[5]]
            m.move(ops.ArcFeed, fields, m.label, m.line)
        c.ca, c.cb = sa, sb
        return
    move_held_end(m, c, *crossing)
    check_held(c)


def _crossing(c: Compensation, before: float, tangent: float, turn: float, sa: float, sb: float,
              kind: int, k1: float, k2: float, kr: float, rot: int, la: float,
              lb: float) -> tuple[float, float] | None:
    """Inside: where the two compensated paths cross (a line and an arc: the crossing first met
    going back along the held arc from its end, or on along the next arc from its start; two
    arcs: the crossing on the side their directions and the compensation's pick); paths that
    never meet cannot be cut without gouging."""
    if c.kind == LINE:
        ua, ub = _cos(before), _sin(before)
        if kind == LINE:
            # the corner takes back r tan(turn / 2) of the held line, which must be that long;
            # the crossing lies on the corner's bisector (the mean of the two directions, turned
            # a quarter), r / cos(turn / 2) from the programmed corner
            back = c.radius * math.tan(abs(turn) / 2)
            if back > _hypot(c.ca - c.sa, c.cb - c.sb):
                _gouge(c)
            return _line_line(c, tangent)
        found = _line_circle(c.ca + la, c.cb + lb, ua, ub, k1, k2, kr)
        if found is None:
            _arc_gouge()
        return _first_on_arc(k1, k2, sa, sb, rot, found)
    if kind == LINE:
        va, vb = _cos(tangent), _sin(tangent)
        found = _line_circle(sa, sb, va, vb, c.ka, c.kb, c.kr)
        if found is None:
            raise NgcSemanticError(
                "Arc to straight motion makes a corner the compensated tool can't fit in without "
                "gouging")
        return _first_on_arc(c.ka, c.kb, c.ca, c.cb, -c.rot, found)
    points = _circle_circle(c.ka, c.kb, c.kr, k1, k2, kr)
    if points is None:
        raise NgcSemanticError(
            "Arc to arc motion makes a corner the compensated tool can't fit in without gouging")
    # The crossing on the left of the line from the held center to the next one when the side
    # and the two directions multiply to a positive, else on its right (it may lie a little
    # beyond the held end, where the circles barely cross).
    return points[0] if c.side * c.rot * rot > 0 else points[1]


def _line_line(c: Compensation, tangent: float) -> tuple[float, float]:
    """The crossing of an inside corner between the held line and the next line (direction
    ``tangent``), computed as rs274 computes it: ``offset`` is the angle from the programmed
    corner to the held line's compensated end; to the left the offset, to the right the
    direction, is taken a turn up when below the other; the corner's turn is pi/2 less their
    difference, and the held end moves back along the held line (at the offset's angle turned
    a quarter away from the side) by the radius over tan((pi - turn) / 2), the turn and its
    half rounded from long double."""
    side = c.side
    offset = _atan2(c.cb - c.prog[c.b], c.ca - c.prog[c.a])
    if side > 0:
        if tangent > offset:
            offset = _turn_up(offset)
        spread = offset - tangent
    else:
        if tangent < offset:
            tangent = _turn_up(tangent)
        spread = tangent - offset
    turn = long_sum(HALF_PI, HALF_PI_REST, -spread)
    half = long_sum(math.pi, PI_REST, -turn) / 2
    back = c.radius / math.tan(half)
    direction = offset + HALF_PI if side > 0 else offset - HALF_PI
    return c.ca + back * _cos(direction), c.cb + back * _sin(direction)


Points = tuple[tuple[float, float], tuple[float, float]]


def _line_circle(pa: float, pb: float, ua: float, ub: float, k1: float, k2: float,
                 kr: float) -> Points | None:
    """The two points where the line ``p + s u`` meets the circle."""
    da, db = pa - k1, pb - k2
    half_b = da * ua + db * ub
    cc = da * da + db * db - kr * kr
    disc = half_b * half_b - cc
    if disc < 0:
        return None
    root = math.sqrt(disc)
    s1, s2 = -half_b - root, -half_b + root
    return (pa + s1 * ua, pb + s1 * ub), (pa + s2 * ua, pb + s2 * ub)


def _circle_circle(a1: float, b1: float, r1: float, a2: float, b2: float,
                   r2: float) -> Points | None:
    """The two points where two circles meet: left, then right, of the line from the first
    center to the second."""
    da, db = a2 - a1, b2 - b1
    d = _hypot(da, db)
    if d == 0.0 or d > r1 + r2 or d < abs(r1 - r2):
        return None
    x = (d * d + r1 * r1 - r2 * r2) / (2 * d)
    y = math.sqrt(max(r1 * r1 - x * x, 0.0))
    ma, mb = a1 + x * da / d, b1 + x * db / d
    return (ma - y * db / d, mb + y * da / d), (ma + y * db / d, mb - y * da / d)


def _first_on_arc(k1: float, k2: float, pa: float, pb: float, rot: int,
                  points: Points) -> tuple[float, float]:
    """Of two points on a circle, the first met going from ``p`` counterclockwise (``rot`` > 0)
    or clockwise."""
    start = _atan2(pb - k2, pa - k1)
    best = points[0]
    best_travel = TWO_PI + 1.0
    for point in points:
        travel = (_atan2(point[1] - k2, point[0] - k1) - start) * (1 if rot > 0 else -1)
        travel %= TWO_PI
        if travel < best_travel:
            best, best_travel = point, travel
    return best


def _bends_inside(c: Compensation, before: float, kind: int, k1: float, k2: float) -> bool:
    """At a reversal the next move is on the compensated side of the held one when it bends
    further toward that side (curvatures, signed toward the side, at the programmed corner)."""
    side = c.side
    na, nb = -side * _sin(before), side * _cos(before)
    pa, pb = c.prog[c.a], c.prog[c.b]
    held = 0.0
    if c.kind == ARC:
        da, db = c.ka - pa, c.kb - pb
        held = (da * na + db * nb) / (da * da + db * db)
    nxt = 0.0
    if kind == ARC:
        da, db = k1 - pa, k2 - pb
        nxt = (da * na + db * nb) / (da * da + db * db)
    return nxt > held


def _sweep(k1: float, k2: float, sa: float, sb: float, ea: float, eb: float,
           rot: int) -> float:
    """The angle an arc of center ``k1, k2`` turns from ``s`` to ``e`` in its direction (a
    whole turn when they meet: a whole circle's compensated start and end, found at angles
    computed apart, may differ in their last bits)."""
    turn = (_atan2(eb - k2, ea - k1) - _atan2(sb - k2, sa - k1)) * (1 if rot > 0 else -1)
    turn %= TWO_PI
    return turn if turn > WHOLE_TURN_SLIP else TWO_PI


def move_held_end(m: Machine, c: Compensation, xa: float, xb: float) -> None:
    """The held move (and the moves out of the plane queued behind it) now end at ``xa, xb``."""
    oa, ob = xa + c.shift_a, xb + c.shift_b
    item = c.item
    if c.kind == ARC:
        if c.sweep == 0.0:
            c.sweep = _sweep(c.ka, c.kb, c.sa, c.sb, c.ca, c.cb, c.rot)
        item[1][0] = oa
        item[1][1] = ob
    else:
        item[1][c.a] = oa
        item[1][c.b] = ob
    for op in m.held:
        if type(op) is list and op is not item:
            op[1][c.a] = oa
            op[1][c.b] = ob
    c.ca, c.cb = xa, xb


def check_held(c: Compensation) -> None:
    """A held move that would now run backwards (a line), or turn further than it did before its
    corners trimmed it (an arc), cannot be cut without gouging."""
    if c.kind == LINE:
        if (c.ca - c.sa) * _cos(c.pdir) + (c.cb - c.sb) * _sin(c.pdir) < 0:
            _gouge(c)
    elif c.sweep != 0.0:
        if (c.sa != c.ca or c.sb != c.cb) and (
                _sweep(c.ka, c.kb, c.sa, c.sb, c.ca, c.cb, c.rot) > c.sweep + c.slack):
            _arc_gouge()
        c.sweep = 0.0



def _arc_gouge() -> NoReturn:
    raise NgcSemanticError(
        "Arc move in concave corner cannot be reached by the tool without gouging")


def _gouge(c: Compensation) -> NoReturn:
    what = "traverse" if c.item[0] is ops.StraightTraverse else "feed"
    raise NgcSemanticError(
        f"Straight {what} in concave corner cannot be reached by the tool without gouging")


# -- tool changes -------------------------------------------------------------------------------
def take_canon_point(m: Machine) -> None:
    """After a line with M6 or M61 rs274 takes the canon's current point as its own: with a move
    held, where the held move starts.  The held move now ends there; the corner after it turns
    from the direction the programmed point's offset to that point gives."""
    c: Compensation = m.comp  # type: ignore[assignment]
    if c.side == 0:  # turned off: the canon is still at the compensated point
        pos = m.state.pos.copy()
        pos[c.a] = c.ca
        pos[c.b] = c.cb
        m.state.pos = pos
        return
    if c.kind == 0:
        return
    a, b = c.a, c.b
    pos = c.start.copy()
    pos[a] = c.sa + c.shift_a
    pos[b] = c.sb + c.shift_b
    m.state.pos = pos
    prog = pos.copy()
    prog[a] = c.prog[a]
    prog[b] = c.prog[b]
    c.prog = prog
    move_held_end(m, c, c.sa, c.sb)
    if c.kind == LINE:
        normal = _atan2(c.sb - prog[b], c.sa - prog[a])
        c.pdir = normal - HALF_PI if c.side > 0 else normal + HALF_PI


def offset_turned(c: Compensation) -> None:
    """The compensated point moved away from the programmed one's offset (a lathe cycle's profile
    leaves it at its last point): the next corner turns from the direction square to the offset
    from the programmed point to the compensated one, as rs274 measures every corner."""
    normal = _atan2(c.cb - c.prog[c.b], c.ca - c.prog[c.a])
    c.pdir = normal - HALF_PI if c.side > 0 else normal + HALF_PI


# -- units ----------------------------------------------------------------------------------------
def convert(m: Machine, k: float) -> None:
    """The units changed (``k`` new units per old one): the held moves and every length kept
    follow, as rs274 converts its whole queue."""
    c: Compensation = m.comp  # type: ignore[assignment]
    pos = m.state.pos  # converted already; a held line may share it
    for op in m.held:
        if type(op) is list and op[1] is not pos:
            fields = op[1]
            for i in (0, 1, 2, 3, 5) if op[0] is ops.ArcFeed else (0, 1, 2):
                fields[i] *= k
    c.prog = [v * k if i < 3 else v for i, v in enumerate(c.prog)]
    c.radius *= k
    c.slack *= k
    c.shift_a *= k
    c.shift_b *= k
    c.ca *= k
    c.cb *= k
    c.sa *= k
    c.sb *= k
    c.ka *= k
    c.kb *= k
    c.kr *= k
