"""Joins with an arc or a helix, as LinuxCNC 2.9's planner makes them (measured; see
``docs/planner.md``): which joins are rounded, how fast a corner blend beside an arc may run, and
where the blend circle touches a line or an arc in the same plane.

A helix is never rounded: a kinked join with one is a parabolic blend.  Under G64 without P a
corner between a line and an arc, or two arcs, in one plane is rounded too.  The blend is a circle
tangent to both moves; it touches an arc on the inside when the arc curves into the corner and on
the outside otherwise, so it takes different lengths from the two moves.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from typing import TYPE_CHECKING

from .geometry import Arc, Line, Piece, Vec

SQRT3_2 = math.sqrt(3.0) / 2.0
# the greatest sweep the rules that count an arc's sweep were measured on (quarter and half
# circles); a longer arc (a full circle) keeps the rules of the corner alone
HALF_TURN = math.pi + 1e-9
LONG_ARC_TURN = math.pi / 8.0  # under G64 P: measured on three quarters of a circle and a full one
# a line into an arc that curves into the corner over more than this is not rounded where the blend
# it aims for is too wide for the arc (measured: 122.5° rounded, 125° not, whatever the width)
WIDE_BLEND_SWEEP = math.radians(123.75)
SQRT3_4 = math.sqrt(3.0) / 4.0

if TYPE_CHECKING:
    from .segment import Segment, Shape


def helical(shape: Shape) -> bool:
    """Whether ``shape`` is (part of) a helix: an arc that rises along its plane's normal."""
    if isinstance(shape, Piece):
        shape = shape.base
    return isinstance(shape, Arc) and abs(shape.rise) > 1e-12


def coplanar(a: Shape, b: Shape) -> bool:
    """Whether two moves, one of them an arc, lie in one plane."""
    if isinstance(a, Piece):
        a = a.base
    if isinstance(b, Piece):
        b = b.base
    arc, other = (a, b) if isinstance(a, Arc) else (b, a)
    if not isinstance(arc, Arc):
        return False
    n = arc.normal
    p: Sequence[float]
    q: Sequence[float]
    if isinstance(other, Arc):
        m = other.normal
        cross = (n[1] * m[2] - n[2] * m[1], n[2] * m[0] - n[0] * m[2], n[0] * m[1] - n[1] * m[0])
        if max(abs(c) for c in cross) > 1e-9:
            return False
        p, q = arc.center, other.center
    elif isinstance(other, Line):
        p, q = arc.center, other.start
        d = ((other.end[0] - q[0]) * n[0] + (other.end[1] - q[1]) * n[1]
             + (other.end[2] - q[2]) * n[2])
        if abs(d) > 1e-9:
            return False
    else:
        return False
    return abs((q[0] - p[0]) * n[0] + (q[1] - p[1]) * n[1] + (q[2] - p[2]) * n[2]) < 1e-9


def arcs_at(prev: Segment, seg: Segment) -> Iterator[tuple[Arc, bool, bool]]:
    """The arcs at the join of ``prev`` and ``seg``: each with whether it comes first (ends at
    the join) and whether it curves the way the corner turns (into the corner)."""
    u1, u2 = prev.end_dir, seg.start_dir
    turn = (u1[1] * u2[2] - u1[2] * u2[1], u1[2] * u2[0] - u1[0] * u2[2],
            u1[0] * u2[1] - u1[1] * u2[0])
    for shape, at_end in ((prev.shape, True), (seg.shape, False)):
        base = shape.base if isinstance(shape, Piece) else shape
        if not isinstance(base, Arc):
            continue
        p = shape.point(shape.length if at_end else 0.0)
        t = u1 if at_end else u2
        c = base.center
        w = (c[0] - p[0], c[1] - p[1], c[2] - p[2])
        bend = (t[1] * w[2] - t[2] * w[1], t[2] * w[0] - t[0] * w[2], t[0] * w[1] - t[1] * w[0])
        yield base, at_end, turn[0] * bend[0] + turn[1] * bend[1] + turn[2] * bend[2] > 0.0


