"""``ngc time``'s planner under ``G64 P``: the sampled trajectory never leaves the programmed path
by more than P.

The programmed path is the interpreter's canon (straight feeds and traverses, arcs and helices in
the XY plane), read with a :class:`~ngc.canon.jsonl.ListSink`; the programs are in G21 G17 with no
offsets, so canon coordinates are machine coordinates.  The trajectory is what ``ngc time
--trajectory`` writes: the timer's segments and standstills through a
:class:`~ngc.planner.trajectory.TrajectoryWriter`, as CSV.  Each sample's distance to the path is
exact (a line segment, or an arc or a helix with Z linear in the angle), taken to the moves of the
lines around the sample's line, and at least the next two moves: a G64 P merges short lines into
one move timed under the last one's line, and a blend runs under the line of the move it leaves,
into the next one.  The bar is P + 1e-6, which covers the six decimals of the CSV file.
"""

from __future__ import annotations

import bisect
import csv
import io
import math
import random
from collections.abc import Callable
from dataclasses import dataclass

import pytest

from ngc import interpret
from ngc.canon import ops
from ngc.canon.jsonl import ListSink
from ngc.planner.machine import DEFAULT_MACHINE
from ngc.planner.timing import time_lines
from ngc.planner.trajectory import TrajectoryWriter

Point = tuple[float, float, float]

TAU = 2.0 * math.pi
TOLERANCES = (0.01, 0.05, 0.1, 0.5, 1.0)
SLACK = 1e-6  # the CSV's six decimals
FLOAT_SLACK = 1e-9
EVERY = DEFAULT_MACHINE.servo_period  # the trajectory's default spacing
NEAR_LINES = 12  # a sample is measured against the moves of the lines this close to its line
AHEAD_MOVES = 2  # and at least the next moves after its line


# -- the programmed path --------------------------------------------------------------------------
@dataclass(frozen=True)
class Straight:
    """A straight move (feed or traverse) from ``start`` to ``end``."""

    line: int
    start: Point
    end: Point

    def distance(self, p: Point) -> float:
        s, e = self.start, self.end
        d = (e[0] - s[0], e[1] - s[1], e[2] - s[2])
        w = (p[0] - s[0], p[1] - s[1], p[2] - s[2])
        dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2]
        f = 0.0 if dd == 0.0 else min(max((w[0] * d[0] + w[1] * d[1] + w[2] * d[2]) / dd, 0.0), 1.0)
        return math.dist(p, (s[0] + f * d[0], s[1] + f * d[1], s[2] + f * d[2]))

    def bound(self, p: Point) -> float:
        """At most the distance from ``p``: here, the distance."""
        return self.distance(p)


