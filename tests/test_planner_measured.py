"""Small programs, each timed on LinuxCNC 2.9's planner with the measuring tool
(``../shared/timing/lcnc-timing``, the machine of ``../shared/timing/README.md``): ngc time takes
what LinuxCNC took, within two servo cycles or 0.1 %."""

from __future__ import annotations

import math

import pytest

from ngc.planner.timing import time_text

HEAD = "G17 G21 G90 G94 G40 G49 G80\n"


def curve(mode: str, feeds: tuple[float, float], every: int) -> str:
    """100 lines of 0.5 mm along a circle of radius 20, the feed switching every ``every``
    lines: the feed changes between blended moves of an adaptive clearing path."""
    lines = [HEAD + mode, "G0 Z1", "G1 Z0 F500"]
    for i in range(1, 101):
        t = 0.5 * i / 20.0
        feed = feeds[(i // every) % 2]
        lines.append(f"G1 X{20 * math.sin(t):.4f} Y{20 - 20 * math.cos(t):.4f} F{feed:g}")
    return "\n".join([*lines, "G0 Z5", ""])



def loops(mode: str, fa: int, fb: int) -> str:
    """Six adaptive loops: half circles of r 3 at ``fa`` and ``fb`` joined by 0.45 mm links."""
    lines = [HEAD + mode, "G0 X0 Y0 Z2", "G1 Z-3 F300"]
    x = 0.0
    for _ in range(6):
        lines += [f"G3 X{x + 6:g} Y0 I3 J0 F{fa}", f"G1 X{x + 6.4:g} Y0.2 F2600",
                  f"G3 X{x + 0.4:g} Y0.2 I-3 J0 F{fb}", f"G1 X{x + 0.8:g} Y0 F1500"]
        x += 0.8
    return "\n".join([*lines, "G0 Z5", ""])


# name, program, LinuxCNC's measured time (s)
CASES: list[tuple[str, str, float]] = [
    # F runs before G20 in the order of execution: 6 mm/min, kept after the switch (0.668 mm at
    # 0.1 mm/s); the last line's F600 is in mm again
    ("feed_on_unit_switch", HEAD + "G61.1\nG1 X10 F600\nG20 F6\nG1 X0.42\nG21\nG1 X30 F600\n",
     9.635),
    # no G61/G64 anywhere: LinuxCNC blends from the start, as G64 without P (the same
    # program after G64 took the same 4.772 s, after G61 5.158 s)
    ("no_blend_mode", HEAD + "G1 X50 F3000\nY50\nX0\nY0\nG1 X20 Y5\nX40 Y0\n", 4.772),
    # after a canned cycle the corner between two rapids (Z up, then XY) stops
    ("rapid_corner_after_cycle", HEAD + "S10000 M3\nG0 Z25\nG0 X21 Y40\n"
     "G99 G83 X21 Y40 Z-12 R2 Q4 F900\nG80\nG0 Z25\nG0 X0 Y0\nM5\n", 4.865),
    # a corner blend from a fast feed into a slow one runs at the fast one and slows down along
    # the blend; what it has not shed the slow move sheds at its own acceleration
    ("feed_changes_g64_p", curve("G64 P0.01", (1000, 2500), 3), 2.411),
    ("feed_changes_every_line_g64_p", curve("G64 P0.01", (1000, 2500), 1), 1.756),
    ("feed_changes_g64", curve("G64", (1000, 2500), 3), 2.784),
    # under G64 P a corner blend beside an arc that curves into the corner is sized as for a turn
    # sharper by a sixth of the arc's sweep (6.22 mm/s at the corners of the arcs that curve into
    # them, 9.93 at the others)
    ("arc_into_corner_g64_p", loops("G64 P0.02", 1100, 2800), 6.767),
    ("arc_into_corner_g64_p_feeds", loops("G64 P0.02", 600, 4000), 9.190),
    ("line_into_quarter_circle_g64_p", HEAD + "G64 P0.02\nG0 X12.9289 Y27.0711\n"
     "G1 X20 Y20 F3000\nG3 X25 Y25 I0 J5\n", 0.884),
    # under G64 without P the blend beside an arc that curves into the corner reaches at most a
    # twelfth of the arc's length from it (0.45 mm links: a quarter of a link)
    ("arc_into_corner_g64", loops("G64", 1100, 2800), 6.485),
    ("line_into_quarter_circle_g64", HEAD + "G64\nG0 X15.5271 Y28.9439\n"
     "G1 X20 Y20 F3000\nG3 X25 Y25 I0 J5\n", 0.863),
    # a cove: XZ half circles joined by 1 mm steps along Y; under G64 P the step across the
    # arcs' plane still keeps a parabolic blend, as without P
    ("cove_g18_g64_p", HEAD + "G64 P0.02\nG0 X0 Y0 Z5\nG1 Z0 F1500\nG18\n"
     + "".join(f"G1 Y{2 * k}\nG2 X20 Z0 I10 K0\nG1 Y{2 * k + 1}\nG3 X0 Z0 I-10 K0\n"
               for k in range(4)) + "G17\nG0 Z10\n", 12.683),
]


@pytest.mark.parametrize(("name", "program", "measured"), CASES, ids=[c[0] for c in CASES])
def test_measured(name: str, program: str, measured: float) -> None:
    assert time_text(program + "M2\n").total_s == pytest.approx(measured, abs=0.0021, rel=0.001)
