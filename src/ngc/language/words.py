"""A block's words with numbers: what rs274 has after reading a line.

``Words`` holds the G codes by modal group, the M codes by modal group and the other words by
letter, plus the line's queued parameter settings and its (last) comment.  :func:`add_word` applies
rs274's read-time rules (repeated words, modal-group clashes, integer words) — shared by the
parser's constant fast path and the interpreter's resolve phase.
"""

from __future__ import annotations

from ..errors import NgcSemanticError, NgcSyntaxError
from . import codes

INTEGER_LETTERS = frozenset("dhlt")
_AXES = frozenset(codes.AXIS_LETTERS + codes.POLAR_LETTERS)
# Letters that every block may carry without a code that uses them.
FREE_LETTERS = frozenset(codes.AXIS_LETTERS + "fs")
# M codes 100..199 are user M codes, looked up as files (not available to the standalone machine).
M_USER_LIMIT = 199
MAX_M_PER_LINE = 4


class Words:
    """``g``/``m``: modal group -> code (G times ten); ``w``: letter -> value."""

    __slots__ = ("assigns", "comment", "g", "has_axes", "m", "others", "plain", "w")

    def __init__(self) -> None:
        self.g: dict[int, int] = {}
        self.m: dict[int, int] = {}
        self.w: dict[str, float] = {}
        self.assigns: list[tuple[int | str, float]] = []
        self.comment: str | None = None
        self.has_axes = False  # any of X Y Z A B C
        self.others = False  # any word that needs a code to use it (not X Y Z A B C F S)
        self.plain = False  # only a motion code, axis, F and S words: the interpreter's fast path

    def finish(self) -> Words:
        """Compute the summary flags once all words are in."""
        keys = self.w.keys()
        self.has_axes = not _AXES.isdisjoint(keys)
        self.others = not FREE_LETTERS.issuperset(keys)
        g = self.g
        self.plain = (
            not self.others
            and not self.m
            and self.comment is None
            and not self.assigns
            and (not g or (len(g) == 1 and codes.G_MOTION in g))
        )
        return self


def integer_value(value: float) -> int:
    """``value`` as an integer if it is within 0.0001 of one (overview.adoc, "Numbers")."""
    k = round(value)
    if abs(value - k) > 0.0001:
        raise NgcSyntaxError("Non integer value for integer")
    return int(k)


def add_word(words: Words, letter: str, v: float) -> None:
    """Add one word, raising rs274's read errors."""
    if letter == "g":
        _g_word(words, v)
    elif letter == "m":
        _m_word(words, v)
    else:
        w = words.w
        if letter in w:
            raise NgcSyntaxError(f"Multiple {letter} words on one line")
        if letter in INTEGER_LETTERS:
            v = float(integer_value(v))
        w[letter] = v


# Every known G code by its value as read (1.0 -> G1), for the common exact values.
G_BY_VALUE: dict[float, tuple[int, int]] = {
    code / 10: (known.group, code) for code, known in codes.G_CODES.items()
}


def _g_word(words: Words, v: float) -> None:
    hit = G_BY_VALUE.get(v)
    if hit is not None:
        group, code = hit
        if group in words.g:
            raise NgcSemanticError("Two g codes used from same modal group")
        words.g[group] = code
        return
    if v < 0.0:
        raise NgcSyntaxError("Negative g code used")
    tenths = v * 10.0
    code = round(tenths)
    if abs(tenths - code) > 0.001 or code > 999:
        raise NgcSyntaxError("G-code out of range")
    known = codes.G_CODES.get(code)
    if known is None:
        raise NgcSemanticError("Unknown g code used")
    if known.group in words.g:
        raise NgcSemanticError("Two g codes used from same modal group")
    words.g[known.group] = code


def _m_word(words: Words, v: float) -> None:
    code = integer_value(v)
    if code < 0:
        raise NgcSyntaxError("Negative m code used")
    if code > M_USER_LIMIT:
        raise NgcSemanticError(f"M-code greater than {M_USER_LIMIT}: M{code}")
    known = codes.M_CODES.get(code)
    if known is None:
        raise NgcSemanticError(f"Unknown m code used: M{code}")
    if known.group in words.m:
        raise NgcSemanticError("Two m codes used from same modal group")
    if len(words.m) >= MAX_M_PER_LINE:
        raise NgcSemanticError("Too many m codes on line")
    words.m[known.group] = code
