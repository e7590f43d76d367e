"""A block's words with numbers: what rs274 has after reading a line.

``Words`` holds the G codes by modal group, the M codes by modal group and the other words by
letter, plus the line's queued parameter settings and its (last) comment.  :func:`add_word` applies
rs274's read-time rules (repeated words, unknown codes, modal-group clashes, integer words) with the
dialect's code table — shared by the parser's constant lines and the interpreter's resolve phase.
"""

from __future__ import annotations

import math
from types import MappingProxyType

from ..errors import NgcError, NgcSemanticError, NgcSyntaxError
from .codes import AXIS_LETTERS, FREE_LETTERS, G_CANCEL_MOTION, G_MOTION, POLAR_LETTERS, CodeTable

INTEGER_LETTERS = frozenset("hlt")  # D is a real: a diameter for G41.1/G42.1, a speed for G96
_AXES = frozenset(AXIS_LETTERS + POLAR_LETTERS)
# Words rs274 refuses negative as it reads them (so before any check of the line).
_SIGNED_AS_READ = MappingProxyType({"f": "Negative f word used", "s": "Negative spindle speed used"})
# Words that run the modal motion on a line with no motion code: axes, and arc centers (rs274 cuts
# a full circle for a line of ``I0.5`` alone in G2).
_MOVES = _AXES | frozenset("ijk")
# M codes 100..199 are user M codes, looked up as files (not available to the standalone machine).
M_USER_LIMIT = 199
MAX_M_PER_LINE = 4


class Words:
    """``g``/``m``: modal group -> code (G times ten); ``w``: letter -> value."""

    __slots__ = ("assigns", "comment", "g", "has_axes", "m", "moves", "others", "w")

    def __init__(self) -> None:
        self.g: dict[int, int] = {}
        self.m: dict[int, int] = {}
        self.w: dict[str, float] = {}
        self.assigns: list[tuple[int | str, float]] = []
        self.comment: str | None = None
        self.has_axes = False  # any of X Y Z A B C @ ^
        self.moves = False  # any word that runs the modal motion: an axis word, I J K
        self.others = False  # any word that needs a code to use it (not X Y Z A B C F S)

    def finish(self) -> Words:
        """Compute the summary flags once all words are in."""
        keys = self.w.keys()
        self.has_axes = not _AXES.isdisjoint(keys)
        self.moves = not _MOVES.isdisjoint(keys)
        self.others = not FREE_LETTERS.issuperset(keys)
        return self


def integer_value(value: float) -> int:
    """``value`` as an integer if it is close to one (overview.adoc, "Numbers"), as rs274 reads
    it: from below, its fraction above its floor must be more than 0.9999 (``T1.9999`` is
    refused, ``T1.99995`` is 2); from above, at most 0.0001."""
    k = math.floor(value)
    fraction = value - k
    if fraction > 0.9999:
        return math.ceil(value)
    if fraction > 0.0001:
        raise NgcSyntaxError("Non integer value for integer")
    return int(k)


def add_word(words: Words, letter: str, v: float, table: CodeTable) -> None:
    """Add one word, raising rs274's read errors (which name the word: ``NgcError.word``)."""
    try:
        _add_word(words, letter, v, table)
    except NgcError as err:
        if err.word is None:
            err.word = (letter, v)
        raise


def _add_word(words: Words, letter: str, v: float, table: CodeTable) -> None:
    if letter == "g":
        _g_word(words, v, table)
    elif letter == "m":
        _m_word(words, v, table)
    else:
        w = words.w
        if letter in w:
            raise NgcSyntaxError(f"Multiple {letter} words on one line")
        if v < 0.0 and letter in _SIGNED_AS_READ:
            raise NgcSemanticError(_SIGNED_AS_READ[letter])
        if letter in INTEGER_LETTERS:
            v = float(integer_value(v))
            if letter == "l" and v < 0.0:
                raise NgcSemanticError("Negative l word used")
            if letter == "h" and v < -1.0:  # (H-1 is read: G76 takes it as no final pass)
                raise NgcSemanticError("Negative h word used")
        w[letter] = v


def check_signs(w: dict[str, float]) -> None:
    """The read-time sign rules of :func:`add_word`, for words read without it (in line order)."""
    for letter, v in w.items():
        if v < 0.0 and letter in _SIGNED_AS_READ:
            err = NgcSemanticError(_SIGNED_AS_READ[letter])
            err.word = (letter, v)
            raise err


def _g_word(words: Words, v: float, table: CodeTable) -> None:
    hit = table.g_by_value.get(v)
    if hit is not None:
        _set_g(words.g, *hit)
        return
    tenths = v * 10.0
    # rs274 reads the code through a C int: past its range (or infinite) it is INT_MIN, negative.
    if v < 0.0 or not tenths < 2147483647.5:
        raise NgcSyntaxError("Negative g code used")
    code = round(tenths)
    if abs(tenths - code) > 0.001 or code > 999:
        raise NgcSyntaxError("G-code out of range")
    known = table.g.get(code)
    if known is None:
        raise NgcSemanticError("Unknown g code used")
    _set_g(words.g, known.group, code)


def _set_g(g: dict[int, int], group: int, code: int) -> None:
    """One G code into its modal group.  G80 gives way to any other motion code on the line (rs274
    reads ``G1 G80 X1`` as ``G1 X1``); any other second code of a group is an error."""
    old = g.get(group)
    if old is not None:
        if group != G_MOTION or (old != G_CANCEL_MOTION and code != G_CANCEL_MOTION):
            raise NgcSemanticError("Two g codes used from same modal group")
        if code == G_CANCEL_MOTION:
            return
    g[group] = code


def _m_word(words: Words, v: float, table: CodeTable) -> None:
    code = integer_value(v)
    if code < 0 or code > 2147483647:  # through a C int, a code past its range is negative
        raise NgcSyntaxError("Negative m code used")
    if code > M_USER_LIMIT:
        raise NgcSemanticError(f"M-code greater than {M_USER_LIMIT}: M{code}")
    known = table.m.get(code)
    if known is None:
        raise NgcSemanticError(f"Unknown m code used: M{code}")
    if known.group in words.m:
        raise NgcSemanticError("Two m codes used from same modal group")
    if len(words.m) >= MAX_M_PER_LINE:
        raise NgcSemanticError("Too many m codes on line")
    words.m[known.group] = code
