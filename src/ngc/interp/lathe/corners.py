"""Fillets (A word) and chamfers (C word) at the corners of a lathe cycle's profile, as rs274
2.9.0~pre1 inserts them.

A move's A or C asks for a fillet or chamfer of that size (its absolute value) at the move's end,
between it and the next move; on the last move it does nothing.  The fillet is the circle of that
radius tangent to both moves on the side the path turns to (the left when the tangents at the
corner turn counterclockwise in the (z, x) plane, else the right, a straight-on corner included):
its centre is where the two moves, moved the radius to that side, meet (lines as lines, arcs as
circles about the same centre, radius grown or shrunk), the crossing nearest the corner.  The
moves are cut back to the feet of the centre on them (on an arc: the centre's direction from the
arc's centre at the arc's radius), and an arc (G3 for a left turn, G2 for a right one) or, for a
chamfer, a line joins the two feet.

What rs274 shows:

* Two lines in the same or opposite direction: "G7X error: Cannot intersect parallel lines".
* A move cut back past its other end (or to nothing), by one corner or by the two at its ends
  together: "G7X error: Not monotonic" (the docs' "non-monotonic path error" of a radius too big).
* A line meeting an arc, or two arcs, that touch at the corner without turning give a fillet of no
  length: the corner stays as it was (the profile's shortest moves are dropped afterwards).
* An A word of 0 (or -0), on any move, even the last: "G7X error: Not monotonic", before any
  corner is made (a C of 0 does nothing).  The recording gives such a move the ``fillet``
  ``A_ZERO`` (-0.0).
* A and C on one move: "G7X error: Both A and C parameters on a corner", when the move is recorded
  (``BOTH_A_AND_C``).
* A move that ends where it starts is left out, with its A or C (the move before it meets the
  move after it).
* G0 moves of the profile take A and C like G1 moves; the first move (from the cycle's start point)
  has a corner at its end like any other.
"""

from __future__ import annotations

import itertools
import math

from ...errors import NgcSemanticError
from .profile import CCW, CW, LINE, NOT_MONOTONIC, PARALLEL, Profile, Seg

BOTH_A_AND_C = "G7X error: Both A and C parameters on a corner"
A_ZERO = -0.0
"""The ``fillet`` of a move whose A word is 0: told apart from a move without A by its sign."""
_TOUCH = 1e-9  # relative: a line or circle this near to touching a circle touches it
_ANGLE = 1e-6  # radians an arc may gain at a fillet of no size (where it touches its neighbour)
_SHORT = 1e-3  # moves shorter than this (program units) are dropped


def _tangent(seg: Seg, at_end: bool) -> tuple[float, float]:
    """The direction (dz, dx) of ``seg`` at its end or start (not normalized)."""
    if seg.kind == LINE:
        return seg.z1 - seg.z0, seg.x1 - seg.x0
    pz, px = (seg.z1, seg.x1) if at_end else (seg.z0, seg.x0)
    rz, rx = pz - seg.cz, px - seg.cx
    # G3 is counterclockwise in (z, x): the direction is the radius turned left
    return (-rx, rz) if seg.kind == CCW else (rx, -rz)


def _radius(seg: Seg) -> float:
    return math.hypot(seg.x1 - seg.cx, seg.z1 - seg.cz)


def _shifted_line(seg: Seg, side: float, r: float) -> tuple[float, float, float, float]:
    """``seg`` (a line) moved ``r`` to its left (side +1) or right (-1): a point and its
    direction, (x, z, dx, dz)."""
    dx, dz = seg.x1 - seg.x0, seg.z1 - seg.z0
    n = math.hypot(dx, dz)
    # left of (dz, dx) in (z, x) is (-dx, dz)
    return seg.x0 + side * r * dz / n, seg.z0 - side * r * dx / n, dx, dz


def _shifted_radius(seg: Seg, side: float, r: float) -> float:
    """The radius of arc ``seg`` moved ``r`` to its left (side +1) or right (-1)."""
    toward_centre = side if seg.kind == CCW else -side  # G3 has its centre on its left
    return _radius(seg) - toward_centre * r


def _near(points: list[tuple[float, float]], px: float,
          pz: float) -> tuple[float, float] | None:
    if not points:  # the radius is too big for the corner
        return None
    return min(points, key=lambda p: math.hypot(p[0] - px, p[1] - pz))


