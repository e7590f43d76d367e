"""What a program asks of the machine, as a machinist reads it before a run (``ngc check``): the
tools it cuts with (each one's diameter and length from the tool table, the length it cuts and
how long that takes at the programmed feed), the feeds it programs and the spindle speeds it cuts
at.

:class:`Usage` follows the canon the toolpath hands on (feed rate and mode, spindle speed, mode
and direction) and is told of each cutting move by the check's summary
(:class:`ngc.commands.check.Summarizer`); :meth:`Usage.summary` gives a :class:`UsageSummary` in
the program's final units.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace

from ..canon import ops
from ..config.tooltable import ToolEntry
from .common import clock

MM_PER_INCH = 25.4
Range = tuple[float, float]


@dataclass(frozen=True)
class ToolUse:
    """One tool's part of the program: ``number`` (0: none in the spindle), the length it cuts
    (feeds, arcs and probes, in the summary's units) and how long that takes at the programmed
    feed (None where a feed per revolution met a constant surface speed, whose spindle speed
    depends on the diameter cut); its ``diameter`` and ``length`` (Z offset) from the tool table,
    None for a tool the table does not hold."""

    number: int
    cut_length: float
    cut_seconds: float | None
    diameter: float | None = None
    length: float | None = None


@dataclass(frozen=True)
class UsageSummary:
    """The tools in the order the program first cuts with them, and the ranges of what it
    programs while cutting: feed per minute and per revolution (the summary's units), spindle
    speed (rpm) and constant surface speed (G96: m/min in a mm program, ft/min in an inch one);
    None for a range never used."""

    tools: tuple[ToolUse, ...] = ()
    feed_per_minute: Range | None = None
    feed_per_rev: Range | None = None
    spindle_rpm: Range | None = None
    surface_speed: Range | None = None

    def with_tool_data(self, find: Callable[[int], ToolEntry | None],
                       mm_per_unit: float) -> UsageSummary:
        """The tools with their diameter and length from the tool table (``find``: the
        interpreter's, in inches), in units of ``mm_per_unit`` mm."""
        scale = MM_PER_INCH / mm_per_unit
        tools = []
        for use in self.tools:
            entry = None if use.number <= 0 else find(use.number)
            if entry is not None:
                use = replace(use, diameter=entry.diameter * scale,
                              length=entry.offsets[2] * scale)
            tools.append(use)
        return replace(self, tools=tuple(tools))


class Usage:
    """The running state (feed, spindle) and totals; lengths are kept in mm and feeds in mm per
    minute or revolution, whatever the program's units.  A cut in the same state as the one
    before costs two additions: the state is settled (the tool's totals found, the seconds per
    mm worked out, the ranges widened) only when something changed."""

    __slots__ = ("_css", "_dirty", "_feed", "_per_rev", "_ranges", "_rpm", "_seconds_per_mm",
                 "_spindle_on", "_sync", "_tool", "_tools", "_totals")

    def __init__(self) -> None:
        self._feed = 0.0  # in mm when it was set, per minute or revolution
        self._per_rev = False
        self._rpm = 0.0  # or the surface speed, under G96
        self._css = False
        self._spindle_on = False
        self._sync = 0.0  # G33, G76: mm per revolution of the spindle (0: not synchronised)
        self._tools: dict[int, list[float]] = {}  # tool -> [mm cut, seconds, seconds unknown]
        self._ranges: dict[str, list[float]] = {}  # name -> [low, high]
        self._tool = -1  # the tool of the last cut, its totals, the seconds each mm takes
        self._totals = [0.0, 0.0, 0.0]
        self._seconds_per_mm = 0.0
        self._dirty = True

    def see(self, op: ops.Op, mm_per_unit: float) -> None:
        """Follow one of the canon operations that are not moves."""
        kind = type(op)
        if kind is ops.SetFeedRate:
            self._feed = op.rate * mm_per_unit  # type: ignore[attr-defined]
        elif kind is ops.SetFeedMode:
            self._per_rev = op.mode == 1  # type: ignore[attr-defined]
        elif kind is ops.SetSpindleSpeed:
            self._rpm = op.rpm  # type: ignore[attr-defined]
        elif kind is ops.SetSpindleMode:
            self._css = op.css_max > 0.0  # type: ignore[attr-defined]
        elif kind in (ops.StartSpindleClockwise, ops.StartSpindleCounterclockwise):
            self._spindle_on = True
        elif kind is ops.StopSpindleTurning:
            self._spindle_on = False
        elif kind is ops.StartSpeedFeedSync:
            self._sync = op.per_rev * mm_per_unit  # type: ignore[attr-defined]
        elif kind is ops.StopSpeedFeedSynch:
            self._sync = 0.0
        else:
            return
        self._dirty = True

    def cut(self, length_mm: float, tool: int) -> None:
        """A cutting move of ``length_mm`` with ``tool`` at the current feed and speed."""
        if tool != self._tool or self._dirty:
            self._settle(tool)
        totals = self._totals
        totals[0] += length_mm
        totals[1] += length_mm * self._seconds_per_mm

    def _settle(self, tool: int) -> None:
        """The tool's totals, the seconds a mm takes now, the ranges the state widens."""
        totals = self._tools.get(tool)
        if totals is None:
            totals = self._tools[tool] = [0.0, 0.0, 0.0]
        self._tool, self._totals, self._dirty = tool, totals, False
        feed, rpm, sync = self._feed, self._rpm, self._sync
        per_mm = 0.0
        if sync > 0.0 or self._per_rev:  # (a thread: the pitch per revolution, not the feed)
            per_rev = sync if sync > 0.0 else feed
            if sync <= 0.0:
                self._widen("feed_per_rev", feed)
            if self._css:
                totals[2] = 1.0  # (the spindle's speed follows the diameter cut)
            elif per_rev > 0.0 and rpm > 0.0:
                per_mm = 60.0 / (per_rev * rpm)
        else:
            self._widen("feed_per_minute", feed)
            if feed > 0.0:
                per_mm = 60.0 / feed
        self._seconds_per_mm = per_mm
        if self._spindle_on:
            self._widen("surface_speed" if self._css else "spindle_rpm", rpm)

    def _widen(self, name: str, value: float) -> None:
        held = self._ranges.get(name)
        if held is None:
            self._ranges[name] = [value, value]
        elif value < held[0]:
            held[0] = value
        elif value > held[1]:
            held[1] = value

    def summary(self, mm_per_unit: float) -> UsageSummary:
        """The totals so far, lengths and feeds in units of ``mm_per_unit`` mm."""
        tools = tuple(ToolUse(number, length / mm_per_unit,
                              None if unknown else seconds)
                      for number, (length, seconds, unknown) in self._tools.items())

        def span(name: str, scale: float = 1.0) -> Range | None:
            held = self._ranges.get(name)
            return None if held is None else (held[0] / scale, held[1] / scale)

        return UsageSummary(tools, span("feed_per_minute", mm_per_unit),
                            span("feed_per_rev", mm_per_unit), span("spindle_rpm"),
                            span("surface_speed"))


# -- how it reads ------------------------------------------------------------------------------
SURFACE_UNITS = {"mm": "m/min", "cm": "m/min", "inch": "ft/min"}


def usage_lines(usage: UsageSummary, units: str) -> list[str]:
    """``ngc check``'s lines on the tools, feeds and speeds (none for a program that cuts
    nothing)."""
    lines = []
    for use in usage.tools:
        name = "no tool" if use.number == 0 else f"T{use.number}"
        data = ""
        if use.diameter is not None and use.length is not None:
            data = f" (diameter {use.diameter:.4f} {units}, length {use.length:.4f} {units})"
        elif use.number > 0:
            data = " (not in the tool table)"
        time = ("time unknown (G95 under G96)" if use.cut_seconds is None
                else f"{clock(use.cut_seconds)} at the programmed feed"
                if math.isfinite(use.cut_seconds) else "time past a double's range")
        lines.append(f"  {name}{data}: cuts {_number(use.cut_length)} {units}, {time}")
    for label, span, unit in (("feed", usage.feed_per_minute, f"{units}/min"),
                              ("feed", usage.feed_per_rev, f"{units}/rev"),
                              ("spindle", usage.spindle_rpm, "rpm"),
                              ("spindle", usage.surface_speed,
                               f"{SURFACE_UNITS.get(units, units)} (constant surface speed)")):
        if span is not None:
            lines.append(f"  {label}: {_rate(span[0])} .. {_rate(span[1])} {unit}")
    return lines


def usage_record(usage: UsageSummary) -> dict[str, object]:
    """The same, as JSON fields (ranges as ``[low, high]``, None when not used)."""
    def span(value: Range | None) -> list[float | None] | None:
        return None if value is None else [_finite(value[0]), _finite(value[1])]

    return {
        "tools": [{"tool": u.number, "diameter": u.diameter, "length": u.length,
                   "cut_length": _finite(u.cut_length), "cut_seconds": u.cut_seconds}
                  for u in usage.tools],
        "feed_per_minute": span(usage.feed_per_minute),
        "feed_per_rev": span(usage.feed_per_rev),
        "spindle_rpm": span(usage.spindle_rpm),
        "surface_speed": span(usage.surface_speed),
    }


def _number(value: float) -> str:
    return f"{value:.4f}" if math.isfinite(value) else "past a double's range"


def _rate(value: float) -> str:
    """A feed or a speed: to 4 decimals, without trailing zeros (``300``, ``0.05``)."""
    return _number(value).rstrip("0").rstrip(".") if math.isfinite(value) else _number(value)


def _finite(value: float) -> float | None:
    return value if math.isfinite(value) else None
