"""Statements of the ``probe`` kind: straight probes G38.2-G38.5 among the ``motion`` statements.

``st_probe`` probes from the current point along one to three axes (now and then with A, in
G91, with the F word on the line, repeated by axis words alone), prints #5061-#5070 and the
current point, and keeps the generator's current point as rs274's machine leaves it: 0.01 inch
(0.254 mm) back from the programmed point toward the start.  About one probe in 25 is refused:
a zero length (G38.2 / G38.4), G93 or G95, no axis word.  ``st_probe_grid`` is a pcb2gcode-style
height probe: a subroutine that lifts, moves over a point and probes down, called in two nested
while loops over a grid, each result printed.  ``mu_probe`` (for ``failing``) inserts a broken
probe line.

The functions take the generator's ``Gen`` (gen.py imports this module).
"""

from __future__ import annotations

import math
from typing import Any

PROBES = ["38.2", "38.3", "38.4", "38.5"]
RESULTS = "(debug, probe #5061 #5062 #5063 #5064 #5070 at #<_x> #<_y> #<_z> #<_a>)"


def _known_point(g: Any) -> None:
    """An absolute traverse to a point on every axis, so that the position is known."""
    if not g.absolute:
        g.emit(g.words(g.g("90")))
        g.absolute = True
    end = {a: g.coord(-40, 40) if a != "z" else g.coord(0, 25) for a in "xyz"}
    g.emit(g.words(g.g("0"), *g.axis_words(end)))
    g.motion = "0"
    g.pos = end


def _feed_ready(g: Any) -> str | None:
    """Units per minute and a feed rate: the F word to put on the probe line, if any."""
    if g.feed_mode != "94":
        g.emit(g.words(g.g("94")))
        g.feed_mode = "94"
        g.feed = 0.0
    force = g.feed == 0.0 or g.rng.random() < 0.15
    return g.feed_word(force=force)


def _backoff(g: Any, start: dict[str, float], end: dict[str, float]) -> dict[str, float]:
    d = {a: start[a] - end[a] for a in "xyz"}
    dist = math.sqrt(sum(v * v for v in d.values()))
    if dist == 0.0:
        return dict(end)
    back = 0.254 if g.metric else 0.01
    return {a: end[a] + back * d[a] / dist for a in "xyz"}


def _probe_line(g: Any, code: str, first: bool) -> None:
    assert g.pos is not None
    axes = "".join(a for a in "xyz" if g.rng.random() < 0.45) or g.rng.choice("xyz")
    end = dict(g.pos)
    for a in axes:
        end[a] = round(g.pos[a] + g.coord(-20, 20), 3)
    if g.rng.random() < 0.03:
        end = dict(g.pos)  # no length: G38.2 / G38.4 refuse it, G38.3 / G38.5 run it
    f = _feed_ready(g) if first else None
    extra = []
    if g.rng.random() < 0.05:
        extra.append(g.word("A", g.num(g.rng.uniform(-90, 90), 2)))
    name = g.g(code) if first or g.rng.random() < 0.3 else None
    g.emit(g.words(name, *g.axis_words(end, only=axes), *extra, f))
    g.motion = code
    g.pos = _backoff(g, g.pos, end)


def st_probe(g: Any) -> None:
    """One probe, sometimes repeated by axis words alone, and its results."""
    if g.comp_on:
        return
    if g.pos is None:
        _known_point(g)
    if g.rng.random() < 0.03:
        broken = g.rng.choice([f"G{g.rng.choice(PROBES)}", "G93 G38.2 Z-1", "G95 G38.3 X1 F1",
                               "F0 G38.4 Y1", "G38.5 F10"])
        g.emit(broken)
        return
    if g.rng.random() < 0.15:
        g.absolute = g.rng.random() < 0.5
        g.emit(g.words(g.g("90" if g.absolute else "91")))
    code = g.rng.choice(PROBES)
    _probe_line(g, code, True)
    for _ in range(g.rng.choice([0, 0, 0, 1, 2])):
        _probe_line(g, code, False)
    if g.rng.random() < 0.7:
        g.emit(RESULTS, numbered=False)
    if g.rng.random() < 0.3:
        g.emit(g.words("#<depth>=#5063", "#<hit>=#5070"))
        g.emit("(print, depth #<depth> hit #<hit>)", numbered=False)


def st_probe_grid(g: Any) -> None:
    """A pcb2gcode-style grid of probes down, from a subroutine in nested while loops."""
    if g.comp_on:
        return
    if g.pos is None:
        _known_point(g)
    if not g.absolute:
        g.emit(g.words(g.g("90")))
        g.absolute = True
    f = _feed_ready(g)
    if f is not None:
        g.emit(f)
    label = g.labels
    g.labels += 3
    safe = g.coord(2, 10)
    depth = -g.coord(1, 5)
    x0, y0 = g.coord(-30, 0), g.coord(-30, 0)
    dx, dy = g.coord(2, 15), g.coord(2, 15)
    nx, ny = g.rng.randint(1, 4), g.rng.randint(1, 3)
    code = g.rng.choice(["38.2", "38.2", "38.3"])
    sub = f"o<probe{label}>"
    for line in [
        f"{sub} sub",
        "  G0 Z#3",
        "  G0 X#1 Y#2",
        f"  G{code} Z#4",
        "  #<_probed> = #5063",
        "  G0 Z#3",
        f"{sub} endsub",
        "#100 = 0",
        f"o{label + 1} while [#100 lt {nx}]",
        "  #101 = 0",
        f"  o{label + 2} while [#101 lt {ny}]",
        f"    {sub} call [{g.num(x0)} + #100 * {g.num(dx)}] [{g.num(y0)} + #101 * {g.num(dy)}]"
        f" [{g.num(safe)}] [{g.num(depth)}]",
        "    (debug, #100 #101 #<_probed> #5070 #<_x> #<_y> #<_z>)",
        "    #101 = [#101 + 1]",
        f"  o{label + 2} endwhile",
        "  #100 = [#100 + 1]",
        f"o{label + 1} endwhile",
    ]:
        g.emit(line, numbered=False)
    g.motion = "0"
    g.pos = None


def mu_probe(g: Any, lines: list[str]) -> None:
    """A broken probe line: no axis, zero feed, G95, G93, no length."""
    text = g.rng.choice(["G38.2", "G38.3 F5", "F0 G38.2 Z-1", "G95 F1 G38.2 Z-1", "G93 G38.4 X1",
                         "G38.2 X[#5420] Y[#5421] Z[#5422] A[#5423] B[#5424] C[#5425] F10",
                         "G38.2 Z-1 R1", "G38.5 G1 X1", "G53 G38.2 Z-1"])
    lines.insert(min(3, len(lines) - 1) + g.rng.randint(0, max(0, len(lines) - 5)), text)
