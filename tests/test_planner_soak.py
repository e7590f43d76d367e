"""``ngc time`` on the differential fuzzer's random programs (``tests/fuzz/gen.py``): whatever a
program does, the planner gives a finite time whose parts add up, and a trajectory that moves
continuously, no faster than the machine allows.

A program the interpreter refuses is skipped (its error is the interpreter's business, tested
elsewhere).  More programs than the suite runs:

    python tests/test_planner_soak.py --count 500 --seed 1000
"""

from __future__ import annotations

import argparse
import csv
import io
import math
import sys
from pathlib import Path

import pytest

from ngc.errors import NgcError
from ngc.planner.machine import DEFAULT_MACHINE
from ngc.planner.timing import time_lines
from ngc.planner.trajectory import TrajectoryWriter

sys.path.insert(0, str(Path(__file__).parent / "fuzz"))

import gen

KINDS = ("motion", "offsets", "oword", "mixed", "comp", "cycles", "threading", "splines",
         "state", "lathe")
SEEDS = range(1, 9)
PERIOD = DEFAULT_MACHINE.servo_period
EVERY = 0.01  # s between samples of the trajectory
# the fastest any point may move: every axis at its own limit at once (the CSV has 6 decimals)
TOP_SPEED = math.sqrt(sum(lim.max_velocity ** 2 for name, lim in DEFAULT_MACHINE.axes.items()
                          if name in "XYZ"))


def check(text: str) -> str | None:
    """What is wrong with ``ngc time`` on ``text`` (None: nothing, or the program is refused)."""
    out = io.StringIO()
    writer = TrajectoryWriter(out, DEFAULT_MACHINE, EVERY)
    try:
        result = time_lines(text.splitlines(keepends=True), DEFAULT_MACHINE,
                            on_segment=writer.segment, on_wait=writer.wait)
    except NgcError:
        return None
    writer.finish(result.total_s)
    total = result.total_s
    if not (math.isfinite(total) and total >= 0.0):
        return f"total {total}"
    parts = sum(result.by_kind.values())
    slack = (result.segments + 1) * PERIOD + 1e-6
    if not total - slack <= parts <= total + 1e-6:
        return f"the kinds add up to {parts}, the total is {total}"
    for name, table in (("line", result.by_line), ("tool", result.by_tool)):
        if sum(table.values()) - parts > 1e-6 or min(table.values(), default=0.0) < -1e-9:
            return f"by {name} does not add up: {sum(table.values())} against {parts}"
    out.seek(0)
    rows = list(csv.DictReader(out))
    before = None
    for row in rows:
        t, p = float(row["t"]), (float(row["x"]), float(row["y"]), float(row["z"]))
        if not all(math.isfinite(c) for c in p):
            return f"t {t}: position {p}"
        if before is not None:
            dt = t - before[0]
            step = math.dist(p, before[1])
            if dt <= 0.0 or step > TOP_SPEED * dt + 2e-6:
                return f"t {t}: moved {step:.6f} in {dt:.6f} s (line {row['line']})"
        before = (t, p)
    if rows and abs(float(rows[-1]["t"]) - total) > EVERY + 1e-9:
        return f"the trajectory ends at {rows[-1]['t']}, the total is {total}"
    return None


@pytest.mark.parametrize("kind", KINDS)
def test_random_programs_time_and_move_continuously(kind: str) -> None:
    problems = {seed: check(gen.generate(kind, seed)) for seed in SEEDS}
    assert {seed: p for seed, p in problems.items() if p} == {}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description="ngc time on random programs")
    ap.add_argument("--kinds", default=",".join(KINDS))
    ap.add_argument("--count", type=int, default=100, help="programs per kind")
    ap.add_argument("--seed", type=int, default=1, help="first seed")
    args = ap.parse_args(argv)
    bad = 0
    for kind in args.kinds.split(","):
        for seed in range(args.seed, args.seed + args.count):
            problem = check(gen.generate(kind, seed))
            if problem:
                bad += 1
                print(f"{kind} {seed}: {problem}")
    print(f"{bad} of {args.count * len(args.kinds.split(','))} programs with a problem")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())


def test_an_xz_arc_under_an_xy_rotation_turns_with_the_plane() -> None:
    # (comp seed 153) the rotation turns the arc's normal (program Y) in the machine's XY plane
    text = ("G21 G90\nG10 L2 P0 R-87.79\nG54 G18\nG0 X12.3912 Y-4.692 Z12.1329\n"
            "G1 X13.0449 Z10.2789 F1200\nG3 Z6.6258 X1.2647 K26.1167 I-14.5555\nG1 X-8 Z6\n"
            "M2\n")
    assert check(text) is None
