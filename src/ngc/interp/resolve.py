"""Resolve: evaluate a parsed block's values against the parameters and apply rs274's read checks.

The result, :class:`Resolved`, is what the check and convert phases see: G codes by modal group,
M codes by modal group, the other words by letter, the queued parameter settings and the comment.
Blocks whose values are all constants are resolved once and the result is reused.
"""

from __future__ import annotations

from ..errors import NgcSemanticError, NgcSyntaxError
from ..language import codes
from ..language.expressions import ParamContext
from ..language.parser import COMMENT, PARAM, WORD, Block, check_index, integer_value
from .parameters import check_writable

_INTEGER_LETTERS = frozenset("dhlt")
# M codes 100..199 are user M codes, looked up as files (not available to the standalone machine).
_M_USER_LIMIT = 199
_MAX_M_PER_LINE = 4


class Resolved:
    """A block's words with numbers: ``g``/``m`` map modal group -> code, ``w`` letter -> value."""

    __slots__ = ("assigns", "comment", "g", "has_axes", "m", "w")

    def __init__(self) -> None:
        self.g: dict[int, int] = {}
        self.m: dict[int, int] = {}
        self.w: dict[str, float] = {}
        self.assigns: list[tuple[int | str, float]] = []
        self.comment: str | None = None
        self.has_axes = False


def resolve(block: Block, params: ParamContext) -> Resolved:
    """Evaluate ``block``'s items in source order (rs274 reads a line left to right)."""
    if block.resolved is not None:
        return block.resolved  # type: ignore[return-value]
    r = Resolved()
    for kind, key, value in block.items:
        if kind == WORD:
            v = value if type(value) is float else value(params)  # type: ignore[operator]
            _word(r, key, v)  # type: ignore[arg-type]
        elif kind == PARAM:
            _param(r, key, value, params)
        elif kind == COMMENT:
            r.comment = key  # type: ignore[assignment]
    w = r.w
    r.has_axes = "x" in w or "y" in w or "z" in w or "a" in w or "b" in w or "c" in w
    if block.static:
        block.resolved = r
    return r


def _word(r: Resolved, letter: str, v: float) -> None:
    if letter == "g":
        _g_word(r, v)
    elif letter == "m":
        _m_word(r, v)
    else:
        if letter in r.w:
            raise NgcSyntaxError(f"Multiple {letter} words on one line")
        if letter in _INTEGER_LETTERS:
            v = float(integer_value(v))
        r.w[letter] = v


def _g_word(r: Resolved, v: float) -> None:
    if v < 0.0:
        raise NgcSyntaxError("Negative g code used")
    tenths = v * 10.0
    code = round(tenths)
    if abs(tenths - code) > 0.001 or code > 999:
        raise NgcSyntaxError("G-code out of range")
    known = codes.G_CODES.get(code)
    if known is None:
        raise NgcSemanticError("Unknown g code used")
    if known.group in r.g:
        raise NgcSemanticError("Two g codes used from same modal group")
    r.g[known.group] = code


def _m_word(r: Resolved, v: float) -> None:
    code = integer_value(v)
    if code < 0:
        raise NgcSyntaxError("Negative m code used")
    if code > _M_USER_LIMIT:
        raise NgcSemanticError(f"M-code greater than {_M_USER_LIMIT}: M{code}")
    known = codes.M_CODES.get(code)
    if known is None:
        raise NgcSemanticError(f"Unknown m code used: M{code}")
    if known.group in r.m:
        raise NgcSemanticError("Two m codes used from same modal group")
    if len(r.m) >= _MAX_M_PER_LINE:
        raise NgcSemanticError("Too many m codes on line")
    r.m[known.group] = code


def _param(r: Resolved, key: object, value: object, params: ParamContext) -> None:
    target: int | str
    if isinstance(key, str):
        check_writable(key)
        target = key
    elif isinstance(key, int):
        target = key
    else:
        target = check_index(key(params))  # type: ignore[operator]
    v = value if type(value) is float else value(params)  # type: ignore[operator]
    r.assigns.append((target, v))  # type: ignore[arg-type]
