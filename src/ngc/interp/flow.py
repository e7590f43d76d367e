"""Control flow: o-word subroutines, conditionals and loops, M98/M99 (o-code.adoc), rs274's way.

Plain programs stream: each line is read, executed and forgotten.  The first o-word line (or M98
/ M99) switches the interpreter to this module's program counter, which runs over *bodies*: the
lines of a file, kept as raw text until first executed and as compiled entries afterwards (a
plain-words tuple or a parsed :class:`Block`), so a loop body is parsed once however often it
runs.  The main program's body, the *tape*, goes on reading the open file as execution or a
search moves ahead; a subroutine runs in the body that holds its definition, as rs274 runs it in
the file it was found in.

rs274's rules, as the reference binary shows them (tests/golden/README.md lists them in full):

* Each scope (the main program, each call) has a table of the control labels it has run: a label
  is bound to its keyword and line the first time it runs; another construct reusing it in the
  same scope is an error.  ``endwhile``, ``break``, ``else``... look the label up there.
* Skipping (a false condition, a definition passed over, a search for a subroutine) reads only
  o-word lines, and those only up to their keyword; other lines are checked for unclosed
  comments and nothing else, an ``M2`` included.
* ``call`` uses a subroutine defined earlier, else ``<name>.ngc`` in the working directory or
  the subroutine path, else the first definition further down the current file.
* A call saves ``#1``-``#30``, passes its arguments as ``#1``...; the others read 0 in the
  subroutine, and the caller's values come back on return.  Nine levels of calls at most.
"""

from __future__ import annotations

import bisect
import os
from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING, NoReturn, Protocol

# (re-exported for the callers that take it from here)
from ..budget import DEFAULT_MAX_ITERATIONS as DEFAULT_MAX_ITERATIONS
from ..errors import (
    NgcEndOfFile,
    NgcError,
    NgcProgramError,
    NgcRuntimeError,
    NgcSemanticError,
    NgcSyntaxError,
)
from ..language.expressions import INT_MIN, c_int, evaluate
from ..language.lexer import C_SPACE
from ..language.oword import KEYWORDS, MAX_ARGS, NOTHING, PROGRAM, OWord, number_label
from ..language.parser import Block, skim_oword
from . import context
from .fastpath import Compiled, Plain
from .machine import Machine
from .snapshot import Context
from .source import CACHE_LINES, CHECKPOINT, ProgramReader, open_program

if TYPE_CHECKING:
    from .parameters import Parameters

# A line of a body: raw text, a compiled plain line (words, motion, N column, source), a block with
# a runner of its own, or a block.
Entry = str | Block | Plain | Compiled


class Host(Protocol):
    """What control flow needs of the interpreter that runs it."""

    machine: Machine
    file: str | None
    percent: bool
    numbered: Iterator[tuple[int, str]]
    reader: ProgramReader | None

    def execute(self, block: Block) -> None: ...

    def _run_plain(self, w: dict[str, float], code: int | None) -> None: ...

    def _checked_line(self, raw: str, number: int) -> str: ...

    def _compile_line(self, raw: str, number: int) -> Plain | Block | Compiled: ...

    def _finish_percent(self) -> None: ...
# Call levels rs274 allows below the main program.
MAX_CALL_DEPTH = 9
# The work budget of one run: loop iterations (endwhile, endrepeat, do-while, continue, M98 L
# repeats), subroutine calls (o-word call, M98) and the iterations of the loops inside codes whose
# counts the program's numbers set (``Machine.work``: canned cycle repeats and pecks, G76 passes,
# G70-G72 passes) count against it, so an endless ``o100 while [1]``, a subroutine that calls
# itself many times per level or a G76 with a depth of 1e-5 ends with an error instead of running
# (practically) forever.  Its default (ngc/budget.py) is the engine dialect's too.
ARGUMENT_PARAMETERS = 30
_LOOPS = ("while", "do")

# The keys (kinds[0]) of the jumps a construct's line may start, for ``Flow.skip`` to leap over.
_LEAPS: dict[str, tuple[str, ...]] = {
    "if": ("elseif",),
    "elseif": ("elseif", "endif"),
    "else": ("endif",),
    "while": ("endwhile",),
    "repeat": ("endrepeat",),
}

# The keywords that end a skip for their label wherever it looks for another: the line runs (an
# ``if`` or a ``while`` there is a second use of the label, an ``else`` of a loop's label is
# refused, a ``do`` goes on).  ``break`` and ``continue`` of the label are checked and passed;
# subroutine lines of the label are passed.
_STRAYS = frozenset(("if", "elseif", "else", "endif", "while", "endwhile", "do", "repeat",
                     "endrepeat"))

# Skipping modes.
BRANCH = 0  # a false condition, a break: control lines must be well formed
DEFINE = 1  # a definition passed over: only nested definitions are noticed
SEEK = 2  # a search for a subroutine to call


