"""Random G-code programs in the style of real code, for differential fuzzing against ``rs274``.

``generate(kind, seed)`` returns the text of one program; the same (kind, seed) always gives the
same text.  Kinds:

``motion``   CAM-like programs: preambles, G0/G1/G2/G3 in all planes, modes, feeds, spindle, coolant
``offsets``  the above plus G10 L2/L20, G52, G92.x, G54-G59.3, G28/G30(.1), G53 and the parameters
             that expose positions and offsets
``oword``    parameters, expressions and o-word control flow that compute toolpaths
``failing``  a program of another kind with one mutation meant to make it fail midway
``cycles``   the motion programs with series of holes drilled by every canned cycle
``splines``  the motion programs with G5 and G5.1 curves and G5.2 ... G5.3 NURBS blocks
``probe``    the motion and offsets programs with straight probes G38.2-G38.5 and probe grids
``threading`` spindle modes, M19, G33 passes, G33.1 taps (``spindlesync.py``)

How it is built: a program is a preamble, a body and an ending.  The body is a sequence of
*statements*; each kind has a table of ``(weight, function)`` entries (``MOTION``, ``OFFSETS``,
``OWORD``) and the generator picks entries by weight.  A statement function takes the ``Gen``
(random source, tracked modal state and position, number and word formatting helpers) and
appends lines with ``g.emit(...)``.  Mutations for ``failing`` are a table too (``MUTATIONS``):
each takes the ``Gen`` and the list of lines and changes it in place.

To extend it when ngc learns a new code: write a statement function that emits the code in a
valid context (use ``g.words`` / ``g.num`` so it gets the odd spellings for free, and update the
tracked state in ``g`` if the code moves the tool or changes a mode), then add ``(weight, fn)`` to
the table of the kind(s) that should use it.  A new kind is a new entry in ``KINDS``.
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable

import continued
import contour
import flow
import inch
import lathe
import lathejob
import probing
import spindlesync
import splines
import state

AXES = "xyz"
# plane code -> (first axis, second axis, normal axis, first offset letter, second offset letter)
PLANES = {
    "17": ("x", "y", "z", "i", "j"),
    "18": ("z", "x", "y", "k", "i"),
    "19": ("y", "z", "x", "j", "k"),
}
# Codes left out of preambles (run.py --exclude), e.g. to look past a known difference.
EXCLUDE: set[str] = set()
COORD_SYSTEMS = ["54", "55", "56", "57", "58", "59", "59.1", "59.2", "59.3"]
WORDS_TEXT = ["roughing", "finish pass", "contour", "pocket 1", "face", "Tool: 6mm endmill",
              "op 3", "spot", "retract", "Z safe", "chamfer", "slot", "-- part A --"]


class Gen:
    """Random source plus the state needed to keep generated programs valid."""

    def __init__(self, seed: int, kind: str) -> None:
        self.rng = random.Random(f"{kind}:{seed}")
        self.lines: list[str] = []
        self.lower = self.rng.random() < 0.15
        self.numbered = self.rng.random() < 0.25
        self.n = 0
        self.n_step = self.rng.choice([1, 5, 10])
        self.sep = self.rng.choice([" ", " ", " ", "", "\t", "  "])
        self.style = self.rng.random()  # how odd the numbers look
        self.metric = True
        self.absolute = True
        self.arc_absolute = False
        self.plane = "17"
        self.motion: str | None = None
        self.feed_mode = "94"
        self.feed = 0.0
        self.speed = 0.0
        self.spindle_on = False
        self.pos: dict[str, float] | None = {"x": 0.0, "y": 0.0, "z": 0.0}
        self.labels = 100
        self.locals = 0
        self.tools = dict(DEFAULT_TABLE)  # the tool table the program runs with
        self.comp_on = False  # a contour left cutter compensation on
        self.lathe_tools: set[int] = set()  # tools of the table with an orientation (Q)

    # ---- formatting -------------------------------------------------------------------------
    def num(self, v: float, places: int = 4) -> str:
        """A number in one of the spellings real programs use; reads back as ``round(v, places)``."""
        v = round(v, places)
        r = self.rng.random()
        if v == 0 and r < 0.15:
            return self.rng.choice(["0", "0.", "-0.", "0.0", ".0", "+0", "-0"])
        text = f"{v:.{places}f}"
        if r < 0.45 * self.style:
            text = text.rstrip("0")
            if text.endswith(".") and self.rng.random() < 0.5:
                text = text[:-1]
        elif r < 0.55 and self.style > 0.7:
            text = f"{v:.{places + self.rng.randint(1, 6)}f}"
        if text.startswith("0.") and len(text) > 2 and self.rng.random() < 0.3:
            text = text[1:]
        elif text.startswith("-0.") and len(text) > 3 and self.rng.random() < 0.3:
            text = "-" + text[2:]
        if v > 0 and self.rng.random() < 0.04:
            text = "+" + text
        return text or "0"

    def coord(self, lo: float = -50, hi: float = 50, places: int = 3) -> float:
        scale = 1 if self.metric else 1 / 25.4
        return round(self.rng.uniform(lo, hi) * scale, places)

    def word(self, letter: str, value: str) -> str:
        sp = " " if self.rng.random() < 0.03 else ""
        return f"{letter}{sp}{value}"

    def words(self, *items: str | None) -> str:
        """Join words of one line with this program's spacing."""
        parts = [w for w in items if w]
        sep = self.sep
        if self.rng.random() < 0.05:
            sep = self.rng.choice([" ", "", "\t", "   "])
        return sep.join(parts)

    def emit(self, text: str, numbered: bool = True) -> None:
        odd_case = self.rng.random() < 0.05 and "#<" not in text
        if (self.lower or odd_case) and "(" not in text:
            text = text.lower()
        if self.numbered and numbered and text and not text.startswith(("%", "o", "O")):
            self.n += self.n_step
            text = f"N{self.n}{self.sep}{text}"
        self.lines.append(text)

    def comment(self) -> str:
        r = self.rng.random()
        if r < 0.1:
            return "(" + " " * self.rng.randint(0, 3) + ")"
        if r < 0.3:
            return f"(MSG,{self.rng.choice(WORDS_TEXT)})"
        return f"({self.rng.choice(WORDS_TEXT)})"

    def g(self, code: str) -> str:
        if self.rng.random() < 0.2 and len(code) == 1:
            code = "0" + code
        return "G" + code

    # ---- state helpers ----------------------------------------------------------------------
    def set_units(self, metric: bool) -> str:
        if metric != self.metric and self.pos is not None:
            f = 25.4 if metric else 1 / 25.4
            self.pos = {a: v * f for a, v in self.pos.items()}
        self.metric = metric
        return self.g("21" if metric else "20")

    def feed_word(self, force: bool = False) -> str | None:
        """The F word a feed move needs now (None if the modal feed will do)."""
        if self.feed_mode == "93":
            return self.word("F", self.num(self.rng.uniform(0.5, 60), 3))
        if self.feed_mode == "95":
            if force or self.feed == 0:
                self.feed = round(self.rng.uniform(0.02, 0.4), 3)
                return self.word("F", self.num(self.feed, 3))
            return None
        if force or self.feed == 0 or self.rng.random() < 0.1:
            top = 3000 if self.metric else 120
            self.feed = round(self.rng.uniform(top / 50, top), 1)
            return self.word("F", self.num(self.feed, 1))
        return None

    def axis_words(self, end: dict[str, float], only: str = "") -> list[str]:
        """X/Y/Z words to reach ``end`` (absolute program coordinates), in the current mode."""
        out = []
        for a in only or AXES:
            if a not in end:
                continue
            if self.absolute or self.pos is None:
                v = end[a]
            else:
                v = end[a] - self.pos[a]
            out.append(self.word(a.upper(), self.num(v)))
        return out

    def move_to(self, end: dict[str, float]) -> None:
        if self.pos is not None:
            self.pos.update(end)
        elif self.absolute and all(a in end for a in AXES):
            self.pos = {a: end[a] for a in AXES}


# ---- statements: motion -------------------------------------------------------------------------


def st_rapid(g: Gen) -> None:
    axes = "".join(a for a in AXES if g.rng.random() < 0.6) or "z"
    if g.pos is None:
        if not g.absolute:
            g.emit(g.words(g.g("90")))
            g.absolute = True
        axes = AXES
    end = {a: g.coord(-40, 40) if a != "z" else g.coord(-5, 25) for a in axes}
    words = g.axis_words(end)
    code = g.g("0") if g.motion != "0" or g.rng.random() < 0.5 else None
    extra = []
    if g.rng.random() < 0.07:
        extra.append(g.word(g.rng.choice("ABC"), g.num(g.rng.uniform(-180, 180), 3)))
    g.emit(g.words(code, *words, *extra))
    g.motion = "0"
    g.move_to(end)


def st_feed_lines(g: Gen) -> None:
    if g.pos is None:
        st_rapid(g)
    assert g.pos is not None
    for k in range(g.rng.randint(1, 6)):
        axes = "".join(a for a in AXES if g.rng.random() < 0.5) or g.rng.choice(AXES)
        end = {a: round(g.pos[a] + g.coord(-20, 20), 3) for a in axes}
        code = g.g("1") if (g.motion != "1" or g.rng.random() < 0.3) else None
        f = g.feed_word(force=k == 0 and g.rng.random() < 0.3)
        extra = []
        if g.rng.random() < 0.05:
            extra.append(g.word(g.rng.choice("ABC"), g.num(g.rng.uniform(-90, 90), 2)))
        g.emit(g.words(code, *g.axis_words(end), *extra, f))
        g.motion = "1"
        g.move_to(end)


