"""Motion: G0, G1, G2, G3 (center and radius formats, full circles, P turns, helices, all planes),
G53 machine-coordinate moves and inverse-time feed (g-code.adoc, G0-G3, G53, G93).

Tolerances are LinuxCNC's, as rs274 shows them: a center-format arc may spiral if the end radius
differs from the start radius by at most ``CENTER_ARC_TOLERANCE`` or by at most 0.1 %, and never
by more than 100 times that absolute tolerance.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from ...canon import ops
from ...errors import NgcSemanticError
from ...numeric.glibc_hypot import hypot
from .. import comp, frames

if TYPE_CHECKING:
    from ..machine import Machine

CENTER_ARC_TOLERANCE_INCH = 2 * 0.001 * math.sqrt(2.0)
CENTER_ARC_TOLERANCE_MM = 2 * 0.01 * math.sqrt(2.0)
CENTER_ARC_RELATIVE_TOLERANCE = 0.001
RADIUS_TOLERANCE_INCH = 0.00005
RADIUS_TOLERANCE_MM = RADIUS_TOLERANCE_INCH * 25.4

# plane code -> (first axis, second axis, helix axis, center letters, forbidden letter, names)
PLANES: dict[int, tuple[int, int, int, str, str, str, str]] = {
    170: (0, 1, 2, "ij", "k", "xy", "XY"),
    180: (2, 0, 1, "ki", "j", "xz", "ZX"),
    190: (1, 2, 0, "jk", "i", "yz", "YZ"),
}


def end_point(it: Machine, w: dict[str, float], machine: bool) -> list[float]:
    """The block's target in program coordinates (G53: axis words are machine coordinates)."""
    st = it.state
    pos = st.pos if it.comp is None else it.comp.prog  # compensation: the programmed point
    if machine:
        given = {i: w[a] for i, a in enumerate("xyzabc") if a in w}
        return frames.machine_target(st, pos, given)
    if "@" in w or "^" in w:
        return polar_end(pos, w, st.absolute)
    if st.absolute:
        return [w.get("x", pos[0]), w.get("y", pos[1]), w.get("z", pos[2]),
                w.get("a", pos[3]), w.get("b", pos[4]), w.get("c", pos[5])]
    return relative_end(pos, w)


def polar_end(pos: list[float], w: dict[str, float], absolute: bool) -> list[float]:
    """@ distance and ^ angle (degrees) from the XY origin; in G91 both add to the current ones.

    As rs274 computes it, to the last bit (its signed zeros show it): the distance of a point is
    the C library's ``hypot`` (:mod:`ngc.numeric.glibc_hypot`), its angle ``atan2`` in radians, the ^
    angle is taken to radians alone.  In G91 an @ moves the point out along its angle first, and
    the ^ then turns that point (its distance and angle taken again)."""
    for letter in "xy":
        if letter in w:
            raise NgcSemanticError(f"Cannot specify both polar coordinate and {letter.upper()} word")
    x, y = pos[0], pos[1]
    at_origin = x == 0.0 and y == 0.0
    if absolute:
        if "^" not in w and at_origin:
            raise NgcSemanticError("Must specify angle in polar coordinate if at the origin")
        radius = w["@"] if "@" in w else hypot(x, y)
        x, y = _polar(radius, math.radians(w["^"]) if "^" in w else math.atan2(y, x))
    else:
        if at_origin:
            raise NgcSemanticError(
                "Incremental motion with polar coordinates is indeterminate when at the origin"
            )
        if "@" in w:
            x, y = _polar(hypot(x, y) + w["@"], math.atan2(y, x))
        if "^" in w:
            x, y = _polar(hypot(x, y), math.atan2(y, x) + math.radians(w["^"]))
    end = relative_end(pos, w) if not absolute else [
        pos[0], pos[1], w.get("z", pos[2]), w.get("a", pos[3]), w.get("b", pos[4]), w.get("c", pos[5])
    ]
    end[0], end[1] = x, y
    return end


def _polar(radius: float, angle: float) -> tuple[float, float]:
    return radius * math.cos(angle), radius * math.sin(angle)


def relative_end(pos: list[float], w: dict[str, float]) -> list[float]:
    """G91: axis words are distances from the current point."""
    end = list(pos)  # an axis not given keeps its value (a -0 stays -0, as in rs274)
    for i, letter in enumerate("xyzabc"):
        if letter in w:
            end[i] += w[letter]
    return end


def traverse(it: Machine, end: list[float]) -> None:
    if it.comp is not None:
        comp.straight(it, ops.StraightTraverse, end)
        return
    it.emit(ops.StraightTraverse(*end))
    it.state.pos = end


def feed(it: Machine, w: dict[str, float], end: list[float]) -> None:
    """G1."""
    st = it.state
    if st.feed_mode != 940 or st.feed == 0.0:
        check_feed(it, w, "g1")
        if st.feed_mode == 930:
            start = st.pos if it.comp is None else it.comp.prog  # the programmed move's length
            st.feed = _inverse_rate(w["f"], _line_length(start, end))  # #<_feed> reads it
            it.emit(ops.SetFeedRate(st.feed))
    if it.comp is not None:
        comp.straight(it, ops.StraightFeed, end)
        return
    it.move(ops.StraightFeed, end, it.label, it.line)
    st.pos = end


