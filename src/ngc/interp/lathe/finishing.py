"""G70, the lathe finishing cycle, as rs274 2.9.0~pre1 runs it.

What rs274 shows (program coordinates, X a radius; ``S`` the cycle's start point, ``F`` the
profile's first point, the end of the subroutine's first move, ``L`` its last point):

* The handler's traverse to ``S`` comes first (X/Z words, else the current point).
* The profile is either *along Z* or *along X*.  Along Z, going -Z, when no move of the profile
  after ``F`` rises in Z; along Z, going +Z, when none falls, there are at least two moves and the
  last one rises; otherwise along X, going the way ``L`` lies from ``F`` in X (-X on a tie).
* The entry point ``I``: a start *ahead* of ``F`` along the profile's axis (beyond F in the
  direction the profile goes) is brought to F's level on that axis first (along Z: (S.x, F.z),
  along X: (F.x, S.z)); otherwise ``I`` is ``S``.
* The side the profile moves to is the side of its first move (after ``F``) that ``I`` is on; a
  profile of one move, or ``I`` in line with that move's start, uses a fixed side: the one whose
  normal points +Z (+X for a move along Z) for one move, the right for ``I`` in line.
* P is truncated to an integer number of passes (P0 or less: none, only the traverse to S); pass
  ``k`` from P down to 1 is the profile moved (k-1)*(D-E)/P+E (P itself, not truncated, in the
  division) to that side; a negative distance moves it the other way.  Each segment moves along
  its normal (arcs keep their centre); an outside corner gets an arc of the distance about the
  programmed corner, an inside corner is cut back to where the moved segments cross; two moved
  lines in line at a corner are "G7X error: Cannot intersect parallel lines".
* Each pass: a traverse to ``I``, a traverse to the moved profile's first point, then G1/G2/G3
  feeds along it.  The tool is left at the last pass's end (the profile's end moved E); there is
  no move back.
* With cutter radius compensation on, the cycle's moves are compensated like programmed ones.
"""

from __future__ import annotations

import math

from ...errors import NgcSemanticError
from .offset import EPS, _shift, intersections, tangent
from .path import Out
from .profile import CCW, CW, LINE, Profile, Seg

TANGENT = 1e-3  # the sine of a turn below which an outside corner is cut like an inside one
NOT_MONOTONIC = "G7X error: Not monotonic"
PARALLEL = "G7X error: Cannot intersect parallel lines"


def _steps(seg: Seg, axis: int) -> tuple[float, bool]:
    """The change of ``seg`` along X (``axis`` 0) or Z (1) and whether it goes one way there
    (an arc that turns back on that axis does not)."""
    v0, v1 = (seg.x0, seg.x1) if axis == 0 else (seg.z0, seg.z1)
    if seg.kind == LINE:
        return v1 - v0, True
    # the arc's extremes on the axis lie where its radius is parallel to the axis
    for extreme in (0.0, math.pi) if axis == 1 else (math.pi / 2, -math.pi / 2):
        if _within(seg, extreme):
            return v1 - v0, False
    return v1 - v0, True


def _within(seg: Seg, angle: float) -> bool:
    """Whether the direction ``angle`` (atan2(x, z) about the centre) lies strictly inside the
    arc ``seg``."""
    a0 = math.atan2(seg.x0 - seg.cx, seg.z0 - seg.cz)
    a1 = math.atan2(seg.x1 - seg.cx, seg.z1 - seg.cz)
    if seg.kind == CW:
        a0, a1 = a1, a0
    sweep = (a1 - a0) % (2 * math.pi)
    at = (angle - a0) % (2 * math.pi)
    return EPS < at < sweep - EPS


def _monotonic(moves: list[Seg], axis: int, way: float) -> bool:
    for seg in moves:
        step, one_way = _steps(seg, axis)
        if not one_way or step * way < 0:
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
    way = 1.0 if any(seg.z1 - seg.z0 > 0 for seg in moves[1:]) else -1.0
    if _monotonic(moves, 1, way):
        return ((sx, fz) if (sz - fz) * way > 0 else start), (way, 0.0)
    last = moves[-1]
    way = 1.0 if last.x1 - fx > 0 else -1.0
    if not _monotonic(moves, 0, way):
        raise NgcSemanticError(NOT_MONOTONIC)
    return ((fx, sz) if (sx - fx) * way > 0 else start), (0.0, way)


