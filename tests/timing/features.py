"""Generator of the programs in ``features/``: each one a behaviour of LinuxCNC's planner that
shop programs lean on, made large enough to weigh in a cycle time.

* feeds set on a line that switches units (``G20 F6``: the feed is read before the switch);
* programs that set neither G61 nor G64 (LinuxCNC blends from the start);
* adaptive clearing: short blended moves, the feed changing between them, under G64 and G64 P;
* thread milling: multi-turn helices (``P``) of several radii and pitches, with lead-in and
  lead-out arcs, and helical ramps shorter than a turn;
* coves: half circles in the XZ and YZ planes joined by steps across the plane;
* NURBS: G5 cubic splines and G5.2 curves, under G64 and G64 P.

Each program starts with ``G17 G21 G90 G94 G40 G49 G80`` (G20 for inch) and ``S10000 M3``, starts
at machine 0,0,0 and ends with ``M5 M2``; the first line says what it is.  The geometry comes from
closed forms and a fixed ``random.Random`` seed, so the output is the same everywhere.

``python tests/timing/features.py`` (re)writes ``tests/timing/features/NN_kind.ngc``; ``--check``
compares the files with what it makes.  ``python tests/timing/measure.py tests/timing/features``
measures them.
"""

from __future__ import annotations

import math
import random
import sys
from collections.abc import Callable
from pathlib import Path

FEATURES_DIR = Path(__file__).resolve().parent / "features"


def n(v: float, nd: int = 4) -> str:
    """A number as a CAM post writes it: up to ``nd`` decimals, no trailing zeros."""
    s = f"{v:.{nd}f}"
    if "." in s:
        s = s.rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def head(title: str, mode: str | None, inch: bool = False) -> list[str]:
    lines = [f"({title.upper()})", f"G17 {'G20' if inch else 'G21'} G90 G94 G40 G49 G80",
             "S10000 M3"]
    return [*lines, mode] if mode else lines


def tail() -> list[str]:
    return ["M5 M2"]


# -- feeds on unit-switching lines ---------------------------------------------------------------


def unit_switch_mm() -> list[str]:
    out = head("feeds set on lines that switch units, in a mm program", "G64")
    out += ["G0 X5 Y5 Z2", "G1 Z-1 F300"]
    for k in range(3):
        y = 5 + 10 * k
        # F on the G20 line is read in mm (before the switch) and kept after it
        out += [f"G1 X40 Y{y} F1200", "G20 F120", f"G1 X{n((40 + 1.5) / 25.4)} Y{n(y / 25.4)}",
                f"G1 Y{n((y + 5) / 25.4)}", "G21", f"G1 X5 Y{y + 5} F1500",
                f"G1 Y{y + 10}"]
    out += ["G0 Z5", "X0 Y0"]
    return out + tail()


def unit_switch_inch() -> list[str]:
    out = head("feeds set on lines that switch units, in an inch program", "G64 P0.001", inch=True)
    out += ["G0 X0.2 Y0.2 Z0.1", "G1 Z-0.04 F12"]
    for k in range(3):
        y = 0.2 + 0.4 * k
        out += [f"G1 X1.6 Y{n(y)} F60", "G21 F20", f"G1 X{n(1.6 * 25.4 + 2)} Y{n(y * 25.4)}",
                f"G1 Y{n((y + 0.2) * 25.4)}", "G20", f"G1 X0.2 Y{n(y + 0.2)}",
                f"G1 Y{n(y + 0.4)} F40"]
    out += ["G0 Z0.2", "X0 Y0"]
    return out + tail()


# -- programs without G61/G64 ----------------------------------------------------------------------


def letters(rng: random.Random, x0: float, y0: float, step: float) -> list[tuple[float, float]]:
    """A wavy engraved stroke: ``step`` long segments along a sum of sines."""
    pts = []
    a, b, c = rng.uniform(1.0, 3.0), rng.uniform(0.5, 1.5), rng.uniform(0.0, math.pi)
    for i in range(int(30 / step) + 1):
        x = i * step
        pts.append((x0 + x, y0 + a * math.sin(x / 3.0 + c) + b * math.sin(x * 1.3)))
    return pts


