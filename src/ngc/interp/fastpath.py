"""The one fast path: shortcuts for the commonest lines, all in this module.

A *plain line* is defined here, once, from the code table: no code but a motion code whose handler
is one of :data:`PLAIN_HANDLERS` (or no code at all), and only the words that need no other code —
X Y Z A B C F S, plus the motion code's own words (I J K R P for arcs).  Most CAM output is plain
lines.  :class:`FastPath` runs them with the same checks and in the same order as the general path
(:class:`~ngc.interp.dispatch.Dispatcher`), without building a block:

* :meth:`FastPath.line` reads a raw line with :func:`~ngc.language.parser.split_plain` (and keeps
  the last plain lines read, as CAM output repeats its retracts) or runs a comment-only line; a
  line of literal words that is not plain but moves nothing (``G40``, ``G41.1 D4``, ``G90``)
  is checked and planned once, as its check and its steps do not depend on the machine's state,
  and kept too;
* :meth:`FastPath.convert` is the plain-line runner (the hot loop of a plain program);
* :meth:`FastPath.compile` and :meth:`FastPath.specialise` give the lines of a loop body a runner
  built once (parameter settings only, or a plain motion with computed values).

An interpreter built with ``fast=False`` has no ``FastPath``: every line takes the general path.
tests/test_golden.py runs every golden case both ways and requires the same transcript.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, NamedTuple

from ..canon import ops
from ..errors import NgcSemanticError
from ..language.codes import (
    FREE_LETTERS,
    G_CANCEL_MOTION,
    G_MACHINE_COORDINATES,
    G_MOTION,
    G_NON_MODAL,
    CodeTable,
)
from ..language.expressions import Expr, Value
from ..language.lexer import C_SPACE
from ..language.parser import (
    PARAM,
    WORD,
    Block,
    check_number_writable,
    n_label,
    split_plain,
    words_of,
)
from ..language.words import Words, check_signs
from . import comp
from .check import check
from .dispatch import Dispatcher
from .handlers import modes, motion, program
from .machine import Machine
from .parameters import INI_PREFIX, PREDEFINED, Parameters

# The motion handlers a plain line may run.
PLAIN_HANDLERS = frozenset({"traverse", "feed", "arc"})
PLAIN_CACHE_SIZE = 1024
_AXES = frozenset("xyzabc")
_new = tuple.__new__

# A plain line read once: (words, motion code or None, N column, source).
Plain = tuple[dict[str, float], "int | None", str, str]


class Compiled(NamedTuple):
    """A block with a runner of its own (see :meth:`FastPath.specialise`)."""

    block: Block
    run: Callable[[], None]


class FastPath:
    """The plain-line shortcuts for one machine and code table."""

    __slots__ = ("_arcs", "_letters", "_lines", "_motion", "dispatcher", "execute", "m", "table")

    def __init__(self, m: Machine, table: CodeTable, execute: Callable[[Block], None],
                 dispatcher: Dispatcher) -> None:
        """``execute`` runs a block on the general path (a line read here that is not plain);
        ``dispatcher`` plans the steps of the lines that move nothing."""
        self.m = m
        self.table = table
        self.execute = execute
        self.dispatcher = dispatcher
        # G word value -> motion code, for the motion codes a plain line may hold.
        self._motion = {code / 10: code for code, row in table.g.items()
                        if row.group == G_MOTION and row.handler in PLAIN_HANDLERS}
        # Motion code -> the letters its plain lines may carry: the free ones and its own (an arc's
        # I J K R; a P word has rules of its own, checked before the line runs, so such lines
        # take the general path).
        self._arcs = {code: FREE_LETTERS | frozenset(row.uses) - {"p"} for code, row in table.g.items()
                      if code in self._motion.values() and row.uses}
        # Motion code (None: none given) -> every letter its plain lines may carry.
        self._letters: dict[int | None, frozenset[str]] = {
            code: self._arcs.get(code, FREE_LETTERS) for code in self._motion.values()}
        self._letters[None] = FREE_LETTERS
        # Raw line -> (words, motion code, N column) of a plain line, or (None, (resolved words,
        # steps), N column) of a line of literal words that moves nothing.
        self._lines: dict[str, tuple[dict[str, float] | None, Any, str]] = {}

    # -- what a plain line is -----------------------------------------------------------------
    def entry(
        self, found: tuple[dict[str, float], float | None, str | None],
    ) -> tuple[dict[str, float], int | None, str] | None:
        """What :func:`split_plain` read, as (words, motion code, N column) if it is a plain line."""
        w, g, digits = found
        code = None if g is None else self._motion.get(g)
        if g is not None and code is None:
            return None
        if self._letters[code].issuperset(w):
            return w, code, "N..... " if digits is None else n_label(digits)
        return None

    def is_plain(self, r: Words) -> bool:
        """The same definition for a block's resolved words."""
        if r.m or r.assigns or r.comment is not None:
            return False
        g = r.g
        if not g:
            return not r.others
        code = g.get(G_MOTION)
        if len(g) != 1 or code is None or self.table.g[code].handler not in PLAIN_HANDLERS:
            return False
        return not r.others or (code in self._arcs and self._arcs[code].issuperset(r.w))

    # -- running ------------------------------------------------------------------------------
    def line(self, raw: str, number: int) -> bool:
        """Run ``raw`` if split_plain can read it or it is one comment; else False.  Errors are
        raised without a place: the caller knows the line."""
        m = self.m
        hit = self._lines.get(raw)
        if hit is None:
            found = split_plain(raw)
            if found is None:
                return self.comment_line(raw, number)
            # (what entry() does, written out: most lines are read once)
            words, g, digits = found
            motion = None if g is None else self._motion.get(g)
            if (g is not None and motion is None) or not self._letters[motion].issuperset(words):
                return self._not_plain(raw, number, words, g, digits)
            hit = words, motion, "N..... " if digits is None else n_label(digits)
            cache = self._lines
            if len(cache) >= PLAIN_CACHE_SIZE:
                cache.clear()
            cache[raw] = hit
        w, code, m.label = hit
        m.line = m.state.line = number
        if w is None:  # moves nothing: code is (resolved words, steps)
            self.dispatcher.run(m, code[0], code[1])  # type: ignore[index]
            return True
        self.convert(w, code)
        return True

    def _not_plain(self, raw: str, number: int, words: dict[str, float], g: float | None,
                   digits: str | None) -> bool:
        """A line split_plain read that is not plain: run on the general path, or planned once
        if it moves nothing (see :meth:`_run_static`)."""
        r = words_of(words, g, self.table)
        if not r.moves and r.g.get(G_NON_MODAL) != G_MACHINE_COORDINATES:
            return self._run_static(raw, number, r, n_label(digits))
        block = Block(number, raw.rstrip(C_SPACE))
        block.resolved = r
        if digits is not None:
            block.n_number = int(digits)
            block.label = n_label(digits)
        self.execute(block)
        return True

    def _run_static(self, raw: str, number: int, r: Words, label: str) -> bool:
        """A line of literal words that moves nothing: checked (the check reads no state when
        nothing moves and every code is supported), planned, kept, run."""
        m = self.m
        m.label = label
        m.line = m.state.line = number
        check(m.state, r, self.table)
        plan = self.dispatcher.plan(m, r)
        rows = self.table.g
        if all(rows[code].handler for code in r.g.values()):
            cache = self._lines
            if len(cache) >= PLAIN_CACHE_SIZE:
                cache.clear()
            cache[raw] = (None, (r, plan), label)
        self.dispatcher.run(m, r, plan)
        return True

    def comment_line(self, raw: str, number: int) -> bool:
        """Run ``raw`` if it holds nothing but one ``( ... )`` comment; else False."""
        text = raw.strip(" \t\r")
        if not (text[:1] == "(" and text[-1:] == ")" and text.count("(") == 1):
            return False
        if text.count(")") != 1 or not text.isascii():
            return False
        m = self.m
        m.label = "N..... "
        m.line = m.state.line = number
        program.comment(m, text)
        return True

    def convert(self, w: dict[str, float], code: int | None) -> None:
        """A plain line: F, S, then the motion (explicit or modal), as the general path runs it."""
        m = self.m
        st = m.state
        if code is None and not _AXES.isdisjoint(w):
            code = st.motion  # the modal motion the axis words run (checked before F runs)
            if code == G_CANCEL_MOTION:
                check_signs(w)  # a negative F or S was refused as the line was read
                raise NgcSemanticError("Cannot use axis values without a g code that uses them")
            if code not in self._letters:  # a modal canned cycle: the general path runs it
                r = words_of(w, None, self.table)
                check(st, r, self.table)
                self.dispatcher.convert(m, r)
                return
        if st.lathe_diameter and "x" in w:
            w = {**w, "x": w["x"] / 2.0}  # G7: an X word is a diameter
        if "f" in w:
            f = w["f"]
            if f >= 0.0 and st.feed_mode == 940 and not m.held:
                st.feed = f
                m.sink.emit(_new(ops.SetFeedRate, (f,)), m.label, m.line)
            else:
                if f < 0.0:
                    check_signs(w)  # refused as read, in line order: "S-1 F-1" is about S
                modes.feed_rate(m, f)
        if "s" in w:
            modes.spindle_speed(m, w["s"])
        if code is None:
            return
        # rs274 takes the motion mode once the move is made: a move that fails leaves the old
        # one (seen when the run goes on after the error, -n 0).
        compensation = m.comp
        pos = st.pos if compensation is None else compensation.prog
        if st.absolute:
            # (cheaper than six w.get calls: a line has two or three axis words)
            end = pos.copy()
            if "x" in w:
                end[0] = w["x"]
            if "y" in w:
                end[1] = w["y"]
            if "z" in w:
                end[2] = w["z"]
            if "a" in w:
                end[3] = w["a"]
            if "b" in w:
                end[4] = w["b"]
            if "c" in w:
                end[5] = w["c"]
        else:
            end = motion.relative_end(pos, w)
        if code in self._arcs:
            motion.arc(m, w, end, code)
            st.motion = code
            return
        if compensation is not None:
            if code == 0:
                comp.straight(m, ops.StraightTraverse, end)
            elif st.feed_mode == 940 and st.feed != 0.0:
                comp.straight(m, ops.StraightFeed, end)
            else:
                motion.feed(m, w, end)
            st.motion = code
            return
        if code == 0:
            m.move(ops.StraightTraverse, end, m.label, m.line)
        elif st.feed_mode == 940 and st.feed != 0.0:
            m.move(ops.StraightFeed, end, m.label, m.line)
        else:
            motion.feed(m, w, end)
            st.motion = code
            return
        st.pos = end
        st.motion = code

    # -- lines run many times -----------------------------------------------------------------
    def compile(self, raw: str, number: int, parse: Callable[[str, int], Block]) -> Plain | Block | Compiled:
        """A line read once for running many times: plain words, a block with a runner, or a
        block for the general path."""
        found = split_plain(raw)
        hit = None if found is None else self.entry(found)
        if hit is not None:
            return (*hit, raw.rstrip(C_SPACE))
        block = parse(raw, number)
        run = self.specialise(block)
        return block if run is None else Compiled(block, run)

    def specialise(self, block: Block) -> Callable[[], None] | None:
        """A runner for ``block`` if it holds only parameter settings, or only a G0/G1 (or no G
        code) with axis, F and S words of computed value; else None."""
        if block.delete or block.oword is not None or block.resolved is not None or not block.items:
            return None
        kinds = {kind for kind, _, _ in block.items}
        if kinds == {PARAM}:
            return self._settings(block)
        if kinds == {WORD}:
            return self._plain_motion(block)
        return None

    def _settings(self, block: Block) -> Callable[[], None] | None:
        """``#1 = [...] #<x> = [...]``: values read left to right, then all set."""
        targets: list[int | str] = []
        values: list[Value] = []
        for _, key, value in block.items:
            if not isinstance(key, int | str):
                return None  # a computed parameter number: the general path checks it
            if isinstance(key, int):
                check_number_writable(key)
            elif key in PREDEFINED or key.startswith(INI_PREFIX):
                return None  # read-only, or perhaps: the general path says
            targets.append(key)
            values.append(value)  # type: ignore[arg-type]
        params = self.m.params
        pairs = list(zip(targets, values, strict=True))
        if len(pairs) == 1 and isinstance(targets[0], str) and type(values[0]) is not float:
            return _one_named_setting(params, targets[0], values[0])  # type: ignore[arg-type]

        def run() -> None:
            read = []
            for target, value in pairs:
                if isinstance(target, str):
                    params.declare(target)  # read-only names were left to the general path
                read.append(value if type(value) is float else value(params))  # type: ignore[operator]
            assign = params.assign
            for (target, _), v in zip(pairs, read, strict=True):
                assign(target, v)

        return run

    def _plain_motion(self, block: Block) -> Callable[[], None] | None:
        """``G1 X[...] Y[...]``: the plain-line runner with the values evaluated."""
        code: int | None = None
        words: list[tuple[str, Value]] = []
        for _, key, value in block.items:
            if key == "g":
                if not isinstance(value, float) or code is not None:
                    return None
                code = self._motion.get(value)
                if code is None or code in self._arcs:
                    return None
            elif key in FREE_LETTERS and all(key != k for k, _ in words):
                words.append((key, value))  # type: ignore[arg-type]
            else:
                return None
        params = self.m.params
        convert = self.convert
        constant = {k: v for k, v in words if type(v) is float}
        computed = [(k, v) for k, v in words if type(v) is not float]

        def run() -> None:
            w = constant.copy()
            for k, v in computed:
                w[k] = v(params)  # type: ignore[operator]
            convert(w, code)

        return run


def _one_named_setting(params: Parameters, name: str, value: Expr) -> Callable[[], None]:
    """``#<name> = [...]``: the name exists (reading 0) before its value is read, as rs274 has it."""
    global_ = name.startswith("_")

    def run() -> None:
        scope = params.globals if global_ else params.locals[-1]
        if name not in scope:
            scope[name] = 0.0
        scope[name] = value(params)

    return run
