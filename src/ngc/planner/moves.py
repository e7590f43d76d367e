"""From canonical operations to the planner's segments: a sink that follows the machine's state
(units, offsets, feed, the blending mode, the tool) and turns each move into a
:class:`~ngc.planner.lookahead.Segment` in machine coordinates, with its speed and acceleration
limits projected from the axes' limits.

What it models of LinuxCNC's task and canon layers (``docs/time.md``):

* ``G64 P… Q…``: straight feeds at one feed rate that stay within the naive-CAM tolerance Q of a
  straight line are merged into one move before the planner sees them; in the XY plane an arc that
  leaves its chord by less than Q is first split into two lines;
* every operation task has to wait for (a dwell, spindle, coolant, a tool change, a program stop,
  a probe) makes the machine stop there, and stand still for the time it takes.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from ..canon import ops
from ..errors import NgcError
from ..toolpath.tracker import PROBE as PROBE_MOVE
from ..toolpath.tracker import RAPID as RAPID_MOVE
from ..toolpath.tracker import ArcMove, Cubics, Toolpath
from .geometry import Line, Pos, Vec, arc_from_canon, cubic_biarcs, nurbs_polyline
from .lookahead import SQRT3_2, Planner
from .machine import MAX_COORDINATE, Machine
from .segment import ARC, EXACT, FEED, PARABOLIC, RAPID, STOP, Segment

MM_PER_INCH = 25.4
INITIAL_ARC_TOLERANCE_INCH = 0.001  # inch: the corner tolerance for arcs before any G61/G64
NURBS_TOLERANCE = 0.001  # machine units: how close the lines that run a NURBS curve stay to it
# a G5 curve runs as this many biarcs, uniform in its parameter (LinuxCNC's, measured)
G5_PIECES = 16

_new = tuple.__new__  # a NamedTuple made without its Python __new__
AXES6 = "XYZABC"


# Operations that make task wait for motion to stop, by kind of wait.
SPINDLE_START = (ops.StartSpindleClockwise, ops.StartSpindleCounterclockwise)
WAITS = (ops.StopSpindleTurning, ops.MistOn, ops.MistOff, ops.FloodOn, ops.FloodOff,
         ops.ProgramStop, ops.OptionalProgramStop, ops.OrientSpindle, ops.WaitOrientComplete,
         ops.PalletShuttle, ops.StartChange, *SPINDLE_START)

Wait = Callable[[str, float, int], None]


class PathSink:
    """A reader of the toolpath (:class:`~ngc.toolpath.tracker.Toolpath`) that feeds a
    :class:`Planner`.  ``on_wait(kind, seconds, line)`` hears of every standstill (a dwell, a
    tool change, a spindle start or stop).  ``toolpath`` is the toolpath it reads (None: one of
    its own, for the machine's units and start position, at ``self.toolpath``): positions come
    from it in machine coordinates, and the units, offsets, tool and plane are its."""

    def __init__(self, machine: Machine, planner: Planner, on_wait: Wait,
                 toolpath: Toolpath | None = None) -> None:
        self.machine = machine
        self.planner = planner
        self.on_wait = on_wait
        self.inch_machine = machine.linear_units == "inch"
        start = machine.start_position
        self.pos: Pos = tuple(float(start.get(a, 0.0)) for a in AXES6)  # type: ignore[assignment]
        if toolpath is None:
            toolpath = Toolpath(self, inch_machine=self.inch_machine, start=self.pos)
        self.toolpath = toolpath
        self.frame = toolpath.frame
        self.feed = 0.0  # units per minute (or per revolution) of the program when it was set
        self.feed_scale = 1.0  # those units to machine units: a feed keeps the units it was set
        # in (F runs before G20/G21 in the order of execution, and canon converts it when set)
        self.per_rev = False
        self.rpm = 0.0
        self.fspeed = 0.0  # the programmed feed in machine units per second
        self.css_max = 0.0  # G96: the spindle's greatest speed (rpm); 0: G97, S in rpm
        self.sync = 0.0  # G33, G33.1, G76: machine units per revolution; 0: not synchronised
        # blend mode without a tolerance until the program says otherwise, as the interpreter
        # starts (G64 without P) and as LinuxCNC runs it (measured: a square with no G61/G64
        # takes G64's time to the servo cycle)
        self.mode = PARABOLIC
        self.exact_line = -1  # the line of the last switch to exact path
        # machine units; 0: none.  Before the program's first G61/G64, LinuxCNC rounds corners
        # beside an arc as under G64 P0.001 inch, and corners of two lines as under G64 without P
        # (measured: adaptive loops of half circles and short links, 18.170 s in two runs, 17.487 s
        # after G64; a square of lines the same as after G64).  The first corners of a run do not
        # always have it: a line into a quarter circle ran as under G64 in two runs of three and
        # as under P0.001 inch in the third.  A negative tolerance says so to the planner.
        self.tolerance = -INITIAL_ARC_TOLERANCE_INCH * (1.0 if self.inch_machine else MM_PER_INCH)
        self.naive_tol = 0.0  # machine units
        self.naive_tol2 = 0.0  # its square
        self.merging = False  # G64 P… Q…: straight feeds go through the naive-CAM chain
        self.per_move = False  # the feed is worked out for each move (feed_at)
        self.tool = 0  # the tool of the moves made now (a chain keeps the one it began with)
        self.spindle_on = False
        # naive-CAM: the points after chain_start (relative to it), the lines and lengths of the
        # moves to them, and the sum of those lengths
        self.chain: list[tuple[float, float, float]] = []
        self.parts: list[tuple[int, float]] = []
        self.chain_length = 0.0
        self.chain_start: Pos = self.pos
        self.chain_feed = 0.0
        limits = []
        for name in AXES6:
            lim = machine.axes.get(name)
            limits.append((lim.max_velocity, lim.max_acceleration) if lim else None)
        self.limits = limits
        # (axis, (1 / velocity, 1 / acceleration)) for the axes that have limits
        self.inv_limits = [(i, (1.0 / lim[0], 1.0 / lim[1])) for i, lim in enumerate(limits)
                           if lim is not None]
        # the axes of a position the machine does not have: a move may not change them
        self.missing = tuple(i for i, lim in enumerate(limits) if lim is None)
        self.vcap = machine.max_linear_velocity

    # -- the toolpath's consumer protocol ------------------------------------------------------
    def straight(self, kind: str, start: Pos, end: Pos, line: int) -> None:
        if kind is RAPID_MOVE:
            self.flush_chain()
            self.line_to(self.pos, end, line, False)
        elif kind is PROBE_MOVE:
            self.wait("wait", 0.0, line)
        elif self.merging:
            self.see_point(end, line)  # the hot path of CAM surfaces
        else:
            self.flush_chain()
            self.line_to(self.pos, end, line, True)

    def arc(self, arc: ArcMove, line: int) -> None:
        self.arc_to(arc.end, arc.centre + arc.end[3:], arc.normal,
                    arc.turns, line)

    def tap(self, start: Pos, bottom: Pos, line: int) -> None:
        self.rigid_tap(bottom, line)

    def bezier(self, cubics: Cubics, motion: str, start: Pos, line: int) -> None:
        """An engine-dialect segment: the engine times its own (ngc time refuses its programs)."""

    def other(self, op: ops.Op, line: int) -> None:
        kind = type(op)
        if kind is ops.SetFeedRate:
            self.feed = op.rate  # type: ignore[attr-defined]
            self.feed_scale = self.frame.scale
            self._feed_changed()
        elif kind is ops.SetFeedMode:
            self.per_rev = op.mode == 1  # type: ignore[attr-defined]
            self._feed_changed()
        elif kind is ops.SetSpindleSpeed:
            self.rpm = op.rpm  # type: ignore[attr-defined]
            self._feed_changed()
            if self.spindle_on:
                self.wait("spindle", self.machine.spindle_start_time, line)
        elif kind is ops.SetSpindleMode:
            self.css_max = op.css_max  # type: ignore[attr-defined]
            self._feed_changed()
        elif kind is ops.StartSpeedFeedSync:
            self.flush_chain()
            self.sync = op.per_rev * self.frame.scale  # type: ignore[attr-defined]
            self._feed_changed()
        elif kind is ops.StopSpeedFeedSynch:
            self.flush_chain()
            self.sync = 0.0
            self._feed_changed()
        elif kind is ops.SetMotionControlMode:
            self.flush_chain()
            self.mode = STOP if op.mode == "CANON_EXACT_STOP" else EXACT  # type: ignore[attr-defined]
            self.exact_line = line
            self.tolerance = 0.0
            self._feed_changed()
        elif kind is ops.SetMotionControlContinuous:
            self.flush_chain()
            if line == self.exact_line:
                # exact path and back on one line: a canned cycle.  After one, LinuxCNC takes
                # the corners between two rapids at a crawl (5.15 mm/s between Z and XY on the
                # reference machine, in every program measured): they stop here
                self.planner.rapid_corners_stop = True
            self.mode = PARABOLIC
            self.tolerance = op.tolerance * self.frame.scale  # type: ignore[attr-defined]
            self._feed_changed()
        elif kind is ops.SetNaivecamTolerance:
            self.flush_chain()
            self.naive_tol = op.tolerance * self.frame.scale  # type: ignore[attr-defined]
            self.naive_tol2 = self.naive_tol * self.naive_tol
            self._feed_changed()
        elif kind is ops.UseLengthUnits:
            self._feed_changed()
        elif kind is ops.ChangeTool:
            self.flush_chain()  # the moves before the change keep the tool they were made with
            self.tool = self.toolpath.tool  # the change counts for the tool it puts in
            self.wait("tool change", self.machine.tool_change_time, line)
        elif kind is ops.ChangeToolNumber:
            self.tool = self.toolpath.tool
        elif kind is ops.Dwell:
            self.wait("dwell", op.seconds, line)  # type: ignore[attr-defined]
        elif kind in SPINDLE_START:
            self.spindle_on = True
            self.wait("spindle", self.machine.spindle_start_time, line)
        elif kind is ops.StopSpindleTurning:
            was = self.spindle_on
            self.spindle_on = False
            self.wait("spindle", self.machine.spindle_stop_time if was else 0.0, line)
        elif kind in WAITS:
            self.wait("wait", 0.0, line)
        elif kind is ops.ProgramEnd:
            self.flush_chain()
            self.planner.stop()

    def nurbs(self, curve: ops.NurbsFeed, start: Pos, line: int) -> None:
        self.nurbs_curve(curve, line)

    def finish(self) -> None:
        self.flush_chain()
        self.planner.stop()

    # -- positions ----------------------------------------------------------------------------
    def _feed_changed(self) -> None:
        """The feed in machine units per second, where it is the same for every move; else
        (G96 with a feed per revolution, or a spindle-synchronised move) it is worked out for
        each move (``feed_at``).  Straight feeds merge (naive CAM) in blend mode with a Q, at
        one feed."""
        rate = self.feed * (self.rpm if self.per_rev else 1.0)
        self.fspeed = rate * self.feed_scale / 60.0
        self.per_move = self.sync > 0.0 or (self.per_rev and self.css_max > 0.0)
        self.merging = (self.mode == PARABOLIC and self.naive_tol > 0.0
                        and not self.per_move)

    def feed_at(self, start: Pos, end: Pos) -> float:
        """The feed, in machine units per second, of a move from ``start`` to ``end`` that goes
        with the spindle: synchronised (G33: its units per revolution) or per revolution (G95),
        at the spindle's speed; under G96 that speed follows the distance from the X axis of the
        program's coordinates in the middle of the move, up to G96's D."""
        rpm = self.rpm
        if self.css_max > 0.0:
            frame = self.frame
            radius = abs(0.5 * (start[0] + end[0]) - frame.shift[0]) / frame.scale
            surface = rpm * (12.0 if frame.inch_program else 1000.0)  # per minute, program units
            circle = 2.0 * math.pi * radius
            rpm = self.css_max if circle * self.css_max <= surface else surface / circle
        per_rev = self.sync if self.sync > 0.0 else self.feed * self.feed_scale
        return per_rev * rpm / 60.0

    def check(self, end: Pos, line: int, start: Pos | None = None) -> None:
        """A move from ``start`` (the current position) to ``end`` that the machine can make:
        every coordinate within :data:`MAX_COORDINATE` (a NaN is not), no change of an axis the
        machine does not have.  Raises :class:`Unreachable` or :class:`MissingAxis`."""
        within(end, line)
        pos = self.pos if start is None else start
        for i in self.missing:
            if end[i] != pos[i]:
                raise MissingAxis(AXES6[i], tuple(self.machine.axes), line)

    # -- moves --------------------------------------------------------------------------------
    def straight_to(self, end: Pos, line: int, feed: bool) -> None:
        if feed and self.merging:
            self.see_point(end, line)
            return
        self.flush_chain()
        self.line_to(self.pos, end, line, feed)

    def see_point(self, end: Pos, line: int) -> None:
        """Naive-CAM merging: extend the chain of straight feeds to ``end`` if every point of it
        stays within the tolerance of the straight line from its start to ``end``."""
        self.check(end, line)
        f = self.fspeed
        pos = self.pos
        ex, ey, ez = end[0], end[1], end[2]
        sx, sy, sz = ex - pos[0], ey - pos[1], ez - pos[2]
        step = math.sqrt(sx * sx + sy * sy + sz * sz)
        points = self.chain
        if points:
            if (f == self.chain_feed and end[3] == pos[3] and end[4] == pos[4]
                    and end[5] == pos[5]):
                # every point of the chain within the tolerance of the line from its start
                s = self.chain_start
                dx, dy, dz = ex - s[0], ey - s[1], ez - s[2]
                ll = dx * dx + dy * dy + dz * dz
                if ll > 0.0:
                    tol2 = self.naive_tol2
                    inv = 1.0 / ll
                    for px, py, pz in points:
                        t = (px * dx + py * dy + pz * dz) * inv
                        if t < 0.0 or t > 1.0:
                            break
                        px -= t * dx
                        py -= t * dy
                        pz -= t * dz
                        if px * px + py * py + pz * pz > tol2:
                            break
                    else:
                        points.append((dx, dy, dz))
                        self.parts.append((line, step))
                        self.chain_length += step
                        self.pos = end
                        return
            self.flush_chain()
        self.pos = end
        self.chain_start = pos
        self.chain_feed = f
        self.chain = [(sx, sy, sz)]
        self.parts = [(line, step)]
        self.chain_length = step

    def flush_chain(self) -> None:
        if not self.chain:
            return
        self.chain = []
        parts = self.parts
        self.line_to(self.chain_start, self.pos, parts[-1][0], True, parts, self.chain_length)

    def line_to(self, start: Pos, end: Pos, line: int, feed: bool,
                parts: list[tuple[int, float]] | None = None, parts_length: float = 0.0) -> None:
        """A straight move; ``parts`` are the (line, length) of the programmed moves a naive-CAM
        chain merged into it, ``parts_length`` their sum."""
        if not parts:  # (a chain's points were checked as they came)
            self.check(end, line, start)
        dx, dy, dz = end[0] - start[0], end[1] - start[1], end[2] - start[2]
        da, db, dc = end[3] - start[3], end[4] - start[4], end[5] - start[5]
        length = math.sqrt(dx * dx + dy * dy + dz * dz)
        self.pos = end
        if length < 1e-9:
            length = math.sqrt(da * da + db * db + dc * dc)
            if length < 1e-9:
                return
        # no axis may exceed its own limits: the time each axis needs at its speed and at its
        # acceleration, the longest of them over the length
        delta = (dx, dy, dz, da, db, dc)
        tv = ta = 0.0
        for i, inv in self.inv_limits:
            d = abs(delta[i])
            if d > 1e-12:
                if d * inv[0] > tv:
                    tv = d * inv[0]
                if d * inv[1] > ta:
                    ta = d * inv[1]
        if tv > 0.0:
            vmax, amax = length / tv, length / ta
        else:
            vmax = amax = math.inf
        if self.vcap is not None and self.vcap < vmax:
            vmax = self.vcap
        if feed:
            if parts:
                f = self.chain_feed
            else:
                f = self.feed_at(start, end) if self.per_move else self.fspeed
            speed = f if f < vmax else vmax
        else:
            speed = vmax
        if not speed > 0.0:
            raise NoSpeed(line)
        naive = length / speed
        u = (dx / length, dy / length, dz / length)
        shape = _new(Line, (start, end, length))
        seg = Segment(FEED if feed else RAPID, line, self.tool, shape, speed, amax, self.mode,
                      self.tolerance, naive, (u, u))
        seg.parts = parts
        seg.parts_length = parts_length
        self.planner.add(seg)

    def arc_to(self, end: Pos, c: Pos, normal: Vec, turns: int, line: int) -> None:
        """An arc from the current position to ``end`` about ``c`` (machine coordinates) in the
        plane of ``normal``, ``turns`` as ARC_FEED's rotation."""
        p1, p2, pn = self.toolpath.plane
        start = self.pos
        self.check(end, line)
        within(c, line)
        for i in (p1, p2):  # an arc turns both axes of its plane
            if i in self.missing and (c[p1], c[p2]) != (start[p1], start[p2]):
                raise MissingAxis(AXES6[i], tuple(self.machine.axes), line)
        shape = arc_from_canon(start, end, (c[0], c[1], c[2]), normal, turns)
        if (self.mode == PARABOLIC and self.naive_tol > 0.0 and (p1, p2) == (0, 1)
                and abs(shape.rise) < 1e-12 and shape.sweep < math.pi
                and shape.radius * (1.0 - math.cos(0.5 * shape.sweep)) < self.naive_tol):
            mid = shape.point(0.5 * shape.length)
            self.see_point(mid, line)
            self.see_point(end, line)
            return
        self.flush_chain()
        self.pos = end
        if shape.length < 1e-9:
            return
        circ = shape.radius * shape.sweep
        rise = abs(shape.rise)
        length = shape.length
        tv = ta = 0.0
        ap = math.inf
        for i in (p1, p2):
            lim = self.limits[i]
            if lim is not None and circ > 1e-12:
                tv = max(tv, circ / lim[0])
                ta = max(ta, circ / lim[1])
                ap = min(ap, lim[1])
        lim = self.limits[pn]
        if lim is not None and rise > 1e-12:
            tv = max(tv, rise / lim[0])
            ta = max(ta, rise / lim[1])
        vmax = length / tv if tv > 0 else math.inf
        amax = length / ta if ta > 0 else math.inf
        if self.vcap is not None:
            vmax = min(vmax, self.vcap)
        accel = 0.5 * amax
        wide = None
        vsoft = math.inf
        if ap < math.inf and shape.radius > 0 and rise <= 1e-12 and amax < math.inf:
            # once another move follows it, the tangential acceleration is what the normal
            # acceleration at the move's greatest speed leaves: at the axes' speed, or at the speed
            # the normal limit allows (√3/2 of the acceleration, half of it next to a parabolic
            # blend); measured from rest, XY axes of 200 mm/s and 1000 mm/s², on arcs of r 48, 50,
            # 51, 55, 57, 60, 121: 552, 600, 620, 687, 713, 745, 944 mm/s² (the rule 553, 600,
            # 621, 687, 712, 745, 944), after a plunge's parabolic blend 375 mm/s² (r 121); the
            # program's last move keeps half (r 50: 500 mm/s²)
            v2 = vmax * vmax
            a_n = min(v2, SQRT3_2 * ap * shape.radius) / shape.radius
            a_w = max(accel, math.sqrt(max(amax * amax - a_n * a_n, 0.0)))
            a_n = min(v2, 0.5 * SQRT3_2 * ap * shape.radius) / shape.radius
            h_w = max(0.25 * amax, math.sqrt(max(0.25 * amax * amax - a_n * a_n, 0.0)))
            if a_w > accel:
                wide = (a_w, h_w)
        if ap < math.inf and shape.radius > 0:
            # the speed in the plane keeps the centripetal acceleration within √3/2 of it
            vmax = min(vmax, math.sqrt(SQRT3_2 * ap * shape.radius)
                       * (length / circ if circ > 1e-12 else 1.0))
            # a helix counts with (rise / radius)²: its normal share shrinks by 1 + q², the
            # tangential acceleration takes the rest
            q = rise / shape.radius
            q2 = q * q
            if rise > 1e-12 and amax < math.inf:
                a_n = SQRT3_2 * ap / (1.0 + q2)
                if a_n < amax:
                    accel = max(accel, math.sqrt(amax * amax - a_n * a_n))
            # next to a parabolic blend the centripetal share is halved
            vsoft = math.sqrt(0.5 * SQRT3_2 * ap * shape.radius * (1.0 + q2))
        speed = min(self.feed_at(start, end) if self.per_move else self.fspeed, vmax)
        if not speed > 0.0:
            raise NoSpeed(line)
        naive = length / speed
        seg = Segment(ARC, line, self.tool, shape, speed, accel, self.mode,
                      self.tolerance, naive)
        seg.half = 0.25 * amax  # next to a parabolic blend
        seg.wide = wide
        seg.vsoft = vsoft
        self.planner.add(seg)

    def nurbs_curve(self, op: ops.NurbsFeed, line: int) -> None:
        """G5: the cubic curve run as LinuxCNC runs it, as G5_PIECES biarcs (see
        :func:`~ngc.planner.geometry.cubic_biarcs`), each arc as an ARC_FEED of its own (naive CAM
        included); G5.1 and G5.2: the curve in the XY plane run as straight feeds within
        NURBS_TOLERANCE of it (a chain of short lines, joined as any other)."""
        z, abc = self.pos[2], self.pos[3:]
        to_machine = self.frame.to_machine
        if op.order == 4 and op.size == 4 and all(w == 1.0 for w in op.weights):
            for end, centre, turns in cubic_biarcs(op.points, G5_PIECES):
                e = to_machine((end[0], end[1], 0.0, 0.0, 0.0, 0.0))
                e = (e[0], e[1], z, abc[0], abc[1], abc[2])
                if centre is None:
                    self.straight_to(e, line, True)
                    continue
                c = to_machine((centre[0], centre[1], 0.0, 0.0, 0.0, 0.0))
                self.arc_to(e, (c[0], c[1], z, abc[0], abc[1], abc[2]), (0.0, 0.0, 1.0), turns,
                            line)
            return
        for x, y in nurbs_polyline(op.points, op.weights, op.knots, op.order, NURBS_TOLERANCE):
            p = to_machine((x, y, 0.0, 0.0, 0.0, 0.0))
            self.straight_to((p[0], p[1], z, abc[0], abc[1], abc[2]), line, True)

    def rigid_tap(self, bottom: Pos, line: int) -> None:
        """G33.1: synchronised to the point and back, stopping at the bottom (the spindle's
        reversal itself takes no time here)."""
        self.flush_chain()
        self.planner.stop()
        start = self.pos
        bottom = (bottom[0], bottom[1], bottom[2], start[3], start[4], start[5])
        mode = self.mode
        self.mode = STOP
        self.line_to(start, bottom, line, True)
        self.line_to(bottom, start, line, True)
        self.mode = mode
        self.planner.stop()

    # -- standstills --------------------------------------------------------------------------
    def wait(self, kind: str, seconds: float, line: int) -> None:
        self.flush_chain()
        self.planner.stop()
        self.on_wait(kind, seconds, line)


def within(point: Pos, line: int) -> None:
    """Raise :class:`Unreachable` unless every coordinate of ``point`` is within
    :data:`MAX_COORDINATE` of 0."""
    top = MAX_COORDINATE
    x, y, z, a, b, c = point
    if not (-top <= x <= top and -top <= y <= top and -top <= z <= top
            and -top <= a <= top and -top <= b <= top and -top <= c <= top):
        raise Unreachable(point, line)


class Unreachable(NgcError):
    """A move to a point past :data:`MAX_COORDINATE` from the origin (or not a number)."""

    def __init__(self, end: Pos, line: int) -> None:
        far = ", ".join(f"{axis} {value:.6g}" for axis, value in zip(AXES6, end, strict=True)
                        if not abs(value) <= MAX_COORDINATE)
        super().__init__(f"ngc time: the move goes past {MAX_COORDINATE:g} machine units from "
                         f"the origin ({far}): too far to time", line=line)


class MissingAxis(NgcError):
    """A move of an axis the machine does not have (one that leaves it where it is is fine)."""

    def __init__(self, axis: str, axes: tuple[str, ...], line: int) -> None:
        have = " ".join(axes) or "none"
        super().__init__(f"ngc time: the move changes {axis}, and the machine has no {axis} axis "
                         f"(its axes: {have})", line=line)


class NoSpeed(NgcError):
    """A feed that cannot move: its feed works out to 0 (the interpreter refuses such moves)."""

    def __init__(self, line: int) -> None:
        super().__init__("ngc time: the move has no speed (its feed works out to 0)", line=line)