def engrave_no_mode(step: float, feed: float, title: str) -> Callable[[], list[str]]:
    def make() -> list[str]:
        rng = random.Random(int(step * 1000) + int(feed))
        out = head(title, None)
        for k in range(4):
            pts = letters(rng, 5.0, 5.0 + 8.0 * k, step)
            out += [f"G0 X{n(pts[0][0], 3)} Y{n(pts[0][1], 3)} Z1", f"G1 Z-0.1 F{n(feed / 4, 0)}"]
            out += [f"G1 X{n(x, 3)} Y{n(y, 3)} F{n(feed, 0)}" if i == 1 else f"X{n(x, 3)} Y{n(y, 3)}"
                    for i, (x, y) in enumerate(pts) if i > 0]
            out.append("G0 Z1")
        out += ["G0 Z5", "X0 Y0"]
        return out + tail()
    return make


def contour_no_mode() -> list[str]:
    out = head("outside contour of lines and arcs with no g61 or g64", None)
    out += ["G0 X-5 Y-5 Z2", "G1 Z-2 F400"]
    for depth in (-2, -4):
        out += [f"G1 Z{depth} F400", "G1 X0 Y0 F1200", "X60", "G3 X70 Y10 I0 J10", "G1 Y30",
                "G2 X60 Y40 I-10 J0", "G1 X20", "X0 Y25", "Y0", "G1 X-5 Y-5"]
    out += ["G0 Z5", "X0 Y0"]
    return out + tail()


def drill_no_mode() -> list[str]:
    out = head("g81 and g83 holes between rapids, with no g61 or g64", None)
    out += ["G0 Z20", "X10 Y10", "G99 G81 X10 Y10 Z-3 R2 F600"]
    out += [f"X{10 + 15 * i} Y{10 + 12 * j}" for j in range(2) for i in range(3) if i or j]
    out += ["G80", "G0 Z20", "X15 Y30", "G98 G83 X15 Y30 Z-10 R2 Q3 F700", "X40 Y30", "G80",
            "G0 Z20", "X0 Y0"]
    return out + tail()


# -- adaptive clearing ---------------------------------------------------------------------------


def adaptive(mode: str, title: str, seed: int) -> Callable[[], list[str]]:
    """Trochoidal loops along a slot as short lines, the feed slowing in the engagement and
    speeding up on the way back, as adaptive-clearing posts write it."""
    def make() -> list[str]:
        rng = random.Random(seed)
        out = head(title, mode)
        r, step, seg = 3.0, 0.6, 0.35
        out += ["G0 X0 Y0 Z2", "G1 Z-3 F300"]
        x = 0.0
        last_f = 0
        for _ in range(14):
            k = int(2 * math.pi * r / seg)
            for i in range(1, k + 1):
                t = 2 * math.pi * i / k
                px, py = x + step * i / k + r * math.sin(t), r - r * math.cos(t)
                engaged = t < math.pi
                f = (1200 if engaged else 3000) + 100 * round(rng.uniform(-2, 2))
                if 0.9 * math.pi < t < 1.1 * math.pi:
                    f = 2000
                words = f"G1 X{n(px, 3)} Y{n(py, 3)}"
                out.append(words + (f" F{f}" if f != last_f else ""))
                last_f = f
            x += step
        out += ["G0 Z5", "X0 Y0"]
        return out + tail()
    return make


def adaptive_arcs(mode: str, title: str) -> Callable[[], list[str]]:
    """Adaptive loops written as arcs and short links, a feed on every move."""
    def make() -> list[str]:
        out = head(title, mode)
        out += ["G0 X0 Y0 Z2", "G1 Z-3 F300"]
        x = 0.0
        for _ in range(20):
            out += [f"G3 X{n(x + 6)} Y0 I3 J0 F1100", f"G1 X{n(x + 6.4)} Y0.2 F2600",
                    f"G3 X{n(x + 0.4)} Y0.2 I-3 J0 F2800", f"G1 X{n(x + 0.8)} Y0 F1500"]
            x += 0.8
        out += ["G0 Z5", "X0 Y0"]
        return out + tail()
    return make


# -- thread milling, helices, coves ------------------------------------------------------------


