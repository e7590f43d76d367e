"""The ``flow`` kind: o-word control flow as people write it, nested to depth four.

Every loop kind (``while``/``endwhile``, ``do``/``while``, ``repeat``/``endrepeat``) and
``if``/``elseif``/``else``/``endif``, with ``break`` and ``continue`` aimed at the innermost or
an outer loop, taken or in a branch never taken, ``return`` (with or without a value) from loops
inside subroutines, and moves, prints and assignments in the bodies so the path shows which lines
ran.  Each loop counts its runs in a parameter of its own, incremented first thing in its body,
so a program ends whichever way its ``continue`` lines go; the counts are small (1 to 4) to keep
nested programs short.  Now and then a program holds a mistake rs274 reports: a ``break`` or
``continue`` aimed at a ``repeat`` or an ``if``, an ``elseif`` whose condition cannot be
evaluated, an ``endwhile`` for a ``do``.  Subroutines are called from the main program's loops
and branches too, their ``#<_value>`` shown after each call.
"""

from __future__ import annotations

import random
from collections.abc import Callable

MAX_DEPTH = 4


class _Flow:
    def __init__(self, seed: int) -> None:
        self.rng = random.Random(f"flow:{seed}")
        self.lines: list[str] = []
        self.labels = 0
        self.counters = 0
        self.statements = 0
        self.indent = self.rng.random() < 0.6
        self.named = self.rng.random()  # share of named labels
        self.upper = self.rng.random() < 0.5
        self.mistakes = self.rng.random() < 0.08
        self.subs: list[str] = []  # subroutines defined so far, called from the main program

    def emit(self, depth: int, text: str) -> None:
        rng = self.rng
        if text.startswith("o") and rng.random() < 0.04:
            # the spellings real programs have: O, a line number, a comment after the o-word
            r = rng.random()
            if r < 0.4:
                text = "O" + text[1:]
            elif r < 0.7:
                text = f"N{10 * len(self.lines)} {text}"
            else:
                text += rng.choice([" (loop)", " ; end", " (print,on o-line)"])
        self.lines.append(("  " * depth if self.indent else "") + text)

    def kw(self, word: str) -> str:
        return word.upper() if self.upper and self.rng.random() < 0.3 else word

    def label(self) -> str:
        if self.mistakes and self.labels > 2 and self.rng.random() < 0.05:
            return f"o{100 + self.rng.randint(1, self.labels)}"  # a label used before
        self.labels += 1
        if self.rng.random() < self.named:
            return f"o<{self.rng.choice(['l', 'loop', 'b', 'x', 'blk'])}{self.labels}>"
        return f"o{100 + self.labels}"

    def counter(self) -> str:
        self.counters += 1
        return f"#<c{self.counters}>"

    def condition(self, counters: list[str]) -> str:
        rng = self.rng
        r = rng.random()
        if not counters or r < 0.1:
            return rng.choice(["[1]", "[0]", "[1 GT 0]", "[#<_t> GT 2]", "[#<_t> LE 1]"])
        c = rng.choice(counters)
        if r < 0.5:
            return f"[{c} {rng.choice(['EQ', 'NE', 'GT', 'GE', 'LT', 'LE'])} {rng.randint(0, 4)}]"
        if r < 0.7:
            return f"[[{c} MOD 2] EQ {rng.randint(0, 1)}]"
        if r < 0.85 and len(counters) > 1:
            d = rng.choice(counters)
            return f"[{c} {rng.choice(['EQ', 'GT', 'LT'])} {d}]"
        return f"[[{c} + #<_t>] GT {rng.randint(1, 6)}]"

    # ---- statements ---------------------------------------------------------------------------
    def block(self, depth: int, loops: list[tuple[str, str, str]], counters: list[str],
              in_sub: str | None, count: int) -> None:
        for _ in range(count):
            self.statement(depth, loops, counters, in_sub)

    def statement(self, depth: int, loops: list[tuple[str, str, str]], counters: list[str],
                  in_sub: str | None) -> None:
        rng = self.rng
        self.statements += 1
        r = rng.random()
        nest = depth < MAX_DEPTH and self.statements < 60
        if nest and r < 0.14:
            self.while_loop(depth, loops, counters, in_sub)
        elif nest and r < 0.27:
            self.do_loop(depth, loops, counters, in_sub)
        elif nest and r < 0.36:
            self.repeat_loop(depth, loops, counters, in_sub)
        elif nest and r < 0.52:
            self.if_chain(depth, loops, counters, in_sub)
        elif loops and r < 0.66:
            self.jump(depth, loops, counters, in_sub)
        elif in_sub is not None and r < 0.7:
            self.ret(depth, in_sub, counters)
        elif in_sub is None and self.subs and r < 0.72:
            c = rng.choice(counters) if counters else str(rng.randint(0, 4))
            self.emit(depth, f"{rng.choice(self.subs)} call [{c}]")
            self.emit(depth, "(debug, value #<_value> #<_value_returned>)")
        elif r < 0.8:
            self.show(depth, counters)
        elif r < 0.9:
            self.move(depth, counters)
        else:
            self.emit(depth, f"#<_t> = [#<_t> + {rng.randint(1, 3)}]")

    def show(self, depth: int, counters: list[str]) -> None:
        rng = self.rng
        kind = rng.choice(["debug", "print", "DEBUG", "PRINT", "print", "debug"])
        sep = rng.choice([", ", ",", ", ", ",  "])
        shown = " ".join(f"{c[2:-1]}={c}" for c in counters[-2:]) or "t=#<_t>"
        self.emit(depth, f"({kind}{sep}at {len(self.lines)} {shown})")

    def move(self, depth: int, counters: list[str]) -> None:
        rng = self.rng
        c = rng.choice(counters) if counters else "#<_t>"
        words = [rng.choice(["G1", "G0", "G1"]), f"X[{c} * {rng.randint(1, 5)}]",
                 f"Y[#<_t> + {len(self.lines) % 17}]"]
        if rng.random() < 0.3:
            words.append(f"Z{rng.choice(['-1', '0.5', '2'])}")
        self.emit(depth, " ".join(words))

    def jump(self, depth: int, loops: list[tuple[str, str, str]], counters: list[str],
             in_sub: str | None) -> None:
        """A break or continue aimed at an enclosing loop, mostly inside an ``if``."""
        rng = self.rng
        label, kind, _ = loops[-1] if rng.random() < 0.6 else rng.choice(loops)
        word = rng.choice(["break", "continue"])
        if kind == "repeat" and not (self.mistakes and rng.random() < 0.3):
            # break or continue cannot aim at a repeat: aim at another loop, or do nothing.
            others = [lp for lp in loops if lp[1] != "repeat"]
            if not others:
                self.show(depth, counters)
                return
            label, kind, _ = rng.choice(others)
        if rng.random() < 0.25:
            self.emit(depth, f"{label} {self.kw(word)}")
            return
        guard = self.label()
        self.emit(depth, f"{guard} if {self.condition(counters)}")
        if rng.random() < 0.4:
            self.show(depth + 1, counters)
        self.emit(depth + 1, f"{label} {self.kw(word)}")
        if rng.random() < 0.2:
            self.emit(depth, f"{guard} else")
            self.show(depth + 1, counters)
        self.emit(depth, f"{guard} endif")

    def ret(self, depth: int, sub: str, counters: list[str]) -> None:
        rng = self.rng
        guard = self.label()
        value = f" [{rng.choice(counters) if counters else '#<_t>'} * 10]" \
            if rng.random() < 0.5 else ""
        self.emit(depth, f"{guard} if {self.condition(counters)}")
        self.emit(depth + 1, f"{sub} return{value}")
        self.emit(depth, f"{guard} endif")

    def body(self, depth: int, loops: list[tuple[str, str, str]], counters: list[str],
             in_sub: str | None) -> None:
        self.block(depth, loops, counters, in_sub, self.rng.randint(1, 3))

    def loop(self, depth: int, loops: list[tuple[str, str, str]], counters: list[str],
             in_sub: str | None, kind: str, head: Callable[[str], str],
             end: Callable[[str], str]) -> None:
        """A loop of ``kind`` counting its runs in a parameter of its own: ``head`` and ``end``
        give the text after the label of its first and last lines, from the counter's name."""
        label, c = self.label(), self.counter()
        self.emit(depth, f"{c} = 0")
        self.emit(depth, f"{label} {head(c)}")
        self.emit(depth + 1, f"{c} = [{c} + 1]")
        self.body(depth + 1, [*loops, (label, kind, c)], [*counters, c], in_sub)
        self.emit(depth, f"{label} {end(c)}")
        if self.rng.random() < 0.5:
            self.emit(depth, f"(debug, after {label[1:]} {c[2:-1]}={c})")

    def mistaken(self, right: str, wrong: list[str]) -> str:
        """``right``, or in a program with mistakes now and then one of ``wrong``."""
        if self.mistakes and self.rng.random() < 0.1:
            return self.rng.choice(wrong)
        return right

    def while_loop(self, depth: int, loops: list[tuple[str, str, str]], counters: list[str],
                   in_sub: str | None) -> None:
        self.loop(depth, loops, counters, in_sub, "while",
                  lambda c: f"{self.kw('while')} [{c} LT {self.rng.randint(0, 4)}]",
                  lambda c: self.kw(self.mistaken("endwhile", ["endrepeat", "endif", "while [0]"])))

    def do_loop(self, depth: int, loops: list[tuple[str, str, str]], counters: list[str],
                in_sub: str | None) -> None:
        self.loop(depth, loops, counters, in_sub, "do", lambda c: self.kw("do"),
                  lambda c: self.kw(self.mistaken(f"while [{c} LT {self.rng.randint(0, 4)}]",
                                                  ["endwhile", "endrepeat"])))

    def repeat_loop(self, depth: int, loops: list[tuple[str, str, str]], counters: list[str],
                    in_sub: str | None) -> None:
        def head(c: str) -> str:
            count = self.rng.choice(["0", "1", "2", "3", "4", "2.5", "[#<_t> MOD 3]"])
            return f"{self.kw('repeat')} [{count}]"

        self.loop(depth, loops, counters, in_sub, "repeat", head, lambda c: self.kw("endrepeat"))

    def if_chain(self, depth: int, loops: list[tuple[str, str, str]], counters: list[str],
                 in_sub: str | None) -> None:
        rng = self.rng
        label = self.label()
        self.emit(depth, f"{label} {self.kw('if')} {self.condition(counters)}")
        self.body(depth + 1, loops, counters, in_sub)
        for _ in range(rng.choice([0, 0, 1, 1, 2, 3])):
            cond = self.condition(counters)
            if self.mistakes and rng.random() < 0.2:
                cond = rng.choice(["[1 / 0]", "[#<undefined>]", "[SQRT[-1]]"])
            self.emit(depth, f"{label} {self.kw('elseif')} {cond}")
            self.body(depth + 1, loops, counters, in_sub)
        if rng.random() < 0.5:
            self.emit(depth, f"{label} {self.kw('else')}")
            self.body(depth + 1, loops, counters, in_sub)
        self.emit(depth, f"{label} {self.kw('endif')}")

    def subroutine(self) -> str:
        rng = self.rng
        name = f"o<s{self.labels}>" if rng.random() < 0.7 else f"o{900 + self.labels}"
        self.labels += 1
        self.emit(0, f"{name} sub")
        self.block(1, [], ["#1"], name, rng.randint(1, 3))
        tail = f" [#1 + {rng.randint(0, 9)}]" if rng.random() < 0.5 else ""
        self.emit(0, f"{name} endsub{tail}")
        return name


def gen_flow(seed: int) -> str:
    f = _Flow(seed)
    rng = f.rng
    f.lines += ["(flow)", "G21 G90 G17", "F500", "#<_t> = " + str(rng.randint(0, 3))]
    subs = f.subs
    for _ in range(rng.choice([0, 0, 1, 1, 2])):
        subs.append(f.subroutine())
    for _ in range(rng.randint(1, 3)):
        if subs and rng.random() < 0.4:
            sub = rng.choice(subs)
            f.emit(0, f"{sub} call [{rng.randint(0, 4)}]")
            f.emit(0, "(debug, value #<_value> #<_value_returned> t=#<_t>)")
        else:
            f.statement(0, [], [], None)
    for sub in subs:
        if rng.random() < 0.6:
            f.emit(0, f"{sub} call [{rng.randint(0, 4)}]")
    f.emit(0, "(debug, end t=#<_t>)")
    f.lines.append(rng.choice(["M2", "M30", "M2"]))
    return "".join(line + "\n" for line in f.lines)
