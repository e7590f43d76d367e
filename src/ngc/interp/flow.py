"""Control flow: o-word subroutines, conditionals and loops (o-code.adoc), LinuxCNC's way.

Plain programs stream: each line is read, executed and forgotten.  The first o-word line switches
the interpreter to this module's program counter, which runs over *bodies*: the lines of a file
from some line on, kept as raw text until first executed and as parsed blocks afterwards, so a
loop body is parsed once however often it runs.  The main program's body (the :class:`Tape`)
keeps reading the open file as execution moves on; it is dropped, and streaming resumes, as soon
as no loop can jump back into it.  A subroutine keeps its own copy of its lines.

rs274's rules, as the reference binary shows them:

* Each scope (the main program, each subroutine) has a table of the control labels it has run:
  a label is bound to its keyword and line the first time it runs, and another construct reusing
  it in the same scope is an error ("duplicate O-word label").  ``endwhile``, ``break``, ``else``
  ... look the label up in that table.
* A false condition skips lines: only o-word lines are read while skipping (their label is
  evaluated), everything else is passed over unread, a ``M2`` included.
* ``call`` of a subroutine not yet defined searches forward in the current file, then for
  ``<name>.ngc`` in the working directory and the subroutine path.
* A call saves ``#1``-``#30`` and passes its arguments as ``#1``... ; the others read 0 in the
  subroutine.  The caller's values come back on return.  Nine levels of calls at most.
"""

from __future__ import annotations

import os
import re
from collections.abc import Iterator
from typing import TYPE_CHECKING, NoReturn

from ..errors import NgcError, NgcProgramError, NgcRuntimeError, NgcSemanticError
from ..language.expressions import evaluate
from ..language.lexer import normalize
from ..language.oword import MAX_ARGS, PROGRAM, OWord, number_label
from ..language.parser import Block, parse_line

if TYPE_CHECKING:
    from .interpreter import Interpreter

Entry = str | Block
# Call levels rs274 allows below the main program.
MAX_CALL_DEPTH = 9
# Safety bound on the lines a program may run (an endless ``o100 while [1]`` ends with an error).
DEFAULT_MAX_LINES = 100_000_000
ARGUMENT_PARAMETERS = 30
_N_WORD = re.compile(r"n[0-9.]*")
_LOOPS = ("while", "do", "repeat")


class Body:
    """Lines of one file from line ``first`` on: raw text until first run, then parsed blocks."""

    __slots__ = ("file", "first", "lines")

    def __init__(self, file: str | None, first: int, lines: list[Entry]) -> None:
        self.file = file
        self.first = first
        self.lines = lines

    def fetch(self, number: int) -> Entry | None:
        """Line ``number`` (1-based in its file), or None past the end."""
        i = number - self.first
        return self.lines[i] if i < len(self.lines) else None

    def last(self) -> int:
        """The number of the last line held."""
        return self.first + len(self.lines) - 1


class Tape(Body):
    """The main program's lines from the first o-word on, read from the open file as needed."""

    __slots__ = ("interp", "numbered")

    def __init__(self, interp: Interpreter, numbered: Iterator[tuple[int, str]], first: int,
                 block: Block) -> None:
        super().__init__(interp.file, first, [block])
        self.interp = interp
        self.numbered = numbered

    def fetch(self, number: int) -> Entry | None:
        i = number - self.first
        lines = self.lines
        while i >= len(lines):
            item = next(self.numbered, None)
            if item is None:
                return None
            read, raw = item
            raw = self.interp.checked_line(raw, read)
            lines.append(raw)
            self.interp.last_read = (read, raw)
        return lines[i]


class Sub:
    """A defined subroutine: its label and the body from its ``sub`` line to its ``endsub``.

    A Fanuc-style program (``o100`` ... ``M99``) runs in the body it was found in, from its
    ``o100`` line on, until ``M99``.
    """

    __slots__ = ("ahead", "body", "fanuc", "label", "start")

    def __init__(self, label: str, body: Body, start: int, fanuc: bool = False) -> None:
        self.label = label
        self.body = body
        self.start = start
        self.fanuc = fanuc
        # Found by a call searching ahead of the line being run.
        self.ahead = False


class Frame:
    """One scope being run: the main program or one call of a subroutine."""

    __slots__ = ("active", "body", "call_block", "labels", "pc", "repeats", "saved", "sub")

    def __init__(self, body: Body, pc: int, sub: Sub | None) -> None:
        self.body = body
        self.pc = pc
        self.sub = sub
        # label -> (keyword, line) of each control construct run in this scope.
        self.labels: dict[str, tuple[str, int]] = {}
        # Loops being run: label -> repeats left (``repeat``) or 0.0.
        self.active: dict[str, float] = {}
        self.saved: list[float] = []
        self.call_block: Block | None = None
        # M98 L: further runs of a Fanuc-style program after this one.
        self.repeats = 0