@dataclass(frozen=True)
class Helix:
    """An arc in the XY plane about (``cx``, ``cy``), from the angle ``angle0`` turning by
    ``sweep`` radians (> 0) counterclockwise (``turn`` 1) or clockwise (``turn`` -1), its Z going
    linearly from ``z0`` by ``rise``."""

    line: int
    cx: float
    cy: float
    radius: float
    angle0: float
    turn: int
    sweep: float
    z0: float
    rise: float

    def point(self, phi: float) -> Point:
        a = self.angle0 + self.turn * phi
        return (self.cx + self.radius * math.cos(a), self.cy + self.radius * math.sin(a),
                self.z0 + self.rise * phi / self.sweep)

    def bound(self, p: Point) -> float:
        """At most the distance from ``p``: to the cylinder of the helix, cut to its Z."""
        low, high = sorted((self.z0, self.z0 + self.rise))
        radial = abs(math.hypot(p[0] - self.cx, p[1] - self.cy) - self.radius)
        return math.hypot(radial, max(low - p[2], p[2] - high, 0.0))

    def distance(self, p: Point, beyond: float = math.inf) -> float:
        """The distance from ``p``; if it is at least ``beyond``, any number at least
        ``beyond`` (a bound that saves a search)."""
        dx, dy = p[0] - self.cx, p[1] - self.cy
        rho = math.hypot(dx, dy)
        r = self.radius
        # the point's angle from the start, the way the arc turns
        alpha = (self.turn * (math.atan2(dy, dx) - self.angle0)) % TAU
        ends = min(math.dist(p, self.point(0.0)), math.dist(p, self.point(self.sweep)))
        if self.rise == 0.0:
            if alpha <= self.sweep:
                return math.hypot(rho - r, p[2] - self.z0)
            return ends  # off the arc's angles: an end is the nearest point
        # The square of the distance at the angle phi is
        #   g(phi) = r² + rho² - 2 r rho cos(phi - alpha) + (z0 + k phi - z)²,
        # strictly convex within a quarter turn of alpha (+ whole turns), and at least r² + rho²
        # everywhere else.
        k = self.rise / self.sweep
        b = 2.0 * r * rho
        base = r * r + rho * rho
        radial = (rho - r) ** 2

        def g(phi: float) -> float:
            return (radial + 2.0 * b * math.sin(0.5 * (phi - alpha)) ** 2
                    + (self.z0 + k * phi - p[2]) ** 2)

        def slope(phi: float) -> float:
            return b * math.sin(phi - alpha) + 2.0 * k * (self.z0 + k * phi - p[2])

        best = ends * ends
        for m in range(-1, int(self.sweep / TAU) + 2):
            centre = alpha + TAU * m
            lo, hi = max(0.0, centre - 0.5 * math.pi), min(self.sweep, centre + 0.5 * math.pi)
            if lo <= hi:
                best = min(best, g(_convex_minimum(slope, lambda phi: b * math.cos(phi - alpha)
                                                   + 2.0 * k * k, lo, hi)))
        if best >= base and base >= beyond * beyond:
            return math.sqrt(base)
        if best >= base:  # farther than the radius: search the whole helix
            steps = max(int(self.sweep / 1e-3), 1)
            grid = min(range(steps + 1), key=lambda i: g(self.sweep * i / steps))
            lo = self.sweep * max(grid - 1, 0) / steps
            hi = self.sweep * min(grid + 1, steps) / steps
            for _ in range(100):
                m1, m2 = lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0
                lo, hi = (lo, m2) if g(m1) < g(m2) else (m1, hi)
            best = min(best, g(0.5 * (lo + hi)))
        return math.sqrt(max(best, 0.0))


def _convex_minimum(slope: Callable[[float], float], curvature: Callable[[float], float],
                    lo: float, hi: float) -> float:
    """Where a strictly convex function with derivative ``slope`` is least on [lo, hi]:
    Newton's method kept within a shrinking bracket."""
    if slope(lo) >= 0.0:
        return lo
    if slope(hi) <= 0.0:
        return hi
    phi = 0.5 * (lo + hi)
    for _ in range(200):
        value = slope(phi)
        if value == 0.0:
            return phi
        if value > 0.0:
            hi = phi
        else:
            lo = phi
        step = phi - value / curvature(phi)
        nxt = step if lo < step < hi else 0.5 * (lo + hi)
        if abs(nxt - phi) <= 1e-13 or hi - lo <= 1e-13:
            return nxt
        phi = nxt
    return phi


Move = Straight | Helix


def programmed_path(text: str) -> list[Move]:
    """The moves of the program ``text`` as the interpreter gives them to a sink."""
    sink = ListSink()
    interpret(text, sink)
    pos: Point = (0.0, 0.0, 0.0)
    moves: list[Move] = []
    for op, _, line in sink.ops:
        if isinstance(op, ops.StraightFeed | ops.StraightTraverse):
            assert (op.a, op.b, op.c) == (0.0, 0.0, 0.0)
            end = (op.x, op.y, op.z)
            moves.append(Straight(line, pos, end))
            pos = end
        elif isinstance(op, ops.ArcFeed):
            cx, cy = op.first_axis, op.second_axis
            end = (op.first_end, op.second_end, op.axis_end_point)
            radius = math.hypot(pos[0] - cx, pos[1] - cy)
            assert math.hypot(end[0] - cx, end[1] - cy) == pytest.approx(radius, abs=1e-9)
            angle0 = math.atan2(pos[1] - cy, pos[0] - cx)
            turn = 1 if op.rotation > 0 else -1
            sweep = (turn * (math.atan2(end[1] - cy, end[0] - cx) - angle0)) % TAU
            if sweep <= 1e-12:
                sweep += TAU
            sweep += TAU * (abs(op.rotation) - 1)
            moves.append(Helix(line, cx, cy, radius, angle0, turn, sweep, pos[2], end[2] - pos[2]))
            pos = end
        elif isinstance(op, ops.SelectPlane):
            assert op.plane == "CANON_PLANE_XY"
        elif isinstance(op, ops.UseLengthUnits):
            assert op.units == "CANON_UNITS_MM"
        elif isinstance(op, ops.SetG5xOffset | ops.SetG92Offset | ops.UseToolLengthOffset):
            assert all(v == 0.0 for v in op if isinstance(v, float))
        elif isinstance(op, ops.SetXYRotation):
            assert op.degrees == 0.0
    return moves


