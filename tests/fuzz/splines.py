"""Spline statements for the fuzzer (``gen.py`` builds the ``splines`` kind from them): G5 and
G5.1 curves and G5.2 ... G5.3 NURBS blocks among ordinary moves, and broken spline lines for
the ``failing`` kind.  The functions take gen.py's ``Gen`` (not imported: gen.py imports this)."""

from __future__ import annotations

from typing import Any

Gen = Any  # gen.Gen


def _ready(g: Gen) -> bool:
    """XY plane, a known position and a feed the curve can use; False if not now."""
    if g.comp_on or g.pos is None:
        return False
    if g.plane != "17":
        g.emit(g.words(g.g("17")))
        g.plane = "17"
    return True


def _end(g: Gen) -> dict[str, float]:
    assert g.pos is not None
    return {a: round(g.pos[a] + g.coord(-15, 15), 3) for a in "xy"}


def _offset(g: Gen, letter: str) -> str:
    return g.word(letter, g.num(g.coord(-8, 8)))


def st_g5(g: Gen) -> None:
    """G5 curves, the first with I J, the next ones with or without."""
    if not _ready(g):
        return
    for k in range(g.rng.randint(1, 4)):
        end = _end(g)
        axes = g.axis_words(end, "xy" if g.rng.random() < 0.9 else g.rng.choice("xy"))
        ij = [_offset(g, "I"), _offset(g, "J")] if k == 0 or g.rng.random() < 0.4 else []
        f = g.feed_word(force=k == 0 and g.feed == 0)
        words = [g.g("5"), *axes, *ij, _offset(g, "P"), _offset(g, "Q"), f]
        g.rng.shuffle(words)
        g.emit(g.words(*words))
        g.move_to(end)


def st_g51(g: Gen) -> None:
    """G5.1 curves."""
    if not _ready(g):
        return
    for k in range(g.rng.randint(1, 4)):
        end = _end(g)
        f = g.feed_word(force=k == 0 and g.feed == 0)
        g.emit(g.words("G5.1", *g.axis_words(end, "xy"), _offset(g, "I"), _offset(g, "J"), f))
        g.move_to(end)


def st_nurbs(g: Gen) -> None:
    """A G5.2 ... G5.3 block: a start weight or a first point, weighted points, now and then an
    order, a comment, a feed or a Z on a line; then G5.3."""
    if not _ready(g):
        return
    assert g.pos is not None
    f = g.feed_word(force=g.feed == 0)
    first: list[str | None] = ["G5.2", f]
    if g.rng.random() < 0.4:
        first.append(g.word("P", g.num(g.rng.uniform(0.2, 3), 2)))
    last = dict(g.pos)
    if g.rng.random() < 0.6:
        last = {**g.pos, **_end(g)}
        first += g.axis_words(last, "xy")
    points = g.rng.randint(3, 8)
    order = 3
    if g.rng.random() < 0.3:
        order = g.rng.randint(1, points)
        first.append(g.word("L", str(order)))
    g.emit(g.words(*first))
    for _ in range(points - 1):
        if g.rng.random() < 0.1:
            g.emit(g.comment())
        last = {**g.pos, **_end(g)}
        words = [*g.axis_words(last, "xy"), g.word("P", g.num(g.rng.uniform(0.1, 4), 3))]
        if g.rng.random() < 0.08:
            words.append(g.word("Z", g.num(g.coord(-5, 5))))
        if g.rng.random() < 0.1:
            words.append(g.word("L", str(g.rng.randint(1, points))))
        g.emit(g.words(*words))
    g.emit(g.words("G5.3"))
    g.move_to({"x": last["x"], "y": last["y"]})
    g.motion = "5.3"


STATEMENTS = [(6, st_g5), (5, st_g51), (6, st_nurbs)]

BROKEN = ["G5 X1 Y1 P1", "G5 X1 Y1 I1 P1 Q1", "G5 X1 Z1 I1 J1 P1 Q1", "G5 I1 J1 P1 Q1",
          "G18\nG5 X1 Y1 I1 J1 P1 Q1", "G19 G5.1 X1 Y1 I1 J1", "G5.1 X1 Y1 I1", "G5.1 X2 I1 J1 P1",
          "G5.3", "G5.3 X1", "G5.2 X1 P1", "G5.2 X1 Y1\nX2 Y2\nG5.3", "G5.2 X1 Y1\nG5.3",
          "G5.2 L5 X1 Y1\nX2 Y2 P1\nG5.3", "G5.2 X1 Y1\nZ1 P1\nG5.3", "G5.2 X1 Y1\nX2 Y2 P0\nG5.3",
          "G5.2 X1 Y1\nX2 Y2 P1\nG5.3 X3", "F0\nG5.2 X1 Y1", "G5.2 X1 Y1\nX2 Y2 P1\nX3 Y3 P1\nG5.3\nX1",
          "G93 G5 X1 Y1 I1 J1 P1 Q1", "G5.2 X1 Y1 Q1", "G5.2 X1 Y1\nX2 Y2 P1\nG0 X0\nG5.3"]


def mu_bad_spline(g: Gen, lines: list[str]) -> None:
    """A broken spline line (or block) somewhere in the middle."""
    lo = min(3, len(lines) - 1)
    lines.insert(g.rng.randint(lo, max(lo, len(lines) - 2)), g.rng.choice(BROKEN))
