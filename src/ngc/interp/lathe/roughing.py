"""G71 (turning) and G72 (facing) roughing, with their .1 (no pockets) and .2 (pockets only)
variants, as rs274 2.9.0~pre1 cuts them.

The cycle works in a frame of two axes: ``a``, the axis the passes step along (X for G71, Z for
G72), and ``b``, the axis each pass cuts along.  What rs274 shows:

* The profile's first move, from the start point, is the approach; the rest is moved ``D`` toward
  the start as G70 moves it (``finishing.moved``; with a D, two lines in a row along X or along Z
  are refused first).  ``P0`` is the moved profile's first point, ``E`` its last.
* The passes cut along ``b`` the way the profile goes from ``P0`` to ``E`` (toward -b where it
  goes nowhere along ``b``).  A start ahead of the profile's first point along ``b`` (in the
  direction of the cut) is moved back to that point's ``b``.
* The passes step from the start toward ``P0``: away from ``E`` on ``a`` (G71: toward larger X when
  E is below P0, else smaller; G72 the same on Z, a tie counting the other way).  If the profile
  lies nowhere beyond the start that way there is nothing to rough: the tool feeds from the
  start along the profile moved D to the side G70 would move it from the start (G7x.1: each
  move entered by a feed to its start and its pockets bridged, as in its contour pass below).
* Each level ``start + k*I`` before P0 (stepped ``I`` at a time): a traverse to where the level
  meets the approach, then (if the level meets the profile, or the closing line from E back to
  the start's level, past that point) a feed along ``b`` to the first such point, a traverse back
  R on both axes, a traverse to R past the entry, and a traverse to the entry (R at most half the
  pass: a short pass retracts to its middle).
* Then a traverse to P0 (a feed where P0 lies at or short of the start's level) and a feed along the
  moved profile, its arcs cut where they turn from climbing to going deeper.  Where it goes
  deeper (a pocket), each level of the start's grid it goes down through (G7x.2: each level from
  the pocket's top) is cut: a feed down along the profile to the level (from the top itself only
  where a line of the profile goes down from it), across to the profile's far side, a retract of
  R on both axes, a traverse back and a feed to the entry.  The profile's way down from P0 (its
  first pieces going deeper, up to the first going no deeper or after one climbing at its end;
  none where the way to P0 is fed) is cut so by G7x.1 too and left uncut by G7x.2; past it, G7x.1
  enters each move and each arc rounding a corner with a feed (of no length) to its start and
  bridges a pocket by a feed across its top (entered so only from a corner's arc), and G7x.2
  cuts each pocket from its own top.  A last feed closes back to the start's level at E unless
  E lies on it or beyond it (rs274's own arithmetic sometimes leaves a G72's moved E a few
  units in the last place short of the level, and closes it with a feed of no length).
* rs274 leaves out some of G7x.1's feeds of no length.  The cases found (a crossing of lines
  along X and Z, the ends of a chamfer or a fillet) suggest it feeds only where its arithmetic
  leaves the two points unequal; no rule is known, and ngc always feeds.
* Zeros print with the sign rs274's frame gives them (``zeros.turning_zeros``,
  ``zeros.facing_zeros``).
"""

from __future__ import annotations

import math

from .finishing import moved_with_corners, pass_side
from .offset import EPS, line_circle
from .path import Out
from .profile import CCW, CW, LINE, Seg, within
from .zeros import facing_zeros, turning_zeros


class _Frame:
    """Maps (x, z) to the cycle's (a, b) and back; G72 swaps the axes."""

    __slots__ = ("swap",)

    def __init__(self, swap: bool) -> None:
        self.swap = swap

    def ab(self, x: float, z: float) -> tuple[float, float]:
        return (z, x) if self.swap else (x, z)

    def xz(self, a: float, b: float) -> tuple[float, float]:
        return (b, a) if self.swap else (a, b)


# two crossings of a level with an arc this close are one: the level touches it
_ONE = 1e-6


