"""The timed motion as a trajectory: the machine's position and path speed sampled at regular
times, from each finished segment's speed profile and shape (``ngc time --trajectory``).

A segment runs a trapezoid: from ``vin`` it speeds up at its acceleration to ``peak``, cruises,
and slows down to ``vout``, all within ``time`` from ``t0``.  :class:`Profile` turns that into the
path length covered at any time, scaled so that the segment ends exactly at its length whatever
rounding the planner did: the position is then continuous from one segment to the next.

Segments may overlap in time (a parabolic blend: the next move starts while the one before slows
down); the machine's position is then the sum of both moves, the older one's position plus the
newer one's displacement from its start, and its velocity the sum of both velocity vectors.

:class:`TrajectoryWriter` takes the segments and standstills of a :class:`~ngc.planner.timing.Timer`
(``on_segment``, ``on_wait``) as they are finished and writes CSV rows as soon as no later segment
can change them, so memory stays flat however long the program is.
"""

from __future__ import annotations

import math
from collections import deque
from collections.abc import Iterable, Iterator, Sequence
from itertools import islice
from typing import Protocol

from .geometry import Pos
from .machine import Machine
from .segment import Segment

POSITION_AXES = "XYZABC"  # the order of a planner position
ALWAYS = "XYZ"  # columns written whatever the machine's axes
ROTARY = "ABC"  # columns written only for a machine with that axis
TIME_EPSILON = 1e-9  # s: a sample this close to a boundary belongs to the time after it
TANGENT_STEP = 1e-6  # relative to a segment's length: the step of a numerical tangent
DEFAULT_MAX_ROWS = 10_000_000  # rows of a trajectory: some 2.8 hours at one a millisecond


class TooManyRows(Exception):
    """The trajectory would have more rows than its writer may write; the message says how
    to get one."""

    def __init__(self, end: float, every: float, max_rows: int) -> None:
        super().__init__(f"the trajectory would have more than {max_rows} rows (a row every "
                         f"{every:g} s up to {end:.3f} s at least): give --every a larger "
                         "spacing or --max-rows a larger number")


class Writable(Protocol):
    """Where the rows go: a text file, or anything with its ``write``."""

    def write(self, text: str, /) -> object: ...


class Shape(Protocol):
    """What the trajectory needs of a segment's shape."""

    @property
    def length(self) -> float: ...

    def point(self, s: float) -> Pos: ...