def thread_mill(mode: str, holes: list[tuple[float, float, float, float]],
                title: str) -> Callable[[], list[str]]:
    """Threads milled bottom-up: plunge at the hole's centre, a half-circle lead-in, a P-turn
    helix up, a quarter-circle lead-out.  ``holes``: (radius, pitch, turns, feed)."""
    def make() -> list[str]:
        out = head(title, mode)
        for i, (r, pitch, turns, f) in enumerate(holes):
            cx, cy = 20.0 * i, 0.0
            depth = pitch * turns
            out += [f"G0 X{n(cx)} Y{n(cy)} Z2", f"G1 Z{n(-depth)} F{n(f / 2, 0)}",
                    f"G3 X{n(cx + r)} Y{n(cy)} I{n(r / 2)} J0 F{n(f, 0)}",
                    f"G3 X{n(cx + r)} Y{n(cy)} Z0 I{n(-r)} J0 P{turns}",
                    f"G3 X{n(cx + r / 2)} Y{n(cy + r / 2)} I{n(-r / 2)} J0",
                    f"G1 X{n(cx)} Y{n(cy)}", "G0 Z2"]
        out += ["G0 Z10", "X0 Y0"]
        return out + tail()
    return make


def helical_ramps() -> list[str]:
    out = head("helical ramps of an eighth to three quarters of a turn, into straight cuts",
               "G64")
    for i, (frac, dz, r) in enumerate([(0.125, 0.4, 5), (0.25, 0.8, 4), (0.375, 1.0, 6),
                                       (0.5, 1.5, 3), (0.75, 2.0, 5)]):
        cx = 25.0 * i
        a = 2 * math.pi * frac
        ex, ey = cx + r * math.cos(a), r * math.sin(a)
        out += [f"G0 X{n(cx + r)} Y0 Z1", "G1 Z0 F600",
                f"G3 X{n(ex)} Y{n(ey)} Z{n(-dz)} I{-r} J0 F1000",
                f"G1 X{n(ex - 8 * math.sin(a))} Y{n(ey + 8 * math.cos(a))} F1400", "G0 Z2"]
    out += ["G0 Z10", "X0 Y0"]
    return out + tail()


def cove(plane: str, mode: str, title: str) -> Callable[[], list[str]]:
    """Half circles across the part in the XZ (G18) or YZ (G19) plane, one step apart."""
    def make() -> list[str]:
        out = head(title, mode)
        out += ["G0 X0 Y0 Z5", "G1 Z0 F1500", plane]
        for k in range(5):
            if plane == "G18":
                out += [f"G1 Y{1.5 * k:g}", "G2 X20 Z0 I10 K0", f"G1 Y{1.5 * k + 0.75:g}",
                        "G3 X0 Z0 I-10 K0"]
            else:
                out += [f"G1 X{1.5 * k:g}", "G3 Y20 Z0 J10 K0", f"G1 X{1.5 * k + 0.75:g}",
                        "G2 Y0 Z0 J-10 K0"]
        out += ["G17", "G0 Z10", "X0 Y0"]
        return out + tail()
    return make


# -- NURBS ------------------------------------------------------------------------------------------


def nurbs(mode: str, title: str) -> Callable[[], list[str]]:
    def make() -> list[str]:
        out = head(title, mode)
        out += ["G0 X0 Y0 Z2", "G1 Z-1 F400", "G1 X5 F1800"]
        for k in range(6):
            y = 6.0 * k
            out += [f"G5 I8 J{n(3 + k)} P8 Q{n(-3 - k)} X25 Y{n(y + 3)}",
                    f"G5 P6 Q{n(3 + k / 2)} X45 Y{n(y + 6)}",
                    f"G1 X{45 + (k % 2)} Y{n(y + 6)}",
                    f"G5 I-6 J{n(1 + k / 3)} P-6 Q{n(-2)} X5 Y{n(y + 6)}"]
        out += ["G0 Z5", "X0 Y0"]
        return out + tail()
    return make


def nurbs_g52(mode: str, title: str) -> Callable[[], list[str]]:
    def make() -> list[str]:
        out = head(title, mode)
        out += ["G0 X0 Y0 Z2", "G1 Z-1 F400", "F2000"]
        for k in range(5):
            y = 10.0 * k
            out += ["G5.2 P1 L3", f"X10 Y{n(y + 4)} P1", f"X20 Y{n(y + 4)} P1",
                    f"X30 Y{n(y)} P1", f"X40 Y{n(y)} P1", "G5.3", f"G1 X40 Y{n(y + 5)}",
                    f"G1 X0 Y{n(y + 10)}"]
        out += ["G0 Z5", "X0 Y0"]
        return out + tail()
    return make