def _level_hits(seg: Seg, fr: _Frame, level: float) -> list[float]:
    """The ``b`` coordinates where ``seg`` meets the line a = level."""
    a0, b0 = fr.ab(seg.x0, seg.z0)
    a1, b1 = fr.ab(seg.x1, seg.z1)
    if seg.kind == LINE:
        if a0 == a1:
            return []
        lo, hi = min(a0, a1), max(a0, a1)
        if not lo - EPS <= level <= hi + EPS:
            return []
        return [b0 + (level - a0) * (b1 - b0) / (a1 - a0)]
    ca, cb = fr.ab(seg.cx, seg.cz)
    r = math.hypot(a0 - ca, b0 - cb)
    out = []
    for pa, pb in line_circle(level, -1.0, level, 1.0, ca, cb, r):
        if _on_arc(seg, fr, pa, pb):
            out.append(pb)
    if len(out) == 2 and abs(out[1] - out[0]) <= _ONE:
        return [(out[0] + out[1]) / 2]  # (the level touches the arc inside it: one point)
    return out


def _on_arc(seg: Seg, fr: _Frame, pa: float, pb: float) -> bool:
    """Whether the point (a, b) on the circle of ``seg`` lies on the arc itself."""
    px, pz = fr.xz(pa, pb)
    def angle(x: float, z: float) -> float:
        return math.atan2(x - seg.cx, z - seg.cz)  # in (z, x): CCW positive
    s, e, p = angle(seg.x0, seg.z0), angle(seg.x1, seg.z1), angle(px, pz)
    sweep = (e - s) % (2 * math.pi) if seg.kind == CCW else (s - e) % (2 * math.pi)
    at = (p - s) % (2 * math.pi) if seg.kind == CCW else (s - p) % (2 * math.pi)
    return at <= sweep + 1e-12 or at >= 2 * math.pi - 1e-12


# how near a level's crossing with the profile is to where the tool is for it to be there (a
# level through an arc's top meets it at a tangent, known to about the square root of EPS)
_TOUCH = 1e-6

# an arc climbing no more than this to its top is not cut there (rs274 leaves whole an arc
# whose top lies 1.5e-8 above its start, and cuts one climbing 4e-5)
_NO_CLIMB = 1e-6

MOVE, CORNER, CONT = 0, 1, 2  # a piece of the walk: a move, an arc rounding a corner, the
# rest of an arc cut where it turns


def _split(profile: list[Seg], corners: set[int], fr: _Frame, s: float
           ) -> tuple[list[Seg], list[int]]:
    """The moved profile with each arc cut where it turns from climbing to going deeper (its
    extreme least far along ``s`` on ``a``), as rs274 walks it; and what each piece is (MOVE,
    CORNER: an arc ``moved`` put in at an outside corner, CONT: the rest of a cut arc)."""
    out: list[Seg] = []
    tags: list[int] = []
    top = _extreme(fr, -s)
    for i, seg in enumerate(profile):
        out.append(seg)
        tags.append(CORNER if i in corners else MOVE)
        if seg.kind == LINE or not within(seg, top):
            continue
        px, pz = _extreme_point(seg, fr, -s)
        if abs(fr.ab(px, pz)[0] - fr.ab(seg.x0, seg.z0)[0]) <= _NO_CLIMB:
            continue
        out[-1] = seg._replace(x1=px, z1=pz)
        out.append(seg._replace(x0=px, z0=pz))
        tags.append(CONT)
    return out, tags


def _depth(seg: Seg, fr: _Frame, s: float) -> tuple[Seg, float]:
    """The part of ``seg`` going deeper (along ``s`` on ``a``) from its start, and the ``a`` it
    goes down to (its start's when it climbs)."""
    a0 = fr.ab(seg.x0, seg.z0)[0]
    a1 = fr.ab(seg.x1, seg.z1)[0]
    if seg.kind != LINE and within(seg, _extreme(fr, s)):
        bx, bz = _extreme_point(seg, fr, s)
        return seg._replace(x1=bx, z1=bz), fr.ab(bx, bz)[0]
    return seg, a1 if s * (a1 - a0) > 0 else a0