class Profile:
    """One segment's motion in time: the path length and speed at an absolute time ``t``
    (before ``t0``: at the start, after ``t1``: at the end).

    >>> from ngc.planner.geometry import Line
    >>> line = Line((0.0,) * 6, (10.0, 0.0, 0.0, 0.0, 0.0, 0.0), 10.0)
    >>> p = Profile(line, t0=1.0, time=2.0, vin=0.0, peak=10.0, vout=0.0, accel=10.0)
    >>> p.distance(2.0), p.speed(2.0), p.distance(3.0), p.point(2.5)[0]
    (5.0, 10.0, 10.0, 8.75)
    """

    __slots__ = ("_a_acc", "_a_dec", "_d_acc", "_d_cruise", "_scale", "_t_acc", "_t_dec_start",
                 "end", "length", "line", "peak", "shape", "start", "t0", "t1", "vin")

    def __init__(self, shape: Shape, *, t0: float, time: float, vin: float, peak: float,
                 vout: float, accel: float, line: int = 0) -> None:
        self.shape = shape
        self.line = line
        self.length = shape.length
        self.t0 = t0
        self.t1 = t0 + max(time, 0.0)
        self.start = shape.point(0.0)
        self.end = shape.point(self.length)
        self._fit(max(time, 0.0), vin, max(peak, vin, vout), vout, accel)

    def _fit(self, time: float, vin: float, peak: float, vout: float, accel: float) -> None:
        """The ramps' durations and accelerations within ``time``, and the scale that makes
        the profile cover the segment's length exactly."""
        t_acc = (peak - vin) / accel if 0.0 < accel < math.inf else 0.0
        t_dec = (peak - vout) / accel if 0.0 < accel < math.inf else 0.0
        if t_acc + t_dec > time:  # the planner's rounding: fit the ramps into the time given
            fit = time / (t_acc + t_dec)
            t_acc, t_dec = t_acc * fit, t_dec * fit
        cruise = time - t_acc - t_dec
        self.vin, self.peak = vin, peak
        self._t_acc = t_acc
        self._t_dec_start = t_acc + cruise
        self._a_acc = (peak - vin) / t_acc if t_acc > 0.0 else 0.0
        self._a_dec = (peak - vout) / t_dec if t_dec > 0.0 else 0.0
        self._d_acc = 0.5 * (vin + peak) * t_acc
        self._d_cruise = peak * cruise
        covered = self._d_acc + self._d_cruise + 0.5 * (peak + vout) * t_dec
        if covered > 0.0:
            self._scale = self.length / covered
        else:  # no speed to speak of: cover the length evenly over the time
            self.vin = self.peak = 1.0
            self._a_acc = self._a_dec = self._d_acc = 0.0
            self._t_acc, self._t_dec_start = 0.0, time
            self._d_cruise = time
            self._scale = self.length / time if time > 0.0 else 0.0

    @classmethod
    def of(cls, seg: Segment) -> Profile:
        """The profile of a finished segment."""
        return cls(seg.path(), t0=seg.t0, time=seg.time, vin=seg.vin, peak=seg.peak,
                   vout=seg.vout, accel=seg.effective_accel(), line=seg.line)

    def distance(self, t: float) -> float:
        """The path length covered at time ``t``."""
        if t >= self.t1:
            return self.length
        tau = t - self.t0
        if tau <= 0.0:
            return 0.0
        if tau < self._t_acc:
            raw = (self.vin + 0.5 * self._a_acc * tau) * tau
        elif tau < self._t_dec_start:
            raw = self._d_acc + self.peak * (tau - self._t_acc)
        else:
            d = tau - self._t_dec_start
            raw = self._d_acc + self._d_cruise + (self.peak - 0.5 * self._a_dec * d) * d
        return min(raw * self._scale, self.length)

    def speed(self, t: float) -> float:
        """The path speed at time ``t``: ``vin`` before the segment starts, 0 once it ends."""
        if t >= self.t1:
            return 0.0
        tau = max(t - self.t0, 0.0)
        if tau < self._t_acc:
            return (self.vin + self._a_acc * tau) * self._scale
        if tau < self._t_dec_start:
            return self.peak * self._scale
        return max(self.peak - self._a_dec * (tau - self._t_dec_start), 0.0) * self._scale

    def point(self, t: float) -> Pos:
        """The position at time ``t``."""
        if t >= self.t1:
            return self.end
        return self.shape.point(self.distance(t))

    def velocity(self, t: float) -> list[float]:
        """The velocity vector (per axis of a position) at time ``t``."""
        v = self.speed(t)
        if v == 0.0 or self.length <= 0.0:
            return [0.0] * 6
        s = self.distance(t)
        h = TANGENT_STEP * self.length
        s0, s1 = max(s - h, 0.0), min(s + h, self.length)
        p, q = self.shape.point(s0), self.shape.point(s1)
        f = v / (s1 - s0)
        return [(q[i] - p[i]) * f for i in range(6)]


def sample(seg: Segment, times: Iterable[float]) -> Iterator[tuple[Pos, float]]:
    """The position and path speed of the finished segment ``seg`` at each of ``times``
    (absolute, on the planner's clock; outside the segment's time it stands at its start or its
    end)."""
    profile = Profile.of(seg)
    for t in times:
        yield profile.point(t), profile.speed(t)


