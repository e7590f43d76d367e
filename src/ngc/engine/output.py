"""The engine dialect's operations as JSON lines or as text (``ngc canon --dialect engine``)."""

from __future__ import annotations

import json
from collections.abc import Iterable
from typing import TextIO

from .state import Dwell, EngineSegment, Op, Stop


def as_dict(op: Op) -> dict[str, object]:
    if isinstance(op, EngineSegment):
        return {"op": "ENGINE_SEGMENT", "line": op.line, "motion": op.motion,
                "duration": op.duration,
                "axes": {a: list(c) for a, c in op.axes.items()}}
    if isinstance(op, Dwell):
        return {"op": "DWELL", "line": op.line, "seconds": op.seconds}
    if isinstance(op, Stop):
        return {"op": "STOP", "line": op.line}
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
    return f"{op.name}(line={op.line}, {json.dumps(op.value)})"


def write(ops: Iterable[Op], out: TextIO, fmt: str) -> None:
    """Each operation on a line of its own, as it comes (an error leaves the ones before it)."""
    for op in ops:
        out.write((json.dumps(as_dict(op)) if fmt == "json" else as_text(op)) + "\n")