def _arc_end(g: Gen) -> tuple[dict[str, float], dict[str, float], float]:
    """End point, center offsets (relative to the start) and radius of a valid arc."""
    assert g.pos is not None
    a1, a2, _, _, _ = PLANES[g.plane]
    sa, sb = g.pos[a1], g.pos[a2]
    scale = 1 if g.metric else 1 / 25.4
    i = round(g.rng.uniform(-15, 15) * scale, 3)
    j = round(g.rng.uniform(-15, 15) * scale, 3)
    if abs(i) + abs(j) < 0.5 * scale:
        i = round(3 * scale, 3)
    r = math.hypot(i, j)
    ca, cb = sa + i, sb + j
    start = math.atan2(-j, -i)
    ang = start + g.rng.uniform(0.2, 2 * math.pi - 0.2)
    end = {a1: round(ca + r * math.cos(ang), 4), a2: round(cb + r * math.sin(ang), 4)}
    return end, {"i": i, "j": j}, r


def st_arc(g: Gen) -> None:
    if g.pos is None:
        st_rapid(g)
    assert g.pos is not None
    a1, a2, normal, l1, l2 = PLANES[g.plane]
    code = g.rng.choice(["2", "3"])
    form = g.rng.random()
    helix = g.rng.random() < 0.15
    end, off, _ = _arc_end(g)
    words: list[str | None] = []
    if form < 0.35:  # R format, not a full circle
        sa, sb = g.pos[a1], g.pos[a2]
        chord = math.hypot(end[a1] - sa, end[a2] - sb)
        if chord < 0.01:
            return
        rad = round(chord / 2 * g.rng.uniform(1.05, 3), 4)
        if g.rng.random() < 0.3:
            rad = -rad
        words = [g.word("R", g.num(rad))]
    else:
        full = form > 0.9
        if full:
            end = {a1: g.pos[a1], a2: g.pos[a2]}
        if g.arc_absolute:
            c = [g.pos[a1] + off["i"], g.pos[a2] + off["j"]]
        else:
            c = [off["i"], off["j"]]
        words = [g.word(l1.upper(), g.num(c[0], 3)), g.word(l2.upper(), g.num(c[1], 3))]
        if full and g.rng.random() < 0.3:
            words.append(g.word("P", str(g.rng.randint(1, 3))))
            helix = True
        elif full and g.rng.random() < 0.5:
            end = {}
    if helix:
        end[normal] = round(g.pos[normal] + g.coord(-6, 3), 3)
    f = g.feed_word()
    lead = g.g(code) if g.motion != code or g.rng.random() < 0.6 else None
    aw = g.axis_words(end)
    g.rng.shuffle(aw)
    g.emit(g.words(lead, *aw, *words, f))
    g.motion = code
    g.move_to(end)


def st_plane(g: Gen) -> None:
    g.plane = g.rng.choice(["17", "17", "18", "19"])
    g.emit(g.words(g.g(g.plane)))


def st_distance(g: Gen) -> None:
    r = g.rng.random()
    if r < 0.6:
        g.absolute = not g.absolute
        code = "90" if g.absolute else "91"
    else:
        g.arc_absolute = not g.arc_absolute
        code = "90.1" if g.arc_absolute else "91.1"
    g.emit(g.words(g.g(code)))


def st_units(g: Gen) -> None:
    g.emit(g.words(g.set_units(not g.metric)))


def st_feed_mode(g: Gen) -> None:
    mode = g.rng.choice(["93", "94", "94", "95"])
    lines = []
    if mode == "95" and not g.spindle_on:
        g.speed = float(g.rng.randint(500, 12000))
        lines.append(g.words(g.word("S", g.num(g.speed, 0)), "M3"))
        g.spindle_on = True
    g.feed = 0.0  # setting a feed mode, even the current one, zeroes the feed rate
    g.feed_mode = mode
    lines.append(g.words(g.g(mode)))
    for line in lines:
        g.emit(line)


def st_path_mode(g: Gen) -> None:
    code = g.rng.choice(["61", "61.1", "64", "64"])
    extra: list[str] = []
    if code == "64" and g.rng.random() < 0.6:
        extra.append(g.word("P", g.num(g.rng.uniform(0.001, 0.1), 3)))
        if g.rng.random() < 0.5:
            extra.append(g.word("Q", g.num(g.rng.uniform(0.001, 0.1), 3)))
    g.emit(g.words(g.g(code), *extra))


def st_spindle(g: Gen) -> None:
    r = g.rng.random()
    if r < 0.6:
        g.speed = float(g.rng.randint(100, 24000))
        m = g.rng.choice(["M3", "M4"])
        g.emit(g.words(g.word("S", g.num(g.speed, 0)), m) if g.rng.random() < 0.7
               else g.words(m, g.word("S", g.num(g.speed, 0))))
        g.spindle_on = True
    elif g.feed_mode != "95":
        g.emit("M5")
        g.spindle_on = False


def st_coolant(g: Gen) -> None:
    g.emit(g.rng.choice(["M7", "M8", "M9", "M8"]))


def st_dwell(g: Gen) -> None:
    g.emit(g.words(g.g("4"), g.word("P", g.num(g.rng.uniform(0, 2), 2))))


def st_comment(g: Gen) -> None:
    r = g.rng.random()
    if r < 0.6:
        g.emit(g.comment(), numbered=False)
    elif r < 0.8:
        g.emit(";" + g.rng.choice(WORDS_TEXT), numbered=False)
    else:
        g.emit("", numbered=False)


def st_override(g: Gen) -> None:
    g.emit(g.rng.choice(["M48", "M49", "M50 P1", "M51 P1", "M52 P1", "M53 P1", "M48"]))


MOTION: list[tuple[float, Callable[[Gen], None]]] = [
    (10, st_rapid),
    (25, st_feed_lines),
    (18, st_arc),
    (3, st_plane),
    (2, st_distance),
    (1, st_units),
    (1.5, st_feed_mode),
    (1.5, st_path_mode),
    (2, st_spindle),
    (1.5, st_coolant),
    (1, st_dwell),
    (4, st_comment),
    (0.4, st_override),
]


# ---- statements: offsets ------------------------------------------------------------------------


def _offset_words(g: Gen, axes: str = "xyz", lo: float = -30, hi: float = 30) -> list[str]:
    chosen = [a for a in axes if g.rng.random() < 0.6] or [g.rng.choice(axes)]
    return [g.word(a.upper(), g.num(g.coord(lo, hi), 3)) for a in chosen]


def _lose_position(g: Gen) -> None:
    g.pos = None


def st_g10(g: Gen) -> None:
    level = g.rng.choice(["2", "2", "20"])
    p = g.rng.randint(0, 9)
    words = _offset_words(g)
    if level == "2" and g.rng.random() < 0.25:
        words.append(g.word("R", g.num(g.rng.uniform(-45, 45), 2)))
    g.emit(g.words("G10", g.word("L", level), g.word("P", str(p)), *words))
    _lose_position(g)


def st_coord_system(g: Gen) -> None:
    g.emit(g.words("G" + g.rng.choice(COORD_SYSTEMS)))
    _lose_position(g)


def st_g52_g92(g: Gen) -> None:
    code = g.rng.choice(["52", "92", "92", "92.1", "92.2", "92.3"])
    words = _offset_words(g) if code in ("52", "92") else []
    g.emit(g.words(g.g(code), *words))
    _lose_position(g)


def st_home(g: Gen) -> None:
    code = g.rng.choice(["28", "30", "28.1", "30.1"])
    words: list[str] = []
    if code in ("28", "30") and g.rng.random() < 0.5:
        if not g.absolute and g.rng.random() < 0.5:
            words = _offset_words(g, lo=-5, hi=5)
        else:
            words = _offset_words(g)
    g.emit(g.words(g.g(code), *words))
    _lose_position(g)


def st_g53(g: Gen) -> None:
    move = g.rng.choice(["0", "1"])
    words = _offset_words(g, lo=-100, hi=0)
    lead: list[str] = []
    if not g.absolute:
        lead = [g.g("90")]
        g.absolute = True
    elif g.rng.random() < 0.3:
        lead = [g.g("90")]
    f = g.feed_word() if move == "1" else None
    parts = [*lead, "G53", g.g(move)] if g.rng.random() < 0.7 else [*lead, g.g(move), "G53"]
    g.emit(g.words(*parts, *words, f))
    g.motion = move
    _lose_position(g)


POSITION_PARAMS = ["#5420", "#5421", "#5422", "#5423", "#<_x>", "#<_y>", "#<_z>", "#<_a>",
                   "#5221", "#5222", "#5223", "#5241", "#5211", "#5212", "#5213", "#5210",
                   "#5161", "#5162", "#5181", "#5220", "#5400", "#<_coord_system>",
                   "#<_abs_x>", "#<_abs_y>", "#<_abs_z>", "#5063", "#<_metric>", "#<_imperial>"]


def st_read_params(g: Gen) -> None:
    ps = g.rng.sample(POSITION_PARAMS, g.rng.randint(1, 3))
    r = g.rng.random()
    if r < 0.5:
        g.emit("(DEBUG," + " ".join(f"{p[1:].strip('<>')}={p}" for p in ps) + ")", numbered=False)
    elif r < 0.75:
        g.locals += 1
        g.emit(f"#{g.locals} = {ps[0]}")
        g.emit(f"(DEBUG,saved #{g.locals})", numbered=False)
    else:
        if not g.absolute:
            g.emit(g.g("90"))
            g.absolute = True
        g.emit(g.words(g.g("0"), f"X[#<_x>+{g.num(g.coord(-5, 5), 2)}]"))
        g.motion = "0"
        _lose_position(g)


OFFSETS: list[tuple[float, Callable[[Gen], None]]] = [
    *MOTION,
    (4, st_g10),
    (3, st_coord_system),
    (4, st_g52_g92),
    (2.5, st_home),
    (2.5, st_g53),
    (5, st_read_params),
    (1, st_units),
]


# ---- statements: o-words and expressions --------------------------------------------------------