def oword_line(raw: str) -> bool:
    """Whether ``raw`` is an o-word line (the only lines read while skipping)."""
    if "o" not in raw and "O" not in raw:
        return False
    try:
        text = normalize(raw)
    except NgcError:
        return False
    text = text.lstrip("/")
    if text.startswith("n"):
        m = _N_WORD.match(text)
        text = text[m.end() if m else 0 :]
    return text.startswith("o")


def _quote(block: Block) -> str:
    return f"{block.line}: %s: '{block.source}'"


class Flow:
    """The control-flow state of one interpreter: frames, subroutines, the main program's tape."""

    def __init__(self, interp: Interpreter) -> None:
        self.interp = interp
        self.subs: dict[str, Sub] = {}
        self.frames: list[Frame] = []
        self.main: Frame | None = None
        self.tape: Tape | None = None
        self.subroutine_path: list[str] = []
        self.max_lines = DEFAULT_MAX_LINES
        self.lines_run = 0

    # -- entering and leaving control mode ------------------------------------------------------
    def enter(self, block: Block, numbered: Iterator[tuple[int, str]]) -> None:
        """An o-word line was met while streaming: run from it under the program counter."""
        self.tape = Tape(self.interp, numbered, block.line, block)
        if self.main is None:
            self.main = Frame(self.tape, block.line, None)
        self.main.body = self.tape
        self.main.pc = block.line
        self.frames = [self.main]

    def run_guarded(self) -> bool:
        """:meth:`run` (kept as the entry point of the streaming loop)."""
        return self.run()

    def run(self) -> bool:
        """Run lines until streaming can resume (True) or the program has ended (False)."""
        it = self.interp
        frames = self.frames
        execute = it.execute
        while True:
            f = frames[-1]
            number = f.pc
            entry = f.body.fetch(number)
            if entry is None:
                self.end_of_file(f)
            if entry.__class__ is str:
                compiled = self.compile(f.body, number, str(entry))
                if compiled is None:
                    return False
                entry = compiled
            assert isinstance(entry, Block)
            f.pc = number + 1
            if entry.delete and it.state.blocks_deleted:
                continue
            if entry.oword is None:
                execute(entry)
            else:
                self.oword(f, entry)
            if it.ended:
                return False
            if len(frames) == 1:
                f = frames[0]
                if not f.active and f.pc > f.body.last():
                    self.tape = None
                    return True

    def compile(self, body: Body, number: int, raw: str) -> Block | None:
        """Parse a line once and keep the block; None for the closing ``%``."""
        it = self.interp
        if it.percent and raw.strip() == "%":
            it.finish_percent()
            return None
        try:
            block = parse_line(raw, number)
        except NgcError as err:
            raise err.locate(file=body.file, line=number, source=raw.rstrip()) from None
        body.lines[number - body.first] = block
        return block

    def end_of_file(self, f: Frame) -> NoReturn:
        last = f.body.last()
        entry = f.body.fetch(last)
        source = entry.source if isinstance(entry, Block) else (entry or "").rstrip()
        if len(self.frames) > 1:
            raise NgcProgramError("File ended with no percent sign or program end",
                                  file=f.body.file, line=last, source=source)
        raise NgcProgramError(
            "File ended with no percent sign" if self.interp.percent
            else "File ended with no percent sign or program end",
            file=f.body.file, line=last, source=source)

    # -- o-words ----------------------------------------------------------------------------
    def oword(self, f: Frame, block: Block) -> None:
        it = self.interp
        it.label = block.label
        it.line = it.state.line = block.line
        ow = block.oword
        assert isinstance(ow, OWord)
        try:
            self.lines_run += 1
            if self.lines_run > self.max_lines:
                raise NgcRuntimeError(
                    f"Program ran more than {self.max_lines} o-word lines: stopped as a runaway")
            getattr(self, "_" + (ow.keyword or "program"))(f, block, ow)
        except NgcError as err:
            raise err.locate(file=f.body.file, line=block.line, source=block.source) from None

    def label(self, f: Frame, block: Block, ow: OWord) -> str:
        return ow.label_of(self.interp.params)

    def bind(self, f: Frame, block: Block, label: str, keyword: str) -> None:
        """Record a construct's label in its scope; reusing it elsewhere is an error."""
        bound = f.labels.get(label)
        if bound is None:
            f.labels[label] = (keyword, block.line)
            return
        if bound[1] == block.line:
            return
        if keyword in ("if", "sub"):
            raise NgcSemanticError(
                f"{block.line}: duplicate O-word label - already defined in line {bound[1]}: "
                f"'{block.source}'")
        raise NgcSemanticError(
            f"{block.line}: duplicate O-word label: '{block.source}' - defined in line {bound[1]}")

    def lookup(self, f: Frame, block: Block, label: str, kinds: tuple[str, ...],
               what: str = "label") -> tuple[str, int]:
        bound = f.labels.get(label)
        if bound is None:
            raise NgcSemanticError(_quote(block) % "undefined O-word label")
        if bound[0] not in kinds:
            raise NgcSemanticError(
                f"{block.line}: no matching {what}: '{block.source}' "
                f"(found '{bound[0]}' in line {bound[1]})")
        return bound

    def condition(self, ow: OWord) -> bool:
        return evaluate(ow.args[0], self.interp.params) != 0.0

    def skip(self, f: Frame, start: int, label: str, kinds: tuple[str, ...],
             seeking: Block | None = None) -> Block:
        """Pass over lines after ``start`` to the o-word ``label`` with one of ``kinds``.

        Only o-word lines are read.  Running out of lines is the end-of-file error (or, when
        ``seeking`` a subroutine to call, rs274's "EOF ... seeking" error).
        """
        body = f.body
        params = self.interp.params
        number = start
        while True:
            number += 1
            entry = body.fetch(number)
            if entry is None:
                if seeking is not None:
                    last = body.fetch(body.last())
                    source = last.source if isinstance(last, Block) else str(last).rstrip()
                    raise NgcProgramError(
                        f"EOF in file:{body.file} seeking o-word: o<{label}> "
                        f"from line: {seeking.line}", file=body.file, line=body.last(),
                        source=source)
                self.end_of_file(f)
            if isinstance(entry, str):
                if not oword_line(entry):
                    if self.interp.percent and entry.strip() == "%" and body is self.tape:
                        self.interp.finish_percent()
                        prefix = "O" if seeking is not None or "endsub" in kinds else "O#"
                        raise NgcProgramError(
                            f"Failed to find sub '{prefix}{label}' before EOF",
                            file=body.file, line=number, source=entry.rstrip())
                    continue
                block = self.compile(body, number, entry)
                assert block is not None
                entry = block
            ow = entry.oword
            if ow is None or ow.keyword not in kinds:
                if ow is not None and ow.keyword == "sub" and kinds[0] == "endsub":
                    raise NgcSemanticError("Nested subroutine definition", file=body.file,
                                           line=number, source=entry.source)
                continue
            if ow.label_of(params) == label:
                return entry

    def jump(self, f: Frame, block: Block, ow: OWord, label: str, kinds: tuple[str, ...]) -> Block:
        """``skip`` from ``block``, remembered on the o-word when its label is constant."""
        key = kinds[0]
        target = ow.jumps.get(key) if ow.label is not None else None
        if target is not None:
            found = f.body.fetch(target)
            if isinstance(found, Block):
                return found
        found = self.skip(f, block.line, label, kinds)
        if ow.label is not None:
            ow.jumps[key] = found.line
        return found

    # -- conditionals -------------------------------------------------------------------------
    def _if(self, f: Frame, block: Block, ow: OWord) -> None:
        label = self.label(f, block, ow)
        self.bind(f, block, label, "if")
        if not self.condition(ow):
            self.next_branch(f, block, ow, label)

    def next_branch(self, f: Frame, block: Block, ow: OWord, label: str) -> None:
        """A false condition: on to the next ``elseif`` that holds, the ``else``, or the ``endif``."""
        while True:
            found = self.jump(f, block, ow, label, ("elseif", "else", "endif"))
            f.pc = found.line + 1
            other = found.oword
            assert isinstance(other, OWord)
            if other.keyword != "elseif":
                return
            try:
                if self.condition(other):
                    return
            except NgcError as err:
                raise err.locate(file=f.body.file, line=found.line, source=found.source) from None
            block, ow = found, other

    def _elseif(self, f: Frame, block: Block, ow: OWord) -> None:
        label = self.label(f, block, ow)
        self.lookup(f, block, label, ("if",))
        found = self.jump(f, block, ow, label, ("endif",))
        f.pc = found.line + 1

    _else = _elseif

    def _endif(self, f: Frame, block: Block, ow: OWord) -> None:
        self.lookup(f, block, self.label(f, block, ow), ("if",))

    # -- loops ---------------------------------------------------------------------------------
    def _while(self, f: Frame, block: Block, ow: OWord) -> None:
        label = self.label(f, block, ow)
        bound = f.labels.get(label)
        if bound is not None and bound[0] == "do" and bound[1] != block.line:
            # The end of a do-while loop.
            if self.condition(ow):
                f.pc = bound[1] + 1
            else:
                f.active.pop(label, None)
            return
        self.bind(f, block, label, "while")
        if self.condition(ow):
            f.active[label] = 0.0
        else:
            f.active.pop(label, None)
            found = self.jump(f, block, ow, label, ("endwhile",))
            f.pc = found.line + 1

    def _endwhile(self, f: Frame, block: Block, ow: OWord) -> None:
        label = self.label(f, block, ow)
        _, line = self.lookup(f, block, label, ("while",))
        f.pc = line

    def _do(self, f: Frame, block: Block, ow: OWord) -> None:
        label = self.label(f, block, ow)
        self.bind(f, block, label, "do")
        f.active[label] = 0.0

    def _repeat(self, f: Frame, block: Block, ow: OWord) -> None:
        label = self.label(f, block, ow)
        self.bind(f, block, label, "repeat")
        left = f.active.get(label)
        if left is None:
            left = evaluate(ow.args[0], self.interp.params)
        if left >= 1.0 - 1e-9 or (left > 0.0 and round(left) >= 1):
            f.active[label] = left - 1.0
        else:
            f.active.pop(label, None)
            found = self.jump(f, block, ow, label, ("endrepeat",))
            f.pc = found.line + 1

    def _endrepeat(self, f: Frame, block: Block, ow: OWord) -> None:
        label = self.label(f, block, ow)
        _, line = self.lookup(f, block, label, ("repeat",))
        f.pc = line

    def _break(self, f: Frame, block: Block, ow: OWord) -> None:
        label = self.label(f, block, ow)
        keyword, _ = self.lookup(f, block, label, _LOOPS, "while/do/repeat label")
        f.active.pop(label, None)
        end = {"while": ("endwhile",), "do": ("while",), "repeat": ("endrepeat",)}[keyword]
        found = self.jump(f, block, ow, label, end)
        f.pc = found.line + 1

    def _continue(self, f: Frame, block: Block, ow: OWord) -> None:
        label = self.label(f, block, ow)
        keyword, line = self.lookup(f, block, label, ("while", "do"), "while/do label")
        if keyword == "while":
            f.pc = line
        else:
            found = self.jump(f, block, ow, label, ("while",))
            f.pc = found.line

    # -- subroutines ---------------------------------------------------------------------------
    def _sub(self, f: Frame, block: Block, ow: OWord) -> None:
        """A definition met in sequence: keep its lines, go on after its ``endsub``."""
        label = self.label(f, block, ow)
        known = self.subs.get(label)
        if known is not None and known.ahead and known.start == block.line:
            raise NgcSemanticError(
                f"File:{f.body.file} line:{block.line} sub: o|{label}| found in illegal location")
        end = self.jump(f, block, ow, label, ("endsub",))
        self.define(f.body, label, block.line, end.line)
        f.pc = end.line + 1

    def define(self, body: Body, label: str, start: int, end: int) -> Sub:
        lines = body.lines[start - body.first : end - body.first + 1]
        sub = Sub(label, Body(body.file, start, lines), start)
        self.subs[label] = sub
        return sub

    def _call(self, f: Frame, block: Block, ow: OWord) -> None:
        it = self.interp
        params = it.params
        label = self.label(f, block, ow)
        if len(ow.args) > MAX_ARGS:
            raise NgcSemanticError("Too many arguments to subroutine call")
        args = [evaluate(a, params) for a in ow.args]
        sub = self.subs.get(label) or self.find(f, block, label)
        if len(self.frames) > MAX_CALL_DEPTH:
            raise NgcRuntimeError("Too many subroutine levels")
        numbered = params.numbered
        frame = Frame(sub.body, sub.start + 1, sub)
        frame.saved = numbered[1 : ARGUMENT_PARAMETERS + 1]
        frame.call_block = block
        numbered[1 : ARGUMENT_PARAMETERS + 1] = [0.0] * ARGUMENT_PARAMETERS
        numbered[1 : len(args) + 1] = args
        it.state.value = 0.0
        it.state.value_returned = 0.0
        params.locals.append({})
        self.frames.append(frame)
        it.state.call_level = len(self.frames) - 1

    def find(self, f: Frame, block: Block, label: str, fanuc: bool = False) -> Sub:
        """A subroutine not defined yet: later in this file, else in ``<label>.ngc``."""
        path = None if fanuc else self.sub_file(label)
        if path is not None:
            return self.load(path, label, block)
        start = self.skip(f, block.line, label, ("sub", PROGRAM), seeking=block)
        assert start.oword is not None
        keyword = start.oword.keyword
        if keyword == PROGRAM:
            if not fanuc:
                raise NgcSemanticError("Fanuc 'O....' subroutine must be called with 'M98'",
                                       file=f.body.file, line=start.line, source=start.source)
            sub = Sub(label, f.body, start.line, fanuc=True)
            self.subs[label] = sub
        elif fanuc:
            raise NgcSemanticError("'O.... sub' subroutine must be called with 'O.... call'",
                                   file=f.body.file, line=start.line, source=start.source)
        else:
            # Run from the definition found; its end is wherever ``endsub`` turns up.
            sub = Sub(label, f.body, start.line)
            self.subs[label] = sub
        sub.ahead = True
        return sub

    def sub_file(self, label: str) -> str | None:
        name = label + ".ngc"
        for folder in (os.getcwd(), *self.subroutine_path):
            path = os.path.join(folder, name)
            if os.path.isfile(path):
                return path
        return None

    def load(self, path: str, label: str, block: Block) -> Sub:
        try:
            with open(path, encoding="latin-1", newline="") as handle:
                raw_lines = [self.interp.checked_line(raw, n) for n, raw in enumerate(handle, 1)]
        except OSError as exc:
            raise NgcRuntimeError(f"Unable to open file {path}: {exc.strerror}") from None
        body = Body(path, 1, list(raw_lines))
        frame = Frame(body, 1, None)
        start = self.skip(frame, 0, label, ("sub",), seeking=block)
        sub = Sub(label, body, start.line)
        self.subs[label] = sub
        return sub

    def _return(self, f: Frame, block: Block, ow: OWord) -> None:
        it = self.interp
        if f.sub is None:
            raise NgcSemanticError(_quote(block) % "not in a subroutine definition")
        if f.sub.fanuc:
            raise NgcSemanticError("Fanuc 'O....' subroutine definition must end with 'M99'")
        if ow.args:
            it.state.value = evaluate(ow.args[0], it.params)
            it.state.value_returned = 1.0
        it.params.numbered[1 : ARGUMENT_PARAMETERS + 1] = f.saved
        it.params.locals.pop()
        self.frames.pop()
        it.state.call_level = len(self.frames) - 1

    _endsub = _return

    def _program(self, f: Frame, block: Block, ow: OWord) -> None:
        """``o100`` alone: a program title (``o1`` at the top), nothing to run."""

    # -- Fanuc style: M98 / M99 ------------------------------------------------------------------
    def fanuc(self, block: Block, code: int, p: float | None, loops: float | None) -> bool:
        """Run ``M98 P- L-`` or ``M99``; False when M99 ends the main program (like M2)."""
        if self.tape is None:
            self.enter(block, self.interp._numbered)
            self.frames[-1].pc = block.line + 1
        f = self.frames[-1]
        if code == 99:
            return self.m99(f, block)
        if p is None:
            raise NgcSemanticError("Found 'm98' code with no P-word")
        count = 1 if loops is None else int(loops)
        if count < 0:
            raise NgcSemanticError("Negative l word used")
        label = number_label(p)
        sub = self.subs.get(label)
        if sub is None:
            sub = self.find(f, block, label, fanuc=True)
        elif not sub.fanuc:
            start = sub.body.fetch(sub.start)
            assert isinstance(start, Block)
            raise NgcSemanticError("'O.... sub' subroutine must be called with 'O.... call'",
                                   file=sub.body.file, line=sub.start, source=start.source)
        if count == 0:
            return True
        if len(self.frames) > MAX_CALL_DEPTH:
            raise NgcRuntimeError("Too many subroutine levels")
        frame = Frame(sub.body, sub.start + 1, sub)
        frame.repeats = count - 1
        frame.call_block = block
        self.frames.append(frame)
        self.interp.state.call_level = len(self.frames) - 1
        return True

    def m99(self, f: Frame, block: Block) -> bool:
        sub = f.sub
        if sub is None:
            return False
        if not sub.fanuc:
            raise NgcSemanticError(
                "'O.... endsub' or 'O.... return' must follow 'O.... sub' subroutine definition")
        if f.repeats > 0:
            f.repeats -= 1
            f.pc = sub.start + 1
            return True
        self.frames.pop()
        self.interp.state.call_level = len(self.frames) - 1
        return True
