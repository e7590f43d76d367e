"""Reading an engine-dialect line: comments, words, expressions and clauses."""

from __future__ import annotations

import re

from ..errors import NgcSyntaxError
from ..language import expressions as ex
from ..language.parser import read_value
from .state import AXIS, POLARS, VECTORS, EngineError, Params

# the references of clauses; I J K R for G2/G3, R Q P for drilling, F the feed, P a dwell
WORDS = frozenset("FIJKPQR")
_REFERENCE = re.compile(r"(V[XYZABCUVW]|P[XYZ]|[XYZABCUVWFIJKPQR])(?![A-Z])", re.IGNORECASE)

_M_CODE = re.compile(r"m\d+", re.IGNORECASE)
_EDGES = re.compile(r"^[\s,]+|[\s,]+$")

Clauses = list[tuple[str, list[float]]]


def strip(raw: str) -> str:
    """The line without its comments (``( ... )`` and from ``;`` on) and without the separators
    (white space, commas) at its ends."""
    text = re.sub(r"\([^)]*\)", " ", raw)
    return _EDGES.sub("", text.split(";", 1)[0])


def tokens(text: str) -> list[str]:
    """Words separated by white space or commas; a bracket keeps its inside together, and a
    reference written against its first expression (``X2``, ``PZ-1``) is split from it."""
    out: list[str] = []
    cur = ""
    depth = 0
    for c in text:
        if depth == 0 and (c.isspace() or c == ","):
            if cur:
                out.append(cur)
            cur = ""
            continue
        depth += (c == "[") - (c == "]")
        cur += c
    if cur:
        out.append(cur)
    split: list[str] = []
    for tok in out:
        m = _REFERENCE.match(tok)
        if m is not None and m.end() < len(tok) and tok[m.end()] in "0123456789.+-#[":
            split += [tok[: m.end()], tok[m.end():]]
        else:
            split.append(tok)
    return split


def value(token: str, params: Params) -> float:
    """An expression's value: a finite number (infinity or NaN, as a number of 400 digits or
    ``[10**400]`` gives, is rs274's error for a value it reads)."""
    text = re.sub(r"\s+", "", token.lower())
    try:
        parsed = read_value(text)
    except NgcSyntaxError as exc:
        if exc.message.startswith("Bad expression"):  # something after a whole value
            raise NgcSyntaxError(f"Bad expression '{token}': clauses are separated by a space "
                                 f"or a comma") from None
        exc.column = None  # (a column in the token, not in the line)
        raise
    except Exception as exc:  # (a token the reader cannot take)
        raise NgcSyntaxError(f"Bad expression '{token}'") from exc
    return ex.finite(ex.evaluate(parsed, params))


def reference(token: str) -> str | None:
    up = token.upper()
    if up in AXIS or up in VECTORS or up in POLARS or up in WORDS:
        return up
    return None


def clauses(words: list[str], params: Params) -> Clauses:
    """``[(reference, values), ...]`` in order."""
    out: Clauses = []
    for tok in words:
        ref = reference(tok)
        if ref is not None:
            out.append((ref, []))
        elif _M_CODE.fullmatch(tok):
            raise EngineError(f"{tok.upper()}: M codes go on a line of their own (with S)")
        elif not out:
            raise NgcSyntaxError(f"Expression '{tok}' before any reference")
        else:
            out[-1][1].append(value(tok, params))
    return out


def single(ref: str, values: list[float], what: str) -> float:
    """The one value of a word that takes one."""
    if len(values) != 1:
        raise EngineError(f"{ref} takes 1 expression in {what}, not {len(values)}")
    return values[0]
