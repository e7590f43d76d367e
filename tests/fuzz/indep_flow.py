#!/usr/bin/env python3
"""Control-flow programs written the way people write macros, from a small weighted grammar.

Unlike gen.py's templates this draws each program from a grammar whose productions recurse with
weights that fall with depth, and dresses the result in one of several hand-writing styles:

    program  := header  subdef*  statement*  footer
    subdef   := 'o<name> sub' | 'oNNN sub'  body  ('endsub' | 'endsub [expr]')
    statement:= move | arc | assign | message | call | if | while | do | repeat
                | break | continue | return | comment
    if       := 'if [cond]' body ('elseif [cond]' body)* ['else' body] 'endif'

Shapes that shop macros have: bolt circles stepped by a while loop over a named counter,
probing-like search loops that break when a "contact" is found, pecking with do/while, grids
of repeat loops, recursive subroutines with a depth guard, subroutines that ``return [value]``
read back through ``#<_value>`` and ``#<_value_returned>``.  Break and continue reach any
enclosing loop of the same scope, at any depth of if/loop nesting; returns leave loops from
inside subroutines.  Styles: upper, lower or mixed case keywords, spaces inside words
(``G 1 X 1.0``, ``o100 repeat [3]``), indentation, comments between lines, numbered and
named labels.  About one program in ten is deliberately wrong (a label that does not match, a
break outside a loop, a sub called before it is defined or never defined, a return in the main
program, a nested sub definition, an elseif after else, ...).

    python tests/fuzz/indep_flow.py SEED                     # print one program
    python tests/fuzz/indep_flow.py --batch --seed 1 --count 500 [--jobs 2] [--shrink]

The batch mode runs rs274 and ngc through run.py's runner and compares them the same way.
"""

from __future__ import annotations

import argparse
import random
import sys
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

HERE = Path(__file__).resolve().parent
if str(HERE) not in sys.path:
    sys.path.insert(0, str(HERE))

WRONG_SHARE = 0.10
MAX_DEPTH = 4
WORK_CAP = 400  # product of enclosing loop counts (and call fan-out) kept below this


# ---- style ----------------------------------------------------------------------------------


@dataclass
class Style:
    """How the programmer writes: case of keywords, spacing, indentation, comments."""

    case: str  # "lower", "upper", "mixed", "title"
    spaces: float  # chance of a space inside a word
    indent: str
    chatter: float  # chance of a comment line before a statement
    numbered_lines: bool
    rng: random.Random

    def kw(self, word: str) -> str:
        if self.case == "upper":
            return word.upper()
        if self.case == "title":
            return word.capitalize()
        if self.case == "mixed":
            return "".join(c.upper() if self.rng.random() < 0.5 else c for c in word)
        return word

    def letter(self, ch: str) -> str:
        return ch.lower() if self.case == "lower" and self.rng.random() < 0.6 else ch

    def word(self, letter: str, value: str) -> str:
        sep = " " if self.rng.random() < self.spaces else ""
        return f"{self.letter(letter)}{sep}{value}"

    def space(self) -> str:
        return " " if self.rng.random() < self.spaces else ""


# ---- scopes ---------------------------------------------------------------------------------


@dataclass
class Loop:
    label: str
    kind: str  # "while", "do", "repeat"


@dataclass
class Scope:
    """A subroutine body or the main program: its labels, loops and readable parameters."""

    sub: str | None  # the sub's label, None for the main program
    nargs: int = 0
    used: set[str] = field(default_factory=set)
    loops: list[Loop] = field(default_factory=list)
    readable: list[str] = field(default_factory=list)
    counters: set[str] = field(default_factory=set)
    counter_no: int = 0


SUB_NAMES = ["probe_x", "bolt", "peck", "pocket", "face", "spot", "helper", "ring", "corner",
             "step_over", "macro7", "zig"]
LOCAL_NAMES = ["count", "n", "dx", "step", "ang", "r", "depth", "acc", "flag", "hit", "k",
               "tmp", "z_top"]
GLOBAL_NAMES = ["_total", "_passes", "_found", "_gsum", "_last"]


