"""The ``lathe`` kind: G71/G72 roughing and G70 finishing on profile subroutines in the style of
real lathe programs.

A profile is drawn in the cycle's own frame: ``a`` is the axis the passes step along, ``b`` the
axis each pass cuts along.  It starts near the stock's face, its ``a`` grows (shoulders, tapers,
quarter and partial arcs, now and then a pocket that dips and rises again) while ``b`` runs one
way, and the start point of the cycle lies outside it.  The frame is then turned into the XZ plane
in one of eight ways: G71 (a is X) or G72 (a is Z), each with either direction on either axis —
external turning, boring, facing from either side.  Arcs are written with I/K or R, lines now and
then with U/W, A (fillet) or C (chamfer).  G70 follows the roughing now and then.
"""

from __future__ import annotations

import math
import random


def _fmt(v: float) -> str:
    text = f"{v:.4f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


class _Profile:
    """Points and segments of a profile in the (a, b) frame; b decreases along it."""

    def __init__(self, rng: random.Random) -> None:
        self.rng = rng
        self.a = round(rng.uniform(0.0, 4.0), 1) if rng.random() < 0.7 else 0.0
        self.b = 0.0
        self.start = (self.a, self.b)
        # (kind, a1, b1, ca, cb, extras): kind "line" or "arc"
        self.segs: list[tuple[str, float, float, float, float]] = []

    def line(self, da: float, db: float) -> None:
        self.a += da
        self.b -= db
        self.segs.append(("line", self.a, self.b, 0.0, 0.0))

    def arc(self, r: float, t0: float, t1: float, ca_sign: int) -> None:
        """An arc of radius r from angle t0 to t1 (within one quadrant), placed at the current point;
        angles are measured in the (a, b) frame from +b toward +a."""
        p0 = (r * math.sin(t0), r * math.cos(t0))
        p1 = (r * math.sin(t1), r * math.cos(t1))
        da, db = p1[0] - p0[0], p1[1] - p0[1]
        if da * ca_sign < -1e-9 or db > -1e-9:
            return
        ca, cb = self.a - p0[0], self.b - p0[1]
        self.a += da
        self.b += db
        self.segs.append(("arc", round(self.a, 4), round(self.b, 4), ca, cb))
        self.a, self.b = self.segs[-1][1], self.segs[-1][2]

    @property
    def top(self) -> float:
        return max([self.start[0]] + [s[1] for s in self.segs])


def _draw(rng: random.Random) -> _Profile:
    p = _Profile(rng)
    for _ in range(rng.randint(2, 7)):
        r = rng.random()
        if r < 0.25:
            p.line(0.0, round(rng.uniform(0.5, 5.0), 2))
        elif r < 0.45:
            p.line(round(rng.uniform(0.3, 3.0), 2), 0.0)
        elif r < 0.6:
            p.line(round(rng.uniform(0.2, 2.0), 2), round(rng.uniform(0.3, 3.0), 2))
        elif r < 0.68:  # a pocket: down, along, up
            depth = round(rng.uniform(0.2, min(1.5, max(0.2, p.a - 0.1))), 2)
            if p.a - depth > 0.05:
                p.line(-depth, round(rng.uniform(0.3, 2.0), 2))
                if rng.random() < 0.5:
                    p.line(0.0, round(rng.uniform(0.3, 2.0), 2))
                p.line(depth + round(rng.uniform(0.0, 1.0), 2), round(rng.uniform(0.3, 2.0), 2))
        else:
            radius = round(rng.uniform(0.5, 4.0), 2)
            quadrant = rng.choice((0, 1, 2, 3))
            lo = quadrant * math.pi / 2
            if rng.random() < 0.6:
                t0, t1 = lo, lo + math.pi / 2
            else:
                t0, t1 = sorted(rng.uniform(lo, lo + math.pi / 2) for _ in range(2))
            if rng.random() < 0.5:
                t0, t1 = t1, t0
            p.arc(radius, t0, t1, 1)
    if not p.segs:
        p.line(0.0, 2.0)
    return p


