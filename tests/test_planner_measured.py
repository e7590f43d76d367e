"""Small programs, each timed on LinuxCNC 2.9's planner with the measuring tool
(``../shared/timing/lcnc-timing``, the machine of ``../shared/timing/README.md``): ngc time takes
what LinuxCNC took, within a servo cycle or two."""

from __future__ import annotations

import pytest

from ngc.planner.timing import time_text

HEAD = "G17 G21 G90 G94 G40 G49 G80\n"

# name, program, LinuxCNC's measured time (s)
CASES: list[tuple[str, str, float]] = [
    # F runs before G20 in the order of execution: 6 mm/min, kept after the switch (0.668 mm at
    # 0.1 mm/s); the last line's F600 is in mm again
    ("feed_on_unit_switch", HEAD + "G61.1\nG1 X10 F600\nG20 F6\nG1 X0.42\nG21\nG1 X30 F600\n",
     9.635),
]


@pytest.mark.parametrize(("name", "program", "measured"), CASES, ids=[c[0] for c in CASES])
def test_measured(name: str, program: str, measured: float) -> None:
    assert time_text(program + "M2\n").total_s == pytest.approx(measured, abs=0.0021)