FUNCS_SAFE = ["SIN", "COS", "ABS", "FIX", "FUP", "ROUND"]


def expr(g: Gen, depth: int = 0, names: list[str] | None = None) -> str:
    """A bracketed or atomic expression that always evaluates without error."""
    rng = g.rng
    atoms = names or []
    r = rng.random()
    if depth > 2 or r < 0.3:
        if atoms and rng.random() < 0.5:
            return rng.choice(atoms)
        return g.num(rng.uniform(-20, 20), rng.choice([0, 1, 2, 3]))
    r = rng.random()
    a = expr(g, depth + 1, names)
    b = expr(g, depth + 1, names)
    if r < 0.35:
        op = rng.choice(["+", "-", "*", "+", "-", "MOD"])
        if op == "MOD":
            return f"[{a} MOD [ABS[{b}]+1]]"
        return f"[{a} {op} {b}]"
    if r < 0.45:
        return f"[{a} / [ABS[{b}] + 1]]"
    if r < 0.6:
        return f"{rng.choice(FUNCS_SAFE)}[{a}]"
    if r < 0.65:
        return f"SQRT[ABS[{a}]]"
    if r < 0.7:
        return f"LN[ABS[{a}]+1]"
    if r < 0.74:
        return f"EXP[{g.num(rng.uniform(-3, 3), 2)}]"
    if r < 0.78:
        return f"ASIN[{g.num(rng.uniform(-1, 1), 3)}]" if rng.random() < 0.5 \
            else f"ACOS[{g.num(rng.uniform(-1, 1), 3)}]"
    if r < 0.82:
        return f"ATAN[{a}]/[{b}]"
    if r < 0.86:
        return f"TAN[{g.num(rng.uniform(-80, 80), 1)}]"
    if r < 0.9:
        return f"[ABS[{a}] ** {rng.choice(['2', '0.5', '3', '1.5'])}]"
    if r < 0.95:
        op = rng.choice(["EQ", "NE", "GT", "GE", "LT", "LE", "AND", "OR", "XOR"])
        return f"[{a} {op} {b}]"
    return f"[-{a}]" if rng.random() < 0.5 else f"[{a} + -{b}]"


def cond(g: Gen, names: list[str]) -> str:
    op = g.rng.choice(["EQ", "NE", "GT", "GE", "LT", "LE"])
    return f"[{expr(g, 1, names)} {op} {expr(g, 1, names)}]"


def new_label(g: Gen) -> str:
    g.labels += 1
    if g.rng.random() < 0.5:
        return f"o{g.labels}"
    return f"o<{g.rng.choice(['loop', 'l', 'blk', 'cut', 'pass'])}{g.labels}>"


def _safe_z(g: Gen) -> str:
    return g.words(g.g("0"), "Z" + g.num(g.coord(2, 10), 1))


def _ensure_feed(g: Gen) -> None:
    if g.feed_mode != "94":
        g.feed_mode = "94"
        g.emit(g.g("94"))
    if not g.absolute:
        g.absolute = True
        g.emit(g.g("90"))
    g.feed = round(g.rng.uniform(50, 1000) * (1 if g.metric else 1 / 25.4), 1)
    g.emit(g.words("F" + g.num(g.feed, 1)))


def st_assign(g: Gen) -> None:
    names = ["#1", "#2", "#<a>", "#<_total>", "#<depth>", "#31", "#100", "#4999"]
    target = g.rng.choice(names)
    known = [n for n in names if n in g.__dict__.setdefault("assigned", set())]
    g.emit(f"{target} = {expr(g, 0, known)}", numbered=g.rng.random() < 0.5)
    g.__dict__["assigned"].add(target)
    if g.rng.random() < 0.6:
        kind = g.rng.choice(["DEBUG", "PRINT"])
        g.emit(f"({kind},{target[1:]} is {target})", numbered=False)


def st_bolt_circle(g: Gen) -> None:
    name = f"o<bolt{g.labels}>"
    g.labels += 1
    lab = new_label(g)
    _ensure_feed(g)
    n = g.rng.randint(3, 12)
    cx, cy = g.coord(-20, 20, 2), g.coord(-20, 20, 2)
    rad = round(abs(g.coord(3, 25, 2)) + 0.5, 2)
    body = [
        f"{name} sub",
        "  #<i> = 0",
        f"  {lab} while [#<i> LT #4]",
        "    #<ang> = [360 * #<i> / #4]",
        "    G0 X[#1 + #3 * COS[#<ang>]] Y[#2 + #3 * SIN[#<ang>]]",
        f"    G1 Z{g.num(-g.coord(0.5, 3, 2), 2)}",
        "    G0 Z2",
        "    #<i> = [#<i> + 1]",
        f"  {lab} endwhile",
        f"{name} endsub",
    ]
    for line in body:
        g.emit(line, numbered=False)
    g.emit(f"{name} call [{g.num(cx, 2)}] [{g.num(cy, 2)}] [{g.num(rad, 2)}] [{n}]", numbered=False)
    g.motion = "0"
    _lose_position(g)


def st_spiral(g: Gen) -> None:
    lab = new_label(g)
    _ensure_feed(g)
    turns = g.rng.randint(1, 4)
    steps = g.rng.choice([4, 6, 8, 12])
    g.emit(g.words(g.g("0"), "X0", "Y0"))
    g.emit(f"#<r> = {g.num(g.coord(0.5, 2, 2), 2)}", numbered=False)
    g.emit("#<k> = 0", numbered=False)
    g.emit(f"{lab} repeat [{turns * steps}]", numbered=False)
    g.emit(f"  #<k> = [#<k> + {360 // steps}]", numbered=False)
    g.emit(f"  #<r> = [#<r> + {g.num(g.coord(0.1, 0.8, 2), 2)}]", numbered=False)
    g.emit("  G1 X[#<r> * COS[#<k>]] Y[#<r> * SIN[#<k>]]", numbered=False)
    g.emit(f"{lab} endrepeat", numbered=False)
    g.motion = "1"
    _lose_position(g)


def st_zigzag(g: Gen) -> None:
    lab = new_label(g)
    _ensure_feed(g)
    rows = g.rng.randint(2, 8)
    width = g.num(g.coord(5, 40, 1), 1)
    step = g.num(g.coord(0.5, 3, 2), 2)
    g.emit("#<row> = 0", numbered=False)
    g.emit(g.words(g.g("0"), "X0", "Y0"))
    g.emit(f"{lab} do", numbered=False)
    g.emit(f"  G1 Y[#<row> * {step}]", numbered=False)
    g.emit("  #<side> = [[#<row> MOD 2] * " + width + "]", numbered=False)
    g.emit("  G1 X[" + width + " - #<side>]", numbered=False)
    g.emit("  #<row> = [#<row> + 1]", numbered=False)
    if g.rng.random() < 0.3:
        inner = new_label(g)
        g.emit(f"  {inner} if [#<row> EQ {rows + 5}]", numbered=False)
        g.emit(f"    {lab} break", numbered=False)
        g.emit(f"  {inner} endif", numbered=False)
    g.emit(f"{lab} while [#<row> LT {rows}]", numbered=False)
    g.motion = "1"
    _lose_position(g)


def st_if_chain(g: Gen) -> None:
    lab = new_label(g)
    names = ["#1", "#<a>"]
    g.emit(f"#1 = {expr(g, 1)}", numbered=False)
    g.emit(f"#<a> = {expr(g, 1, ['#1'])}", numbered=False)
    g.emit(f"{lab} if {cond(g, names)}", numbered=False)
    g.emit("  (DEBUG,branch one #1 #<a>)", numbered=False)
    for _ in range(g.rng.randint(0, 2)):
        g.emit(f"{lab} elseif {cond(g, names)}", numbered=False)
        g.emit(f"  #<a> = {expr(g, 1, names)}", numbered=False)
        g.emit("  (PRINT,elseif a=#<a>)", numbered=False)
    if g.rng.random() < 0.6:
        g.emit(f"{lab} else", numbered=False)
        g.emit("  (DEBUG,else #<a>)", numbered=False)
    g.emit(f"{lab} endif", numbered=False)


def st_function_sub(g: Gen) -> None:
    name = f"o<f{g.labels}>"
    g.labels += 1
    g.emit(f"{name} sub", numbered=False)
    g.emit(f"  #<t> = {expr(g, 1, ['#1', '#2'])}", numbered=False)
    inner = new_label(g)
    g.emit(f"  {inner} if [#1 GT #2]", numbered=False)
    g.emit(f"    {name} return [#<t> + 1]", numbered=False)
    g.emit(f"  {inner} endif", numbered=False)
    if g.rng.random() < 0.7:
        g.emit(f"{name} endsub [#<t> * 2]", numbered=False)
    else:
        g.emit(f"{name} endsub", numbered=False)
    for _ in range(g.rng.randint(1, 3)):
        g.emit(f"{name} call [{expr(g, 2)}] [{expr(g, 2)}]", numbered=False)
        g.emit("(DEBUG,value=#<_value> returned=#<_value_returned>)", numbered=False)


def st_while_continue(g: Gen) -> None:
    lab = new_label(g)
    inner = new_label(g)
    g.emit("#<n> = 0", numbered=False)
    g.emit("#<s> = 0", numbered=False)
    g.emit(f"{lab} while [#<n> LT {g.rng.randint(2, 9)}]", numbered=False)
    g.emit("  #<n> = [#<n> + 1]", numbered=False)
    g.emit(f"  {inner} if [[#<n> MOD {g.rng.randint(2, 3)}] EQ 0]", numbered=False)
    g.emit(f"    {lab} continue", numbered=False)
    g.emit(f"  {inner} endif", numbered=False)
    g.emit(f"  #<s> = [#<s> + #<n> * {g.num(g.rng.uniform(-3, 3), 2)}]", numbered=False)
    if g.rng.random() < 0.3:
        third = new_label(g)
        g.emit(f"  {third} if [#<s> GT 10]", numbered=False)
        g.emit(f"    {lab} break", numbered=False)
        g.emit(f"  {third} endif", numbered=False)
    g.emit(f"{lab} endwhile", numbered=False)
    g.emit("(DEBUG,sum=#<s> n=#<n>)", numbered=False)


