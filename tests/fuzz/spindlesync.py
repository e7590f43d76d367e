"""The ``threading`` kind: spindle modes and spindle-synchronized motion in lathe- and mill-like
programs -- G96 (with and without D) / G97, S with $, M3/M4/M5, M19 R/P/Q, G33 passes along a
drive line (straight and tapered, G90/G91, G20/G21, G7/G8, all planes) and G33.1 rigid taps
(I, $) and G76 threading cycles (every word: degression, compound angle, spring passes, tapers at
either or both ends, X and Y end points, G91, values of four and five decimals that G7 halves into
ties), with now and then a mistake (K missing, F on the line, the spindle stopped, a G76 word
missing or out of range, a rotary word, $1, H-2)."""

from __future__ import annotations

import random


def _num(rng: random.Random, lo: float, hi: float, digits: int = 3) -> str:
    return f"{rng.uniform(lo, hi):.{digits}f}".rstrip("0").rstrip(".")


def _spindle(rng: random.Random) -> str:
    pick = rng.random()
    if pick < 0.3:
        d = f" D{rng.choice([500, 1500, 2500, 3000])}" if rng.random() < 0.6 else ""
        return f"G96{d} S{rng.choice([50, 120, 200, 250])} M{rng.choice([3, 4])}"
    if pick < 0.45:
        return f"G97 S{rng.choice([300, 800, 1200])} M{rng.choice([3, 4])}" + (
            " $0" if rng.random() < 0.3 else "")
    if pick < 0.55:
        r = f" R{_num(rng, 0, 360, 1)}" if rng.random() < 0.7 else ""
        p = f" P{rng.choice([0, 1, 2])}" if rng.random() < 0.4 else ""
        q = f" Q{_num(rng, 0.5, 3, 1)}" if rng.random() < 0.4 else ""
        return f"M19{r}{p}{q}"
    if pick < 0.6:
        return "M5"
    return f"S{rng.choice([100, 400, 1000])} M{rng.choice([3, 4])}" + (
        " $-1" if rng.random() < 0.1 else "")


def _lathe_pass(rng: random.Random, lines: list[str], mistake: bool) -> None:
    x = float(_num(rng, 5, 20, 2))
    z0 = float(_num(rng, 0.5, 2, 2))
    lines.append(f"G0 X{x} Z{z0}")
    depth = rng.choice([0.1, 0.2, 0.3])
    pitch = rng.choice([0.5, 1, 1.25, 1.5, 2])
    end = _num(rng, -30, -5, 2)
    for k in range(rng.randint(1, 4)):
        xc = round(x - depth * (k + 1), 4)
        lines.append(f"G0 X{xc}")
        taper = f" X{round(xc - rng.uniform(0, 1), 3)}" if rng.random() < 0.25 else ""
        kw = "" if mistake and k == 0 and rng.random() < 0.3 else f" K{pitch}"
        f = " F100" if mistake and rng.random() < 0.2 else ""
        lines.append(f"G33 Z{end}{taper}{kw}{f}" + (" $0" if rng.random() < 0.1 else ""))
        lines.append(f"G0 X{x + 1}")
        lines.append(f"Z{z0}")


def _tap(rng: random.Random, lines: list[str]) -> None:
    lines.append(f"G0 X{_num(rng, -20, 20)} Y{_num(rng, -20, 20)} Z{_num(rng, 1, 5)}")
    i = f" I{_num(rng, 0.5, 3, 1)}" if rng.random() < 0.4 else ""
    if rng.random() < 0.3:
        lines.append(f"G91 G33.1 Z-{_num(rng, 2, 10)} K{rng.choice([0.5, 0.7, 1.0])}{i}")
        lines.append("G90")
    else:
        lines.append(f"G33.1 Z-{_num(rng, 2, 10)} K{rng.choice([0.5, 0.7, 1.0])}{i}")


_G76_MISTAKES = ("P", "I", "J", "K", "I0", "J0", "K<J", "A", "$1", "H-2", "L-1", "H1.5", "M5",
                 "P-1")


