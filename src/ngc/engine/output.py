"""The engine dialect's operations as JSON lines or as text (``ngc canon --dialect engine``)."""

from __future__ import annotations

import json
from typing import TypeGuard

from .state import Dwell, EngineSegment, ModeChange, Op, ProgramStop, Stop

_NAMES = {EngineSegment: "ENGINE_SEGMENT", Dwell: "DWELL", Stop: "STOP"}


def is_op(op: object) -> TypeGuard[Op]:
    """Whether ``op`` is one of the engine dialect's operations."""
    return type(op) in _NAMES or type(op) in (ModeChange, ProgramStop)


def name(op: Op) -> str:
    """The operation's name, as its JSON ``"op"`` and its text have it."""
    return op.name if isinstance(op, (ModeChange, ProgramStop)) else _NAMES[type(op)]


def as_dict(op: Op) -> dict[str, object]:
    if isinstance(op, EngineSegment):
        return {"op": "ENGINE_SEGMENT", "line": op.line, "motion": op.motion,
                "duration": op.duration,
                "axes": {a: list(c) for a, c in op.axes.items()}}
    if isinstance(op, Dwell):
        return {"op": "DWELL", "line": op.line, "seconds": op.seconds}
    if isinstance(op, Stop):
        return {"op": "STOP", "line": op.line}
    if isinstance(op, ProgramStop):
        return {"op": op.name, "line": op.line}
    return {"op": op.name, "line": op.line, "value": op.value}


def _number(x: float) -> str:
    return f"{x:.6f}"


def as_text(op: Op) -> str:
    if isinstance(op, EngineSegment):
        axes = ", ".join(f"{a}=[{', '.join(_number(v) for v in c)}]" for a, c in op.axes.items())
        return (f"ENGINE_SEGMENT(line={op.line}, motion={op.motion}, duration="
                f"{_number(op.duration)}, {axes})")
    if isinstance(op, Dwell):
        return f"DWELL(line={op.line}, seconds={_number(op.seconds)})"
    if isinstance(op, Stop):
        return f"STOP(line={op.line})"
    if isinstance(op, ProgramStop):
        return f"{op.name}(line={op.line})"
    return f"{op.name}(line={op.line}, {json.dumps(op.value)})"