def _side(profile: Profile, entry: tuple[float, float], axis: tuple[float, float]) -> float:
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
    # I in line (or a profile of one move): the side back against the way the profile goes
    tz, tx = tangent(first, False)
    back = -tx * axis[0] + tz * axis[1]  # the left normal (-tx, tz) along the axis
    return -1.0 if back >= 0 else 1.0


def _crossings(a: Seg, b: Seg) -> list[tuple[float, float]]:
    """Where the carriers of two moved segments cross; carriers that just miss each other (a
    corner close to tangent) meet where they come closest."""
    points = intersections(a, b)
    if points:
        return points
    if a.kind == LINE and b.kind == LINE:
        raise NgcSemanticError(PARALLEL)
    if a.kind == LINE or b.kind == LINE:
        line, arc = (a, b) if a.kind == LINE else (b, a)
        dx, dz = line.x1 - line.x0, line.z1 - line.z0
        t = ((arc.cx - line.x0) * dx + (arc.cz - line.z0) * dz) / (dx * dx + dz * dz)
        return [(line.x0 + t * dx, line.z0 + t * dz)]
    r1 = math.hypot(a.x0 - a.cx, a.z0 - a.cz)
    dx, dz = b.cx - a.cx, b.cz - a.cz
    n = math.hypot(dx, dz)
    return [(a.cx + dx / n * r1, a.cz + dz / n * r1)]


def _along(seg: Seg, pt: tuple[float, float]) -> float:
    """How far along ``seg`` (from its start, in its direction) ``pt`` lies."""
    x, z = pt
    if seg.kind == LINE:
        return (x - seg.x0) * (seg.x1 - seg.x0) + (z - seg.z0) * (seg.z1 - seg.z0)
    a0 = math.atan2(seg.x0 - seg.cx, seg.z0 - seg.cz)
    a = math.atan2(x - seg.cx, z - seg.cz)
    turn = (a - a0) % (2 * math.pi) if seg.kind == CCW else (a0 - a) % (2 * math.pi)
    return turn if turn < 1.5 * math.pi else turn - 2 * math.pi


def moved(profile: Profile, side: float, d: float) -> list[Seg]:
    """The profile after ``F`` moved ``d`` to ``side``, its corners joined."""
    moves = profile[1:]
    if d == 0.0:
        return list(moves)
    shifted = [_shift(seg, side, d) for seg in moves]
    out: list[Seg] = []
    for i, seg in enumerate(shifted):
        if not out:
            out.append(seg)
            continue
        prev = out[-1]
        t1 = tangent(moves[i - 1], True)
        t2 = tangent(moves[i], False)
        turn = t1[0] * t2[1] - t1[1] * t2[0]  # > 0: turning left
        if prev.kind == LINE and seg.kind == LINE and abs(turn) < EPS:
            raise NgcSemanticError(PARALLEL)
        if math.hypot(prev.x1 - seg.x0, prev.z1 - seg.z0) < EPS:
            out.append(seg)
            continue
        outside = turn * side * d < 0 and abs(turn) > TANGENT
        if outside:  # the moved segments part: an arc about the corner joins them
            corner = moves[i]
            out.append(Seg(CCW if turn > 0 else CW, prev.x1, prev.z1, seg.x0, seg.z0,
                           corner.x0, corner.z0, line=corner.line))
            out.append(seg)
            continue
        px, pz = min(_crossings(prev, seg), key=lambda pt: _along(prev, pt))
        out[-1] = prev._replace(x1=px, z1=pz)
        out.append(seg._replace(x0=px, z0=pz))
    return out


def g70(out: Out, profile: Profile, start: tuple[float, float], d: float, e: float,
        p: float) -> None:
    """The passes of G70 Q- D- E- P- over ``profile`` (its first segment from ``start``); the
    traverse to ``start`` is the caller's."""
    if not profile:
        return
    passes = int(p)
    if passes <= 0:
        return
    if len(profile) < 2:
        return  # (no profile after the approach: nothing to follow)
    entry, axis = _entry(profile, start)
    side = _side(profile, entry, axis)
    first = profile[0]
    for k in range(passes, 0, -1):
        dist = (k - 1) * (d - e) / p + e
        path = moved(profile, side, dist)
        out.traverse(*entry)
        if path:
            out.traverse(path[0].x0, path[0].z0)
        else:
            out.traverse(first.x1, first.z1)
        for seg in path:
            if seg.kind == LINE:
                out.feed(seg.x1, seg.z1)
            else:
                out.arc(seg.x1, seg.z1, seg.cx, seg.cz, seg.kind)
