"""Seeded generator of realistic 3-axis mill programs for judging the cycle-time planner.

The programs are of the kinds of ``../shared/timing`` (pockets, contours, 3D surfaces, exact path
and exact stop, drilling cycles, helices and side-plane arcs, inch trochoids, O-word programs,
engraving) plus mixed programs with feed changes, spindle stops and a tool change, each with its
own geometry and parameters.  Each program starts with ``G17 G21 G90 G94 G40 G49 G80`` (G20 for
inch), ``S10000 M3``, starts at machine 0,0,0, stays within ±400 mm and ends with ``M5 M2``.

``python tests/timing/generate.py`` (re)writes ``tests/timing/cases/NN_kind.ngc``;
``--check`` only compares the files with what the generator makes.  The random numbers come from
``random.Random(seed).random()`` alone, so the output is the same on every Python version.
"""

from __future__ import annotations

import argparse
import itertools
import math
import random
import sys
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path

CASES_DIR = Path(__file__).resolve().parent / "cases"

Point = tuple[float, float]


class Rng:
    """The few random helpers the programs need, all built on ``random.random()``."""

    def __init__(self, seed: int) -> None:
        self.r = random.Random(seed)

    def uniform(self, a: float, b: float) -> float:
        return a + (b - a) * self.r.random()

    def step(self, a: float, b: float, q: float) -> float:
        """A value in [a, b] on a grid of q (for round shop numbers)."""
        n = round((b - a) / q)
        return round(a + q * min(n, int(self.r.random() * (n + 1))), 6)

    def integer(self, a: int, b: int) -> int:
        return a + min(b - a, int(self.r.random() * (b - a + 1)))

    def choice(self, seq: Sequence[object]) -> object:
        return seq[min(len(seq) - 1, int(self.r.random() * len(seq)))]

    def chance(self, p: float) -> bool:
        return self.r.random() < p


def num(v: float, nd: int) -> str:
    s = f"{v:.{nd}f}"
    if "." in s:
        s = s.rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


class Emitter:
    """Writes G-code the way a CAM post does: modal motion words and feeds only when they change,
    and only the axes that move.  Positions are kept as the rounded values that were written."""

    def __init__(self, inch: bool = False) -> None:
        self.nd = 4 if inch else 3
        self.lines: list[str] = []
        self.pos = {"X": 0.0, "Y": 0.0, "Z": 0.0}
        self.motion = ""
        self.feed: float | None = None
        self.plane = "G17"

    def r(self, v: float) -> float:
        return float(num(v, self.nd))

    def raw(self, *lines: str) -> None:
        self.lines.extend(lines)

    def comment(self, text: str) -> None:
        self.lines.append(f"({text.upper()})")

    def _words(self, axes: dict[str, float | None], force: Iterable[str] = ()) -> list[str]:
        words = []
        for a in "XYZ":
            v = axes.get(a)
            if v is None:
                continue
            v = self.r(v)
            if a in force or v != self.pos[a]:
                words.append(f"{a}{num(v, self.nd)}")
                self.pos[a] = v
        return words

    def _feed(self, f: float | None) -> list[str]:
        if f is None or f == self.feed:
            return []
        self.feed = f
        return [f"F{num(f, 1)}"]

    def _emit(self, motion: str, words: list[str], feed: list[str], extra: Sequence[str] = ()) -> None:
        if not words:
            return
        head = [motion] if motion != self.motion else []
        self.motion = motion
        self.lines.append(" ".join([*head, *words, *extra, *feed]))

    def g0(self, x: float | None = None, y: float | None = None, z: float | None = None) -> None:
        self._emit("G0", self._words({"X": x, "Y": y, "Z": z}), [])

    def g1(self, x: float | None = None, y: float | None = None, z: float | None = None,
           f: float | None = None) -> None:
        words = self._words({"X": x, "Y": y, "Z": z})
        if words:
            self._emit("G1", words, self._feed(f))

    def set_plane(self, plane: str) -> None:
        if plane != self.plane:
            self.plane = plane
            self.lines.append(plane)

    def arc(self, cw: bool, end: dict[str, float], centre: dict[str, float], f: float | None = None,
            plane: str = "G17") -> None:
        """An arc (or helix) in ``plane`` from the current position to ``end`` about ``centre``
        (both by axis letter, in the plane's two axes; ``end`` may add the third axis)."""
        self.set_plane(plane)
        a1, a2 = {"G17": ("X", "Y"), "G18": ("Z", "X"), "G19": ("Y", "Z")}[plane]
        offs = {"X": "I", "Y": "J", "Z": "K"}
        start = dict(self.pos)
        words = self._words(dict(end), force=(a1, a2))
        extra = []
        for a in sorted((a1, a2)):
            extra.append(f"{offs[a]}{num(self.r(centre[a]) - start[a], self.nd)}")
        self._emit("G2" if cw else "G3", words, self._feed(f), extra)


def header(e: Emitter, title: str, notes: Sequence[str], inch: bool = False) -> None:
    e.comment(title)
    for n in notes:
        e.comment(n)
    e.raw(f"G17 {'G20' if inch else 'G21'} G90 G94 G40 G49 G80", "S10000 M3")


def footer(e: Emitter) -> None:
    e.raw("M5 M2")


def unit(dx: float, dy: float) -> Point:
    n = math.hypot(dx, dy)
    return dx / n, dy / n


# ---------------------------------------------------------------------------------------------
# Rounded polygons (profiles with a fillet at every vertex) and their offsets.


@dataclass
class Elem:
    """A line to ``end``, or an arc to ``end`` about ``centre`` (``cw`` gives the direction)."""

    end: Point
    centre: Point | None = None
    cw: bool = False


def rounded_polygon(verts: Sequence[tuple[float, float, float]], d: float) -> tuple[Point, list[Elem]]:
    """The closed path of a polygon (clockwise or not) with a fillet of radius r at each vertex
    ``(x, y, r)``, offset by ``d`` to the left of the direction of travel.  Returns the start (the
    middle of the first edge) and the elements back to it."""
    n = len(verts)
    pts = []  # per vertex: tangent point on the incoming edge, on the outgoing edge, centre, cw
    for i in range(n):
        px, py, _ = verts[i - 1]
        x, y, r = verts[i]
        nx, ny, _ = verts[(i + 1) % n]
        u1 = unit(x - px, y - py)
        u2 = unit(nx - x, ny - y)
        turn = u1[0] * u2[1] - u1[1] * u2[0]  # > 0: left turn
        theta = math.acos(max(-1.0, min(1.0, u1[0] * u2[0] + u1[1] * u2[1])))
        t = r * math.tan(theta / 2)
        n1 = (-u1[1], u1[0])  # left normal of the incoming edge
        n2 = (-u2[1], u2[0])
        s = 1.0 if turn > 0 else -1.0  # the centre is on the left for a left turn
        t1 = (x - u1[0] * t, y - u1[1] * t)
        c = (t1[0] + s * r * n1[0], t1[1] + s * r * n1[1])
        t1o = (t1[0] + d * n1[0], t1[1] + d * n1[1])
        t2 = (x + u2[0] * t, y + u2[1] * t)
        t2o = (t2[0] + d * n2[0], t2[1] + d * n2[1])
        pts.append((t1o, t2o, c, turn < 0))
    # start in the middle of the edge from vertex 0 to vertex 1
    a = pts[0][1]
    b = pts[1][0]
    start = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
    elems = []
    for k in range(1, n + 1):
        t1o, t2o, c, cw = pts[k % n]
        elems.append(Elem(t1o))
        if math.dist(t1o, t2o) > 1e-6:
            elems.append(Elem(t2o, c, cw))
    elems.append(Elem(start))
    return start, elems


