"""Timing a whole program: the interpreter's canon feeds the planner; the result sums the time by
line, by tool and by kind, beside the naive distance / feed figure.

:func:`time_text` times a program given as text, :func:`time_lines` one given as lines (with the
interpreter a command line configures), :func:`time_file` a file.  A :class:`Timer` can also
hand each finished segment and each standstill to a listener (``on_segment``, ``on_wait``): the
trajectory writer of ``ngc time --trajectory`` (:mod:`ngc.planner.trajectory`) is one.
"""

from __future__ import annotations

import heapq
import math
import sys
from array import array
from collections import defaultdict
from collections.abc import Callable, ItemsView, Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from itertools import compress, count
from typing import BinaryIO

from ..canon.ops import Sink
from ..interp.interpreter import Interpreter
from ..interp.source import ProgramReader, text_reader
from ..options import MachineOptions, load_setup, new_interpreter
from ..toolpath.limits import Excess, LimitWatch
from ..toolpath.tracker import Tee, Toolpath
from .lookahead import MAX_SECONDS, Planner, TooLong
from .machine import DEFAULT_MACHINE, Machine
from .moves import AXES6, PathSink
from .segment import BLEND, Segment

KINDS = ("rapid", "feed", "arc", "dwell", "tool change", "spindle", "wait")

SegmentListener = Callable[[Segment], None]
# A standstill: its kind, its start and its duration (s, on the planner's clock), its line.
WaitListener = Callable[[str, float, float, int], None]


class LineTimes(Mapping[int, float]):
    """Seconds by program line: a mapping of the lines that took part in a move or a standstill
    to their time, kept in an array indexed by the line number (9 bytes a line, where a dict
    takes over a hundred)."""

    __slots__ = ("seconds", "seen")

    def __init__(self) -> None:
        self.seconds = array("d")
        self.seen = bytearray()

    def add(self, line: int, seconds: float) -> None:
        if line >= len(self.seen):
            self.grow(line)
        self.seconds[line] += seconds
        self.seen[line] = 1

    def spread(self, parts: list[tuple[int, float]], per_unit: float) -> None:
        """Add ``per_unit`` times each part's length to its line: ``parts`` are (line, length)."""
        top = max(parts)[0]  # the greatest line
        if top >= len(self.seen):
            self.grow(top)
        seconds, seen = self.seconds, self.seen
        for line, length in parts:
            seconds[line] += per_unit * length
            seen[line] = 1

    def grow(self, line: int) -> None:
        """Make room for lines up to ``line`` (>= 0)."""
        if line < 0:
            raise IndexError(f"line {line}")
        more = max(line + 1, 2 * len(self.seen)) - len(self.seen)
        self.seconds.extend(array("d", bytes(8 * more)))
        self.seen.extend(bytes(more))

    def __getitem__(self, line: int) -> float:
        if 0 <= line < len(self.seen) and self.seen[line]:
            return self.seconds[line]
        raise KeyError(line)

    def __iter__(self) -> Iterator[int]:
        return compress(count(), self.seen)

    def items(self) -> ItemsView[int, float]:
        return _LineItems(self)

    def slowest(self, number: int) -> list[tuple[int, float]]:
        """The ``number`` lines that took the most time, slowest first (the earlier line on a
        tie), as (line, seconds)."""
        best = heapq.nlargest(number, compress(zip(self.seconds, count(0, -1)), self.seen))
        return [(-line, seconds) for seconds, line in best]

    def __len__(self) -> int:
        return len(self.seen) - self.seen.count(0)

    def __repr__(self) -> str:
        return f"LineTimes({dict(self.items())!r})"


class _LineItems(ItemsView[int, float]):
    """The (line, seconds) pairs of :class:`LineTimes`, read straight from its arrays."""

    def __init__(self, times: LineTimes) -> None:
        super().__init__(times)
        self.times = times

    def __iter__(self) -> Iterator[tuple[int, float]]:
        return compress(zip(count(), self.times.seconds), self.times.seen)


@dataclass
class TimeResult:
    total_s: float = 0.0
    naive_s: float = 0.0
    by_kind: dict[str, float] = field(default_factory=lambda: defaultdict(float))
    by_tool: dict[int, float] = field(default_factory=lambda: defaultdict(float))
    by_line: LineTimes = field(default_factory=LineTimes)
    segments: int = 0
    length: float = 0.0
    # Where the moves go past the machine's travel (:attr:`Machine.travel`), axis and side.
    limits: tuple[Excess, ...] = ()
    _slowest: dict[int, list[tuple[int, float]]] = field(default_factory=dict, repr=False,
                                                        compare=False)

    def slowest(self, count: int) -> list[tuple[int, float]]:
        """The ``count`` lines that took the most time, slowest first (the earlier line on a
        tie), as (line, seconds); worked out once for each count."""
        if count not in self._slowest:
            self._slowest[count] = self.by_line.slowest(count)
        return self._slowest[count]


