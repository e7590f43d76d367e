#!/usr/bin/env python3
"""Inch programs that move work offsets about, written as a setup person or a CAM post does.

A program is a sequence of *setups*, each drawn from a weighted table and each followed by a few
cuts: touch-off style ``G10 L20`` after a move, fixture tables written with ``G10 L2 P1..P9``
(sometimes P0, sometimes with a rotation ``R``), ``G52`` local shifts and their cancel,
``G92`` / ``G92.1`` / ``G92.2`` / ``G92.3``, a change of system among G54-G59.3, a switch to
G21 and back.  Cuts are traverses and feeds to absolute points, arcs in G91 (whose end and
centre are relative, so they are valid wherever the tool is: I J K or R form, in XY, XZ or YZ)
and full circles.  Values carry four or five decimals as CAM output for inch machines does, many
of them exact ties at the fourth decimal (``-0.27835``); now and then the position and offset
parameters (#5221.., #5420..) are printed with DEBUG.  Headers and line numbers vary
(Fusion-like ``N10 G20 G17 G90``, bare hand-written lines, lower case, spaces inside words).
About one program in twelve has a mistake (P out of range, G10 without L, L20 without P,
an axis the machine lacks, an arc whose radius is too small, G92.3 with nothing saved).

    python tests/fuzz/indep_offsets.py SEED
    python tests/fuzz/indep_offsets.py --batch --seed 1 --count 500 [--jobs 2] [--shrink]
"""

from __future__ import annotations

import math
import random
import sys
from collections.abc import Callable
from pathlib import Path

HERE = Path(__file__).resolve().parent
if str(HERE) not in sys.path:
    sys.path.insert(0, str(HERE))

import indep_flow  # noqa: E402

WRONG_SHARE = 0.08
SYSTEMS = ["G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3"]


