"""Drilling cycles (G73, G81, G82, G83, G85, G86, G89) along the drill vector (G107).

Levels are positions along the drill vector's direction, which points out of the hole: the level
of a point is its projection on that direction.  A cycle's axes give the hole (its position across
the drill vector) and its bottom (the level of that point); R is the retract level, Q the peck, P
the dwell.  R, Q, P and the bottom are kept for the next cycle until G80.  As LinuxCNC's cycles
do: if the tool is below R it first rises to R; it crosses at the higher of its level and R, goes
down to R at rapid and then cuts; in G91 R is from the start's level and the bottom from R.  The
seed has no G98/G99: every cycle ends at R.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator

from .motion import check_seconds, need_feed, set_feed, straight
from .reading import Clauses, single
from .state import AXIS, Dwell, Engine, EngineError, ModeChange, Op, Stop

# the clearance of a peck: how far G73 backs off, and how far above the last depth G83 comes
# back down at rapid (LinuxCNC's default 0.010 in)
PECK_CLEARANCE = 0.254

WHAT = {73: "G73 (chip breaking drill)", 81: "G81 (drill)", 82: "G82 (drill, dwell)",
        83: "G83 (chip clearing drill)", 85: "G85 (drill, feed out)",
        86: "G86 (drill, dwell, spindle off, out)", 89: "G89 (drill, dwell, feed out)"}
_DWELLS = {82, 86, 89}
_PECKS = {73, 83}


def drill(eng: Engine, line: int, code: int, clauses: Clauses) -> Iterator[Op]:
    """One drilling cycle at the hole the line names."""
    what = WHAT[code]
    vec = eng.vectors[eng.drill]
    norm = math.sqrt(sum(v * v for v in vec))
    if norm == 0.0:
        raise EngineError(f"{what}: the drill vector {eng.drill} is zero")
    d = [v / norm for v in vec]

    def level(p: list[float]) -> float:
        return sum(pi * di for pi, di in zip(p, d, strict=True))

    prog = eng.program()
    hole = list(prog)
    deep = False
    cycle = eng.cycle
    ops: list[Op] = []
    for ref, values in clauses:
        v = single(ref, values, what)
        if ref == "F":
            ops.append(set_feed(eng, line, v))
        elif ref in AXIS:
            k = AXIS[ref]
            hole[k] = v * eng.unit(k) + (0.0 if eng.absolute else prog[k])
            deep = deep or d[k] != 0.0
        elif ref == "R":
            r = v * eng.length_unit
            cycle.retract = r if eng.absolute else level(prog) + r
        elif ref == "Q":
            if v <= 0.0:
                raise EngineError(f"{what}: Q (the peck) must be positive")
            cycle.peck = v * eng.length_unit
        elif ref == "P":
            if v < 0.0:
                raise EngineError(f"{what}: P (the dwell) must not be negative")
            check_seconds(v, f"{what}: P (the dwell)")
            cycle.dwell = v
        else:
            raise EngineError(f"{ref} is not a word of {what}")
    yield from ops
    if cycle.retract is None:
        raise EngineError(f"{what} needs R (the retract level)")
    if deep:
        cycle.bottom = level(hole) if eng.absolute else (
            cycle.retract + level(hole) - level(prog))
    elif cycle.bottom is None:
        raise EngineError(f"{what} needs the bottom of the hole: a position on the drill "
                          f"vector's axes")
    if cycle.bottom > cycle.retract:
        raise EngineError(f"{what}: the bottom of the hole is above R")
    if code in _PECKS and cycle.peck is None:
        raise EngineError(f"{what} needs Q (the peck)")
    if code in _DWELLS and cycle.dwell is None:
        raise EngineError(f"{what} needs P (the dwell)")
    need_feed(eng, what)
    offsets = eng.offsets()
    across = level(hole)

    def at(s: float) -> list[float]:
        """The machine position on the hole's axis at level ``s``."""
        return [h + (s - across) * di + o for h, di, o in zip(hole, d, offsets, strict=True)]

    r, bottom = cycle.retract, cycle.bottom
    start = level(prog)
    if start < r:
        yield from straight(eng, line, [p + (r - start) * di + o
                                        for p, di, o in zip(prog, d, offsets, strict=True)],
                            "rapid")
    yield from straight(eng, line, at(max(start, r)), "rapid")
    yield from straight(eng, line, at(r), "rapid")
    if code in _PECKS:
        assert cycle.peck is not None
        yield from _pecks(eng, line, code, at, r, bottom, cycle.peck)
    else:
        yield from straight(eng, line, at(bottom), "feed")
        if code in _DWELLS:
            assert cycle.dwell is not None
            yield Dwell(line, cycle.dwell)
        if code == 86:
            yield ModeChange(line, "SPINDLE", "off")
        yield from straight(eng, line, at(r), "feed" if code in (85, 89) else "rapid")
        if code == 86:
            yield ModeChange(line, "SPINDLE", "on")
    if eng.exact:
        yield Stop(line)


def _pecks(eng: Engine, line: int, code: int, at: Callable[[float], list[float]], r: float,
           bottom: float, peck: float) -> Iterator[Op]:
    """G73: feed a peck deeper, back off by the clearance, again; G83: feed a peck deeper, out to
    R, back down at rapid to the clearance above the last depth, again.  Then out to R."""
    depth = r
    while depth > bottom:
        eng.work()  # (Q sets how many pecks there are)
        if code == 83 and depth < r:
            yield from straight(eng, line, at(depth + PECK_CLEARANCE), "rapid")
        depth = max(bottom, depth - peck)
        yield from straight(eng, line, at(depth), "feed")
        if depth > bottom:
            yield from straight(eng, line, at(depth + PECK_CLEARANCE if code == 73 else r),
                                "rapid")
    yield from straight(eng, line, at(r), "rapid")
