"""What ``ngc time`` prints about a timed program (:class:`ngc.planner.timing.TimeResult`): the
total time, the naive distance / feed figure beside it, the time by kind, by tool and by line,
and the machine it was timed on; as a paragraph of text or as one JSON object
(``docs/time.md``).  Also the trajectory file ``--trajectory`` writes, which only replaces the
file named once the program has run without an error.
"""

from __future__ import annotations

import contextlib
import json
import math
import os
from collections.abc import Iterable, Mapping
from typing import TextIO

from ..canon.jsonl import dumps
from ..interp.source import open_text_program
from ..planner.machine import ANGULAR_AXES, Machine
from ..planner.timing import KINDS, TimeResult
from .common import clock

JSON_CHUNK = 4096  # lines of by_line written at a time
DIGITS = 6  # JSON numbers are rounded to the microsecond (and the micrometre)
SOURCE_WIDTH = 60  # characters of a slowest line's source text shown in the text report
MACHINE_TIMES = (("tool change", "tool_change_time"), ("spindle start", "spindle_start_time"),
                 ("spindle stop", "spindle_stop_time"))



def ratio(result: TimeResult) -> float | None:
    """The planned time over the naive time (``None`` when the naive time is 0)."""
    return result.total_s / result.naive_s if result.naive_s > 0.0 else None


def by_kind(result: TimeResult) -> dict[str, float]:
    """The time of each kind that took any, in the order of :data:`KINDS`."""
    kinds = [kind for kind in KINDS if kind in result.by_kind]
    kinds += sorted(kind for kind in result.by_kind if kind not in KINDS)
    return {kind: result.by_kind[kind] for kind in kinds}


def slowest(result: TimeResult, count: int) -> list[tuple[int, float]]:
    """The ``count`` lines that take the most time, slowest first (the earlier line on a tie)."""
    return result.slowest(count)


def source_lines(path: str, numbers: Iterable[int]) -> dict[int, str]:
    """The text of the lines ``numbers`` of the program file ``path`` (read again, up to the last
    of them; nothing for standard input or a file that is not a regular file)."""
    wanted = set(numbers)
    found: dict[int, str] = {}
    if path == "-" or not wanted or not os.path.isfile(path):
        return found
    last = max(wanted)
    try:
        with open_text_program(path) as reader:
            for number, text in enumerate(reader, 1):
                if number in wanted:
                    found[number] = text.rstrip("\r\n")
                if number >= last:
                    break
    except OSError:  # the file went away since it ran: no source text then
        return {}
    return found


# -- text -------------------------------------------------------------------------------------------
def render(name: str, result: TimeResult, machine: Machine, top: int = 10,
           sources: Mapping[int, str] | None = None) -> str:
    """``ngc time``'s report: a paragraph (see ``docs/time.md``)."""
    total = result.total_s
    units = machine.linear_units
    lines = [f"{name}: {clock(total)} ({total:.3f} s)",
             f"  naive (distance / feed): {clock(result.naive_s)} ({result.naive_s:.3f} s), "
             f"planned / naive: {_ratio_text(ratio(result))}",
             f"  by kind: {_shares(by_kind(result), total)}",
             f"  by tool: {_shares(_tools(result), total)}",
             f"  motion: {result.segments} segments, path length {result.length:.3f} {units}",
             f"  machine: {machine_text(machine)}",
             f"  axes: {axes_text(machine)}"]
    rows = slowest(result, top)
    if rows:
        lines.append("  slowest lines:")
        width = len(str(max(line for line, _ in rows)))
        for line, seconds in rows:
            text = _cut((sources or {}).get(line, ""))
            lines.append(f"    line {line:>{width}} {seconds:10.3f} s  {text}".rstrip())
    lines.extend(f"  {excess.text(units)}" for excess in result.limits)
    return "\n".join(lines)


def _ratio_text(value: float | None) -> str:
    return "-" if value is None else f"{value:.3f}"


def _shares(times: Mapping[str, float], total: float) -> str:
    if not times:
        return "none"
    parts = []
    for key, seconds in times.items():
        share = f" ({100.0 * seconds / total:.1f}%)" if total > 0.0 else ""
        parts.append(f"{key} {seconds:.3f} s{share}")
    return ", ".join(parts)


def _tools(result: TimeResult) -> dict[str, float]:
    return {f"T{tool}": result.by_tool[tool] for tool in sorted(result.by_tool)}


def _cut(text: str) -> str:
    text = text.strip()
    return text if len(text) <= SOURCE_WIDTH else text[: SOURCE_WIDTH - 3] + "..."


def machine_text(machine: Machine) -> str:
    """The machine in one line: units, servo period and the times the machine stands still for
    (those that are not 0).

    >>> machine_text(Machine(tool_change_time=6.0))
    'mm, servo period 0.001 s, tool change 6 s'
    """
    parts = [machine.linear_units, f"servo period {machine.servo_period:g} s"]
    for label, field in MACHINE_TIMES:
        seconds = getattr(machine, field)
        if seconds > 0.0:
            parts.append(f"{label} {seconds:g} s")
    return ", ".join(parts)


def axes_text(machine: Machine) -> str:
    """The machine's axes in one line: each one's speed and acceleration limits and its travel
    (if known), and the cap on every move's speed, if any.

    >>> axes_text(Machine())
    'X 200 mm/s 1000 mm/s^2, Y 200 mm/s 1000 mm/s^2, Z 100 mm/s 500 mm/s^2'
    """
    units = machine.linear_units
    parts = []
    for axis, limits in machine.axes.items():
        unit = "deg" if axis in ANGULAR_AXES else units
        travel = machine.travel.get(axis)
        span = "" if travel is None else f" travel {travel[0]:g}..{travel[1]:g}"
        parts.append(f"{axis} {limits.max_velocity:g} {unit}/s {limits.max_acceleration:g} "
                     f"{unit}/s^2{span}")
    if machine.max_linear_velocity is not None:
        parts.append(f"max linear velocity {machine.max_linear_velocity:g} {units}/s")
    return ", ".join(parts) or "none"