class Offsets:
    def __init__(self, seed: int) -> None:
        self.rng = random.Random(f"indep-offsets-{seed}")
        r = self.rng
        self.case = r.choice(["upper", "upper", "lower", "mixed"])
        self.spaces = r.choice([0.0, 0.0, 0.0, 0.2])
        self.numbered = r.random() < 0.5
        self.n = r.choice([1, 5, 10, 100])
        self.step = r.choice([1, 5, 10])
        self.lines: list[str] = []
        self.inch = True
        self.wrong = r.random() < WRONG_SHARE
        self.turns = 0
        # how far from the origin the work sits, and how many values are ties at the 4th decimal
        self.reach = r.choice([1.0, 1.0, 1.0, 8.0, 40.0])
        self.ties = r.choice([0.2, 0.45, 0.45, 0.9])

    # -- writing --
    def emit(self, *words: str) -> None:
        text = " ".join(w for w in words if w)
        if self.numbered:
            text = f"N{self.n} {text}"
            self.n += self.step
        self.lines.append(text)

    def w(self, letter: str, value: str) -> str:
        r = self.rng
        if self.case == "lower" or (self.case == "mixed" and r.random() < 0.5):
            letter = letter.lower()
        sep = " " if r.random() < self.spaces else ""
        return f"{letter}{sep}{value}"

    def g(self, code: str) -> str:
        return self.w("G", code[1:])

    # -- numbers --
    def val(self, span: float, ties: float | None = None) -> str:
        """A CAM-style number: 4 or 5 decimals, often an exact tie at the fourth."""
        r = self.rng
        ties = self.ties if ties is None else ties
        places = 5 if r.random() < 0.6 else 4
        if self.inch is False:
            places = r.choice([3, 4])
        v = r.uniform(-span, span) * (self.reach if span > 1.5 else 1.0)
        if places == 5 and r.random() < ties:
            v = (math.floor(v * 10000) + 0.5) / 10000
        text = f"{v:.{places}f}"
        if r.random() < 0.2:
            text = text.rstrip("0").rstrip(".")
        if r.random() < 0.1 and text.startswith("0."):
            text = text[1:]
        elif r.random() < 0.1 and text.startswith("-0."):
            text = "-" + text[2:]
        if text in ("", "-", "-0", "-."):
            text = "0"
        return text

    def axes(self, span: float, letters: str = "XYZ", min_n: int = 1) -> list[str]:
        r = self.rng
        picked = r.sample(list(letters), r.randint(min_n, len(letters)))
        return [self.w(a, self.val(span)) for a in sorted(picked, key=letters.index)]

    # -- setups --
    def setup(self) -> None:
        r = self.rng
        table: list[tuple[float, Callable[[], None]]] = [
            (4, self.g10_l2), (3, self.g10_l20), (2.5, self.g52), (3, self.g92),
            (2.5, self.select), (1.2, self.units), (1.2, self.show), (0.6, self.rotated_pattern),
            (0.8, self.incremental),
        ]
        total = sum(wt for wt, _ in table)
        x = r.uniform(0, total)
        for wt, fn in table:
            x -= wt
            if x <= 0:
                fn()
                return

    def g10_l2(self) -> None:
        r = self.rng
        p = r.choice(["0", "1", "1", "2", "3", "4", "5", "6", "7", "8", "9", "1."])
        words = self.axes(6.0, "XYZ", 0)
        if r.random() < 0.35:
            words.append(self.w("R", r.choice([self.val(90, 0.2), "0", "90", "30", "45.",
                                                "-15.5", "12.34567", "180"])))
        if r.random() < 0.05:
            words.append(self.w("A", self.val(30)))
        if not words:
            words = [self.w("X", self.val(3))]
        self.emit(self.g("G10"), self.w("L", "2"), self.w("P", p), *words)

    def g10_l20(self) -> None:
        r = self.rng
        p = r.choice(["0", "1", "2", "3", "6", "9"])
        if r.random() < 0.6:
            self.emit(self.g("G0"), *self.axes(4.0, "XYZ"))
        words = self.axes(2.0, "XYZ")
        if r.random() < 0.03:
            words.append(self.w("R", self.val(60, 0.2)))
        self.emit(self.g("G10"), self.w("L", "20"), self.w("P", p), *words)

    def g52(self) -> None:
        r = self.rng
        if r.random() < 0.3:
            self.emit(self.g("G52"), self.w("X", "0"), self.w("Y", "0"), self.w("Z", "0"))
        else:
            self.emit(self.g("G52"), *self.axes(3.0, "XYZ"))

    def g92(self) -> None:
        r = self.rng
        kind = r.choice(["G92", "G92", "G92", "G92.1", "G92.2", "G92.3"])
        if kind == "G92":
            if r.random() < 0.5:
                self.emit(self.g("G1"), *self.axes(3.0, "XY"))
            self.emit(self.g("G92"), *self.axes(2.5, "XYZ"))
        else:
            self.emit(self.g(kind))

    def incremental(self) -> None:
        """A stretch in G91: moves relative, an offset set in between (G91 leaves G10 alone)."""
        r = self.rng
        self.emit(self.g("G91"))
        self.emit(self.g(r.choice(["G0", "G1"])), *self.axes(1.0, "XYZ"))
        r.choice([self.g10_l2, self.g10_l20, self.g52, self.g92])()
        self.emit(self.g("G1"), *self.axes(1.0, "XYZ"))
        self.emit(self.g("G90"))

    def select(self) -> None:
        self.emit(self.g(self.rng.choice(SYSTEMS)))

    def units(self) -> None:
        """A stretch in millimetres, then back to inches."""
        r = self.rng
        self.emit(self.g("G21"))
        self.inch = False
        self.cut(r.randint(1, 3), scale=25.4)
        if r.random() < 0.6:
            # offsets set in millimetres, then shown and used in inches
            r.choice([self.g10_l2, self.g10_l20, self.g52, self.g92])()
            self.cut(1, scale=25.4)
        self.inch = True
        self.emit(self.g("G20"))
        if r.random() < 0.4:
            self.show()

    def show(self) -> None:
        r = self.rng
        groups = [["#5220", "#5221", "#5222", "#5223"], ["#5241", "#5242", "#5229"],
                  ["#5211", "#5212", "#5213", "#5210"], ["#5420", "#5421", "#5422"],
                  ["#5261", "#5262", "#5281", "#5282"], ["#<_x>", "#<_y>", "#<_z>"]]
        params = r.choice(groups)
        self.lines.append(f"(DEBUG, {' '.join(params)})")

    def rotated_pattern(self) -> None:
        """A part cut four times, each time with the system turned a further step."""
        r = self.rng
        p = r.choice(["1", "2", "0"])
        step = r.choice(["90", "45", "30", "22.5", "72"])
        base_x, base_y = self.val(4), self.val(4)
        self.turns += 1
        lab = f"o<turn{self.turns}>"
        self.lines.append("#<rot> = 0")
        self.lines.append(f"{lab} repeat [{r.randint(2, 4)}]")
        self.lines.append(f"G10 L2 P{p} X{base_x} Y{base_y} R#<rot>")
        self.cut(r.randint(1, 2))
        self.lines.append(f"#<rot> = [#<rot> + {step}]")
        self.lines.append(f"{lab} endrepeat")

    # -- cuts --
    def cut(self, count: int, scale: float = 1.0) -> None:
        r = self.rng
        for _ in range(count):
            roll = r.random()
            if roll < 0.35:
                self.emit(self.g(r.choice(["G0", "G1"])), *self.axes(3.0 * scale, "XYZ"))
            elif roll < 0.5:
                self.emit(self.g("G1"), *self.axes(3.0 * scale, "XY"),
                          self.w("F", r.choice(["10.", "25", "12.5", "40.0", "7.87402"])))
            elif roll < 0.6:
                self.arc(scale)
            elif roll < 0.78:
                self.absolute_arc(scale)
            elif roll < 0.82:
                self.emit(self.g("G91"), self.g(r.choice(["G0", "G1"])), *self.axes(1.0 * scale, "XYZ"))
                self.emit(self.g("G90"))
            elif roll < 0.85:
                self.emit(self.g("G53"), self.g(r.choice(["G0", "G1"])), *self.axes(2.0 * scale, "XYZ"))
            else:
                self.emit(self.g(r.choice(["G2", "G3"])), self.w("I", self.val(1.2 * scale)),
                          self.w("J", self.val(1.2 * scale)))

    def arc(self, scale: float) -> None:
        r = self.rng
        plane = r.choice(["G17", "G17", "G17", "G18", "G19"])
        a, b, c = {"G17": ("XY", "IJ", "Z"), "G18": ("ZX", "KI", "Y"),
                   "G19": ("YZ", "JK", "X")}[plane]
        rad = r.uniform(0.2, 1.5) * scale
        t0, t1 = r.uniform(0, 2 * math.pi), r.uniform(0, 2 * math.pi)
        ci, cj = -rad * math.cos(t0), -rad * math.sin(t0)
        dx, dy = ci + rad * math.cos(t1), cj + rad * math.sin(t1)
        places = 4 if r.random() < 0.5 else 5
        f = f"{{:.{places}f}}"
        words = [self.w(a[0], f.format(dx)), self.w(a[1], f.format(dy))]
        if r.random() < 0.2:
            words.append(self.w(c, self.val(0.5 * scale)))
        if r.random() < 0.3:
            chord = math.hypot(dx, dy)
            sign = "-" if r.random() < 0.3 else ""
            words.append(self.w("R", sign + f.format(max(rad, chord / 2 + 1e-4))))
        else:
            words += [self.w(b[0], f.format(ci)), self.w(b[1], f.format(cj))]
        self.emit(self.g(plane), self.g("G91"), self.g(r.choice(["G2", "G3"])), *words)
        self.emit(self.g("G90"), self.g("G17") if plane != "G17" else "")

    def absolute_arc(self, scale: float) -> None:
        """As CAM writes it: a move to the arc's start, then the arc to an absolute end."""
        r = self.rng
        places = 4 if r.random() < 0.4 else 5
        q = 10 ** places
        rad = round(r.uniform(0.1, 1.5) * scale * q) / q
        cx, cy = r.uniform(-2, 2) * scale, r.uniform(-2, 2) * scale
        t0, t1 = r.uniform(0, 2 * math.pi), r.uniform(0, 2 * math.pi)
        f = f"{{:.{places}f}}"
        sx, sy = f.format(cx + rad * math.cos(t0)), f.format(cy + rad * math.sin(t0))
        ex, ey = f.format(cx + rad * math.cos(t1)), f.format(cy + rad * math.sin(t1))
        self.emit(self.g(r.choice(["G0", "G1"])), self.w("X", sx), self.w("Y", sy))
        i, j = f.format(cx - float(sx)), f.format(cy - float(sy))
        words = [self.w("X", ex), self.w("Y", ey)]
        if r.random() < 0.25:
            words.append(self.w("R", f.format(rad)))
        else:
            words += [self.w("I", i), self.w("J", j)]
        if r.random() < 0.2:
            words.append(self.w("Z", self.val(0.3 * scale)))
        self.emit(self.g(r.choice(["G2", "G3"])), *words)

    # -- mistakes --
    def mistake(self) -> None:
        r = self.rng
        choice = r.choice([
            "G10 L2 P10 X1", "G10 L2 P-1 X1", "G10 P1 X1.2", "G10 L20 X0.5", "G10 L2 P1.5 X1",
            "G10 L2 P1 U0.5", "G92", "G52 R0.5", "G10 L20 P2 X1 G92 Y1",
            "G91 G2 X2.00005 Y0 R0.5", "G92.3 X1", "G59.4", "G10 L2 P3 X1 Y2 Z3 A4 B5 C6 Q1",
        ])
        self.emit(*choice.split())

    # -- the program --
    def program(self) -> str:
        r = self.rng
        head = r.random()
        if head < 0.3:
            self.lines += ["%", "(1001)", "(T1  D=0.25 CR=0. - ZMIN=-0.1 - FLAT END MILL)"]
            self.emit("G90", "G94", "G17")
            self.emit("G20")
            self.emit("G53", "G0", "Z0.")
        elif head < 0.6:
            self.emit(self.g("G20"), self.g("G17"), self.g("G40"), self.g("G49"),
                      self.g("G80"), self.g("G90"))
        else:
            self.lines.append(r.choice(["G20", "g20 (inch)", "G20 G90"]))
        if r.random() < 0.5:
            self.emit(self.g(r.choice(SYSTEMS)))
        self.emit(self.w("F", r.choice(["20.", "15", "31.5", "8.66142"])))
        for _ in range(r.randint(2, 7)):
            self.setup()
            self.cut(r.randint(1, 4))
        if self.wrong:
            self.mistake()
            self.cut(1)
        if r.random() < 0.4:
            self.emit(self.g("G92.1"))
            self.emit(self.g("G54"))
        self.emit(self.w("M", r.choice(["30", "2"])))
        if self.lines[0] == "%":
            self.lines.append("%")
        return "\n".join(line for line in self.lines if line) + "\n"


def generate(seed: int) -> str:
    return Offsets(seed).program()


indep_flow.GENERATORS["indep-offsets"] = generate

if __name__ == "__main__":
    sys.exit(indep_flow.main(kind="indep-offsets"))
