"""Splines: G5 (cubic), G5.1 (quadratic) and the G5.2 ... G5.3 NURBS block (g-code.adoc, "G5",
"G5.1", "G5.2 G5.3"), as rs274 runs them.

Each curve is one canonical :class:`~ngc.canon.ops.NurbsFeed` from the current point, which
carries the whole curve (control points, weights, order, knots); rs274 prints only the number of
control points.  What rs274 does, as it shows it:

* G5 and G5.1 do not change the motion mode (a line of axis words after them runs the mode
  before them), but a canned cycle after them starts a new series, from the current level.
  Checks, in this order: cutter compensation on ("Cannot convert spline ..."), the feed
  (inverse time: an F word on the line; units per minute: a rate not zero; units per
  revolution: none), the XY plane, no Z A B C word (even one that does not move), then G5: P and
  Q both, I and J both or neither; G5.1: I and J both.  The control points: G5, the start, the
  start plus I J, the end plus P Q, the end (no I J: the start less the last G5's P Q, so that
  the curve goes on smoothly); G5.1, the start, the start plus I J, the end.
* G5.2 opens a block: its line and the lines after it (the motion mode is G5.2) each give a
  control point X Y (both, or neither), with its weight P, after the current point, which stays
  where it is until G5.3 (in G91 every point is relative to it).  On the first line P may come
  without X Y (the start's weight), or be anything; on the next lines each point needs a P above
  0.  Then the feed: not zero in units per minute.  An L above 3 on any line is the order (3 if
  none).  Any other motion abandons the block.
* G5.3 needs the motion mode G5.2 and at least as many points as the order; it feeds along the
  curve to the last point and leaves the motion mode none (``#<_motion_mode>`` -1).  Its line is
  checked as if the G5.3 were not on it (see ``interp/check.py``); then an X without a Y (or a
  Y without an X) on it is refused, after the curve ran.
* With compensation just turned off (G40), the curve is the exit move.  ngc refuses G5.2 and
  G5.3 while compensation is on (rs274 runs them, but drops the move compensation holds).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ...canon import ops
from ...errors import NgcSemanticError
from ...language.codes import G_NURBS_END, SPLINE_COMP
from .. import comp
from . import ccomp, motion

if TYPE_CHECKING:
    from ...language.words import Words
    from ..machine import Machine

G_NURBS = 52  # G5.2
DEFAULT_ORDER = 3
_BOTH_XY = "You must specify both X and Y coordinates for Control Points"
_WEIGHT = "Must specify positive weight P for every Control Point"
Point = tuple[float, float]


def cubic(it: Machine, r: Words, code: int) -> None:
    """G5 X Y [I J] P Q."""
    w = r.w
    _check_spline(it, w)
    if "p" not in w or "q" not in w:
        raise NgcSemanticError("Must specify both P and Q with G5")
    if ("i" in w) != ("j" in w):
        raise NgcSemanticError("Must specify both I and J, or neither")
    st = it.state
    start = _start(it)
    end = motion.end_point(it, w, False)
    if "i" in w:
        first = (start[0] + w["i"], start[1] + w["j"])
    else:
        first = (start[0] - st.spline_pq[0], start[1] - st.spline_pq[1])
    second = (end[0] + w["p"], end[1] + w["q"])
    st.spline_pq = (w["p"], w["q"])
    _feed(it, (start, first, second, (end[0], end[1])), (1.0,) * 4, 4, end)


def quadratic(it: Machine, r: Words, code: int) -> None:
    """G5.1 X Y I J."""
    w = r.w
    _check_spline(it, w)
    if "i" not in w or "j" not in w:
        raise NgcSemanticError("Must specify both I and J with G5.1")
    start = _start(it)
    end = motion.end_point(it, w, False)
    middle = (start[0] + w["i"], start[1] + w["j"])
    _feed(it, (start, middle, (end[0], end[1])), (1.0,) * 3, 3, end)


def _check_spline(it: Machine, w: dict[str, float]) -> None:
    """What G5 and G5.1 check first, in rs274's order."""
    ccomp.refuse(it, SPLINE_COMP)
    st = it.state
    if st.feed_mode == 930:
        if "f" not in w:
            raise NgcSemanticError("F word missing with inverse time arc move")
    elif st.feed_mode == 940 and st.feed == 0.0:
        raise NgcSemanticError("Cannot make arc with zero feed rate")
    if st.plane != 170:
        raise NgcSemanticError("Splines must be in the XY plane")
    if "z" in w or "a" in w or "b" in w or "c" in w:
        raise NgcSemanticError("Splines may not have motion in Z, A, B, or C")


