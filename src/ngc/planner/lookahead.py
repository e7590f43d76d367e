"""The look-ahead planner: joins moves the way LinuxCNC 2.9's trajectory planner does, as observed
on its motion controller (see ``docs/time.md``), and times them.

Moves come in with :meth:`Planner.add`; :meth:`Planner.stop` ends motion (a dwell, an M-code, the
end of the program).  A move's end is decided when the next one comes: in blend mode (G64) a
corner between two lines is rounded by an arc, a (nearly) tangent join is passed at speed, other
joins stop.  A backward pass gives each move the speed it may end with so that every later move
can still slow down in time; a forward pass then runs each move's speed profile (a trapezoid) from
the speed the move before really ended with.  Finished moves go to the ``done`` callback with their
times, so memory stays bounded by the look-ahead window.
"""

from __future__ import annotations

import math
from collections import deque
from collections.abc import Callable

from ..errors import NgcError
from .arcjoin import (
    arc_arc_fit,
    arc_away_tolerance,
    arc_blend_cap,
    arc_room,
    arc_tolerance,
    arcs_at,
    coplanar,
    helical,
    line_arc_fit,
    too_wide_for_arc,
)
from .geometry import (
    Arc,
    BlendArc,
    Corner,
    Line,
    Piece,
    angle_between,
    blend_arc,
    corner_reach,
    radius_of,
)
from .machine import Machine
from .segment import (
    ARC,
    BLEND,
    EXACT,
    PARABOLIC,
    RAPID,
    STOP,
    TANGENT,
    Segment,
    Shape,
)

SQRT3_2 = math.sqrt(3.0) / 2.0
# s: the longest run the planner counts (some 31,700 years).  Past it a time is no estimate,
# and its sums lose the servo period's precision long before they overflow.
MAX_SECONDS = 1e12
# the share of a servo cycle past a whole number of cycles that a group of joined moves may last
# and still take only those cycles (the sums' rounding error, not one more cycle)
CYCLE_NOISE = 1e-6
# the most of an axis's acceleration a kink or an exact-path corner may take: the moves beside it
# keep at least the rest, whatever ARC_BLEND_KINK_RATIO says (a ratio of 1 or more would leave
# them none, or less than none)
MAX_KINK_SHARE = 0.999

_new = tuple.__new__  # a NamedTuple made without its Python __new__


Done = Callable[[Segment], None]


def profile_time(v0: float, v1: float, vmax: float, a: float, length: float) -> tuple[float, float,
                                                                                       float]:
    """Time, end speed and peak speed of a trapezoid over ``length`` from ``v0`` toward ``v1``
    with acceleration ``a`` and speed limit ``vmax``."""
    if length <= 0.0:
        return 0.0, v0, v0
    if v0 > vmax:
        # entered above its own speed (a feed that drops after a corner blend): it slows down
        # to it at once, then runs as usual
        d_slow = (v0 * v0 - vmax * vmax) / (2.0 * a)
        if d_slow >= length:
            v = math.sqrt(v0 * v0 - 2.0 * a * length)
            return 2.0 * length / (v0 + v), v, v0
        t, v1, _ = profile_time(vmax, v1, vmax, a, length - d_slow)
        return (v0 - vmax) / a + t, v1, v0
    if v0 * v0 - 2.0 * a * length > v1 * v1:
        # cannot slow down to v1 in time (a corner blend entered at its full speed, or a
        # look-ahead too short): it slows down all along, and the next move goes on
        v = math.sqrt(v0 * v0 - 2.0 * a * length)
        return 2.0 * length / (v0 + v), v, v0
    reach = math.sqrt(v0 * v0 + 2.0 * a * length)
    if v1 > reach:
        v1 = reach
    if vmax < v1:
        vmax = v1
    vp2 = a * length + 0.5 * (v0 * v0 + v1 * v1)
    vp = math.sqrt(vp2)
    if vp > vmax:
        vp = vmax
    if vp <= 0.0:
        return 0.0, 0.0, 0.0
    d_acc = (vp * vp - v0 * v0) / (2.0 * a)
    d_dec = (vp * vp - v1 * v1) / (2.0 * a)
    cruise = length - d_acc - d_dec
    if cruise < 0.0:
        cruise = 0.0
    return (vp - v0) / a + (vp - v1) / a + cruise / vp, v1, vp


