"""G70, the lathe finishing cycle, as rs274 2.9.0~pre1 runs it.

What rs274 shows (program coordinates, X a radius; ``S`` the cycle's start point, ``F`` the
profile's first point, the end of the subroutine's first move, ``L`` its last point):

* The handler's traverse to ``S`` comes first (X/Z words, else the current point).  Moves of the
  profile that go nowhere are left out (the first move too when S is F: the next move then is
  the approach; the move after one keeps the zeros of where the last move kept ended).  A
  profile of the approach alone gives no pass.
* The profile goes *along Z* when it is monotonic in Z (arcs by their extent; a step of 0.001
  or less counts for nothing), the way set by the moves after the first: +Z if one of them
  rises, else -Z (so a profile rising only in its first
  move, or of one rising move, is not along Z).  Otherwise it goes *along X* if monotonic there,
  the way ``L`` lies from ``F`` (-X on a tie), else "G7X error: Not monotonic" (shown at the
  subroutine's last line, after the traverse to S).
* The entry point ``I``: a start *ahead* of ``F`` along the axis (beyond F the way the profile
  goes) is brought to F's level on that axis first (along Z: (S.x, F.z), along X: (F.x, S.z));
  otherwise ``I`` is ``S``.
* The side the profile moves to is the side ``I`` lies on of the line from ``F`` to the start of
  the last move.  With ``I`` on that line (or a profile of one move) it is the side where the
  chord F-L has its normal pointing back against the way the profile goes (the right when that
  normal is square to the axis).
* P is truncated to a whole number of passes (P0 or less: none, only the traverse to S); pass
  ``k`` from P down to 1 is the profile moved (k-1)*(D-E)/P+E (P itself, not truncated, in the
  division) to that side; a negative distance moves it the other way.  Lines move along their
  normal; an arc keeps its centre and is scaled about it by its start's new radius over its old
  one (a centre-format arc's end a little off its start's circle keeps that proportion).
* The profile moves in steps, its corners joined after each (as below): a step is at most half
  the shortest chord of a move and half the smallest radius of an arc of the profile as the last
  step left it (the arcs rounding corners included).  So an outside corner whose moved ends part
  by less than 0.01 in each step stays sharp (small distances beside short moves), and a corner
  that turns the other way partway is rounded about where it was then (a fillet of the rest of
  the distance about a moved corner, where rs274 prints "Oops").  An arc a step shrinks to a
  radius of 0.001 or less is gone, its neighbours meeting where they cross (one left a little
  larger is cut, and refused as a "Zero-radius arc"); a last move it shrinks to less than 0.001
  from end to end just goes, as when the profile is read (so a last line shorter than D stops
  the line before it where it vanished).  Found with G70 on profiles of
  two arcs, of a fillet after an arc, and of short lines: the fillet's centre stays put as D
  grows, at the distance of half the smallest radius or chord.
* Corners: an inside corner is cut back to where the moved carriers cross (a line and a circle: at
  the crossing nearer to where the first ends, an arc before the line first where the line crosses
  the arc itself; two circles: at the crossing right of the line from the first centre to the
  second in rs274's frame, which turns Z round for a profile going +Z and X round for one whose
  last point lies below its first, the frame of G72 and of a G70 profile going along X a quarter
  turn of it; the circles' radii: see ``_crossing``; carriers that just miss meet where they come
  closest). An outside corner gets an arc about the programmed corner when the moved ends (an
  arc's as scaled) lie 0.01 or more apart along the profile's axis, else it is cut like an inside
  one; an arc before it ends where its circle (after a line and moved away from its centre, of its
  scaled end's radius where that is larger than its start's) meets the circle about the corner
  through its scaled end (the crossing right of the line from its centre to the corner in rs274's
  frame, turned round again for a profile along X that ends at a greater Z than it starts); where
  those circles miss each other or touch, at the point between them on the line through their
  centres. A corner whose tangents turn by less than 1e-6 is no outside corner. Every arc a pass
  cuts is held to a programmed arc's radius tolerance (the profile's own arcs are not held when it
  is read). Two moved lines in line at a corner: "G7X error: Cannot intersect parallel lines".
* Each pass: a traverse to ``I``, a traverse to the moved profile's first point, then G1/G2/G3
  feeds along it.  The tool is left at the last pass's end (the profile's end moved E); there is
  no move back.
* With cutter radius compensation on (G41/G42 and their .1 forms) the cycle's moves are
  compensated like programmed ones.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from ...errors import NgcSemanticError
from .corners import _SHORT
from .offset import EPS, _shift, intersections, tangent
from .path import Out
from .profile import CCW, CW, LINE, NOT_MONOTONIC, PARALLEL, Profile, Seg, steps, within
from .zeros import turning_zeros

# an outside corner whose moved ends lie closer than this along the profile's axis is cut like
# an inside one, not rounded
ROUNDED = 0.01

# two crossings this much as far from an end (relative) are as near
_TIE = 1e-9

# corners whose tangents turn (sine) by less than this are tangent: no outside corner
TANGENT = 1e-6


# a step no longer than this along the axis turns nothing back, nor sets the way (rs274: in the
# program's units, 0.001 goes, 0.0010000000000000009 does not; as G71's profile check)
_NO_STEP = 1e-3


def _monotonic(moves: list[Seg], axis: int, way: float) -> bool:
    for seg in moves:
        step, one_way = steps(seg, axis)
        if not one_way or (step * way < 0 and abs(step) > _NO_STEP):
            return False
    return True


def _entry(profile: Profile, start: tuple[float, float]
           ) -> tuple[tuple[float, float], tuple[float, float]]:
    """The point ``I`` each pass comes from, and the (z, x) direction the profile goes along
    (see the module's description)."""
    sx, sz = start
    first = profile[0]
    fx, fz = first.x1, first.z1
    moves = profile[1:]
    way = 1.0 if any(seg.z1 - seg.z0 > _NO_STEP for seg in moves[1:]) else -1.0
    if _monotonic(moves, 1, way):
        return ((sx, fz) if (sz - fz) * way > 0 else start), (way, 0.0)
    last = moves[-1]
    way = 1.0 if last.x1 - fx > 0 else -1.0
    if not _monotonic(moves, 0, way):
        raise NgcSemanticError(NOT_MONOTONIC)
    return ((fx, sz) if (sx - fx) * way > 0 else start), (0.0, way)


def pass_side(profile: Profile, entry: tuple[float, float], axis: tuple[float, float]) -> float:
    """+1: the profile moves to its left (in the (z, x) plane), -1: to its right.  ``axis``: the
    unit (z, x) direction the profile goes along."""
    moves = profile[1:]
    first, last = moves[0], moves[-1]
    # the side of I from the line through the first point and the last move's start
    tz, tx = last.z0 - first.z0, last.x0 - first.x0
    vz, vx = entry[1] - first.z0, entry[0] - first.x0
    c = tz * vx - tx * vz
    if c != 0:
        return 1.0 if c > 0 else -1.0
    # I in line (or a profile of one move): the side where the chord from the first point to
    # the last has its normal pointing back against the way the profile goes
    tz, tx = last.z1 - first.z0, last.x1 - first.x0
    back = -tx * axis[0] + tz * axis[1]  # the chord's left normal (-tx, tz) along the axis
    return -1.0 if back >= 0 else 1.0


def _move(seg: Seg, side: float, d: float) -> Seg:
    """``seg`` moved ``d`` to its left (``side`` +1) or right (-1); an arc keeps its centre and
    is scaled about it by its start's new radius over its old one (a centre-format arc whose end
    lies a little off its start's circle keeps that proportion: rs274's ends at 1000 times the
    size show it)."""
    if seg.kind == LINE:
        return _shift(seg, side, d)
    r_start = math.hypot(seg.x0 - seg.cx, seg.z0 - seg.cz)
    toward_centre = side if seg.kind == CCW else -side
    k = (r_start - toward_centre * d) / r_start
    return seg._replace(x0=seg.cx + (seg.x0 - seg.cx) * k, z0=seg.cz + (seg.z0 - seg.cz) * k,
                        x1=seg.cx + (seg.x1 - seg.cx) * k, z1=seg.cz + (seg.z1 - seg.cz) * k)


def _crossing(a: Seg, b: Seg, mirror: float, r_arc: float = 0.0) -> tuple[float, float]:
    """Where the carriers of two moved segments, ``a`` then ``b``, meet, as rs274 picks it:
    a line and a circle at the crossing nearer to where ``a`` ends; two circles at the crossing
    right of the line from the first centre to the second (in the (z, x) plane).  The circle
    of an arc beside a line has the radius ``r_arc`` (see ``_own_end_radius``), two arcs the
    radii of their moved starts (fitted on near-tangent corners; the radii differ a little for
    a centre-format arc).  Carriers that miss each other (a corner close to tangent) meet where
    they come closest."""
    if a.kind == LINE and b.kind == LINE:
        points = intersections(a, b)
        if not points:
            raise NgcSemanticError(PARALLEL)
        return points[0]
    if a.kind == LINE or b.kind == LINE:
        line, arc = (a, b) if a.kind == LINE else (b, a)
        r = r_arc
        dx, dz = line.x1 - line.x0, line.z1 - line.z0
        n2 = dx * dx + dz * dz
        if not 0.0 < n2 < math.inf:  # (a line of no length, or past what a double holds)
            raise NgcSemanticError(NOT_MONOTONIC)
        t = ((arc.cx - line.x0) * dx + (arc.cz - line.z0) * dz) / n2
        fx, fz = line.x0 + t * dx, line.z0 + t * dz  # the foot of the centre on the line
        ex, ez = fx - arc.cx, fz - arc.cz
        h2 = r * r - (ex * ex + ez * ez)  # (products: a square past a double's range is inf)
        if h2 <= 0:
            return fx, fz
        h = math.sqrt(h2 / n2)
        roots = [(fx - h * dx, fz - h * dz), (fx + h * dx, fz + h * dz)]
        # the nearer to where ``a`` ends; as near either way (an arc ``a`` bulging across the
        # line, ending where the line touches its circle), where the line crosses the arc itself
        near = [math.hypot(pt[0] - a.x1, pt[1] - a.z1) for pt in roots]
        if arc is a and abs(near[0] - near[1]) <= _TIE * max(1.0, near[0]):
            return min(roots, key=lambda pt: not within(
                arc, math.atan2(pt[0] - arc.cx, pt[1] - arc.cz)))
        return roots[0] if near[0] <= near[1] else roots[1]
    r1 = math.hypot(a.x0 - a.cx, a.z0 - a.cz)
    r2 = math.hypot(b.x0 - b.cx, b.z0 - b.cz)
    dz, dx = b.cz - a.cz, b.cx - a.cx
    dist = math.hypot(dz, dx)
    if dist == 0.0:
        raise NgcSemanticError(NOT_MONOTONIC)  # (two arcs about one centre do not cross)
    along = (dist * dist + r1 * r1 - r2 * r2) / (2 * dist)
    mz, mx = a.cz + along * dz / dist, a.cx + along * dx / dist
    h2 = r1 * r1 - along * along
    h = math.sqrt(h2) if h2 > 0 else 0.0
    # right of (dz, dx) in (z, x) is (dx, -dz), in rs274's frame (``mirror``)
    h *= mirror
    return mx - h * dz / dist, mz + h * dx / dist


def _own_end_radius(arc: Seg, side: float, d: float) -> float:
    """The radius of an arc's programmed end scaled with its start (see ``_move``): its circle
    where it meets a line before it.  It differs from the end moved ``d`` along its own radius
    where a centre-format arc's end lies off its start's circle; near-tangent corners (a line
    into an arc moved inward or outward) show rs274 takes the scaled one."""
    toward_centre = side if arc.kind == CCW else -side
    r_start = math.hypot(arc.x0 - arc.cx, arc.z0 - arc.cz)
    return math.hypot(arc.x1 - arc.cx, arc.z1 - arc.cz) * (r_start - toward_centre * d) / r_start


def _carrier_radius(prev: Seg, prev_moved: Seg, move: Seg, side: float, d: float) -> float:
    """The radius of the circle an arc meets a line on (see ``_crossing``): a line into an arc
    (``move`` as programmed), its scaled end's; an arc (``prev``, moved whole as ``prev_moved``)
    into a line, its moved end's; 0 for two lines or two arcs."""
    if prev.kind == LINE and move.kind != LINE:
        return _own_end_radius(move, side, d)
    if prev.kind != LINE and move.kind == LINE:
        return math.hypot(prev_moved.x1 - prev.cx, prev_moved.z1 - prev.cz)
    return 0.0


def _arc_end_at_corner(arc: Seg, corner: Seg, mirror: float,
                       after_line: bool) -> tuple[float, float]:
    """Where a moved arc ends at an outside corner, as rs274 finds it: where its circle, of its
    moved start's radius (``after_line``, a line before it, and moved away from its centre: of
    its scaled end's where that is larger), meets the circle about the programmed corner through its moved end
    (the point on the line between their centres where they miss each other, as a
    centre-format arc whose end lies beyond its start's circle makes them: measured at 1000
    times the size); of two crossings, the one right of the line from the arc's centre to the
    corner in rs274's frame (``mirror``), as two moved arcs cross."""
    r1 = math.hypot(arc.x0 - arc.cx, arc.z0 - arc.cz)
    r2 = math.hypot(arc.x1 - corner.x0, arc.z1 - corner.z0)
    dx, dz = corner.x0 - arc.cx, corner.z0 - arc.cz
    dist = math.hypot(dx, dz)
    if after_line and r1 > dist:
        # (an arc after a line, moved away from its centre: the circle the line met, of the
        # scaled end's radius as in ``_carrier_radius``, where that is the larger; it touches the
        # corner's circle at the scaled end)
        r1 = max(r1, math.hypot(arc.x1 - arc.cx, arc.z1 - arc.cz))
    along = (dist * dist + r1 * r1 - r2 * r2) / (2 * dist)
    mx, mz = arc.cx + along * dx / dist, arc.cz + along * dz / dist
    h2 = r1 * r1 - along * along
    if h2 <= 0:
        return mx, mz
    # right of (dz, dx) in (z, x) is (dx, -dz), in rs274's frame (``mirror``)
    h = math.sqrt(h2) / dist * mirror
    return mx - h * dz, mz + h * dx


def _mirror(profile: Profile, axis: tuple[float, float]) -> float:
    """-1 where rs274's frame for the profile is a mirror image of ours: it turns Z round for a
    profile going +Z and X round for one whose last point lies below its first."""
    first, last = profile[0], profile[-1]
    flip = -1.0 if axis[0] > 0 else 1.0
    if last.x1 < first.x1:
        flip = -flip
    return flip


def moved(profile: Profile, side: float, d: float, axis: tuple[float, float], *,
          roughing: bool = False, work: Callable[[], None] | None = None) -> list[Seg]:
    """The profile after ``F`` moved ``d`` to ``side``, its corners joined (``axis``: the unit
    (z, x) direction the profile goes along).  G70 measures an outside corner's gap along
    ``axis`` and refuses two moved lines in line; for G71/G72 (``roughing``) the gap is measured
    along the axis the passes cut along (Z for G71, X for G72: ``axis`` either way round),
    slanted lines in line join, and a line shorter than ``d`` that turns round between its
    corners is left out."""
    return moved_with_corners(profile, side, d, axis, roughing=roughing, work=work)[0]


_MAX_STEPS = 200  # then the rest at once (an arc shrinking by half its radius each step)


def _step(moves: Profile) -> float:
    """How far the profile moves at once: half its shortest chord, or half its smallest arc's
    radius."""
    h = math.inf
    for seg in moves:
        chord = math.hypot(seg.x1 - seg.x0, seg.z1 - seg.z0)
        if chord > 0.0:
            h = min(h, chord / 2)
        if seg.kind != LINE:
            h = min(h, math.hypot(seg.x0 - seg.cx, seg.z0 - seg.cz) / 2)
    return h


# an arc a step shrinks to this radius or less is gone: its neighbours meet where they cross
# (rs274 drops a quarter circle moved to r 0.001 and cuts one moved to r 0.0012, which its
# zero-radius tolerance then refuses)
_VANISHED = 0.001 + 1e-9


def _without_vanished(moves: Profile, mirror: float) -> Profile:
    """``moves`` without a last move shrunk to less than ``_SHORT`` (as ``drop_short``), and
    without the arcs shrunk to ``_VANISHED`` or less (but the first and the last), the moves on
    either side cut back or out to where their carriers cross; an arc whose neighbours do not
    cross stays."""
    out = list(moves)
    last = out[-1]
    if len(out) > 1 and math.hypot(last.x1 - last.x0, last.z1 - last.z0) < _SHORT:
        out.pop()  # (a last move shrunk to less than 0.001 just goes, as when it is read)
    i = 1
    while i < len(out) - 1:
        seg = out[i]
        if seg.kind == LINE or math.hypot(seg.x0 - seg.cx, seg.z0 - seg.cz) > _VANISHED:
            i += 1
            continue
        prev, nxt = out[i - 1], out[i + 1]
        arc = prev if prev.kind != LINE else nxt
        r = math.hypot(arc.x0 - arc.cx, arc.z0 - arc.cz) if arc.kind != LINE else 0.0
        try:
            px, pz = _crossing(prev, nxt, mirror, r)
        except NgcSemanticError:
            i += 1
            continue
        out[i - 1:i + 2] = [prev._replace(x1=px, z1=pz), nxt._replace(x0=px, z0=pz)]
    return out


def moved_with_corners(profile: Profile, side: float, d: float, axis: tuple[float, float], *,
                       roughing: bool = False, work: Callable[[], None] | None = None
                       ) -> tuple[list[Seg], set[int]]:
    """``moved``, and the indices of the arcs it put in to round outside corners.  The profile
    moves in steps (``_step``), its corners joined after each; ``work`` is called for each step
    (the run's work budget: the profile's numbers set how many there are)."""
    if d == 0.0:
        return list(profile[1:]), set()
    current = list(profile)
    left = abs(d)
    sign = 1.0 if d > 0 else -1.0
    for k in range(_MAX_STEPS + 1):
        if work is not None:
            work()
        h = min(left, _step(current[1:]))
        if not h > 1e-9 or k == _MAX_STEPS:
            h = left  # (the rest at once)
        current = [current[0], *_moved_once(current, side, sign * h, axis, roughing, k == 0)]
        current = [current[0], *_without_vanished(current[1:], _mirror(current, axis))]
        left -= h
        if left <= 0.0:
            break
    moved = current[1:]
    return moved, {i for i, seg in enumerate(moved) if seg.rounding}


def _moved_once(profile: Profile, side: float, d: float, axis: tuple[float, float],
                roughing: bool, first: bool) -> list[Seg]:
    moves = profile[1:]
    gz, gx = (abs(axis[0]), abs(axis[1])) if roughing else axis
    mirror = _mirror(profile, axis)
    if axis[0] == 0.0:
        mirror = -mirror  # (along X, G72's or G70's: the frame turned a quarter round)
    end_mirror = mirror
    if axis[0] == 0.0 and profile[-1].z1 > profile[0].z1:
        end_mirror = -mirror  # (and Z turned round too for one that ends at a greater Z)
    shifted = [_move(seg, side, d) for seg in moves]
    out: list[Seg] = []
    for i, seg in enumerate(shifted):
        if not out:
            out.append(seg)
            continue
        prev = out[-1]
        t1 = tangent(moves[i - 1], True)
        t2 = tangent(moves[i], False)
        turn = t1[0] * t2[1] - t1[1] * t2[0]  # > 0: turning left
        if prev.kind == LINE and seg.kind == LINE and abs(turn) < EPS and first and not roughing:
            # (G70: two programmed lines in line; lines a step turned round are not refused)
            raise NgcSemanticError(PARALLEL)
        if math.hypot(prev.x1 - seg.x0, prev.z1 - seg.z0) < EPS:
            if roughing and _turned_round(out, moves[i - 1], prev.x1, prev.z1):
                # (a line turned round, as below, whose end meets the next move as it is)
                _join_past(out, seg, mirror,
                           _carrier_radius(out[-2], shifted[i - 2], moves[i], side, d))
                continue
            out.append(seg)
            continue
        corner = moves[i]
        outside = turn * side * d < 0 and abs(turn) >= TANGENT
        ex, ez = prev.x1, prev.z1
        if outside and prev.kind != LINE:
            ex, ez = _arc_end_at_corner(shifted[i - 1], corner, end_mirror,
                                        i >= 2 and moves[i - 2].kind == LINE)
        # (from the arc's end as moved, before it is brought to the corner's circle)
        gap = (seg.z0 - prev.z1) * gz + (seg.x0 - prev.x1) * gx
        if outside and abs(gap) >= ROUNDED:
            # the moved segments part (an outside corner): an arc about the corner joins them
            out[-1] = prev._replace(x1=ex, z1=ez)
            out.append(Seg(CCW if turn > 0 else CW, ex, ez, seg.x0, seg.z0, corner.x0,
                           corner.z0, line=corner.line, rounding=True))
            out.append(seg)
            continue
        if prev.kind == LINE and seg.kind == LINE and abs(turn) < EPS:
            out.append(seg)  # (slanted lines in line, joined as G71/G72 join them)
            continue
        r_arc = _carrier_radius(prev, shifted[i - 1], moves[i], side, d)
        try:
            px, pz = _crossing(prev, seg, mirror, r_arc)
        except NgcSemanticError:
            if first:
                raise
            out.append(seg)  # (lines a step made parallel: they stay as they are)
            continue
        if roughing and _turned_round(out, moves[i - 1], px, pz):
            # a line shorter than the distance turns round between its corners: G71/G72 leave
            # it out, the lines on either side meeting where their carriers cross
            _join_past(out, seg, mirror, r_arc)
            continue
        out[-1] = prev._replace(x1=px, z1=pz)
        out.append(seg._replace(x0=px, z0=pz))
    return out


def _turned_round(out: list[Seg], was: Seg, px: float, pz: float) -> bool:
    """Whether the moved line ``out[-1]``, ending at (px, pz), runs against ``was``, the line as
    programmed (not the first move of ``out``)."""
    prev = out[-1]
    return (len(out) > 1 and prev.kind == LINE
            and (px - prev.x0) * (was.x1 - was.x0) + (pz - prev.z0) * (was.z1 - was.z0) < 0)


def _join_past(out: list[Seg], seg: Seg, mirror: float, r_arc: float) -> None:
    """Leave out the move ``out[-1]``: the move before it and ``seg`` meet where their carriers
    cross (``r_arc``: see ``_crossing``), and ``seg`` follows."""
    out.pop()
    prev = out[-1]
    px, pz = _crossing(prev, seg, mirror, r_arc)
    out[-1] = prev._replace(x1=px, z1=pz)
    out.append(seg._replace(x0=px, z0=pz))


def _without_nowhere(profile: Profile) -> Profile:
    """``profile`` without its lines that go nowhere; the move after one starts where the last
    move kept ended, and keeps that point's zeros on the axes it does not move (a ``Z-0`` that
    goes nowhere leaves no -0 behind, as rs274 shows)."""
    kept: Profile = []
    for seg in profile:
        if seg.kind == LINE and (seg.x0, seg.z0) == (seg.x1, seg.z1):
            continue
        if kept:
            px, pz = kept[-1].x1, kept[-1].z1
            seg = seg._replace(x0=px, z0=pz, x1=px if seg.x1 == px else seg.x1,
                               z1=pz if seg.z1 == pz else seg.z1)
        kept.append(seg)
    return kept


def g70(out: Out, profile: Profile, start: tuple[float, float], d: float, e: float,
        p: float) -> None:
    """The passes of G70 Q- D- E- P- over ``profile`` (its first segment from ``start``); the
    traverse to ``start`` is the caller's."""
    # moves that go nowhere are left out (the approach too, when the start is the first point)
    profile = _without_nowhere(profile)
    if not profile:
        return
    passes = int(p)
    if passes <= 0:
        return
    if len(profile) < 2:
        return  # (no profile after the approach: nothing to follow)
    entry, axis = _entry(profile, start)
    side = pass_side(profile, entry, axis)
    first = profile[0]
    # a pass that moves the profile gives the zeros of its points the signs of rs274's frame (X
    # turned round for a profile ending below its first point, Z for one going +Z); one that
    # does not keeps the profile's own
    # (and Z round too for a profile along X that ends at a greater Z)
    turned = turning_zeros(profile[-1].x1 < first.x1,
                           axis[0] > 0 or (axis[0] == 0.0 and profile[-1].z1 > first.z1))
    for k in range(passes, 0, -1):
        out.m.work()  # (P sets how many passes there are)
        dist = (k - 1) * (d - e) / p + e
        path = moved(profile, side, dist, axis, work=out.m.work)
        out.zeros = None  # (the entry is not in the frame)
        out.traverse(*entry)
        out.zeros = turned if dist else None
        if path:
            out.traverse(path[0].x0, path[0].z0)
        else:
            out.traverse(first.x1, first.z1)
        for seg in path:
            if seg.kind == LINE:
                out.feed(seg.x1, seg.z1)
            else:
                out.arc(seg.x1, seg.z1, seg.cx, seg.cz, seg.kind, checked=True)
