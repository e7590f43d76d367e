"""What a program does, summed up from its canonical operations: move counts, rapid and feed
path lengths, and the extents of the toolpath (``ngc check``).

The summary reads the toolpath (:mod:`ngc.toolpath`, DESIGN.md "Data flow"): each move's start
and end in program coordinates and units, which the toolpath re-expresses when the units, the
offsets, the rotation or the tool length offset change.  Lengths and extents are kept in the
current program units and converted when the units change, so a program that never changes units
is summed without any conversion (and its rounding noise).  Extents are in program coordinates.
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any, Literal, overload

from ..canon import ops
from ..canon.ops import Op, Sink
from ..errors import NgcError
from ..interp.interpreter import Interpreter
from ..interp.source import ProgramReader, open_text_program
from ..toolpath.frame import Pos
from ..toolpath.limits import Excess, FastFeed, FeedWatch, LimitWatch
from ..toolpath.tracker import RAPID, ArcMove, Cubics, Tee, Toolpath
from .check_common import error_record, headline
from .common import defined_names
from .usage import Usage, UsageSummary, usage_lines, usage_record

if TYPE_CHECKING:
    from ..engine import Setup as EngineSetup
    from ..planner.config import SoftLimits
    from .check_engine import EngineCheckResult

MM_PER_UNIT = {"CANON_UNITS_MM": 1.0, "CANON_UNITS_INCHES": 25.4, "CANON_UNITS_CM": 10.0}
UNIT_NAMES = {"CANON_UNITS_MM": "mm", "CANON_UNITS_INCHES": "inch", "CANON_UNITS_CM": "cm"}
_CANON_UNITS = {name: canon for canon, name in UNIT_NAMES.items()}

TAU = 2.0 * math.pi
QUADRANT_ANGLES = (0.0, 0.5 * math.pi, math.pi, 1.5 * math.pi)

Point = tuple[float, float, float]


@dataclass(frozen=True)
class Extents:
    """The axis-aligned box around a toolpath: lowest and highest X, Y, Z."""

    low: Point
    high: Point


@dataclass(frozen=True)
class Summary:
    """Counts and lengths of a program's motion.

    Lengths and extents are in ``units`` (``"mm"``, ``"inch"`` or ``"cm"``), the length units in
    effect when the program ended; ``mixed_units`` says the units changed after the first move
    (everything is converted).  ``extents`` bounds the end points of the moves and the extreme
    points of the arcs (not the point the machine starts from); ``None`` when nothing moved.
    """

    units: str
    traverses: int
    feeds: int
    arcs: int
    rapid_length: float
    feed_length: float
    extents: Extents | None
    mixed_units: bool
    usage: UsageSummary = field(default_factory=UsageSummary)  # the tools, feeds and speeds

    @property
    def moves(self) -> int:
        """All motion operations: traverses, straight feeds and arcs."""
        return self.traverses + self.feeds + self.arcs


class Summarizer:
    """A reader of the toolpath that keeps only a running summary (constant memory, any
    program length).  It is a canon sink too: ``emit`` (and ``emit_move``) hand operations to
    its :class:`~ngc.toolpath.tracker.Toolpath`, ``self.toolpath``, whose moves it sums in
    program coordinates and units."""

    __slots__ = (
        "_arcs",
        "_feed_length",
        "_feeds",
        "_high",
        "_low",
        "_mm_per_unit",
        "_rapid_length",
        "_stay",
        "_traverses",
        "_units",
        "_units_changed",
        "_usage",
        "_waiting",
        "toolpath",
    )

    def __init__(self, toolpath: Toolpath | None = None) -> None:
        self.toolpath = Toolpath(self) if toolpath is None else toolpath
        self._units = "CANON_UNITS_MM"
        self._units_changed = False  # after something moved
        self._mm_per_unit = 1.0
        self._traverses = self._feeds = self._arcs = 0
        # in current program units, like the current point
        self._rapid_length = self._feed_length = 0.0
        self._low = [math.inf] * 3
        self._high = [-math.inf] * 3
        # The axes still where the program found them: such an axis enters the extents when a
        # move changes it (its end) or a cut starts with it there, not from the start position
        # alone (a first ``G0 Z5`` does not put the machine origin's X and Y in the extents).
        self._waiting: tuple[int, ...] = (0, 1, 2)
        self._stay: Sequence[float] = (0.0, 0.0, 0.0)  # where they are, after the last rapid
        self._usage = Usage()

    # -- the sink protocol ------------------------------------------------------------------------
    def emit(self, op: Op, label: str, line: int) -> None:
        self.toolpath.emit(op, label, line)

    def emit_move(self, kind: type, fields: Sequence[Any], label: str, line: int) -> None:
        self.toolpath.emit_move(kind, fields, label, line)

    def print_text(self, text: str) -> None:
        """``(PRINT,...)`` output does not move the machine."""

    def flush(self) -> None:
        """Nothing is held back."""

    def add(self, op: Op) -> None:
        """Follow one canonical operation."""
        self.toolpath.emit(op, "", 0)

    def summary(self) -> Summary:
        """The summary of everything seen so far, in the current units."""
        extents = None
        low, high = list(self._low), list(self._high)
        if self._waiting and self._traverses:  # (an axis no move changed: where it stayed)
            for i in self._waiting:
                low[i] = high[i] = self._stay[i]
        if low[0] <= high[0] and low[1] <= high[1] and low[2] <= high[2]:
            extents = Extents((low[0], low[1], low[2]), (high[0], high[1], high[2]))
        return Summary(
            units=UNIT_NAMES.get(self._units, self._units),
            traverses=self._traverses,
            feeds=self._feeds,
            arcs=self._arcs,
            rapid_length=self._rapid_length,
            feed_length=self._feed_length,
            extents=extents,
            mixed_units=self._units_changed,
            usage=self._usage.summary(self._mm_per_unit),
        )

    # -- the toolpath's consumer protocol ---------------------------------------------------------
    def straight(self, kind: str, start: Pos, end: Pos, line: int) -> None:
        """A straight move, summed in program coordinates (a probe counts as a feed to its
        programmed point: where it stops is not in the call)."""
        tp = self.toolpath
        p, q = tp.prog, tp.prog_end
        length = math.dist((p[0], p[1], p[2]), (q[0], q[1], q[2]))
        if kind is RAPID:
            self._traverses += 1
            self._rapid_length += length
            if self._waiting:
                self._arrive(p, q)
                return
        else:
            self._feeds += 1
            self._feed_length += length
            self._usage.cut(length * self._mm_per_unit, tp.tool)
            if self._waiting:
                self._waiting = ()
                self._include(p)
        self._include(q)

    def arc(self, arc: ArcMove, line: int) -> None:
        self._arcs += 1
        first, second, axis = self.toolpath.plane
        op, pos = arc.op, arc.prog_start
        if self._waiting:
            self._waiting = ()
            self._include(pos)
        extremes, length = arc_bounds((pos[first], pos[second], pos[axis]),
                                      (op.first_end, op.second_end, op.axis_end_point),
                                      (op.first_axis, op.second_axis), op.rotation)
        xyz = [0.0, 0.0, 0.0]
        for p in extremes:
            xyz[first], xyz[second], xyz[axis] = p
            self._include(xyz)
        self._include(self.toolpath.prog_end)
        self._feed_length += length
        self._usage.cut(length * self._mm_per_unit, self.toolpath.tool)

    def nurbs(self, curve: ops.NurbsFeed, start: Pos, line: int) -> None:
        """A curve is not counted (its end is where the next move starts)."""

    def tap(self, start: Pos, bottom: Pos, line: int) -> None:
        """A rigid tap is not counted (it ends where it started)."""

    def bezier(self, cubics: Cubics, motion: str, start: Pos, line: int) -> None:
        """Engine programs are summed by :mod:`ngc.commands.check_engine`."""

    def other(self, op: Op, line: int) -> None:
        if type(op) is ops.UseLengthUnits:
            self._length_units(op)
        else:
            self._usage.see(op, self._mm_per_unit)

    def finish(self) -> None:
        """Nothing is held back."""

    def _length_units(self, op: ops.UseLengthUnits) -> None:
        """The totals so far in the new units (the toolpath re-expresses the current point)."""
        new_mm_per_unit = MM_PER_UNIT.get(op.units, 1.0)
        ratio = self._mm_per_unit / new_mm_per_unit
        if ratio != 1.0:
            self._units_changed |= self._traverses + self._feeds + self._arcs > 0
            self._low = [v * ratio for v in self._low]
            self._stay = [v * ratio for v in self._stay]
            self._high = [v * ratio for v in self._high]
            self._rapid_length *= ratio
            self._feed_length *= ratio
        self._mm_per_unit = new_mm_per_unit
        self._units = op.units

    def _arrive(self, start: Sequence[float], end: Sequence[float]) -> None:
        """A rapid while some axes are still where the program found them: those it changes
        enter the extents from its end; the others wait on."""
        low, high = self._low, self._high
        waiting = []
        for i in range(3):
            if i in self._waiting and end[i] == start[i]:
                waiting.append(i)
                continue
            v = end[i]
            if v < low[i]:
                low[i] = v
            if v > high[i]:
                high[i] = v
        self._waiting = tuple(waiting)
        self._stay = end

    def _include(self, p: Sequence[float]) -> None:
        low, high = self._low, self._high
        x, y, z = p[0], p[1], p[2]
        if x < low[0]:
            low[0] = x
        if x > high[0]:
            high[0] = x
        if y < low[1]:
            low[1] = y
        if y > high[1]:
            high[1] = y
        if z < low[2]:
            low[2] = z
        if z > high[2]:
            high[2] = z


@dataclass(frozen=True)
class Arc:
    """An ARC_FEED in plane coordinates: (first, second, axis) start and end, the center in the
    plane, and rs274's rotation (positive: counterclockwise turns, negative: clockwise).

    Start and end may lie at different radii (LinuxCNC accepts a slight spiral); the radius then
    changes linearly with the angle, as does the helix axis coordinate.

    >>> quarter = Arc(start=(1.0, 0.0, 0.0), end=(0.0, 1.0, 0.0), center=(0.0, 0.0), rotation=1)
    >>> round(quarter.length(), 6) == round(math.pi / 2, 6)
    True
    >>> [tuple(round(v, 6) for v in p) for p in quarter.extremes()]
    [(1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]
    """

    start: Point
    end: Point
    center: tuple[float, float]
    rotation: int

    def sweep(self) -> float:
        """The angle travelled, in radians (always positive; a full circle when start == end)."""
        return _sweep(self.start, self.end, self.center, self.rotation)

    def length(self) -> float:
        """Path length, helix rise included."""
        return arc_bounds(self.start, self.end, self.center, self.rotation)[1]

    def extremes(self) -> list[Point]:
        """The points where the arc crosses the 0°, 90°, 180° and 270° directions of its
        center: with the end points, they bound the arc."""
        return arc_bounds(self.start, self.end, self.center, self.rotation)[0]


def _sweep(start: Point, end: Point, center: tuple[float, float], rotation: int) -> float:
    c1, c2 = center
    a0 = math.atan2(start[1] - c2, start[0] - c1)
    a1 = math.atan2(end[1] - c2, end[0] - c1)
    delta = (a1 - a0) % TAU if rotation > 0 else (a0 - a1) % TAU
    if delta == 0.0:
        delta = TAU
    return delta + TAU * (max(abs(rotation), 1) - 1)


def arc_bounds(start: Point, end: Point, center: tuple[float, float],
               rotation: int) -> tuple[list[Point], float]:
    """An :class:`Arc`'s extremes (see :meth:`Arc.extremes`) and its length, worked out at
    once (the summary's hot path for arc-heavy programs)."""
    c1, c2 = center
    s1, s2, z0 = start
    z1 = end[2]
    r0 = math.hypot(s1 - c1, s2 - c2)
    r1 = math.hypot(end[0] - c1, end[1] - c2)
    a0 = math.atan2(s2 - c2, s1 - c1)
    sweep = _sweep(start, end, center, rotation)
    direction = 1.0 if rotation > 0 else -1.0
    points = []
    for theta in QUADRANT_ANGLES:
        travelled = ((theta - a0) * direction) % TAU
        if travelled > sweep:
            continue
        t = travelled / sweep
        r = r0 + (r1 - r0) * t
        points.append((c1 + r * math.cos(theta), c2 + r * math.sin(theta), z0 + (z1 - z0) * t))
    return points, math.hypot(sweep * (r0 + r1) / 2.0, z1 - z0)


def summarize(operations: Iterable[Op]) -> Summary:
    """Sum up a sequence of canonical operations.

    >>> from ngc.canon.ops import ArcFeed, StraightFeed, StraightTraverse
    >>> s = summarize([
    ...     StraightTraverse(10.0, 0.0, 0.0, 0.0, 0.0, 0.0),
    ...     StraightFeed(10.0, 10.0, 0.0, 0.0, 0.0, 0.0),
    ...     ArcFeed(0.0, 0.0, 5.0, 5.0, 1, 0.0, 0.0, 0.0, 0.0),  # half circle back to X0 Y0
    ... ])
    >>> s.moves, s.units, s.rapid_length, round(s.feed_length, 4)
    (3, 'mm', 10.0, 32.2144)
    >>> [round(v, 4) for v in s.extents.low + s.extents.high]  # the arc bulges past X0 and Y10
    [-2.0711, 0.0, 0.0, 10.0, 12.0711, 0.0]
    """
    summarizer = Summarizer()
    for op in operations:
        summarizer.add(op)
    return summarizer.summary()


@dataclass(frozen=True)
class CheckResult:
    """The outcome of checking one program file: its line count, the summary of what ran (up to
    the error, if there is one) and the first error, or ``None``."""

    path: str
    lines: int
    summary: Summary
    error: NgcError | None
    limits: tuple[Excess, ...] = ()  # where the moves go past the machine's soft limits
    machine_units: str = "mm"
    subroutines: tuple[str, ...] = ()  # those a program that moved nothing only defined
    diameter: bool = False  # the program ends in a lathe's diameter mode (G7): X as a diameter
    fast_feeds: tuple[FastFeed, ...] = ()  # feeds past the axes' MAX_VELOCITY (a note)
    dialect = "linuxcnc"  # (an engine program's is an ngc.commands.check_engine.EngineCheckResult)

    @property
    def ok(self) -> bool:
        return self.error is None and not self.limits


def _quiet_interpreter(sink: Sink) -> Interpreter:
    return Interpreter(sink, write_files=False)


def check_lines(
    lines: Iterable[str],
    name: str,
    new_interpreter: Callable[[Sink], Interpreter] = _quiet_interpreter,
    *,
    reader: ProgramReader | None = None,
    limits: SoftLimits | None = None,
    machine_units: str = "mm",
    speeds: tuple[Mapping[str, float], float | None] | None = None,
) -> CheckResult:
    """Run a program, given as its lines, through an interpreter, keeping only a summary of its
    motion; ``name`` is the file name errors carry.  ``new_interpreter`` makes the interpreter
    for a given sink; the default writes no file (log comments emit their calls only).

    Errors in the program are returned in :attr:`CheckResult.error` (interpretation stops at the
    first one); the lines after it are counted.

    ``limits`` are the machine's soft limits (:func:`ngc.planner.config.soft_limits`, in
    ``machine_units``): the moves that go past them are in :attr:`CheckResult.limits`, and the
    program is not ``ok``.  ``speeds`` are the axes' MAX_VELOCITY and the path's
    MAX_LINEAR_VELOCITY (:func:`ngc.planner.config.axis_speeds`, in ``machine_units``): the feeds
    that ask for more are in :attr:`CheckResult.fast_feeds` (a note: the program stays ``ok``).

    >>> result = check_lines(["G21 F100", "G1 X3", "G1 Y4", "M2"], "square.ngc")
    >>> result.ok, result.lines, result.summary.feeds, result.summary.feed_length
    (True, 4, 2, 7.0)
    >>> past = check_lines(["G21 G0 X500 Y-5", "M2"], "far.ngc", limits={"X": (0.0, 100.0)})
    >>> past.ok, past.limits[0].text("mm")
    (False, 'Program exceeds machine maximum on axis X: 400.0000 mm past 100, first at line 1')
    """
    watch: LimitWatch | None = None
    feeds: FeedWatch | None = None
    if limits or (speeds and (speeds[0] or speeds[1] is not None)):
        tee = Tee()
        toolpath = Toolpath(tee, inch_machine=machine_units == "inch")
        summarizer = Summarizer(toolpath)
        tee.readers.append(summarizer)
        if limits:
            watch = LimitWatch(limits, toolpath)
            tee.readers.append(watch)
        if speeds:
            feeds = FeedWatch(speeds[0], speeds[1], toolpath)
            tee.readers.append(feeds)
    else:
        summarizer = Summarizer()
    counted = _CountedLines(lines)
    error: NgcError | None = None
    interp = new_interpreter(summarizer.toolpath)
    interp.startup()
    try:
        interp.run(counted, file=name, reader=reader)
    except NgcError as exc:
        error = exc
    summary = summarizer.summary()
    slots = interp.machine.state.tools.slots
    summary = replace(summary, usage=summary.usage.with_tool_data(
        lambda number: next((e for e in slots[1:] if e.number == number), None),
        MM_PER_UNIT[_CANON_UNITS[summary.units]] if summary.units in _CANON_UNITS else 1.0))
    defined: tuple[str, ...] = ()
    if error is None and summary.moves == 0:
        defined = defined_names(interp)
    return CheckResult(path=name, lines=counted.total(), summary=summary,
                       error=error, limits=() if watch is None else tuple(watch.excesses()),
                       machine_units=machine_units, subroutines=defined,
                       diameter=interp.machine.state.lathe_diameter,
                       fast_feeds=() if feeds is None else tuple(feeds.excesses()))


@overload
def check_file(path: str | os.PathLike[str], dialect: Literal["linuxcnc"], *,
               setup: None = None) -> CheckResult: ...


@overload
def check_file(path: str | os.PathLike[str], dialect: Literal["engine"], *,
               setup: EngineSetup | None = None) -> EngineCheckResult: ...


@overload
def check_file(path: str | os.PathLike[str], dialect: str | None = None, *,
               setup: EngineSetup | None = None) -> CheckResult | EngineCheckResult: ...


def check_file(path: str | os.PathLike[str], dialect: str | None = None, *,
               setup: EngineSetup | None = None) -> CheckResult | EngineCheckResult:
    """Run a program file through an interpreter that writes no file, keeping only a summary of
    its motion (see :func:`check_lines`).  The file is read as UTF-8 (a byte that is not UTF-8 is
    kept as a lone surrogate, see :mod:`ngc.canon.jsonl`); a leading byte-order mark is skipped.

    ``dialect`` is ``"linuxcnc"`` or ``"engine"``; None: the one the program's first line names
    (:mod:`ngc.dialects`), else ``"linuxcnc"``.  An engine program gives an
    :class:`ngc.commands.check_engine.EngineCheckResult` (the same ``path``, ``lines``, ``error`` and
    ``ok``, and an :class:`~ngc.commands.check_engine.EngineSummary`), run on the machine ``setup``
    describes (:func:`ngc.engine.read_setup`; None: the default machine).  An unknown dialect,
    or a ``setup`` for a LinuxCNC program, is a ``ValueError``.

    Raises ``OSError`` if the file cannot be read; errors in the program are returned in
    :attr:`CheckResult.error` (interpretation stops at the first one).

    >>> import pathlib, tempfile
    >>> program = pathlib.Path(tempfile.mkdtemp()) / "square.ngc"
    >>> _ = program.write_text("G20 F10\\nG1 X1\\nY1\\nX0\\nY0\\nM2\\n")
    >>> result = check_file(program)
    >>> result.ok, result.lines, result.summary.feeds, result.summary.feed_length
    (True, 6, 4, 4.0)
    >>> _ = program.write_text("G1 X1\\nM2\\n")
    >>> error = check_file(program).error
    >>> error.line, error.message
    (1, 'Cannot do g1 with zero feed rate')
    >>> _ = program.write_text("(dialect: engine)\\nF10\\nfeed X3 Y4\\n")
    >>> result = check_file(program)
    >>> result.dialect, result.summary.segments["feed"], result.summary.time
    ('engine', 1, 0.5)
    """
    from .. import dialects

    name = os.fspath(path)
    chosen = dialects.checked(dialect) or dialects.of_file(name)
    if chosen == dialects.ENGINE:
        from . import check_engine as engine_report

        return engine_report.check_file(name, setup)
    if setup is not None:
        raise ValueError(dialects.API_SETUP_IS_ENGINES)
    with open_text_program(name) as reader:
        return check_lines(reader, name, reader=reader)


class _CountedLines:
    """The lines of a program, counting those read; :meth:`total` reads and counts the rest."""

    def __init__(self, lines: Iterable[str]) -> None:
        self._lines = iter(lines)
        self.count = 0

    def __iter__(self) -> Iterator[str]:
        for line in self._lines:
            self.count += 1
            yield line

    def total(self) -> int:
        return self.count + sum(1 for _ in self._lines)


def render(result: CheckResult) -> str:
    """``ngc check``'s report on one file: a paragraph with the line count, the moves, the path
    lengths and the extents (the error itself goes to stderr)."""
    s = result.summary
    head = headline(result.path, result.error)
    if result.error is None and result.limits:
        head = f"{result.path}: past the machine's soft limits"
    elif result.lines == 0:
        head = f"{result.path}: the file is empty"
    paragraph = [
        f"{head}, {result.lines} lines",
        f"  moves: {s.moves} ({s.traverses} traverse, {s.feeds} feed, {s.arcs} arc)",
        f"  rapid length: {_length_text(s.rapid_length, s.units)}, "
        f"feed length: {_length_text(s.feed_length, s.units)}",
        f"  extents: {_extents_text(s, result.diameter)}",
    ]
    if s.mixed_units:
        paragraph.append(f"  (the program changes length units; all lengths are in {s.units})")
    paragraph.extend(usage_lines(s.usage, s.units))
    paragraph.extend(f"  {excess.text(result.machine_units)}" for excess in result.limits)
    paragraph.extend(f"  {fast.text(result.machine_units)}" for fast in result.fast_feeds)
    if result.subroutines:
        paragraph.append(f"  no moves: the file defines {', '.join(result.subroutines)} (a "
                         "subroutine file is checked through a program that calls it)")
    return "\n".join(paragraph)


def _length_text(length: float, units: str) -> str:
    """A path length; one past a double's range (moves between coordinates near 1e308) is said
    to be so rather than printed as inf or nan (JSON has null)."""
    if math.isfinite(length):
        return f"{length:.4f} {units}"
    return f"past a double's range ({units})"


def _extents_text(s: Summary, diameter: bool = False) -> str:
    """The extents; X as the program gives it (a diameter in a lathe's diameter mode, G7: twice
    the radius canon moves along)."""
    if s.extents is None:
        return "none (no motion)"
    lo, hi = list(s.extents.low), list(s.extents.high)
    names = ["X", "Y", "Z"]
    if diameter:
        lo[0], hi[0], names[0] = 2.0 * lo[0], 2.0 * hi[0], "X (diameter)"
    return "  ".join(f"{a} {lo[i]:.4f} .. {hi[i]:.4f}" for i, a in enumerate(names)) + f" {s.units}"


def _finite_or_none(value: float) -> float | None:
    """A length for JSON: ``None`` (null) for one past a double's range (as the text says)."""
    return value if math.isfinite(value) else None


def record(result: CheckResult) -> dict[str, object]:
    """``ngc check --format json``'s object for one file (see ``README.md``)."""
    s = result.summary
    extents = None
    if s.extents is not None:
        extents = {"low": list(s.extents.low), "high": list(s.extents.high)}
    summary = {
        "units": s.units, "moves": s.moves, "traverses": s.traverses, "feeds": s.feeds,
        "arcs": s.arcs, "rapid_length": _finite_or_none(s.rapid_length),
        "feed_length": _finite_or_none(s.feed_length),
        "extents": extents, "mixed_units": s.mixed_units, **usage_record(s.usage),
    }  # fmt: skip
    out: dict[str, object] = {
        "file": result.path, "ok": result.ok, "lines": result.lines,
        "error": None if result.error is None else error_record(result.error),
        "summary": summary,
    }  # fmt: skip
    if result.diameter:
        out["x_as_diameter"] = True  # (the extents' X stay radii, as canon gives them)
    if result.limits:
        out["soft_limits"] = [{"axis": e.axis, "side": e.side, "limit": e.limit, "by": e.by,
                               "line": e.line, "units": result.machine_units}
                              for e in result.limits]
    if result.fast_feeds:
        out["fast_feeds"] = [{"axis": f.axis, "asked": f.asked, "limit": f.limit,
                              "line": f.line, "units": result.machine_units}
                             for f in result.fast_feeds]
    return out
