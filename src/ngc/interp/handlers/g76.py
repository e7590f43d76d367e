"""G76, the lathe threading cycle (g-code.adoc, "G76 Threading Cycle"), as rs274 2.9.0~pre1 runs
it (every rule below found by asking rs274).

Words: P pitch, Z the end of the drive line (X, Y: where the tool goes at the end), I the thread
peak's offset from the drive line (negative: an outside thread), J the first cut's depth, K the
full depth, R the depth degression (below 1 taken as 1), Q the compound slide angle (degrees), H
spring passes, E the taper length, L which ends are tapered (bit 1 the entry, bit 2 the exit),
$ the spindle.  In G7 (diameter mode) I, J and K are diameters.

* Before the line runs, after its axis word: "P word missing with G76" (P-1 counts as missing,
  and Q-1 as no Q), then "I J or K words missing with G76".
* At the motion step: $ must be 0 ("Invalid D-number in G76 cycle"), the spindle must turn, no
  A, B or C word; with cutter radius compensation on (a tool of no radius) the cycle is refused;
  I not 0, J above 0, K above J.  With a tool of some radius, rs274 takes G76 for a compensated
  straight feed to the end point, refused as the entry move, out of the plane or at an outside
  corner ("Bug code not g0 or g1").
* Passes: the n-th cuts at depth J * n ** (1 / R) while that depth's offset from the drive line
  is short of the full depth's (I - depth against I - K outside); then 1 + H passes at K.  Each
  pass is the full-depth pass moved back along the compound angle: in by a traverse (or, with an
  entry taper, a feed from the peak line E long), the cut synchronized at P per revolution (a
  taper at P times its slope's length per unit of Z), out by a traverse; feed override off for
  the pass.  At the end the tool goes to X Y Z by a traverse; the drive line is where it was.
  The shift along Z is the depth the cut's X offset gives back (its offset less I) times
  tan Q, added to the start and to the end less K tan Q, in that order: rs274's sums, which
  show at a tie of the fifth decimal and at Q90.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from ...canon import ops
from ...errors import NgcSemanticError
from .. import comp
from . import spindle, threading

if TYPE_CHECKING:
    from ..machine import Machine

G76 = 760
_ENTRY_TAPER = 1  # L bits
_EXIT_TAPER = 2
_DISABLE = ops.DisableFeedOverride()
_ENABLE = ops.EnableFeedOverride()
_STOP = ops.StopSpeedFeedSynch()
# rs274 takes a P or Q of exactly -1 for a word not given: P-1 is missing, Q-1 is no angle.
_ABSENT = -1.0


def check(w: dict[str, float]) -> None:
    """G76's words, before the line runs (after the axis word the table requires)."""
    if w.get("p", _ABSENT) == _ABSENT:
        raise NgcSemanticError("P word missing with G76")
    if "i" not in w or "j" not in w or "k" not in w:
        raise NgcSemanticError("I J or K words missing with G76")


def run(it: Machine, w: dict[str, float], end: list[float]) -> None:
    """G76 from the current point (the drive line's start) to ``end``."""
    st = it.state
    st.motion = G76
    c = it.comp
    if c is not None and c.radius != 0.0 and _compensated(it, end):
        return
    if spindle.number(w) != 0:
        raise NgcSemanticError("Invalid D-number in G76 cycle")
    if st.spindle == 0:
        raise NgcSemanticError("Chosen spindle (0) not turning in G76")
    if "a" in w or "b" in w or "c" in w:
        raise NgcSemanticError("Cannot move rotary axes with G76")
    if c is not None:
        if c.side != 0:
            raise NgcSemanticError(
                "Cannot use G76 threading cycle with cutter radius compensation on")
        it.comp = None  # the exit move of compensation: the cycle takes its place
    half = 0.5 if st.lathe_diameter else 1.0
    i, j, k = w["i"] * half, w["j"] * half, w["k"] * half
    if i == 0.0:
        raise NgcSemanticError("In G76, I must not be 0")
    if j <= 0.0:
        raise NgcSemanticError("In G76, J must be greater than 0")
    if k <= j:
        raise NgcSemanticError("In G76, K must be greater than J")
    _Cycle(it, w, end, i, k).cut(j, max(w.get("r", 1.0), 1.0), int(w.get("h", 0.0)))