def run_elems(e: Emitter, elems: Sequence[Elem], f: float | None = None, z: float | None = None) -> None:
    for el in elems:
        if el.centre is None:
            if math.dist((e.pos["X"], e.pos["Y"]), el.end) > 5e-4:
                e.g1(el.end[0], el.end[1], z, f=f)
        else:
            e.arc(el.cw, {"X": el.end[0], "Y": el.end[1]}, {"X": el.centre[0], "Y": el.centre[1]}, f)
        f = None


# ---------------------------------------------------------------------------------------------
# The kinds of program.


def rect_ring(e: Emitter, cx: float, cy: float, a: float, b: float, r: float) -> None:
    """A counter-clockwise ring of half sizes a, b about (cx, cy) with corner arcs of radius r,
    from and back to the middle of its bottom side."""
    e.g1(cx, cy - b)
    corners = [(cx + a - r, cy - b + r, (0.0, -1.0), (1.0, 0.0)),
               (cx + a - r, cy + b - r, (1.0, 0.0), (0.0, 1.0)),
               (cx - a + r, cy + b - r, (0.0, 1.0), (-1.0, 0.0)),
               (cx - a + r, cy - b + r, (-1.0, 0.0), (0.0, -1.0))]
    for ccx, ccy, (sx, sy), (ex, ey) in corners:
        e.g1(ccx + r * sx, ccy + r * sy)
        if r > 0:
            e.arc(False, {"X": ccx + r * ex, "Y": ccy + r * ey}, {"X": ccx, "Y": ccy})
    e.g1(cx, cy - b)


def pocket_rect(rng: Rng, inch: bool = False) -> list[str]:
    """Rectangular pocket: rings from the centre out, a ramp entry, arc corners on the outer ring
    and a finish pass; G64 P."""
    k = 1 / 25.4 if inch else 1.0

    def size(a: float, b: float, q: float) -> float:
        """A size between a and b mm, on a grid of q mm (0.05 in for inch programs)."""
        return rng.step(a * k, b * k, 0.05) if inch else rng.step(a, b, q)

    e = Emitter(inch)
    tool = rng.choice([6.0, 8.0, 10.0]) if not inch else rng.choice([0.25, 0.375])
    assert isinstance(tool, float)
    rt = tool / 2
    w = size(32, 50, 1)
    h = size(20, 32, 1)
    cr = max(size(4, 8, 0.5), rt * 1.3)
    cx = size(35, 80, 1)
    cy = size(25, 50, 1)
    depth = rng.step(0.12, 0.24, 0.02) if inch else rng.step(3, 6, 0.5)
    steps = 2
    p = rng.choice([0.01, 0.02, 0.03, 0.05]) if not inch else rng.choice([0.0005, 0.001])
    assert isinstance(p, float)
    fc, fr, ff = (round(rng.step(a, b, 100) * k) if inch else rng.step(a, b, 100)
                  for a, b in ((2000, 3200), (600, 1000), (1200, 2000)))
    stepover = tool * rng.uniform(0.4, 0.6)
    leave = rng.step(0.008, 0.016, 0.002) if inch else rng.step(0.2, 0.4, 0.05)
    header(e, f"POCKET_RECT - RECTANGULAR POCKET, OFFSET RINGS, RAMP ENTRY, G64 P{num(p, 4)}",
           [f"T1 D={num(tool, 4)} FLAT ENDMILL - POCKET {num(w, 3)} X {num(h, 3)} CORNER R{num(cr, 3)}"
            f" - DEPTH {num(depth, 3)} IN {steps} STEPS",
            "CONTOUR-PARALLEL FROM THE CENTRE OUT, RAMP ENTRY, FINISH PASS"], inch)
    e.raw(f"G64 P{num(p, 4)}")
    zs = 15 * k
    e.g0(z=zs)
    # ring half sizes, from the outer one (the wall less what the finish leaves) inwards
    rings = []
    a, b = w / 2 - rt - leave, h / 2 - rt - leave
    while b > stepover * 0.6:
        rings.append((a, b))
        a -= stepover
        b -= stepover
    rings.reverse()
    ramp = max(min(rings[0][0] * 0.9, 8 * k), 3 * k)
    dz = rng.step(0.6, 1.0, 0.05) * k
    ztop = 0.0
    for s in range(steps):
        zb = -depth * (s + 1) / steps
        e.g0(cx - ramp, cy)
        e.g0(z=ztop + 1 * k)
        e.g1(z=ztop + 0.3 * k, f=fr)
        zz = ztop + 0.3 * k
        x_at = cx - ramp
        while zz - dz > zb:
            zz -= dz
            x_at = cx + ramp if x_at < cx else cx - ramp
            e.g1(x_at, z=zz)
        x_at = cx + ramp if x_at < cx else cx - ramp
        e.g1(x_at, z=zb)
        e.g1(cx, f=fc)
        for i, (a, b) in enumerate(rings):
            r = max(cr - rt - leave, 0.5 * k) if i == len(rings) - 1 else 0.0
            rect_ring(e, cx, cy, a, b, r)
        e.g1(y=cy - b + stepover * 0.3)
        e.g0(z=zb + 1 * k)
        ztop = zb
    e.comment("finish wall")
    af, bf = w / 2 - rt, h / 2 - rt
    e.g0(cx, cy - bf + 2 * k)
    e.g0(z=-depth)
    e.g1(y=cy - bf + 1 * k, f=ff)
    rect_ring(e, cx, cy, af, bf, max(cr - rt, 0.5 * k))
    e.g1(y=cy - bf + 1 * k)
    e.g0(z=zs)
    footer(e)
    return e.lines