def st_exists(g: Gen) -> None:
    name = g.rng.choice(["#<a>", "#<_total>", "#<nothere>", "#<_nothere>", "#<depth>"])
    g.emit(f"#<e> = EXISTS[{name}]", numbered=False)
    g.emit("(DEBUG,exists=#<e>)", numbered=False)


def st_expr_move(g: Gen) -> None:
    _ensure_feed(g)
    g.emit(g.words("G1", f"X{expr(g, 1)}", f"Y{expr(g, 2)}"))
    g.motion = "1"
    _lose_position(g)


OWORD: list[tuple[float, Callable[[Gen], None]]] = [
    (8, st_assign),
    (3, st_bolt_circle),
    (3, st_spiral),
    (3, st_zigzag),
    (4, st_if_chain),
    (3, st_function_sub),
    (3, st_while_continue),
    (1.5, st_exists),
    (3, st_expr_move),
    (2, st_rapid),
    (2, st_feed_lines),
    (1, st_comment),
]


# ---- preamble and ending ------------------------------------------------------------------------


def preamble(g: Gen) -> None:
    rng = g.rng
    if rng.random() < 0.2:
        g.lines.append("%")
    if rng.random() < 0.6:
        g.emit(f"({rng.choice(WORDS_TEXT)})", numbered=False)
    codes = ["17", "21", "40", "49", "80", "90", "94"]
    if rng.random() < 0.25:
        codes[1] = "20"
    # G40 and G49 are rarer than in real preambles so they do not hide everything after them.
    codes = [c for c in codes if rng.random() < (0.2 if c in ("40", "49") else 0.85)
             and "G" + c not in EXCLUDE]
    if rng.random() < 0.5:
        rng.shuffle(codes)
    for c in codes:
        if c == "20":
            g.set_units(False)
    if rng.random() < 0.3:
        g.emit("".join(g.g(c.zfill(2) if rng.random() < 0.5 else c) for c in codes))
    elif rng.random() < 0.5:
        # one code a line, or two lines
        half = len(codes) // 2
        g.emit(g.words(*(g.g(c) for c in codes[:half])))
        g.emit(g.words(*(g.g(c) for c in codes[half:])))
    else:
        g.emit(g.words(*(g.g(c) for c in codes)))
    if rng.random() < 0.4:
        g.emit(g.words(g.g(rng.choice(["54", "54", "55"]))))
    if rng.random() < 0.4:
        g.emit(g.words(g.g("64"), g.word("P", g.num(0.01, 3))) if rng.random() < 0.5 else g.g("61"))
    if rng.random() < 0.6:
        g.speed = float(rng.randint(1000, 18000))
        g.emit(g.words(g.word("S", g.num(g.speed, 0)), "M3"))
        g.spindle_on = True
    if rng.random() < 0.3:
        g.emit(rng.choice(["M8", "M7"]))


def ending(g: Gen) -> None:
    rng = g.rng
    if rng.random() < 0.5:
        g.emit(g.words(g.g("0"), "Z" + g.num(g.coord(5, 20), 1)))
    if rng.random() < 0.4:
        g.emit("M5")
    if rng.random() < 0.3:
        g.emit("M9")
    g.emit(rng.choice(["M2", "M30", "M2", "M30", "M02"]))
    if g.lines[0] == "%":
        g.lines.append("%")


def st_mixed_line(g: Gen) -> None:
    """One line holding codes of several modal groups, M codes, F, S and a comment, in random
    order: the order of execution, not the order of the words, decides what happens."""
    rng = g.rng
    words: list[str] = []
    pick = rng.random
    if pick() < 0.3:
        g.plane = rng.choice(["17", "18", "19"])
        words.append("G" + g.plane)
    if pick() < 0.3:
        g.absolute = rng.random() < 0.6
        words.append("G90" if g.absolute else "G91")
    if pick() < 0.15:
        g.arc_absolute = rng.random() < 0.5
        words.append("G90.1" if g.arc_absolute else "G91.1")
    if pick() < 0.2:
        g.metric = rng.random() < 0.6
        words.append("G21" if g.metric else "G20")
    if pick() < 0.25:
        words.append(rng.choice(["G61", "G61.1", "G64", f"G64 P{g.num(rng.uniform(0, 0.1), 3)}",
                                 f"G64 P{g.num(rng.uniform(0, 0.1), 3)} Q{g.num(rng.uniform(0, 0.1), 3)}"]))
    if pick() < 0.15:
        words.append(rng.choice(["G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3"]))
    for code, chance in (("G98", 0.05), ("G99", 0.05), ("G40", 0.1), ("G49", 0.1), ("G80", 0.05)):
        if pick() < chance:
            words.append(code)
    if pick() < 0.2:
        code = rng.choice(["3", "4", "5"])
        g.spindle_on = code != "5"
        words.append("M" + code)
    if pick() < 0.2:
        words.append(rng.choice(["M7", "M8", "M9"]))
    if pick() < 0.1:
        words.append(rng.choice(["M48", "M49", "M50", "M51", "M50 P0", "M51 P1", "M53 P1"]))
    if pick() < 0.25 or (g.feed_mode == "95" and g.speed == 0):
        g.speed = round(rng.uniform(100, 20000))
        words.append(f"S{g.speed}")
    if pick() < 0.1:
        g.feed_mode = rng.choice(["94", "95"])
        words.append("G" + g.feed_mode)
        g.feed = 0.0
        if g.feed_mode == "95" and g.speed == 0:
            g.speed = 1000
            words.append("S1000")
    motion = pick() < 0.6
    if motion:
        g.motion = rng.choice(["0", "1", "1"])
        if g.motion == "1" and (g.feed == 0 or pick() < 0.3):
            g.feed = round(rng.uniform(10, 2000), 1)
            words.append(f"F{g.feed}")
        words.append("G" + g.motion)
        for axis in rng.sample("XYZ", rng.randint(1, 3)):
            words.append(f"{axis}{g.num(g.coord(-20, 20))}")
        if pick() < 0.1:
            words.append(f"A{g.num(rng.uniform(-90, 90), 2)}")
        _lose_position(g)
    elif pick() < 0.3:
        words.append(rng.choice(["G92.1", "G92.2", "G92.3", "G28.1", "G30.1",
                                 f"G92 X{g.num(g.coord(-5, 5))}", f"G52 Y{g.num(g.coord(-5, 5))}",
                                 "G28", "G30", f"G28 Z{g.num(g.coord(0, 10))}"]))
        _lose_position(g)
    if pick() < 0.1:
        words.append(f"G4 P{g.num(rng.uniform(0, 2), 2)}")
    rng.shuffle(words)
    if pick() < 0.2:
        words.append(g.comment())
    if words:
        g.emit(g.words(*words))


# ---- tools: tool tables, T/M6/M61, tool length offsets, G10 L1/L10/L11, G7/G8 ------------------

# The table rs274 loads without -t (inch values); tool number -> (pocket, diameter, z).
DEFAULT_TABLE: dict[int, tuple[int, float, float]] = {
    1: (1, 0.125, 0.511), 2: (2, 0.0625, 0.1), 3: (3, 0.201, 1.273), 99999: (123, 0.0, 0.1)}
# A program that carries its own tool table holds it in comment lines starting with this mark;
# run.py writes them (without the mark) to TABLE_NAME and passes ``-t TABLE_NAME`` to both sides.
TABLE_MARK = ";tooltable:"
TABLE_NAME = "table.tbl"
TOOL_PARAMS = ["#5400", "#5401", "#5402", "#5403", "#5404", "#5405", "#5406", "#5407", "#5408",
               "#5409", "#5410", "#5411", "#5412", "#5413", "#<_current_tool>",
               "#<_current_pocket>", "#<_selected_tool>", "#<_selected_pocket>"]


def table_of(text: str) -> str | None:
    """The tool table a program carries (the lines after TABLE_MARK), or None: the default."""
    rows = [line[len(TABLE_MARK):].strip() for line in text.splitlines()
            if line.startswith(TABLE_MARK)]
    return "".join(row + "\n" for row in rows) if rows else None


def write_table(g: Gen) -> None:
    """Make a tool table of 1-7 tools and put it into the program (after a leading %)."""
    rng = g.rng
    numbers = rng.sample([*range(1, 21), 99, 1234, 0], rng.randint(1, 7))
    pockets = rng.sample(range(1, 40), len(numbers))
    tools: dict[int, tuple[int, float, float]] = {}
    rows = []
    for t, p in zip(numbers, pockets, strict=True):
        d = round(rng.uniform(0.01, 0.6), rng.choice([3, 4, 6]))
        z = round(rng.uniform(-3, 6), rng.choice([2, 3, 6]))
        fields = [f"D{d}", f"Z{'+' if z >= 0 and rng.random() < 0.5 else ''}{z}"]
        if rng.random() < 0.3:
            fields.append(f"X{round(rng.uniform(-1, 1), 3)}")
        if rng.random() < 0.2:
            fields += [f"Q{rng.randint(0, 9)}", f"I{rng.randint(-90, 90)}", f"J{rng.randint(0, 90)}"]
            g.lathe_tools.add(t)
        if rng.random() < 0.1:
            fields.remove(f"D{d}")
            d = 0.0
        rng.shuffle(fields)
        comment = rng.choice(["", " ;", f" ;{rng.choice(WORDS_TEXT)}"])
        rows.append(f"T{t} P{p} {' '.join(fields)}{comment}")
        tools[t] = (p, d, z)
    at = 1 if g.lines and g.lines[0] == "%" else 0
    g.lines[at:at] = [TABLE_MARK + " " + row for row in rows]
    g.tools = tools


