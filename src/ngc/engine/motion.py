"""Motion: clauses as displacements over the move's normalised time, summed into engine segments.

A clause gives, for any share [t0, t1] of the move's time, a cubic of displacement from the move's
start per axis (mm or degrees); the clauses of a move add.  A move has as many segments as its
most demanding clause, each an equal share of t.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from itertools import chain
from typing import NamedTuple

from . import bezier
from .bezier import Cubic
from .reading import Clauses, single
from .state import (
    AXES,
    AXIS,
    PLANES,
    POLARS,
    ROTARY,
    VECTORS,
    Engine,
    EngineError,
    EngineSegment,
    ModeChange,
    Op,
    Stop,
    direction,
    unit_vector,
)

# axis index -> cubic of displacement over [t0, t1]
Piece = dict[int, Cubic]


class Clause(NamedTuple):
    segments: int  # how many it needs
    piece: Callable[[float, float], Piece]
    # machine positions the clause ends at, where it knows them exactly: an axis only this clause
    # moves ends there, not at its start plus the displacement (which may differ in the last bit)
    ends: dict[int, float] = {}


def line_clause(disp: dict[int, float], ends: dict[int, float] | None = None) -> Clause:
    """Constant speed through the displacements ``disp`` (axis -> mm), to ``ends`` if known."""
    moving = dict(disp)

    def piece(t0: float, t1: float) -> Piece:
        return {k: bezier.line(d, t0, t1) for k, d in moving.items()}

    return Clause(1, piece, ends or {})


def to(eng: Engine, target: dict[int, float]) -> Clause:
    """Constant speed to the machine positions ``target``."""
    return line_clause({k: t - eng.pos[k] for k, t in target.items()}, target)


def axis_clause(eng: Engine, scales: dict[int, float], values: list[float],
                along: float | None) -> Clause:
    """An axis (``scales`` = {k: 1}, ``along`` None) or a vector's axes (its scales, ``along``
    its position): 1 value, constant speed; 3 values, the Bézier's inner control points and its
    end.  Values are program values, absolute or incremental."""
    cps: dict[int, Cubic] = {}
    ends: dict[int, float] = {}
    prog = eng.program()
    offsets = eng.offsets()
    for k, scale in scales.items():
        unit = eng.length_unit if along is not None else eng.unit(k)
        origin = (along if along is not None else prog[k]) if eng.absolute else 0.0
        if len(values) == 1:
            d = (values[0] * unit - origin) * scale
            cps[k] = (0.0, d / 3.0, 2.0 * d / 3.0, d)
        else:
            e1, e2, e3 = ((v * unit - origin) * scale for v in values)
            cps[k] = (0.0, e1, e2, e3)
        if along is None and eng.absolute:
            ends[k] = values[-1] * unit + offsets[k]

    def piece(t0: float, t1: float) -> Piece:
        return {k: bezier.part(c, t0, t1) for k, c in cps.items()}

    return Clause(1, piece, ends)


def polar_point(eng: Engine, name: str, values: list[float]) -> Clause:
    """A polar transform with 1 to 3 values: a linear move to the point at that angle, radius
    and normal offset from its centre."""
    p = eng.polars[name]
    if p.centre is None:
        raise EngineError(f"{name} has no centre: set one with G103 (set polar center)")
    n, z, q = eng.frame(name)
    u = direction(z, q, values[0])
    radius = values[1] * eng.length_unit if len(values) > 1 else p.radius
    offset = values[2] * eng.length_unit if len(values) > 2 else 0.0
    p.radius = radius
    target = [c + radius * ui + offset * ni for c, ui, ni in zip(p.centre, u, n, strict=True)]
    return to(eng, {k: target[k] for k in range(9) if target[k] != eng.pos[k]})


# A segment whose positions, length or duration a number cannot hold (past some 1e308; a length
# whose square passes it, past 1e154): an error, not a segment of infinities or NaNs.
TOO_LARGE = ("The move is too large to run: its positions, length or time are past what a number "
             "holds")
# the longest a segment or a dwell may last, s (some 30 billion years; a move of the setup sheet's
# widest travel at its slowest speed is shorter): a program's time, their sum,
# stays a number however many there are
MAX_SECONDS = 1e18


def check_seconds(seconds: float, what: str) -> None:
    """A segment's or a dwell's time is at most :data:`MAX_SECONDS` (and a number)."""
    if not seconds <= MAX_SECONDS:
        raise EngineError(f"{what} lasts more than {MAX_SECONDS:g} s: too long to run")


def arc_count(sweep: float, radius: float) -> int:
    """Segments for an arc of ``sweep`` degrees and ``radius`` program units: at most 90 degrees
    each; over a radius of 1 the radius times the angle decides (the seed)."""
    size = abs(sweep) * max(1.0, abs(radius))
    if not math.isfinite(size):  # (a product of two large numbers)
        raise EngineError(f"An arc of {sweep:g} degrees at radius {radius:g} needs more segments "
                          "than can be counted")
    return max(1, math.ceil(size / 90.0 - 1e-9))


def arc_clause(z: list[float], q: list[float], start: float, sweep: float, radius: float,
               count: int) -> Clause:
    """A circle of ``radius`` (mm) in the plane of directions ``z`` (0 degrees) and ``q`` (90),
    from the angle ``start`` through ``sweep`` degrees, uniformly in t, as displacements from the
    start point; each piece the cubic with tangents of 4/3 tan(angle/4) r."""
    u0 = direction(z, q, start)
    moving = [k for k in range(9) if z[k] or q[k]]

    def piece(t0: float, t1: float) -> Piece:
        b0, b1 = start + sweep * t0, start + sweep * t1
        ua, ub = direction(z, q, b0), direction(z, q, b1)
        ta, tb = direction(z, q, b0 + 90.0), direction(z, q, b1 + 90.0)
        k_ = bezier.quarter_factor(math.radians(b1 - b0)) * radius
        out: Piece = {}
        for k in moving:
            p0 = radius * (ua[k] - u0[k])
            p3 = radius * (ub[k] - u0[k])
            out[k] = (p0, p0 + k_ * ta[k], p3 - k_ * tb[k], p3)
        return out

    return Clause(count, piece)


def polar_arc(eng: Engine, name: str, values: list[float]) -> list[Clause]:
    """A polar transform with 4 values (start angle, end angle, radius, normal offset): an arc
    whose centre puts the current position at the start angle; the offset makes a helix."""
    a0, a1, radius, offset = values
    eng.polars[name].radius = radius * eng.length_unit
    n, z, q = eng.frame(name)
    sweep = a1 - a0
    out = [arc_clause(z, q, a0, sweep, radius * eng.length_unit, arc_count(sweep, radius))]
    if offset:
        out.append(line_clause({k: offset * eng.length_unit * nk for k, nk in enumerate(n) if nk}))
    return out


def polar_coordinates(eng: Engine, clauses: Clauses) -> tuple[Clauses, list[Clause]]:
    """In G16, the plane's radius and angle axes as a move to that polar point from the polar
    origin; the other clauses as they are."""
    mode = eng.polar_mode
    first, second, _ = PLANES[eng.plane]
    polar_axes = {AXES[first]: "radius", AXES[second]: "angle"}
    if mode is None or not any(ref in polar_axes for ref, _ in clauses):
        return clauses, []
    rest: Clauses = []
    for ref, values in clauses:
        if ref not in polar_axes:
            rest.append((ref, values))
            continue
        v = single(ref, values, "polar coordinates (G16)")
        if polar_axes[ref] == "radius":
            v *= eng.length_unit
            mode.radius = v if eng.absolute else mode.radius + v
        else:
            mode.angle = v if eng.absolute else mode.angle + v
    a = math.radians(mode.angle)
    target = {first: mode.origin[first] + mode.radius * math.cos(a),
              second: mode.origin[second] + mode.radius * math.sin(a)}
    return rest, [to(eng, target)]


def clauses_of(eng: Engine, line: int, clauses: Clauses, what: str
               ) -> tuple[list[Clause], dict[str, float], list[Op]]:
    """The motion clauses of a G0/G1/G31 line, the vectors' new positions and the feed's
    ModeChange (if F is given)."""
    clauses, made = polar_coordinates(eng, clauses)
    ends: dict[str, float] = {}
    ops: list[Op] = []
    for ref, values in clauses:
        if ref == "F":
            ops.append(set_feed(eng, line, single("F", values, what)))
        elif ref in AXIS or ref in VECTORS:
            if len(values) not in (1, 3):
                raise EngineError(f"{ref} takes 1 or 3 expressions, not {len(values)}")
            if ref in AXIS:
                made.append(axis_clause(eng, {AXIS[ref]: 1.0}, values, None))
            else:
                vec = eng.vectors[ref]
                scales = {k: s for k, s in enumerate(vec) if s}
                made.append(axis_clause(eng, scales, values, eng.along[ref]))
                last = values[-1] * eng.length_unit
                ends[ref] = last if eng.absolute else ends.get(ref, eng.along[ref]) + last
        elif ref in POLARS:
            if not 1 <= len(values) <= 4:
                raise EngineError(f"{ref} takes 1 to 4 expressions, not {len(values)}")
            if len(values) == 4:
                made += polar_arc(eng, ref, values)
            else:
                made.append(polar_point(eng, ref, values))
        else:
            raise EngineError(f"{ref} is not a reference of {what}")
    return made, ends, ops


def set_feed(eng: Engine, line: int, value: float) -> ModeChange:
    """F: mm/s in G21, inches per minute in G20 (the seed)."""
    if value < 0.0:
        raise EngineError(f"Negative feed rate F {value:g}")
    eng.feed = value if eng.metric else value * eng.length_unit / 60.0
    eng.feed_rotary = value if eng.metric else value / 60.0
    return ModeChange(line, "FEED_RATE", value)


def need_feed(eng: Engine, what: str) -> None:
    """A move at the feed rate (G1, G2, G3, G31, a drilling cycle) needs one."""
    if not eng.feed:
        raise EngineError(f"{what} with no feed rate: set one with F")


def segments(eng: Engine, line: int, made: list[Clause], motion: str, pin_all: bool = False
             ) -> Iterator[Op]:
    """The engine segments of a move made of ``made`` clauses; the position follows.  Axes
    running at constant speed (G100) that the move does not name run on through it; those it
    names stop running.  With ``pin_all`` the last clause's ends hold for every axis."""
    if not made:
        return
    count = max(c.segments for c in made)
    eng.work(count)  # (all of them or none: the line fails before its first segment)
    start = list(eng.pos)
    pins = _pins(made, pin_all)
    # the segments are made one at a time as they are taken: a move of millions of them holds
    # one at a time
    for j in range(count):
        total = _summed(made, j / count, (j + 1) / count)
        if j == count - 1:
            for k, e in pins.items():
                if k in total:
                    total[k][3] = e - start[k]
        if j == 0:
            stopped = set(total) & set(eng.running)
            if stopped:
                for k in stopped:
                    del eng.running[k]
                yield run_change(eng, line)
        mm = {k: (start[k] + c[0], start[k] + c[1], start[k] + c[2], start[k] + c[3])
              for k, c in sorted(total.items())}
        yield from timed(eng, line, mm, duration(eng, motion, mm), motion)
    for k, acc in total.items():
        eng.pos[k] = start[k] + acc[3]
    if eng.exact:
        yield Stop(line)