class Mark:
    """Where a skip stopped: the line, its o-word and its source text; and whether the skip
    passed a ``break`` line of its label (see ``Flow.broken_while``)."""

    __slots__ = ("broke", "computed", "line", "oword", "source", "stray")

    def __init__(self, line: int, oword: OWord, source: str, broke: bool = False,
                 computed: bool = False, stray: bool = False) -> None:
        self.line = line
        self.oword = oword
        self.source = source
        self.broke = broke
        self.computed = computed
        # The skip ended at a line of its label with another keyword, which runs next.
        self.stray = stray


class Body:
    """The lines of one file from line ``first`` on, read as execution or a search reaches them.

    Lines stay raw text until first executed, then compiled entries.  A body read from a file
    that can be read again keeps only a bounded cache of them and, every :data:`CHECKPOINT` lines,
    the byte position where the next line starts: any line is read again from there
    (:mod:`.source`), so memory stays flat however long the file.  Other input is kept whole.
    """

    __slots__ = ("base", "cache", "count", "file", "first", "head", "interp", "numbered",
                 "positions", "reader")

    def __init__(self, interp: Host, file: str | None, first: int,
                 numbered: Iterator[tuple[int, str]], reader: ProgramReader | None,
                 head: Entry | None = None) -> None:
        self.interp = interp
        self.file = file
        self.first = first
        self.numbered = numbered
        self.cache: dict[int, Entry] = {}
        # The first line when it was read before the body began (the main program's first
        # control line): kept for good, as it cannot be read again.
        self.head = head
        self.count = 0  # the lines read so far
        if head is not None:
            self.cache[first] = head
            self.count = 1
        self.reader = reader if reader is not None and reader.seekable else None
        # positions[j]: where line base + j * CHECKPOINT starts in the file.
        self.base = first + self.count
        self.positions: list[int] = [] if self.reader is None else [self.reader.tell()]

    def fetch(self, number: int) -> Entry | None:
        """Line ``number`` (1-based in its file), or None past the end."""
        entry = self.cache.get(number)
        if entry is not None:
            return entry
        if number < self.first:
            return None
        if number >= self.first + self.count:
            return self._read_to(number)
        return self._read_again(number)

    def _read_to(self, number: int) -> Entry | None:
        last = self.first + self.count - 1
        reader = self.reader
        checked = self.interp._checked_line
        while last < number:
            item = next(self.numbered, None)
            if item is None:
                return None
            last += 1
            self.count += 1
            raw = checked(item[1], last)
            if reader is not None and (last + 1 - self.base) % CHECKPOINT == 0:
                self.positions.append(reader.tell())
            self.keep(last, raw)
        return self.cache.get(number)

    def _read_again(self, number: int) -> Entry | None:
        """A line read before whose entry the cache no longer holds."""
        assert self.reader is not None
        j = (number - self.base) // CHECKPOINT
        start = self.base + j * CHECKPOINT
        lines = self.reader.read_at(self.positions[j], number - start + 1)
        checked = self.interp._checked_line
        for i, raw in enumerate(lines):
            if start + i not in self.cache:
                self.keep(start + i, checked(raw, start + i))
        return self.cache.get(number)

    def keep(self, number: int, entry: Entry) -> None:
        """Hold line ``number``'s entry; a body that can read again starts over when full."""
        cache = self.cache
        if self.reader is not None and len(cache) >= CACHE_LINES:
            cache.clear()
            if self.head is not None:
                cache[self.first] = self.head
        cache[number] = entry

    def last(self) -> int:
        """The number of the last line read so far."""
        return self.first + self.count - 1

    def source(self, number: int) -> str:
        entry = self.fetch(number)
        if entry is None:
            return ""
        if isinstance(entry, str):
            return entry.rstrip(C_SPACE)
        if isinstance(entry, Block):
            return entry.source
        if isinstance(entry, Compiled):
            return entry.block.source
        return str(entry[3])


class Sub:
    """A defined subroutine: its name, the body holding it and the line of its ``sub`` (or
    ``o100``)."""

    __slots__ = ("body", "fanuc", "name", "start")

    def __init__(self, name: str, body: Body, start: int, fanuc: bool = False) -> None:
        self.name = name
        self.body = body
        self.start = start
        self.fanuc = fanuc


class Frame:
    """One scope being run: the main program or one call of a subroutine."""

    __slots__ = ("body", "labels", "pc", "repeats", "saved", "sub")

    def __init__(self, body: Body, pc: int, sub: Sub | None) -> None:
        self.body = body
        self.pc = pc
        self.sub = sub
        # label -> (keyword, line) of each control construct run in this scope.
        self.labels: dict[str, tuple[str, int]] = {}
        self.saved: list[float] = []
        # M98 L: further runs of a Fanuc-style program after this one.
        self.repeats = 0


class _Skimming:
    """Parameters as a definition passed over reads them: an undefined named parameter reads 0
    (rs274)."""

    __slots__ = ("params",)

    def __init__(self, params: Parameters) -> None:
        self.params = params

    def num(self, index: int) -> float:
        return self.params.num(index)

    def named(self, name: str) -> float:
        return self.params.named(name) if self.params.exists(name) else 0.0

    def local(self, name: str) -> float:
        return self.named(name)

    def exists(self, name: str) -> bool:
        return self.params.exists(name)

    def index(self, value: float) -> int:
        return self.params.index(value)