def _tool(g: Gen, known: float = 0.99) -> int:
    """A tool number of the table (or, now and then, one that is not in it)."""
    if g.rng.random() < known and g.tools:
        t = g.rng.choice(sorted(g.tools))
        if t == 99999 and g.rng.random() < 0.8:  # a big number: rs274 does not find it for G43 H
            t = g.rng.choice(sorted(g.tools))
        return t
    return g.rng.choice([0, 4, 17, 50, 99999])


def st_tool_change(g: Gen) -> None:
    rng = g.rng
    t = _tool(g)
    r = rng.random()
    if r < 0.5:
        g.emit(g.words(g.word("T", str(t)), "M6") if rng.random() < 0.7
               else g.words("M6", g.word("T", str(t))))
    elif r < 0.7:
        g.emit(g.words(g.word("T", str(t))))
        if rng.random() < 0.7:
            g.emit("M6")
    elif r < 0.9:
        g.emit(g.words("M61", g.word("Q", str(t))))
    else:
        g.emit(g.words(g.word("T", str(t))))
    if rng.random() < 0.4:
        g.emit(g.words("G43") if rng.random() < 0.7 else g.words("G43", g.word("H", str(t))))
        _lose_position(g)


def st_tool_offset(g: Gen) -> None:
    rng = g.rng
    r = rng.random()
    scale = 1 if g.metric else 1 / 25.4
    if r < 0.3:
        g.emit(g.words("G43", g.word("H", str(_tool(g)))) if rng.random() < 0.6 else "G43")
    elif r < 0.5:
        axes = ["Z"] if rng.random() < 0.5 else rng.sample(["X", "Z", "Y", "A"], rng.randint(1, 2))
        g.emit(g.words("G43.1", *(g.word(a, g.num(rng.uniform(-20, 20) * scale, 3)) for a in axes)))
    elif r < 0.7:
        if rng.random() < 0.9:
            g.emit(g.words("G43.2", g.word("H", str(_tool(g)))))
        else:
            g.emit(g.words("G43.2", g.word("Z", g.num(rng.uniform(-5, 5) * scale, 3))))
    else:
        g.emit("G49")
    _lose_position(g)


def st_g10_tool(g: Gen) -> None:
    rng = g.rng
    level = rng.choice(["1", "1", "10", "11"])
    t = _tool(g)
    if t == 0 and rng.random() < 0.9:  # P0 is out of range
        t = rng.choice([n for n in sorted(g.tools) if n] or [1])
    scale = 1 if g.metric else 1 / 25.4
    words: list[str] = []
    letters = ["Z", "X", "R", "I", "J", "Q"] if level == "1" else ["Z", "X", "Y"]
    for letter in rng.sample(letters, rng.randint(1, 3)):
        if letter == "R":
            v = g.num(rng.uniform(0, 5) * scale, 3)
        elif letter == "Q":
            v = str(rng.randint(0, 9))
        elif letter in "IJ":
            v = g.num(rng.uniform(-90, 90), 1)
        else:
            v = g.num(rng.uniform(-30, 30) * scale, 3)
        words.append(g.word(letter, v))
    g.emit(g.words("G10", g.word("L", level), g.word("P", str(t)), *words))
    if rng.random() < 0.3:
        g.emit("G43")
    _lose_position(g)


def st_tool_params(g: Gen) -> None:
    ps = g.rng.sample(TOOL_PARAMS, g.rng.randint(1, 4))
    if g.rng.random() < 0.7:
        g.emit("(DEBUG," + " ".join(f"{p[1:].strip('<>')}={p}" for p in ps) + ")", numbered=False)
    else:
        g.locals += 1
        g.emit(f"#{g.locals} = [{ps[0]} * 2]")
        g.emit(f"(DEBUG,twice {ps[0][1:]} is #{g.locals})", numbered=False)


def st_lathe_diameter(g: Gen) -> None:
    """G7 (X words are diameters) with a few moves in the XZ plane, then G8 again."""
    rng = g.rng
    if g.plane != "18":
        g.plane = "18"
        g.emit(g.g("18"))
    if not g.absolute:
        g.absolute = True
        g.emit(g.g("90"))
    g.emit(g.words("G7"))
    scale = 1 if g.metric else 1 / 25.4
    for k in range(rng.randint(1, 4)):
        x = round(rng.uniform(1, 30) * scale, 3)
        z = round(rng.uniform(-40, 5) * scale, 3)
        code = rng.choice(["0", "1", "1"])
        f = g.feed_word(force=k == 0) if code == "1" else None
        g.emit(g.words(g.g(code), g.word("X", g.num(2 * x)), g.word("Z", g.num(z)), f))
        g.motion = code
        if rng.random() < 0.3:
            g.emit("(DEBUG,x=#<_x> 5420=#5420 diameter=#<_lathe_diameter_mode>)", numbered=False)
    g.emit(g.words("G8"))
    _lose_position(g)


TOOLS: list[tuple[float, Callable[[Gen], None]]] = [
    (10, st_rapid),
    (14, st_feed_lines),
    (6, st_arc),
    (1.5, st_plane),
    (1, st_distance),
    (0.6, st_units),
    (3, st_comment),
    (8, st_tool_change),
    (6, st_tool_offset),
    (5, st_g10_tool),
    (6, st_tool_params),
    (2.5, st_lathe_diameter),
    # the offsets tool lengths combine with
    (2, st_g10),
    (1.5, st_coord_system),
    (2, st_g52_g92),
    (1.5, st_home),
    (1.5, st_g53),
    (2, st_read_params),
]


def gen_tools(seed: int) -> str:
    g = Gen(seed, "tools")
    preamble(g)
    if g.rng.random() < 0.7:
        write_table(g)
    body(g, TOOLS_WITH_COMP, g.rng.randint(5, 30))
    ending(g)
    return text_of(g.lines)


# ---- cutter radius compensation: contours with entry and exit moves ---------------------------

# plane -> (axis words of u and v, center offset letters of u and v, the normal axis word)
COMP_PLANES = {"17": ("X", "Y", "I", "J", "Z"), "18": ("Z", "X", "K", "I", "Y")}


def _comp_radius(g: Gen) -> tuple[float, list[str], bool]:
    """The tool radius (mm), the words after the G code that turns comp on, and whether that is
    G41.1/G42.1 (a diameter) rather than G41/G42 (a tool)."""
    rng = g.rng
    r = rng.random()
    # a lathe tool (one with an orientation) takes comp in G18 only: now and then try it anyway
    tools = {t: v for t, v in g.tools.items()
             if v[1] > 0 and (t not in g.lathe_tools or g.plane == "18" or rng.random() < 0.05)}
    if r < 0.55 or not tools:
        radius = rng.choice([0.5, 1, 1.5, 2, 3, 4, 5, 6.35]) * rng.uniform(0.8, 1.2)
        d = radius * 2 / (1 if g.metric else 25.4)
        return radius, [g.word("D", g.num(d, 4))], True
    t = rng.choice(sorted(tools))
    radius = tools[t][1] * 25.4 / 2
    if r < 0.8:
        return radius, [g.word("D", str(t))], False
    g.emit(g.words(g.word("T", str(t)), "M6"))
    return radius, ([g.word("D", "0")] if rng.random() < 0.3 else []), False


MISTAKES = ["short-entry", "big-tool", "arc-exit", "on-twice", "yz"]


