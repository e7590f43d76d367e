"""Timing a whole program: the interpreter's canon feeds the planner; the result sums the time by
line, by tool and by kind, beside the naive distance / feed figure."""

from __future__ import annotations

import math
from collections import defaultdict
from dataclasses import dataclass, field

from ..interp.interpreter import Interpreter
from .lookahead import BLEND, Planner, Segment
from .machine import DEFAULT_MACHINE, Machine
from .moves import PathSink

KINDS = ("rapid", "feed", "arc", "dwell", "tool change", "spindle", "wait")


@dataclass
class TimeResult:
    total_s: float = 0.0
    naive_s: float = 0.0
    motion_s: float = 0.0
    by_kind: dict[str, float] = field(default_factory=lambda: defaultdict(float))
    by_tool: dict[int, float] = field(default_factory=lambda: defaultdict(float))
    by_line: dict[int, float] = field(default_factory=lambda: defaultdict(float))
    segments: int = 0
    length: float = 0.0


class Timer:
    """Collects finished segments and standstills into a :class:`TimeResult`."""

    def __init__(self, machine: Machine) -> None:
        self.machine = machine
        self.result = TimeResult()
        self.planner = Planner(machine, self.segment)
        self.sink = PathSink(machine, self.planner, self.wait)
        self.last_kind = "feed"

    def segment(self, seg: Segment) -> None:
        r = self.result
        kind = seg.kind
        if kind == BLEND:
            kind = self.last_kind
        else:
            self.last_kind = kind
        t = seg.time
        r.by_kind[kind] += t
        r.by_tool[seg.tool] += t
        parts = seg.parts
        if parts and len(parts) > 1:
            total = sum(p[2] for p in parts) or 1.0
            for _, line, length in parts:
                r.by_line[line] += t * length / total
        else:
            r.by_line[seg.line] += t
        if seg.naive != math.inf:
            r.naive_s += seg.naive
        r.segments += 1
        r.length += seg.length

    def wait(self, kind: str, seconds: float, line: int) -> None:
        overhead = 0.0
        if kind == "dwell":
            overhead = 2.5 * self.machine.task_cycle if self.planner.total > 0 else 0.0
        t = seconds + overhead
        if t <= 0.0:
            return
        self.planner.clock += t
        r = self.result
        r.by_kind[kind] += t
        r.by_line[line] += t
        r.by_tool[self.sink.tool] += t
        r.naive_s += seconds

    def finish(self) -> TimeResult:
        self.sink.flush()
        self.result.total_s = self.planner.total
        return self.result


def time_text(text: str, machine: Machine = DEFAULT_MACHINE) -> TimeResult:
    timer = Timer(machine)
    interp = Interpreter(timer.sink)
    interp.startup()
    interp.run(text.splitlines(keepends=True))
    return timer.finish()