def _line_line(a: tuple[float, float, float, float],
               b: tuple[float, float, float, float]) -> tuple[float, float]:
    ax, az, adx, adz = a
    bx, bz, bdx, bdz = b
    den = adz * bdx - adx * bdz
    if den == 0.0:
        raise NgcSemanticError(PARALLEL)
    t = ((bz - az) * bdx - (bx - ax) * bdz) / den
    return ax + t * adx, az + t * adz


def _line_circle(line: tuple[float, float, float, float], cx: float, cz: float,
                 r: float) -> list[tuple[float, float]]:
    x0, z0, dx, dz = line
    fx, fz = x0 - cx, z0 - cz
    a = dx * dx + dz * dz
    b = 2.0 * (fx * dx + fz * dz)
    c = fx * fx + fz * fz - r * r
    disc = b * b - 4.0 * a * c
    if disc < 0.0:
        if disc < -_TOUCH * b * b:
            return []
        disc = 0.0  # the line touches the circle
    sq = math.sqrt(disc)
    return [(x0 + t * dx, z0 + t * dz) for t in ((-b - sq) / (2.0 * a), (-b + sq) / (2.0 * a))]


def _circle_circle(ax: float, az: float, ar: float, bx: float, bz: float,
                   br: float) -> list[tuple[float, float]]:
    dx, dz = bx - ax, bz - az
    d = math.hypot(dx, dz)
    if d == 0.0:
        return []
    along = (d * d + ar * ar - br * br) / (2.0 * d)
    h2 = ar * ar - along * along
    if h2 < 0.0:
        if h2 < -_TOUCH * ar * ar:
            return []
        h2 = 0.0  # the circles touch
    h = math.sqrt(h2)
    mx, mz = ax + along * dx / d, az + along * dz / d
    return [(mx - h * dz / d, mz + h * dx / d), (mx + h * dz / d, mz - h * dx / d)]


def _foot(seg: Seg, ox: float, oz: float) -> tuple[float, float]:
    """The point of ``seg``'s line or circle nearest the centre (ox, oz) of a fillet."""
    if seg.kind == LINE:
        dx, dz = seg.x1 - seg.x0, seg.z1 - seg.z0
        t = ((ox - seg.x0) * dx + (oz - seg.z0) * dz) / (dx * dx + dz * dz)
        return seg.x0 + t * dx, seg.z0 + t * dz
    r = _radius(seg)
    d = math.hypot(ox - seg.cx, oz - seg.cz)
    if d == 0.0:  # (a fillet about the arc's own centre: rs274 finds the path not monotonic)
        raise NgcSemanticError(NOT_MONOTONIC)
    return seg.cx + (ox - seg.cx) * r / d, seg.cz + (oz - seg.cz) * r / d


def _centre(a: Seg, b: Seg, side: float, r: float,
            flip: bool) -> tuple[float, float] | None:
    """The centre of the circle of radius ``r`` tangent to ``a`` and ``b`` on ``side``; ``flip``
    when the profile runs toward -X or toward +Z, not both."""
    px, pz = a.x1, a.z1
    if a.kind == LINE and b.kind == LINE:
        return _line_line(_shifted_line(a, side, r), _shifted_line(b, side, r))
    if a.kind == LINE or b.kind == LINE:
        line, arc = (a, b) if a.kind == LINE else (b, a)
        return _near(_line_circle(_shifted_line(line, side, r), arc.cx, arc.cz,
                                  _shifted_radius(arc, side, r)), px, pz)
    # two arcs: not the crossing nearest the corner but the one on a fixed side of the line
    # from the first arc's centre to the second's, in the profile turned to run toward +X and -Z
    points = _circle_circle(a.cx, a.cz, _shifted_radius(a, side, r),
                            b.cx, b.cz, _shifted_radius(b, side, r))
    return points[1 if flip else 0] if points else None


def _sweep(seg: Seg) -> float:
    """The angle an arc turns through, in its direction, in [0, 2 pi)."""
    a0 = math.atan2(seg.x0 - seg.cx, seg.z0 - seg.cz)
    a1 = math.atan2(seg.x1 - seg.cx, seg.z1 - seg.cz)
    s = a1 - a0 if seg.kind == CCW else a0 - a1
    return s % (2.0 * math.pi)