# -- JSON -------------------------------------------------------------------------------------------
def record(name: str, result: TimeResult, machine: Machine, top: int = 10,
           sources: Mapping[int, str] | None = None) -> dict[str, object]:
    """``ngc time --format json``'s object but ``by_line`` (:func:`write_json` adds it; see
    ``docs/time.md``); numbers rounded to 1e-6."""
    value = ratio(result)
    return {
        "file": name,
        "total_s": _round(result.total_s),
        "naive_s": _round(result.naive_s),
        "ratio": None if value is None else _round(value),
        "by_kind": {kind: _round(s) for kind, s in by_kind(result).items()},
        "by_tool": {tool: _round(s) for tool, s in _tools(result).items()},
        "slowest_lines": [{"line": line, "s": _round(s), "source": (sources or {}).get(line)}
                          for line, s in slowest(result, top)],
        "segments": result.segments,
        "length": _round(result.length),
        "units": machine.linear_units,
        "machine": machine_record(machine),
        "soft_limits": [{"axis": e.axis, "side": e.side, "limit": e.limit, "by": _round(e.by),
                         "line": e.line, "units": machine.linear_units} for e in result.limits],
    }


def write_json(out: TextIO, name: str, result: TimeResult, machine: Machine, top: int = 10,
               sources: Mapping[int, str] | None = None) -> None:
    """Write ``ngc time --format json``'s object on one line of ``out``: :func:`record` with
    ``by_line`` last, written a few thousand lines at a time, so that a long program's report
    takes no more memory than its lines' times."""
    head = dumps(record(name, result, machine, top, sources))
    out.write(head[:-1] + ', "by_line": {')
    chunk: list[str] = []
    sep = ""
    for line, seconds in result.by_line.items():
        chunk.append(f'"{line}": {_number(seconds)}')
        if len(chunk) >= JSON_CHUNK:
            out.write(sep + ", ".join(chunk))
            sep = ", "
            chunk.clear()
    if chunk:
        out.write(sep + ", ".join(chunk))
    out.write("}}\n")


def _number(value: float) -> str:
    """A rounded JSON number (``null`` if not finite)."""
    return json.dumps(_round(value)) if math.isfinite(value) else "null"


def machine_record(machine: Machine) -> dict[str, object]:
    """The machine a program was timed on, as JSON: units, axes limits, speed cap, servo period
    and the times of tool changes and spindle starts and stops."""
    axes: dict[str, dict[str, object]] = {
        axis: {"max_velocity": limits.max_velocity, "max_acceleration": limits.max_acceleration}
        for axis, limits in machine.axes.items()}
    for axis, (low, high) in machine.travel.items():
        if axis in axes:  # (JSON has no infinity: an open side is null)
            axes[axis]["travel"] = [low if math.isfinite(low) else None,
                                    high if math.isfinite(high) else None]
    return {"units": machine.linear_units, "axes": axes,
            "max_linear_velocity": machine.max_linear_velocity,
            "servo_period": machine.servo_period,
            **{field: getattr(machine, field) for _, field in MACHINE_TIMES}}


def _round(value: float) -> float:
    return round(value, DIGITS)


# -- the trajectory file ----------------------------------------------------------------------------
class TrajectoryWriteError(Exception):
    """The trajectory file could not be written; the message says which and why."""


class TrajectoryFile:
    """The CSV file of ``--trajectory``.  A regular file (or a new one) is
    written under a temporary name beside it and takes its name in :meth:`commit`, so a program
    error or an interruption leaves the file named as it was; anything else (``/dev/null``, a
    pipe) is written directly.  Raises ``OSError`` if it cannot be created; a failed write is a
    :class:`TrajectoryWriteError`."""

    def __init__(self, path: str) -> None:
        self.path = path
        self.name = os.fsencode(path).decode("utf-8", "surrogateescape")
        direct = os.path.exists(path) and not os.path.isfile(path)
        self._temp = None if direct else _temporary_name(path)
        target = path if self._temp is None else self._temp
        flags = os.O_WRONLY | (os.O_TRUNC if direct else os.O_CREAT | os.O_EXCL)
        fd = os.open(target, flags, 0o666)  # the umask applies, as for any new file
        self._stream = open(fd, "w", encoding="utf-8", newline="\n")  # noqa: SIM115 (commit)

    def write(self, text: str) -> None:
        try:
            self._stream.write(text)
        except OSError as exc:
            raise TrajectoryWriteError(f"cannot write {self.name}: {exc.strerror}") from None

    def commit(self) -> None:
        """Close the file and give it its name."""
        try:
            self._stream.close()
            if self._temp is not None:
                os.replace(self._temp, self.path)
                self._temp = None
        except OSError as exc:
            raise TrajectoryWriteError(f"cannot write {self.name}: {exc.strerror}") from None

    def discard(self) -> None:
        """Close the file and remove what was written (a temporary file only)."""
        with contextlib.suppress(OSError):
            self._stream.close()
        if self._temp is not None:
            with contextlib.suppress(OSError):
                os.unlink(self._temp)
            self._temp = None


def _temporary_name(path: str) -> str:
    folder, base = os.path.split(path)
    return os.path.join(folder, f".{base}.{os.getpid()}.tmp")