def _quote(block: Block, message: str) -> str:
    return f"{block.line}: {message}: '{block.source}'"


class Flow:
    """The control-flow state of one interpreter: frames, subroutines, the main program's tape."""

    def __init__(self, interp: Host) -> None:
        self.interp = interp
        self.subs: dict[str, Sub] = {}
        self.frames: list[Frame] = []
        self.tape: Body | None = None
        self.opened: list[ProgramReader] = []
        # The folders a subroutine file is looked for in, in order ("." is the current one).
        self.search_path: list[str] = ["."]
        self.fanuc_enabled = True
        self.max_iterations = DEFAULT_MAX_ITERATIONS
        self.max_call_depth = MAX_CALL_DEPTH
        self.iterations = 0
        # Repeat loops under way: (body, line of the repeat) -> runs left.  A repeat left early
        # (a return inside it) keeps its count: the next run of that line counts on from there.
        self.active: dict[tuple[Body, int], int] = {}
        # A break left a while loop, or a skip passed over a break of a while loop under way: the
        # next do loop's closing while does not loop back (rs274 2.9.0~pre1 does so).
        self.broken_while = False
        # A continue is under way: the next endwhile or endrepeat a skip reaches loops back.
        self.continuing = False
        self.resumed: tuple[Frame, int, Body, int] | None = None
        # The line a skip failed at (see ``skip``), until a run going on after it reads past it.
        self.failed_at: int | None = None
        # Where the skip from an o-word (constant label) to a keyword ends, once found.
        self.jumps: dict[tuple[Body, int, str], Mark] = {}
        # The lines of each constant label that skips have passed, ascending, per body.
        self.passed: dict[tuple[Body, str], list[int]] = {}
        self.handlers: dict[str, Callable[[Frame, Block, OWord], None]] = {
            keyword: getattr(self, "_" + (keyword or "program"))
            for keyword in (*KEYWORDS, PROGRAM, NOTHING)
        }

    def fresh(self) -> Flow:
        """A flow for a program about to run: these settings, nothing of a program run before
        (its subroutines, labels, loop counts, work done)."""
        flow = Flow(self.interp)
        flow.search_path = self.search_path
        flow.fanuc_enabled = self.fanuc_enabled
        flow.max_iterations = self.max_iterations
        flow.max_call_depth = self.max_call_depth
        return flow

    # -- running --------------------------------------------------------------------------------
    def enter(self, block: Block, numbered: Iterator[tuple[int, str]],
              reader: ProgramReader | None = None) -> None:
        """The first control line: from here on the program counter runs the program.

        ``reader`` is the file the lines come from, just after this line, if it has one.
        """
        self.tape = Body(self.interp, self.interp.file, block.line, numbered, reader, head=block)
        self.frames = [Frame(self.tape, block.line, None)]

    def run(self) -> None:
        """Run lines until the program ends (M2, M30, ``%``); errors propagate."""
        it = self.interp
        m = it.machine
        frames = self.frames
        execute = it.execute
        plain = it._run_plain
        st = m.state
        while True:
            f = frames[-1]
            number = f.pc
            entry = f.body.fetch(number)
            if entry is None:
                self.end_of_file(f)
            f.pc = number + 1
            if entry.__class__ is str:
                if it.percent and entry.strip() == "%":
                    it._finish_percent()
                    return
                entry = self.compile(f.body, number, entry)
            if entry.__class__ is tuple:
                w, code, m.label, source = entry  # type: ignore[misc]
                m.line = st.line = number
                try:
                    plain(w, code)
                except NgcError as err:
                    raise err.locate(file=f.body.file, line=number, source=source) from None
            elif entry.__class__ is Compiled:
                block, run = entry
                m.label = block.label
                m.line = st.line = number
                try:
                    run()
                except NgcError as err:
                    raise err.locate(file=f.body.file, line=number, source=block.source) from None
            else:
                block = entry  # type: ignore[assignment]
                if block.oword is None:
                    execute(block)
                elif not (block.delete and st.blocks_deleted):
                    self.oword(f, block)
            if m.ended:
                return

    def run_profile(self, call: Block, parse: Callable[[str, int], Block]
                    ) -> tuple[str | None, int, str]:
        """Run the call ``call`` until it returns, each line read afresh with ``parse`` and run on
        the general path (a lathe cycle's profile: see handlers/lathe.py).  Returns the file,
        number and text of the line that returned."""
        frames = self.frames
        depth = len(frames)
        self.oword(frames[-1], call)
        execute = self.interp.execute
        while len(frames) > depth:
            f = frames[-1]
            number = f.pc
            if f.body.fetch(number) is None:
                self.end_of_file(f)
            f.pc = number + 1
            source = f.body.source(number)
            try:
                block = parse(source, number)
            except NgcError as err:
                raise err.locate(file=f.body.file, line=number, source=source) from None
            if block.oword is None:
                execute(block)
            elif not (block.delete and self.interp.machine.state.blocks_deleted):
                self.oword(f, block)
        return f.body.file, number, source

    def compile(self, body: Body, number: int, raw: str) -> Plain | Block | Compiled:
        """Read a line once; the compiled entry replaces the raw text in its body."""
        try:
            entry = self.interp._compile_line(raw, number)
        except NgcError as err:
            raise err.locate(file=body.file, line=number, source=raw.rstrip(C_SPACE)) from None
        body.keep(number, entry)
        return entry

    def end_of_file(self, f: Frame) -> NoReturn:
        """The end of a body: rs274 shows the last line it read, which is the ``endsub`` (or
        ``return``) of a call that returned to the end of the file."""
        last = f.body.last()
        source = f.body.source(last)
        resumed = self.resumed
        if resumed is not None and resumed[0] is f and resumed[1] == f.pc:
            source = resumed[2].source(resumed[3])
        message = ("File ended with no percent sign" if self.interp.percent and len(self.frames) == 1
                   else "File ended with no percent sign or program end")
        raise NgcEndOfFile(message, file=f.body.file, line=last, source=source)

    # -- o-words ----------------------------------------------------------------------------
    def oword(self, f: Frame, block: Block) -> None:
        it = self.interp
        it.machine.label = block.label
        it.machine.line = it.machine.state.line = block.line
        ow = block.oword
        assert ow is not None
        try:
            self.handlers[ow.keyword](f, block, ow)
        except NgcError as err:
            raise err.locate(file=f.body.file, line=block.line, source=block.source) from None

    def again(self) -> None:
        """One more loop iteration or call; past the budget the program is stopped as a runaway."""
        self.iterations += 1
        if self.iterations > self.max_iterations:
            raise NgcRuntimeError(
                f"Work limit reached: {self.max_iterations} loop iterations and subroutine calls; "
                "the program looks like it runs forever (raise the limit with --max-iterations)")

    def label(self, ow: OWord) -> str:
        return ow.label_of(self.interp.machine.params)

    def bind(self, f: Frame, block: Block, label: str, keyword: str) -> None:
        """Record a construct's label in its scope; reusing it elsewhere is an error."""
        bound = f.labels.get(label)
        if bound is None:
            f.labels[label] = (keyword, block.line)
            return
        if bound[1] == block.line:
            return
        if keyword == "if":
            raise NgcSemanticError(_quote(
                block, f"duplicate O-word label - already defined in line {bound[1]}"))
        raise NgcSemanticError(
            f"{block.line}: duplicate O-word label: '{block.source}' - defined in line {bound[1]}")

    def lookup(self, f: Frame, block: Block, label: str, kinds: tuple[str, ...],
               what: str = "label") -> tuple[str, int]:
        bound = f.labels.get(label)
        if bound is None:
            raise NgcSemanticError(_quote(block, "undefined O-word label"))
        if bound[0] not in kinds:
            raise NgcSemanticError(_quote(
                block, f"no matching {what}") + f" (found '{bound[0]}' in line {bound[1]})")
        return bound

    def condition(self, ow: OWord) -> bool:
        return evaluate(ow.args[0], self.interp.machine.params) != 0.0

    def skip(self, f: Frame, start: int, label: str, kinds: tuple[str, ...], mode: int,
             seeking: Block | None = None) -> Mark:
        """Pass over the lines after ``start`` to the o-word ``label`` with one of ``kinds``.

        A skip that fails (not a search) leaves its place in ``failed_at``: a run that goes on
        after the error reads on from there (:mod:`.unwind`)."""
        try:
            return self._skip(f, start, label, kinds, mode, seeking)
        except NgcError as err:
            self.failed_at = err.line if mode != SEEK else None
            raise

    def _skip(self, f: Frame, start: int, label: str, kinds: tuple[str, ...], mode: int,
              seeking: Block | None = None) -> Mark:
        it = self.interp
        body = f.body
        broke = False  # a break line of the label passed
        computed = False  # a computed label was passed over: the skip may end otherwise next time
        params = it.machine.params
        # A search for a subroutine reads the labels it passes as a branch does (an undefined
        # name is an error, even in the body of another subroutine); a definition reads it as 0.
        context = _Skimming(params) if mode == DEFINE else params
        number = start
        while True:
            number += 1
            entry = body.fetch(number)
            if entry is None:
                if mode == SEEK:
                    assert seeking is not None
                    last = body.last()
                    line, source = (last, body.source(last)) if last > start else (
                        seeking.line, seeking.source)
                    raise NgcProgramError(
                        f"EOF in file:{body.file} seeking o-word: o<{label}> "
                        f"from line: {seeking.line if start else 0}",
                        file=body.file, line=line, source=source)
                self.end_of_file(Frame(body, number, None))
            if isinstance(entry, tuple):
                continue
            if isinstance(entry, str):
                if it.percent and body is self.tape and entry.strip() == "%":
                    it._finish_percent()
                    # rs274 names a control label after the subroutine it is in: 'Osub#label'.
                    scope = f.sub.name if f.sub is not None else ""
                    prefix = f"O{scope}#" if mode == BRANCH else "O"
                    raise NgcProgramError(f"Failed to find sub '{prefix}{label}' before EOF",
                                          file=body.file, line=number, source=entry.rstrip(C_SPACE))
                if it.machine.state.blocks_deleted and entry.lstrip(" \t").startswith("/"):
                    continue
                try:
                    ow = skim_oword(entry, number)
                except NgcError as err:
                    if mode == DEFINE and err.message.startswith("Unknown control"):
                        continue
                    raise err.locate(file=body.file, line=number, source=entry.rstrip(C_SPACE)) from None
                source = entry.rstrip(C_SPACE)
            else:
                if entry.delete and it.machine.state.blocks_deleted:
                    continue
                ow = entry.oword
                source = entry.source
            if ow is None or ow.keyword == NOTHING:
                continue
            if mode == BRANCH and ow.label is not None:
                self.note(body, ow.label, number)
                if ow.label != label and ow.keyword in _LEAPS:
                    leap = self.leap(body, number, ow.keyword, label)
                    if leap is not None:
                        number = leap.line - 1  # the construct's end is read as usual
                        continue
            try:
                # rs274 computes the label of every o-word it passes over (o[1/0] is an error
                # there too); a definition passed over reads undefined names as 0.
                computed = computed or ow.label is None
                passed = ow.label_of(context)
                if mode == DEFINE:
                    if ow.keyword in ("sub", PROGRAM):
                        raise NgcSemanticError("Nested subroutine definition")
                    if ow.keyword not in ("endsub", "return") or passed != label:
                        continue
                    value = [evaluate(a, context) for a in ow.args]
                    if ow.keyword == "return":
                        continue
                    st = it.machine.state
                    st.value, st.value_returned = (value[0], 1.0) if value else (0.0, 0.0)
                    return Mark(number, ow, source)
                if passed != label:
                    continue
                if ow.keyword in kinds:
                    return Mark(number, ow, source, broke, computed)
                if mode != BRANCH:
                    continue
                if ow.keyword in _STRAYS:
                    return Mark(number, ow, source, broke, computed, stray=True)
                if ow.keyword in ("break", "continue"):
                    bound = f.labels.get(label)
                    if bound is not None and bound[0] not in _LOOPS:
                        raise NgcSemanticError(
                            f"{number}: no matching while/do label: '{source}' "
                            f"(found '{bound[0]}' in line {bound[1]})")
                    if ow.keyword == "break":
                        broke = True
            except NgcError as err:
                raise err.locate(file=body.file, line=number, source=source) from None

    def note(self, body: Body, label: str, number: int) -> None:
        lines = self.passed.setdefault((body, label), [])
        if not lines or lines[-1] < number:
            lines.append(number)
        else:
            i = bisect.bisect_left(lines, number)
            if i == len(lines) or lines[i] != number:
                lines.insert(i, number)

    def leap(self, body: Body, number: int, keyword: str, label: str) -> Mark | None:
        """A skip for ``label`` passing the construct at ``number`` may leap to where a skip from
        it ended before, when no line of ``label`` lies between: nested loops and conditionals
        are skipped in time linear in their size, not quadratic in their depth."""
        for kind in _LEAPS[keyword]:
            found = self.jumps.get((body, number, kind))
            if found is None:
                continue
            lines = self.passed.get((body, label))
            if lines:
                i = bisect.bisect_right(lines, number)
                if i < len(lines) and lines[i] < found.line:
                    return None
            return found
        return None

    def jump(self, f: Frame, start: int, ow: OWord, label: str, kinds: tuple[str, ...]) -> Mark:
        """``skip`` (BRANCH) from line ``start`` (``ow``'s line), remembered when the label is
        constant."""
        key = (f.body, start, kinds[0])
        found = self.jumps.get(key) if ow.label is not None else None
        if found is None:
            found = self.skip(f, start, label, kinds, BRANCH)
            if ow.label is not None and not found.computed:
                self.jumps[key] = found
        if found.broke:
            self.broken_while = True
        return found

    # -- conditionals -------------------------------------------------------------------------
    def _if(self, f: Frame, block: Block, ow: OWord) -> None:
        # rs274 evaluates a line's condition (or count) before it checks the label.
        label = self.label(ow)
        holds = self.condition(ow)
        self.bind(f, block, label, "if")
        if not holds:
            self.next_branch(f, block.line, ow, label)

    def past(self, f: Frame, start: int, ow: OWord, label: str, kinds: tuple[str, ...]
             ) -> Mark | None:
        """``jump`` and go on after the line found; a stray line of the label found instead runs
        next (None)."""
        found = self.jump(f, start, ow, label, kinds)
        if found.stray:
            f.pc = found.line
            return None
        f.pc = found.line + 1
        return found

    def next_branch(self, f: Frame, start: int, ow: OWord, label: str) -> None:
        """A false condition: on to the next ``elseif`` that holds, the ``else``, or the ``endif``."""
        while True:
            found = self.past(f, start, ow, label, ("elseif", "else", "endif"))
            if found is None:
                return
            other = found.oword
            if other.keyword != "elseif":
                return
            try:
                if not other.args:
                    raise NgcSyntaxError("Left bracket missing after 'elseif'")
                if self.condition(other):
                    return
            except NgcError as err:
                raise err.locate(file=f.body.file, line=found.line, source=found.source) from None
            start, ow = found.line, other

    def _elseif(self, f: Frame, block: Block, ow: OWord) -> None:
        label = self.label(ow)
        self.lookup(f, block, label, ("if",), "'if' label")
        if ow.args:
            self.condition(ow)  # rs274 evaluates it even though the branch is over
        self.past(f, block.line, ow, label, ("endif",))

    def _else(self, f: Frame, block: Block, ow: OWord) -> None:
        label = self.label(ow)
        self.lookup(f, block, label, ("if",), "'if' label")
        self.past(f, block.line, ow, label, ("endif",))

    def _endif(self, f: Frame, block: Block, ow: OWord) -> None:
        label = self.label(ow)
        bound = f.labels.get(label)
        if bound is None:
            raise NgcSemanticError(_quote(block, "undefined O-word label"))
        if bound[0] != "if":
            # rs274 names the label as it keys it: after the name of the subroutine it is in.
            scope = f.sub.name if f.sub is not None else ""
            raise NgcSemanticError(
                f"{block.line}: no matching label: '{scope}#{label}' (found '{bound[0]}' in line "
                f"{bound[1]}): '{block.source}'")

    # -- loops ---------------------------------------------------------------------------------
    def _while(self, f: Frame, block: Block, ow: OWord) -> None:
        label = ow.label if ow.label is not None else self.label(ow)
        holds = self.condition(ow)
        bound = f.labels.get(label)
        if bound is not None and bound[0] == "do" and bound[1] != block.line:
            # The end of a do-while loop.
            if holds and not self.broken_while:
                self.again()
                f.pc = bound[1] + 1
            self.broken_while = False
            return
        if bound is None or bound[1] != block.line:
            self.bind(f, block, label, "while")
        if not holds:
            self.end_loop(f, block.line, ow, label, "endwhile", block.line)

    def end_loop(self, f: Frame, start: int, ow: OWord, label: str, end: str, top: int) -> None:
        """Skip to the loop's ``end`` line and run it as rs274 runs an ``endwhile`` or
        ``endrepeat`` that a skip reached: with a ``continue`` noted it loops back to ``top`` (the
        note is done), else the loop is over.  (A ``continue`` of a do loop is noted and never
        done, so the next ``break`` or end of a while or repeat loop loops back once more.)"""
        found = self.past(f, start, ow, label, (end,))
        if found is not None and self.continuing:
            self.continuing = False
            self.again()
            f.pc = top

    def _endwhile(self, f: Frame, block: Block, ow: OWord) -> None:
        label = ow.label if ow.label is not None else self.label(ow)
        bound = f.labels.get(label)
        if bound is None or bound[0] != "while":
            bound = self.lookup(f, block, label, ("while",))
        self.again()
        f.pc = bound[1]

    def _do(self, f: Frame, block: Block, ow: OWord) -> None:
        # rs274 binds a label to the first ``do`` that uses it and checks nothing: a later ``do``
        # of the label goes on, and its ``while`` loops back to the first one.
        f.labels.setdefault(self.label(ow), ("do", block.line))

    def _repeat(self, f: Frame, block: Block, ow: OWord) -> None:
        label = self.label(ow)
        count = evaluate(ow.args[0], self.interp.machine.params)  # each run, a left count too
        self.bind(f, block, label, "repeat")
        key = (f.body, block.line)
        left = self.active.get(key)
        if left is None:
            # Halves to even, through a C int: a count past its range (or NaN) runs no time.
            left = c_int(round(count)) if count - count == 0.0 else INT_MIN
        if left > 0:
            self.active[key] = left - 1
        else:
            self.active.pop(key, None)
            self.end_loop(f, block.line, ow, label, "endrepeat", block.line)

    def _endrepeat(self, f: Frame, block: Block, ow: OWord) -> None:
        line = self.lookup(f, block, self.label(ow), ("repeat",))[1]
        self.again()
        f.pc = line

    def _break(self, f: Frame, block: Block, ow: OWord) -> None:
        label = self.label(ow)
        keyword, top = self.lookup(f, block, label, _LOOPS, "while/do label")
        # rs274 notes the break until the closing ``while`` of a do loop runs, which then does
        # not loop back: the do loop's own (the break's skip ends on it), or, after a while loop,
        # the next one.
        self.broken_while = True
        if keyword == "while":
            self.end_loop(f, block.line, ow, label, "endwhile", top)
        else:
            f.pc = self.jump(f, block.line, ow, label, ("while",)).line

    def _continue(self, f: Frame, block: Block, ow: OWord) -> None:
        label = self.label(ow)
        keyword, line = self.lookup(f, block, label, _LOOPS, "while/do label")
        self.continuing = True
        if keyword == "while":
            self.end_loop(f, block.line, ow, label, "endwhile", line)
        else:
            # rs274 skips to the do's ``while`` and runs it: it loops back when its condition
            # holds, unless the skip passed a ``break`` of the loop (or a stray line ran).
            f.pc = self.jump(f, block.line, ow, label, ("while",)).line

    # -- subroutines ---------------------------------------------------------------------------
    def _sub(self, f: Frame, block: Block, ow: OWord) -> None:
        """A definition met in sequence: known from here on; run on after its ``endsub``."""
        if f.sub is not None:
            return  # rs274 runs over a ``sub`` line inside a subroutine it entered
        label = self.label(ow)
        known = self.subs.get(label)
        if known is not None:
            file = f.body.file
            if known.start == block.line and known.body is f.body:
                raise NgcSemanticError(
                    f"File:{file} line:{block.line} sub: o|{label}| found in illegal location")
            raise NgcSemanticError(
                f"File:{file} line:{block.line} redefining sub: o|{label}| already defined in "
                f"file:{known.body.file}")
        end = self.skip(f, block.line, label, ("endsub",), DEFINE)
        self.subs[label] = Sub(label, f.body, block.line)
        f.pc = end.line + 1
        # rs274 forgets here that a call has returned: a ``return`` or ``endsub`` in the main
        # program after this definition is refused as before any call.
        self.resumed = None

    def _call(self, f: Frame, block: Block, ow: OWord) -> None:
        it = self.interp
        params = it.machine.params
        label = self.label(ow)
        if len(ow.args) > MAX_ARGS:
            raise NgcSemanticError("Too many subroutine parameters")
        args = [evaluate(a, params) for a in ow.args]
        sub = self.subs.get(label) or self.find_for_call(f, block, label, args)
        if sub.fanuc:
            self.refuse(sub, "Fanuc 'O....' subroutine must be called with 'M98'")
        self.push(Frame(sub.body, sub.start + 1, sub))
        numbered = params.numbered
        frame = self.frames[-1]
        frame.saved = numbered[1 : ARGUMENT_PARAMETERS + 1]
        numbered[1 : ARGUMENT_PARAMETERS + 1] = [0.0] * ARGUMENT_PARAMETERS
        numbered[1 : len(args) + 1] = args
        params.locals.append({})

    def push(self, frame: Frame) -> None:
        if len(self.frames) > self.max_call_depth:
            raise NgcRuntimeError("Too many subroutine levels")
        self.again()
        self.frames.append(frame)
        self.interp.machine.contexts.append(Context())
        self.interp.machine.state.call_level = len(self.frames) - 1

    def refuse(self, sub: Sub, message: str) -> NoReturn:
        raise NgcSemanticError(message, file=sub.body.file, line=sub.start,
                               source=sub.body.source(sub.start))

    def find_for_call(self, f: Frame, block: Block, label: str, args: list[float]) -> Sub:
        """``find`` as rs274 runs it for a call: with the call's parameters in place, #1-#30 the
        arguments (the others 0) and no local named parameter, so the labels the search passes
        read those (a local name of the caller is not defined there)."""
        params = self.interp.machine.params
        numbered = params.numbered
        saved = numbered[1 : ARGUMENT_PARAMETERS + 1]
        numbered[1 : ARGUMENT_PARAMETERS + 1] = [0.0] * ARGUMENT_PARAMETERS
        numbered[1 : len(args) + 1] = args
        params.locals.append({})
        try:
            return self.find(f, block, label, fanuc=False)
        finally:
            params.locals.pop()
            numbered[1 : ARGUMENT_PARAMETERS + 1] = saved

    def find(self, f: Frame, block: Block, label: str, fanuc: bool) -> Sub:
        """A subroutine not defined yet: ``<label>.ngc``, else further down this file."""
        path = self.sub_file(label)
        if path is not None:
            body = self.load(path)
            found = self.skip(Frame(body, 0, None), 0, label, ("sub", PROGRAM), SEEK, block)
        else:
            body = f.body
            found = self.skip(f, block.line, label, ("sub", PROGRAM), SEEK, block)
        sub = Sub(label, body, found.line, fanuc=found.oword.keyword == PROGRAM)
        self.subs[label] = sub
        return sub

    def sub_file(self, label: str) -> str | None:
        """``<label>.ngc`` in the first folder of the search path that has it: as rs274, the
        working directory, PROGRAM_PREFIX, then SUBROUTINE_PATH (:meth:`Interpreter.configure`;
        ngc's other commands search as a machine does, :func:`ngc.options.new_interpreter`).

        A name is a path inside those folders: one that is absolute or climbs out of them
        (``o<../x> call``) is refused, so program text reads no file elsewhere.
        """
        shown = label + ".ngc"  # as the program has it, for messages
        name = self.interp.machine.file_name(shown)  # as the operating system takes it
        if os.path.isabs(name) or os.path.normpath(name).split(os.sep)[0] == os.pardir:
            raise NgcSemanticError(
                f"Subroutine file '{shown}' is outside the working directory and the subroutine "
                "path")
        for folder in self.search_path:
            if os.path.isfile(name if folder == "." else os.path.join(folder, name)):
                return shown if folder == "." else os.path.join(folder, shown)
        return None

    def load(self, path: str) -> Body:
        """A subroutine file, read as its lines are needed (it stays open until ``close``)."""
        try:
            reader = open_program(self.interp.machine.file_name(path))
        except OSError as exc:
            raise NgcRuntimeError(f"Unable to open file {path}: {exc.strerror}") from None
        self.opened.append(reader)
        return Body(self.interp, path, 1, enumerate(reader, 1), reader)

    def close(self) -> None:
        """Close the subroutine files the run opened."""
        for reader in self.opened:
            reader.close()
        self.opened.clear()

    def _return(self, f: Frame, block: Block, ow: OWord) -> None:
        it = self.interp
        if f.sub is None:
            if self.resumed is None:  # no call has returned yet
                # rs274 sets #<_value> first (seen when the run goes on after the error, -n 0)
                self._set_value(ow)
                raise NgcSemanticError(_quote(block, "not in a subroutine definition"))
            # rs274, once a call has returned: ``return`` in the main program sets #<_value>
            # and goes on; ``endsub`` is refused.
            if ow.keyword == "endsub":
                raise NgcSemanticError("Not in subroutine definition")
            self._set_value(ow)
            return
        if f.sub.fanuc:
            raise NgcSemanticError("Fanuc 'O....' subroutine definition must end with 'M99'")
        self._set_value(ow)
        it.machine.params.numbered[1 : ARGUMENT_PARAMETERS + 1] = f.saved
        it.machine.params.locals.pop()
        self.pop()

    _endsub = _return

    def _set_value(self, ow: OWord) -> None:
        """#<_value> and #<_value_returned> from a ``return`` or ``endsub``."""
        st = self.interp.machine.state
        if ow.args:
            st.value = evaluate(ow.args[0], self.interp.machine.params)
            st.value_returned = 1.0
        else:
            st.value = st.value_returned = 0.0

    def pop(self) -> None:
        context.leave(self.interp.machine)  # M73's restore comes first
        left = self.frames.pop()
        caller = self.frames[-1]
        # Where the caller resumes, and the last line read before (for the end-of-file message).
        self.resumed = (caller, caller.pc, left.body, left.pc - 1)
        self.interp.machine.state.call_level = len(self.frames) - 1

    def _program(self, f: Frame, block: Block, ow: OWord) -> None:
        """``o100`` alone: a program title or the start of a numbered program; nothing to run."""
        if not self.fanuc_enabled:
            raise NgcSemanticError(
                "DISABLE_FANUC_STYLE_SUB disabled in INI file, but found bare O-word")

    def _nothing(self, f: Frame, block: Block, ow: OWord) -> None:
        """``o<name`` without its ``>``: rs274 lets the line pass."""

    # -- Fanuc style: M98 / M99 ------------------------------------------------------------------
    def fanuc(self, block: Block, code: int, p: float | None, loops: float | None) -> bool:
        """Run ``M98 P- L-`` or ``M99``; False when M99 ends the main program (like M2)."""
        if self.tape is None:
            self.enter(block, self.interp.numbered, self.interp.reader)
            self.frames[-1].pc = block.line + 1
        f = self.frames[-1]
        if code == 99:
            return self.m99(f)
        if not self.fanuc_enabled:
            raise NgcSemanticError("DISABLE_FANUC_STYLE_SUB set in INI file, but found m98")
        if p is None:
            raise NgcSemanticError("Found 'm98' code with no P-word")
        count = 1 if loops is None else int(loops)
        if count < 0:
            raise NgcSemanticError("Negative l word used")
        label = number_label(p)
        sub = self.subs.get(label) or self.find(f, block, label, fanuc=True)
        if not sub.fanuc:
            self.refuse(sub, "'O.... sub' subroutine must be called with 'O.... call'")
        if count == 0:
            return True
        self.push(Frame(sub.body, sub.start + 1, sub))
        self.frames[-1].repeats = count - 1
        return True

    def m99(self, f: Frame) -> bool:
        sub = f.sub
        if sub is None:
            return False
        if not sub.fanuc:
            raise NgcSemanticError(
                "'O.... endsub' or 'O.... return' must follow 'O.... sub' subroutine definition")
        if f.repeats > 0:
            self.again()
            f.repeats -= 1
            f.pc = sub.start + 1
            context.leave(self.interp.machine)  # each run is a call of its own (M70-M73)
            self.interp.machine.contexts.append(Context())
        else:
            self.pop()
        return True
