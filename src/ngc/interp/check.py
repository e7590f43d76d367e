"""Check: the rules a resolved block must satisfy before anything in it executes.

These are rs274's checks of G codes, M codes and "other" words (a word must have a code that uses
it), with its messages.  Nothing here changes state.
"""

from __future__ import annotations

from ..errors import NgcSemanticError, NgcSyntaxError
from ..language import codes
from ..language.words import Words as Resolved
from .state import State

_ARC = (20, 30)

# Words that need a code to use them: letter -> (codes that use it (G*10 or "M<n>"), message).
_P_MSG = (
    "P word with no G2 G3 G4 G10 G64 G5 G5.2 G76 G82 G86 G88 G89 or M50 M51 M52 M53 M62 M63 M64 "
    "M65 M66 M98 or user M code to use it"
)


def check(st: State, r: Resolved) -> None:
    """Raise the first rule ``r`` breaks, in rs274's order."""
    g = r.g
    non_modal = g.get(codes.G_NON_MODAL)
    motion = g.get(codes.G_MOTION)
    if non_modal == 530:
        _check_g53(st, motion)
    if r.has_axes:
        _check_axis_users(st, motion, non_modal)
    if r.others:
        active = _active_motion(st, r, motion, non_modal)
        _check_other_words(r, active, non_modal)


def _check_g53(st: State, motion: int | None) -> None:
    mode = st.motion if motion is None else motion
    if mode not in (0, 10):
        raise NgcSemanticError("Must use g0 or g1 with g53")
    if not st.absolute:
        raise NgcSemanticError("Cannot use g53 incremental")


def _check_axis_users(st: State, motion: int | None, non_modal: int | None) -> None:
    axis_user = non_modal in codes.G_AXIS_USERS_NON_MODAL
    if motion is not None and motion != 800 and axis_user:
        raise NgcSemanticError("Cannot use two g codes that both use axis values")
    if axis_user:
        return
    if motion == 800:
        raise NgcSemanticError("Cannot use axis values with g80")
    if motion is None and st.motion == 800:
        raise NgcSemanticError("Cannot use axis values without a g code that uses them")


def _active_motion(st: State, r: Resolved, motion: int | None, non_modal: int | None) -> int | None:
    """The motion code this block executes, if any."""
    if motion is not None:
        return motion
    if r.has_axes and non_modal not in codes.G_AXIS_USERS_NON_MODAL and st.motion != 800:
        return st.motion
    return None


def _check_other_words(r: Resolved, active: int | None, non_modal: int | None) -> None:
    w = r.w
    g = r.g
    m = r.m
    arc = active in _ARC
    g10 = non_modal == 100
    m98 = m.get(codes.M_USER) == 98
    if m.get(codes.M_USER) == 99 and ("p" in w or "l" in w):
        raise NgcSyntaxError("Unexpected character after O-word")
    if "i" in w and not (arc or g10):
        raise NgcSemanticError("I word with no G2, G3, G5, G5.1, G10, G33.1, G76, or G87 to use it")
    if "j" in w and not (arc or g10):
        raise NgcSemanticError("J word with no G2, G3, G5, G5.1, G10, G76 or G87 to use it")
    if "k" in w and not (arc or g10):
        raise NgcSemanticError("K word with no G2, G3, G33, G33.1, G76, or G87 to use it")
    if "l" in w and not (g10 or m98):
        raise NgcSemanticError(
            "L word with no G10, cutter compensation, canned cycle, digital/analog input, M98 or "
            "NURBS code"
        )
    if "p" in w and not (
        arc or non_modal in (40, 100) or g.get(codes.G_CONTROL) == 640
        or m.get(codes.M_OVERRIDE, 0) in (50, 51, 52, 53) or m98
    ):
        raise NgcSemanticError(_P_MSG)
    if "q" in w and not (g.get(codes.G_CONTROL) == 640 or g10):
        raise NgcSemanticError(
            "Q word with no G5, G10, G64, G73, G76, G83, M19, M66, M67, M68 or user M code that "
            "uses it"
        )
    if "r" in w and not (arc or g10):
        raise NgcSemanticError("R word with no g code that uses it")
    if "d" in w:
        raise NgcSemanticError(
            "D word with no G41, G41.1, G42, G42.1, G71, G71.1, G71.2 or G96 to use it"
        )
    if "h" in w:
        raise NgcSemanticError("H word with no G43 or G76 to use it")
    if "e" in w:
        raise NgcSemanticError("E word with no G70, G76, M66, M67 or M68 to use it")
    if "t" in w:
        raise NgcSemanticError("T words (tool selection) are not supported yet")
