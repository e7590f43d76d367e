"""Benchmark programs that ``../shared/bench/benchgen.py`` does not make (deterministic).

Usage: programs.py ccomp LINES OUT.ngc [--seed N]

kinds:
  ccomp  compensated outside profiles, as a CAM post writes them for a profile with cutter radius
         compensation in the control: a lead-in, ``G41.1 D``, a clockwise rounded rectangle
         with one chamfered corner (lines, tangent arcs and convex corners the interpreter
         rounds with arcs of its own), ``G40`` and a lead-out
"""

from __future__ import annotations

import argparse
import random
from typing import TextIO


def ccomp(n: int, rng: random.Random, out: TextIO) -> None:
    out.write("(compensated contour benchmark)\nG21 G90 G17 G94 G54 G64 P0.02\nS9000 M3\n"
              "G0 X0 Y0 Z5\n")
    count = k = 0
    while count < n:
        cx, cy = rng.uniform(0, 200), rng.uniform(0, 200)
        w, h = rng.uniform(10, 40), rng.uniform(10, 40)
        rc = rng.uniform(1, 4)  # corner radius
        d = rng.choice((3.0, 4.0, 6.0, 6.35))  # tool diameter
        x0, y0, x1, y1 = cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2
        c = min(w, h) / 5  # the chamfer
        out.write(f"(profile {k})\nG0 X{x0 - 10:.4f} Y{y0 - 10:.4f}\nG1 Z-2 F300\n")
        out.write(f"G41.1 D{d:.4f}\n")
        out.write(f"G1 X{x0:.4f} Y{y0 + rc:.4f} F1200\n")  # lead-in onto the left edge
        out.write(f"G1 X{x0:.4f} Y{y1 - rc:.4f}\n")
        out.write(f"G2 X{x0 + rc:.4f} Y{y1:.4f} I{rc:.4f} J0\n")
        out.write(f"G1 X{x1 - c:.4f} Y{y1:.4f}\n")
        out.write(f"G1 X{x1:.4f} Y{y1 - c:.4f}\n")
        out.write(f"G1 X{x1:.4f} Y{y0 + rc:.4f}\n")
        out.write(f"G2 X{x1 - rc:.4f} Y{y0:.4f} I{-rc:.4f} J0\n")
        out.write(f"G1 X{x0 + rc:.4f} Y{y0:.4f}\n")
        out.write(f"G2 X{x0:.4f} Y{y0 + rc:.4f} I0 J{rc:.4f}\n")
        out.write(f"G40\nG1 X{x0 - 10:.4f} Y{y0 + rc:.4f}\nG0 Z5\n")
        count += 16
        k += 1
    out.write("M5\nM2\n")


KINDS = {"ccomp": ccomp}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("kind", choices=sorted(KINDS))
    ap.add_argument("lines", type=int)
    ap.add_argument("out")
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    with open(a.out, "w") as f:
        KINDS[a.kind](a.lines, random.Random(a.seed), f)


if __name__ == "__main__":
    main()