def _extreme(fr: _Frame, way: float) -> float:
    """The direction about an arc's centre (atan2(x, z)) of its extreme toward ``way`` on ``a``."""
    if fr.swap:
        return 0.0 if way > 0 else math.pi
    return math.pi / 2 if way > 0 else -math.pi / 2


def _extreme_point(seg: Seg, fr: _Frame, way: float) -> tuple[float, float]:
    """The point of the circle of ``seg`` farthest toward ``way`` on ``a``."""
    r = math.hypot(seg.x0 - seg.cx, seg.z0 - seg.cz)
    if fr.swap:
        return seg.cx, seg.cz + way * r
    return seg.cx + way * r, seg.cz


def _emit(out: Out, seg: Seg) -> None:
    if seg.kind == LINE:
        out.feed(seg.x1, seg.z1)
    else:
        out.arc(seg.x1, seg.z1, seg.cx, seg.cz, seg.kind, checked=True)


def rough(out: Out, profile: list[Seg], start: tuple[float, float], code: int, d: float,
          inc: float, retract: float) -> None:
    """G71 (``code`` 710, 711, 712) or G72 (720, 721, 722) on ``profile`` from ``start`` (x, z):
    D ``d``, I ``inc``, R ``retract``."""
    fr = _Frame(code >= 720)
    variant = code % 10
    sa, sb = fr.ab(*start)
    if len(profile) < 2:  # no move, or the approach alone: nothing to cut
        return
    approach, rest = profile[0], profile[1:]
    p0a = fr.ab(approach.x1, approach.z1)[0]
    ea = fr.ab(rest[-1].x1, rest[-1].z1)[0]
    if fr.swap:
        s = 1.0 if ea <= p0a else -1.0
    else:
        s = 1.0 if ea < p0a else -1.0
    eb = fr.ab(rest[-1].x1, rest[-1].z1)[1]
    fb = fr.ab(approach.x1, approach.z1)[1]
    t = 1.0 if eb > fb else -1.0  # the way the profile goes (a profile going nowhere: toward -b)
    turn = -s  # how rs274's frame has the step axis (see the levels)
    if not fr.swap:
        out.zeros = turning_zeros(s > 0, t > 0)
    else:
        out.zeros = facing_zeros(t > 0, s * t > 0)
    # A start ahead of the profile's first point along the cut starts from that point's b.
    if t * (sb - fb) > 0:
        sb = fb
        start = fr.xz(sa, sb)
    # The profile moves D to the side G70 would move it from the start.
    way = (t, 0.0) if not fr.swap else (0.0, t)
    side = pass_side(profile, start, way)
    far = max(s * fr.ab(seg.x1, seg.z1)[0] for seg in rest)
    if far <= s * sa:
        # nothing beyond the start: the profile moved D to the side G70 would take from the
        # start, fed from the start (G7x.1: each move entered by a feed to its start, pockets
        # bridged)
        out.traverse(*start)
        moved, corners = moved_with_corners(profile, side, d, way, roughing=True,
                                            work=out.m.work)
        approach_line = Seg(LINE, start[0], start[1], moved[0].x0, moved[0].z0)
        # (its arcs cut where they turn, as below)
        walk, tags = _split(moved, corners, fr, s)
        if variant == 1:
            # (bridging its pockets as below)
            _bridged(out, fr, [approach_line, *walk], [MOVE, *tags], len(walk) + 1, s, t)
            return
        for seg in [approach_line, *walk]:
            _emit(out, seg)
        return
    moved, corners = moved_with_corners(profile, side, d, way, roughing=True, work=out.m.work)
    first, last = moved[0], moved[-1]
    p0a = fr.ab(first.x0, first.z0)[0]
    la, lb = fr.ab(last.x1, last.z1)
    closing = Seg(LINE, last.x1, last.z1, *fr.xz(sa, lb))
    # a closing feed unless E lies on the start's level or beyond it
    closes = s * la > s * sa
    chain = [*moved, closing] if closes else list(moved)
    approach_line = Seg(LINE, start[0], start[1], first.x0, first.z0)

    def exit_b(level: float, from_b: float, beyond: float = EPS) -> float | None:
        """Where the level next meets the profile (or the closing line) past ``from_b``."""
        best: float | None = None
        for seg in chain:
            for hb in _level_hits(seg, fr, level):
                if t * (hb - from_b) > beyond and (best is None or t * (hb - best) < 0):
                    best = hb
        return best

    grid = [turn * sa]

    def turned(k: int) -> float:
        """Level ``k`` of the start's grid in rs274's turned frame (its zeros keep their sign
        there), reached by stepping ``I`` at a time as rs274 does (its last digits show it): the
        level itself is ``turn`` times it."""
        while len(grid) <= k:
            grid.append(grid[-1] + turn * s * inc)
        return grid[k]

    out.traverse(*start)
    k = 0
    if variant != 2:
        while True:
            out.m.work()  # (I sets how many levels there are)
            up = turned(k)
            level = turn * up
            if s * level >= s * p0a - EPS:
                break
            hits = _level_hits(approach_line, fr, level)
            entry = hits[0] if hits else sb
            # (a level meeting the profile where it enters has nothing to cut)
            end = exit_b(level, entry, -EPS)
            out.traverse(*fr.xz(level, entry))
            if end is None or abs(end - entry) <= EPS:  # nothing to cut here: on to the next
                k += 1
                continue
            out.feed(*fr.xz(level, end))
            r = min(retract, abs(end - entry) / 2.0)  # at most back to the middle of the pass
            back = turn * (up - turn * s * r)
            out.traverse(*fr.xz(back, end - t * r))
            out.traverse(*fr.xz(back, entry + t * r))
            out.traverse(*fr.xz(level, entry))
            k += 1
    walk, tags = _split(moved, corners, fr, s)
    if s * (p0a - sa) < EPS:  # (fed, below)
        # the moved profile starts at or short of the start's level: the way to it is cut too
        if variant == 1:
            walk.insert(0, approach_line)
            tags.insert(0, MOVE)
        else:
            out.feed(first.x0, first.z0)
    else:
        out.traverse(first.x0, first.z0)
    # G7x.1 cuts the profile's way down from its first point as G7x does (G7x.2 leaves it
    # uncut), up to the first piece going no deeper; only later pockets are bridged (a cut way
    # to the first point is the first piece, going no deeper)
    fed = s * (p0a - sa) < EPS
    descent = _descent(walk, fr, s) if variant == 1 or not fed else 0
    top: float | None = None  # where the pocket being walked down began
    from_top: list[float] = []  # G7x.2's levels from there, stepped I at a time as rs274 does
    uncut = False
    for i, (seg, tag) in enumerate(zip(walk, tags, strict=True)):
        if variant == 1 and i == descent:
            break
        a0 = fr.ab(seg.x0, seg.z0)[0]
        a1 = fr.ab(seg.x1, seg.z1)[0]
        down, deep = _depth(seg, fr, s)
        if variant == 2 and i < descent:
            uncut = True
        elif s * (deep - a0) <= EPS:
            uncut = False
        if s * (deep - a0) > EPS and not uncut:
            # a pocket: passes at the levels the segment goes down through (G7x.2: from the
            # pocket's top down, the others: on the start's grid)
            if top is None:
                top = a0
                from_top[:] = [top]
            k = 0
            while True:
                out.m.work()
                if variant == 2:
                    while len(from_top) <= k:
                        from_top.append(from_top[-1] + s * inc)
                    level = from_top[k]
                else:
                    level = turn * turned(k)
                if s * level < s * a0 - EPS:
                    k += 1
                    continue
                if s * level >= s * deep - EPS:
                    break
                hits = _level_hits(down, fr, level)
                if hits:
                    cb = hits[0]
                elif abs(level - a0) <= EPS:
                    # (the level through the start of an arc whose top lies a hair above it,
                    # its other crossing before the start: the start)
                    cb = fr.ab(seg.x0, seg.z0)[1]
                else:
                    # (a level just short of an arc's end moved off its circle at a corner)
                    cb = fr.ab(down.x1, down.z1)[1]
                x, z = fr.xz(level, cb)
                # down along the profile (from a pocket's top: only where a line of the
                # profile goes down from it)
                here = abs(x - out.x) <= _TOUCH and abs(z - out.z) <= _TOUCH
                if not here or (tag == MOVE and seg.kind == LINE):
                    _emit(out, seg._replace(x1=x, z1=z))
                end = exit_b(level, cb)
                if end is not None:
                    out.feed(*fr.xz(level, end))
                    r = min(retract, abs(end - cb) / 2.0)
                    back = level - s * r
                    out.traverse(*fr.xz(back, end - t * r))
                    out.traverse(*fr.xz(back, cb + t * r))
                    out.feed(x, z)
                k += 1
        if s * (a1 - deep) < -EPS:  # climbing at its end
            top = None
            uncut = False
        _emit(out, seg)
    if variant == 1:
        rest, rest_tags = walk[descent:], tags[descent:]
        ends = len(rest)
        if closes:
            rest.append(closing)
            rest_tags.append(MOVE)
        _bridged(out, fr, rest, rest_tags, ends, s, t)
        return
    if closes:
        _emit(out, closing)