def _summed(made: list[Clause], t0: float, t1: float) -> dict[int, list[float]]:
    """The clauses' pieces over [t0, t1], added per axis."""
    total: dict[int, list[float]] = {}
    for c in made:
        for k, cub in c.piece(t0, t1).items():
            acc = total.setdefault(k, [0.0, 0.0, 0.0, 0.0])
            for i in range(4):
                acc[i] += cub[i]
    return total


def _pins(made: list[Clause], pin_all: bool) -> dict[int, float]:
    """Where the last segment ends exactly (machine positions), per axis: an axis that one
    clause alone moves ends where that clause says it ends; with ``pin_all``, every axis the
    last clause knows the end of."""
    if pin_all:
        return dict(made[-1].ends)
    movers: dict[int, list[Clause]] = {}
    for c in made:
        for k in c.piece(1.0, 1.0):
            movers.setdefault(k, []).append(c)
    return {k: cs[0].ends[k] for k, cs in movers.items() if len(cs) == 1 and k in cs[0].ends}


def timed(eng: Engine, line: int, mm: dict[int, Cubic], seconds: float, motion: str
          ) -> Iterator[Op]:
    """One segment of the axes ``mm`` (machine, mm) lasting ``seconds``, the running axes
    moving on through it; the running axes' positions follow."""
    for k, speed in eng.running.items():
        if k not in mm:
            p, d = eng.pos[k], speed * seconds
            mm[k] = (p, p + d / 3.0, p + 2.0 * d / 3.0, p + d)
            eng.pos[k] = p + d
    if not (math.isfinite(seconds) and all(map(math.isfinite, chain.from_iterable(mm.values())))):
        raise EngineError(TOO_LARGE)
    check_seconds(seconds, "The move")
    axes = {AXES[k]: (eng.shown(k, c[0]), eng.shown(k, c[1]), eng.shown(k, c[2]),
                      eng.shown(k, c[3])) for k, c in sorted(mm.items())}
    yield EngineSegment(line, seconds, axes, motion)