class Gen:
    def __init__(self, seed: int) -> None:
        self.rng = random.Random(f"indep-flow-{seed}")
        r = self.rng
        self.style = Style(
            case=r.choice(["lower", "lower", "upper", "mixed", "title"]),
            spaces=r.choice([0.0, 0.0, 0.15, 0.5]),
            indent=r.choice(["", "  ", "    ", "\t"]),
            chatter=r.choice([0.0, 0.08, 0.2]),
            numbered_lines=r.random() < 0.15,
            rng=r,
        )
        self.lines: list[str] = []
        self.level = 0
        self.subs: list[tuple[str, int]] = []  # defined subs: label, number of args it reads
        self.globals: list[str] = []
        self.work = 1
        self.next_n = 10
        self.scope = Scope(None)

    # -- output --
    def emit(self, text: str) -> None:
        prefix = ""
        if self.style.numbered_lines and not text.lstrip().lower().startswith(("o", "%")):
            prefix = f"N{self.next_n} "
            self.next_n += 10
        self.lines.append(self.style.indent * self.level + prefix + text)

    def chatter(self) -> None:
        if self.rng.random() < self.style.chatter:
            self.emit(self.rng.choice(["(next)", "(--- step ---)", "; keep going",
                                       "(TODO check depth)", "(cut)", "( )"]))

    def o(self, label: str, keyword: str, tail: str = "") -> str:
        s = self.style
        r = self.rng
        if s.spaces and r.random() < s.spaces:
            # spaces are not part of a line's words: 'o 1 00 while', 'o100while[...]'
            if label.isdigit() and len(label) > 1 and r.random() < 0.5:
                cut = r.randint(1, len(label) - 1)
                label = f"{label[:cut]} {label[cut:]}"
            elif label.startswith("<") and r.random() < 0.3:
                label = f"<{label[1:2].upper()}{label[2:-1]}>"
            sep = r.choice(["", " ", "  "])
            text = f"{s.letter('o')}{r.choice(['', ' '])}{label}{sep}{s.kw(keyword)}"
            return f"{text}{r.choice(['', ' '])}{tail}" if tail else text
        text = f"{s.letter('o')}{label} {s.kw(keyword)}"
        return f"{text} {tail}" if tail else text

    # -- numbers and expressions --
    def num(self, lo: float = -5.0, hi: float = 5.0, places: int | None = None) -> str:
        p = places if places is not None else self.rng.choice([0, 1, 2, 3, 4])
        v = round(self.rng.uniform(lo, hi), p)
        text = f"{v:.{p}f}"
        if p and self.rng.random() < 0.3:
            text = text.rstrip("0").rstrip(".") or "0"
        if text.startswith("-0") and float(text) == 0:
            text = "0"
        return text

    def atom(self) -> str:
        r = self.rng
        if self.scope.readable and r.random() < 0.55:
            return self.spell(r.choice(self.scope.readable))
        return self.num(-4, 9)

    def spell(self, name: str) -> str:
        """A named parameter as a person may type it again: other case, a space inside."""
        r = self.rng
        if not name.startswith("#<") or r.random() > 0.15:
            return name
        inner = name[2:-1]
        if r.random() < 0.5:
            inner = inner.upper() if r.random() < 0.5 else inner.capitalize()
        elif len(inner) > 2:
            cut = r.randint(1, len(inner) - 1)
            inner = f"{inner[:cut]} {inner[cut:]}"
        return f"#<{inner}>"

    def expr(self, depth: int = 0) -> str:
        r = self.rng
        roll = r.random()
        if depth > 2 or roll < 0.35:
            return self.atom()
        if roll < 0.7:
            op = r.choice(["+", "-", "*", "+", "-", "*", "/"])
            right = self.num(1, 4) if op == "/" else self.expr(depth + 1)
            kw = self.style.kw
            if op == "*" and r.random() < 0.1:
                op = kw("MOD")
                right = self.num(1, 4, 0)
            return f"[{self.expr(depth + 1)} {op} {right}]"
        fn = r.choice(["SIN", "COS", "ABS", "FIX", "FUP", "ROUND", "SQRT", "ATAN"])
        kwfn = self.style.kw(fn)
        if fn == "SQRT":
            return f"{kwfn}[ABS[{self.expr(depth + 1)}]]".replace("ABS", self.style.kw("ABS"))
        if fn == "ATAN":
            return f"{kwfn}[{self.expr(depth + 1)}]/[{self.num(1, 3)}]"
        return f"{kwfn}[{self.expr(depth + 1)}]"

    def cond(self) -> str:
        r = self.rng
        kw = self.style.kw
        op = kw(r.choice(["LT", "LE", "GT", "GE", "EQ", "NE"]))
        c = f"[{self.expr(1)} {op} {self.expr(1)}]"
        if r.random() < 0.15:
            c = f"[{c} {kw(r.choice(['AND', 'OR', 'XOR']))} [{self.atom()} GT {self.num(-2, 3)}]]"
        elif r.random() < 0.08 and any(p.startswith("#<") for p in self.scope.readable):
            name = r.choice([p for p in self.scope.readable if p.startswith("#<")])
            c = f"[{kw('EXISTS')}[{name}]]"
        return c

    # -- labels and parameters --
    def label(self, hint: str) -> str:
        r = self.rng
        while True:
            if r.random() < 0.2:
                lab = f"<{hint}{r.randint(1, 99)}>"
            elif r.random() < 0.4:
                # the same few numbers in every sub, as people number their blocks
                lab = str(r.choice([100, 110, 120, 130, 200, 1, 2, 3]))
            else:
                lab = str(r.choice([r.randint(1, 999), 100 * r.randint(1, 9) + 10 * r.randint(0, 9)]))
            key = lab.lower()
            if key not in self.scope.used and key not in {s.lower() for s, _ in self.subs}:
                self.scope.used.add(key)
                return lab

    def counter(self) -> str:
        """A fresh loop counter: a numbered parameter above #30 or a named one."""
        self.scope.counter_no += 1
        if self.scope.sub is None and self.rng.random() < 0.4:
            name = f"#{100 + self.scope.counter_no + 20 * self.level}"
        elif self.rng.random() < 0.5:
            name = f"#<i{self.scope.counter_no}>"
        else:
            base = self.rng.choice(["count", "n", "k", "idx"])
            name = f"#<{base}{self.scope.counter_no}>"
        self.scope.counters.add(name)
        return name

    def local_name(self) -> str:
        names = [f"#<{n}>" for n in LOCAL_NAMES if f"#<{n}>" not in self.scope.counters]
        return self.rng.choice(names)

    def assign(self, name: str, value: str) -> None:
        s = self.style
        eq = f"{s.space()}={s.space()}"
        self.emit(f"{name}{eq}{value}")
        if name not in self.scope.readable:
            self.scope.readable.append(name)

    # -- statements --
    def body(self, depth: int, size: int) -> None:
        for _ in range(size):
            self.statement(depth)

    def statement(self, depth: int) -> None:
        r = self.rng
        self.chatter()
        loops = self.scope.loops
        deep = depth >= MAX_DEPTH or self.work > WORK_CAP
        choices: list[tuple[float, Callable[[int], None]]] = [
            (3, self.s_move), (1.5, self.s_arc), (3, self.s_assign), (2, self.s_message),
            (0 if deep else 2.5 / (1 + depth), self.s_if),
            (0 if deep else 2 / (1 + depth), self.s_while),
            (0 if deep else 1.5 / (1 + depth), self.s_do),
            (0 if deep else 1.5 / (1 + depth), self.s_repeat),
            (2 if self.subs and self.work < WORK_CAP else 0, self.s_call),
            (2 if loops else 0, self.s_jump),
            (0.8 if self.scope.sub is not None else 0, self.s_return),
        ]
        total = sum(w for w, _ in choices)
        x = r.uniform(0, total)
        for w, f in choices:
            x -= w
            if x <= 0:
                f(depth)
                return
        choices[0][1](depth)

    def s_move(self, depth: int) -> None:
        s = self.style
        r = self.rng
        g = r.choice(["0", "1", "1", "1"])
        words = [s.word("G", g)]
        for axis in r.sample(["X", "Y", "Z"], r.randint(1, 3)):
            v = self.expr(1) if r.random() < 0.5 else self.num(-20, 20)
            words.append(s.word(axis, v))
        if g == "1" and r.random() < 0.3:
            words.append(s.word("F", self.num(50, 900, 0)))
        self.emit(" ".join(words))

    def s_arc(self, depth: int) -> None:
        s = self.style
        r = self.rng
        g = r.choice(["2", "3"])
        rad = self.num(0.5, 5, r.choice([1, 2, 3]))
        if r.random() < 0.5:
            self.emit(" ".join([s.word("G", g), s.word("I", rad), s.word("J", "0")]))
        else:
            self.emit(f"{s.word('G', '91')} {s.word('G', g)} {s.word('X', f'[2*{rad}]')} "
                      f"{s.word('I', rad)} {s.word('J', '0')}")
            self.emit(s.word("G", "90"))

    def s_assign(self, depth: int) -> None:
        r = self.rng
        roll = r.random()
        if roll < 0.35:
            name = self.local_name()
        elif roll < 0.55:
            name = f"#<{r.choice(GLOBAL_NAMES)}>"
        elif roll < 0.75 and self.scope.readable:
            name = r.choice(self.scope.readable)
            if name.startswith("#<_value") or name in self.scope.counters:
                name = f"#{r.randint(31, 60)}"
        else:
            low = self.scope.sub is not None or r.random() < 0.25
            name = f"#{r.randint(1, 30) if low else r.randint(31, 99)}"
        if r.random() < 0.3 and name in self.scope.readable:
            self.assign(name, f"[{name} + {self.num(0.5, 3, 1)}]")
        else:
            self.assign(name, self.expr())

    def s_message(self, depth: int) -> None:
        r = self.rng
        kind = r.choice(["debug", "debug", "print", "print", "msg", "DEBUG", "Print"])
        sep = r.choice([",", ", ", ",  "])
        parts = [r.choice(["i=", "pass", "val", "at", "x:", "", "loop", "hit"])]
        for _ in range(r.randint(0, 3)):
            if self.scope.readable and r.random() < 0.8:
                parts.append(r.choice(self.scope.readable))
            elif r.random() < 0.2:
                # text that only looks like a parameter
                parts.append(r.choice(["#", "##1", "#[1+1]", "#1.5", "#<>", "#<_value>x", "[#1]"]))
            else:
                parts.append(r.choice(["ok", "=", "/", "end"]))
        text = " ".join(p for p in parts if p)
        if kind.lower() == "msg":
            text = text.replace("#", "")
        self.emit(f"({kind}{sep}{text})")

    def s_if(self, depth: int) -> None:
        r = self.rng
        lab = self.label("if")
        self.emit(self.o(lab, "if", self.cond()))
        self.nested(lambda: self.body(depth + 1, r.randint(1, 3)))
        for _ in range(r.choice([0, 0, 1, 1, 2, 3])):
            cond = self.cond()
            if r.random() < 0.08:
                # a condition that cannot be evaluated: is it read after a branch ran?
                cond = r.choice(["[#<never_set> GT 0]", "[1 / [2 - 2] GT 0]",
                                 "[SQRT[-4] GT 0]", "[#<_unset_global> EQ 1]"])
            self.emit(self.o(lab, "elseif", cond))
            self.nested(lambda: self.body(depth + 1, r.randint(0, 2)))
        if r.random() < 0.45:
            self.emit(self.o(lab, "else"))
            self.nested(lambda: self.body(depth + 1, r.randint(0, 2)))
        self.emit(self.o(lab, "endif"))

    def nested(self, fn: Callable[[], None]) -> None:
        """A body that may not run: what it assigns is not known to be set after it."""
        self.level += 1
        saved = list(self.scope.readable)
        try:
            fn()
        finally:
            self.level -= 1
            self.scope.readable = saved

    def loop_body(self, depth: int, loop: Loop, count: int, head: Callable[[], None]) -> None:
        self.scope.loops.append(loop)
        saved = self.work
        self.work *= max(count, 1)

        def inside() -> None:
            head()
            self.body(depth + 1, self.rng.randint(1, 3))

        self.nested(inside)
        self.work = saved
        self.scope.loops.pop()

    def s_while(self, depth: int) -> None:
        r = self.rng
        lab = self.label("w")
        c = self.counter()
        n = r.randint(0, 4)
        start = r.choice([0, 1])
        self.assign(c, str(start))
        bound = f"[{c} {self.style.kw(r.choice(['LT', 'LE']))} {n}]"
        self.emit(self.o(lab, "while", bound))

        def head() -> None:
            self.assign(c, f"[{c} + 1]")

        self.loop_body(depth, Loop(lab, "while"), n + 1, head)
        self.emit(self.o(lab, "endwhile"))

    def s_do(self, depth: int) -> None:
        r = self.rng
        lab = self.label("d")
        c = self.counter()
        n = r.randint(0, 4)
        self.assign(c, "0")
        self.emit(self.o(lab, "do"))

        def head() -> None:
            self.assign(c, f"[{c} + 1]")

        self.loop_body(depth, Loop(lab, "do"), n + 1, head)
        self.emit(self.o(lab, "while", f"[{c} {self.style.kw('LT')} {n}]"))

    def s_repeat(self, depth: int) -> None:
        r = self.rng
        lab = self.label("r")
        n = r.choice(["0", "1", "2", "3", "[1+1]", "2.0"])
        self.emit(self.o(lab, "repeat", f"[{n}]" if not n.startswith("[") else n))
        self.loop_body(depth, Loop(lab, "repeat"), 3, lambda: None)
        self.emit(self.o(lab, "endrepeat"))

    def s_jump(self, depth: int) -> None:
        r = self.rng
        loops = self.scope.loops
        target = loops[-1] if r.random() < 0.75 else r.choice(loops)
        if target.kind == "repeat" and r.random() < 0.85:
            return self.s_message(depth)
        word = r.choice(["break", "continue"])
        if r.random() < 0.7:
            lab = self.label("g")
            self.emit(self.o(lab, "if", self.cond()))
            self.nested(lambda: self.emit(self.o(target.label, word)))
            self.emit(self.o(lab, "endif"))
        else:
            self.emit(self.o(target.label, word))
        return None

    def s_return(self, depth: int) -> None:
        r = self.rng
        assert self.scope.sub is not None
        tail = f"[{self.expr(1)}]" if r.random() < 0.6 else ""
        if r.random() < 0.7:
            lab = self.label("q")
            self.emit(self.o(lab, "if", self.cond()))
            self.nested(lambda: self.emit(self.o(self.scope.sub or "", "return", tail)))
            self.emit(self.o(lab, "endif"))
        else:
            self.emit(self.o(self.scope.sub, "return", tail))

    def s_call(self, depth: int) -> None:
        r = self.rng
        lab, nargs = r.choice(self.subs)
        args = [f"[{self.expr(1)}]" for _ in range(r.randint(max(0, nargs - 1), nargs + 1))]
        sep = r.choice([" ", "", " "])
        if lab.isdigit() and r.random() < 0.3:
            # indirection: the number computed (o-code.adoc, Indirection)
            base = r.randint(1, int(lab))
            self.emit(f"#<sub_no> = {base}")
            lab = f"[#<sub_no> + {int(lab) - base}]"
        self.emit(self.o(lab, "call", sep.join(args)))
        self.work *= 2
        if r.random() < 0.6:
            kind = r.choice(["debug", "print"])
            self.emit(f"({kind}, ret #<_value> #<_value_returned>)")
            if r.random() < 0.5:
                self.assign(self.local_name(), "#<_value>")

    # -- subroutines and shapes --
    def subdef(self) -> None:
        r = self.rng
        if r.random() < 0.6:
            name = r.choice(SUB_NAMES)
            if any(s.lower() == f"<{name}>" for s, _ in self.subs):
                name = f"{name}{len(self.subs)}"
            lab = f"<{name}>"
        else:
            lab = str(r.choice([100, 200, 300, 500, 1000, 9001]) + len(self.subs))
        nargs = r.randint(0, 3)
        outer = self.scope
        seen = [f"#{i + 1}" for i in range(nargs + (1 if r.random() < 0.3 else 0))]
        self.scope = Scope(lab, nargs, readable=seen + self.globals)
        self.emit(self.o(lab, "sub"))
        self.level += 1
        saved = self.work
        shape = r.random()
        if shape < 0.15 and nargs >= 1:
            self.recursive_body(lab)
        elif shape < 0.3:
            self.bolt_circle()
        elif shape < 0.42:
            self.probe_search(lab)
        else:
            self.body(1, r.randint(1, 4))
        self.work = saved
        self.level -= 1
        end_tail = f"[{self.expr(1)}]" if r.random() < 0.4 else ""
        self.emit(self.o(lab, "endsub", end_tail))
        self.scope = outer
        self.subs.append((lab, nargs))

    def recursive_body(self, lab: str) -> None:
        kw = self.style.kw
        g = self.label("rec")
        self.emit("(debug, depth #1)")
        self.assign("#<acc>", "0")
        self.emit(self.o(g, "if", f"[#1 {kw('GT')} 0]"))
        self.level += 1
        self.emit(self.o(lab, "call", "[#1 - 1]"))
        self.assign("#<acc>", "[#<_value> + #1]")
        self.emit(self.o(lab, "return", "[#<acc>]"))
        self.level -= 1
        self.emit(self.o(g, "endif"))
        self.s_move(1)

    def bolt_circle(self) -> None:
        r = self.rng
        kw = self.style.kw
        n = r.randint(2, 6)
        lab = self.label("bc")
        self.assign("#<n>", "0")
        self.assign("#<holes>", str(n))
        self.scope.counters.update(("#<n>", "#<holes>"))
        self.emit(self.o(lab, "while", f"[#<n> {kw('LT')} #<holes>]"))
        self.level += 1
        self.assign("#<ang>", "[360 / #<holes> * #<n>]")
        self.assign("#<n>", "[#<n> + 1]")
        self.scope.loops.append(Loop(lab, "while"))
        self.work *= n
        self.emit(f"G0 X[{kw('COS')}[#<ang>] * {self.num(1, 4, 1)}] "
                  f"Y[{kw('SIN')}[#<ang>] * {self.num(1, 4, 1)}]")
        self.body(2, r.randint(0, 2))
        self.scope.loops.pop()
        self.level -= 1
        self.emit(self.o(lab, "endwhile"))

    def probe_search(self, lab: str) -> None:
        r = self.rng
        kw = self.style.kw
        loop = self.label("p")
        self.assign("#<z>", "0")
        self.scope.counters.add("#<z>")
        self.assign("#<_found>", "0")
        self.emit(self.o(loop, "do"))
        self.level += 1
        self.assign("#<z>", f"[#<z> - {self.num(0.1, 0.9, 2)}]")
        self.emit(f"G1 Z#<z> F{self.num(20, 200, 0)}")
        g = self.label("c")
        self.emit(self.o(g, "if", f"[#<z> {kw('LT')} {self.num(-3, -0.5, 1)}]"))
        self.level += 1
        self.assign("#<_found>", "1")
        self.emit(self.o(r.choice([loop, loop, lab]), r.choice(["break", "break", "return"])
                         if lab.startswith("<") else "break"))
        self.level -= 1
        self.emit(self.o(g, "endif"))
        self.level -= 1
        self.emit(self.o(loop, "while", f"[#<z> {kw('GT')} -5]"))
        self.emit("(debug, found #<_found> at #<z>)")

    # -- the program --
    def program(self) -> str:
        r = self.rng
        s = self.style
        if r.random() < 0.3:
            self.emit("%")
        self.emit(r.choice(["(macro test)", "(PROGRAM 1001)", "; generated", "(bolt pattern)"]))
        self.emit(" ".join([s.word("G", "21"), s.word("G", "17"), s.word("G", "90"),
                            s.word("G", "40")] if r.random() < 0.7 else [s.word("G", "21")]))
        if r.random() < 0.95:
            self.emit(f"{s.word('F', self.num(100, 800, 0))}")
        for name in r.sample(GLOBAL_NAMES, r.randint(0, 2)):
            self.assign(f"#<{name}>", self.num(0, 5))
            self.globals.append(f"#<{name}>")
        for _ in range(r.choice([0, 1, 1, 2, 3])):
            self.subdef()
        self.scope.readable.extend(g for g in self.globals if g not in self.scope.readable)
        if r.random() < 0.5:
            self.assign(f"#<{r.choice(LOCAL_NAMES)}>", self.num(0, 4))
        self.body(0, r.randint(2, 6))
        if r.random() < 0.3:
            # a sub defined in the middle of the main program, then used
            self.subdef()
            self.body(0, r.randint(1, 4))
        if r.random() < 0.5:
            self.emit("(print, total #<_total>)" if "#<_total>" in self.globals
                      else "(print, done)")
        end = r.choice(["M2", "M30", "m2", "M02"])
        self.emit(end)
        if self.lines[0] == "%":
            self.emit("%")
        return "\n".join(self.lines) + "\n"