def check_feed(it: Machine, w: dict[str, float], name: str) -> None:
    """A straight feed ``name`` may run: a feed rate (an F word in G93), a spindle speed in G95."""
    st = it.state
    if st.feed_mode == 930:
        if "f" not in w:
            raise NgcSemanticError(f"F word missing with inverse time {name} move")
    elif st.feed_mode == 950:
        if st.feed == 0.0:
            raise NgcSemanticError(f"Cannot do {name} with zero feed rate")
        if st.speed == 0.0:
            raise NgcSemanticError("Cannot feed with zero spindle speed in feed per rev mode")
    elif st.feed == 0.0:
        raise NgcSemanticError(f"Cannot do {name} with zero feed rate")


def _line_length(a: list[float], b: list[float]) -> float:
    """As C computes it: a length too large for a double is infinite (its rate prints ``inf``)."""
    dx, dy, dz = b[0] - a[0], b[1] - a[1], b[2] - a[2]
    d = math.sqrt(dx * dx + dy * dy + dz * dz)
    if d == 0.0:
        da, db, dc = b[3] - a[3], b[4] - a[4], b[5] - a[5]
        d = math.sqrt(da * da + db * db + dc * dc)
    return d


def _inverse_rate(f: float, length: float) -> float:
    """G93: the move takes 1/F minutes, so the rate is length * F; rs274 gives no less than 0.1."""
    return max(length * f, 0.1)


# -- arcs ---------------------------------------------------------------------------------------
def check_arc_feed(it: Machine, w: dict[str, float]) -> None:
    """An arc may run: an F word in G93, else a feed rate and, in G95, a spindle speed."""
    st = it.state
    if st.feed_mode == 930:
        if "f" not in w:
            raise NgcSemanticError("F word missing with inverse time arc move")
        return
    if st.feed == 0.0:
        raise NgcSemanticError("Cannot make arc with zero feed rate")
    if st.feed_mode == 950 and st.speed == 0.0:
        raise NgcSemanticError("Cannot feed with zero spindle speed in feed per rev mode")


def arc(it: Machine, w: dict[str, float], end: list[float], code: int) -> None:
    """G2 (clockwise) / G3 (counterclockwise) in the active plane."""
    st = it.state
    plane = PLANES.get(st.plane)
    if plane is None:
        raise NgcSemanticError("Cannot do an arc in planes G17.1, G18.1, or G19.1")
    first, second, helix, letters, forbidden, pname, labels = plane
    compensation = it.comp
    if compensation is not None and compensation.side == 0:
        raise NgcSemanticError(
            "The move just after exiting cutter compensation mode must be straight, not an arc")
    if "r" not in w and "i" not in w and "j" not in w and "k" not in w:
        raise NgcSemanticError("R i j k words all missing for arc")
    if st.feed_mode == 930 and "f" not in w:
        raise NgcSemanticError("F word missing with inverse time arc move")
    if forbidden in w:
        raise NgcSemanticError(f"{forbidden.upper()} word given for arc in {pname} plane")
    if "r" in w and (letters[0] in w or letters[1] in w):
        raise NgcSemanticError("Mixed radius ijk format for arc")
    check_arc_feed(it, w)
    # a whole number of turns, at least 1 (checked before the line ran)
    turns = round(w["p"]) if "p" in w else 1  # within 0.001 of a whole number
    start = st.pos if compensation is None else compensation.prog
    s1, s2 = start[first], start[second]
    e1, e2 = end[first], end[second]
    if "r" in w:
        axis_letters = "xyz"[first] + "xyz"[second]
        if axis_letters[0] not in w and axis_letters[1] not in w:
            a, b = sorted(axis_letters)
            raise NgcSemanticError(f"{a.upper()} and {b} words missing for arc in {pname} plane")
        c1, c2 = _radius_center(it, code, w["r"], s1, s2, e1, e2)
    else:
        c1, c2 = _ijk_center(it, w, letters, s1, s2, e1, e2, labels)
    rotation = turns if code == 30 else -turns
    if st.feed_mode == 930:
        length = _arc_length(s1, s2, e1, e2, c1, c2, rotation, end[helix] - start[helix])
        st.feed = _inverse_rate(w["f"], length)
        it.emit(ops.SetFeedRate(st.feed))
    if compensation is not None:
        comp.arc(it, end, c1, c2, rotation)
        return
    it.move(ops.ArcFeed, (e1, e2, c1, c2, rotation, end[helix], end[3], end[4], end[5]), it.label,
            it.line)
    st.pos = end


def arc_center(it: Machine, w: dict[str, float], code: int, start: list[float],
               end: list[float]) -> tuple[float, float]:
    """The centre of an arc (G2 ``code`` 20, G3 30) from ``start`` to ``end`` in the active plane,
    on the plane's first and second axes (Z and X in G18), with the checks and errors of ``arc``."""
    first, second, _, letters, _, _, labels = PLANES[it.state.plane]
    s1, s2, e1, e2 = start[first], start[second], end[first], end[second]
    if "r" in w:
        return _radius_center(it, code, w["r"], s1, s2, e1, e2)
    return _ijk_center(it, w, letters, s1, s2, e1, e2, labels)


