"""The spindle: the $ word (which spindle), G96 / G97 speed modes, S, M3 / M4 / M5, M19 orient.

The standalone machine has one spindle (rs274's ``num_spindles`` is 1 without an INI that says
otherwise), so ``$`` picks spindle 0, or -1 "every spindle" where rs274 allows it.  rs274 reads
``$`` as a real and takes its integer part (``$0.9`` is spindle 0, ``$-1.5`` is -1).  Messages and
canon calls are rs274's (verified against rs274 2.9.0~pre1):

* G96 [D max rpm] S surface speed: ``SET_SPINDLE_MODE(n max)``, max the D word's magnitude, or
  1e30 without D (D is not sticky); G97: ``SET_SPINDLE_MODE(n 0)``.  They run before the feed
  mode (so before F and S).  $ must be 0 ("Invalid spindle ($) number in Spindle Mode command").
* S: $ from -1 to 0 ("Invalid spindle ($) number in Spindle speed command").
* M3 / M4 / M5: $ from -1 to 0, else a three-line report naming ``num_spindles`` and ``$``.
* M19 [R angle] [Q seconds] [P direction]: R and P are checked before the line runs (P a whole
  number within 0.001, 0 to 2; R 0 to 360); at its step $ must be 0; with R or P, the orient
  call (R plus [RS274NGC]ORIENT_OFFSET, P's integer part); with Q, the wait, Q above 0 (checked
  after the orient call is made).
* M51 takes no $ at all in rs274 ("Invalid spindle ($) number in M51 command").
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from types import MappingProxyType
from typing import TYPE_CHECKING

from ...canon import ops
from ...errors import NgcSemanticError

if TYPE_CHECKING:
    from ..machine import Machine

SPINDLES = 1  # rs274's num_spindles on the standalone machine
ALL = -1  # $-1: every spindle (S, M3, M4, M5)
CSS_UNLIMITED = 1e30  # G96 without D: no maximum speed
_P_INTEGER_TOLERANCE = 0.001  # M19 and G2/G3 P: how far from a whole number rs274 lets it be
_ORIENT_DIRECTIONS = (0, 1, 2)  # M19 P: shortest way, clockwise, counterclockwise
_M_NAMES = MappingProxyType({3: "M3", 4: "M4", 5: "M5"})
# M3 / M4 / M5: the state's direction (1 clockwise, -1 counterclockwise, 0 stopped), the call
_TURNS: Mapping[int, tuple[int, Callable[[int], ops.Op]]] = MappingProxyType({
    3: (1, ops.StartSpindleClockwise),
    4: (-1, ops.StartSpindleCounterclockwise),
    5: (0, ops.StopSpindleTurning),
})


def number(w: dict[str, float]) -> int:
    """The spindle the line's $ word names (0 without one): its integer part, as rs274 reads it."""
    return int(w.get("$", 0.0))


def spindles(n: int) -> range:
    """The spindles ``n`` stands for (-1: all)."""
    return range(SPINDLES) if n == ALL else range(n, n + 1)


def speed_mode(it: Machine, w: dict[str, float], code: int) -> None:
    """G96 constant surface speed (D: the maximum rpm) or G97 rpm mode."""
    n = number(w)
    if not 0 <= n < SPINDLES:
        raise NgcSemanticError("Invalid spindle ($) number in Spindle Mode command")
    st = it.state
    st.css = code == 960
    st.css_max = abs(w.get("d", CSS_UNLIMITED)) if st.css else 0.0
    it.emit(ops.SetSpindleMode(n, st.css_max))


def speed(it: Machine, w: dict[str, float]) -> None:
    """S (its sign is checked as the line is read)."""
    n = number(w)
    if not ALL <= n < SPINDLES:
        raise NgcSemanticError("Invalid spindle ($) number in Spindle speed command")
    s = w["s"]
    it.state.speed = s
    for k in spindles(n):
        it.emit(ops.SetSpindleSpeed(k, s))


def turn(it: Machine, w: dict[str, float], code: int) -> None:
    """M3 / M4 / M5."""
    n = number(w)
    if not ALL <= n < SPINDLES:
        raise NgcSemanticError(f"Spindle ($) number out of range in {_M_NAMES[code]} Command\n"
                               f"num_spindles ={SPINDLES}. $={n}\n")
    direction, call = _TURNS[code]
    it.state.spindle = direction
    for k in spindles(n):
        it.emit(call(k))


def check_whole_p(p: float) -> None:
    """M19's P, and an arc's P (its turns): a whole number to within 0.001, as rs274 allows."""
    if abs(p - round(p)) > _P_INTEGER_TOLERANCE:
        raise NgcSemanticError("P value not an integer with M19 G2 or G3")


def check_orient(w: dict[str, float]) -> None:
    """M19's P and R, checked before its line runs."""
    p = w.get("p")
    if p is not None:
        check_whole_p(p)
        if int(p) not in _ORIENT_DIRECTIONS:
            raise NgcSemanticError("P value must be 0,1,or 2 with M19")
    r = w.get("r")
    if r is not None and not 0.0 <= r <= 360.0:
        raise NgcSemanticError("R value must be within 0..360 with M19")


def orient(it: Machine, w: dict[str, float]) -> None:
    """M19: turn the spindle to angle R (plus the INI's offset) the P way; wait Q seconds."""
    n = number(w)
    if not 0 <= n < SPINDLES:
        raise NgcSemanticError("Spindle ($) number out of range in M19 Command")
    st = it.state
    st.spindle = 0  # orienting, the spindle no longer turns (G33, G84 ... refuse to run)
    if "r" in w or "p" in w:
        it.emit(ops.OrientSpindle(n, w.get("r", 0.0) + st.orient_offset, int(w.get("p", 0.0))))
    q = w.get("q")
    if q is not None:
        if q <= 0.0:
            raise NgcSemanticError("Q word with M19 requires a value > 0")
        it.emit(ops.WaitOrientComplete(n, q))


def check_override(w: dict[str, float]) -> None:
    """M51 with a $ word: rs274 refuses every spindle number there."""
    if "$" in w:
        raise NgcSemanticError("Invalid spindle ($) number in M51 command")
