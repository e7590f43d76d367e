"""Resolve: evaluate a parsed block's values against the parameters, in source order.

The result is the block's :class:`~ngc.language.words.Words`, which the check and convert phases
see.  Blocks whose values are all constants were resolved by the parser already and are reused.
"""

from __future__ import annotations

from ..language.codes import CodeTable
from ..language.expressions import ParamContext
from ..language.parser import COMMENT, PARAM, WORD, Block, check_index, check_number_writable
from ..language.words import Words, add_word
from .parameters import PREDEFINED, Parameters, check_writable

Resolved = Words


def resolve(block: Block, params: Parameters, table: CodeTable) -> Words:
    """Evaluate ``block``'s items in source order (rs274 reads a line left to right)."""
    cached = block.resolved
    if cached is not None:
        return cached
    r = Words()
    for kind, key, value in block.items:
        if kind == WORD:
            v = value if type(value) is float else value(params)  # type: ignore[operator]
            add_word(r, key, v, table)  # type: ignore[arg-type]
        elif kind == PARAM:
            _param(r, key, value, params)
        elif kind == COMMENT:
            r.comment = key  # type: ignore[assignment]
    for target, _ in r.assigns:
        if isinstance(target, str):
            check_writable(target)  # rs274 refuses a predefined name once the line is read
    return r.finish()


def _param(r: Words, key: object, value: object, params: Parameters) -> None:
    target: int | str
    if isinstance(key, str):
        if key not in PREDEFINED:
            params.declare(key)
        target = key
    elif isinstance(key, int):
        check_number_writable(key)
        target = key
    else:
        target = check_index(key(params))  # type: ignore[operator]
        check_number_writable(target)
    v = value if type(value) is float else value(params)  # type: ignore[operator]
    r.assigns.append((target, v))


__all__ = ["ParamContext", "Resolved", "resolve"]