def st_comp_contour(g: Gen) -> None:
    """A compensated contour: lead-in point, comp on, entry move, the contour (maybe held in a
    subroutine, maybe incremental), things between the moves, G40 and an exit move.  Now and
    then a mistake: a short entry, a tool too big for the contour, an arc after G40, ..."""
    rng = g.rng
    if g.plane not in COMP_PLANES or rng.random() < 0.2:
        g.plane = rng.choice(["17", "17", "17", "18"])
        g.emit(g.g(g.plane))
    wu, wv, lu, lv, wn = COMP_PLANES[g.plane]
    if g.feed_mode != "94":
        g.feed_mode = "94"
        g.feed = 0.0
        g.emit(g.g("94"))
    mistake = rng.choice(MISTAKES) if rng.random() < 0.04 else ""
    radius, dwords, dynamic = _comp_radius(g)
    scale = 1 if g.metric else 1 / 25.4
    left = rng.random() < 0.5
    c = contour.shape(rng, rng.uniform(8, 40), ccw=rng.random() < 0.5)
    if mistake == "big-tool":
        c = c.scaled(radius * rng.uniform(0.6, 1.5) / c.feature)
    elif c.feature < 8 * radius:
        c = c.scaled(8 * radius / c.feature)
    c = c.moved(rng.uniform(-30, 30), rng.uniform(-30, 30)).scaled(scale).rounded(4)
    r_prog = radius * scale
    # the lead-in point: beside the start on the tool's side, farther from it than the radius
    d0 = contour.start_direction(c.start, c.segs[0])
    n = contour.side_normal(d0, left)
    if mistake == "short-entry":
        dist, back = rng.uniform(0.2, 0.9) * r_prog, 0.0
    else:
        dist, back = rng.uniform(1.5, 3) * r_prog + 0.5 * scale, rng.uniform(0, 1.5) * r_prog
    lead = (round(c.start[0] + n[0] * dist - d0[0] * back, 4),
            round(c.start[1] + n[1] * dist - d0[1] * back, 4))
    incremental = rng.random() < 0.2
    use_sub = rng.random() < 0.15

    def to(p: contour.Point, frm: contour.Point) -> list[str]:
        if incremental:
            return [g.word(wu, g.num(p[0] - frm[0])), g.word(wv, g.num(p[1] - frm[1]))]
        return [g.word(wu, g.num(p[0])), g.word(wv, g.num(p[1]))]

    side = ("41" if left else "42") + (".1" if dynamic else "")
    extra = [g.word("L", str(rng.randint(0, 9)))] \
        if g.plane == "18" and dynamic and rng.random() < 0.4 else []
    on_line = g.words(g.g(side), *dwords, *extra)
    # the contour after the entry move
    body_lines: list[str] = []
    cur = last_start = c.start
    prev: str | None = None
    for k, s in enumerate(c.segs):
        code = ("3" if s.ccw else "2") if s.is_arc else "1"
        words = to(s.end, cur)
        if s.center is not None:
            ref = (0.0, 0.0) if g.arc_absolute else cur
            words += [g.word(lu, g.num(s.center[0] - ref[0])), g.word(lv, g.num(s.center[1] - ref[1]))]
        lead_code = g.g(code) if code != prev or rng.random() < 0.4 else None
        body_lines.append(g.words(lead_code, *words, g.feed_word() if rng.random() < 0.3 else None))
        prev = code
        last_start, cur = cur, s.end
        if mistake == "on-twice" and k == len(c.segs) // 2:
            body_lines.append(on_line)
        if rng.random() < 0.2:
            body_lines += _between(g, wn, incremental)
            prev = None
    if c.closed and not c.segs[0].is_arc and rng.random() < 0.3:  # overlap past the start
        mid = (round((cur[0] + c.segs[0].end[0]) / 2, 4), round((cur[1] + c.segs[0].end[1]) / 2, 4))
        body_lines.append(g.words(g.g("1"), *to(mid, cur)))
        cur = mid
    if use_sub:
        name = f"o<contour{g.labels}>"
        g.labels += 1
        g.emit(f"{name} sub", numbered=False)
        for line in body_lines:
            g.emit("  " + line, numbered=False)
        g.emit(f"{name} endsub", numbered=False)
    # frame changes before the lead-in, now and then
    frame = rng.random()
    if frame < 0.06:
        g.emit(g.words("G52", g.word(wu, g.num(g.coord(-20, 20))), g.word(wv, g.num(g.coord(-20, 20)))))
    elif frame < 0.1:
        g.emit(g.words("G10", "L2", "P0", g.word("R", g.num(rng.uniform(-90, 90), 2))))
    elif frame < 0.14:
        g.emit(g.words("G92", g.word(wu, g.num(g.coord(-20, 20))), g.word(wv, g.num(g.coord(-20, 20)))))
    if not g.absolute:
        g.absolute = True
        g.emit(g.g("90"))
    safe = g.coord(2, 10)
    g.emit(g.words(g.g("0"), g.word(wn, g.num(safe))))
    g.emit(g.words(g.g("0"), g.word(wu, g.num(lead[0])), g.word(wv, g.num(lead[1]))))
    f = g.feed_word(force=True)
    if rng.random() < 0.7:
        g.emit(g.words(g.g("1"), g.word(wn, g.num(g.coord(-5, 0))), f))
        f = None
    if mistake == "yz":
        g.plane = "19"
        g.emit(g.g("19"))
    if incremental:
        g.absolute = False
        g.emit(g.g("91"))
    entry_code = "0" if rng.random() < 0.1 else "1"
    entry = [g.g(entry_code), *to(c.start, lead), f]
    if rng.random() < 0.25:
        g.emit(g.words(on_line, *entry))
    else:
        g.emit(on_line)
        g.emit(g.words(*entry))
    if use_sub:
        g.emit(f"{name} call", numbered=False)
    else:
        for line in body_lines:
            g.emit(line)
    _lose_position(g)
    g.motion = None
    if rng.random() < 0.03:
        g.comp_on = True  # comp stays on till the program ends
        return
    # the exit: G40 and a move away on the tool's side
    direction = contour.start_direction(c.start, c.segs[0]) if c.closed \
        else contour.end_direction(last_start, c.segs[-1])
    dl = contour.side_normal(direction, left)
    away = rng.uniform(2.5, 4) * r_prog + scale
    exit_pt = (round(cur[0] + dl[0] * away, 4), round(cur[1] + dl[1] * away, 4))
    exit_code = rng.choice(["0", "1"])
    if mistake == "arc-exit":
        g.emit(g.g("40"))
        g.emit(g.words(g.g("2"), *to(exit_pt, cur), g.word("R", g.num(away * 2))))
    elif rng.random() < 0.3:
        g.emit(g.words(g.g("40"), g.g(exit_code), *to(exit_pt, cur)))
    else:
        g.emit(g.g("40"))
        g.emit(g.words(g.g(exit_code), *to(exit_pt, cur)))
    g.motion = exit_code


def _between(g: Gen, normal: str, incremental: bool) -> list[str]:
    """Lines between compensated moves: comments, messages, a feed, coolant, a dwell, a normal
    axis move, a spindle speed, a parameter read."""
    rng = g.rng
    r = rng.random()
    if r < 0.25:
        return [g.comment()]
    if r < 0.35:
        return [g.words("F" + g.num(rng.uniform(50, 2000) * (1 if g.metric else 1 / 25.4), 1))]
    if r < 0.45:
        return [rng.choice(["M7", "M8", "M9"])]
    if r < 0.55:
        return [g.words(g.g("4"), g.word("P", g.num(rng.uniform(0, 1), 2)))]
    if r < 0.7:
        v = rng.uniform(-1, 1) * (1 if g.metric else 1 / 25.4)
        return [g.words(g.g("1"), g.word(normal, g.num(v if incremental else v - 1, 3)))]
    if r < 0.8:
        return [g.words(g.word("S", g.num(rng.randint(500, 12000), 0)), rng.choice(["M3", "M4"]))]
    if r < 0.9:
        return ["(DEBUG,x=#<_x> y=#<_y> z=#<_z> comp=#<_ccomp>)"]
    return [f";{rng.choice(WORDS_TEXT)}"]


COMP: list[tuple[float, Callable[[Gen], None]]] = [
    (10, st_comp_contour),
    (3, st_rapid),
    (2, st_feed_lines),
    (1, st_arc),
    (1, st_units),
    (1, st_comment),
    (0.7, st_distance),
    (0.7, st_tool_change),
    (0.5, st_spindle),
    (0.5, st_coolant),
]
TOOLS_WITH_COMP: list[tuple[float, Callable[[Gen], None]]] = [*TOOLS, (4, st_comp_contour)]


def gen_comp(seed: int) -> str:
    g = Gen(seed, "comp")
    preamble(g)
    if g.rng.random() < 0.1:
        write_table(g)
    body(g, COMP, g.rng.randint(1, 6))
    ending(g)
    return text_of(g.lines)


def body(g: Gen, table: list[tuple[float, Callable[[Gen], None]]], count: int) -> None:
    weights = [w for w, _ in table]
    fns = [f for _, f in table]
    for _ in range(count):
        if g.comp_on:  # a contour left compensation on: the program ends here
            break
        g.rng.choices(fns, weights)[0](g)


def _program(kind: str, seed: int, table: list[tuple[float, Callable[[Gen], None]]],
             lo: int, hi: int) -> Gen:
    g = Gen(seed, kind)
    preamble(g)
    body(g, table, g.rng.randint(lo, hi))
    ending(g)
    return g


# ---- statements: canned cycles ------------------------------------------------------------------

CYCLE_CODES = ["73", "74", "81", "82", "83", "84", "85", "86", "87", "88", "89"]  # all of them


def st_drill(g: Gen) -> None:
    """A series of holes with one drilling cycle: G98/G99, R above the bottom (now and then not),
    G91 values relative to the start level and R, an L count, a few modal repeats of the cycle
    with only hole positions, then G80 and an absolute traverse that makes the position known."""
    if g.comp_on or g.feed_mode == "93":
        return
    if g.pos is None:
        st_rapid(g)
    first, second, normal, _, _ = PLANES[g.plane]
    assert g.pos is not None
    level = g.pos[normal]
    code = g.rng.choice(CYCLE_CODES)
    r_plane = level + g.coord(-3, 8)
    bottom = r_plane - g.coord(0.5, 12)
    if g.rng.random() < 0.015:
        bottom = r_plane + g.coord(0.5, 3)  # R below the bottom: rs274's error
    words: list[str | None] = [g.g(g.rng.choice(["98", "99"])) if g.rng.random() < 0.6 else None,
                               g.g(code)]
    here = {first: g.pos[first], second: g.pos[second]}
    hole = {a: here[a] + g.coord(-30, 30) for a in (first, second) if g.rng.random() < 0.8}
    for a in (first, second):
        if a in hole:
            v = hole[a] if g.absolute else hole[a] - here[a]
            words.append(g.word(a.upper(), g.num(v)))
    if g.absolute:
        words += [g.word(normal.upper(), g.num(bottom)), g.word("R", g.num(r_plane))]
    else:
        words += [g.word(normal.upper(), g.num(bottom - r_plane)),
                  g.word("R", g.num(r_plane - level))]
    p_odds = {"74": 0.5, "82": 0.97, "84": 0.5, "86": 0.97, "88": 0.97, "89": 0.97}  # G74, G84: optional
    if g.rng.random() < p_odds.get(code, 0.0):
        words.append(g.word("P", g.num(g.rng.choice([0, 0.5, 1, g.rng.uniform(0, 3)]), 2)))
    if code in ("73", "83") and g.rng.random() < 0.97:  # the peck depth: a few to a hole, or more
        q = g.rng.choice([g.coord(0.2, 3), (r_plane - bottom) / g.rng.randint(1, 5), 0.5])
        words.append(g.word("Q", g.num(q if g.rng.random() < 0.98 else -q)))
    if code == "84" and g.rng.random() < 0.9:  # G84 taps with the spindle turning clockwise
        words.append("M3")
        g.spindle_on = True
    if code == "74" and g.rng.random() < 0.9:  # G74 taps with the spindle turning counterclockwise
        words.append("M4")
        g.spindle_on = True
    if code in ("86", "87", "88") and g.rng.random() < 0.9:  # the spindle turning either way
        words.append(g.rng.choice(["M3", "M4"]))
        g.spindle_on = True
    if code == "87":
        words += _back_bore_words(g, normal, bottom, r_plane)
    if g.rng.random() < (0.01 if code == "74" else 0.25):  # rs274 refuses L with G74
        words.append(g.word("L", str(g.rng.randint(1, 4))))
    words.append(g.feed_word())
    g.emit(g.words(*words))
    for _ in range(g.rng.randint(0, 3)):  # more holes: the cycle is the motion mode
        if g.rng.random() < 0.15:
            first, second, normal = _cycle_plane_change(g, code)
            continue
        step = [g.word(a.upper(), g.num(g.coord(-30, 30) if not g.absolute
                                         else g.pos[a] + g.coord(-30, 30)))
                for a in (first, second) if g.rng.random() < 0.8]
        if step:
            g.emit(g.words(*step))
    g.emit(g.words(g.g("80")))
    g.motion = "80"
    end = {a: g.coord(-40, 40) if a != normal else g.coord(15, 30) for a in AXES}
    g.emit(g.words(g.g("90"), g.g("0"), *[g.word(a.upper(), g.num(end[a])) for a in AXES]))
    g.absolute = True
    g.motion = "0"
    g.pos = end