class _Cycle:
    """One G76: the drive line, the thread's shape, and the passes' common moves."""

    __slots__ = (
        "entry",
        "exit",
        "full",
        "it",
        "k",
        "offset",
        "out",
        "peak",
        "pitch",
        "pos",
        "side",
        "tan",
        "taper",
        "taper_pitch",
        "z_dir",
        "z_end",
    )

    def __init__(self, it: Machine, w: dict[str, float], end: list[float], i: float,
                 k: float) -> None:
        pos = it.state.pos
        self.it = it
        self.pos = pos  # the drive line's start (and the Y, A, B, C every move keeps)
        self.out = end
        self.z_end = end[2]
        self.side = 1.0 if i > 0.0 else -1.0  # the way a deeper cut goes in X
        self.peak = i
        self.k = k
        self.full = i + self.side * k  # the full depth's offset from the drive line
        self.z_dir = 1.0 if end[2] > pos[2] else -1.0
        q = w.get("q", 0.0)
        self.tan = math.tan(math.radians(q if q != _ABSENT else 0.0))
        self.pitch = w["p"]
        taper = w.get("e", 0.0)
        lword = int(w.get("l", 0.0))
        self.taper = taper if taper > 0.0 else 0.0
        self.entry = bool(self.taper) and bool(lword & _ENTRY_TAPER)
        self.exit = bool(self.taper) and bool(lword & _EXIT_TAPER)
        self.taper_pitch = self.pitch * math.hypot(taper, k) / taper if self.taper else 0.0

    def cut(self, first: float, degression: float, spring: int) -> None:
        """The passes, then the move to the end point."""
        depth = first
        n = 1
        while abs(self.peak + self.side * depth) < abs(self.full):
            self.one_pass(depth)
            n += 1
            depth = first * math.pow(n, 1.0 / degression)
        for _ in range(spring + 1):
            self.one_pass(self.k)
        it = self.it
        it.emit(ops.StraightTraverse(*self.out))
        it.state.pos = self.out

    def one_pass(self, depth: float) -> None:
        it = self.it
        it.work()  # (J, K, R and H set how many passes there are)
        emit = it.emit
        pos = self.pos
        y, rest = pos[1], pos[3:]
        offset = self.peak + self.side * depth  # the cut's offset from the drive line
        x_cut = pos[0] + offset
        x_safe = x_cut - self.full
        # the compound angle's shift: by the depth as the offset gives it back (rs274's sums)
        z_dir, z_off = self.z_dir, abs(offset - self.peak) * self.tan
        z_start = pos[2] + z_dir * z_off
        z_stop = self.z_end - z_dir * (self.k * self.tan) + z_dir * z_off
        emit(ops.StraightTraverse(x_safe, y, z_start, *rest))
        if self.entry:
            emit(_DISABLE)
            emit(ops.StartSpeedFeedSync(self.taper_pitch, 0))
            emit(ops.StraightFeed(x_cut - self.side * self.k, y, z_start, *rest))
            emit(ops.StraightFeed(x_cut, y, z_start + z_dir * self.taper, *rest))
            emit(ops.StartSpeedFeedSync(self.pitch, 0))
        else:
            emit(ops.StraightTraverse(x_cut, y, z_start, *rest))
            emit(_DISABLE)
            emit(ops.StartSpeedFeedSync(self.pitch, 0))
        if self.exit:
            emit(ops.StraightFeed(x_cut, y, z_stop - z_dir * self.taper, *rest))
            emit(ops.StartSpeedFeedSync(self.taper_pitch, 0))
            emit(ops.StraightFeed(x_cut - self.side * self.k, y, z_stop, *rest))
        else:
            emit(ops.StraightFeed(x_cut, y, z_stop, *rest))
        emit(_STOP)
        emit(ops.StraightTraverse(x_safe, y, z_stop, *rest))
        emit(_ENABLE)


def _compensated(it: Machine, end: list[float]) -> bool:
    """With cutter radius compensation on and a tool of some radius, rs274 takes G76 for a
    compensated straight feed, or refuses it ("Bug code not g0 or g1"): as the entry move
    (after the entry's own check), out of the plane, and at an outside corner (after the held
    move goes out).  True if it ran; False for the exit move, which the cycle replaces."""
    c = it.comp
    assert c is not None
    if c.side == 0:
        comp.flush(it)
        return False
    threading.compensated_feed(it, end, corner_refusal=threading.NOT_G0_G1)
    return True
