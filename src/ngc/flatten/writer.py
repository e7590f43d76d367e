"""A program written out plain: a reader of the toolpath (:mod:`ngc.toolpath`) that writes each
move as a G0, G1, G2 or G3 line in the coordinates of the work offset the operator set.

What the operator sets at the machine stays a reference: the work offset (G54-G59.3) the
program selects, with the origin it had when the program started (the parameter file's), and a
tool length that is a tool's in the table (``G43 H<tool>``).  What the program computes is
resolved into the coordinates: parameters and expressions, O-words, loops, canned and lathe
cycles and cutter compensation (canon has them as moves already), offsets the program sets
(G10, G92, G52), XY rotation and unit switches.  What cannot be written truthfully is refused
(:class:`Refused`): probing, spindle-synchronised motion, rigid tapping, NURBS and anything this
writer does not know yet.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Callable, Sequence
from typing import Protocol

from ..canon import ops
from ..config.tooltable import ToolEntry
from ..render import curves
from ..toolpath.frame import Pos
from ..toolpath.held import View
from ..toolpath.tracker import FEED, PROBE, RAPID, ArcMove, Cubics, Toolpath
from .curves import NO_ARC, arc_points, cubic_pieces, is_cubic, nurbs_points
from .targets import Target

MM_PER_INCH = 25.4
SYSTEMS = ("G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3")
AXES = "XYZABC"
_LINEAR_WORDS = ((0, " X"), (1, " Y"), (2, " Z"))
LINEAR = (True, True, True, False, False, False)
# An arc's plane by its normal, and the offset words of each plane with their axes.
_PLANES = {(0.0, 0.0, 1.0): "G17", (0.0, 1.0, 0.0): "G18", (1.0, 0.0, 0.0): "G19"}
_OFFSETS = {"G17": (("I", 0), ("J", 1)), "G18": (("I", 0), ("K", 2)),
            "G19": (("J", 1), ("K", 2))}
TOOL_CHANGES = ("pause", "strip", "keep")
TEXTS = 1 << 16  # numbers whose text the writer keeps
_ONE = [1]  # (a straight move: one line)
# Canon operations that change nothing the output must say: resolved into the coordinates or
# said by the moves themselves.
RESOLVED = frozenset({
    ops.UseLengthUnits, ops.SelectPlane, ops.SetG92Offset, ops.SetXYRotation,
    ops.SetFeedReference, ops.StartChange, ops.EnableFeedOverride, ops.DisableFeedOverride,
    ops.EnableSpeedOverride, ops.DisableSpeedOverride, ops.EnableAdaptiveFeed,
    ops.DisableAdaptiveFeed, ops.EnableFeedHold, ops.DisableFeedHold, ops.SetToolTableEntry,
    ops.ReloadTooldata, ops.OnReset, ops.Finish, ops.LogOpen, ops.LogAppend, ops.Log,
    ops.LogClose, ops.TurnProbeOn, ops.TurnProbeOff,
})


# The outputs, as the M code that sets them (M62-M65 synchronised with motion or at once, M67/M68
# analog): the canon operation -> (code, what it carries).
_OUTPUTS: dict[type, tuple[str, str]] = {
    ops.SetMotionOutputBit: ("M62", "bit"), ops.ClearMotionOutputBit: ("M63", "bit"),
    ops.SetAuxOutputBit: ("M64", "bit"), ops.ClearAuxOutputBit: ("M65", "bit"),
    ops.SetMotionOutputValue: ("M67", "value"), ops.SetAuxOutputValue: ("M68", "value"),
}


class Output(Protocol):
    """Where the lines go."""

    def write(self, text: str) -> object: ...


class Refused(Exception):
    """A program that cannot be flattened truthfully: the line and the reason."""

    def __init__(self, line: int, reason: str) -> None:
        super().__init__(f"line {line}: {reason}")
        self.line = line
        self.reason = reason


class Flattener:
    """The toolpath's reader that writes the plain program to ``out``.

    ``origins`` are the work offsets' origins when the program started (machine coordinates, mm,
    X Y Z A B C, by system 1-9) and ``system`` the one selected then; ``tool`` finds a tool's
    entry in the table (lengths in mm); ``inch`` writes in inches (else mm)."""

    def __init__(self, toolpath: Toolpath | View, out: Output, target: Target, *,
                 origins: Sequence[Sequence[float]], system: int,
                 tool: Callable[[int], ToolEntry | None], inch: bool = False,
                 decimals: int | None = None, source_lines: bool = False,
                 tolerance: float = 0.002, toolchange: str | None = None,
                 fold_lengths: bool = False) -> None:
        self.toolpath = toolpath
        self.target = target
        self.origins = origins
        self.system = system
        self.tool_entry = tool
        self.inch = inch
        self.scale = MM_PER_INCH if inch else 1.0
        self.decimals = decimals if decimals is not None else (
            target.decimals_inch if inch else target.decimals_mm)
        self.source_lines = source_lines
        # lines for a curve stay this close to it (mm), less what rounding the ends may move
        self.tolerance = tolerance
        self.fold_lengths = fold_lengths  # tool lengths folded into the coordinates, as asked
        rounding = 0.5 * 10.0 ** -self.decimals * self.scale * math.sqrt(3.0)
        self.chord = max(tolerance - rounding, 0.25 * tolerance)
        self.toolchange = toolchange or ("keep" if target.tool_change else "pause")
        if self.toolchange not in TOOL_CHANGES:
            raise ValueError(f"--toolchange {self.toolchange}: choose one of "
                             f"{', '.join(TOOL_CHANGES)}")
        self.kept: int | None = None  # the tool whose length G43 H applies
        self.kept_offset: Pos = (0.0,) * 6
        self.motion = ""
        self.feed_mm = 0.0  # the feed now, mm per minute (or per revolution)
        self.feed_written: str | None = None
        self.per_rev = False
        self.per_rev_written = False
        self.feed_key: tuple[float, bool, float, str] | None = None
        self.selected = 0
        self.naive = 0.0
        self.where: list[str | None] = [None] * 6  # the output's current position (as written)
        self.raw: list[float | None] = [None] * 6  # and the coordinates it was written from
        self.shift: tuple[float, ...] = tuple(origins[system - 1])  # (+ the kept tool length)
        self.inverse = 1.0 / self.scale
        self.same = self.inverse == 1.0 and not any(self.shift)  # (machine points are written)
        self.format = f"%.{self.decimals}f"
        self.texts: dict[float, str] = {}  # numbers as written, kept for the next time
        self.unit = 10.0 ** -self.decimals * self.scale  # (mm: a unit of the last decimal)
        # (a number at least this large has fewer decimals: the target keeps so many digits)
        self.big = 10.0 ** (target.digits - self.decimals) if target.digits else math.inf
        limits = [n for n in (target.max_line, target.raw_line) if n]
        self.short = min(limits) if limits else sys.maxsize  # (a line no longer: no checks)
        self.put = out.write
        self.feed_changed = True  # (the feed's words are looked at again: see ``other``)
        self.lines = 0
        self.line = 0  # the program's line of the move being written
        self.motions = 0  # motion lines written
        self.counts: list[int] = _ONE  # the motion lines of the last move (of each G5 piece)
        self.plane = "G17"
        self.ended = False  # M2 or M30 written
        self.shuttle = False  # a pallet shuttle waits for what comes with it (M30, M60)
        self.rpm = 0.0
        self.spindle_on = ""  # "M3", "M4", or "" when it stands
        self.coolant = False
        self.css_max = 0.0  # G96's greatest speed (rpm), 0 under G97
        self.sync_per_rev = 0.0  # a synchronised move's distance a revolution (program units)
        self.orient = ""  # M19 R P, written with its wait (Q) if one comes next

    # -- writing ------------------------------------------------------------------------------
    def write(self, text: str, line: int = 0) -> None:
        if len(text) > self.short or self.source_lines:
            self._write_long(text, line)
            return
        self.put(text + "\n")
        self.lines += 1

    def _write_long(self, text: str, line: int) -> None:
        """A line that may be past the target's limits, or that takes a ``(line N)``."""
        limit = self.target.max_line
        if limit and len(text) > limit and len(_significant(text)) > limit:
            raise Refused(line, f"a line of more than {limit} characters for {self.target.name}: "
                          f"{text}")
        if self.source_lines and line:
            text = f"{text} (line {line})"
        raw = self.target.raw_line
        if raw and len(text) > raw:
            if text.startswith("("):  # (a comment: cut to fit)
                text = text[:raw - 1] + ")"
            else:
                raise Refused(line, f"a line of more than {raw} characters for "
                              f"{self.target.name}: {text[:60]}...")
        self.put(text + "\n")
        self.lines += 1

    def header(self, name: str) -> None:
        self.write(f"(flattened by ngc from {_comment_text(name)} for {self.target.name}, "
                   f"curves within {self.tolerance:g} mm)")
        self.write(f"{'G20' if self.inch else 'G21'} {self.target.header}")
        self._system_words(self.system, 0)

    def _number(self, v: float) -> str:
        text = self.texts.get(v)  # (a number written before: most are)
        if text is not None:
            return text
        if -self.big < v < self.big or (not self.target.digits or v != v
                                         or v in (math.inf, -math.inf)):
            text = (self.format % v).rstrip("0").rstrip(".")
        else:  # (fewer decimals: the target's reader keeps only so many digits)
            whole = len(str(int(abs(v))))
            text = f"{v:.{max(self.target.digits - whole, 0)}f}"
            text = text.rstrip("0").rstrip(".") if "." in text else text
        if text == "-0":
            text = "0"
        if len(self.texts) >= TEXTS:
            self.texts.clear()
        self.texts[v] = text
        return text

    def _forget(self) -> None:
        """The offsets changed: the next move says every axis again, from the new shift."""
        origin, kept = self.origins[self.system - 1], self.kept_offset
        self.shift = tuple(origin[i] + kept[i] for i in range(6))
        self.same = self.inverse == 1.0 and not any(self.shift)
        self.where = [None] * 6
        self.raw = [None] * 6

    def _coordinates(self, p: Sequence[float], line: int) -> Sequence[float]:
        """A machine point (mm, degrees) in the output's coordinates and units."""
        if self.same:
            if (p[0] + p[1] + p[2] + p[3] + p[4] + p[5]) * 0.0 != 0.0:
                raise Refused(line, "a coordinate past a double's range")
            return p
        o, k = self.shift, self.inverse
        x, y, z = (p[0] - o[0]) * k, (p[1] - o[1]) * k, (p[2] - o[2]) * k
        a, b, c = p[3] - o[3], p[4] - o[4], p[5] - o[5]
        if (x + y + z + a + b + c) * 0.0 != 0.0:  # (an infinity or not a number)
            raise Refused(line, "a coordinate past a double's range")
        return (x, y, z, a, b, c)

    def _axes(self, q: Sequence[float], force: bool = False) -> str:
        """The axis words that change (``force``: X Y Z whatever; A B C only once they are
        away from 0, so that a program for three axes has no rotary word), each after a space."""
        words = ""
        raw, where = self.raw, self.where  # (where[i] is raw[i] written)
        for i, word in _LINEAR_WORDS:
            v = q[i]
            if v != raw[i]:  # (the same coordinate as the move before: the same word)
                raw[i] = v
                text = self._number(v)
                if text != where[i] or force:
                    words += word + text
                    where[i] = text
            elif force:
                words += f"{word}{where[i]}"
        if q[3] != raw[3] or q[4] != raw[4] or q[5] != raw[5]:
            words += self._rotary(q)
        return words

    def _rotary(self, q: Sequence[float]) -> str:
        """The A B C words that change, for a target that has them."""
        words = ""
        raw, where = self.raw, self.where
        for i in (3, 4, 5):
            v = q[i]
            if v == raw[i]:
                continue
            raw[i] = v
            text = self._number(v)
            was = where[i]
            if text == was or (was is None and text == "0"):
                where[i] = text
                continue
            if not self.target.rotary:
                raise Refused(self.line, f"a move of the {AXES[i]} axis: "
                              f"{self.target.name} has X Y Z only")
            words += " " + AXES[i] + text
            where[i] = text
        return words

    def _feed_words(self, line: int = 0) -> str:
        """The feed's words where it changed (G94/G95 and F), each after a space, else ''."""
        self.feed_changed = False
        key = (self.feed_mm, self.per_rev, self.rpm, self.spindle_on)
        if key == self.feed_key:
            return ""
        self.feed_key = key
        words = []
        feed = self.feed_mm
        if self.per_rev and not self.target.feed_per_rev:
            # (G95 for a target without it: per minute, at the spindle speed it turns at)
            if not (self.spindle_on and self.rpm > 0.0):
                raise Refused(line, f"feed per revolution (G95) for {self.target.name}, which "
                              "has none, with no spindle speed to turn it into a feed per minute")
            feed *= self.rpm
        elif self.per_rev != self.per_rev_written:
            words.append(" G95" if self.per_rev else " G94")
            self.per_rev_written = self.per_rev
            self.feed_written = None  # (a new feed mode sets the feed to 0: F again)
        rate = self._number(feed / self.scale)
        if rate != self.feed_written:
            words.append(" F" + rate)
            self.feed_written = rate
        return "".join(words)

    # -- the toolpath's consumer protocol -----------------------------------------------------
    def straight(self, kind: str, start: Pos, end: Pos, line: int) -> None:
        self.line = line
        if self.orient:
            self._write_orient(line)
        if kind == FEED:
            code = "G1" + self._feed_words(line) if self.feed_changed else "G1"
        elif kind == RAPID:
            code = "G0"
        elif kind == PROBE:
            raise Refused(line, "probing: where the probe stops is known only at the machine")
        else:
            if not self.target.sync:
                raise Refused(line, "spindle-synchronised motion (G33, G76): "
                              f"{self.target.name} has none")
            q = self._coordinates(end, line)
            axes = self._axes(q) or self._axes(q, force=True)
            self.write(f"G33{axes} K{self._per_rev()}", line)
            self.motions += 1
            self.counts = _ONE
            return
        q = self._coordinates(end, line)
        axes = self._axes(q) or self._axes(q, force=True)  # (a move of no length still goes in)
        self.write(code + axes, line)
        self.motions += 1
        self.counts = _ONE

    def arc(self, arc: ArcMove, line: int) -> None:
        before = self.motions
        self._arc(arc, line)
        self.counts = [self.motions - before]

    def _arc(self, arc: ArcMove, line: int) -> None:
        self.line = line
        if self.orient:
            self._write_orient(line)
        n = arc.normal
        code, sign = _PLANES.get(n), 1  # (exactly on an axis, most arcs: or else)
        if code is None:
            code, sign = _PLANES.get((-n[0], -n[1], -n[2])), -1
        target = self.target
        if code is None or code not in target.arc_planes or (not target.helix and abs(
                sum((arc.end[i] - arc.start[i]) * n[i] for i in range(3))) > 1e-9):
            # (a plane the XY rotation turns off the axes, or one the target lacks, or a helix
            # it cannot cut: straight lines within the tolerance)
            for point in arc_points(arc, self.chord):
                self.straight(FEED, arc.start, point, line)
            return
        first, second = _OFFSETS[code]
        i, j = first[1], second[1]
        centre, a, b = arc.centre, arc.start, arc.end
        r0 = math.hypot(a[i] - centre[i], a[j] - centre[j])
        r1 = math.hypot(b[i] - centre[i], b[j] - centre[j])
        if max(r0, r1) <= 0.5 * self.unit:  # (no radius the numbers can hold: along the axis)
            self.straight(FEED, a, b, line)
            return
        # An arc whose end is off its start's circle (LinuxCNC takes one within its tolerance,
        # which depends on the units, and runs a spiral) is an arc for a target that runs it
        # alike in the same units; an arc too small for its offsets to be written is lines.
        spiral = abs(r1 - r0) > 1e-9 * max(1.0, r0)
        if (min(r0, r1) < max(2.0 * self.unit, target.min_radius) or (spiral and not (
                target.spiral and self.toolpath.frame.inch_program == self.inch))):
            for point in arc_points(arc, self.chord):
                self.straight(FEED, arc.start, point, line)
            return
        turns = arc.turns * sign
        if (turns > 1 or turns < -1) and not target.turns:
            self._turns(arc, turns, line)
            return
        was = (self.where[i], self.where[j])
        q = self._coordinates(arc.end, line)
        o, k = self.shift, self.inverse  # (the centre in the output's coordinates)
        cx, cy = (centre[i] - o[i]) * k, (centre[j] - o[j]) * k
        if (cx + cy) * 0.0 != 0.0:
            raise Refused(line, "a coordinate past a double's range")
        words = ("G3" if turns > 0 else "G2") if code == self.plane else (
            code + (" G3" if turns > 0 else " G2"))
        self.plane = code
        if self.feed_changed:
            words += self._feed_words(line)
        words += self._axes(q, force=True) + " " + self._centre_words(
            first, second, was, arc.start, cx, cy, line, spiral)
        if turns > 1 or turns < -1:
            words += f" P{abs(turns)}"
        self.write(words, line)
        self.motions += 1

    def _centre_words(self, first: tuple[str, int], second: tuple[str, int],
                      was: tuple[str | None, str | None], start: Pos, cx: float,
                      cy: float, line: int, spiral: bool) -> str:
        """The centre's offset words from the start as written.  Where the rounded numbers
        leave the radii to the written start and end more than a unit of the last decimal
        apart, the centre moves onto the perpendicular bisector of the two (the nearest such
        point to the true one), so that they agree but for the offsets' own rounding (Grbl's
        error:33, rs274's "radius to end of arc differs")."""
        i, j = first[1], second[1]
        a0, b0 = was
        if a0 is None or b0 is None:  # (the start as it would be written)
            s = self._coordinates(start, line)
            a0 = self._number(s[i]) if a0 is None else a0
            b0 = self._number(s[j]) if b0 is None else b0
        sx, sy = float(a0), float(b0)
        end = self.where[i], self.where[j]
        a, b = self._number(cx - sx), self._number(cy - sy)
        if end[0] is None or end[1] is None or spiral:  # (a spiral keeps its centre)
            return f"{first[0]}{a} {second[0]}{b}"
        ex, ey = float(end[0]), float(end[1])
        ox, oy = sx + float(a), sy + float(b)
        unit = self.unit / self.scale
        if abs(math.hypot(sx - ox, sy - oy) - math.hypot(ex - ox, ey - oy)) > unit:
            # the nearest of the neighbouring written centres whose radii agree; else onto the
            # bisector (which a short chord's rounding may turn a long way)
            best: tuple[float, str, str] | None = None
            for da in (-1, 0, 1):
                for db in (-1, 0, 1):
                    px, py = ox + da * unit, oy + db * unit
                    if abs(math.hypot(sx - px, sy - py) - math.hypot(ex - px, ey - py)) > unit:
                        continue
                    off = math.hypot(px - cx, py - cy)
                    if best is None or off < best[0]:
                        best = (off, self._number(px - sx), self._number(py - sy))
            if best is not None:
                return f"{first[0]}{best[1]} {second[0]}{best[2]}"
            dx, dy = ex - sx, ey - sy
            length = math.hypot(dx, dy)
            if length > 1e-9:
                nx, ny = -dy / length, dx / length
                along = (cx - 0.5 * (sx + ex)) * nx + (cy - 0.5 * (sy + ey)) * ny
                cx, cy = 0.5 * (sx + ex) + along * nx, 0.5 * (sy + ey) + along * ny
                a, b = self._number(cx - sx), self._number(cy - sy)
        return f"{first[0]}{a} {second[0]}{b}"

    def _turns(self, arc: ArcMove, turns: int, line: int) -> None:
        """An arc of several turns for a target without P: one arc a turn, each a full circle
        rising its share of the helix, then the rest of the arc (as ``curves.frame`` measures
        it)."""
        f = curves.frame(arc.start, arc.end, arc.centre, arc.normal, arc.turns)
        full = abs(turns) - 1
        points = [f.point(curves.TAU * k) for k in range(1, full + 1)]
        starts = [arc.start, *[(*p, *arc.start[3:]) for p in points]]
        ends = [*[(*p, *arc.end[3:]) for p in points], arc.end]
        for a, b in zip(starts, ends, strict=True):
            piece = ArcMove(a, b, arc.centre, arc.normal, 1 if arc.turns > 0 else -1,
                            arc.op, arc.prog_start)
            self._arc(piece, line)

    def nurbs(self, curve: ops.NurbsFeed, start: Pos, line: int) -> None:
        """G5 as the biarcs LinuxCNC runs it as; G5.1 and G5.2 as lines within the tolerance."""
        if self.feed_mm <= 0.0:  # (under G93 canon gives a curve no feed of its own)
            raise Refused(line, "a spline (G5, G5.1, G5.2) with no feed rate (inverse time, "
                          "G93): not written yet")
        to_machine = self.toolpath.frame.to_machine
        counts = []
        if is_cubic(curve):
            a = start
            for end, centre, turns in cubic_pieces(curve, start, to_machine):
                before = self.motions
                if centre is None:
                    self.straight(FEED, a, end, line)
                else:
                    self._arc(ArcMove(a, end, centre, (0.0, 0.0, 1.0), turns, NO_ARC, a), line)
                counts.append(self.motions - before)
                a = end
        else:
            before = self.motions
            chord = self.chord / self._program_mm()
            for point in nurbs_points(curve, start, to_machine, chord):
                self.straight(FEED, start, point, line)
            counts.append(self.motions - before)
        self.counts = counts

    def tap(self, start: Pos, bottom: Pos, line: int) -> None:
        """G33.1 to the bottom and back: the position after it is the start again."""
        if not self.target.sync:
            raise Refused(line, f"rigid tapping (G33.1): {self.target.name} has none")
        s = list(self.where), list(self.raw)
        q = self._coordinates(bottom, line)
        axes = self._axes(q) or self._axes(q, force=True)
        self.write(f"G33.1{axes} K{self._per_rev()}", line)
        self.motions += 1
        self.counts = _ONE
        self.where, self.raw = s

    def _write_orient(self, line: int) -> None:
        """An M19 R P no wait came with: written alone before what follows it."""
        self.write(self.orient, line)
        self.orient = ""

    def _per_rev(self) -> str:
        """The synchronised motion's distance a revolution, in the output's units."""
        return self._number(self.sync_per_rev * self._program_mm() / self.scale)

    def bezier(self, cubics: Cubics, motion: str, start: Pos, line: int) -> None:
        raise Refused(line, "engine-dialect programs are not flattened yet")

    def other(self, op: ops.Op, line: int) -> None:
        kind = type(op)
        self.feed_changed = True  # (what sets the feed, its mode or the spindle comes here)
        if self.orient and kind is not ops.WaitOrientComplete:
            self._write_orient(line)
        if kind is ops.SetFeedRate:  # (the commonest first)
            self.feed_mm = op.rate * self._program_mm()  # type: ignore[attr-defined]
            return
        if kind is ops.Comment:
            text = op.text  # type: ignore[attr-defined]
            if not text.startswith("interpreter: "):  # (rs274's notes of its own changes)
                self.write(f"({_comment_text(text)})", line)
            return
        if kind in RESOLVED:
            return
        if kind is ops.SetG5xOffset:
            system = op.system  # type: ignore[attr-defined]
            if system != self.system:
                self.system = system
                self._forget()
                self._system_words(system, line)
        elif kind is ops.UseToolLengthOffset:
            self._tool_length(line)
        elif kind is ops.SetFeedMode:
            self.per_rev = op.mode == 1  # type: ignore[attr-defined]
        elif kind is ops.SetMotionControlMode:
            mode = op.mode  # type: ignore[attr-defined]
            if self.target.blending and mode in ("CANON_EXACT_STOP", "CANON_EXACT_PATH"):
                self.write("G61.1" if mode == "CANON_EXACT_STOP" else "G61", line)
        elif kind is ops.SetNaivecamTolerance:
            self.naive = op.tolerance  # type: ignore[attr-defined]
        elif kind is ops.SetMotionControlContinuous:
            if self.target.blending:
                tolerance = op.tolerance * self._program_mm() / self.scale  # type: ignore[attr-defined]
                naive = self.naive * self._program_mm() / self.scale
                self.write(f"G64 P{self._number(tolerance)} Q{self._number(naive)}", line)
        elif kind is ops.SetSpindleSpeed:
            self.rpm = op.rpm  # type: ignore[attr-defined]
            if self.css_max > 0.0:  # (G96: S is a surface speed, m or ft a minute)
                self._surface_speed(line)
            else:
                self.write(f"S{self._number(self.rpm)}", line)
        elif kind is ops.StartSpindleClockwise:
            self.spindle_on = "M3"
            self.write("M3", line)
        elif kind is ops.StartSpindleCounterclockwise:
            self.spindle_on = "M4"
            self.write("M4", line)
        elif kind is ops.StopSpindleTurning:
            if self.spindle_on:  # (canon stops a standing spindle again: at M6, at the end)
                self.write("M5", line)
            self.spindle_on = ""
        elif kind is ops.SetSpindleMode:
            css = op.css_max  # type: ignore[attr-defined]
            if css > 0.0 and not self.target.css:
                raise Refused(line, f"constant surface speed (G96): {self.target.name} has none")
            if css <= 0.0 and self.css_max > 0.0:
                self.write("G97", line)
            self.css_max = css
        elif kind is ops.StartSpeedFeedSync:
            self.sync_per_rev = op.per_rev  # type: ignore[attr-defined]
        elif kind is ops.StopSpeedFeedSynch:
            self.sync_per_rev = 0.0
        elif kind is ops.OrientSpindle:
            direction = op.direction  # type: ignore[attr-defined]
            if not self.target.orient or direction not in (0, 1, 2):
                raise Refused(line, "spindle orientation (M19)"
                              + (f": {self.target.name} has none" if not self.target.orient
                                 else f" of direction {direction}: not written yet"))
            # (written with the wait that may come next: M19 R P Q is one line)
            self.orient = f"M19 R{self._number(op.degrees)} P{direction}"  # type: ignore[attr-defined]
            return
        elif kind is ops.WaitOrientComplete:
            if not self.target.orient:
                raise Refused(line, f"spindle orientation (M19): {self.target.name} has none")
            self.write(f"{self.orient or 'M19'} Q{self._number(op.seconds)}", line)  # type: ignore[attr-defined]
            self.orient = ""
        elif kind is ops.SelectTool:
            self.selected = op.tool  # type: ignore[attr-defined]
        elif kind is ops.ChangeTool:
            if self.toolchange == "keep":
                self.write(f"T{self.selected} M6", line)
            elif self.toolchange == "pause":
                self._tool_change(line)
            else:
                self.write(f"(tool change to tool {self.selected}{self._diameter()} left out)",
                           line)
        elif kind is ops.ChangeToolNumber:
            if self.target.tool_change and self.toolchange == "keep":
                self.write(f"M61 Q{self.selected}", line)
            else:
                self.write(f"(the spindle holds tool {self.selected})", line)
        elif kind is ops.Dwell:
            self.write(f"G4 P{self._number(op.seconds)}", line)  # type: ignore[attr-defined]
        elif kind is ops.FloodOn:
            self.coolant = True
            self.write("M8", line)
        elif kind is ops.MistOn:
            if not self.target.mist:
                raise Refused(line, f"mist coolant (M7): {self.target.name} has none in its "
                              "default build")
            self.coolant = True
            self.write("M7", line)
        elif kind in (ops.FloodOff, ops.MistOff):
            if self.coolant:  # (M9 is both: canon says each)
                self.write("M9", line)
            self.coolant = False
        elif kind is ops.Message:
            self.write(f"(MSG,{_comment_text(op.text)})", line)  # type: ignore[attr-defined]
        elif kind is ops.ProgramStop:
            if self.shuttle:  # (M60: the pallets exchanged, then a pause)
                if not self.target.tool_change:
                    raise Refused(line, f"M60 (pallet shuttle): {self.target.name} has none")
                self.write("M60", line)
            else:
                self.write("M0", line)
            self.shuttle = False
        elif kind is ops.OptionalProgramStop:
            self.write("M1", line)
        elif kind is ops.ProgramEnd:
            self.write("M30" if self.shuttle else "M2", line)  # (M30: the pallets, then the end)
            self.shuttle = False
            self.ended = True
        elif kind is ops.PalletShuttle:
            self.shuttle = True
        elif kind in _OUTPUTS:
            code, field = _OUTPUTS[kind]
            if not self.target.io:
                raise Refused(line, f"an output ({code}): {self.target.name} has none")
            if field == "bit":
                self.write(f"{code} P{op.bit}", line)  # type: ignore[attr-defined]
            else:
                self.write(f"{code} E{op.channel} Q{self._number(op.value)}",  # type: ignore[attr-defined]
                           line)
        else:
            name = kind.__name__
            raise Refused(line, f"{name} is not flattened yet")

    def finish(self) -> None:
        """Nothing is held back."""

    def _system_words(self, system: int, line: int) -> None:
        if system > self.target.systems:
            raise Refused(line, f"{SYSTEMS[system - 1]}: {self.target.name} has no such work "
                          "offset")
        self.write(SYSTEMS[system - 1], line)

    def _tool_change(self, line: int) -> None:
        """A target without M6: the spindle stops (as M6 stops it), a comment names the tool and
        its diameter, the program pauses (M0) for the operator; the program starts the spindle
        again itself, as after M6."""
        size = self._diameter()
        if self.spindle_on:  # (canon stops it for M6 already)
            self.write("M5", line)
            self.spindle_on = ""
        self.write(f"(tool change: put in tool {self.selected}{size}, then resume)", line)
        self.write("M0", line)

    def _surface_speed(self, line: int) -> None:
        """G96 D S: the surface speed in the output's units (m a minute in mm, ft in inches) about
        X 0 of the coordinates written, which must be the program's."""
        frame = self.toolpath.frame
        if frame.g92[0] != 0.0 or frame.rotation != 0.0:
            raise Refused(line, "constant surface speed (G96) under a G92, G52 or rotation: its "
                          "centre would move")
        metres = self.rpm * (0.3048 if frame.inch_program else 1.0)
        speed = metres / (0.3048 if self.inch else 1.0)
        limit = f" D{self._number(self.css_max)}" if self.css_max < 1e20 else ""  # (no D: none)
        self.write(f"G96{limit} S{self._number(speed)}", line)

    def _diameter(self) -> str:
        """``, diameter D`` for the selected tool in the table (in the output's units)."""
        entry = self.tool_entry(self.selected) if self.selected > 0 else None
        return "" if entry is None else f", diameter {self._number(entry.diameter / self.scale)}"

    # -- tool length ----------------------------------------------------------------------------
    def _program_mm(self) -> float:
        """mm per program unit now (the toolpath's machine is in mm: its frame's scale)."""
        return self.toolpath.frame.scale

    def _tool_length(self, line: int) -> None:
        """The tool length offset now: a tool's in the table stays ``G43 H<tool>``; any other
        is folded into the coordinates."""
        tlo = self.toolpath.frame.tlo  # machine units (mm)
        if not any(tlo):
            if self.kept is not None:
                self.write("G49", line)
                self.kept, self.kept_offset = None, (0.0,) * 6
                self._forget()
            return
        if self.target.tool_length in ("G43 H", "G43.1") and not self.fold_lengths:
            for number in (self.toolpath.tool, self.selected):
                entry = self.tool_entry(number) if number > 0 else None
                if entry is None or not _same(entry.offsets[:6], tlo):
                    continue
                if self.target.tool_length == "G43.1":
                    if any(entry.offsets[i] for i in (0, 1, 3, 4, 5)):
                        break  # (G43.1 moves Z alone: a length off Z is folded)
                    words = f"G43.1 Z{self._number(entry.offsets[2] / self.scale)}"
                else:
                    words = f"G43 H{number}"
                if self.kept != number:
                    self.write(words, line)
                self.kept = number
                self.kept_offset = tuple(entry.offsets[:6])  # type: ignore[assignment]
                self._forget()
                return
        if self.kept is not None:
            self.write("G49", line)
        self.kept, self.kept_offset = None, (0.0,) * 6
        self._forget()


def _significant(text: str) -> str:
    """A line as a controller counts it: without spaces and comments."""
    out, depth = [], 0
    for c in text:
        if c == "(":
            depth += 1
        elif c == ")" and depth:
            depth -= 1
        elif not depth and not c.isspace():
            out.append(c)
    return "".join(out)


def _same(a: Sequence[float], b: Sequence[float]) -> bool:
    return all(abs(x - y) <= 1e-9 * max(1.0, abs(x)) for x, y in zip(a, b, strict=True))


def _comment_text(text: str) -> str:
    """Text a comment can hold: no parentheses, no line breaks."""
    return text.replace("(", "[").replace(")", "]").replace("\n", " ").replace("\r", " ")
