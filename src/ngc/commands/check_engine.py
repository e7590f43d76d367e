"""What an engine-dialect program does, summed up from its operations (``ngc check`` on an
engine program, :func:`ngc.check_file`): segments by motion kind, dwells, time, path length and
the extents of X Y Z, shaped like the LinuxCNC summary of :mod:`ngc.commands.check`.

A consumer of the engine's operations (:mod:`ngc.engine`), never of its state: an
``EngineSegment`` gives, per axis it names, the four Bézier control points of the axis's
position over the segment's time, in program units, and its duration in seconds.  So:

* the time is the sum of the segments' durations and the dwells' seconds, also by kind (each
  motion kind, and ``dwell``);
* the path length is that of the curve X Y Z draw together (:func:`ngc.engine.bezier.length`),
  by motion kind;
* the extents are, per axis X Y Z, the lowest and highest position the axis takes in the
  segments that name it: the ends of each cubic and its turning points (the roots of its
  derivative).  An axis no segment names has none (its position is not in the operations).

Lengths and extents are in the program's units at its end (``UNITS`` changes are followed, as in
:mod:`ngc.commands.check`); other operations are counted by nothing.
"""

from __future__ import annotations

import math
import os
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

from ..budget import DEFAULT_MAX_ITERATIONS
from ..errors import NgcError
from .check_common import error_record, headline

if TYPE_CHECKING:
    from ..engine import Op, Setup
    from ..engine.bezier import Cubic

MOTIONS = ("rapid", "feed", "arc", "probe", "run")  # the kinds always shown, in this order
DWELL = "dwell"
XYZ = "XYZ"
MM_PER_UNIT = {"mm": 1.0, "inch": 25.4}


@dataclass(frozen=True)
class EngineSummary:
    """Counts, times, lengths and extents of an engine program's motion.

    ``segments`` and ``lengths`` are by motion kind (``rapid``, ``feed``, ``arc``, ``probe``,
    ``run``, then any other kind in the order met), ``times`` by the same kinds and ``dwell``.
    Lengths and extents are in ``units`` (``"mm"`` or ``"inch"``), the units in effect at the
    end; ``mixed_units`` says they changed after the first segment (all is converted).
    ``extents`` maps each of X Y Z that some segment moves to its (lowest, highest) position.
    """

    units: str
    segments: Mapping[str, int]
    dwells: int
    times: Mapping[str, float]
    lengths: Mapping[str, float]
    extents: Mapping[str, tuple[float, float]]
    mixed_units: bool

    @property
    def segment_count(self) -> int:
        return sum(self.segments.values())

    @property
    def time(self) -> float:
        """Seconds: every segment's duration and every dwell."""
        return sum(self.times.values())

    @property
    def length(self) -> float:
        """The path length of X Y Z over all segments."""
        return sum(self.lengths.values())


@dataclass(frozen=True)
class EngineCheckResult:
    """The outcome of checking one engine-dialect program: its line count, the summary of what
    ran (up to the error, if there is one) and the first error, or ``None``."""

    path: str
    lines: int
    summary: EngineSummary
    error: NgcError | None
    dialect = "engine"

    @property
    def ok(self) -> bool:
        return self.error is None


def cubic_range(c: Cubic) -> tuple[float, float]:
    """The lowest and highest value of a cubic Bézier over [0, 1]: its ends and the points where
    its derivative is zero.

    >>> cubic_range((0.0, 1.0, 1.0, 0.0))  # rises to 0.75 at t = 0.5 and comes back
    (0.0, 0.75)
    """
    from ..engine.bezier import point

    values = [c[0], c[3]]
    values.extend(point(c, t) for t in _turning_points(c))
    return min(values), max(values)


def _turning_points(c: Cubic) -> list[float]:
    """The t in (0, 1) where the derivative is zero: it is 3 times
    ``a(1-t)^2 + 2b(1-t)t + ct^2`` with a, b, c the control points' differences, a quadratic
    ``qa t^2 + qb t + qc``.  Its roots are taken the stable way (``q / qa`` and ``qc / q``), so a
    nearly symmetric arc, whose ``qa`` is rounding noise, still gets its top at t = 1/2."""
    a, b, c2 = c[1] - c[0], c[2] - c[1], c[3] - c[2]
    qa, qb, qc = a - 2.0 * b + c2, 2.0 * (b - a), a
    disc = qb * qb - 4.0 * qa * qc
    if disc < 0.0:
        return []
    q = -0.5 * (qb + math.copysign(math.sqrt(disc), qb))
    roots = [q / qa] if qa != 0.0 else []
    if q != 0.0:
        roots.append(qc / q)
    return [t for t in roots if 0.0 < t < 1.0]