def run_change(eng: Engine, line: int) -> ModeChange:
    """RUN: the axes running at constant speed, each as a percentage of its maximum speed."""
    return ModeChange(line, "RUN", {AXES[k]: 100.0 * s / eng.setup.max_speed[k]
                                    for k, s in sorted(eng.running.items())})


def duration(eng: Engine, motion: str, mm: dict[int, Cubic]) -> float:
    """G1, G2, G3, G31: the length on X Y Z (else U V W, else A B C) over the feed rate; G0:
    each axis at its maximum speed, the slowest deciding."""
    if motion != "rapid":
        for group in ((0, 1, 2), (6, 7, 8), (3, 4, 5)):  # the first group that moves
            dist = bezier.length([mm[k] for k in group if k in mm])
            if dist:
                rate = eng.feed_rotary if group[0] in ROTARY else eng.feed
                assert rate
                return dist / rate
        return 0.0
    return max((bezier.length([c]) / eng.setup.max_speed[k] for k, c in mm.items()), default=0.0)


def straight(eng: Engine, line: int, target: list[float], motion: str) -> Iterator[Op]:
    """A straight move to the machine position ``target`` (no stop in G61: a part of a
    command), if it goes anywhere."""
    moved = {k: t for k, (t, p) in enumerate(zip(target, eng.pos, strict=True)) if t != p}
    if moved:
        exact, eng.exact = eng.exact, False
        try:
            yield from segments(eng, line, [to(eng, moved)], motion)
        finally:
            eng.exact = exact


