"""The engine dialect (``../shared/spec/seeds/003_4acd6ea7c5d2d9d9.txt``): G-codes by number or
by name, motion made of clauses of
axis, vector and polar references, each a constant-speed or cubic-Bézier motion over the move's
normalised time, interpolated as *engine segments* (per axis, the four control points of a cubic
Bézier of position over the segment's time, and a duration).

``run(text)`` interprets a program and yields its operations; ``docs/engine-dialect.md`` is the
dialect as ngc implements it.
"""

from .interp import (
    Dwell,
    Engine,
    EngineError,
    EngineSegment,
    ModeChange,
    Op,
    ProgramStop,
    Stop,
    run,
)
from .setup import Setup, read_setup

__all__ = ["Dwell", "Engine", "EngineError", "EngineSegment", "ModeChange", "Op", "ProgramStop",
           "Setup", "Stop", "read_setup", "run"]