def nurbs(it: Machine, r: Words, code: int) -> None:
    """A line of a G5.2 block (the G5.2 line, or a line of axis words in the G5.2 mode)."""
    _refuse_comp(it)
    st = it.state
    w = r.w
    first = st.motion != G_NURBS
    has_xy = "x" in w
    if has_xy != ("y" in w):
        raise NgcSemanticError(_BOTH_XY)
    p = w.get("p")
    if not first:
        if not has_xy:
            raise NgcSemanticError(
                _WEIGHT if p is None else "Can specify P without X and Y only for the first "
                "control point")
        if p is None or p <= 0.0:
            raise NgcSemanticError(_WEIGHT)
    if st.feed_mode == 940 and st.feed == 0.0:
        raise NgcSemanticError("Cannot make a NURBS with 0 feedrate")
    if first:
        sx, sy = _start(it)
        st.nurbs = [(sx, sy, 1.0 if p is None or has_xy else p)]
        st.nurbs_order = DEFAULT_ORDER
        st.motion = G_NURBS
    order = w.get("l", 0.0)
    if order > DEFAULT_ORDER:
        st.nurbs_order = int(order)
    if has_xy:
        end = motion.end_point(it, w, False)
        st.nurbs.append((end[0], end[1], 1.0 if p is None else p))


def nurbs_end(it: Machine, r: Words, code: int) -> None:
    """G5.3: the block's curve."""
    st = it.state
    if st.motion != G_NURBS:
        raise NgcSemanticError("Cannot use G5.3 without G5.2 first")
    _refuse_comp(it)
    points = st.nurbs
    if len(points) < st.nurbs_order:
        raise NgcSemanticError("You must specify a number of control points at least equal to "
                               f"the order L = {st.nurbs_order}")
    end = [points[-1][0], points[-1][1], *st.pos[2:]]
    _feed(it, tuple((x, y) for x, y, _ in points), tuple(weight for _, _, weight in points),
          st.nurbs_order, end)
    st.nurbs = []
    st.motion = G_NURBS_END
    if ("x" in r.w) != ("y" in r.w):
        raise NgcSemanticError(_BOTH_XY)


def _refuse_comp(it: Machine) -> None:
    if ccomp.is_on(it):
        raise NgcSemanticError("G5.2 with cutter radius compensation on is not supported yet")


def _start(it: Machine) -> Point:
    """Where the curve starts: the current point (just after G40, the compensated one)."""
    c = it.comp
    if c is not None and (c.a, c.b) == (0, 1):
        return c.ca, c.cb
    pos = it.state.pos
    return pos[0], pos[1]


def _feed(it: Machine, points: tuple[Point, ...], weights: tuple[float, ...], order: int,
          end: list[float]) -> None:
    """Emit the curve (as the exit move if compensation was just turned off); ``end`` is the new
    current point."""
    if it.comp is not None:
        comp.flush(it)
        it.comp = None
    count = len(points)
    it.emit(ops.NurbsFeed(count, order, points, weights, knots(count, order)))
    st = it.state
    st.pos = end
    st.cycle_code = -1  # a canned cycle after it starts a new series (at the current level)


def knots(count: int, order: int) -> tuple[float, ...]:
    """The clamped uniform knot vector of ``count`` control points and ``order``: ``order``
    zeros, then 1, 2, ... and ``order`` times the last.

    >>> knots(4, 4)
    (0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0)
    >>> knots(5, 3)
    (0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 3.0)
    """
    last = max(count - order + 1, 0)
    return tuple(float(min(max(i - order + 1, 0), last)) for i in range(count + order))
