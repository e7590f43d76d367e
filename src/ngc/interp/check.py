"""Check: the rules a resolved block must satisfy before anything in it executes.

A block that breaks one leaves no trace: nothing emitted, no state changed.  The rules come from
the code table (codes not supported yet, the words each code uses and requires) and from rs274's
checks of G53, axis words and G10, with its messages.  Nothing here changes state.
"""

from __future__ import annotations

from ..errors import NgcSemanticError, NgcSyntaxError
from ..language import codes
from ..language.codes import CodeTable
from ..language.words import Words
from .handlers import g76, spindle, threading
from .state import State

_G10_L = (0.0, 1.0, 2.0, 10.0, 11.0, 20.0)
_ARCS = (20, 30)
# The motion modes that run nothing: G80, and none after G5.3.
_NO_MOTION = (codes.G_CANCEL_MOTION, codes.G_NURBS_END)


def check(st: State, r: Words, table: CodeTable) -> None:
    """Raise the first rule ``r`` breaks, in rs274's order."""
    _check_supported(st, r, table)
    if r.g.get(codes.G_MOTION) == codes.G_NURBS_END:
        r = _without_nurbs_end(r)
    g = r.g
    non_modal = g.get(codes.G_NON_MODAL)
    motion = g.get(codes.G_MOTION)
    w = r.w
    if "t" in w and w["t"] < 0:
        raise NgcSemanticError("Negative tool id (tool not found)")
    if "@" in w or "^" in w:
        _check_polar(st, w)
    if r.has_axes:
        _check_cycle_axes(st, r, motion, table)
    if r.has_axes:
        _check_axis_users(st, r, motion, non_modal, table)
    if non_modal == codes.G_MACHINE_COORDINATES:
        _check_g53(st, r, motion)
    # (a code's required words before the words no code uses: "G4 E1" is "Dwell time missing")
    for code in g.values():
        row = table.g[code]
        if row.requires and not any(letter in r.w for letter in row.requires):
            raise NgcSemanticError(row.missing)
    if r.others:
        active = implied_motion(st, r, table) if motion is None else motion
        if motion is None and not r.has_axes and (active in threading.SYNCHRONIZED
                                                  or active == g76.G76):
            active = None  # I J K alone run no modal G33 / G33.1 / G76 (unlike G2 / G3)
        _check_other_words(r, active, table)
        if "p" in r.w and active in _ARCS:
            _check_turns(r.w["p"])
        if r.m.get(codes.M_SPINDLE) == 19:
            spindle.check_orient(r.w)
    if non_modal == 100:
        _check_g10(r)
    active = motion if motion is not None else implied_motion(st, r, table)
    if active in threading.SYNCHRONIZED:
        threading.check(r.w)
    elif active == g76.G76:
        g76.check(r.w)


def _check_polar(st: State, w: dict[str, float]) -> None:
    """Polar words: in the XY plane (as it is before the line), and not with an X or Y word."""
    if st.plane != 170:
        raise NgcSemanticError("Cannot use polar coordinate except in G17 plane")
    for letter in "xy":
        if letter in w:
            raise NgcSemanticError(f"Cannot specify both polar coordinate and {letter.upper()} word")


def _without_nurbs_end(r: Words) -> Words:
    """A G5.3 line as rs274 checks it: as if the G5.3 were not on it, its words against the
    modal motion (``G5.3 X1`` after G0 passes, and fails at G5.3's own check; at the start, in
    G80, it is "Cannot use axis values without a g code that uses them")."""
    rest = Words()
    rest.g = {group: code for group, code in r.g.items() if group != codes.G_MOTION}
    rest.m, rest.w, rest.assigns, rest.comment = r.m, r.w, r.assigns, r.comment
    return rest.finish()


def implied_motion(st: State, r: Words, table: CodeTable) -> int | None:
    """The modal motion a line without a motion code runs: its axis (or I J K) words run it,
    unless a group-0 code on the line takes the axis words.  None if it runs none."""
    if codes.G_MOTION in r.g or not r.moves or r.g.get(codes.G_NON_MODAL) in table.axis_users:
        return None
    if r.g.get(codes.G_TOOL_LENGTH) in table.modal_axis_users:
        return None
    return st.motion


