"""``ngc view``'s page: one self-contained HTML file with the program's toolpath, its text, its
timing and its trajectory, and the viewer's script (three.js bundled with it, see ``js/``).

:func:`build_page` runs the program through the toolpath (:class:`~ngc.view.data.PathArrays`)
and, on a machine, through the planner (:class:`~ngc.planner.timing.Timer`: each line's start
time and greatest speed), then once more for the trajectory sampled at up to
:data:`MAX_SAMPLES` times (:class:`~ngc.planner.trajectory.TrajectoryWriter`).  The page is the
same bytes for the same program and inputs.
"""

from __future__ import annotations

import base64
import gzip
import json
import math
from array import array
from collections.abc import Callable, Sequence
from importlib import resources
from typing import TYPE_CHECKING, NamedTuple

from ..canon.ops import Sink
from ..engine.bezier import length, point
from ..errors import NgcError
from ..interp.interpreter import Interpreter
from ..toolpath.limits import LimitWatch
from ..toolpath.tracker import Tee, Toolpath
from .data import PathArrays

if TYPE_CHECKING:
    from ..engine import Setup as EngineSetup
    from ..planner.machine import Machine
    from ..planner.segment import Segment

MAX_SAMPLES = 20000  # trajectory samples in a page (the slider interpolates between them)
THREE_VERSION = "0.187.0"  # npm "three", as js/package.json pins it


class Page(NamedTuple):
    """The page's HTML, and what the command says about it: the segments drawn, the error the
    program stopped with, the machine's time."""

    html: bytes
    segments: int
    error: NgcError | None
    total_s: float | None
    warnings: tuple[str, ...]


class _Lines:
    """Each line's start time (the first planner segment's) and greatest speed."""

    def __init__(self, count: int) -> None:
        self.t0 = array("f", [math.nan]) * (count + 2)
        self.speed = array("f", bytes(4 * (count + 2)))

    def segment(self, seg: Segment) -> None:
        """A planner's segment (:class:`~ngc.planner.timing.Timer`'s listener)."""
        self.note(seg.line, seg.t0, seg.peak)

    def note(self, line: int, t0: float, speed: float) -> None:
        """A piece of line ``line`` starting at ``t0`` at up to ``speed``."""
        if 0 <= line < len(self.t0):
            if not self.t0[line] <= t0:  # (nan, or later)
                self.t0[line] = t0
            if speed > self.speed[line]:
                self.speed[line] = speed


class _Rows:
    """The trajectory writer's CSV rows, kept as t, x, y, z, line."""

    def __init__(self) -> None:
        self.values = array("f")
        self._header = True

    def write(self, text: str, /) -> int:
        if self._header:
            self._header = False
            return len(text)
        fields = text.split(",")
        self.values.extend((float(fields[0]), float(fields[1]), float(fields[2]),
                            float(fields[3]), float(fields[-1])))
        return len(text)


def build_page(text: str, name: str, new_interpreter: Callable[[Sink], Interpreter] | None, *,
               machine: Machine | None = None, units: str = "mm",
               engine: EngineSetup | None = None, engine_dialect: bool = False,
               max_iterations: int | None = None, view: str = "iso") -> Page:
    """The page of the program ``text`` (named ``name``), run by ``new_interpreter(sink)`` (or,
    ``engine_dialect``, by the engine with ``engine``: no interpreter); timed on ``machine`` if
    given (whose units are then the page's), else drawn in ``units``; ``view`` is the view it
    opens in (``iso``, or ``lathe``: Z to the right, X up)."""
    if machine is not None:
        units = machine.linear_units
    inch = units == "inch"
    where = {} if machine is None else machine.start_position
    x, y, z, a, b, c = (float(where.get(axis, 0.0)) for axis in "XYZABC")
    tee = Tee()
    toolpath = Toolpath(tee, inch_machine=inch, start=(x, y, z, a, b, c))
    path = PathArrays(toolpath, inch)
    tee.readers.append(path)
    count = text.count("\n") + 1
    lines = _Lines(count)
    timer = None
    watch = None
    if machine is not None and not engine_dialect:
        from ..planner.timing import Timer

        timer = Timer(machine, lines.segment, toolpath=toolpath)
        tee.readers.append(timer.path)
        if machine.travel:
            watch = LimitWatch(machine.travel, toolpath)
            tee.readers.append(watch)
    clock = _EngineClock(toolpath, lines) if engine_dialect else None
    error = _run(text, name, toolpath if clock is None else clock, new_interpreter, engine,
                 engine_dialect, max_iterations)
    result: object = None
    if clock is not None:
        result = clock.result()
    if timer is not None:
        try:
            result = timer.finish()
        except NgcError:  # (a program that stopped may leave the planner nothing to finish)
            result = None
    rows = _Rows()
    if clock is not None:
        rows = clock.trajectory()
    elif (result is not None and machine is not None and new_interpreter is not None
          and result.total_s > 0.0):  # type: ignore[attr-defined]
        rows = _trajectory(text, name, new_interpreter, machine,
                           result.total_s)  # type: ignore[attr-defined]
    warnings = tuple(e.text(units) for e in (watch.excesses() if watch else ()))
    meta = _meta(name, units, path, result, machine, error, toolpath, warnings,
                 "the engine's own times" if clock is not None else None)
    meta["view"] = view
    html = _html(name, meta, text, path, lines, rows)
    total = None if result is None else float(result.total_s)  # type: ignore[attr-defined]
    return Page(html, path.count, error, total, warnings)