def gen_lathe(seed: int) -> str:
    rng = random.Random(seed)
    p = _draw(rng)
    facing = rng.random() < 0.4
    sa = 1 if rng.random() < 0.75 else -1  # the step axis: growing (external) or shrinking
    sb = 1 if rng.random() < 0.75 else -1  # the cut: toward -b or +b
    inch = rng.random() < 0.1
    scale = 0.1 if inch else 1.0
    oa = 0.0 if sa == 1 else round(p.top + rng.uniform(2.0, 6.0), 1)
    low_b = min([p.start[1]] + [s[2] for s in p.segs])
    if facing:  # X stays on the positive side: toward the centre or away from it
        ob = round(-low_b + rng.uniform(0.0, 2.0), 1) if sb == 1 else round(rng.uniform(0.0, 3.0), 1)
    else:
        ob = round(rng.uniform(-3.0, 3.0), 1) if rng.random() < 0.3 else 0.0

    def xz(a: float, b: float) -> tuple[float, float]:
        pa, pb = (oa + sa * a) * scale, (ob + sb * b) * scale
        return (pb, pa) if facing else (pa, pb)

    lines = ["G18 G90 G40 " + ("G20 F8" if inch else "G21 F200"), "G0 X30 Z30"]
    if facing:
        lines[1] = "G0 X40 Z20"
    sub = rng.choice((100, 101, 200))
    lines.append(f"o{sub} sub")
    x0, z0 = xz(*p.start)
    lines.append(f"G{rng.choice((0, 0, 1))} X{_fmt(x0)} Z{_fmt(z0)}")
    px, pz = x0, z0
    for i, (kind, a1, b1, ca, cb) in enumerate(p.segs):
        x1, z1 = xz(a1, b1)
        if kind == "line":
            words = []
            if rng.random() < 0.1:
                words.append(f"U{_fmt(x1 - px)}")
            elif abs(x1 - px) > 1e-9 or rng.random() < 0.3:
                words.append(f"X{_fmt(x1)}")
            if rng.random() < 0.1:
                words.append(f"W{_fmt(z1 - pz)}")
            elif abs(z1 - pz) > 1e-9 or rng.random() < 0.3:
                words.append(f"Z{_fmt(z1)}")
            if not words:
                words.append(f"Z{_fmt(z1)}")
            if i + 1 < len(p.segs) and p.segs[i + 1][0] == "line" and rng.random() < 0.08:
                words.append(rng.choice(("A", "C")) + _fmt(round(rng.uniform(0.1, 0.4), 2) * scale))
            lines.append(("G1 " if rng.random() < 0.7 else "") + " ".join(words))
        else:
            cx, cz = xz(ca, cb)
            # G2 or G3 from the turn of the arc in the (z, x) plane
            sx, sz_ = px - cx, pz - cz
            ex, ez = x1 - cx, z1 - cz
            cross = sz_ * ex - sx * ez
            g = 3 if cross > 0 else 2
            if rng.random() < 0.7:
                lines.append(f"G{g} X{_fmt(x1)} Z{_fmt(z1)} I{_fmt(cx - px)} K{_fmt(cz - pz)}")
            else:
                lines.append(f"G{g} X{_fmt(x1)} Z{_fmt(z1)} R{_fmt(math.hypot(sx, sz_))}")
        px, pz = x1, z1
    # out to the stock again now and then
    if rng.random() < 0.5:
        xe, ze = xz(p.top + rng.uniform(0.5, 2.0) * (1 if rng.random() < 0.8 else 0), p.segs[-1][2])
        lines.append(f"G{rng.choice((0, 1))} X{_fmt(xe)} Z{_fmt(ze)}")
    lines.append(f"o{sub} endsub")
    clear_a = round(p.top + rng.uniform(0.5, 3.0), 1)
    clear_b = round(rng.uniform(0.0, 2.0), 1) if rng.random() < 0.8 else 0.0
    xs, zs = xz(clear_a, clear_b)
    code = ("G72" if facing else "G71") + rng.choice(("", "", "", ".1", ".2"))
    d = rng.choice((0, 0.2, 0.5, 1.0)) * scale
    words = [f"Q{sub}", f"X{_fmt(xs)}", f"Z{_fmt(zs)}"]
    if d or rng.random() < 0.3:
        words.append(f"D{_fmt(d)}")
    words.append(f"I{_fmt(rng.choice((0.5, 1.0, 1.5, 2.0)) * scale)}")
    if rng.random() < 0.7:
        words.append(f"R{_fmt(rng.choice((0.2, 0.3, 0.5)) * scale)}")
    lines.append(f"{code} " + " ".join(words))
    if rng.random() < 0.4:
        lines.append(f"G70 Q{sub} X{_fmt(xs)} Z{_fmt(zs)} D{_fmt(d / 2)} P{rng.choice((1, 2))}")
    lines.append("G0 X" + ("40 Z20" if facing else "30 Z30"))
    lines.append("M2")
    return "".join(line + "\n" for line in lines)


__all__ = ["gen_lathe"]