# -- the sampled trajectory -----------------------------------------------------------------------
@dataclass(frozen=True)
class Sample:
    t: float
    point: Point
    line: int


def trajectory(text: str, every: float = EVERY) -> list[Sample]:
    """The trajectory ``ngc time --trajectory --every EVERY`` writes for the program ``text``."""
    out = io.StringIO()
    writer = TrajectoryWriter(out, DEFAULT_MACHINE, every)
    result = time_lines(text.splitlines(keepends=True), DEFAULT_MACHINE,
                        on_segment=writer.segment, on_wait=writer.wait)
    writer.finish(result.total_s)
    out.seek(0)
    return [Sample(float(row["t"]), (float(row["x"]), float(row["y"]), float(row["z"])),
                   int(row["line"]))
            for row in csv.DictReader(out)]


@dataclass(frozen=True)
class Deviation:
    distance: float
    sample: Sample
    nearest: Move


def deviation(text: str, every: float = EVERY) -> Deviation:
    """The sample of ``text``'s trajectory farthest from the programmed path near its line."""
    moves = programmed_path(text)
    lines = [m.line for m in moves]
    worst: Deviation | None = None
    for sample in trajectory(text, every):
        first = bisect.bisect_left(lines, sample.line - NEAR_LINES)
        last = min(max(bisect.bisect_right(lines, sample.line + NEAR_LINES),
                       bisect.bisect_right(lines, sample.line) + AHEAD_MOVES), len(moves))
        near = moves[max(min(first, last - 1), 0):last]
        d, move = math.inf, near[0]
        for bound, m in sorted(((m.bound(sample.point), m) for m in near), key=lambda bm: bm[0]):
            if bound >= d:
                break
            dm = bound if isinstance(m, Straight) else m.distance(sample.point, d)
            if dm < d:
                d, move = dm, m
        if worst is None or d > worst.distance:
            worst = Deviation(d, sample, move)
    assert worst is not None
    return worst


def describe(text: str, found: Deviation) -> str:
    source = text.splitlines()
    line = found.sample.line
    around = "\n".join(f"    {n}: {source[n - 1]}" for n in range(max(line - 1, 1),
                                                                 min(line + 2, len(source)) + 1))
    return (f"{found.distance:.7f} mm off the path at t={found.sample.t:.4f} s, "
            f"{found.sample.point}, line {line}, nearest: line {found.nearest.line} "
            f"({type(found.nearest).__name__})\n{around}")


# -- the programs ---------------------------------------------------------------------------------
class Pen:
    """Writes a program in the XY plane move by move, following the position and the heading, so
    that each join is tangent or turns by a given angle."""

    def __init__(self, header: str) -> None:
        self.x = self.y = self.z = 0.0
        self.heading = 0.0
        self.lines = [header]

    def text(self) -> str:
        return "\n".join([*self.lines, "M2", ""])

    def _xyz(self) -> str:
        return f"X{self.x:.10f} Y{self.y:.10f} Z{self.z:.10f}"

    def line(self, length: float, turn: float = 0.0, dz: float = 0.0, feed: float | None = None,
             rapid: bool = False) -> None:
        """A straight move of ``length`` in XY after turning by ``turn`` degrees (+: left)."""
        self.heading += math.radians(turn)
        self.x += length * math.cos(self.heading)
        self.y += length * math.sin(self.heading)
        self.z += dz
        word = "G0" if rapid else "G1"
        f = "" if feed is None else f" F{feed:g}"
        self.lines.append(f"{word} {self._xyz()}{f}")

    def goto(self, x: float, y: float, z: float, rapid: bool = False,
             feed: float | None = None) -> None:
        if (x, y) != (self.x, self.y):
            self.heading = math.atan2(y - self.y, x - self.x)
        self.x, self.y, self.z = x, y, z
        f = "" if feed is None else f" F{feed:g}"
        self.lines.append(f"{'G0' if rapid else 'G1'} {self._xyz()}{f}")

    def arc(self, radius: float, sweep: float, ccw: bool, turn: float = 0.0, dz: float = 0.0,
            feed: float | None = None) -> None:
        """An arc (G3 if ``ccw``, else G2) of ``sweep`` degrees and ``radius``, leaving along
        the heading turned by ``turn`` degrees; a helix if ``dz``; more than a turn with a P
        word."""
        self.heading += math.radians(turn)
        side = 1.0 if ccw else -1.0
        normal = self.heading + side * 0.5 * math.pi
        cx, cy = self.x + radius * math.cos(normal), self.y + radius * math.sin(normal)
        i, j = cx - self.x, cy - self.y
        end = math.atan2(self.y - cy, self.x - cx) + side * math.radians(sweep)
        self.x, self.y = cx + radius * math.cos(end), cy + radius * math.sin(end)
        self.z += dz
        self.heading += side * math.radians(sweep)
        turns = f" P{math.ceil(sweep / 360.0 - 1e-9)}" if sweep > 360.0 else ""
        f = "" if feed is None else f" F{feed:g}"
        self.lines.append(f"{'G3' if ccw else 'G2'} {self._xyz()} I{i:.10f} J{j:.10f}{turns}{f}")