# ---- deliberate mistakes --------------------------------------------------------------------


def _o_lines(lines: list[str], keyword: str) -> list[int]:
    out = []
    for i, line in enumerate(lines):
        toks = line.strip().lower().split()
        if len(toks) >= 2 and toks[0].startswith("o") and toks[1] == keyword:
            out.append(i)
    return out


def _relabel(line: str, new: str) -> str:
    lead = line[: len(line) - len(line.lstrip())]
    toks = line.strip().split(None, 1)
    return f"{lead}o{new} {toks[1]}" if len(toks) > 1 else line


def spoil(text: str, rng: random.Random) -> str:
    """One mistake a person makes with o-words."""
    lines = text.rstrip("\n").split("\n")
    end = max(i for i, ln in enumerate(lines) if ln.strip().upper().split()[-1:] in
              (["M2"], ["M30"], ["M02"]))
    kinds = ["relabel_end", "drop_end", "break_outside", "undefined", "return_main", "nested_sub",
             "elseif_after_else", "continue_if", "call_before", "no_endsub", "repeat_dup",
             "endwhile_do", "stray_else", "break_to_caller", "redefine", "many_args"]
    for _ in range(20):
        kind = rng.choice(kinds)
        if kind == "relabel_end":
            ix = _o_lines(lines, "endif") + _o_lines(lines, "endwhile") + _o_lines(lines, "endrepeat")
            if ix:
                i = rng.choice(ix)
                lines[i] = _relabel(lines[i], str(rng.randint(1000, 1999)))
                break
        elif kind == "drop_end":
            ix = _o_lines(lines, "endif") + _o_lines(lines, "endwhile") + _o_lines(lines, "endsub")
            if ix:
                del lines[rng.choice(ix)]
                break
        elif kind == "break_outside":
            lines.insert(rng.randint(1, end), rng.choice(["o77 break", "o77 continue"]))
            break
        elif kind == "undefined":
            lines.insert(rng.randint(1, end), rng.choice(["o<nosuch> call [1]", "o4321 call"]))
            break
        elif kind == "return_main":
            lines.insert(rng.randint(1, end), rng.choice(["o<main> return", "o9 endsub"]))
            break
        elif kind == "nested_sub":
            ix = _o_lines(lines, "sub")
            if ix:
                i = rng.choice(ix) + 1
                lines[i:i] = ["o<inner> sub", "G0 X1", "o<inner> endsub"]
                break
        elif kind == "elseif_after_else":
            ix = _o_lines(lines, "else")
            if ix:
                i = rng.choice(ix)
                lab = lines[i].strip().split()[0]
                lines.insert(i + 1, f"{lab} elseif [1 GT 0]")
                break
        elif kind == "continue_if":
            ix = _o_lines(lines, "if")
            if ix:
                i = rng.choice(ix)
                lab = lines[i].strip().split()[0]
                lines.insert(i + 1, f"{lab} {rng.choice(['continue', 'break'])}")
                break
        elif kind == "call_before":
            calls = _o_lines(lines, "call")
            subs = _o_lines(lines, "sub")
            if calls and subs:
                i = rng.choice(calls)
                lines.insert(subs[0], lines[i].strip())
                break
        elif kind == "no_endsub":
            ix = _o_lines(lines, "endsub")
            if ix:
                i = rng.choice(ix)
                lines[i] = "(" + lines[i].strip() + " forgotten)"
                break
        elif kind == "repeat_dup":
            ix = _o_lines(lines, "while") + _o_lines(lines, "repeat")
            if ix:
                i = rng.choice(ix)
                lab = lines[i].strip().split()[0]
                lines.insert(rng.randint(i + 1, end), f"{lab} repeat [2]")
                lines.insert(min(len(lines) - 1, end + 1), f"{lab} endrepeat")
                break
        elif kind == "endwhile_do":
            ix = _o_lines(lines, "do")
            if ix:
                i = rng.choice(ix)
                lab = lines[i].strip().split()[0]
                j = next((k for k in range(i + 1, len(lines))
                          if lines[k].strip().lower().startswith(lab.lower() + " while")), None)
                if j is not None:
                    lines[j] = f"{lab} endwhile"
                    break
        elif kind == "break_to_caller":
            loops = _o_lines(lines, "while") + _o_lines(lines, "do")
            subs = _o_lines(lines, "sub")
            if loops and subs:
                lab = lines[rng.choice(loops)].strip().split()[0]
                lines.insert(subs[0] + 1, f"{lab} {rng.choice(['break', 'continue'])}")
                break
        elif kind == "redefine":
            subs = _o_lines(lines, "sub")
            if subs:
                lab = lines[rng.choice(subs)].strip().split()[0]
                lines[end:end] = [f"{lab} sub", "(debug, again)", f"{lab} endsub"]
                break
        elif kind == "many_args":
            calls = _o_lines(lines, "call")
            if calls:
                i = rng.choice(calls)
                lines[i] += "".join(f" [{k}]" for k in range(rng.choice([29, 30, 31])))
                break
        elif kind == "stray_else":
            lines.insert(rng.randint(1, end), rng.choice(["o55 else", "o55 endif", "o55 endwhile"]))
            break
    return "\n".join(lines) + "\n"