class EngineSummarizer:
    """Follows engine operations one at a time, keeping only the running summary."""

    def __init__(self) -> None:
        self._units = "mm"
        self._units_changed = False
        self._segments: dict[str, int] = dict.fromkeys(MOTIONS, 0)
        self._dwells = 0
        self._times: dict[str, float] = dict.fromkeys((*MOTIONS, DWELL), 0.0)
        self._lengths: dict[str, float] = dict.fromkeys(MOTIONS, 0.0)  # current units
        self._extents: dict[str, list[float]] = {}  # axis -> [low, high], current units

    def add(self, op: Op) -> None:
        from ..engine import Dwell, EngineSegment, ModeChange

        if isinstance(op, EngineSegment):
            self._segment(op)
        elif isinstance(op, Dwell):
            self._dwells += 1
            self._times[DWELL] += op.seconds
        elif isinstance(op, ModeChange) and op.name == "UNITS":
            self._change_units(str(op.value))

    def _segment(self, op: Op) -> None:
        from ..engine import EngineSegment
        from ..engine.bezier import length

        assert isinstance(op, EngineSegment)
        kind = op.motion
        self._segments[kind] = self._segments.get(kind, 0) + 1
        self._times[kind] = self._times.get(kind, 0.0) + op.duration
        curves = [op.axes[a] for a in XYZ if a in op.axes]
        self._lengths[kind] = self._lengths.get(kind, 0.0) + (length(curves) if curves else 0.0)
        for axis in XYZ:
            if axis in op.axes:
                low, high = cubic_range(op.axes[axis])
                box = self._extents.setdefault(axis, [low, high])
                box[0], box[1] = min(box[0], low), max(box[1], high)

    def _change_units(self, units: str) -> None:
        """Lengths and extents so far re-expressed in the new units."""
        ratio = MM_PER_UNIT.get(self._units, 1.0) / MM_PER_UNIT.get(units, 1.0)
        if ratio != 1.0:
            self._units_changed |= sum(self._segments.values()) > 0
            self._lengths = {k: v * ratio for k, v in self._lengths.items()}
            self._extents = {k: [v[0] * ratio, v[1] * ratio] for k, v in self._extents.items()}
        self._units = units

    def summary(self) -> EngineSummary:
        return EngineSummary(
            units=self._units, segments=dict(self._segments), dwells=self._dwells,
            times=dict(self._times), lengths=dict(self._lengths),
            extents={a: (v[0], v[1]) for a, v in sorted(self._extents.items())},
            mixed_units=self._units_changed)


def summarize(ops: Iterable[Op]) -> EngineSummary:
    """Sum up a sequence of engine operations.

    >>> from ngc.engine import run
    >>> s = summarize(run("move X3 Y4\\nF10\\nfeed X0 Y0\\ndwell P0.5\\n"))
    >>> s.segments["rapid"], s.segments["feed"], s.dwells, s.length, s.time
    (1, 1, 1, 10.0, 1.16)
    """
    summarizer = EngineSummarizer()
    for op in ops:
        summarizer.add(op)
    return summarizer.summary()


def check_text(text: str, name: str, setup: Setup | None = None,
               max_iterations: int = DEFAULT_MAX_ITERATIONS) -> EngineCheckResult:
    """Run an engine-dialect program given as text, keeping only a summary of its motion;
    ``name`` is the file name errors carry; ``max_iterations`` the work budget (segments and
    pecks).  The first error is returned, not raised.

    >>> result = check_text("F10\\nfeed X3\\nfrobnicate\\n", "p.ngc")
    >>> result.lines, round(result.summary.length, 9), result.error.line
    (3, 3.0, 3)
    """
    from ..dialects import engine_ops

    summarizer = EngineSummarizer()
    error: NgcError | None = None
    try:
        for op in engine_ops(text, setup, name, max_iterations):
            summarizer.add(op)
    except NgcError as exc:
        error = exc
    return EngineCheckResult(path=name, lines=len(text.splitlines()),
                             summary=summarizer.summary(), error=error)


def check_file(path: str | os.PathLike[str], setup: Setup | None = None) -> EngineCheckResult:
    """Run an engine-dialect program file (UTF-8, as :func:`ngc.dialects.read_text` reads it);
    raises ``OSError`` if it cannot be read."""
    from ..dialects import read_text

    name = os.fspath(path)
    with open(name, "rb") as handle:
        text = read_text(handle)
    return check_text(text, name, setup)


# -- ngc check's report ---------------------------------------------------------------------------
def _kinds(values: Mapping[str, float], number: str) -> str:
    return ", ".join(f"{kind} {format(v, number)}" for kind, v in values.items())


def render(result: EngineCheckResult) -> str:
    """``ngc check``'s paragraph on an engine program (the error itself goes to stderr)."""
    s = result.summary
    head = headline(result.path, result.error)
    counts = ", ".join(f"{n} {kind}" for kind, n in s.segments.items())
    paragraph = [
        f"{head}, {result.lines} lines (engine dialect)",
        f"  segments: {s.segment_count} ({counts}), dwells: {s.dwells}",
        f"  time: {s.time:.4f} s ({_kinds(s.times, '.4f')})",
        f"  length: {s.length:.4f} {s.units} ({_kinds(s.lengths, '.4f')})",
        f"  extents: {_extents_text(s)}",
    ]
    if s.mixed_units:
        paragraph.append(f"  (the program changes length units; all lengths are in {s.units})")
    return "\n".join(paragraph)


def _extents_text(s: EngineSummary) -> str:
    if not s.extents:
        return "none (no motion on X Y Z)"
    parts = [f"{a} {low:.4f} .. {high:.4f}" for a, (low, high) in s.extents.items()]
    return "  ".join(parts) + f" {s.units}"


def record(result: EngineCheckResult) -> dict[str, object]:
    """``ngc check --format json``'s object for an engine program: the LinuxCNC record's
    ``file``, ``ok``, ``lines``, ``error``, and ``"dialect": "engine"`` and its own summary."""
    s = result.summary
    extents = None
    if s.extents:
        extents = {"low": [s.extents[a][0] if a in s.extents else None for a in XYZ],
                   "high": [s.extents[a][1] if a in s.extents else None for a in XYZ]}
    summary = {
        "units": s.units, "segments": s.segment_count, "segments_by_motion": dict(s.segments),
        "dwells": s.dwells, "time": s.time, "time_by_kind": dict(s.times), "length": s.length,
        "length_by_motion": dict(s.lengths), "extents": extents, "mixed_units": s.mixed_units,
    }  # fmt: skip
    return {
        "file": result.path, "dialect": "engine", "ok": result.ok, "lines": result.lines,
        "error": None if result.error is None else error_record(result.error),
        "summary": summary,
    }  # fmt: skip
