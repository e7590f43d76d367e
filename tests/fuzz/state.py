"""The ``state`` kind: modal state saved and restored (M70-M73) in the main program, in o-word
subroutines and in Fanuc-style M98 subprograms, among changes of every mode M70 saves, digital and
analog outputs (M62-M68), and DEBUG lines that show the state back.

Every statement sets on its own line what it needs (a move is ``G0``, or ``G94 G1 ... F``), since
after a restore the generator no longer knows the modes.  M72 is written where something was saved
at that call level, now and then where nothing was (an error), and sometimes with more words after
it on its line (which rs274 drops when the restore ran anything).
"""

from __future__ import annotations

import random

MODES = [
    ["G17", "G18", "G19", "G17.1", "G18.1", "G19.1"],
    ["G20", "G21", "G21", "G21"],
    ["G90", "G91"],
    ["G90.1", "G91.1"],
    ["G93", "G94", "G94", "G95"],
    ["G54", "G55", "G56", "G59.1", "G59.3"],
    ["G43 H1", "G43 H2", "G43", "G43.1 Z0.5", "G43.2 H3", "G49", "G49"],
    ["G98", "G99"],
    ["G61", "G61.1", "G64", "G64 P0.01", "G64 P0.02 Q0.01", "G64 P0.123456789"],
    ["G7", "G8", "G8"],
    ["M3", "M4", "M5"],
    ["M7", "M8", "M9", "M9"],
    ["M48", "M49", "M50 P0", "M50 P1", "M51 P0", "M51", "M52 P1", "M52 P0", "M53 P0", "M53 P1"],
]
OUTPUTS = ["M62 P{p}", "M63 P{p}", "M64 P{p}", "M65 P{p}", "M67 E{p} Q{q}", "M68 E{p} Q{q}",
           "M66 P{p} L0", "M66 E{p} L0", "M66 P{p} L{l} Q{q}", "M66 E{p} L0 Q0"]
DUMP = ("(debug, m#<_metric> p#<_plane> a#<_absolute> i#<_ijk_absolute_mode> "
        "f#<_inverse_time>#<_units_per_minute>#<_units_per_rev> cs#<_coord_system> "
        "t#<_tool_offset> r#<_retract_r_plane> d#<_lathe_diameter_mode> c#<_ccomp>)")
DUMP2 = ("(debug, s#<_spindle_on>#<_spindle_cw> mi#<_mist> fl#<_flood> so#<_speed_override> "
         "fo#<_feed_override> af#<_adaptive_feed> fh#<_feed_hold> F#<_feed> S#<_rpm> "
         "in#5399)")


class StateGen:
    """Random source, the lines, and which call levels have something saved."""

    def __init__(self, seed: int) -> None:
        self.rng = random.Random(f"state:{seed}")
        self.lines: list[str] = []
        self.saved = [False]  # per call level being written: M70/M73 ran there
        self.subs: list[str] = []
        self.fanuc: list[int] = []
        self.numbered = self.rng.random() < 0.2
        self.n = 0

    def emit(self, text: str) -> None:
        if self.numbered and not text.lower().startswith("o") and self.rng.random() < 0.5:
            self.n += 10
            text = f"N{self.n} {text}"
        self.lines.append(text)

    def num(self, lo: float, hi: float, places: int = 3) -> str:
        return f"{round(self.rng.uniform(lo, hi), places):g}"


def st_modes(g: StateGen) -> None:
    picks = g.rng.sample(MODES, g.rng.randint(1, 4))
    words = [g.rng.choice(p) for p in picks]
    if g.rng.random() < 0.4:
        words.append("F" + g.num(1, 500, g.rng.choice([0, 1, 2, 4])))
    if g.rng.random() < 0.3:
        words.append("S" + g.num(0, 5000, g.rng.choice([0, 1, 3])))
    coolant = [w for w in words if w in ("M7", "M8", "M9")]
    if len(coolant) > 1:
        words = [w for w in words if w not in coolant[1:]]
    g.rng.shuffle(words)
    g.emit(" ".join(words))


def st_save(g: StateGen) -> None:
    r = g.rng.random()
    if r < 0.45:
        g.emit(g.rng.choice(["M70", "M73", "M70 (save)", "M73 (save, restore on return)"]))
        g.saved[-1] = True
    elif r < 0.55:
        g.emit("M71")
        g.saved[-1] = False
    elif g.saved[-1] or g.rng.random() < 0.03:
        rest = g.rng.choice(["", "", "", " G91", " M8", " G0 X1", " (restore)", " F7 G18",
                             " G91 G0 X2 M9", " S100"])
        g.emit("M72" + rest)