def pocket_circ(rng: Rng) -> list[str]:
    """Circular pocket: a helical entry, then full-circle rings (or a half-circle spiral) outward,
    a finish pass; G64 P."""
    e = Emitter()
    tool = rng.choice([6.0, 8.0, 10.0])
    assert isinstance(tool, float)
    rt = tool / 2
    rp = rng.step(14, 22, 0.5)
    cx, cy = rng.step(40, 90, 1), rng.step(40, 80, 1)
    depth = rng.step(3, 5, 0.5)
    steps = 2
    p = rng.choice([0.01, 0.02, 0.03])
    assert isinstance(p, float)
    fc = rng.step(2000, 3200, 100)
    fh = rng.step(800, 1400, 100)
    ff = rng.step(1400, 2200, 100)
    spiral = rng.chance(0.5)
    stepover = tool * rng.uniform(0.45, 0.6)
    header(e, f"POCKET_CIRC - CIRCULAR POCKET D{num(2 * rp, 3)}, HELICAL ENTRY, G64 P{num(p, 3)}",
           [f"T2 D={num(tool, 3)} FLAT ENDMILL - DEPTH {num(depth, 3)} IN {steps} STEPS",
            "HALF-CIRCLE SPIRAL OUT" if spiral else "FULL-CIRCLE RINGS WITH RADIAL STEPS"])
    e.raw(f"G64 P{num(p, 3)}")
    e.g0(z=10)
    rh = rt * 0.8
    e.g0(cx + rh, cy)
    e.g0(z=1)
    e.g1(z=0.3, f=400)
    pitch = rng.step(1.0, 2.0, 0.1)
    z = 0.3
    rmax = rp - rt - 0.2
    for s in range(steps):
        zb = -depth * (s + 1) / steps
        if s > 0:
            e.g0(z=z + 0.5)
            e.g0(cx + rh, cy)
            e.g1(z=z + 0.3, f=400)
            z += 0.3
        while z - pitch > zb:
            z -= pitch
            e.arc(False, {"X": cx + rh, "Y": cy, "Z": z}, {"X": cx, "Y": cy}, fh)
        z = zb
        e.arc(False, {"X": cx + rh, "Y": cy, "Z": z}, {"X": cx, "Y": cy}, fh)
        e.arc(False, {"X": cx + rh, "Y": cy}, {"X": cx, "Y": cy})
        r = rh
        if spiral:
            # half circles about centres shifted by half a stepover: a smooth spiral
            side = 1
            while r < rmax:
                r2 = min(r + stepover / 2, rmax)
                ex = cx - side * r2
                mid = ((cx + side * r) + ex) / 2
                e.arc(False, {"X": ex, "Y": cy}, {"X": mid, "Y": cy}, fc)
                r = r2
                side = -side
            if side == -1:
                e.arc(False, {"X": cx + r, "Y": cy}, {"X": cx, "Y": cy})
            e.arc(False, {"X": cx + r, "Y": cy}, {"X": cx, "Y": cy})
        else:
            while r < rmax:
                r = min(r + stepover, rmax)
                e.g1(cx + r, f=fc)
                e.arc(False, {"X": cx + r, "Y": cy}, {"X": cx, "Y": cy})
        e.g1(cx + r - 0.5)
    e.comment("finish wall, arc in and out")
    rf = rp - rt
    e.g1(cx, cy, f=fc)
    rl = min(rf / 2, rng.step(2, 4, 0.5))
    e.g1(cx + rf - 2 * rl, cy)
    e.arc(False, {"X": cx + rf - rl, "Y": cy - rl}, {"X": cx + rf - rl, "Y": cy}, ff)
    e.arc(False, {"X": cx + rf, "Y": cy}, {"X": cx + rf - rl, "Y": cy})
    e.arc(False, {"X": cx + rf, "Y": cy}, {"X": cx, "Y": cy})
    e.arc(False, {"X": cx + rf - rl, "Y": cy + rl}, {"X": cx + rf - rl, "Y": cy})
    e.g1(cx, cy)
    e.g0(z=10)
    e.g0(0, 0)
    footer(e)
    return e.lines


def contour(rng: Rng, inch: bool = False) -> list[str]:
    """Outside profile of lines and arcs (a plate with corner radii, a chamfer and a notch), tangent
    arc lead-in and lead-out, several rough depths and finish passes; G64 without P."""
    k = 1 / 25.4 if inch else 1.0
    e = Emitter(inch)
    tool = (rng.choice([6.0, 8.0, 10.0]) if not inch else rng.choice([0.25, 0.375]))
    assert isinstance(tool, float)
    rt = tool / 2
    w = rng.step(40, 65, 1) * k
    h = rng.step(25, 40, 1) * k
    x0, y0 = rng.step(0, 30, 1) * k, rng.step(0, 25, 1) * k
    verts: list[tuple[float, float, float]] = []
    # clockwise from the bottom-right corner: bottom edge goes -X
    rc = [rng.step(3, 10, 0.5) * k for _ in range(4)]
    verts.append((x0, y0, rc[0]))  # bottom left
    verts.append((x0, y0 + h, rc[1]))  # top left
    if rng.chance(0.8):  # U notch in the top edge
        nw = rng.step(8, 14, 1) * k
        lip = rng.step(1.5, 3, 0.5) * k
        rn = nw / 2
        nd = rn + lip + rng.step(2, 6, 1) * k
        nx = x0 + round(rng.uniform(0.25, 0.4) * w / k) * k
        verts += [(nx, y0 + h, lip), (nx, y0 + h - nd, rn), (nx + nw, y0 + h - nd, rn),
                  (nx + nw, y0 + h, lip)]
    if rng.chance(0.7):  # chamfer on the top right corner
        c = rng.step(0.15, 0.25, 0.01) * w
        rch = rng.step(2, 4, 0.5) * k
        verts += [(x0 + w - c, y0 + h, rch), (x0 + w, y0 + h - c, rch)]
    else:
        verts.append((x0 + w, y0 + h, rc[2]))
    verts.append((x0 + w, y0, rc[3]))  # bottom right
    # start in the middle of the bottom edge: rotate so the bottom edge (right -> left) is first
    verts = [verts[-1], *verts[:-1]]
    stock = rng.step(0.2, 0.4, 0.05) * k
    depth = rng.step(6, 14, 1) * k
    nrough = rng.integer(1, 2)
    fr = rng.step(2000, 3200, 100) / (25 if inch else 1)
    ff = rng.step(1600, 2400, 100) / (25 if inch else 1)
    fp = rng.step(300, 600, 100) / (25 if inch else 1)
    fr, ff, fp = (round(v, 1) for v in (fr, ff, fp))
    rl = rng.step(4, 7, 0.5) * k
    header(e, "CONTOUR - OUTSIDE PROFILE, LINES AND ARCS, G64 [NO P]",
           [f"T3 D={num(tool, 4)} FLAT ENDMILL - PLATE {num(w, 3)} X {num(h, 3)} WITH CORNER RADII",
            f"{nrough} ROUGH DEPTHS LEAVING {num(stock, 3)}, THEN FINISH PASSES",
            "CLIMB [CW], TANGENT ARC LEAD-IN AND LEAD-OUT"], inch)
    e.raw("G64")
    zs = 15 * k
    e.g0(z=zs)

    def one_pass(d: float, z: float, feed: float, first: bool) -> None:
        start, elems = rounded_polygon(verts, d)
        # travel on the bottom edge is -X; the outside is -Y (left of travel for a CW path)
        sx, sy = start
        e.g0(sx + rl, sy - rl)
        e.g0(z=(2 * k if first else z + 1 * k))
        e.g1(z=z, f=fp)
        e.arc(False, {"X": sx, "Y": sy}, {"X": sx, "Y": sy - rl}, feed)
        run_elems(e, elems)
        e.arc(False, {"X": sx - rl, "Y": sy - rl}, {"X": sx, "Y": sy - rl})
        e.g0(z=5 * k)

    for i in range(nrough):
        one_pass(rt + stock, -depth * (i + 1) / nrough, fr, i == 0)
    e.comment("finish, contour-parallel")
    if nrough == 1:
        one_pass(rt + stock / 2, -depth, ff, False)
    one_pass(rt, -depth, ff, False)
    e.g0(z=zs)
    footer(e)
    return e.lines