def _ijk_center(
    it: Machine, w: dict[str, float], letters: str,
    s1: float, s2: float, e1: float, e2: float, labels: str,
) -> tuple[float, float]:
    o1 = w.get(letters[0], 0.0)
    o2 = w.get(letters[1], 0.0)
    if it.state.arc_absolute:
        for letter in letters:
            if letter not in w:
                raise NgcSemanticError(f"{letter.upper()} word missing in absolute center arc")
        c1, c2 = o1, o2
    else:
        c1, c2 = s1 + o1, s2 + o2
    r1 = math.hypot(s1 - c1, s2 - c2)
    r2 = math.hypot(e1 - c1, e2 - c2)
    zero = RADIUS_TOLERANCE_MM if it.state.metric else RADIUS_TOLERANCE_INCH
    # (a lathe cycle's profile: a small arc is held when it is cut, one of no radius at once)
    if (r1 < zero or r2 < zero) and (it.profile is None or r1 == 0.0 or r2 == 0.0):
        where = arc_where(labels, s1, s2, c1, c2, e1, e2, r1, r2)
        raise NgcSemanticError(f"Zero-radius arc: {where}")
    abs_err = abs(r1 - r2)
    tol = CENTER_ARC_TOLERANCE_MM if it.state.metric else CENTER_ARC_TOLERANCE_INCH
    if abs_err > tol and it.profile is None:  # (a lathe cycle's profile: held when it is cut)
        rel_err = abs_err / max(r1, r2)
        if abs_err > 100 * tol or rel_err > CENTER_ARC_RELATIVE_TOLERANCE:
            where = arc_where(labels, s1, s2, c1, c2, e1, e2, r1, r2)
            raise NgcSemanticError(
                "Radius to end of arc differs from radius to start: "
                f"{where} abs_err={abs_err:.4g} rel_err={rel_err * 100:.4f}%"
            )
    return c1, c2


def arc_where(
    labels: str, s1: float, s2: float, c1: float, c2: float, e1: float, e2: float,
    r1: float, r2: float,
) -> str:
    """The arc's points as rs274's arc errors show them."""
    a, b = labels[0], labels[1]
    return (
        f"start=({a}{s1:.4f},{b}{s2:.4f}) center=({a}{c1:.4f},{b}{c2:.4f}) "
        f"end=({a}{e1:.4f},{b}{e2:.4f}) r1={r1:.4f} r2={r2:.4f}"
    )


def _radius_center(
    it: Machine, code: int, radius: float, s1: float, s2: float, e1: float, e2: float
) -> tuple[float, float]:
    if s1 == e1 and s2 == e2:
        raise NgcSemanticError("Current point same as end point of arc")
    tol = RADIUS_TOLERANCE_MM if it.state.metric else RADIUS_TOLERANCE_INCH
    abs_r = abs(radius)
    m1 = (s1 + e1) / 2.0
    m2 = (s2 + e2) / 2.0
    # the half chord from the midpoint, as rs274 measures it (a midpoint past the largest
    # number makes it infinite: "too small")
    half = math.hypot(e1 - m1, e2 - m2)
    if abs_r < half:
        if it.profile is not None:
            # a lathe cycle's profile: rs274 finds no centre (it reports "G7X error: Not
            # monotonic" when the cycle runs), nor forgives the last digits
            return math.nan, math.nan
        if abs_r < half - tol:
            raise NgcSemanticError("Arc radius too small to reach end point")
    abs_r = max(abs_r, half)
    theta = math.atan2(e2 - s2, e1 - s1)
    # For G2 the center lies right of the chord (left for G3); a negative R takes the far side.
    side = -1.0 if code == 20 else 1.0
    if radius < 0:
        side = -side
    # The center's distance from the chord as rs274 computes it (through the half angle, which
    # leaves a residue of the order of 1e-17 for a half circle: the printed -0.0000).
    offset = abs_r * math.cos(math.asin(min(half / abs_r, 1.0)))
    angle = theta + side * math.pi / 2.0
    return m1 + offset * math.cos(angle), m2 + offset * math.sin(angle)


def _arc_length(
    s1: float, s2: float, e1: float, e2: float, c1: float, c2: float, rotation: int, dz: float
) -> float:
    radius = math.hypot(s1 - c1, s2 - c2)
    a0 = math.atan2(s2 - c2, s1 - c1)
    a1 = math.atan2(e2 - c2, e1 - c1)
    if rotation > 0:
        sweep = a1 - a0
        if sweep <= 0.0:
            sweep += 2 * math.pi
        sweep += 2 * math.pi * (rotation - 1)
    else:
        sweep = a0 - a1
        if sweep <= 0.0:
            sweep += 2 * math.pi
        sweep += 2 * math.pi * (-rotation - 1)
    return math.hypot(radius * sweep, dz)