def st_move(g: StateGen) -> None:
    axes = g.rng.sample("XYZ", g.rng.randint(1, 3))
    words = " ".join(f"{a}{g.num(-20, 20)}" for a in axes)
    if g.rng.random() < 0.5:
        g.emit(f"G90 G0 {words}")
    else:
        g.emit(f"G94 G1 {words} F{g.num(10, 900, 1)}")


def st_output(g: StateGen) -> None:
    text = g.rng.choice(OUTPUTS).format(p=g.rng.randint(0, 3), q=g.num(-10, 10, 2),
                                        l=g.rng.randint(0, 4))
    g.emit(text)


def st_comp(g: StateGen) -> None:
    """Cutter radius compensation on (tool 0 or a D word) or off: a restore with it on may be
    refused (rs274 says so with the restore's line)."""
    g.emit(g.rng.choice(["G40", "G40", "G17 G40 G41", "G17 G42", "G40 G18 G41.1 D0.2", "G40"]))


def st_dump(g: StateGen) -> None:
    g.emit(g.rng.choice([DUMP, DUMP2]))


def st_comment(g: StateGen) -> None:
    g.emit(g.rng.choice(["(note)", "(MSG, state)", "G4 P0.5"]))


def st_call(g: StateGen) -> None:
    if g.subs and g.rng.random() < 0.7:
        args = " ".join(f"[{g.rng.randint(0, 2)}]" for _ in range(g.rng.randint(0, 2)))
        g.emit(f"o<{g.rng.choice(g.subs)}> call {args}".rstrip())
    elif g.fanuc:
        loops = g.rng.choice(["", "", " L2"])
        g.emit(f"M98 P{g.rng.choice(g.fanuc)}{loops}")


STATEMENTS = [(4, st_modes), (4, st_save), (2, st_move), (1.5, st_dump), (0.5, st_comment), (0.4, st_comp),
              (1.2, st_output)]


def _body(g: StateGen, count: int, calls: bool) -> None:
    table = STATEMENTS + ([(2.5, st_call)] if calls else [])
    weights = [w for w, _ in table]
    fns = [f for _, f in table]
    for _ in range(count):
        g.rng.choices(fns, weights)[0](g)


def _sub(g: StateGen, name: str) -> None:
    """An o-word subroutine: M73 or M70 early (mostly), changes, maybe a conditional return."""
    g.lines.append(f"o<{name}> sub")
    g.saved.append(False)
    if g.rng.random() < 0.6:
        g.emit(g.rng.choice(["M73", "M73", "M70"]))
        g.saved[-1] = True
    _body(g, g.rng.randint(1, 6), calls=True)
    if g.rng.random() < 0.4:
        g.lines.append(f"o<{name}r> if [#1 GT 0]")
        _body(g, g.rng.randint(0, 2), calls=False)
        g.lines.append(f"o<{name}> return")
        g.lines.append(f"o<{name}r> endif")
        _body(g, g.rng.randint(0, 3), calls=False)
    g.saved.pop()
    g.lines.append(f"o<{name}> endsub")
    g.subs.append(name)


def _fanuc(g: StateGen, number: int) -> list[str]:
    """A Fanuc-style subprogram (after the main program's end)."""
    keep = g.lines
    g.lines = [f"O{number}"]
    g.saved.append(False)
    if g.rng.random() < 0.6:
        g.emit("M73")
        g.saved[-1] = True
    _body(g, g.rng.randint(1, 5), calls=False)
    g.saved.pop()
    g.lines.append("M99")
    lines, g.lines = g.lines, keep
    return lines


def gen_state(seed: int) -> str:
    g = StateGen(seed)
    g.lines.append("G10 L2 P2 X1 Y2 Z0.5 R5")
    g.lines.append("G10 L2 P3 X-3")
    g.lines.append("G10 L2 P7 Y4 R-10")
    g.lines.append("G10 L2 P9 X2 Z-1")
    tail: list[str] = []
    if g.rng.random() < 0.35:
        for number in range(100, 100 + g.rng.randint(1, 2)):
            tail += _fanuc(g, number)
            g.fanuc.append(number)
    for i in range(g.rng.randint(0, 3)):
        _sub(g, f"s{i}")
    _body(g, g.rng.randint(4, 25), calls=True)
    g.emit(g.rng.choice([DUMP, DUMP2]))
    g.lines.append(g.rng.choice(["M2", "M30"]))
    return "".join(line + "\n" for line in g.lines + tail)
