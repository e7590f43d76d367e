"""Straight probes: G38.2, G38.3 (toward the work, stop on contact), G38.4, G38.5 (away from it,
stop on loss of contact) (g-code.adoc "G38.n Straight Probe").

What rs274 does, as its output shows (2.9.0~pre1):

* Refusals, in this order: cutter radius compensation on ("Cannot probe with cutter radius comp
  on"), a zero feed rate (in G93 too: an F word there sets no rate), G95 ("Cannot probe with feed
  per rev mode"), a programmed point equal to the current one on every axis ("Start point too
  close to probe point"; G38.3 and G38.5 allow it).  No axis word is "All axes missing with
  motion code" (the code table's check).
* The canon: ``TURN_PROBE_ON()``, ``STRAIGHT_PROBE(programmed point)``, ``TURN_PROBE_OFF()``.
* Its standalone probe never trips: #5070 is 0 and #5061-#5066 are the programmed point,
  #5067-#5069 (U V W) 0.  The machine stops back from the programmed point by 0.01 inch (0.254 mm),
  toward where the canon's move started, along X Y Z only; the interpreter takes that point as
  its current point (the canon's start is the last move's end, which a tool length offset or
  rotation change since then did not move, and which compensation just turned off left at the
  compensated point).  A probe of no length in X Y Z stops at the programmed point.

With a simulated probe (:class:`ngc.config.probe.Probe`, ``ngc canon --probe``; never ``ngc rs274``), the move
stops where the probe's state changes: there the current point and #5061-#5069 are, #5070 is 1
and the probe log (``(PROBEOPEN name)``) gets a line.  A probe that does not trip ends at the
programmed point with #5070 0, except that G38.2 and G38.4 then stop the program, as LinuxCNC's
motion controller does; so does a probe already in the state it waits for.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING

from ...canon import ops
from ...errors import NgcSemanticError
from .. import comp
from ..frames import to_machine
from ..state import AXES, LINEAR, MM_PER_INCH
from . import ccomp, logfile, motion

if TYPE_CHECKING:
    from ...config.probe import Probe
    from ...language.words import Words
    from ..machine import Machine
    from ..state import State

PROBE_RESULT = 5061  # #5061-#5069: X Y Z A B C U V W of the probe; #5070: 1 if it tripped
PROBE_TRIPPED = 5070
# How far rs274's standalone machine stops short of the programmed point.
BACKOFF_MM = 0.254
BACKOFF_INCH = 0.01

_ON = ops.TurnProbeOn()
_OFF = ops.TurnProbeOff()


def straight_probe(it: Machine, r: Words, code: int) -> None:
    """G38.2 / G38.3 / G38.4 / G38.5 axes."""
    st = it.state
    ccomp.refuse(it, "Cannot probe with cutter radius comp on")
    if st.feed == 0.0:
        raise NgcSemanticError("Cannot probe with zero feed rate")
    if st.feed_mode == 950:
        raise NgcSemanticError("Cannot probe with feed per rev mode")
    end = motion.end_point(it, r.w, False)
    if end == st.pos and code in (382, 384):
        raise NgcSemanticError("Start point too close to probe point")
    start = _canon_start(it)
    simulated = it.probe
    result = None if simulated is None else _simulate(st, simulated, code, start, end)
    if it.comp is not None:  # just turned off: nothing is held then, but keep the order
        comp.flush(it)
        it.comp = None
    it.emit(_ON)
    it.emit(ops.StraightProbe(*end))
    it.emit(_OFF)
    st.motion = code
    st.canon_pos = st.canon_anchor = None
    if result is None:
        _standalone(it, start, end)
    else:
        _finish(it, *result)


def _canon_start(it: Machine) -> list[float]:
    """Where the canon's move starts, in program coordinates: the current point, unless a tool
    length offset or rotation change moved that and not the canon's (see tools.hold_canon), or
    compensation just turned off (the canon is at the compensated point)."""
    st = it.state
    if st.canon_pos is not None and st.canon_anchor is st.pos:
        metric = st.metric
        start = [(v if metric or not LINEAR[i] else v / MM_PER_INCH) - st.g5x[i] - st.g92[i]
                 for i, v in enumerate(st.canon_pos)]
    else:
        start = list(st.pos)
    c = it.comp
    if c is not None:
        start[c.a] = c.ca
        start[c.b] = c.cb
    return start


def _standalone(it: Machine, start: list[float], end: list[float]) -> None:
    """rs274's probe, which never trips: back off from the programmed point (module docstring)."""
    st = it.state
    stop = list(end)
    dx, dy, dz = (start[i] - end[i] for i in range(3))
    distance = math.sqrt(dx * dx + dy * dy + dz * dz)
    if distance != 0.0:
        backoff = BACKOFF_MM if st.metric else BACKOFF_INCH
        stop[0] = end[0] + backoff * dx / distance
        stop[1] = end[1] + backoff * dy / distance
        stop[2] = end[2] + backoff * dz / distance
    st.pos = stop
    _results(it, end, tripped=False)


def _results(it: Machine, point: Sequence[float], tripped: bool) -> None:
    numbered = it.params.numbered
    for i in range(AXES):
        numbered[PROBE_RESULT + i] = point[i]
    for i in range(AXES, 9):  # U V W
        numbered[PROBE_RESULT + i] = 0.0
    numbered[PROBE_TRIPPED] = 1.0 if tripped else 0.0


# -- a simulated probe ------------------------------------------------------------------------------
_WAITS = {382: "G38.2 or G38.3", 383: "G38.2 or G38.3", 384: "G38.4 or G38.5", 385: "G38.4 or G38.5"}


def _simulate(
    st: State, probe: Probe, code: int, start: list[float], end: list[float],
) -> tuple[list[float], bool]:
    """Where the move stops and whether the probe tripped; raises what LinuxCNC's motion
    controller reports."""
    scale = 1.0 if st.metric else MM_PER_INCH
    start_mm = [v * scale for v in to_machine(st, start)[:3]]
    end_mm = [v * scale for v in to_machine(st, end)[:3]]
    touching, t = probe.first_change(start_mm, end_mm)
    toward = code in (382, 383)
    if touching == toward:
        state = "already tripped" if toward else "not tripped"
        raise NgcSemanticError(f"Probe is {state} when starting {_WAITS[code]} move")
    if t is None:
        if code == 382:
            raise NgcSemanticError("G38.2 move finished without making contact")
        if code == 384:
            raise NgcSemanticError("G38.4 move finished without breaking contact")
        return list(end), False
    return [s + t * (e - s) for s, e in zip(start, end, strict=True)], True


def _finish(it: Machine, point: list[float], tripped: bool) -> None:
    it.state.pos = point
    _results(it, point, tripped)
    if tripped:
        logfile.write_probe(it, [*point, 0.0, 0.0, 0.0])