def _back_bore_words(g: Gen, normal: str, bottom: float, r_plane: float) -> list[str]:
    """G87's I J K: the offset point in the plane, the back-bore height on the drill axis
    (absolute in G90, from the bottom in G91); each left out now and then."""
    words = []
    for a, letter in zip("xyz", "IJK", strict=True):
        if g.rng.random() < 0.02:
            continue
        if a == normal:
            height = g.rng.uniform(bottom, r_plane)
            words.append(g.word(letter, g.num(height if g.absolute else height - bottom)))
        else:
            words.append(g.word(letter, g.num(g.coord(-2, 2))))
    return words


def _cycle_plane_change(g: Gen, code: str) -> tuple[str, str, str]:
    """In the middle of a series of cycles: another plane, and a hole there, with its bottom (and
    now and then a new R and, for G87, new I J K) on the new drill axis."""
    assert g.pos is not None
    g.plane = g.rng.choice([p for p in PLANES if p != g.plane])
    first, second, normal, _, _ = PLANES[g.plane]
    level = g.pos[normal]
    r_plane = level + g.coord(-3, 8)
    bottom = r_plane - g.coord(0.5, 12)
    words = [g.g(g.plane)]
    if g.rng.random() < 0.3:
        words.append(g.g(g.rng.choice(["98", "99"])))
    words += [g.word(a.upper(), g.num(g.coord(-30, 30) if not g.absolute
                                      else g.pos[a] + g.coord(-30, 30)))
              for a in (first, second) if g.rng.random() < 0.8]
    words.append(g.word(normal.upper(), g.num(bottom if g.absolute else bottom - r_plane)))
    if g.rng.random() < 0.7:
        words.append(g.word("R", g.num(r_plane if g.absolute else r_plane - level)))
    if code == "87" and g.rng.random() < 0.5:
        words += _back_bore_words(g, normal, bottom, r_plane)
    g.emit(g.words(*words))
    return first, second, normal


CYCLES: list[tuple[float, Callable[[Gen], None]]] = [*MOTION, (25, st_drill)]


PROBE: list[tuple[float, Callable[[Gen], None]]] = [
    *MOTION, (20, probing.st_probe), (3, probing.st_probe_grid)]
# Probes among offsets, rotations, G53 and homing: the probe's start is the canon's point.
PROBE_OFFSETS: list[tuple[float, Callable[[Gen], None]]] = [
    *OFFSETS, (15, probing.st_probe), (2, probing.st_probe_grid)]


def gen_probe(seed: int) -> str:
    table = PROBE if seed % 3 else PROBE_OFFSETS
    return text_of(_program("probe", seed, table, 3, 25).lines)


def gen_cycles(seed: int) -> str:
    return text_of(_program("cycles", seed, CYCLES, 3, 25).lines)


SPLINES: list[tuple[float, Callable[[Gen], None]]] = [*MOTION, *splines.STATEMENTS]


def gen_splines(seed: int) -> str:
    return text_of(_program("splines", seed, SPLINES, 5, 30).lines)


def gen_motion(seed: int) -> str:
    return text_of(_program("motion", seed, MOTION, 5, 40).lines)


def gen_offsets(seed: int) -> str:
    return text_of(_program("offsets", seed, OFFSETS, 5, 40).lines)


OFFSETS_INCH: list[tuple[float, Callable[[Gen], None]]] = [*OFFSETS, *inch.STATEMENTS]


def gen_offsets_inch(seed: int) -> str:
    """``offsets`` in G20 with five-decimal values (``inch.py``)."""
    g = Gen(seed, "offsets-inch")
    preamble(g)
    g.emit(g.words(g.set_units(False)))
    body(g, OFFSETS_INCH, g.rng.randint(5, 40))
    ending(g)
    return text_of(g.lines)


MIXED: list[tuple[float, Callable[[Gen], None]]] = [
    *MOTION, (30, st_mixed_line), (0.6, st_comp_contour), (0.4, st_tool_change),
    (0.3, st_tool_offset), (0.3, st_tool_params)]


def gen_mixed(seed: int) -> str:
    return text_of(_program("mixed", seed, MIXED, 5, 40).lines)


def gen_oword(seed: int) -> str:
    return text_of(_program("oword", seed, OWORD, 3, 14).lines)


# ---- failing: mutations -------------------------------------------------------------------------


def _pick(g: Gen, lines: list[str]) -> int:
    """A line index in the middle of the program (after the preamble, before the end)."""
    lo = min(3, len(lines) - 1)
    hi = max(lo, len(lines) - 2)
    return g.rng.randint(lo, hi)


def _insert(g: Gen, lines: list[str], text: str) -> None:
    lines.insert(_pick(g, lines), text)


def mu_unknown_code(g: Gen, lines: list[str]) -> None:
    _insert(g, lines, g.rng.choice(["G50", "M200", "G12", "G1.5", "G66", "M101 P1", "G17.5",
                                    "G0 X1 G150", "M1000", "G99.9"]))


def mu_modal_conflict(g: Gen, lines: list[str]) -> None:
    _insert(g, lines, g.rng.choice(["G0 G1 X1", "G90 G91", "G20 G21", "G17 G18", "M3 M4 S100",
                                    "G54 G55", "G93 G94", "G61 G64", "M7 M9", "G2 G3 X1 R1",
                                    "G90.1 G91.1", "M2 M30", "G52 G92 X1"]))


def mu_repeated_word(g: Gen, lines: list[str]) -> None:
    _insert(g, lines, g.rng.choice(["G1 X1 X2 F10", "G0 Y1 Y1", "F10 F20", "S100 S200 M3",
                                    "G1 Z1 F100 F100", "G4 P1 P2", "N10 N20 G0 X0"]))


def mu_orphan_word(g: Gen, lines: list[str]) -> None:
    _insert(g, lines, g.rng.choice(["I1", "G1 X1 J2 F100", "K3", "R5", "G0 X1 R2", "P3", "Q1",
                                    "L2", "G90 I5", "G1 X2 Q1 F10", "G0 X0 P1", "H1", "D1", "E1"]))


def mu_bad_arc(g: Gen, lines: list[str]) -> None:
    _insert(g, lines, g.rng.choice(["G2 X100 Y0 R1 F100", "G3 X10 I0 J0 F100", "G2 X1 Y1 F100",
                                    "G17 G2 X5 Y5 I1 J0 F100", "G19 G2 Y1 Z1 I1 F100",
                                    "G2 X50 R0 F100", "G18 G3 X1 Z1 J1 F10",
                                    "G2 X3 Y3 R2 P0 F100"]))


def mu_zero_feed(g: Gen, lines: list[str]) -> None:
    _insert(g, lines, g.rng.choice(["F0\nG1 X1", "G93 G1 X3", "G95 M5 S0\nG1 X2 F1",
                                    "F-10", "G1 X1 F0", "G93\nG2 X0 Y0 I1 J0"]))


def mu_g53_incremental(g: Gen, lines: list[str]) -> None:
    _insert(g, lines, g.rng.choice(["G91 G53 G0 X1", "G91\nG53 G1 X0 F10", "G53 X1",
                                    "G53 G2 X1 I1", "G91 G0 G53 Z0"]))


def mu_bad_number(g: Gen, lines: list[str]) -> None:
    choice = g.rng.choice(["G1 X1.2.3", "G0 X-", "F10 G", "G1 X1..2", "X+-1", "G0 X.", "G1 Y1e3",
                           "G0 X 1 2", "S-", "G0 X1 Y", "G1 X#", "N G0 X1", "G1 X--1 F10"])
    if g.rng.random() < 0.5:
        i = _pick(g, lines)
        lines[i] = lines[i] + " " + choice if not lines[i].lstrip().lower().startswith("o") \
            else lines[i]
        if lines[i].endswith(choice):
            return
    _insert(g, lines, choice)


def mu_bad_expression(g: Gen, lines: list[str]) -> None:
    _insert(g, lines, g.rng.choice(["#1 = [1 +]", "#1 = [2 * [3]", "G0 X[1 / 0]", "#2 = [1 MOD 0]",
                                    "G1 X[SQRT[-1]] F10", "#3 = LN[0]", "#3 = LN[-2]",
                                    "#4 = ASIN[2]", "#5 = ACOS[-1.5]", "G0 X[1 ** ]",
                                    "#6 = ATAN[1]", "#7 = FOO[1]", "#8 = [1 XOR]", "#9 = [1 2]",
                                    "#1 = #<undefined_name>", "G0 X#<nope>", "#<_g> = [#<_h> + 1]",
                                    "#10 = [[-8] ** 0.5]", "#0 = 1", "#5420 = 1", "#6000 = 1",
                                    "#[1/0] = 2", "G0 X[0 / [1 - 1]]", "#1 = [1 EQ]",
                                    "#1 = SIN 30", "G0 X[1]]"]))