def header(p: float, q: float | None = None) -> str:
    return f"G21 G17 G90 G64 P{p:g}" + ("" if q is None else f" Q{q:g}")


def squares(p: float) -> str:
    pen = Pen(header(p))
    for size, feed in ((20.0, 6000), (5.0, 1800), (1.0, 300)):
        pen.line(size, feed=feed)
        for _ in range(3):
            pen.line(size, turn=90.0)
        pen.line(size, turn=90.0)  # round the first corner again: a closed loop
        pen.heading += math.pi / 2.0
    return pen.text()


TURNS = (5.0, 10.0, 20.0, 30.0, 45.0, 60.0, 75.0, 90.0, 105.0, 120.0, 135.0, 150.0, 160.0, 170.0,
         175.0)


def zigzags(p: float) -> str:
    pen = Pen(header(p))
    for length, feed in ((10.0, 6000), (4.0, 3000), (2.0, 900)):
        pen.line(length, feed=feed)
        for n, turn in enumerate(TURNS):
            pen.line(length, turn=turn if n % 2 else -turn)
    return pen.text()


def short_lines(p: float) -> str:
    rng = random.Random(1964)
    pen = Pen(header(p))
    for feed in (600, 3000, 6000):
        pen.line(rng.uniform(0.2, 2.0), turn=90.0, feed=feed)
        for _ in range(40):
            pen.line(rng.uniform(0.2, 2.0), turn=rng.choice((-1, 1)) * rng.uniform(5.0, 170.0))
    return pen.text()


def arcs(p: float) -> str:
    pen = Pen(header(p))
    for feed in (1200, 3000, 6000):
        pen.line(8.0, turn=90.0, feed=feed)
        pen.arc(2.0, 90.0, ccw=True)  # line -> arc, tangent
        pen.line(5.0)  # arc -> line, tangent
        pen.arc(3.0, 120.0, ccw=False, turn=40.0)  # line -> arc, 40 degrees
        pen.line(5.0, turn=-60.0)  # arc -> line, 60 degrees
        pen.arc(1.0, 150.0, ccw=True, turn=90.0)  # line -> arc, square, r 1
        pen.arc(5.0, 90.0, ccw=False)  # arc -> arc, tangent, G3 -> G2
        pen.arc(2.0, 60.0, ccw=False, turn=30.0)  # arc -> arc, G2 -> G2, 30 degrees
        pen.arc(4.0, 100.0, ccw=True, turn=-45.0)  # arc -> arc, G2 -> G3, 45 degrees
        pen.arc(1.5, 200.0, ccw=True)  # arc -> arc, tangent, G3 -> G3, smaller
        pen.arc(1.0, 120.0, ccw=True, turn=120.0)  # arc -> arc, 120 degrees, r 1
        pen.line(4.0, turn=150.0)  # arc -> line, 150 degrees
        pen.arc(2.5, 80.0, ccw=False, turn=-10.0)  # line -> arc, 10 degrees
        pen.line(3.0, turn=5.0)  # arc -> line, 5 degrees
    return pen.text()