def arc_blend_cap(prev: Segment, seg: Segment, theta: float, a: float, room: float) -> float:
    """The greatest speed of a corner blend next to an arc (acceleration a in the corner's plane,
    ``room`` what the moves may give): beside an arc that curves into the corner (sweep φ,
    radius r) the blend is the circle of a turn sharper by φ/6 reaching d = min(room, r·φ/12)
    from the corner, so it runs at √(√3/2·a·d / tan((θ + φ/6)/2)) (measured on quarter circles
    of r 5 at 30° to 120°, half circles of r 2 at 30° and 45°, and 0.45 mm lines between half
    circles of r 3 and 6; for an arc of more than half a turn only the second cap), and at
    √(0.65·a·r·(1 - s)/(1 + s)), s = sin(θ/2); beside one that curves away from it and follows
    the blend at √(π/(2√3)·a·r)."""
    cap = math.inf
    s = math.sin(0.5 * theta)
    for arc, at_end, same in arcs_at(prev, seg):
        r = arc.radius
        if same:
            cap = min(cap, math.sqrt(0.65 * a * r * (1.0 - s) / (1.0 + s)))
            if arc.sweep <= HALF_TURN:
                reach = min(room, r * arc.sweep / 12.0)
                half = min(0.5 * (theta + arc.sweep / 6.0), 0.5 * math.pi - 1e-6)
                cap = min(cap, math.sqrt(SQRT3_2 * a * reach / math.tan(half)))
        elif not at_end:
            cap = min(cap, math.sqrt(math.pi / (2.0 * math.sqrt(3.0)) * a * r))
    return cap


def too_wide_for_arc(prev: Segment, seg: Segment, theta: float, goal: float, a: float) -> bool:
    """Whether a line into an arc that curves into the corner (sweep φ from 123.75° to half a
    turn, radius r) keeps a parabolic blend: the blend it aims for, the radius
    R = min(v²/(√3/4·a), d/tan(θ/2)) (v the faster move's speed ``goal``, a the acceleration in the
    corner's plane, d what the line may give: half its length), is wider than c·r, c = 8.68 at
    180° to 9.52 at 135°, 0.84 more for each 45° less (measured at 90° on the XY axes of 200 mm/s
    and 1000 mm/s², the line from rest: a half circle of r 0.6, 1 and 2 after lines of 20 to
    40 mm rounded up to 46.9, 60.6 and 86.1 mm/s and not from 48.0, 62.1 and 88.2; r 1 from
    62.1 and 63.5 at 160°, r 0.6 and 1 from 50.3 and 65.0 at 135°; a line of 16 mm rounded,
    18 mm not, at 200 mm/s; a sweep of 122.5° rounded where R is 16.7·r, 125° not at 10·r)."""
    if not isinstance(prev.shape, Line):
        return False
    for arc, at_end, same in arcs_at(prev, seg):
        if at_end or not same or not WIDE_BLEND_SWEEP < arc.sweep <= HALF_TURN:
            continue
        d = min(0.5 * prev.full_length, prev.length)
        wide = min(goal * goal / (SQRT3_4 * a), d / math.tan(0.5 * theta))
        c = 8.68 + 0.84 * (math.pi - arc.sweep) / (0.25 * math.pi)
        if wide > c * arc.radius:
            return True
    return False


def arc_room(prev: Segment, seg: Segment, room: float) -> float:
    """What the moves may give to a corner blend before an arc that curves away from the corner:
    at most a third of the arc's length (measured on a quarter circle of r 5 under G64 without
    P: blends reaching 2.62 mm from the corner at 90° and 120°, radius 2.62 and 1.51 mm; an arc
    that ends at such a corner gives up to half its length, as a line does)."""
    for arc, at_end, same in arcs_at(prev, seg):
        if not same and not at_end:
            room = min(room, arc.length / 3.0)
    return room