def _g76(rng: random.Random, lines: list[str], mistake: bool) -> None:
    """A G76 threading cycle from a drive line just off the part."""
    digits = rng.choice([2, 3, 4, 4, 5])
    x = _num(rng, 0.2, 20, digits)
    z0 = _num(rng, -2, 3, digits)
    lines.append(f"G0 X{x} Z{z0}")
    k = float(_num(rng, 0.02, 2, digits)) or 0.5
    j = float(_num(rng, k / 12, k * 0.9, digits)) or k / 2
    i = _num(rng, 0.01, 2, digits)
    words = {"P": _num(rng, 0.1, 3, digits), "Z": _num(rng, -30, 5, digits),
             "I": i if rng.random() < 0.3 else f"-{i}", "J": repr(j), "K": repr(k)}
    if rng.random() < 0.5:
        words["R"] = rng.choice(["1", "1.5", "2", "2.5", "0.5", _num(rng, 1, 3)])
    if rng.random() < 0.5:
        words["Q"] = rng.choice(["29.5", "30", "-29.5", "0", "-1", _num(rng, -45, 45, 1)])
    if rng.random() < 0.4:
        words["H"] = str(rng.choice([0, 1, 2, 3, -1]))
    if rng.random() < 0.5:
        words["E"] = rng.choice([_num(rng, 0.01, 2, digits), "0", "-0.1"])
        words["L"] = str(rng.choice([0, 1, 2, 3, 3, 4, 7]))
    if rng.random() < 0.2:
        words["X"] = _num(rng, 0.2, 20, digits)
    if rng.random() < 0.1:
        words["Y"] = _num(rng, -2, 2, digits)
    if rng.random() < 0.1:
        words["$"] = "0"
    if mistake:
        _g76_mistake(rng, words)
    incremental = rng.random() < 0.15
    items = list(words.items())
    rng.shuffle(items)
    line = "G76 " + " ".join(f"{letter}{value}" for letter, value in items)
    lines.append(f"G91 {line}" if incremental else line)
    if incremental:
        lines.append("G90")
    lines.append(f"G0 X{x}")


def _g76_mistake(rng: random.Random, words: dict[str, str]) -> None:
    pick = rng.choice(_G76_MISTAKES)
    if pick == "P-1":
        words["P"] = "-1"
    elif pick in "PIJK":
        words.pop(pick)
    elif pick == "K<J":
        words["K"] = words["J"]
    elif pick == "M5":
        words["M"] = "5"
    elif pick[0] in "IJ":
        words[pick[0]] = "0"
    else:
        words[pick[0]] = pick[1:] or "1"


def gen_threading(seed: int) -> str:
    rng = random.Random(seed)
    lathe = rng.random() < 0.5
    lines = ["(threading fuzz)", rng.choice(["G21", "G20", "G21"])]
    if lathe:
        lines.append(rng.choice(["G18 G7", "G18 G8", "G18"]))
    else:
        lines.append(rng.choice(["G17", "G17", "G19", "G18"]))
    if rng.random() < 0.2:
        lines.append(f"G10 L2 P1 X{_num(rng, -5, 5)} Z{_num(rng, -5, 5)}")
    mistake = rng.random() < 0.1
    lines.append(_spindle(rng))
    for _ in range(rng.randint(2, 6)):
        pick = rng.random()
        if pick < 0.25:
            lines.append(_spindle(rng))
            if lines[-1].startswith(("M19", "M5")):
                lines.append("S500 M3")
        elif pick < 0.45 and lathe:
            _lathe_pass(rng, lines, mistake)
        elif pick < 0.7:
            _g76(rng, lines, mistake)
        elif pick < 0.8:
            _tap(rng, lines)
        else:
            lines.append(f"G1 X{_num(rng, -10, 10)} Z{_num(rng, -5, 5)} F{rng.choice([100, 250])}")
    if mistake and rng.random() < 0.3:
        lines.insert(len(lines) - 1, "M5")
    lines.append("M5")
    lines.append("M2")
    return "".join(line + "\n" for line in lines)