def helices(p: float) -> str:
    pen = Pen(header(p))
    for feed in (900, 3000, 6000):
        pen.line(6.0, turn=90.0, feed=feed)
        pen.arc(3.0, 180.0, ccw=True, dz=-1.0)  # line -> helix, tangent in XY
        pen.line(4.0, dz=-0.5)  # helix -> line going down
        pen.arc(2.0, 270.0, ccw=False, turn=30.0, dz=1.0)  # line -> helix, 30 degrees
        pen.arc(4.0, 90.0, ccw=True, dz=-2.0)  # helix -> helix, S, Z turning back
        pen.arc(1.0, 120.0, ccw=True, turn=60.0, dz=0.5)  # helix -> helix, 60 degrees, r 1
        pen.arc(2.5, 500.0, ccw=False, turn=-20.0, dz=-1.5)  # a helix of more than a turn (P2)
        pen.line(5.0, turn=90.0, dz=2.0)  # helix -> line, square
        pen.arc(5.0, 60.0, ccw=True, dz=0.0)  # line -> arc, tangent
        pen.arc(1.5, 90.0, ccw=True, turn=45.0, dz=-1.0)  # arc -> helix, 45 degrees
    return pen.text()


CORNERS_3D = ((10.0, 0.0, -2.0), (10.0, 10.0, 0.0), (0.0, 10.0, -3.0), (5.0, 5.0, 2.0),
              (15.0, 8.0, -1.0), (12.0, -4.0, 1.0), (12.5, -4.0, -2.0), (20.0, 3.0, -2.5),
              (20.0, 3.2, 3.0), (8.0, 3.0, 3.5), (0.0, 0.0, 0.0))


def corners_3d(p: float) -> str:
    pen = Pen(header(p))
    for scale, feed in ((1.0, 6000), (0.3, 3000), (0.1, 600)):
        for n, (x, y, z) in enumerate(CORNERS_3D):
            pen.goto(x * scale, y * scale, z * scale, feed=feed if n == 0 else None)
    return pen.text()


def rapids(p: float) -> str:
    pen = Pen(header(p))
    pen.goto(10.0, 0.0, 5.0, rapid=True)
    pen.goto(10.0, 10.0, 5.0, rapid=True)  # a corner between rapids
    pen.goto(20.0, 15.0, 2.0, rapid=True)
    pen.goto(20.0, 15.0, -1.0, feed=600)  # rapid -> feed
    pen.goto(30.0, 15.0, -1.0, feed=3000)
    pen.goto(30.0, 25.0, -1.0)
    pen.goto(30.0, 25.0, 5.0, rapid=True)  # feed -> rapid
    pen.goto(0.0, 25.0, 5.0, rapid=True)
    pen.goto(0.0, 0.0, 1.0, rapid=True)
    pen.goto(0.0, 0.0, 0.0, feed=300)
    pen.goto(5.0, 0.0, 0.0, feed=6000)
    pen.goto(5.0, 5.0, 0.0)
    pen.goto(40.0, 5.0, 3.0, rapid=True)
    pen.goto(40.0, 40.0, 10.0, rapid=True)
    pen.goto(38.0, 2.0, 0.0, rapid=True)
    pen.goto(38.0, 0.0, 0.0, feed=6000)
    pen.goto(30.0, 0.0, 0.0, rapid=True)
    pen.goto(0.0, 0.0, 0.0, rapid=True)
    return pen.text()


def sampled_circle(p: float, q: float, points: int = 200, radius: float = 10.0) -> str:
    """A circle as a naive CAM writes it: ``points`` short lines."""
    pen = Pen(header(p, q))
    for feed in (1200, 6000):
        pen.goto(radius, 0.0, 0.0, feed=feed)
        for i in range(1, points + 1):
            a = TAU * i / points
            pen.goto(radius * math.cos(a), radius * math.sin(a), 0.0)
    return pen.text()


PROGRAMS: dict[str, Callable[[float], str]] = {
    "squares": squares,
    "zigzags": zigzags,
    "short_lines": short_lines,
    "arcs": arcs,
    "helices": helices,
    "corners_3d": corners_3d,
    "rapids": rapids,
}


def check(text: str, p: float) -> None:
    found = deviation(text)
    assert found.distance <= p + SLACK + FLOAT_SLACK, f"G64 P{p:g}: {describe(text, found)}"