def _kept(new: Seg, old: Seg, to_nothing: bool = True) -> bool:
    """Whether ``new``, ``old`` cut back at its ends, still runs the way ``old`` did; a line cut
    back to nothing does where ``to_nothing``."""
    if new.kind == LINE:
        way = (new.x1 - new.x0) * (old.x1 - old.x0) + (new.z1 - new.z0) * (old.z1 - old.z0)
        return way > 0.0 or (to_nothing and way == 0.0)
    s = _sweep(new)
    return 0.0 < s <= _sweep(old) + _ANGLE


def round_corners(profile: Profile) -> Profile:
    """``profile`` with a fillet arc or chamfer line at the end of each move that asks for one
    (but the last), the moves on either side cut back to meet it, and its shortest moves dropped
    (``drop_short``).

    A corner cutting a line back past its other end, or too big to be made, is refused at once;
    an arc cut back too far, or a line cut back at both ends until they cross, only once every
    corner is made (two parallel lines at a later corner are reported first)."""
    if any(seg.fillet == 0.0 and math.copysign(1.0, seg.fillet) < 0.0 for seg in profile):
        raise NgcSemanticError(NOT_MONOTONIC)  # an A of 0 anywhere, before any corner is made
    # a move that goes nowhere is no move: its A or C goes with it
    profile = [seg for seg in profile if seg.x1 != seg.x0 or seg.z1 != seg.z0]
    if not profile:
        return []
    made: list[Seg | None] = []  # per corner: its fillet arc or chamfer line
    first, last = profile[0], profile[-1]
    flip = (last.x1 < first.x1) != (last.z1 > first.z1)
    for cur, nxt in itertools.pairwise(profile):
        size = abs(cur.fillet) or abs(cur.chamfer)
        if size == 0.0:
            made.append(None)
            continue
        t1 = _tangent(cur, True)
        t2 = _tangent(nxt, False)
        side = 1.0 if t1[0] * t2[1] - t1[1] * t2[0] > 0.0 else -1.0
        centre = _centre(cur, nxt, side, size, flip)
        if centre is None:
            raise NgcSemanticError(NOT_MONOTONIC)
        ox, oz = centre
        ax, az = _foot(cur, ox, oz)
        bx, bz = _foot(nxt, ox, oz)
        # (a line may be cut back to nothing at its end, not at its start)
        if not ((cur.kind != LINE or _kept(cur._replace(x1=ax, z1=az), cur))
                and (nxt.kind != LINE or _kept(nxt._replace(x0=bx, z0=bz), nxt, False))):
            raise NgcSemanticError(NOT_MONOTONIC)
        if cur.fillet:
            corner = Seg(CCW if side > 0 else CW, ax, az, bx, bz, ox, oz, line=cur.line)
        else:
            corner = Seg(LINE, ax, az, bx, bz, line=cur.line)
        made.append(corner)
    out: Profile = []
    for i, seg in enumerate(profile):
        cut = seg._replace(fillet=0.0, chamfer=0.0)
        before = made[i - 1] if i else None
        after = made[i] if i < len(made) else None
        if before is not None:
            cut = cut._replace(x0=before.x1, z0=before.z1)
        if after is not None:
            cut = cut._replace(x1=after.x0, z1=after.z0)
        # (a line one corner cuts back to nothing is kept, as rs274 does; the two at its ends
        # together may not)
        if not _kept(cut, seg, before is None or after is None):
            raise NgcSemanticError(NOT_MONOTONIC)
        if after is not None and cut.x0 == cut.x1 and cut.z0 == cut.z1:
            # a line the corner at its end cuts back to nothing: rs274 runs the corner as a
            # line from foot to foot, a fillet too
            out.append(after._replace(kind=LINE, cx=0.0, cz=0.0))
            continue
        out.append(cut)
        if after is not None:
            out.append(after)
    return drop_short(out)


def drop_short(profile: Profile) -> Profile:
    """``profile`` without its moves (after the first) shorter than 0.001 from end to end: the
    moves on either side meet at the dropped move's middle; a short last move just goes."""
    out: Profile = profile[:1]
    rest = profile[1:]
    for i, seg in enumerate(rest):
        if math.hypot(seg.x1 - seg.x0, seg.z1 - seg.z0) >= _SHORT:
            out.append(seg)
            continue
        if i + 1 == len(rest):
            break
        mx, mz = (seg.x0 + seg.x1) / 2.0, (seg.z0 + seg.z1) / 2.0
        out[-1] = out[-1]._replace(x1=mx, z1=mz)
        rest[i + 1] = rest[i + 1]._replace(x0=mx, z0=mz)
    return out