def _check_supported(st: State, r: Words, table: CodeTable) -> None:
    """A code (or word) ngc does not run yet is refused before anything else is said of it,
    unless cutter radius compensation is (or turns) on and rs274 refuses the code then: that
    refusal comes at the code's step (dispatch)."""
    comp = st.ccomp != 400 or r.g.get(codes.G_CUTTER_COMP, 400) != 400
    for code in r.g.values():
        row = table.g[code]
        if row.handler is None and not (comp and row.comp_refusal):
            raise NgcSemanticError(f"{codes.g_name(code)} is not supported yet")
    for code in r.m.values():
        row = table.m[code]
        if row.handler is None and not (comp and row.comp_refusal):
            raise NgcSemanticError(f"M{code} is not supported yet")


def _check_cycle_axes(st: State, r: Words, motion: int | None, table: CodeTable) -> None:
    """No rotary axis word in a canned cycle (one given, or the modal one the line runs)."""
    active = implied_motion(st, r, table) if motion is None else motion
    if active is not None and table.g[active].cycle:
        for letter in "abc":
            if letter in r.w:
                raise NgcSemanticError(f"Cannot put {'an' if letter == 'a' else 'a'} {letter} in "
                                       "canned cycle")


def _check_g53(st: State, r: Words, motion: int | None) -> None:
    mode = st.motion if motion is None else motion
    if mode not in (0, 10):
        raise NgcSemanticError("Must use g0 or g1 with g53")
    distance = r.g.get(codes.G_DISTANCE)
    if not (st.absolute if distance is None else distance == 900):
        raise NgcSemanticError("Cannot use g53 incremental")


def _check_axis_users(
    st: State, r: Words, motion: int | None, non_modal: int | None, table: CodeTable,
) -> None:
    axis_user = non_modal in table.axis_users
    if motion is not None and motion != codes.G_CANCEL_MOTION and axis_user:
        raise NgcSemanticError("Cannot use two g codes that both use axis values")
    if axis_user or r.g.get(codes.G_TOOL_LENGTH) in table.modal_axis_users:
        return
    if motion == codes.G_CANCEL_MOTION:
        raise NgcSemanticError("Cannot use axis values with g80")
    if motion is None and st.motion in _NO_MOTION:
        raise NgcSemanticError("Cannot use axis values without a g code that uses them")


def _check_other_words(r: Words, active: int | None, table: CodeTable) -> None:
    """Every word beyond X Y Z A B C F S needs a code on the line (or the modal motion its axis
    words run, ``active``) that gives it a use."""
    w = r.w
    if r.m.get(codes.M_USER) == 99 and ("p" in w or "l" in w):
        raise NgcSyntaxError("Unexpected character after O-word")
    used = "".join(table.g[code].uses for code in r.g.values())
    used += "".join(table.m[code].uses for code in r.m.values())
    if active is not None and codes.G_MOTION not in r.g:
        used += table.g[active].uses
    if "s" in w:
        used += "$"  # S takes a spindle number too
    for letter, message in codes.UNUSED_WORD_MESSAGES:
        if letter in w and letter not in used:
            raise NgcSemanticError(message)


def _check_turns(p: float) -> None:
    """An arc's P: a whole number of turns (to within 0.001, as rs274 allows), at least 1."""
    spindle.check_whole_p(p)
    if round(p) < 1:
        raise NgcSemanticError("P value should be 1 or greater with G2 or G3")


def _check_g10(r: Words) -> None:
    """G10's L and P, which rs274 checks before the line runs."""
    w = r.w
    l_word = w.get("l")
    if l_word not in _G10_L:
        raise NgcSemanticError("Line with G10 does not have L0, L1, L10, L11, L2, or L20")
    if l_word == 0.0:
        return
    p = w.get("p")
    if l_word not in (2.0, 20.0):
        # A tool number: rs274 rounds P2.5 up but refuses P2.4, before the range check.
        if p is not None and 0.0001 < p - int(p) < 0.5:
            raise NgcSemanticError("P value not an integer with G10")
        if p is None or p + 0.5 < 1.0:
            raise NgcSemanticError(f"P value out of range with G10 L{int(l_word)}")
        return
    if p is None or p < 0 or p >= 10:
        raise NgcSemanticError(f"P value out of range (0-9) with G10 L{int(l_word)}")
    if 0.0001 < p - int(p) < 0.5:
        # rs274 takes P2.5 or P3.99 as system 2 or 3 but refuses P2.4.
        raise NgcSemanticError("P value not an integer with G10")
