"""Spindle-synchronized motion: G33 (one move at K per revolution) and G33.1 rigid tapping
(g-code.adoc, "G33 Spindle Synchronized Motion", "G33.1 Rigid Tapping").  Messages, order and
canon calls are rs274's (verified against rs274 2.9.0~pre1).

* Before the line runs: an axis word ("All axes missing with motion code"), then K ("K word
  missing with g33/g33.1"), then no F ("F word used with a g33/g33.1"): the feed follows from K.
* At the motion step: $ must be 0 ("Invalid spindle ($) number in G33 move"), the spindle must
  turn, either way ("Spindle not turning in G33").
* G33: ``START_SPEED_FEED_SYNC(K,0)``, the feed to the end, ``STOP_SPEED_FEED_SYNCH()``; any feed
  mode.  With cutter radius compensation on, G33 and G33.1 are a compensated G1 (no
  synchronization calls, no spindle checks), and refused as the entry move or out of the plane
  ("Bug code not g0 or g1").
* G33.1: ``RIGID_TAP(x, y, z)`` of the end between the same two calls; the tool comes back: the
  current point is the start again, but for the rotary axes, which stay at the end.  I (the
  return's speed multiplier) prints nothing.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from ...canon import ops
from ...errors import NgcSemanticError
from .. import comp
from . import spindle

if TYPE_CHECKING:
    from ..machine import Machine

G33 = 330
G33_1 = 331
SYNCHRONIZED = frozenset({G33, G33_1})
_NAMES = {G33: "G33", G33_1: "G33.1"}
NOT_G0_G1 = "Bug code not g0 or g1"


def check(w: dict[str, float]) -> None:
    """G33 / G33.1's words, before the line runs (after the axis words the table requires)."""
    if "k" not in w:
        raise NgcSemanticError("K word missing with g33/g33.1")
    if "f" in w:
        raise NgcSemanticError("F word used with a g33/g33.1")


def start(it: Machine, w: dict[str, float], code: int) -> int:
    """The motion step's checks: the spindle the move follows, which must turn."""
    n = spindle.number(w)
    if not 0 <= n < spindle.SPINDLES:
        raise NgcSemanticError(f"Invalid spindle ($) number in {_NAMES[code]} move")
    if it.state.spindle == 0:
        raise NgcSemanticError(f"Spindle not turning in {_NAMES[code]}")
    return n


def sync_feed(it: Machine, w: dict[str, float], end: list[float]) -> None:
    """G33 to ``end`` at K per revolution."""
    st = it.state
    st.motion = G33
    if _compensated(it, end):
        return
    start(it, w, G33)
    it.emit(ops.StartSpeedFeedSync(w["k"], 0))
    it.move(ops.StraightFeed, end, it.label, it.line)
    it.emit(ops.StopSpeedFeedSynch())
    st.pos = end


def rigid_tap(it: Machine, w: dict[str, float], end: list[float]) -> None:
    """G33.1 to ``end`` and back."""
    st = it.state
    st.motion = G33_1
    if _compensated(it, end):
        return
    start(it, w, G33_1)
    it.emit(ops.StartSpeedFeedSync(w["k"], 0))
    it.emit(ops.RigidTap(end[0], end[1], end[2]))
    it.emit(ops.StopSpeedFeedSynch())
    st.pos = [*st.pos[:3], *end[3:]]


def _compensated(it: Machine, end: list[float]) -> bool:
    """With cutter radius compensation on (a tool of some radius), rs274 takes G33 and G33.1 for
    a compensated straight feed (no synchronization) or refuses them ("Bug code not g0 or g1"):
    as the entry move (after the entry's own check), and out of the plane.  True if it ran."""
    c = it.comp
    if c is None:
        return False
    if c.side == 0 or c.radius == 0.0:  # the exit move, or no radius: the held moves go first
        comp.flush(it)
        if c.side == 0:
            it.comp = None
        else:
            c.prog = end
            c.ca, c.cb = end[c.a], end[c.b]
        return False
    compensated_feed(it, end)
    return True


def compensated_feed(it: Machine, end: list[float], corner_refusal: str = "") -> None:
    """A spindle-synchronized move (G33, G33.1, G76) run as a compensated straight feed, with
    rs274's refusals: as the entry move (after the entry's own length check) and out of the plane
    ("Bug code not g0 or g1"); ``corner_refusal`` as in :func:`comp.straight`."""
    c = it.comp
    assert c is not None
    if c.first:
        if math.hypot(end[c.a] - c.ca, end[c.b] - c.cb) <= c.radius:
            raise NgcSemanticError(
                "Length of cutter compensation entry move is not greater than the tool radius")
        raise NgcSemanticError(NOT_G0_G1)
    if end[c.a] == c.prog[c.a] and end[c.b] == c.prog[c.b]:
        raise NgcSemanticError(NOT_G0_G1)
    comp.straight(it, ops.StraightFeed, end, corner_refusal=corner_refusal)