def _descent(walk: list[Seg], fr: _Frame, s: float) -> int:
    """How many pieces from the walk's start go deeper (along ``s`` on ``a``): the profile's way
    down from its first point, ending at the first piece going no deeper or after one climbing
    at its end."""
    n = 0
    for seg in walk:
        a0 = fr.ab(seg.x0, seg.z0)[0]
        a1 = fr.ab(seg.x1, seg.z1)[0]
        deep = _depth(seg, fr, s)[1]
        if s * (deep - a0) <= EPS:
            break
        n += 1
        if s * (a1 - deep) < -EPS:
            break
    return n


def _touches_at_start(seg: Seg, fr: _Frame, s: float, a0: float) -> bool:
    """Whether ``seg`` is an arc whose circle's top (its extreme against ``s`` on ``a``) lies no
    more than ``_NO_CLIMB`` from ``a0``, its start's level: that level only touches it."""
    if seg.kind == LINE:
        return False
    top = fr.ab(*_extreme_point(seg, fr, -s))[0]
    return abs(top - a0) <= _NO_CLIMB


def _bridged(out: Out, fr: _Frame, chain: list[Seg], tags: list[int], pockets_end: int,
             s: float, t: float) -> None:
    """G7x.1's contour pass: each move and corner arc is entered by a feed to its start (of no
    length, as rs274 makes it), and a pocket is bridged by a feed across its top to where the
    level meets the profile again, the walk going on from there (from the next piece where that
    is a piece's end).  A pocket is entered by that feed of no length only at a corner arc or a
    programmed arc whose top is its start (not the rest of an arc cut at its top)."""
    i = 0
    while i < len(chain):
        seg = chain[i]
        a0, b0 = fr.ab(seg.x0, seg.z0)
        deep = _depth(seg, fr, s)[1]
        if i < pockets_end and s * (deep - a0) > EPS:
            exit_at = None
            touches = _touches_at_start(seg, fr, s, a0)
            for j in range(i, len(chain)):
                if j == i and touches:
                    continue  # (its other crossing, a hair past its start, is that tangent)
                # (past the tangent a level through an arc's top makes at the arc's start)
                hits = [hb for hb in _level_hits(chain[j], fr, a0) if t * (hb - b0) > _TOUCH]
                if hits:
                    exit_at = (j, min(hits, key=lambda hb: t * hb))
                    break
            if exit_at is None:
                return  # (a pocket the profile never climbs out of: the rest is left uncut)
            if tags[i] == CORNER or (touches and tags[i] == MOVE):
                out.feed(seg.x0, seg.z0)
            j, hb = exit_at
            x, z = fr.xz(a0, hb)
            out.feed(x, z)
            land = chain[j]
            if abs(x - land.x1) > EPS or abs(z - land.z1) > EPS:
                _emit(out, land._replace(x0=x, z0=z))
            i = j + 1
            continue
        if tags[i] != CONT:
            out.feed(seg.x0, seg.z0)
        _emit(out, seg)
        i += 1


__all__ = ["CW", "rough"]