def surface(rng: Rng) -> list[str]:
    """3D raster finish of a bumpy floor with short segments under G64 P0.01 (merged by the
    naive-CAM detector)."""
    e = Emitter()
    along_y = rng.chance(0.5)
    seg = rng.choice([0.4, 0.5, 0.6])
    assert isinstance(seg, float)
    lx = rng.step(30, 45, 5)
    ly = rng.step(20, 30, 5)
    so = rng.choice([1.0, 1.25, 1.5])
    assert isinstance(so, float)
    f = rng.step(2400, 3600, 200)
    p = rng.choice([0.01, 0.01, 0.02])
    assert isinstance(p, float)
    bumps = []
    for _ in range(rng.integer(1, 3)):
        bumps.append((rng.uniform(0.2, 0.8) * lx, rng.uniform(0.2, 0.8) * ly, rng.uniform(-2, 3),
                      rng.uniform(4, 10)))
    ripple = (rng.uniform(0.1, 0.5), rng.uniform(0.15, 0.4), rng.uniform(0.15, 0.4))
    base = -rng.step(3, 6, 0.5)

    def zf(x: float, y: float) -> float:
        z = base + ripple[0] * math.sin(ripple[1] * x) * math.cos(ripple[2] * y)
        for bx, by, a, s in bumps:
            z += a * math.exp(-((x - bx) ** 2 + (y - by) ** 2) / (s * s))
        return z

    header(e, f"SURFACE - 3D RASTER FINISH, {num(seg, 2)} MM SEGMENTS, G64 P{num(p, 3)}",
           [f"T5 D=6 BALL ENDMILL - BUMPS ON A RIPPLED FLOOR, {num(lx, 1)} X {num(ly, 1)}",
            f"ZIGZAG ALONG {'Y' if along_y else 'X'}, STEPOVER {num(so, 2)}, TOOL TIP POSITIONS"])
    e.raw(f"G64 P{num(p, 3)}")
    ox, oy = rng.step(0, 20, 5), rng.step(0, 20, 5)
    e.g0(z=10)
    (la, lb) = (ly, lx) if along_y else (lx, ly)
    n_along = round(la / seg)
    n_rows = round(lb / so)

    def xy(a: float, b: float) -> Point:
        return (b, a) if along_y else (a, b)

    x, y = xy(0, 0)
    e.g0(ox + x, oy + y)
    e.g0(z=zf(x, y) + 2)
    e.g1(z=zf(x, y), f=800)
    for row in range(n_rows + 1):
        b = row * so
        if row > 0:
            a = 0.0 if row % 2 == 0 else la
            x, y = xy(a, b)
            e.g1(ox + x, oy + y, zf(x, y))
        rng_a = range(1, n_along + 1) if row % 2 == 0 else range(n_along - 1, -1, -1)
        first = True
        for i in rng_a:
            x, y = xy(i * seg, b)
            e.g1(ox + x, oy + y, zf(x, y), f=f if first else None)
            first = False
    e.g0(z=10)
    footer(e)
    return e.lines


def rings_g61(rng: Rng) -> list[str]:
    """3D contour-parallel finish rings, short segments; G61 (exact path)."""
    e = Emitter()
    ellipse = rng.chance(0.5)
    chord = rng.choice([0.6, 0.7, 0.8, 1.0])
    assert isinstance(chord, float)
    a0 = rng.step(12, 18, 1)
    b0 = rng.step(8, 12, 1)
    so = rng.step(1.4, 2.2, 0.2)
    f = rng.step(1600, 2600, 200)
    cz = rng.uniform(2, 4)
    r0 = rng.step(3, 6, 0.5)
    header(e, "FINISH_RINGS_G61 - 3D CONTOUR-PARALLEL FINISH, G61 EXACT PATH",
           [f"T7 D=6 BALL ENDMILL - RINGS OFFSET FROM A {num(2 * a0, 1)} X {num(2 * b0, 1)} "
            f"{'ELLIPSE' if ellipse else 'ROUNDED RECTANGLE'}, STEPOVER {num(so, 2)}",
            f"Z FOLLOWS A DOME, CHORD ABOUT {num(chord, 2)} MM"])
    e.raw("G61")
    ox, oy = rng.step(30, 60, 1), rng.step(25, 45, 1)

    def zf(x: float, y: float) -> float:
        return -cz * (x * x / (a0 * a0 * 2.2) + y * y / (b0 * b0 * 2.2)) - 2.0

    def ring(a: float, b: float) -> list[Point]:
        pts: list[Point] = []
        if ellipse:
            # arc-length parametrisation by dense sampling
            dense = [(a * math.cos(-math.pi / 2 + 2 * math.pi * i / 2000),
                      b * math.sin(-math.pi / 2 + 2 * math.pi * i / 2000)) for i in range(2001)]
        else:
            r = max(0.8, r0 - (a0 - a))
            dense = []
            corners = [(a - r, -b + r, -math.pi / 2), (a - r, b - r, 0.0), (-a + r, b - r, math.pi / 2),
                       (-a + r, -b + r, math.pi)]
            dense.append((0.0, -b))
            for cxx, cyy, ang0 in corners:
                for i in range(0, 41):
                    t = ang0 + (math.pi / 2) * i / 40
                    dense.append((cxx + r * math.cos(t), cyy + r * math.sin(t)))
            dense.append((0.0, -b))
            # fill the straight parts densely
            filled: list[Point] = []
            for p0, p1 in itertools.pairwise(dense):
                n = max(1, int(math.dist(p0, p1) / 0.05))
                filled += [(p0[0] + (p1[0] - p0[0]) * j / n, p0[1] + (p1[1] - p0[1]) * j / n)
                           for j in range(n)]
            filled.append(dense[-1])
            dense = filled
        total = sum(math.dist(p, q) for p, q in itertools.pairwise(dense))
        n = max(8, round(total / chord))
        step = total / n
        acc = 0.0
        target = 0.0
        pts.append(dense[0])
        for p, q in itertools.pairwise(dense):
            d = math.dist(p, q)
            while acc + d >= target + step - 1e-9 and len(pts) < n:
                target += step
                t = (target - acc) / d if d else 0.0
                pts.append((p[0] + (q[0] - p[0]) * t, p[1] + (q[1] - p[1]) * t))
            acc += d
        pts.append(dense[-1])
        return pts

    e.g0(z=10)
    a, b = a0, b0
    first = True
    while b > so * 0.8:
        pts = ring(a, b)
        x, y = pts[0]
        if first:
            e.g0(ox + x, oy + y)
            e.g0(z=zf(x, y) + 2)
            e.g1(z=zf(x, y), f=600)
            first = False
        else:
            e.g1(ox + x, oy + y, zf(x, y))
        fset: float | None = f
        for x, y in pts[1:]:
            e.g1(ox + x, oy + y, zf(x, y), f=fset)
            fset = None
        a -= so
        b -= so
    e.g0(z=10)
    footer(e)
    return e.lines


def exactstop_mix(rng: Rng) -> list[str]:
    """G61.1: G0 and G1 moves from a few microns to hundreds of mm."""
    e = Emitter()
    wx = rng.step(200, 300, 10) / 2
    wy = rng.step(100, 160, 10) / 2
    header(e, "EXACTSTOP_MIX - G61.1 EXACT STOP, VERY LONG AND VERY SHORT G0/G1 MOVES",
           [f"T9 D=12 FLAT ENDMILL - SKIM A {num(2 * wx, 1)} X {num(2 * wy, 1)} PLATE, "
            "TOUCH OFF POINTS ALONG ITS EDGES"])
    e.raw("G61.1")
    e.g0(z=30)
    e.g0(-wx, -wy)
    e.g0(z=1)
    e.g1(z=-0.2, f=400)
    e.g1(z=-0.2 - rng.step(0.01, 0.05, 0.01), f=100)
    fl = rng.step(3000, 6000, 500)
    nskim = rng.integer(2, 3)
    for i in range(nskim):
        xe = wx if i % 2 == 0 else -wx
        e.g1(xe, f=fl)
        e.g1(xe + (0.01 if i % 2 == 0 else -0.01))
        e.g1(y=-wy + (i + 1) * rng.step(8, 12, 1))
    e.g0(z=30)
    pts = [(-wx, wy), (wx, wy), (wx, -wy), (0.0, 0.0), (-wx / 2, wy / 2), (wx / 2, -wy / 2)]
    for px, py in pts:
        e.g0(px, py)
        e.g0(z=0.5)
        e.g1(z=-0.5, f=300)
        d = rng.choice([0.005, 0.01, 0.02, 0.05])
        assert isinstance(d, float)
        fs = rng.choice([100, 200, 300])
        assert isinstance(fs, int)
        e.g1(px + d, f=fs)
        e.g1(y=py + d)
        e.g1(px)
        e.g1(y=py)
        e.g0(z=0.5)
        e.g0(z=0.5 + rng.choice([0.005, 0.01]))  # type: ignore[operator]
        if rng.chance(0.5):
            e.g0(z=30)
    e.g0(z=2)
    e.g1(z=-1, f=300)
    e.g1(rng.step(40, 80, 5), f=rng.step(3000, 5000, 500))
    e.g1(e.pos["X"] + 0.03)
    e.g1(y=e.pos["Y"] + 0.03)
    e.g1(0)
    e.g0(z=30)
    e.g0(0, 0)
    footer(e)
    return e.lines