def arc_away_tolerance(prev: Segment, seg: Segment, tolerance: float) -> float:
    """The tolerance of a corner blend beside an arc that curves away from the corner (before or
    after it): the blend is sized as one between the tangents at the corner that passes at most a
    quarter of the arc's programmed length from the corner, and the circle of that radius is then
    fitted to the moves (measured under G64 without P: a quarter circle of r 5 into a line at 120°
    and 150°, blends of radius 1.963 and 0.686 mm, each 1.963 mm from the corner of the tangents;
    a line into such an arc at 150° the same; half a circle of r 2 and an eighth of one of r 8
    into a line at 135°: radius 0.974 mm); ``tolerance`` 0 is none."""
    for arc, _, same in arcs_at(prev, seg):
        if not same:
            cap = 0.25 * arc.length
            tolerance = cap if tolerance <= 0.0 else min(tolerance, cap)
    return tolerance


def arc_tolerance(prev: Segment, seg: Segment, theta: float) -> float:
    """The tolerance that sizes a corner blend next to an arc under G64 P: an arc that curves into
    the corner counts as a turn sharper by a sixth of its sweep (measured on quarter circles into
    lines at 30° to 120°: the blend of a turn 15° sharper, to 0.01°; half circles: 29° to 34°;
    three quarters of a circle and a full one: 22.5°), so the blend's radius is the tolerance's at
    that angle."""
    extra = 0.0
    for arc, _, same in arcs_at(prev, seg):
        if same:
            extra += arc.sweep / 6.0 if arc.sweep <= HALF_TURN else LONG_ARC_TURN
    tolerance: float = abs(prev.tolerance)
    if extra <= 0.0:
        return tolerance
    c0 = math.cos(0.5 * theta)
    if c0 >= 1.0:
        return tolerance  # (no turn at the join: nothing to size)
    c1 = math.cos(min(0.5 * (theta + extra), 0.5 * math.pi - 1e-6))
    return tolerance * (c1 / (1.0 - c1)) / (c0 / (1.0 - c0))


def least_radius(theta: float, speed: float, normal: float, cycles: float) -> float:
    """The smallest radius a blend beside an arc that curves into the corner is given: the one
    that lets ``speed`` through (centripetal acceleration ``normal``), but no smaller than keeps
    the blend, turning by about ``theta``, ``cycles`` seconds long at that speed (two servo
    periods: a shorter blend would be slowed down to last them; LinuxCNC passes the joins of a G5
    curve's arcs and chords, 0.5° to 1.7°, at the feed)."""
    return max(speed * speed / normal, cycles * speed / max(theta, 1e-9))


def line_arc_fit(prev: Segment, seg: Segment, theta: float, radius: float, room: float,
                 speed: float, normal: float, cycles: float) -> tuple[float, float, float] | None:
    """How much a blend circle of ``radius`` tangent to both a line and an arc (in one plane)
    takes from ``prev`` and from ``seg``, and its length; the radius shrinks until neither
    gives more than ``room``."""
    side = next(arcs_at(prev, seg), None)
    if side is None:
        return None
    arc, arc_first, same = side
    if same:  # the radius that lets the speed through, no longer
        radius = min(radius, least_radius(theta, speed, normal, cycles))
    r = arc.radius
    sin_t, cos_t = math.sin(theta), math.cos(theta)
    # the line runs along +x into the join at the origin, the arc leaves it turning left by
    # theta (an arc before the join is the mirror image of one after it)
    if same:
        cx, cy, dist = -r * sin_t, r * cos_t, -1.0
    else:
        cx, cy, dist = r * sin_t, -r * cos_t, 1.0
    big = radius
    for _ in range(40):
        dd = (r + dist * big) ** 2 - (big - cy) ** 2
        if (big < r or dist > 0.0) and dd >= 0.0:
            x = -cx - math.sqrt(dd) if same else -cx + math.sqrt(dd)
            bx, by = -x, big
            a0 = math.atan2(-cy, -cx)
            a1 = math.atan2(by - cy, bx - cx)
            phi = abs(math.remainder(a1 - a0, 2.0 * math.pi))
            take = r * phi
            if 0.0 <= x <= room and take <= room:
                turn = theta + phi if same else theta - phi
                length = big * max(turn, 0.0)
                return (take, x, length) if arc_first else (x, take, length)
        big *= 0.8
    return None