class Planner:
    """Plans and times a stream of segments on ``machine``; ``done`` receives each segment once
    its time is known."""

    def __init__(self, machine: Machine, done: Done) -> None:
        self.machine = machine
        self.period = machine.servo_period
        self.kink_ratio = min(machine.arc_blend_kink_ratio, MAX_KINK_SHARE)
        self.depth = max(1, machine.arc_blend_optimization_depth)
        axes = [machine.axes.get(a) for a in "XYZ"]
        # per axis X Y Z: 1 / acceleration (0: the axis has no limit)
        self.inv_accel = [1.0 / lim.max_acceleration if lim and lim.max_acceleration > 0.0
                          else 0.0 for lim in axes]
        # per axis X Y Z: 1 / velocity (0: the axis has no limit)
        self.inv_vel = [1.0 / lim.max_velocity if lim and lim.max_velocity > 0.0 else 0.0
                        for lim in axes]
        self.vcap = machine.max_linear_velocity
        self.queue: deque[Segment] = deque()
        self.done = done
        self.clock = 0.0  # time at which the current group of joined moves started
        self.group = 0.0  # time of the moves run since the last stop
        self.vnow = 0.0  # speed at the end of the last move run
        self.overlap = 0.0  # how long the next move runs alongside the last one
        self.rapid_corners_stop = False  # a corner between two rapids stops (after a canned cycle)

    # -- adding moves ------------------------------------------------------------------------
    def add(self, seg: Segment) -> None:
        q = self.queue
        if q:
            prev = q[-1]
            if prev.wide is not None:
                # a wide arc takes the acceleration its normal share leaves once a move follows
                prev.accel, prev.half = prev.wide
                prev.wide = None
            self._join(prev, seg)
        q.append(seg)
        self._backward()
        window = self.depth + 2
        while len(q) > window:
            self._run(q.popleft())

    def _join(self, prev: Segment, seg: Segment) -> None:
        """Decide how ``prev`` ends, now that ``seg`` follows it."""
        mode = prev.mode
        if mode == STOP or prev.length <= 0.0 or (prev.kind == RAPID) != (seg.kind == RAPID):
            prev.term = STOP
            return
        u1, u2 = prev.end_dir, seg.start_dir
        dx, dy, dz = u2[0] - u1[0], u2[1] - u1[1], u2[2] - u1[2]
        sx, sy, sz = u2[0] + u1[0], u2[1] + u1[1], u2[2] + u1[2]
        theta = 2.0 * math.atan2(math.sqrt(dx * dx + dy * dy + dz * dz),
                                 math.sqrt(sx * sx + sy * sy + sz * sz))
        vmax = prev.vmax if prev.vmax < seg.vmax else seg.vmax
        if theta < 1e-9:
            prev.term = TANGENT
            prev.vend = vmax
            return
        # The join is a kink the axes can take in one servo cycle at full speed: the change of
        # velocity, per axis, needs at most the kink ratio of that axis's acceleration.
        ia = self.inv_accel
        need = max(abs(dx) * ia[0], abs(dy) * ia[1], abs(dz) * ia[2]) * vmax / self.period
        if need < self.kink_ratio:
            prev.term = TANGENT
            prev.vend = vmax
            used = 1.0 - need
            prev.reduce = min(prev.reduce, used)
            seg.reduce = min(seg.reduce, used)
            return
        if theta > math.pi - 1e-3:  # a turn back stops, whatever the mode
            prev.term = STOP
            return
        if mode == EXACT:
            prev.term = EXACT
            factor = 1.0 - max(self.kink_ratio, 1.0 - MAX_KINK_SHARE)
            prev.reduce = min(prev.reduce, factor)
            seg.reduce = min(seg.reduce, factor)
            return
        if self.rapid_corners_stop and seg.kind == RAPID:
            prev.term = STOP
            return
        # blend mode: a corner is rounded by an arc where it can be (arcjoin), else it keeps a
        # parabolic blend
        if self.machine.arc_blend_enable and prev.kind != BLEND:
            if isinstance(prev.shape, Line) and isinstance(seg.shape, Line):
                if self._blend(prev, seg, theta, True) is None:
                    prev.term = STOP
                return
            # with an arc: rounded when both lie in one plane, with or without P (a line across
            # the plane of an arc keeps a parabolic blend under G64 P too); never beside a helix
            if (coplanar(prev.shape, seg.shape)
                    and not helical(prev.shape) and not helical(seg.shape)
                    and self._blend(prev, seg, theta, False) is not None):
                return
        prev.term = PARABOLIC
        seg.soft = True
        # both moves of a parabolic blend keep half the normal acceleration: arcs slow down
        prev.vmax = min(prev.vmax, prev.vsoft)
        seg.vmax = min(seg.vmax, seg.vsoft)

    def _blend(self, prev: Segment, seg: Segment, theta: float, lines: bool) -> Segment | None:
        """Round the corner of ``prev`` and ``seg`` (two lines if ``lines``, else at least one
        arc) by an arc, put between them in the queue; None if it cannot be."""
        u1, u2 = prev.end_dir, seg.start_dir
        # acceleration and speed limits in the plane of the corner
        cos_t = u1[0] * u2[0] + u1[1] * u2[1] + u1[2] * u2[2]
        wx, wy, wz = u2[0] - cos_t * u1[0], u2[1] - cos_t * u1[1], u2[2] - cos_t * u1[2]
        n = math.sqrt(wx * wx + wy * wy + wz * wz)
        if n > 1e-12:
            wx, wy, wz = wx / n, wy / n, wz / n
        else:
            wx = wy = wz = 0.0
        # each axis's share of the plane (the length of its unit vector projected on it) over
        # its limit: the greatest of them says what the plane allows
        cx = math.sqrt(u1[0] * u1[0] + wx * wx)
        cy = math.sqrt(u1[1] * u1[1] + wy * wy)
        cz = math.sqrt(u1[2] * u1[2] + wz * wz)
        ia, iv = self.inv_accel, self.inv_vel
        k = max(cx * ia[0], cy * ia[1], cz * ia[2])
        amax = 1.0 / k if k > 0.0 else math.inf
        k = max(cx * iv[0], cy * iv[1], cz * iv[2])
        vlim = 1.0 / k if k > 0.0 else math.inf
        if self.vcap is not None and self.vcap < vlim:
            vlim = self.vcap
        goal = prev.vmax if prev.vmax > seg.vmax else seg.vmax
        if vlim < goal:
            goal = vlim
        # each move gives at most half its programmed length, and what it has left
        room = 0.5 * (prev.full_length if prev.full_length < seg.full_length
                      else seg.full_length)
        if prev.length < room:
            room = prev.length
        if seg.length < room:
            room = seg.length
        pl, sl = prev.shape, seg.shape
        tolerance = prev.tolerance
        if tolerance < 0.0 and lines:
            tolerance = 0.0  # before any G61/G64: beside an arc only
        if not lines:
            if too_wide_for_arc(prev, seg, theta, goal, amax):
                return None  # a parabolic blend
            room = arc_room(prev, seg, room)
            if tolerance != 0.0:  # (< 0: the tolerance before any G61/G64, for arcs only)
                # a blend with an arc is drawn as a Corner: keep it within the tolerance, with
                # the curvature of an arc that curves into the corner (one that curves away bends
                # away from the blend: a line, an arc of r 2 curving away from both 30° corners
                # and a line under G64 P0.01 run their corners at 15.67 mm/s, as two lines)
                bend = min((arc.radius for arc, _, same in arcs_at(prev, seg) if same),
                           default=math.inf)
                room = min(room, corner_reach(theta, abs(tolerance), bend))
                tolerance = arc_tolerance(prev, seg, theta)
            tolerance = arc_away_tolerance(prev, seg, tolerance)
            goal = min(goal, arc_blend_cap(prev, seg, theta, amax, room))
        b = blend_arc(theta, goal, room, tolerance, 0.5 * amax, SQRT3_2 * amax)
        if b is None or b.trim <= 0.0:
            return None
        d = b.trim
        if isinstance(pl, Line) and isinstance(sl, Line):
            # the lines are cut when their path is asked for (Segment.path)
            arc: Shape = _new(BlendArc, (pl.end, u1, u2, b.radius, d, theta, b.length))
            prev.cut1 = d
            seg.cut0 = d
            prev.length -= d
            seg.length -= d
        else:
            pl, sl = prev.path(), seg.path()
            prev.cut0 = prev.cut1 = seg.cut0 = seg.cut1 = 0.0
            corner = pl.point(pl.length)
            d0 = d1 = d
            length = b.length
            fit = None
            if coplanar(pl, sl):
                # a circle tangent to the line or arc on each side
                if isinstance(pl, Line) or isinstance(sl, Line):
                    fit = line_arc_fit(prev, seg, theta, b.radius, room, b.speed,
                                       SQRT3_2 * amax, 2.0 * self.period)
                else:
                    fit = arc_arc_fit(prev, seg, theta, b.radius, room, b.speed,
                                      SQRT3_2 * amax, 2.0 * self.period)
            if fit is not None:
                d0, d1, length = fit
            prev.shape = _trimmed(pl, 0.0, pl.length - d0)
            seg.shape = _trimmed(sl, d1, sl.length - d1)
            arc = Corner(prev.shape.point(prev.shape.length), corner, seg.shape.point(0.0),
                         length, u1, u2)
            b = b._replace(length=length)
            prev.length = prev.shape.length
            seg.length = seg.shape.length
        vmax = b.speed
        short = b.length / (2.0 * self.period)  # a blend is at least two servo cycles long
        if short < vmax:
            vmax = short
        blend = Segment(BLEND, prev.line, prev.tool, arc, vmax, 0.5 * amax, prev.mode,
                        prev.tolerance, 0.0, (u1, u2), TANGENT)
        prev.term = TANGENT
        prev.vend = vmax
        blend.vend = vmax
        if lines:
            seg.ramp_in = True
            if prev.ramp_in:
                if prev.length < MERGE_TIME * vmax:
                    # so short a line between two blends runs as part of the second one
                    prev.vmax = vmax  # the blend's, even above the line's own feed
                    prev.accel = min(prev.accel, 0.5 * amax)
                    prev.half = min(prev.half, 0.5 * amax)
                    before = self.queue[-2] if len(self.queue) > 1 else None
                    if before is not None and before.kind == BLEND and vmax < before.vend:
                        before.vend = vmax  # and the blend before it ends at that speed
                else:
                    prev.ramp = True
        # the blend goes between prev and seg
        self.queue.append(blend)
        return blend

    # -- planning ------------------------------------------------------------------------------
    def _backward(self) -> None:
        q = self.queue
        n = len(q)
        nxt = q[-1]
        nxt.vfinal = nxt.vreach = 0.0
        # the move that ends the run with a parabolic end may be entered no faster than the peak
        # of a triangle over its length, √(a·L), where a stop allows √(2·a·L) (measured: a
        # quarter circle after a corner blend, the program's last move, entered at 40.3 mm/s,
        # √(250 mm/s² · 6.49 mm))
        k = 1.0 if nxt.term == PARABOLIC else 2.0
        i = n - 2
        count = 0
        while i >= 0 and count < self.depth:
            seg = q[i]
            if seg.term != TANGENT:
                v = reach = 0.0
            else:
                # (Segment.effective_accel, written out: this loop is the planner's hottest)
                if nxt.term == PARABOLIC or nxt.soft:
                    a = nxt.half * nxt.reduce
                else:
                    a = nxt.accel * nxt.reduce
                v = math.sqrt(nxt.vreach * nxt.vreach + k * a * nxt.length)
                if v > seg.vend:
                    v = seg.vend
                if v > seg.vmax:
                    v = seg.vmax
                reach = v
                if v > nxt.vmax:
                    v = nxt.vmax
                if seg.kind is not BLEND:
                    reach = v
            if v == seg.vfinal and reach == seg.vreach and count > 0:
                break
            seg.vfinal = v
            seg.vreach = reach
            k = 2.0
            nxt = seg
            i -= 1
            count += 1

    # -- running ------------------------------------------------------------------------------
    def _run(self, seg: Segment) -> None:
        term = seg.term
        a = seg.effective_accel()
        vin = self.vnow
        vmax = seg.vmax
        if vin == vmax and seg.vfinal == vmax and vmax > 0.0:  # cruise: most moves of a run
            t, vout, peak = seg.length / vmax, vmax, vmax
        else:
            t, vout, peak = profile_time(vin, seg.vfinal, vmax, a, seg.length)
            if seg.ramp:
                t, vout, peak = ramp_time(vin, seg.vfinal, a, seg.length, (t, vout, peak))
        if not t <= MAX_SECONDS:  # (not a number either)
            raise TooLong(seg.line)
        seg.vin = vin
        seg.vout = vout
        seg.peak = peak
        seg.time = t
        # the start that runs alongside the move before: no longer than this move itself (the
        # overlap is worked out from the moves' lengths, not from this time)
        overlap = self.overlap if self.overlap < t else t
        seg.t0 = self.clock + self.group - overlap
        seg.overlap = overlap  # the start of this move that runs alongside the one before
        self.group += t - overlap
        self.vnow = vout
        if term == PARABOLIC and self.queue:
            # The next move starts while this one slows down: the ramps overlap.
            self.overlap = min(parabolic_overlap(seg, a, peak, self.queue[0]), t)
        else:
            self.overlap = 0.0
            if term != TANGENT or vout <= 0.0:
                self._settle()
        self.done(seg)

    def _settle(self) -> None:
        """Motion has come to rest: round the group of joined moves up to whole servo cycles.
        A group less than :data:`CYCLE_NOISE` of a cycle past a whole number of cycles is the
        sums' rounding error: it takes those cycles, but never less than it lasts itself (the
        moves' own times, which by_kind, by_tool and by_line add up, fit in the total)."""
        if self.group > 0.0:
            cycles = math.ceil(self.group / self.period - CYCLE_NOISE)
            whole = cycles * self.period
            self.clock += whole if whole >= self.group else self.group
        self.group = 0.0
        self.vnow = 0.0

    def stop(self) -> None:
        """Motion stops after the moves given so far (the queue drains)."""
        q = self.queue
        if q:
            q[-1].term = q[-1].mode
            self._backward()
        while q:
            self._run(q.popleft())
        self._settle()

    def wait(self, seconds: float) -> None:
        """Stand still for ``seconds`` after motion has stopped."""
        self.stop()
        self.clock += seconds

    @property
    def total(self) -> float:
        return self.clock + self.group