def drill(rng: Rng, variant: int) -> list[str]:
    """Drilling grids with canned cycles and G98/G99, a G4 dwell."""
    e = Emitter()
    nx = rng.integer(3, 4)
    ny = 2 if variant else rng.integer(2, 3)
    px, py = rng.step(15, 25, 1), rng.step(15, 25, 1)
    x0, y0 = rng.step(10, 30, 1), rng.step(10, 30, 1)
    r = rng.choice([1.0, 2.0, 3.0])
    assert isinstance(r, float)
    holes = [(x0 + i * px, y0 + j * py) for j in range(ny) for i in (range(nx) if j % 2 == 0 else
                                                                     range(nx - 1, -1, -1))]
    if variant == 0:
        title = "DRILL_G81_G83 - SPOT AND PECK DRILLING, G81/G83 WITH G99 AND G98"
        spot, peck = "G81", "G83"
    else:
        title = "DRILL_G82_G73 - SPOT WITH DWELL AND CHIP-BREAK DRILLING, G82/G73 WITH G99 AND G98"
        spot, peck = "G82", "G73"
    dwell = rng.choice([0.3, 0.5, 0.8])
    assert isinstance(dwell, float)
    header(e, title, [f"{nx} X {ny} GRID, PITCH {num(px, 1)} X {num(py, 1)}, G98 OVER A CLAMP",
                      f"ONE G4 DWELL P{num(dwell, 2)} - MEASURE AT REAL TIME"])
    e.g0(z=25)
    e.g0(*holes[0])
    fs = rng.step(600, 1000, 100)
    zspot = -rng.step(2, 4, 0.5)
    clamp = rng.integer(1, len(holes) - 2)
    spot_words = f"{spot} X{num(holes[0][0], 3)} Y{num(holes[0][1], 3)} Z{num(zspot, 3)} R{num(r, 3)}"
    if spot == "G82":
        spot_words += f" P{num(rng.choice([0.1, 0.2]), 2)}"  # type: ignore[arg-type]
    e.raw(f"G99 {spot_words} F{num(fs, 0)}")
    for i, (hx, hy) in enumerate(holes[1:], start=1):
        mode = "G98 " if i == clamp else ("G99 " if i == clamp + 1 else "")
        e.raw(f"{mode}X{num(hx, 3)} Y{num(hy, 3)}")
    e.raw("G80")
    e.pos.update(X=holes[-1][0], Y=holes[-1][1], Z=math.nan)
    e.motion = ""
    e.g0(z=25)
    e.raw(f"G4 P{num(dwell, 2)}")
    # pecked holes in between the spots
    ph = [((holes[i][0] + px / 2), holes[i][1] + py / 2) for i in range(len(holes))
          if holes[i][0] + px / 2 < x0 + (nx - 1) * px and holes[i][1] + py / 2 < y0 + (ny - 1) * py]
    ph = ph[: rng.integer(3, 5)]
    zd = -rng.step(8, 14, 1)
    q = rng.step(2.5, 5, 0.5)
    fp = rng.step(700, 1100, 100)
    e.g0(*ph[0])
    e.raw(f"G98 {peck} X{num(ph[0][0], 3)} Y{num(ph[0][1], 3)} Z{num(zd, 3)} R{num(r, 3)} "
          f"Q{num(q, 3)} F{num(fp, 0)}")
    for i, (hx, hy) in enumerate(ph[1:], start=1):
        e.raw(f"{'G99 ' if i == 1 else ''}X{num(hx, 3)} Y{num(hy, 3)}")
    e.raw("G80")
    e.motion = ""
    e.pos.update(X=ph[-1][0], Y=ph[-1][1], Z=math.nan)
    e.g0(z=25)
    e.g0(0, 0)
    footer(e)
    return e.lines


def helix_side_arcs(rng: Rng, side_plane: str) -> list[str]:
    """Helical bores (G2/G3 with Z) and full circles, then arcs in G18 (XZ) or G19 (YZ) stepping
    across; G64 without P."""
    e = Emitter()
    header(e, f"HELIX_{side_plane} - HELICAL BORES, FULL CIRCLES, {side_plane} SIDE-PLANE ARCS",
           ["T14 D=10 FLAT: HELIX BORES AND SPRING PASSES",
            f"T15 D=6 BALL: EDGE ROUND AS {'XZ' if side_plane == 'G18' else 'YZ'} ARCS"])
    e.raw("G64")
    e.g0(z=10)
    nb = 2
    xs = rng.step(30, 40, 1)
    y = rng.step(25, 40, 1)
    for b in range(nb):
        cx = xs + b * rng.step(30, 40, 1)
        r = rng.step(3, 6, 0.5)
        pitch = rng.step(1.0, 2.0, 0.25)
        turns = rng.integer(2, 4)
        cw = rng.chance(0.5)
        e.g0(cx + r, y)
        e.g0(z=1)
        e.g1(z=0.5, f=400)
        fh = rng.step(900, 1500, 100)
        z = 0.5
        for _ in range(turns):
            z -= pitch
            e.arc(cw, {"X": cx + r, "Y": y, "Z": z}, {"X": cx, "Y": y}, fh)
        e.arc(cw, {"X": cx + r, "Y": y}, {"X": cx, "Y": y})
        if rng.chance(0.7):
            r2 = r + rng.step(0.2, 0.5, 0.05)
            e.g1(cx + r - 1, f=1000)
            e.arc(cw, {"X": cx + r2, "Y": y}, {"X": (cx + r - 1 + cx + r2) / 2, "Y": y})
            fs = rng.step(1400, 2000, 100)
            e.arc(cw, {"X": cx + r2, "Y": y}, {"X": cx, "Y": y}, fs)
            e.arc(cw, {"X": cx + r2, "Y": y}, {"X": cx, "Y": y})
        e.g1(cx, f=2000)
        e.g0(z=10)
    e.comment("edge round, side plane")
    rr = rng.step(5, 9, 1)
    n = rng.integer(4, 6)
    stp = rng.step(1.0, 2.0, 0.5)
    fe = rng.step(1200, 1800, 100)
    if side_plane == "G18":
        x1 = xs + nb * 40 + 10
        y1 = rng.step(5, 15, 1)
        e.g0(x1 - rr - 2, y1)
        e.g0(z=2)
        e.g1(x1 - rr, z=0, f=800)
        for i in range(n):
            if i > 0:
                e.g1(y=y1 + i * stp, f=fe)
            if i % 2 == 0:  # down the quarter round: from the top edge to the side
                e.arc(False, {"X": x1, "Z": -rr}, {"X": x1 - rr, "Z": -rr}, fe, plane="G18")
            else:
                e.arc(True, {"X": x1 - rr, "Z": 0}, {"X": x1 - rr, "Z": -rr}, fe, plane="G18")
    else:
        x1 = rng.step(10, 30, 1)
        y1 = y + 40
        e.g0(x1, y1 - rr - 2)
        e.g0(z=2)
        e.g1(y=y1 - rr, z=0, f=800)
        for i in range(n):
            if i > 0:
                e.g1(x=x1 + i * stp, f=fe)
            if i % 2 == 0:
                e.arc(True, {"Y": y1, "Z": -rr}, {"Y": y1 - rr, "Z": -rr}, fe, plane="G19")
            else:
                e.arc(False, {"Y": y1 - rr, "Z": 0}, {"Y": y1 - rr, "Z": -rr}, fe, plane="G19")
    e.g0(z=10)
    e.set_plane("G17")
    e.g0(0, 0)
    footer(e)
    return e.lines


