"""Plane geometry for compensated contours: closed shapes and open paths of lines and arcs.

Everything is in the coordinates of the active plane, ``(u, v)``: (X, Y) in G17, (Z, X) in G18.
A contour is a start point and a list of segments; a segment is a line to an end point or an arc
to an end point around a center, counterclockwise in (u, v) or not (G3 or G2 then, in both
planes).  ``feature`` is the smallest length that matters for a tool following the contour (the
shortest edge, the smallest arc radius): a tool radius well below it gives no gouging corner.

Standard library only; the callers pass their own ``random.Random`` so programs stay
deterministic per seed.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass

Point = tuple[float, float]


@dataclass(frozen=True)
class Seg:
    end: Point
    center: Point | None = None  # None: a line
    ccw: bool = False

    @property
    def is_arc(self) -> bool:
        return self.center is not None


@dataclass(frozen=True)
class Contour:
    start: Point
    segs: tuple[Seg, ...]
    closed: bool
    feature: float

    def scaled(self, k: float, about: Point = (0.0, 0.0)) -> Contour:
        def sp(p: Point) -> Point:
            return (about[0] + (p[0] - about[0]) * k, about[1] + (p[1] - about[1]) * k)

        segs = tuple(Seg(sp(s.end), sp(s.center) if s.center else None, s.ccw) for s in self.segs)
        return Contour(sp(self.start), segs, self.closed, self.feature * k)

    def moved(self, du: float, dv: float) -> Contour:
        def mp(p: Point) -> Point:
            return (p[0] + du, p[1] + dv)

        segs = tuple(Seg(mp(s.end), mp(s.center) if s.center else None, s.ccw) for s in self.segs)
        return Contour(mp(self.start), segs, self.closed, self.feature)

    def rounded(self, places: int) -> Contour:
        """Points rounded as the program will print them; arc centers then keep both radii within
        rounding of each other."""
        def rp(p: Point) -> Point:
            return (round(p[0], places), round(p[1], places))

        segs = tuple(Seg(rp(s.end), rp(s.center) if s.center else None, s.ccw) for s in self.segs)
        return Contour(rp(self.start), segs, self.closed, self.feature)


def _dist(a: Point, b: Point) -> float:
    return math.hypot(b[0] - a[0], b[1] - a[1])


def start_direction(start: Point, seg: Seg) -> Point:
    """Unit direction of travel at the start of ``seg`` (which starts at ``start``)."""
    if seg.center is None:
        d = _dist(start, seg.end) or 1.0
        return ((seg.end[0] - start[0]) / d, (seg.end[1] - start[1]) / d)
    ru, rv = start[0] - seg.center[0], start[1] - seg.center[1]
    r = math.hypot(ru, rv) or 1.0
    return (-rv / r, ru / r) if seg.ccw else (rv / r, -ru / r)


def end_direction(start: Point, seg: Seg) -> Point:
    if seg.center is None:
        return start_direction(start, seg)
    ru, rv = seg.end[0] - seg.center[0], seg.end[1] - seg.center[1]
    r = math.hypot(ru, rv) or 1.0
    return (-rv / r, ru / r) if seg.ccw else (rv / r, -ru / r)


def side_normal(direction: Point, left: bool) -> Point:
    du, dv = direction
    return (-dv, du) if left else (dv, -du)


def _arc_between(p: Point, q: Point, radius: float, bulge_left: bool) -> Seg:
    """The minor arc from p to q of the given radius, bulging to the left of p->q or right."""
    chord = _dist(p, q)
    radius = max(radius, chord / 2 * 1.0001)
    mu, mv = (p[0] + q[0]) / 2, (p[1] + q[1]) / 2
    h = math.sqrt(max(radius * radius - chord * chord / 4, 0.0))
    du, dv = (q[0] - p[0]) / chord, (q[1] - p[1]) / chord
    # the center lies on the side opposite the bulge
    nu, nv = side_normal((du, dv), not bulge_left)
    center = (mu + nu * h, mv + nv * h)
    # bulging left of p->q: the arc turns clockwise
    return Seg(q, center, ccw=not bulge_left)


def polygon(rng: random.Random, n: int, size: float, ccw: bool, bulges: float = 0.0) -> Contour:
    """A closed polygon around the origin (vertices at radius 0.75-1 x size, corners neither
    sharp nor flat); with ``bulges`` > 0 some edges are arcs bulging out or in."""
    base = rng.uniform(0, 2 * math.pi)
    angles = sorted(base + (k + rng.uniform(-0.25, 0.25)) * 2 * math.pi / n for k in range(n))
    if not ccw:
        angles.reverse()
    pts = [(size * rng.uniform(0.75, 1.0) * math.cos(a), size * rng.uniform(0.75, 1.0) * math.sin(a))
           for a in angles]
    segs: list[Seg] = []
    feature = math.inf
    for k in range(n):
        p, q = pts[k], pts[(k + 1) % n]
        chord = _dist(p, q)
        feature = min(feature, chord)
        if rng.random() < bulges:
            radius = chord * rng.uniform(0.8, 3.0)
            outward_left = not ccw  # travelling ccw the outside is on the right
            out = rng.random() < 0.7
            seg = _arc_between(p, q, radius, bulge_left=outward_left if out else not outward_left)
            feature = min(feature, radius)
            segs.append(seg)
        else:
            segs.append(Seg(q))
    return Contour(pts[0], tuple(segs), True, feature)


def rounded_rect(rng: random.Random, w: float, h: float, corner: float, ccw: bool) -> Contour:
    """A rectangle centred on the origin with quarter-circle corners, starting mid-edge."""
    hw, hh, c = w / 2, h / 2, min(corner, w / 3, h / 3)
    # counterclockwise: bottom edge left to right, then up the right side ...
    pts_ccw: list[Seg] = [
        Seg((hw - c, -hh)), Seg((hw, -hh + c), (hw - c, -hh + c), True),
        Seg((hw, hh - c)), Seg((hw - c, hh), (hw - c, hh - c), True),
        Seg((-hw + c, hh)), Seg((-hw, hh - c), (-hw + c, hh - c), True),
        Seg((-hw, -hh + c)), Seg((-hw + c, -hh), (-hw + c, -hh + c), True),
        Seg((0.0, -hh)),
    ]
    start = (0.0, -hh)
    segs = pts_ccw
    if not ccw:  # the same path backwards
        points = [start] + [s.end for s in pts_ccw]
        rev: list[Seg] = []
        for k in range(len(pts_ccw) - 1, -1, -1):
            s = pts_ccw[k]
            rev.append(Seg(points[k], s.center, False) if s.is_arc else Seg(points[k]))
        segs = rev
    feature = min(c, w - 2 * c, h - 2 * c) if c > 0 else min(w, h)
    return Contour(start, tuple(segs), True, max(feature, 1e-6))


def circle(rng: random.Random, radius: float, ccw: bool) -> Contour:
    a = rng.uniform(0, 2 * math.pi)
    start = (radius * math.cos(a), radius * math.sin(a))
    return Contour(start, (Seg(start, (0.0, 0.0), ccw),), True, radius)


def open_path(rng: random.Random, n: int, size: float) -> Contour:
    """An open path of lines and arcs turning at most ~100 degrees at each joint."""
    p: Point = (0.0, 0.0)
    heading = rng.uniform(0, 2 * math.pi)
    segs: list[Seg] = []
    feature = math.inf
    for _ in range(n):
        length = size * rng.uniform(0.4, 1.0)
        heading += rng.uniform(-1.75, 1.75)
        q = (p[0] + length * math.cos(heading), p[1] + length * math.sin(heading))
        feature = min(feature, length)
        if rng.random() < 0.35:
            radius = length * rng.uniform(0.8, 3.0)
            seg = _arc_between(p, q, radius, bulge_left=rng.random() < 0.5)
            feature = min(feature, radius)
            segs.append(seg)
        else:
            segs.append(Seg(q))
        p = q
    return Contour((0.0, 0.0), tuple(segs), False, feature)


def shape(rng: random.Random, size: float, ccw: bool) -> Contour:
    """One contour of a random sort: polygon, polygon with arcs, rounded rectangle, circle or an
    open path."""
    r = rng.random()
    if r < 0.3:
        return polygon(rng, rng.randint(3, 8), size, ccw)
    if r < 0.55:
        return polygon(rng, rng.randint(3, 7), size, ccw, bulges=0.5)
    if r < 0.75:
        w = size * rng.uniform(1.0, 2.0)
        h = size * rng.uniform(0.8, 1.6)
        return rounded_rect(rng, w, h, size * rng.uniform(0.1, 0.35), ccw)
    if r < 0.85:
        return circle(rng, size * rng.uniform(0.5, 1.0), ccw)
    return open_path(rng, rng.randint(2, 6), size)
