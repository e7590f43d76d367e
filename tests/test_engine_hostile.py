"""Hostile input on the engine dialect: lines of stray separators, and moves whose numbers ask
for more segments than a run may make (``--max-iterations``), which stream in flat memory."""

from __future__ import annotations

import itertools
import math
import time
import tracemalloc

import pytest

from ngc.engine import Engine, EngineSegment, Op, Setup, run
from ngc.errors import NgcError

PROGRAM = "G21\nF 10\nG1 X 1 Y 2\nmove PZ 0 90 1 0\nM2\n"


@pytest.mark.parametrize("separators", [",", ", ,", ",,,", "\t,", " , ", "(a comment),",
                                        ", (a comment) ,", ",; a comment", ", \t ,"])
def test_a_line_of_separators_is_empty(separators: str) -> None:
    lines = PROGRAM.splitlines()
    with_separators = "\n".join([separators, *lines[:2], separators, *lines[2:]])
    ops = list(run(with_separators))
    shifted = [op._replace(line=op.line - 2 if op.line > 3 else op.line - 1) for op in ops]
    assert shifted == list(run(PROGRAM))


@pytest.mark.parametrize("text", [",", "G90 ,", ", G90", "M2 ,", ", M2", "F 1 ,", "move X1 ,"])
def test_stray_separators_around_words(text: str) -> None:
    """A separator before or after a line's words changes nothing."""
    assert list(run(text)) == list(run(text.replace(",", " ")))


# -- the work budget and segments made one at a time ---------------------------------------------

def ops(text: str, max_iterations: int) -> list[Op]:
    return list(run(text, Engine(max_iterations=max_iterations)))


@pytest.mark.parametrize(("text", "segments"), [
    ("move PZ 0 360 1 0", 4),  # a quarter turn each
    ("move PZ 0 360 3 0", 12),  # over a radius of 1: radius x angle / 90
    ("F10\nG2 X0 Y0 I2 J0", 8),
    ("F10\nG1 X1 Y1", 1),
    ("G61\nF10\nG1 X1 Y1", 1),
])
def test_each_segment_counts_one(text: str, segments: int) -> None:
    made = ops(text, segments)
    assert sum(isinstance(op, EngineSegment) for op in made) == segments
    with pytest.raises(NgcError, match=f"Work limit reached: {segments} segments") as info:
        ops(text + "\nG91\nmove X1", segments)  # one more
    assert info.value.line == text.count("\n") + 3


def test_each_peck_counts_one() -> None:
    """G83 with a peck of 1 to a depth of 3: three pecks of three segments (in, out, back)
    less the last back, and the retract: 9 segments, 3 pecks."""
    text = "F10\nG83 Z-3 R0 Q1"
    segments = sum(isinstance(op, EngineSegment) for op in ops(text, 1000))
    ops(text, segments + 3)
    with pytest.raises(NgcError, match="Work limit reached"):
        ops(text, segments + 2)


@pytest.mark.parametrize("text", [
    "move PZ 0 360 100000000000 0",  # radius x angle: 4e11 segments
    "move PZ 0 360000000 1 0",  # 4e6 segments
    "F10\nG2 X0 Y0 I[10**200] J0",
    "F10\nG83 Z-10 R0 Q[10**-300]",  # pecks that no longer go deeper
])
def test_a_move_past_the_budget_stops_before_its_first_segment(text: str) -> None:
    started = time.process_time()  # (CPU time: a busy machine does not make it slow)
    with pytest.raises(NgcError, match="Work limit reached: 1000 ") as info:
        ops("G21\n" + text, 1000)
    assert time.process_time() - started < 2.0
    assert info.value.line == text.count("\n") + 2


def test_an_arc_too_large_to_count_its_segments() -> None:
    with pytest.raises(NgcError, match="An arc of 1e\\+300 degrees at radius 1e\\+300 needs more "
                                       "segments than can be counted"):
        ops("move PZ 0 [10**300] [10**300] 0", 1000)


@pytest.mark.parametrize(("text", "line"), [
    ("G103 PZ 0 1\nmove PZ 0 360 [10**300]", 2),  # lengths whose squares overflow
    ("G103 PZ 0 1\nF1\nG1 PZ 0 [10**300] 1", 3),
    ("F1\nG1 X[10**300] Y[10**300]", 2),
    ("G91\nmove X[10**308]\nmove X[10**308]", 2),  # a length past the largest number
    ("G20\nmove X[10**307]", 2),  # in mm
])
def test_a_move_too_large_for_numbers_is_an_error(text: str, line: int) -> None:
    # they gave segments of duration inf, or of NaN positions and durations
    with pytest.raises(NgcError, match="The move is too large to run") as info:
        ops(text, 1000)
    assert info.value.line == line


def test_a_move_at_the_slowest_speed_a_sheet_allows_is_finite() -> None:
    setup = Setup(max_speed=(1e-6,) * 9)
    last = list(run("move X1000000000 Y-1000000000 A1000000000", Engine(setup=setup, max_iterations=10)))[-1]
    assert isinstance(last, EngineSegment) and math.isfinite(last.duration)


def test_segments_are_made_as_they_are_taken() -> None:
    """A move of 4 million segments under the default budget: the first ones come at once and
    taking 20,000 of them holds one at a time."""
    tracemalloc.start()
    try:
        started = time.process_time()  # (CPU time: a busy machine does not make it slow)
        taken = sum(1 for _ in itertools.islice(run("move PZ 0 360000000 1 0"), 20_000))
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert taken == 20_000
    assert time.process_time() - started < 20.0
    assert peak < 2_000_000


@pytest.mark.parametrize("text", [
    "S" + "3" * 400 + " M3",  # a number past a float: SPINDLE_SPEED was inf
    "F1\nG1 X" + "9" * 400,
    "dwell [" + "9" * 400 + "]",
    "F[10**400]",
    "#1 = [10**400]",
])
def test_a_value_past_a_float_is_an_error(text: str) -> None:
    with pytest.raises(NgcError, match="Calculation resulted in 'infinity'") as info:
        ops(text, 1000)
    assert info.value.line == text.count("\n") + 1