def trochoid_inch(rng: Rng) -> list[str]:
    """G20: a trochoidal slot of short chords with a feed on almost every line, then a zigzag with
    feed optimisation; G64 P in inch."""
    e = Emitter(inch=True)
    p = rng.choice([0.001, 0.002, 0.003])
    assert isinstance(p, float)
    r = rng.step(0.06, 0.1, 0.01)
    adv = rng.step(0.03, 0.05, 0.005)
    length = rng.step(1.2, 2.0, 0.1)
    ang = rng.choice([0.0, 90.0, 30.0, -20.0])
    assert isinstance(ang, float)
    npts = rng.choice([12, 16, 20])
    assert isinstance(npts, int)
    fmax = rng.step(140, 200, 10)
    fmin = rng.step(45, 65, 5)
    header(e, f"INCH_TROCHOID - G20, TROCHOIDAL SLOT AND ZIGZAG, FEED VARIES LINE TO LINE, G64 P{num(p, 4)}",
           [f"T18 D=1/4 IN FLAT - SLOT {num(length, 2)} IN LONG AT {num(ang, 0)} DEG BY TROCHOIDAL LOOPS",
            "THEN ZIGZAG FACE WITH FEED OPTIMISATION"], inch=True)
    e.raw(f"G64 P{num(p, 4)}")
    ca, sa = math.cos(math.radians(ang)), math.sin(math.radians(ang))
    sx, sy = 0.6, 0.6 + (0.2 if ang < 0 else 0.0)

    def at(u: float, v: float) -> Point:
        return sx + u * ca - v * sa, sy + u * sa + v * ca

    e.g0(z=0.6)
    e.g0(*at(r, 0))
    e.g0(z=0.1)
    e.g1(z=-rng.step(0.15, 0.3, 0.05), f=20)
    u = 0.0
    while u < length:
        for i in range(1, npts + 1):
            t = 2 * math.pi * i / npts
            uu = u + adv * i / npts
            x, y = at(uu + r * math.cos(t), r * math.sin(t))
            # slow on the engaged side (cos t > 0 ahead), fast on the way back
            eng = max(0.0, math.cos(t - math.pi / 2 * 0.0))
            feed = round(fmax - (fmax - fmin) * eng ** 1.5, 0)
            e.g1(x, y, f=feed)
        u += adv
    e.g0(z=0.6)
    e.comment("zigzag with feed optimisation")
    zx0, zy0 = at(0, 0.5)[0], max(at(0, 0.5)[1], at(length, 0.5)[1]) + 0.3
    wz = rng.step(1.2, 1.8, 0.1)
    rows = rng.integer(5, 8)
    so = rng.step(0.08, 0.12, 0.01)
    e.g0(zx0, zy0)
    e.g0(z=0.1)
    e.g1(z=-0.08, f=25)
    fz = [rng.step(60, 80, 5), rng.step(85, 100, 5), rng.step(110, 130, 5)]
    xs = [zx0 + wz * t for t in (0.08, 0.25, 0.5, 0.75, 0.92, 1.0)]
    for row in range(rows):
        seq = xs if row % 2 == 0 else [zx0 + zx0 + wz - x for x in xs]
        feeds = [fz[0], fz[1], fz[2], fz[2], fz[1], fz[0]]
        for x, f in zip(seq, feeds, strict=True):
            e.g1(x, f=f)
        e.g1(y=zy0 + (row + 1) * so, f=45)
    e.g0(z=0.6)
    e.g0(0, 0)
    footer(e)
    return e.lines


def oword_grid(rng: Rng) -> list[str]:
    """O-word subroutine (incremental ring pocket), nested while, if/else and repeat; G64 P."""
    p = rng.choice([0.02, 0.03, 0.05])
    assert isinstance(p, float)
    cols, rows = 2, 2
    sx, sy = rng.step(18, 24, 1), rng.step(18, 24, 1)
    f = rng.step(1600, 2600, 200)
    s1, s2 = rng.step(3, 4, 0.5), rng.step(4, 5.5, 0.5)
    passes = 2
    dz = rng.step(1.0, 2.0, 0.5)
    lines = [
        "(OWORD_GRID - O-WORD SUBROUTINE IN G91, NESTED WHILE LOOPS, IF, REPEAT)",
        f"(T20 D=4 FLAT - {cols} X {rows} GRID OF RECTANGULAR POCKETS CUT BY AN INCREMENTAL SUBROUTINE)",
        f"(PASSES AND SIZES FROM PARAMETERS, G64 P{num(p, 3)})",
        "G17 G21 G90 G94 G40 G49 G80",
        "S10000 M3",
        f"G64 P{num(p, 3)}",
        "#<_zsafe> = 5",
        f"#<_cutfeed> = {num(f, 0)}",
        "",
        "(rectangular ring pocket around the current XY, incremental)",
        "(#1 = half width of the outer ring, #2 = passes, #3 = depth per pass, #4 = aspect)",
        "o100 sub",
        "  G91",
        "  #5 = 0",
        "  o110 while [#5 LT #2]",
        "    G1 Z[-#3 - [#5 EQ 0]] F300",
        "    #6 = [#1 / 2]",
        "    o120 repeat [2]",
        "      G1 X#6 F#<_cutfeed>",
        "      Y[#6 * #4]",
        "      X[-2*#6]",
        "      Y[-2*#6 * #4]",
        "      X[2*#6]",
        "      Y[#6 * #4]",
        "      X-#6",
        "      #6 = #1",
        "    o120 endrepeat",
        "    #5 = [#5 + 1]",
        "  o110 endwhile",
        "  G90",
        "o100 endsub",
        "",
        "G0 Z#<_zsafe>",
        "#<_row> = 0",
        f"o200 while [#<_row> LT {rows}]",
        "  #<_col> = 0",
        f"  o210 while [#<_col> LT {cols}]",
        f"    G0 X[12 + #<_col> * {num(sx, 1)}] Y[12 + #<_row> * {num(sy, 1)}]",
        "    G0 Z1",
        "    o220 if [[#<_col> + #<_row>] MOD 2 EQ 1]",
        f"      o100 call [{num(s2, 2)}] [{passes}] [{num(dz, 2)}] [0.8]",
        "    o220 else",
        f"      o100 call [{num(s1, 2)}] [{passes}] [{num(dz, 2)}] [1.2]",
        "    o220 endif",
        "    G0 Z#<_zsafe>",
        "    #<_col> = [#<_col> + 1]",
        "  o210 endwhile",
        "  #<_row> = [#<_row> + 1]",
        "o200 endwhile",
        "G0 X0 Y0",
        "M5 M2",
    ]
    return lines