class Timer:
    """Collects finished segments and standstills into a :class:`TimeResult`, and hands each to
    ``on_segment`` and ``on_wait`` (if given) once it is counted."""

    def __init__(self, machine: Machine, on_segment: SegmentListener | None = None,
                 on_wait: WaitListener | None = None, toolpath: Toolpath | None = None) -> None:
        self.machine = machine
        self.on_segment = on_segment
        self.on_wait = on_wait
        self.result = TimeResult()
        self.planner = Planner(machine, self.segment)
        # A machine with a travel has the moves held against it on their way to the planner
        # (a toolpath the caller gives is theirs to watch: ``ngc plot --time``).
        self.watch: LimitWatch | None = None
        if toolpath is None and machine.travel:
            tee = Tee()
            start = machine.start_position
            toolpath = Toolpath(tee, inch_machine=machine.linear_units == "inch",
                                start=tuple(float(start.get(a, 0.0)) for a in AXES6))  # type: ignore[arg-type]
            self.watch = LimitWatch(machine.travel, toolpath)
            self.path = PathSink(machine, self.planner, self.wait, toolpath)
            tee.readers.extend((self.path, self.watch))
        else:
            self.path = PathSink(machine, self.planner, self.wait, toolpath)
        self.sink = self.path.toolpath
        self.last_kind = "feed"
        # time of the run of segments of one kind and one tool, not yet in by_kind and by_tool
        self.run_kind: str | None = None
        self.run_tool = 0
        self.run_time = 0.0

    def segment(self, seg: Segment) -> None:
        r = self.result
        if not self.planner.total <= MAX_SECONDS:
            raise TooLong(seg.line)
        r.segments += 1
        r.length += seg.length
        t = seg.time - seg.overlap  # the overlap is counted with the move before
        parts = seg.parts
        if seg.kind == BLEND and self.run_kind is not None:
            # a corner: of the kind and the tool of the move before it (the run in progress)
            self.run_time += t
        else:
            kind = self.last_kind if seg.kind == BLEND else seg.kind
            self.last_kind = kind
            if kind == self.run_kind and seg.tool == self.run_tool:
                self.run_time += t
            else:
                self._close_run()
                self.run_kind, self.run_tool, self.run_time = kind, seg.tool, t
            if seg.naive != math.inf:
                r.naive_s += seg.naive
        by_line = r.by_line
        if parts and len(parts) > 1:  # merged moves share the time by their lengths
            total = seg.parts_length
            by_line.spread(parts, t / total if total > 0.0 else t)
        else:
            by_line.add(seg.line, t)
        if self.on_segment is not None:
            self.on_segment(seg)

    def wait(self, kind: str, seconds: float, line: int) -> None:
        overhead = 0.0
        if kind == "dwell":
            overhead = 2.5 * self.machine.task_cycle if self.planner.total > 0 else 0.0
        t = seconds + overhead
        if t <= 0.0:
            return
        start = self.planner.total
        if not start + t <= MAX_SECONDS:
            raise TooLong(line)
        self.planner.clock += t
        r = self.result
        r.by_kind[kind] += t
        r.by_line.add(line, t)
        r.by_tool[self.path.tool] += t
        r.naive_s += seconds
        if self.on_wait is not None:
            self.on_wait(kind, start, t, line)

    def _close_run(self) -> None:
        if self.run_kind is not None:
            r = self.result
            r.by_kind[self.run_kind] += self.run_time
            r.by_tool[self.run_tool] += self.run_time
            self.run_kind, self.run_time = None, 0.0

    def finish(self) -> TimeResult:
        self.sink.flush()
        self._close_run()
        self.result.total_s = self.planner.total
        if self.watch is not None:
            self.result.limits = tuple(self.watch.excesses())
        return self.result


def time_text(text: str, machine: Machine = DEFAULT_MACHINE) -> TimeResult:
    """Time the program ``text`` on ``machine``; raises :class:`NgcError` on a program error.

    >>> round(time_text("G61.1 G1 X100 F6000\\nM2\\n").total_s, 6)
    1.1
    """
    return time_lines(text.splitlines(keepends=True), machine)


def time_lines(lines: Iterable[str], machine: Machine = DEFAULT_MACHINE,
               interpreter: Callable[[Sink], Interpreter] = Interpreter, *,
               file: str | None = None, reader: ProgramReader | None = None,
               on_segment: SegmentListener | None = None,
               on_wait: WaitListener | None = None) -> TimeResult:
    """Time the program ``lines`` on ``machine``, run by ``interpreter(sink)`` (the machine
    inputs of a command line: :func:`ngc.options.new_interpreter`).  ``file`` and ``reader`` are
    :meth:`Interpreter.run`'s; ``on_segment`` and ``on_wait`` are :class:`Timer`'s.  Raises
    :class:`NgcError` on the first program error."""
    timer = Timer(machine, on_segment, on_wait)
    interp = interpreter(timer.sink)
    interp.startup()
    interp.run(lines, file=file, reader=reader)
    return timer.finish()


def time_file(path: str, machine: Machine = DEFAULT_MACHINE,
              options: MachineOptions | None = None, *,
              on_segment: SegmentListener | None = None,
              on_wait: WaitListener | None = None) -> TimeResult:
    """Time the program file ``path`` (``-``: standard input) on ``machine``, with the machine
    inputs ``options`` (``-i``, ``-t``, ``-v``, ...) loaded as ``ngc check`` loads them
    (:func:`ngc.options.load_setup`; the program writes no file).  Raises ``OSError`` if the
    file cannot be opened, :class:`NgcConfigError` for a machine input and :class:`NgcError` for
    a program error."""
    inputs = MachineOptions() if options is None else options
    setup = load_setup(inputs)
    name = "<stdin>" if path == "-" else path
    with text_reader(_open_binary(path)) as handle:
        return time_lines(handle, machine,
                          lambda sink: new_interpreter(sink, inputs, setup, write_files=False),
                          file=name, reader=handle, on_segment=on_segment, on_wait=on_wait)


def _open_binary(path: str) -> BinaryIO:
    """The program file ``path`` (``-``: standard input, left open) as bytes."""
    if path == "-":
        return open(sys.stdin.fileno(), "rb", closefd=False)
    return open(path, "rb")