class TooLong(NgcError):
    """A move, a standstill or a whole program that takes longer than :data:`MAX_SECONDS`."""

    def __init__(self, line: int | None) -> None:
        super().__init__(f"ngc time: the program runs for more than {MAX_SECONDS:g} s here: "
                         "too long to time", line=line)


def parabolic_overlap(seg: Segment, a1: float, peak: float, nxt: Segment) -> float:
    """How long ``nxt`` runs while ``seg`` finishes its parabolic end: the blend lasts as long as
    the slower of the two ramps, but no longer than it takes to run the shorter move."""
    a2 = nxt.effective_accel()
    if a1 <= 0.0 or a2 <= 0.0 or seg.length <= 0.0 or nxt.length <= 0.0:
        return 0.0
    v1 = min(peak, math.sqrt(a1 * seg.length))
    v2 = min(nxt.vmax, math.sqrt(a2 * nxt.length))
    if v1 <= 0.0 or v2 <= 0.0:
        return 0.0
    t_blend = min(max(v1 / a1, v2 / a2), seg.length / v1, nxt.length / v2)
    vb = min(v1, t_blend * a1)
    if seg.tolerance > 0.0:
        # the two ramps together cut the corner by about vb² / (4 a) · sin(θ / 2): keep that
        # within the tolerance
        half = 0.5 * angle_between(seg.end_dir, nxt.start_dir)
        if half > 1e-9:
            # the ramp, vb² / (2·a1) long, stays within the reach of a corner blend (where a
            # line meets an arc, counted with half its radius); two arcs curve alike and count
            # as straight here
            r1, r2 = radius_of(seg.shape), radius_of(nxt.shape)
            r = 0.5 * min(r1, r2) if r1 == math.inf or r2 == math.inf else math.inf
            vb = min(vb, math.sqrt(2.0 * a1 * corner_reach(2.0 * half, seg.tolerance, r)))
        # next to an arc of radius r (acceleration a in its plane), whatever the kink, the blend
        # is kept to 2·a·√(P·r) / v, v the faster move's speed before the blend halved its
        # centripetal share (a helix of r 3 into a circle at F3000, F4200, F6000: LinuxCNC
        # 1.812, 1.809, 1.809 s; with the halved speed, 38.02 mm/s, ngc took 1.803, 1.799, 1.799)
        for other in (seg, nxt):
            shape = other.shape.base if isinstance(other.shape, Piece) else other.shape
            if isinstance(shape, Arc) and other.kind == ARC:
                v = max(seg.vfeed, nxt.vfeed)
                vb = min(vb, 8.0 * other.half * math.sqrt(seg.tolerance * shape.radius) / v)
    return vb / a1