def mu_unclosed(g: Gen, lines: list[str]) -> None:
    _insert(g, lines, g.rng.choice(["G0 X1 (comment", "(MSG, a (nested) comment)", "G0 X[1 + 2",
                                    "G1 X[[1] F10", "G0 X1 )", "(DEBUG,#<x",
                                    "(unclosed comment G0 X1"]))


def mu_control_char(g: Gen, lines: list[str]) -> None:
    ch = g.rng.choice(["\x01", "\x07", "\x1b", "\x7f", "\x02", "\x0c", "$", "!", '"', "'", "{",
                       "|", "~", "\x80", "\xe9", "?"])
    i = _pick(g, lines)
    line = lines[i]
    pos = g.rng.randint(0, len(line))
    lines[i] = line[:pos] + ch + line[pos:]


def mu_no_end(g: Gen, lines: list[str]) -> None:
    while lines and (lines[-1].strip() == "%" or "M2" in lines[-1].upper()
                     or "M30" in lines[-1].upper() or "M02" in lines[-1].upper()):
        lines.pop()
    if g.rng.random() < 0.3 and lines and lines[0] != "%":
        lines.append("%")


def mu_bad_g10(g: Gen, lines: list[str]) -> None:
    _insert(g, lines, g.rng.choice(["G10 L2 P10 X1", "G10 L5 P1 X1", "G10 L2 X1", "G10 L2 P-1 X0",
                                    "G10 L20 P1.5 X1", "G10 L2 P1 R45 G91",
                                    "G10 L2 P1 X1 G0", "G10 P1 X1", "G10 L2 P2 R", "G10 L3 P1"]))


def mu_bad_oword(g: Gen, lines: list[str]) -> None:
    _insert(g, lines, g.rng.choice(["o100 endwhile", "o<x> endsub", "o200 call", "o300 if [1]",
                                    "o<missing> call [1]", "o400 else", "o500 break", "o600 return",
                                    "o700 endif", "o800 repeat", "o[1/0] call", "o<a> sub",
                                    "o900 do", "o901 while [1] G1", "o902 foo"]))


def mu_bad_value(g: Gen, lines: list[str]) -> None:
    _insert(g, lines, g.rng.choice(["G4 P-1", "S-100 M3", "G1 X1 F-5", "M50 P-1", "G64 P-1",
                                    "G4", "G10 L2 P1 X1 R1 R2", "G28.1 X1", "G92 ", "G52",
                                    "G0 G28 X0", "G92.1 X1", "G4 P1 X1", "G61 P1", "M3 S1 G95 G1 X1",
                                    "G20 G1 X1 F0"]))


def mu_drop_word(g: Gen, lines: list[str]) -> None:
    """Remove one word from a line with an arc or move (often leaves an incomplete arc)."""
    i = _pick(g, lines)
    parts = lines[i].split()
    if len(parts) > 1:
        del parts[g.rng.randrange(len(parts))]
        lines[i] = " ".join(parts)


# Values that are infinite or not a number, or that hide one (rs274 checks each value it reads,
# not the operators inside a bracket, nor a function's argument).
NON_FINITE = ["EXP[710]", "[EXP[709]*10]", "[0**-1]", "[1 MOD 0]", "[EXP[709]*10*0]",
              "SIN[EXP[709]*10]", "FIX[EXP[709]*10]", "ROUND[EXP[709]*10]", "[10**400 GT 0]",
              "ABS[EXP[709]*10]", "[EXP[709]*10*0 LT 1]", "ATAN[EXP[709]*10]/[1]", "EXP[709]",
              "[2**2000 - 2**2000]", "FUP[-EXP[709]*10]", "[EXP[709.78]]"]


def mu_non_finite(g: Gen, lines: list[str]) -> None:
    v = g.rng.choice(NON_FINITE)
    _insert(g, lines, g.rng.choice([
        f"#1 = {v}", f"G0 X{v}", f"G1 X[{v} + 1] F10", f"#<nf> = [{v} GT 0]", f"G[{v}]",
        f"M[{v}]", f"o1 if [{v}]\no1 endif", f"o2 repeat [{v}]\nG0 X1\no2 endrepeat",
        f"o77 sub\n(debug,#1 %d #1)\no77 endsub\no77 call [{v}]", f"#2 = [{v} * 0]",
        f"G0 X[[{v}]]", f"#3 = EXISTS[#[{v}]]", f"G10 L2 P2 R{v}\nG0 X1"]))


def mu_read_order(g: Gen, lines: list[str]) -> None:
    """A value that fails and a read error on one line, in either order."""
    bad_value = g.rng.choice(["X[1/0]", "X#<nope>", "Y[SQRT[-1]]", "Z[EXP[710]]", "X[ACOS[2]]",
                              "#[1/0]=1", "#1=[1/0]", "X[[1/0] + SQRT[-1]]", "X[1 + 2/0 * LN[0]]"])
    bad_read = g.rng.choice(["G0 G1", "X2", "Y[1+", "M3 M4", "Q", "#5420=1", "G1.7", "#<_a>=1"])
    parts = [bad_value, bad_read] if g.rng.random() < 0.6 else [bad_read, bad_value]
    _insert(g, lines, " ".join(parts))


def mu_bad_cycle(g: Gen, lines: list[str]) -> None:
    _insert(g, lines, g.rng.choice([
        "G81 X1 Z-1", "G82 X1 Z-1 R1", "G81 X1 Z-1 R1 L0", "G81 X1 Z2 R1", "G93 G81 X1 Z-1 R1 F1",
        "G81 X1 A1 Z-1 R1", "G41.1 D1\nG81 X1 Z-1 R1", "G18 G81 X1 Y-1 R1", "G19 G85 Y1 X2 R1",
        "F0\nG81 X1 Z-1 R1", "G17.1 G81 X1 Z-1 R1", "G81 X1 Z-1 R1 L-2", "G89 X1 Z-1 R1 P",
        "G82 X2 Z-3 R1 P1\nG81 X3", "G81 X1 Z-1 R1\nG0 X2\nX3", "M3\nG74 X1 Z-1 R1",
        "M5\nG74 X1 Z-1 R1", "M4\nG91 G74 X1 Z-1 R1 L2", "M3\nG87 X1 Z-1 R1 I1 J1",
        "M3\nG87 X1 Z-1 R1 J1 K1", "M5\nG87 X1 Z-1 R1 I1 J1 K1", "G18 G87 X1 Y-1 R1 I1 K1",
        "M3\nG87 X1 Z-1 R1 I1 J1 K1\nG81 X2\nG87 X3 Z-1 R1"]))


MUTATIONS: list[tuple[float, Callable[[Gen, list[str]], None]]] = [
    (2, mu_bad_cycle),
    (2, splines.mu_bad_spline),
    (2, mu_non_finite),
    (2, mu_read_order),
    (3, mu_unknown_code),
    (3, mu_modal_conflict),
    (2, mu_repeated_word),
    (3, mu_orphan_word),
    (3, mu_bad_arc),
    (2, mu_zero_feed),
    (2, mu_g53_incremental),
    (3, mu_bad_number),
    (4, mu_bad_expression),
    (2, mu_unclosed),
    (2, mu_control_char),
    (1.5, mu_no_end),
    (2, mu_bad_g10),
    (2, mu_bad_oword),
    (2, mu_bad_value),
    (1.5, mu_drop_word),
    (1.5, probing.mu_probe),
]


def gen_failing(seed: int) -> str:
    g = Gen(seed, "failing")
    base_kind = g.rng.choice(["motion", "motion", "offsets", "mixed", "oword", "splines"])
    lines = KINDS[base_kind](g.rng.randrange(1 << 30)).split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    weights = [w for w, _ in MUTATIONS]
    fns = [f for _, f in MUTATIONS]
    for _ in range(1 if g.rng.random() < 0.8 else 2):
        g.rng.choices(fns, weights)[0](g, lines)
    return text_of("\n".join(lines).split("\n"))


def mutate_keeping_end(rng: random.Random, lines: list[str]) -> None:
    """One of the ``failing`` kind's mutations, other than losing the program's end."""
    g = Gen(rng.randrange(1 << 30), "failing")
    fns = [(w, f) for w, f in MUTATIONS if f is not mu_no_end]
    rng.choices([f for _, f in fns], [w for w, _ in fns])[0](g, lines)


def gen_continue(seed: int) -> str:
    return continued.gen_continue(seed, KINDS, mutate_keeping_end)


def text_of(lines: list[str]) -> str:
    return "".join(line + "\n" for line in lines)


KINDS: dict[str, Callable[[int], str]] = {
    "motion": gen_motion,
    "offsets": gen_offsets,
    "offsets-inch": gen_offsets_inch,
    "oword": gen_oword,
    "mixed": gen_mixed,
    "failing": gen_failing,
    "tools": gen_tools,
    "comp": gen_comp,
    "cycles": gen_cycles,
    "threading": spindlesync.gen_threading,
    "splines": gen_splines,
    "probe": gen_probe,
    "state": state.gen_state,
    "continue": gen_continue,
    "lathe": lathe.gen_lathe,
    "lathejob": lathejob.gen_lathejob,
    "flow": flow.gen_flow,
}


def generate(kind: str, seed: int) -> str:
    """The program of this kind for this seed (deterministic)."""
    return KINDS[kind](seed)


if __name__ == "__main__":
    import sys

    print(generate(sys.argv[1], int(sys.argv[2])), end="")