class TrajectoryWriter:
    """Writes a timed program's trajectory as CSV to ``out``: a header ``t,x,y,z[,a][,b][,c],
    velocity,line`` (A, B and C only for the axes the machine has), then a row every ``every``
    seconds from 0, and a last row at the end of the program (:meth:`finish`).

    Give it each finished segment (:meth:`segment`) and standstill (:meth:`wait`) in time order,
    as :class:`~ngc.planner.timing.Timer` calls its listeners.  Positions are in machine units
    (degrees for A, B and C), the velocity is the path speed in machine units per second.
    A segment or standstill that ends past the time of ``max_rows`` rows raises
    :class:`TooManyRows` before any of its rows is written.
    """

    def __init__(self, out: Writable, machine: Machine, every: float,
                 max_rows: int = DEFAULT_MAX_ROWS) -> None:
        if not every > 0.0:
            raise ValueError(f"the sample spacing must be positive, not {every!r}")
        self._write = out.write
        self._every = every
        self._max_rows = max_rows
        self._k = 0  # the next sample is at k * every
        self._columns = [i for i, axis in enumerate(POSITION_AXES)
                         if axis in ALWAYS or axis in machine.axes]
        start = machine.start_position
        self._rest: Pos = tuple(float(start.get(axis, 0.0))  # type: ignore[assignment]
                                for axis in POSITION_AXES)
        self._active: deque[Profile] = deque()
        self._line = 0
        names = [POSITION_AXES[i].lower() for i in self._columns]
        self._write(",".join(["t", *names, "velocity", "line"]) + "\n")
        self._row = "%.6f," + ",".join(["%.6f"] * len(self._columns)) + ",%.6f,%d\n"

    def segment(self, seg: Segment) -> None:
        """A finished segment: every sample before it starts is now known."""
        self._room(seg.t0 + seg.time)
        self._until(seg.t0)
        self._active.append(Profile.of(seg))

    def wait(self, kind: str, start: float, seconds: float, line: int) -> None:
        """A standstill of ``seconds`` from ``start``: motion has stopped before it."""
        self._room(start + seconds)
        self._until(start)
        self._line = line
        self._until(start + seconds)

    def finish(self, total: float) -> None:
        """The program ends at ``total`` seconds: the rows up to it, and one at ``total``."""
        self._room(total)
        self._until(total)
        self._emit(total)

    def _room(self, end: float) -> None:
        """Raise :class:`TooManyRows` if the rows up to ``end``, and the last one, would be more
        than the writer may write."""
        rows = math.ceil(end / self._every - TIME_EPSILON) + 1
        if rows > self._max_rows:
            raise TooManyRows(end, self._every, self._max_rows)

    def _until(self, end: float) -> None:
        """Write the samples before ``end``."""
        every = self._every
        t = self._k * every
        while t < end - TIME_EPSILON:
            self._emit(t)
            self._k += 1
            t = self._k * every

    def _emit(self, t: float) -> None:
        position, speed = self._state(t)
        columns = [position[i] for i in self._columns]
        self._write(self._row % (t, *columns, speed, self._line))

    def _state(self, t: float) -> tuple[Sequence[float], float]:
        """The position and path speed at ``t``; the line of the move running then."""
        active = self._active
        while active and active[0].t1 <= t + TIME_EPSILON:
            self._rest = active.popleft().end
        late = t + TIME_EPSILON
        if not active or active[0].t0 > late:
            return self._rest, 0.0
        anchor = active[0]
        self._line = anchor.line
        if len(active) == 1 or active[1].t0 > late:
            return anchor.point(t), anchor.speed(t)
        return self._overlap(t)

    def _overlap(self, t: float) -> tuple[Sequence[float], float]:
        """Moves that run at once: the oldest one's position plus the displacement of the
        others since their start; their velocities add up."""
        active = self._active
        position = list(active[0].point(t))
        velocity = active[0].velocity(t)
        for profile in islice(active, 1, None):
            if profile.t0 > t + TIME_EPSILON:
                break
            p, p0 = profile.point(t), profile.start
            v = profile.velocity(t)
            for i in range(6):
                position[i] += p[i] - p0[i]
                velocity[i] += v[i]
            self._line = profile.line
        return position, _path_speed(velocity)


def _path_speed(velocity: Sequence[float]) -> float:
    """The speed along the path: in X Y Z, or for a motion of A B C alone, in A B C (the path
    length's own definition, :mod:`ngc.planner.geometry`)."""
    linear = math.sqrt(velocity[0] ** 2 + velocity[1] ** 2 + velocity[2] ** 2)
    if linear > 0.0:
        return linear
    return math.sqrt(velocity[3] ** 2 + velocity[4] ** 2 + velocity[5] ** 2)