def _run(text: str, name: str, toolpath: Toolpath | _EngineClock,
         new_interpreter: Callable[[Sink], Interpreter] | None, engine: EngineSetup | None,
         engine_dialect: bool, max_iterations: int | None) -> NgcError | None:
    try:
        if engine_dialect:
            from .. import dialects

            kwargs = {} if max_iterations is None else {"max_iterations": max_iterations}
            dialects.interpret_engine(text, toolpath, setup=engine, file=name, **kwargs)
        else:
            assert isinstance(toolpath, Toolpath) and new_interpreter is not None
            interp = new_interpreter(toolpath)
            interp.startup()
            interp.run(text.splitlines(), file=name)
    except NgcError as exc:
        return exc
    return None


class _Timed(NamedTuple):
    total_s: float
    by_tool: dict[int, float]


class _EngineClock:
    """The sink of an engine-dialect run that keeps its own times (each segment runs its
    duration, each dwell its seconds: what ``ngc check`` sums) before handing each operation to
    the toolpath: each line's start and greatest speed, and the trajectory along the segments'
    cubics."""

    def __init__(self, toolpath: Toolpath, lines: _Lines) -> None:
        self.toolpath = toolpath
        self.lines = lines
        self.t = 0.0
        self.starts = array("d")
        self.pieces: list[tuple[float, list[tuple[float, float, float, float]], int]] = []

    def emit(self, op: object, label: str, line: int) -> None:
        from ..engine import Dwell, EngineSegment

        if isinstance(op, EngineSegment):
            held = self.toolpath.pos
            cubics = [tuple(op.axes[a]) if a in op.axes else (held[i],) * 4
                      for i, a in enumerate("XYZ")]
            duration = max(op.duration, 0.0)
            speed = length(cubics) / duration if duration > 0.0 else 0.0  # type: ignore[arg-type]
            self.lines.note(line, self.t, speed)
            self.starts.append(self.t)
            self.pieces.append((duration, cubics, line))  # type: ignore[arg-type]
            self.t += duration
        elif isinstance(op, Dwell):
            self.t += max(op.seconds, 0.0)
        self.toolpath.emit(op, label, line)  # type: ignore[arg-type]

    def flush(self) -> None:
        self.toolpath.flush()

    def print_text(self, text: str) -> None:
        """Engine programs print nothing the page shows."""

    def result(self) -> _Timed:
        return _Timed(self.t, {0: self.t} if self.t > 0.0 else {})

    def trajectory(self) -> _Rows:
        """Samples evenly spaced in time, each on its segment's cubics."""
        import bisect

        rows = _Rows()
        total = self.t
        if total <= 0.0 or not self.pieces:
            return rows
        n = MAX_SAMPLES
        for k in range(n):
            t = total * k / (n - 1)
            i = max(0, bisect.bisect_right(self.starts, t) - 1)
            duration, cubics, line = self.pieces[i]
            u = 1.0 if duration <= 0.0 else min(max((t - self.starts[i]) / duration, 0.0), 1.0)
            rows.values.extend((t, *(point(c, u) for c in cubics), float(line)))
        return rows


def _trajectory(text: str, name: str, new_interpreter: Callable[[Sink], Interpreter],
                machine: Machine, total: float) -> _Rows:
    """The trajectory of a second run, sampled evenly at up to :data:`MAX_SAMPLES` times."""
    from ..planner.timing import Timer
    from ..planner.trajectory import TrajectoryWriter

    rows = _Rows()
    every = max(total / (MAX_SAMPLES - 1), 1e-6)
    writer = TrajectoryWriter(rows, machine, every, MAX_SAMPLES + 2)
    timer = Timer(machine, writer.segment, writer.wait)
    try:
        interp = new_interpreter(timer.sink)
        interp.startup()
        interp.run(text.splitlines(), file=name)
    except NgcError:
        pass  # (the samples up to the error)
    try:
        finished = timer.finish()
        writer.finish(finished.total_s)
    except NgcError:
        pass
    return rows