def oword_bolt(rng: Rng) -> list[str]:
    """O-word subroutine of incremental arcs (a counterbore) called on a bolt circle by a while loop
    with trigonometry, if/else on the index, repeat for spring passes; G64 P."""
    p = rng.choice([0.01, 0.02, 0.04])
    assert isinstance(p, float)
    n = rng.integer(4, 6)
    rb = rng.step(25, 40, 1)
    cx, cy = rng.step(50, 70, 1), rng.step(45, 60, 1)
    rc = rng.step(3, 5, 0.5)
    f = rng.step(1200, 2000, 100)
    depth = rng.step(2, 3, 1)
    a0 = rng.step(0, 30, 5)
    lines = [
        "(OWORD_BOLT - O-WORD SUB OF G91 ARCS ON A BOLT CIRCLE, WHILE WITH TRIG, IF/ELSE, REPEAT)",
        f"(T21 D=6 FLAT - {n} COUNTERBORES R{num(rc, 2)} ON A D{num(2 * rb, 1)} BOLT CIRCLE, "
        f"G64 P{num(p, 3)})",
        "G17 G21 G90 G94 G40 G49 G80",
        "S10000 M3",
        f"G64 P{num(p, 3)}",
        f"#<_cx> = {num(cx, 1)}",
        f"#<_cy> = {num(cy, 1)}",
        f"#<_fcut> = {num(f, 0)}",
        "",
        "(counterbore at the current XY: helix down in G91, then #3 spring passes)",
        "(#1 = radius, #2 = depth, #3 = spring passes)",
        "o300 sub",
        "  G91",
        "  G1 X#1 F#<_fcut>",
        "  #4 = 0",
        "  o310 while [#4 LT #2]",
        "    G3 X0 Y0 Z-1 I-#1 J0",
        "    #4 = [#4 + 1]",
        "  o310 endwhile",
        "  o320 repeat [#3]",
        "    G3 X0 Y0 I-#1 J0",
        "  o320 endrepeat",
        "  G1 X-#1",
        "  G90",
        "o300 endsub",
        "",
        "G0 Z5",
        "#<_hole> = 0",
        f"o400 while [#<_hole> LT {n}]",
        f"  #<_ang> = [{num(a0, 1)} + 360 * #<_hole> / {n}]",
        f"  G0 X[#<_cx> + {num(rb, 1)} * COS[#<_ang>]] Y[#<_cy> + {num(rb, 1)} * SIN[#<_ang>]]",
        "  G0 Z1",
        "  G1 Z0 F400",
        "  o410 if [#<_hole> MOD 2 EQ 0]",
        f"    o300 call [{num(rc, 2)}] [{num(depth, 1)}] [2]",
        "  o410 else",
        f"    o300 call [{num(rc - 0.5, 2)}] [{num(depth, 1)}] [1]",
        "  o410 endif",
        "  G0 Z5",
        "  #<_hole> = [#<_hole> + 1]",
        "o400 endwhile",
        "G0 X0 Y0",
        "M5 M2",
    ]
    return lines


def engrave(rng: Rng) -> list[str]:
    """Engraving: curves as 0.05 mm segments at a high feed; G64 P0.01."""
    e = Emitter()
    f = rng.step(2400, 3600, 200)
    curves: list[tuple[str, Callable[[float], Point], float, float]] = []
    cx, cy = rng.step(20, 30, 1), rng.step(18, 25, 1)
    k = rng.choice([3, 4, 5, 7])
    assert isinstance(k, int)
    ra = rng.step(6, 10, 0.5)
    curves.append(("rose", lambda t: (cx + ra * math.cos(k * t) * math.cos(t),
                                      cy + ra * math.cos(k * t) * math.sin(t)), 0.0, math.pi))
    lx, ly = cx + 2 * ra + 8, cy
    la, lb = rng.integer(2, 4), rng.integer(3, 5)
    curves.append(("lissajous", lambda t: (lx + 6 * math.sin(la * t + 0.5), ly + 5 * math.sin(lb * t)),
                   0.0, 2 * math.pi))
    hx, hy = cx, cy + 2 * ra + 6
    big, small, dd = rng.step(5, 7, 0.5), rng.step(1.5, 2.5, 0.5), rng.step(1, 2.5, 0.5)
    ratio = (big - small) / small
    curves.append(("hypotrochoid", lambda t: (hx + (big - small) * math.cos(t) + dd * math.cos(ratio * t),
                                              hy + (big - small) * math.sin(t) - dd * math.sin(ratio * t)),
                   0.0, 2 * math.pi * small / math.gcd(int(big * 2), int(small * 2)) * 2))
    header(e, "ENGRAVE - ENGRAVING, 0.05 MM SEGMENTS, G64 P0.01",
           [f"T22 60DEG V-BIT - ROSE, LISSAJOUS FIGURE AND HYPOTROCHOID, F{num(f, 0)}, DEPTH 0.15"])
    e.raw("G64 P0.01")
    e.g0(z=5)
    for name, fn, t0, t1 in curves:
        dense = [fn(t0 + (t1 - t0) * i / 20000) for i in range(20001)]
        pts = [dense[0]]
        acc = 0.0
        for p, q in itertools.pairwise(dense):
            acc += math.dist(p, q)
            if acc >= 0.05:
                pts.append(q)
                acc = 0.0
        e.comment(name)
        e.g0(z=1)
        e.g0(*pts[0])
        e.g1(z=-0.15, f=400)
        first = True
        for x, y in pts[1:]:
            e.g1(x, y, f=f if first else None)
            first = False
        e.g0(z=1)
    e.g0(z=5)
    e.g0(0, 0)
    footer(e)
    return e.lines


def mixed(rng: Rng, variant: int) -> list[str]:
    """A shop program: facing passes, G0 between cuts, feed changes, a contour, spindle stop and
    start in the middle (variant 1) or a T2 M6 tool change (variant 0) followed by drilling and
    slots."""
    e = Emitter()
    blend = rng.choice(["G64", "G64 P0.02", "G64 P0.05"])
    assert isinstance(blend, str)
    wx, wy = rng.step(50, 70, 5), rng.step(35, 45, 5)
    ox, oy = rng.step(5, 20, 1), rng.step(5, 20, 1)
    notes = ["FACE, POCKET CORNERS, SLOTS; FEED CHANGES AND RAPIDS BETWEEN CUTS"]
    if variant == 0:
        title = f"MIXED_TOOLCHANGE - FACE WITH T1, T2 M6 TOOL CHANGE, SLOTS AND HOLES, {blend}"
        notes.append("ONE TOOL CHANGE [T2 M6] - MEASURE AT REAL TIME")
    else:
        title = f"MIXED_SPINDLE - FACE, SPINDLE STOP/START MID-PROGRAM, G61.1 AND {blend}"
        notes.append("M5 AND M3 IN THE MIDDLE - MEASURE AT REAL TIME")
    header(e, title, notes)
    e.raw(blend)
    e.g0(z=20)
    # facing zigzag
    so = rng.step(10, 14, 1)
    ff = rng.step(3000, 4500, 250)
    e.g0(ox - 8, oy)
    e.g0(z=2)
    e.g1(z=-0.5, f=600)
    y = oy
    row = 0
    while y <= oy + wy + 1e-9:
        xe = ox + wx + 8 if row % 2 == 0 else ox - 8
        e.g1(xe, f=ff)
        y += so
        if y <= oy + wy + 1e-9:
            e.g1(y=y, f=ff * 0.6)
        row += 1
    e.g0(z=5)
    # corner slots with different feeds, G0 between cuts
    for i, (px, py) in enumerate([(ox + 5, oy + 5), (ox + wx - 5, oy + 5), (ox + wx - 5, oy + wy - 5),
                                  (ox + 5, oy + wy - 5)]):
        e.g0(px, py)
        e.g0(z=1)
        e.g1(z=-2, f=rng.step(300, 500, 50))
        sl = rng.step(10, 20, 1)
        dx = sl if px < ox + wx / 2 else -sl
        e.g1(px + dx, f=rng.step(1200, 2400, 100))
        e.g1(y=py + (3 if py < oy + wy / 2 else -3), f=rng.step(800, 1200, 100))
        e.g1(px, f=rng.step(1500, 3000, 100))
        e.g0(z=5 if i < 3 else 20)
    if variant == 0:
        e.raw("T2 M6")
        e.raw("S12000 M3")
        e.motion = ""
    else:
        e.raw("M5")
        e.g0(ox + wx / 2, oy + wy / 2)
        e.raw("M3 S8000")
        e.raw("G4 P0.5")
        e.raw("G61.1")
    # a contour (rounded rectangle) and some holes with plain G1 pecks
    r = rng.step(4, 8, 1)
    verts = [(ox + wx - 10, oy + 10, r), (ox + 10, oy + 10, r), (ox + 10, oy + wy - 10, r),
             (ox + wx - 10, oy + wy - 10, r)]
    verts = [verts[1], verts[2], verts[3], verts[0]]
    start, elems = rounded_polygon(verts[::-1], 0.0)
    e.g0(*start)
    e.g0(z=1)
    e.g1(z=-1.5, f=400)
    run_elems(e, elems, f=rng.step(1500, 2500, 100))
    e.g0(z=5)
    if variant == 1:
        e.raw(blend)
    fd = rng.step(400, 600, 50)
    for hx, hy in [(ox + wx / 3, oy + wy / 2), (ox + 2 * wx / 3, oy + wy / 2), (ox + wx / 2, oy + wy / 3)]:
        e.g0(hx, hy)
        e.g0(z=1)
        e.g1(z=-2, f=fd)
        e.g0(z=0.5)
        e.g1(z=-4)
        e.g0(z=5)
    e.g0(z=20)
    e.g0(0, 0)
    footer(e)
    return e.lines