# name: (what it exercises, how it is made)
FEATURES: list[tuple[str, str, Callable[[], list[str]]]] = [
    ("unit_switch_mm", "feeds set on G20/G21 lines in a mm program; G64", unit_switch_mm),
    ("unit_switch_inch", "feeds set on G21/G20 lines in an inch program; G64 P", unit_switch_inch),
    ("engrave_no_mode", "engraving, 0.1 mm segments at F3000, no G61/G64",
     engrave_no_mode(0.1, 3000, "engraving in 0.1 mm segments with no g61 or g64")),
    ("engrave_no_mode_b", "engraving, 0.5 mm segments at F1500, no G61/G64",
     engrave_no_mode(0.5, 1500, "engraving in 0.5 mm segments with no g61 or g64")),
    ("contour_no_mode", "outside contour of lines and arcs, no G61/G64", contour_no_mode),
    ("drill_no_mode", "G81 and G83 between rapids, no G61/G64", drill_no_mode),
    ("adaptive_g64p", "adaptive loops of 0.35 mm lines, feed changing, G64 P0.01",
     adaptive("G64 P0.01", "adaptive clearing loops with feed changes under g64 p0.01", 1)),
    ("adaptive_g64", "adaptive loops of 0.35 mm lines, feed changing, G64",
     adaptive("G64", "adaptive clearing loops with feed changes under g64", 2)),
    ("adaptive_g64p_coarse", "adaptive loops, feed changing, G64 P0.05",
     adaptive("G64 P0.05", "adaptive clearing loops with feed changes under g64 p0.05", 3)),
    ("adaptive_arcs", "adaptive loops of arcs and links, a feed on every move; G64 P0.02",
     adaptive_arcs("G64 P0.02", "adaptive loops of arcs and links with a feed on every move")),
    ("thread_mill_r3", "thread milling: r 3 helix P7 climbing 14 mm and others; G64",
     thread_mill("G64", [(3, 2, 7, 1200), (4, 1.5, 5, 900), (6, 1, 4, 1500)],
                 "thread milling with p-turn helices under g64")),
    ("thread_mill_p", "thread milling: helices of r 2 to 8, pitch 0.75 to 2.5; G64 P0.01",
     thread_mill("G64 P0.01", [(2, 0.75, 6, 700), (5, 1.25, 4, 1400), (8, 2.5, 3, 2500)],
                 "thread milling with p-turn helices under g64 p0.01")),
    ("helical_ramps", "helical ramps of 1/8 to 3/4 of a turn into lines; G64", helical_ramps),
    ("cove_g18", "coves: XZ half circles and steps along Y; G64 P0.02",
     cove("G18", "G64 P0.02", "coves of xz half circles under g64 p0.02")),
    ("cove_g19", "coves: YZ half circles and steps along X; G64",
     cove("G19", "G64", "coves of yz half circles under g64")),
    ("nurbs_g5", "G5 cubic splines between lines; G64", nurbs("G64", "g5 cubic splines under g64")),
    ("nurbs_g5_p", "G5 cubic splines between lines; G64 P0.01",
     nurbs("G64 P0.01", "g5 cubic splines under g64 p0.01")),
    ("nurbs_g52", "G5.2 NURBS curves between lines; G64",
     nurbs_g52("G64", "g5.2 nurbs curves under g64")),
]


def files() -> dict[str, tuple[str, Callable[[], list[str]]]]:
    return {f"{i:02d}_{name}.ngc": (what, make)
            for i, (name, what, make) in enumerate(FEATURES, start=1)}


def generate() -> dict[str, str]:
    return {name: "\n".join(make()) + "\n" for name, (_, make) in files().items()}


def main(argv: list[str] | None = None) -> int:
    from generate import write_programs  # the sibling generator's command line

    return write_programs(__doc__.split("\n")[0], FEATURES_DIR, generate, argv)

if __name__ == "__main__":
    sys.exit(main())