RAMP_TIME = 0.01098  # s: a line between two corner blends run in less than this is a ramp
MERGE_TIME = 0.00385  # s: a line between two corner blends shorter than the second one runs in
# this time joins it


def ramp_time(v0: float, v1: float, a: float, length: float,
              trapezoid: tuple[float, float, float]) -> tuple[float, float, float]:
    """A line cut by corner blends at both ends that takes less than RAMP_TIME goes straight
    from its start speed to its end speed (at most what its acceleration ``a`` reaches) with no
    peak in between; a longer one keeps its ``trapezoid``."""
    reach = math.sqrt(v0 * v0 + 2.0 * a * length)
    if v1 > reach:
        v1 = reach
    if v0 + v1 <= 0.0:
        return trapezoid
    t = 2.0 * length / (v0 + v1)
    if t >= RAMP_TIME:
        return trapezoid
    return t, v1, max(v0, v1)
def _trimmed(shape: Shape, s0: float, length: float) -> Shape:
    """``shape`` from path length ``s0`` on, ``length`` long."""
    if isinstance(shape, Line):
        return Line(shape.point(s0), shape.point(s0 + length), length)
    if isinstance(shape, Piece):
        return Piece(shape.base, shape.s0 + s0, length)
    if isinstance(shape, Arc):
        return Piece(shape, s0, length)
    return shape