def generate(seed: int) -> str:
    g = Gen(seed)
    text = g.program()
    if g.rng.random() < WRONG_SHARE:
        text = spoil(text, g.rng)
    return text


# ---- batch runs against rs274 -----------------------------------------------------------------

GENERATORS: dict[str, Callable[[int], str]] = {"indep-flow": generate}


def _job(job: tuple[str, int]) -> object:
    import run

    kind, seed = job
    assert run._CFG is not None
    text = GENERATORS[kind](seed)
    ref, ours = run.run_pair(run._CFG, text)
    hint, sig = run.compare(ref, ours)
    return run.Result(kind, seed, text, ref, ours, hint, sig)


def batch(kind: str, seed: int, count: int, jobs: int, shrink: bool, out: Path,
          timeout: float) -> int:
    import multiprocessing
    import time

    import run

    cfg = run.Config(["rs274"], None, timeout=timeout)
    todo = [(kind, s) for s in range(seed, seed + count)]
    start = time.monotonic()
    if jobs <= 1:
        run._init_worker(cfg)
        results = [_job(j) for j in todo]
    else:
        ctx = multiprocessing.get_context("fork")
        with ctx.Pool(jobs, initializer=run._init_worker, initargs=(cfg,)) as pool:
            results = list(pool.imap(_job, todo, chunksize=4))
    rs = [r for r in results if isinstance(r, run.Result)]
    crashed = [r for r in rs if r.ref.rc < 0 and not r.hung]
    counted = [r for r in rs if not r.hung and r.ref.rc >= 0]
    differ = [r for r in counted if r.differs]
    print(f"{kind}: seeds {seed}..{seed + count - 1}: {len(rs)} programs in "
          f"{time.monotonic() - start:.0f}s; rs274 hung {sum(r.hung for r in rs)}, "
          f"crashed {len(crashed)}; counted {len(counted)}, identical {len(counted) - len(differ)}, "
          f"differ {len(differ)}; rs274 rc 0: {sum(r.ref.rc == 0 for r in counted)}")
    classes: dict[tuple[str, ...], list[run.Result]] = {}
    for r in differ:
        classes.setdefault(r.signature, []).append(r)
    for _sig, group in sorted(classes.items(), key=lambda kv: -len(kv[1])):
        print(f"- {len(group)}x seeds {[r.seed for r in group[:8]]}\n    {group[0].hint}")
    if shrink and classes:
        import shrink as shrinker

        reps = [g[0] for g in classes.values()]
        for r, small in shrinker.shrink_many(cfg, reps, jobs):
            ref, ours = run.run_pair(cfg, small)
            path = run.write_finding(out, f"{kind}-{r.seed}", small, ref, ours)
            print(f"\n== {path}")
            for line in small.splitlines():
                print(f"   | {line}")
            for line in run.show_diff(ref, ours):
                print(f"   {line}")
    return 1 if differ else 0


def main(argv: list[str] | None = None, kind: str = "indep-flow") -> int:
    ap = argparse.ArgumentParser(description=(__doc__ or "").split("\n\n")[0])
    ap.add_argument("seed", nargs="?", type=int, default=1)
    ap.add_argument("--batch", action="store_true")
    ap.add_argument("--seed", dest="first", type=int, default=None)
    ap.add_argument("--count", type=int, default=100)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--shrink", action="store_true")
    ap.add_argument("--timeout", type=float, default=10.0)
    ap.add_argument("--out", type=Path, default=Path("/tmp") / "indep-found")
    opts = ap.parse_args(argv)
    if not opts.batch:
        sys.stdout.write(GENERATORS[kind](opts.seed))
        return 0
    first = opts.first if opts.first is not None else opts.seed
    return batch(kind, first, opts.count, opts.jobs, opts.shrink, opts.out, opts.timeout)


if __name__ == "__main__":
    sys.exit(main())