def _meta(name: str, units: str, path: PathArrays, result: object, machine: Machine | None,
          error: NgcError | None, toolpath: Toolpath, warnings: Sequence[str],
          timed_by: str | None = None) -> dict[str, object]:
    low, high = path.extents()
    origin = [(lo + hi) / 2.0 for lo, hi in zip(low, high, strict=True)]
    size = [hi - lo for lo, hi in zip(low, high, strict=True)]
    meta: dict[str, object] = {
        "title": name, "units": units, "origin": origin, "low": low, "high": high,
        "size": size, "segments": path.count, "three": THREE_VERSION,
        "lengths": {"rapid": path.rapid_length, "cut": path.cut_length},
        "warnings": list(warnings), "time": None, "error": None, "tools": [],
    }
    by_tool: dict[int, float] = {}
    if result is not None and (machine is not None or timed_by is not None):
        by_tool = dict(result.by_tool)  # type: ignore[attr-defined]
        on = timed_by if machine is None else f"the {machine.linear_units} machine"
        meta["time"] = {"total": result.total_s,  # type: ignore[attr-defined]
                        "machine": on,
                        "by_tool": {("no tool" if t == 0 else f"T{t}"): s
                                    for t, s in sorted(by_tool.items())}}
    meta["tools"] = [
        {"name": "no tool" if t == 0 else f"T{t}",
         "text": f"cuts {length:.3f} {units}"
                 + (f" in {_clock(by_tool[t])}" if t in by_tool else "")}
        for t, length in sorted(path.cut_by_tool.items())]
    if error is not None:
        at = toolpath.pos
        meta["error"] = {"where": error.where(), "message": error.explained(),
                         "line": error.line or 0,
                         "at": [at[i] - origin[i] for i in range(3)]}
    return meta


def _clock(seconds: float) -> str:
    from ..commands.common import clock

    return clock(seconds)


def _html(name: str, meta: dict[str, object], text: str, path: PathArrays, lines: _Lines,
          rows: _Rows) -> bytes:
    origin = meta["origin"]
    assert isinstance(origin, list)
    parts: list[tuple[str, bytes]] = [
        ("points", path.relative_points(origin).tobytes()),
        ("starts", path.starts.tobytes()),
        ("line", path.line.tobytes()),
        ("feed", path.feed.tobytes()),
        ("line_t0", lines.t0.tobytes()),
        ("line_speed", lines.speed.tobytes()),
        ("trajectory", rows.values.tobytes()),
        ("tool", path.tool.tobytes()),
        ("kind", path.kind.tobytes()),
    ]
    blob = bytearray()
    arrays = {}
    item = {"points": 4, "starts": 4, "line": 4, "feed": 4, "line_t0": 4, "line_speed": 4,
            "trajectory": 4, "tool": 2, "kind": 1}
    for key, data in parts:
        while len(blob) % 4:
            blob.append(0)
        arrays[key] = [len(blob), len(data) // item[key]]
        blob.extend(data)
    meta["arrays"] = arrays
    assets = resources.files("ngc.view") / "assets"
    template = (assets / "page.html").read_text(encoding="utf-8")
    script = (assets / "view.js").read_text(encoding="utf-8")
    licence = (assets / "three-LICENSE.txt").read_text(encoding="utf-8")
    fill = {
        "@TITLE@": _escape_html(name),
        "@META@": _script_json(meta),
        "@TEXT@": _packed(text.encode("utf-8", "surrogateescape")),
        "@DATA@": _packed(bytes(blob)),
        "@THREE_VERSION@": THREE_VERSION,
        "@LICENCE@": licence.replace("--", "- -"),
        "@SCRIPT@": script.replace("</script", "<\\/script"),
    }
    out = template
    for key in ("@TITLE@", "@THREE_VERSION@", "@LICENCE@", "@META@", "@TEXT@", "@DATA@"):
        out = out.replace(key, fill[key])
    head, tail = out.split("@SCRIPT@")
    return (head + fill["@SCRIPT@"] + tail).encode("utf-8", "surrogateescape")


def _packed(data: bytes) -> str:
    """Bytes as the page holds them: gzip (no time stamp: the same bytes each time), base64; the
    page opens them with the browser's DecompressionStream."""
    return base64.b64encode(gzip.compress(data, compresslevel=6, mtime=0)).decode("ascii")


def _script_json(value: object) -> str:
    """JSON that can sit in a ``<script>`` block (no ``</`` to end it early)."""
    text = json.dumps(value, ensure_ascii=True, allow_nan=False)
    return text.replace("</", "<\\/")


def _escape_html(text: str) -> str:
    return (text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
            .replace('"', "&quot;"))
