"""Specialised runners for blocks that run many times (loop and subroutine bodies).

A block is read once; when it holds only parameter settings, or only a G0/G1 (or no G code) with
axis, F and S words, a closure runs it without building its words: the same evaluation order and
checks as :meth:`Interpreter.execute <ngc.interp.interpreter.Interpreter.execute>`, fewer steps.
Anything else keeps the general path.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from ..language.expressions import Value
from ..language.parser import PARAM, WORD, Block
from ..language.words import FREE_LETTERS, G_BY_VALUE
from .parameters import check_number_writable, check_writable

if TYPE_CHECKING:
    from .interpreter import Interpreter

_MOTIONS = {value: code for value, (_, code) in G_BY_VALUE.items() if code in (0, 10)}


def specialise(it: Interpreter, block: Block) -> Callable[[], None] | None:
    """A runner for ``block`` if it has one of the simple shapes; else None."""
    if block.delete or block.oword is not None or block.resolved is not None or not block.items:
        return None
    kinds = {kind for kind, _, _ in block.items}
    if kinds == {PARAM}:
        return _settings(it, block)
    if kinds == {WORD}:
        return _plain_motion(it, block)
    return None


def _settings(it: Interpreter, block: Block) -> Callable[[], None] | None:
    """``#1 = [...] #<x> = [...]``: values read left to right, then all set."""
    targets: list[int | str] = []
    values: list[Value] = []
    for _, key, value in block.items:
        if not isinstance(key, int | str):
            return None  # a computed parameter number: the general path checks it
        if isinstance(key, int):
            check_number_writable(key)
        targets.append(key)
        values.append(value)  # type: ignore[arg-type]
    params = it.params
    pairs = list(zip(targets, values, strict=True))

    def run() -> None:
        read = []
        for target, value in pairs:
            if isinstance(target, str):
                check_writable(target)
                params.declare(target)
            read.append(value if type(value) is float else value(params))  # type: ignore[operator]
        assign = params.assign
        for (target, _), v in zip(pairs, read, strict=True):
            assign(target, v)

    return run


def _plain_motion(it: Interpreter, block: Block) -> Callable[[], None] | None:
    """``G1 X[...] Y[...]``: the plain-line path with the values evaluated."""
    code: int | None = None
    words: list[tuple[str, Value]] = []
    for _, key, value in block.items:
        if key == "g":
            if not isinstance(value, float) or value not in _MOTIONS or code is not None:
                return None
            code = _MOTIONS[value]
        elif key in FREE_LETTERS and all(key != k for k, _ in words):
            words.append((key, value))  # type: ignore[arg-type]
        else:
            return None
    params = it.params
    convert = it.convert_plain

    def run() -> None:
        convert({k: v if type(v) is float else v(params) for k, v in words}, code)  # type: ignore[operator]

    return run
