"""The lathe cycles G70, G71/G71.1/G71.2, G72/G72.1/G72.2: their checks, the recording of the
profile subroutine, and the cycle (``interp/lathe``).

rs274 runs the subroutine Q as the line ``O<q> CALL``: its control flow and parameter settings
run (global parameters are given back their values afterwards), its G0/G1/G2/G3 moves (or the
modal motion of a line with axis words) become the profile, in the distance modes of the cycle's
line, U and W adding to X and Z (refused in G91: "Cannot use U in incremental mode"), an A or C
word asking for a fillet or chamfer at the move's end; nothing else of its lines runs.  The modal
motion the last move leaves stays.  An error of the cycle itself is shown at the subroutine's last
line.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from ...errors import NgcSemanticError
from ...language import codes
from .. import comp
from ..lathe.corners import A_ZERO, BOTH_A_AND_C, round_corners
from ..lathe.finishing import g70
from ..lathe.offset import check_joinable
from ..lathe.path import Out
from ..lathe.profile import CCW, CW, LINE, NOT_MONOTONIC, Seg, steps
from ..lathe.roughing import rough
from . import motion

if TYPE_CHECKING:
    from ...language.words import Words
    from ..machine import Machine

_KINDS = {20: CW, 30: CCW}


def _name(code: int) -> str:
    return f"G{code // 10}.{code % 10}"


def record(m: Machine, r: Words) -> None:
    """A line of the profile subroutine: its move, if it has one, added to ``m.profile``."""
    st = m.state
    w = r.w
    code = r.g.get(codes.G_MOTION)
    if code is None:
        if not ("x" in w or "z" in w or "u" in w or "w" in w or "y" in w):
            return
        code = st.motion
    if not st.absolute:  # (the cycle line's G91, whatever the profile line says)
        for letter in "uw":
            if letter in w:
                raise NgcSemanticError(
                    f"G7x error: Cannot use {letter.upper()} in incremental mode (G91)")
    if "u" in w and "x" in w:
        raise NgcSemanticError("G7x error: Cannot use U and X in the same block")
    if "w" in w and "z" in w:
        raise NgcSemanticError("G7x error: Cannot use W and Z in the same block")
    pos = st.pos
    x0, z0 = pos[0], pos[2]
    u = w.get("u", 0.0)
    if st.lathe_diameter:
        u /= 2.0
    if st.absolute:
        # (U and W add only when given: a Z of -0 stays -0, as rs274 shows it)
        x1 = w.get("x", x0) + u if "u" in w else w.get("x", x0)
        z1 = w.get("z", z0) + w["w"] if "w" in w else w.get("z", z0)
    else:  # (U and W refused above)
        x1 = x0 + w.get("x", 0.0)
        z1 = z0 + w.get("z", 0.0)
    end = [x1, pos[1], z1, pos[3], pos[4], pos[5]]
    kind = _KINDS.get(code, LINE)
    cx = cz = 0.0
    if kind != LINE:
        if "i" not in w and "k" not in w and "r" not in w:
            raise NgcSemanticError("G7X error: either I or K must be present for arc")
        cz, cx = motion.arc_center(m, w, code, pos, end)
    if "a" in w and "c" in w:
        raise NgcSemanticError(BOTH_A_AND_C)
    assert m.profile is not None
    fillet = w.get("a", 0.0) or (A_ZERO if "a" in w else 0.0)
    m.profile.append(Seg(kind, x0, z0, x1, z1, cx, cz, fillet, w.get("c", 0.0), m.line))
    st.pos = end
    st.motion = code


def cycle(m: Machine, r: Words, code: int) -> None:
    """G70-G72: checks, the preliminary traverse, the profile, the cycle."""
    w = r.w
    st = m.state
    r_where = (m.label, m.line)
    if "q" not in w:
        raise NgcSemanticError("G7x.x  requires a Q word")
    if st.plane != 180:
        raise NgcSemanticError(f"{_name(code)} can only be used in XZ plane (G18)")
    if m.comp is not None and code != 700:  # (rs274 runs G70 compensated)
        raise NgcSemanticError(f"{_name(code)} cannot be used with cutter compensation enabled")
    pos = st.pos
    target = motion.end_point(m, w, False)
    start = (target[0], target[2])
    out = Out(m)
    # rs274's first traverse takes the X and Z words as they are, even in G91; the cycle
    # starts from the point they give in the distance mode
    out.traverse(w.get("x", pos[0]), w.get("z", pos[2]))
    st.motion = code  # a line of the subroutine with axis words alone runs this motion
    profile, (file, line, source) = _record(m, w["q"], start)
    m.line = r_where[1]  # the label stays the one of the subroutine's last line, as in rs274
    try:
        if any(math.isnan(seg.cx) for seg in profile):  # (an R arc whose R cannot reach)
            raise NgcSemanticError(NOT_MONOTONIC)
        if code != 700 and w.get("d", 0.0):  # (before anything else, even an A of 0)
            check_joinable(profile[1:])
        profile = round_corners(profile)
        if code == 700:  # (G70 takes a profile monotonic in Z or else in X)
            g70(out, profile, start, w.get("d", 0.0), w.get("e", 0.0), w.get("p", 1.0))
        else:
            check_monotonic(profile, code >= 720)
            rough(out, profile, start, code, w.get("d", 0.0), w.get("i", 1.0), w.get("r", 0.5))
    except NgcSemanticError as err:  # shown at the subroutine's last line
        raise err.locate(file=file, line=line, source=source) from None


# a step along the axis no longer than this turns nothing back (rs274 lets a move climb 0.001
# and stops at 0.00101, whatever the profile's size)
_CLIMB = 1e-3


def check_monotonic(profile: list[Seg], facing: bool) -> None:
    """The profile after its first move must not turn back along Z (G71) or X (G72)."""
    axis = 0 if facing else 1
    direction = 0.0
    for seg in profile[1:]:
        step, one_way = steps(seg, axis)
        if not one_way:  # an arc passing its extreme on that axis turns back
            raise NgcSemanticError(NOT_MONOTONIC)
        if abs(step) <= _CLIMB:
            continue
        if direction * step < 0:
            raise NgcSemanticError(NOT_MONOTONIC)
        direction = step


def _record(m: Machine, q: float, start: tuple[float, float]
            ) -> tuple[list[Seg], tuple[str | None, int, str]]:
    """Run the subroutine ``q`` as a profile from ``start``; the parameters are as before, the
    modal motion as its last move left it, and the current point is the profile's last point,
    as rs274 leaves it (a G70 P0 then a G91 move shows it; under compensation the compensated
    point moves there while the programmed one stays: the next pass's moves turn from it)."""
    st = m.state
    params = m.params
    pos = list(st.pos)
    st.pos = [start[0], pos[1], start[1], pos[3], pos[4], pos[5]]
    numbered = list(params.numbered)
    named = dict(params.globals)
    m.profile = []
    assert m.run_profile is not None
    done = False
    try:
        where = m.run_profile(q)
        profile: list[Seg] = m.profile
        done = True
    finally:
        m.profile = None
        last = st.pos
        st.pos = pos
        params.numbered[:] = numbered
        params.globals.clear()
        params.globals.update(named)
    if done and profile:  # (a profile of no move leaves the point where the traverse went)
        _move_to(m, last[0], last[2])
    return profile, where


def _move_to(m: Machine, x: float, z: float) -> None:
    """The current point (the compensated one under compensation) is now ``x, z``."""
    pos = list(m.state.pos)
    pos[0] = x
    pos[2] = z
    m.state.pos = pos
    c = m.comp
    if c is not None and c.side != 0:
        c.ca, c.cb = pos[c.a], pos[c.b]
        comp.offset_turned(c)