# ---------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Case:
    number: int
    kind: str
    seed: int
    make: Callable[[Rng], list[str]]
    what: str  # what the program exercises, for tables
    tags: tuple[str, ...]

    @property
    def file(self) -> str:
        return f"{self.number:02d}_{self.kind}.ngc"


CASES: list[Case] = [
    Case(1, "pocket_rect", 101, pocket_rect, "rect pocket, rings from the centre, ramp, arc corners; G64 P",
         ("2d_pocket", "offset_rings", "ramp_entry", "g2g3_corners", "g64_p")),
    Case(2, "pocket_circ", 202, pocket_circ, "circular pocket, helical entry, full-circle rings; G64 P",
         ("2d_pocket", "helix_entry", "full_circles", "g64_p")),
    Case(3, "pocket_rect_inch", 303, lambda r: pocket_rect(r, inch=True),
         "inch rect pocket, rings, ramp, arc corners; G20 G64 P",
         ("inch_g20", "2d_pocket", "offset_rings", "ramp_entry", "g64_p")),
    Case(4, "contour_plate", 404, contour, "outside profile lines+arcs, notch, lead-in/out arcs; G64",
         ("contour_lines_arcs", "lead_in_out_arcs", "g64_default")),
    Case(5, "contour_plate_b", 505, contour, "outside profile with chamfer, lead-in/out arcs; G64",
         ("contour_lines_arcs", "lead_in_out_arcs", "g64_default")),
    Case(6, "contour_inch", 606, lambda r: contour(r, inch=True),
         "inch outside profile, notch, chamfer; G20 G64",
         ("inch_g20", "contour_lines_arcs", "lead_in_out_arcs", "g64_default")),
    Case(7, "surface_raster", 707, surface, "3D raster, short segments, merged; G64 P0.01",
         ("3d_surface", "short_segments", "raster", "g64_p0.01")),
    Case(8, "surface_raster_b", 808, surface, "3D raster along the other axis; G64 P",
         ("3d_surface", "short_segments", "raster", "g64_p")),
    Case(9, "finish_rings_g61", 909, rings_g61, "3D finishing rings (ellipses), short segments; G61",
         ("3d_surface", "g61_exact_path", "contour_parallel_finish")),
    Case(10, "finish_rings_g61_b", 1010, rings_g61, "3D finishing rings (rounded rectangles); G61",
         ("3d_surface", "g61_exact_path", "contour_parallel_finish")),
    Case(11, "exactstop_mix", 1111, exactstop_mix, "G0/G1 from 0.005 mm to 220 mm; G61.1",
         ("g61.1_exact_stop", "g0_g1_very_short_and_very_long")),
    Case(12, "drill_g81_g83", 1212, lambda r: drill(r, 0), "G81 spots, G83 pecks, G98/G99, G4 dwell",
         ("drilling", "g81", "g83", "g98", "g99", "g4_dwell")),
    Case(13, "drill_g82_g73", 1313, lambda r: drill(r, 1), "G82 spots with P, G73 pecks, G98/G99, G4 dwell",
         ("drilling", "g82", "g73", "g98", "g99", "g4_dwell")),
    Case(14, "helix_g18", 1414, lambda r: helix_side_arcs(r, "G18"),
         "helical bores, spring passes, G18 XZ arcs; G64",
         ("helix", "full_circles", "g18_xz_arcs", "g64_default")),
    Case(15, "helix_g19", 1515, lambda r: helix_side_arcs(r, "G19"),
         "helical bores G2/G3, G19 YZ arcs; G64",
         ("helix", "full_circles", "g19_yz_arcs", "g64_default")),
    Case(16, "inch_trochoid", 1616, trochoid_inch, "inch trochoid + zigzag, feed on every line; G20 G64 P",
         ("inch_g20", "trochoidal", "feed_changes_line_to_line", "g64_p")),
    Case(17, "oword_grid", 1717, oword_grid, "O-word sub in G91, while, if/else, repeat; G64 P",
         ("o_word_sub", "o_word_while", "o_word_if", "o_word_repeat", "g91_incremental", "g64_p")),
    Case(18, "oword_bolt", 1818, oword_bolt, "O-word G91 helix sub on a bolt circle, trig; G64 P",
         ("o_word_sub", "o_word_while", "o_word_if", "o_word_repeat", "g91_incremental", "helix", "g64_p")),
    Case(19, "engrave", 1919, engrave, "engraving, 0.05 mm segments at a high feed; G64 P0.01",
         ("engraving", "tiny_segments_0.05mm", "high_feed", "g64_p0.01")),
    Case(20, "mixed_toolchange", 2020, lambda r: mixed(r, 0),
         "facing, slots, contour, holes; feed changes, T2 M6 mid-program",
         ("mixed", "feed_changes", "tool_change_m6", "g64")),
    Case(21, "mixed_spindle", 2121, lambda r: mixed(r, 1),
         "facing, slots; M5/M3 + G4 mid-program, G61.1 section",
         ("mixed", "feed_changes", "spindle_stop_start", "g4_dwell", "g61.1_exact_stop", "g64")),
]


def generate() -> dict[str, str]:
    return {c.file: "\n".join(c.make(Rng(c.seed))) + "\n" for c in CASES}


def write_programs(description: str, default_out: Path, make: Callable[[], dict[str, str]],
                   argv: list[str] | None = None) -> int:
    """The command line of a generator of timing programs: write them (``--out``), or only
    compare them with the files there (``--check``, exit 1 if any differs)."""
    ap = argparse.ArgumentParser(description=description)
    ap.add_argument("--out", type=Path, default=default_out)
    ap.add_argument("--check", action="store_true", help="compare with the files, write nothing")
    args = ap.parse_args(argv)
    progs = make()
    if args.check:
        bad = [n for n, t in progs.items() if not (args.out / n).exists() or (args.out / n).read_text() != t]
        for n in bad:
            print(f"differs: {n}")
        return 1 if bad else 0
    args.out.mkdir(parents=True, exist_ok=True)
    for name, text in progs.items():
        (args.out / name).write_text(text)
        print(f"{name}: {text.count(chr(10))} lines")
    return 0


def main(argv: list[str] | None = None) -> int:
    return write_programs(__doc__.split("\n")[0], CASES_DIR, generate, argv)


if __name__ == "__main__":
    sys.exit(main())