def circle(eng: Engine, line: int, code: int, clauses: Clauses) -> Iterator[Op]:
    """G2/G3: the end point in the contour plane with I J K (the centre, from the start) or R;
    other axes named move along (a helix); segments as for polar arcs."""
    what = "G2 (circle cw)" if code == 2 else "G3 (circle ccw)"
    first, second, _ = PLANES[eng.plane]
    prog = eng.program()
    end = list(prog)
    centre = [0.0, 0.0]
    given: set[str] = set()
    radius_word: float | None = None
    ops: list[Op] = []
    ijk = {"I": 0, "J": 1, "K": 2}
    polar: Clauses = []
    for ref, values in clauses:
        if ref == "F":
            ops.append(set_feed(eng, line, single("F", values, what)))
        elif ref in AXIS:
            v = single(ref, values, what)
            k = AXIS[ref]
            if eng.polar_mode is not None and k in (first, second):
                polar.append((ref, values))
                continue
            end[k] = v * eng.unit(k) + (0.0 if eng.absolute else prog[k])
        elif ref in ijk:
            k = ijk[ref]
            if k not in (first, second):
                raise EngineError(f"{ref} is not a centre offset in the {eng.plane} plane "
                                  f"({'IJK'[first]} {'IJK'[second]})")
            centre[0 if k == first else 1] = single(ref, values, what) * eng.length_unit
            given.add(ref)
        elif ref == "R":
            radius_word = single(ref, values, what) * eng.length_unit
        else:
            raise EngineError(f"{ref} is not a word of {what}")
    if polar:
        _, made = polar_coordinates(eng, polar)
        offs = eng.offsets()
        for k, t in made[0].ends.items():
            end[k] = t - offs[k]
    yield from ops
    need_feed(eng, what)
    if radius_word is not None and given:
        raise EngineError(f"{what} takes I J K or R, not both")
    s = (prog[first], prog[second])
    e = (end[first], end[second])
    if radius_word is not None:
        c = _centre_of_radius(s, e, radius_word, code, what)
    elif given:
        c = (s[0] + centre[0], s[1] + centre[1])
    else:
        raise EngineError(f"{what} needs the centre (I J K) or the radius (R)")
    r0 = math.hypot(s[0] - c[0], s[1] - c[1])
    r1 = math.hypot(e[0] - c[0], e[1] - c[1])
    if r0 == 0.0:
        raise EngineError("Zero-radius arc")
    if abs(r0 - r1) > 0.002:
        raise EngineError("Radius to end of arc differs from radius to start")
    a0 = math.degrees(math.atan2(s[1] - c[1], s[0] - c[0]))
    a1 = math.degrees(math.atan2(e[1] - c[1], e[0] - c[0]))
    sweep = (a1 - a0) % 360.0 if code == 3 else -((a0 - a1) % 360.0)
    if math.hypot(e[0] - s[0], e[1] - s[1]) < 1e-9:
        sweep = 360.0 if code == 3 else -360.0  # the same point: a full circle
    made = [arc_clause(unit_vector(first), unit_vector(second), a0, sweep, r0,
                       arc_count(sweep, r0 / eng.length_unit))]
    # the rest of the way: the other axes (a helix), and what the end's radius differs by
    reached = _turned(s, c, math.radians(sweep))
    rest = {k: end[k] - prog[k] for k in range(9) if k not in (first, second)}
    rest[first] = e[0] - reached[0]
    rest[second] = e[1] - reached[1]
    offsets = eng.offsets()
    made.append(line_clause({k: d for k, d in rest.items() if d},
                            {k: end[k] + offsets[k] for k in range(9)}))
    yield from segments(eng, line, made, "arc", pin_all=True)


def _turned(s: tuple[float, float], c: tuple[float, float], angle: float) -> tuple[float, float]:
    dx, dy = s[0] - c[0], s[1] - c[1]
    ca, sa = math.cos(angle), math.sin(angle)
    return (c[0] + dx * ca - dy * sa, c[1] + dx * sa + dy * ca)


def _centre_of_radius(s: tuple[float, float], e: tuple[float, float], r: float, code: int,
                      what: str) -> tuple[float, float]:
    """The centre of the arc of radius |r| from s to e: the shorter arc for r > 0, the longer
    for r < 0."""
    dx, dy = e[0] - s[0], e[1] - s[1]
    chord = math.hypot(dx, dy)
    if chord < 1e-9:
        raise EngineError(f"{what} with R: the start and end points are the same")
    half = chord / 2.0
    if abs(r) < half - 1e-9:
        raise EngineError("Arc radius too small to reach end point")
    h = math.sqrt(max(0.0, r * r - half * half))
    # left of the chord for a short counter-clockwise arc
    side = 1.0 if code == 3 else -1.0
    if r < 0:
        side = -side
    mx, my = (s[0] + e[0]) / 2.0, (s[1] + e[1]) / 2.0
    return (mx - side * h * dy / chord, my + side * h * dx / chord)
