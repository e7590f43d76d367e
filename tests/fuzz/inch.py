"""Statements of the ``offsets-inch`` kind: the ``offsets`` programs in G20 with the five-decimal
values of CAM output for inch machines.  rs274 keeps offsets in parameters in inches by way of
millimetres, so a value in inches may come back from them a little off; five decimals are often
exactly half-way between two printed at four.  The statements set origins (G10 L2 with and without
a rotation R, G10 L20), local and G92 offsets, and move with five-decimal traverses, feeds and
arcs among them.  The functions take gen.py's ``Gen`` (not imported: gen.py imports this)."""

from __future__ import annotations

import math
from typing import Any

Gen = Any  # gen.Gen
PLACES = 5
# plane code -> (first axis, second axis, first offset letter, second offset letter)
PLANES = {"17": ("x", "y", "i", "j"), "18": ("z", "x", "k", "i"), "19": ("y", "z", "j", "k")}


def _number(g: Gen, lo: float, hi: float) -> float:
    """A five-decimal number (``lo`` .. ``hi`` mm in program units), often one that ends in 5:
    a tie at four decimals."""
    v = g.coord(lo, hi, PLACES)
    if g.rng.random() < 0.5:
        v = round(math.floor(v * 1e4) / 1e4 + 0.00005, PLACES)
    return float(v)


def _value(g: Gen, lo: float, hi: float) -> str:
    return g.num(_number(g, lo, hi), PLACES)


def _offset_words(g: Gen, lo: float = -30, hi: float = 30) -> list[str]:
    chosen = [a for a in "xyz" if g.rng.random() < 0.6] or [g.rng.choice("xyz")]
    return [g.word(a.upper(), _value(g, lo, hi)) for a in chosen]


def st_g10(g: Gen) -> None:
    """G10 L2 (sometimes with R) or L20 of any system, the active one often."""
    level = g.rng.choice(["2", "2", "2", "20"])
    p = g.rng.choice([0, 0, 1, 1, 1, 2, g.rng.randint(3, 9)])
    words = _offset_words(g)
    if level == "2" and g.rng.random() < 0.4:
        angle = g.rng.choice([g.rng.uniform(-180, 180), g.rng.choice([90, -90, 180, 45, 30])])
        words.append(g.word("R", g.num(angle, g.rng.choice([0, 2, 5]))))
    g.emit(g.words("G10", g.word("L", level), g.word("P", str(p)), *words))
    g.pos = None


def st_g52_g92(g: Gen) -> None:
    code = g.rng.choice(["52", "92", "92", "92.1", "92.2", "92.3"])
    words = _offset_words(g) if code in ("52", "92") else []
    g.emit(g.words(g.g(code), *words))
    g.pos = None


def _start(g: Gen) -> None:
    """Known position: all three axes, absolute."""
    if not g.absolute:
        g.emit(g.words(g.g("90")))
        g.absolute = True
    end = {a: _number(g, -40, 40) for a in "xyz"}
    g.emit(g.words(g.g("0"), *(g.word(a.upper(), g.num(end[a], PLACES)) for a in "xyz")))
    g.motion = "0"
    g.pos = end


def st_moves(g: Gen) -> None:
    """Traverses and feeds to five-decimal points, absolute or incremental."""
    if g.pos is None:
        _start(g)
    for _ in range(g.rng.randint(1, 5)):
        code = g.rng.choice(["0", "1", "1"])
        axes = [a for a in "xyz" if g.rng.random() < 0.6] or ["x"]
        words = []
        for a in axes:
            v = _number(g, -40, 40)
            words.append(g.word(a.upper(), g.num(v, PLACES)))
            g.pos[a] = v if g.absolute else round(g.pos[a] + v, 9)
        f = g.feed_word() if code == "1" else None
        lead = g.g(code) if g.motion != code or g.rng.random() < 0.5 else None
        g.emit(g.words(lead, *words, f))
        g.motion = code


def st_arc(g: Gen) -> None:
    """An arc with five-decimal centre offsets and end (or R), in the current plane."""
    if g.pos is None:
        _start(g)
    a1, a2, l1, l2 = PLANES[g.plane]
    scale = 1 / 25.4 if not g.metric else 1.0
    i = round(g.rng.uniform(-12, 12) * scale, PLACES)
    j = round(g.rng.uniform(-12, 12) * scale, PLACES)
    if math.hypot(i, j) < 1 * scale:
        i = round(2 * scale, PLACES)
    r = math.hypot(i, j)
    ca, cb = g.pos[a1] + i, g.pos[a2] + j
    ang = math.atan2(-j, -i) + g.rng.uniform(0.3, 2 * math.pi - 0.3)
    end = {a1: round(ca + r * math.cos(ang), PLACES), a2: round(cb + r * math.sin(ang), PLACES)}
    if g.absolute:
        ends = [g.word(a.upper(), g.num(end[a], PLACES)) for a in (a1, a2)]
    else:
        ends = [g.word(a.upper(), g.num(end[a] - g.pos[a], PLACES)) for a in (a1, a2)]
    if g.rng.random() < 0.3:
        chord = math.hypot(end[a1] - g.pos[a1], end[a2] - g.pos[a2])
        if chord < 0.01:
            return
        centre = [g.word("R", g.num(round(chord / 2 * g.rng.uniform(1.05, 3), PLACES), PLACES))]
    elif g.arc_absolute:
        centre = [g.word(l1.upper(), g.num(ca, PLACES)), g.word(l2.upper(), g.num(cb, PLACES))]
    else:
        centre = [g.word(l1.upper(), g.num(i, PLACES)), g.word(l2.upper(), g.num(j, PLACES))]
    code = g.rng.choice(["2", "3"])
    g.emit(g.words(g.g(code), *ends, *centre, g.feed_word()))
    g.motion = code
    g.pos.update(end)


STATEMENTS = [(6, st_g10), (5, st_g52_g92), (14, st_moves), (8, st_arc)]