def arc_arc_fit(prev: Segment, seg: Segment, theta: float, radius: float, room: float,
                speed: float, normal: float, cycles: float) -> tuple[float, float, float] | None:
    """As :func:`line_arc_fit`, for two arcs in one plane."""
    a1 = prev.shape.base if isinstance(prev.shape, Piece) else prev.shape
    a2 = seg.shape.base if isinstance(seg.shape, Piece) else seg.shape
    if not isinstance(a1, Arc) or not isinstance(a2, Arc):
        return None
    u1, u2 = prev.end_dir, seg.start_dir
    cos_t = u1[0] * u2[0] + u1[1] * u2[1] + u1[2] * u2[2]
    ey = (u2[0] - cos_t * u1[0], u2[1] - cos_t * u1[1], u2[2] - cos_t * u1[2])
    n = math.sqrt(ey[0] ** 2 + ey[1] ** 2 + ey[2] ** 2)
    if n < 1e-12:
        return None
    ey = (ey[0] / n, ey[1] / n, ey[2] / n)
    p = prev.shape.point(prev.shape.length)

    def local(c: Vec) -> tuple[float, float]:
        w = (c[0] - p[0], c[1] - p[1], c[2] - p[2])
        return (w[0] * u1[0] + w[1] * u1[1] + w[2] * u1[2],
                w[0] * ey[0] + w[1] * ey[1] + w[2] * ey[2])

    c1, c2 = local(a1.center), local(a2.center)
    r1, r2 = a1.radius, a2.radius
    st, ct = math.sin(theta), math.cos(theta)
    same1 = c1[1] > 0.0  # curves into the corner
    same2 = -st * c2[0] + ct * c2[1] > 0.0
    if same1 or same2:
        radius = min(radius, least_radius(theta, speed, normal, cycles))
    big = radius
    for _ in range(40):
        d1 = r1 - big if same1 else r1 + big
        d2 = r2 - big if same2 else r2 + big
        dx, dy = c2[0] - c1[0], c2[1] - c1[1]
        d = math.hypot(dx, dy)
        if d1 > 0.0 and d2 > 0.0 and d > 1e-12:
            a = (d1 * d1 - d2 * d2 + d * d) / (2.0 * d)
            h2 = d1 * d1 - a * a
            if h2 >= 0.0:
                h = math.sqrt(h2)
                mx, my = c1[0] + a * dx / d, c1[1] + a * dy / d
                best = None
                for sgn in (1.0, -1.0):
                    bx, by = mx - sgn * h * dy / d, my + sgn * h * dx / d
                    if by > 0.0 and (best is None or bx * bx + by * by < best[0]):
                        best = (bx * bx + by * by, bx, by)
                if best is not None:
                    _, bx, by = best
                    phi1 = abs(math.remainder(math.atan2(by - c1[1], bx - c1[0])
                                              - math.atan2(-c1[1], -c1[0]), 2.0 * math.pi))
                    phi2 = abs(math.remainder(math.atan2(by - c2[1], bx - c2[0])
                                              - math.atan2(-c2[1], -c2[0]), 2.0 * math.pi))
                    take1, take2 = r1 * phi1, r2 * phi2
                    if take1 <= room and take2 <= room:
                        turn = (theta + (phi1 if same1 else -phi1)
                                + (phi2 if same2 else -phi2))
                        return take1, take2, big * max(turn, 0.0)
        big *= 0.8
    return None
