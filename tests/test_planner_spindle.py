"""Moves that go with the spindle, timed by hand: feed per revolution (G95), spindle-synchronised
moves (G33, G76), rigid tapping (G33.1), constant surface speed (G96) up to its D.

Each program is in G61.1 (every move stops), on the default machine: Z 100 mm/s and 500 mm/s²,
X 200 mm/s and 1000 mm/s².  A straight move of length L at speed v from rest to rest takes
L / v + v / a when it reaches v; stops round to the 1 ms servo period.
"""

from __future__ import annotations

import math

import pytest

from ngc.planner.timing import time_text

A_Z = 500.0
A_X = 1000.0


def trapezoid(length: float, speed: float, accel: float) -> float:
    """Rest to rest: a trapezoid if the move is long enough to reach ``speed``, a triangle if
    not."""
    if length < speed * speed / accel:
        return 2.0 * math.sqrt(length / accel)
    return length / speed + speed / accel


def motion(text: str) -> float:
    """The time of the program's moves (the spindle starts and stops take none here)."""
    result = time_text("G21 G90 G61.1 G18\n" + text + "M2\n")
    return result.total_s


@pytest.mark.parametrize(("program", "expected"), [
    # G95: 0.1 mm per revolution at 1000 rpm is 1000 * 0.1 / 60 mm/s
    ("S1000 M3\nG95 G1 Z-10 F0.1\n", trapezoid(10.0, 100.0 / 60.0, A_Z)),
    # G33 at 500 rpm, 1.25 mm per revolution: 10.4167 mm/s, down 30 mm
    ("S500 M3\nG33 Z-30 K1.25\n", trapezoid(30.0, 1.25 * 500 / 60.0, A_Z)),
    # G33.1: down 15 mm and back up, stopping at the bottom
    ("S500 M3\nG0 Z5\nG33.1 Z-10 K1.25\n",
     trapezoid(5.0, 100.0, A_Z) + 2.0 * trapezoid(15.0, 1.25 * 500 / 60.0, A_Z)),
])
def test_moves_that_go_with_the_spindle(program: str, expected: float) -> None:
    assert motion(program) == pytest.approx(expected, abs=0.0025)


def test_constant_surface_speed_sets_the_spindle_from_the_radius() -> None:
    # G96 S100: 100 m/min at X 20 (radius 20 mm) is 100000 / (2π·20) = 795.8 rpm; G33 K2
    # along Z at that radius: 2 * 795.8 / 60 mm/s
    rpm = 100_000 / (2.0 * math.pi * 20.0)
    body = "G96 D3000 S100 M3\nG0 X20 Z0\nG33 Z-40 K2\n"
    assert motion(body) == pytest.approx(trapezoid(20.0, 200.0, A_X)
                                         + trapezoid(40.0, 2.0 * rpm / 60.0, A_Z),
                                         abs=0.0025)


def test_constant_surface_speed_stops_at_d() -> None:
    # at X 2 the surface speed would need 7958 rpm: D1000 holds it at 1000
    body = "G96 D1000 S100 M3\nG0 X2 Z0\nG33 Z-40 K2\n"
    assert motion(body) == pytest.approx(trapezoid(2.0, 200.0, A_X)
                                         + trapezoid(40.0, 2.0 * 1000 / 60.0, A_Z),
                                         abs=0.0025)


def test_threading_cycle_runs_at_the_spindle_speed() -> None:
    slow = motion("S200 M3\nG0 X12 Z2\nG76 P1.5 Z-20 I-1 J0.2 K1 Q29.5 L0\n")
    fast = motion("S400 M3\nG0 X12 Z2\nG76 P1.5 Z-20 I-1 J0.2 K1 Q29.5 L0\n")
    assert 1.6 < slow / fast < 2.0  # the threading passes take half the time, the rapids not


def test_a_feed_that_works_out_to_zero_is_refused_with_its_line() -> None:
    from ngc.canon import ops
    from ngc.planner.lookahead import Planner
    from ngc.planner.machine import DEFAULT_MACHINE
    from ngc.planner.moves import NoSpeed, PathSink

    sink = PathSink(DEFAULT_MACHINE, Planner(DEFAULT_MACHINE, lambda seg: None),
                    lambda kind, seconds, line: None).toolpath
    sink.emit(ops.SetFeedRate(0.0), "", 3)
    with pytest.raises(NoSpeed) as caught:
        sink.emit(ops.StraightFeed(10.0, 0.0, 0.0, 0.0, 0.0, 0.0), "", 4)
    assert caught.value.line == 4
    assert "no speed" in str(caught.value)