# -- the requirement ------------------------------------------------------------------------------
@pytest.mark.parametrize("p", TOLERANCES)
@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_the_path_stays_within_p(name: str, p: float) -> None:
    """With Q0 (no naive-CAM merging) and with Q as G64 P leaves it (Q = P): within P.  The one
    exception is below."""
    text = PROGRAMS[name](p)
    assert header(p) in text
    check(text.replace(header(p), header(p, 0.0), 1), p)
    if name != "arcs":
        check(text, p)


@pytest.mark.parametrize("p", TOLERANCES)
def test_arcs_split_by_naive_cam_stay_within_p_plus_q(p: float) -> None:
    """An XY arc that leaves its chord by less than Q is run as two straight lines (as LinuxCNC
    does, docs/planner.md), so the blend between them is within P of the lines, not of the arc:
    the path stays within P + Q."""
    text = arcs(p)
    assert header(p) in text
    check(text, p + p)


@pytest.mark.parametrize(("p", "q"), [(0.05, 0.02)])
def test_naive_cam_circle_stays_within_p(p: float, q: float) -> None:
    check(sampled_circle(p, q), p)


# -- the measure ----------------------------------------------------------------------------------
def test_distance_to_a_line() -> None:
    line = Straight(1, (0.0, 0.0, 0.0), (10.0, 0.0, 0.0))
    assert line.distance((5.0, 3.0, 4.0)) == pytest.approx(5.0)
    assert line.distance((-3.0, 4.0, 0.0)) == pytest.approx(5.0)
    assert line.distance((13.0, 0.0, 4.0)) == pytest.approx(5.0)


def test_distance_to_an_arc() -> None:
    # a quarter circle of radius 2 about the origin from (2, 0) counterclockwise to (0, 2)
    arc = Helix(1, 0.0, 0.0, 2.0, 0.0, 1, 0.5 * math.pi, 0.0, 0.0)
    assert arc.distance((3.0 / math.sqrt(2.0), 3.0 / math.sqrt(2.0), 0.0)) == pytest.approx(1.0)
    assert arc.distance((0.5, 0.5, 0.0)) == pytest.approx(2.0 - math.sqrt(0.5))
    assert arc.distance((2.0, -1.0, 0.0)) == pytest.approx(1.0)  # beyond the start: the start
    assert arc.distance((-2.0, 0.0, 0.0)) == pytest.approx(math.sqrt(8.0))  # nearer the end
    clockwise = Helix(1, 0.0, 0.0, 2.0, 0.0, -1, 0.5 * math.pi, 0.0, 0.0)  # to (0, -2)
    assert clockwise.distance((0.0, 2.5, 0.0)) == pytest.approx(math.hypot(2.0, 2.5))
    assert clockwise.distance((0.0, -2.5, 1.0)) == pytest.approx(math.hypot(0.5, 1.0))


def test_distance_to_a_helix() -> None:
    helix = Helix(1, 1.0, 2.0, 3.0, 0.3, -1, 3.0 * math.pi, -1.0, 4.0)  # a turn and a half
    rng = random.Random(3)
    for _ in range(100):
        assert helix.distance(helix.point(rng.uniform(0.0, helix.sweep))) == pytest.approx(
            0.0, abs=1e-9)
    steps = 100000
    polyline = [helix.point(helix.sweep * i / steps) for i in range(steps + 1)]
    for _ in range(3):
        phi = rng.uniform(0.0, helix.sweep)
        a = helix.angle0 + helix.turn * phi
        off = helix.point(phi)
        off = (off[0] + rng.uniform(-0.3, 0.3) * math.cos(a),
               off[1] + rng.uniform(-0.3, 0.3) * math.sin(a), off[2] + rng.uniform(-0.3, 0.3))
        nearest = min(math.dist(off, q) for q in polyline)  # the vertices: a little farther
        assert nearest - 1e-6 <= helix.distance(off) <= nearest


CORNERS = "G21 G17 G90 {}\nG1 X20 F6000\nG1 Y20\nG1 X0\nM2\n"


def test_the_measure_sees_a_rounded_corner() -> None:
    assert deviation(CORNERS.format("G61.1")).distance < 1e-6  # exact stop: on the path
    assert deviation(CORNERS.format("G64")).distance > 0.001  # no tolerance: cut at speed
    assert deviation(CORNERS.format("G64 P1")).distance > 0.001


def test_the_check_fails_beyond_p() -> None:
    with pytest.raises(AssertionError, match="off the path"):
        check(CORNERS.format("G64"), 0.01)  # held to a P the program does not ask for
