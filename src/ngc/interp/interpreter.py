"""The interpreter: runs blocks through resolve -> check -> convert, in LinuxCNC's order.

``Interpreter.execute`` takes one parsed :class:`~ngc.language.parser.Block`;
``Interpreter.run`` streams a whole program (``%`` delimiters, program end, end-of-file rules).
Canonical operations go to the sink the interpreter is given.  All state lives on the instance.
"""

from __future__ import annotations

import copy
from collections.abc import Callable, Iterable, Iterator
from typing import TYPE_CHECKING, TextIO

from ..canon import ops
from ..errors import NgcEndOfFile, NgcError, NgcOpenError, NgcSemanticError, NgcSyntaxError
from ..language import codes
from ..language.codes import LINUXCNC, CodeTable
from ..language.lexer import C_SPACE
from ..language.parser import Block, parse_line
from .check import check
from .dispatch import Dispatcher
from .fastpath import Compiled, FastPath, Plain
from .flow import DEFAULT_MAX_ITERATIONS, MAX_CALL_DEPTH, Flow
from .frames import to_program
from .handlers import coordinates, program
from .machine import Machine
from .parameters import COORD_SYSTEM, DEBUG_ENABLE, G92_APPLIED, Parameters
from .resolve import Resolved, resolve
from .snapshot import Context
from .source import ProgramReader
from .state import State
from .unwind import unwind

if TYPE_CHECKING:
    from ..canon.ops import Op, Sink
    from ..config.ini import Ini, Rs274ngcSettings
    from ..config.probe import Probe

# rs274 reads lines into a 256-byte buffer: a line of 253 characters or more is refused.
MAX_LINE = 252


def _too_long_echo(raw: str) -> str:
    """What rs274 echoes of a line that is too long: what its buffer held."""
    return raw[:254] if len(raw) > MAX_LINE + 1 else raw + "\n"


class Interpreter:
    """One RS274/NGC interpreter: a machine (state, parameters, the sink for its canonical
    operations), a dialect's code table, and the control flow that runs programs on them."""

    def __init__(
        self,
        sink: Sink,
        *,
        block_delete: bool = False,
        max_iterations: int = DEFAULT_MAX_ITERATIONS,
        max_call_depth: int = MAX_CALL_DEPTH,
        table: CodeTable = LINUXCNC,
        fast: bool = True,
        write_files: bool = True,
        probe: Probe | None = None,
    ) -> None:
        """``max_iterations`` is the work budget of a run: loop iterations, subroutine calls and
        the iterations of codes' loops (cycle passes, pecks; a runaway program is an error);
        ``max_call_depth`` the subroutine levels below the main program (rs274: 9); ``table`` is
        the dialect's code table; ``fast=False`` sends every line down the general path (the
        fast path gives the same results; see :mod:`.fastpath`); ``write_files=False`` keeps the
        program's log files (LOGOPEN, PROBEOPEN) from being written; ``probe`` is a simulated probe
        input for G38.2-G38.5 (:class:`ngc.config.probe.Surfaces`; None: rs274's, which never
        trips)."""
        self.machine = m = Machine(sink, write_files)
        m.probe = probe
        m.run_text = self._run_text
        m.run_profile = self._run_profile
        m.work = self._work
        self.sink = sink
        self.state: State = m.state
        self.state.blocks_deleted = block_delete
        self.params: Parameters = m.params
        self.table = table
        self.dispatcher = Dispatcher(table)
        self.fast: FastPath | None = (
            FastPath(m, table, self.execute, self.dispatcher) if fast else None
        )
        self.file: str | None = None
        self.percent = False
        self.finished = False  # the closing % was read
        self.flow = Flow(self)
        self.flow.max_iterations = max_iterations
        self.flow.max_call_depth = max_call_depth
        self.numbered: Iterator[tuple[int, str]] = iter(())
        self.reader: ProgramReader | None = None
        # Told of each error; True: the run goes on with the next line (rs274's -n 0 and -n 1).
        self.recover: Callable[[NgcError], bool] | None = None

    # The machine's running block and program files, as attributes of the interpreter too.
    @property
    def label(self) -> str:
        return self.machine.label

    @label.setter
    def label(self, value: str) -> None:
        self.machine.label = value

    @property
    def line(self) -> int:
        return self.machine.line

    @line.setter
    def line(self, value: int) -> None:
        self.machine.line = value

    @property
    def ended(self) -> bool:
        return self.machine.ended

    @ended.setter
    def ended(self, value: bool) -> None:
        self.machine.ended = value

    @property
    def log(self) -> TextIO | None:
        return self.machine.log

    @property
    def probe_log(self) -> TextIO | None:
        return self.machine.probe_log

    def close(self) -> None:
        """Release what the program opened (log files, subroutine files)."""
        self.machine.close()
        self.flow.close()

    def emit(self, op: Op) -> None:
        self.machine.emit(op)

    # -- program ------------------------------------------------------------------------------
    def configure(self, settings: Rs274ngcSettings, ini: Ini | None = None) -> None:
        """Apply INI settings: the subroutine path, Fanuc-style programs, ``#<_ini[...]...>``."""
        prefix = settings.program_prefix_dir
        self.flow.search_path = [".", *(() if prefix is None else (prefix,)),
                                 *settings.subroutine_path]
        self.flow.fanuc_enabled = not settings.disable_fanuc_style_sub
        self.params.ini = ini if settings.ini_vars else None
        self.state.orient_offset = settings.orient_offset

    def load_parameters(self, values: dict[int, float], disable_g92: bool = False) -> None:
        """Parameters read from a parameter file, and the origins and offsets they hold."""
        numbered = self.params.numbered
        for number, value in values.items():
            numbered[number] = value
        numbered[DEBUG_ENABLE] = 1.0
        if disable_g92:
            numbered[G92_APPLIED : G92_APPLIED + 10] = [0.0] * 10
        if not 1.0 <= numbered[COORD_SYSTEM] < 10.0:
            numbered[COORD_SYSTEM] = 1.0
        coordinates.load_system(self.machine, int(numbered[COORD_SYSTEM]))
        coordinates.load_g92(self.machine)
        self.state.pos = to_program(self.state, [0.0] * len(self.state.pos))

    def startup(self, units: bool = True) -> None:
        """The canonical calls of interpreter initialisation (rs274 prints them first)."""
        st = self.state
        if units:
            self.emit(ops.UseLengthUnits("CANON_UNITS_MM"))
        self.emit(ops.SetG5xOffset(st.coord_index, *st.g5x))
        self.emit(ops.SetG92Offset(*st.g92))
        self.emit(ops.SetXYRotation(st.rotation))
        self.emit(ops.SetFeedReference("CANON_XYZ"))

    def run(
        self,
        lines: Iterable[str],
        file: str | None = None,
        on_open: Callable[[], None] | None = None,
        *,
        reader: ProgramReader | None = None,
    ) -> None:
        """Execute a program line by line until M2/M30, the closing ``%`` or an error.

        ``lines`` may be a :class:`~ngc.interp.source.ProgramReader`, or lines read from one
        given as ``reader`` (a progress display wraps them, say): control flow then reads lines
        again from the file instead of keeping them, so memory stays flat in the program's length.

        The program is "open" once its first non-blank line is read (``on_open`` is called then);
        an empty program raises :class:`NgcOpenError`.  Raises :class:`NgcError` (with file and
        line) on the first error.  Plain lines stream; from the first o-word line (or M98/M99)
        on, :mod:`.flow` runs the rest of the program.  Files the program opened (logs) are
        closed at the end, whatever the outcome.
        """
        if reader is None and isinstance(lines, ProgramReader):
            reader = lines
        self.reader = reader
        self.machine.encoding = None if reader is None else (reader.encoding, reader.errors)
        try:
            self._run(lines, file, on_open)
        finally:
            self.close()

    def _run(
        self,
        lines: Iterable[str],
        file: str | None,
        on_open: Callable[[], None] | None,
    ) -> None:
        self.file = file
        self.ended = self.finished = False
        # Each program its own control flow; the machine's modes and parameters carry over from
        # a program run before (and the scopes of calls an error left are dropped).
        self.flow = self.flow.fresh()
        self.machine.state.call_level = 0
        del self.params.locals[1:]
        self.machine.contexts = [Context()]
        numbered = enumerate(lines, 1)
        self.numbered = numbered
        number, raw = 0, ""
        opened = False
        try:
            for number, raw in numbered:
                raw = self._checked(raw, number, opening=True)
                if raw.strip():
                    opened = True
                    break
        except NgcError as err:
            raise err.locate(file=file, line=number + 1, source="") from None
        if not opened:
            raise NgcOpenError("File ended with no percent sign", file=file, line=number,
                               source=raw.rstrip("\r\n"))
        if on_open is not None:
            on_open()
        self.percent = percent = raw.strip() == "%"
        flow = self.flow
        if not percent:
            try:
                self._execute_raw(raw, number)
            except NgcError as err:
                if not self._recovered(err):
                    raise
            if self.ended or flow.tape is not None:
                self._finish_run()
                return
        line = self.fast.line if self.fast is not None else None
        m = self.machine
        while True:
            try:
                for number, raw in numbered:
                    raw = raw.rstrip("\n")
                    if "\x00" in raw or len(raw) > MAX_LINE:
                        raw = self._checked(raw, number, opening=False)
                    if percent and raw.strip() == "%":
                        self._finish_percent()
                        return
                    if line is None or not line(raw, number):
                        self.execute_line(raw, number)
                    if m.ended or flow.tape is not None:
                        break
                else:
                    message = "File ended with no percent sign" if percent else (
                        "File ended with no percent sign or program end"
                    )
                    raise NgcEndOfFile(message, file=file, line=number, source=raw.rstrip(C_SPACE))
            except NgcError as err:
                # The fast path's errors know neither their line nor their file; the others do.
                err = err.locate(file=file, line=number, source=raw.rstrip(C_SPACE))
                if self._recovered(err):
                    if m.ended or flow.tape is not None:
                        break
                    continue  # on with the next line
                raise err from None
            break
        self._finish_run()

    def _recovered(self, err: NgcError) -> bool:
        """An error the run goes on after (``recover`` says so; rs274's ``-n 0``): the calls
        under way are left, the subroutines and labels forgotten (:mod:`.unwind`)."""
        if self.recover is None or isinstance(err, NgcEndOfFile) or not self.recover(err):
            return False
        self.machine.held.clear()  # rs274 drops the moves cutter compensation holds back
        if self.flow.tape is not None:
            unwind(self.flow)
        return True

    def _finish_run(self) -> None:
        """The program ended, or control flow took it over: it runs the rest, to the end."""
        while not self.ended:
            try:
                self.flow.run()
            except NgcError as err:
                if not self._recovered(err):
                    raise
            else:
                break
        self._after_end()

    def _after_end(self) -> None:
        """After M2/M30 in a ``%`` program rs274 looks for the closing ``%`` in the lines left."""
        if not self.percent or not self.ended or self.finished:
            return
        tape = self.flow.tape
        if tape is not None and self.flow.frames and self.flow.frames[-1].body is tape:
            for number in range(self.line + 1, tape.last() + 1):
                if tape.source(number).strip() == "%":
                    return
        for _, raw in self.numbered:
            if raw.strip() == "%":
                return
        self.label = "N..... "
        self.emit(ops.Comment("interpreter: percent sign missing from end of file"))

    def _finish_percent(self) -> None:
        """The closing ``%`` of a ``%``-delimited program."""
        self.label = "N..... "
        self.emit(ops.Finish())
        self.ended = self.finished = True

    def _checked_line(self, raw: str, number: int) -> str:
        """A line read after the program opened (see :meth:`_checked`)."""
        raw = raw.rstrip("\n")
        if "\x00" in raw or len(raw) > MAX_LINE:
            raw = self._checked(raw, number, opening=False)
        return raw

    def _checked(self, raw: str, number: int, opening: bool) -> str:
        """A line as rs274 reads it: up to a NUL byte, refused when too long."""
        raw = raw.rstrip("\n")
        if "\x00" in raw:
            raw = raw[: raw.index("\x00")]  # rs274 reads a line as a C string
        if len(raw) > MAX_LINE:
            error = NgcOpenError if opening else NgcSyntaxError
            raise error("Command too long", file=self.file, line=number, source=_too_long_echo(raw))
        return raw

    def _execute_raw(self, raw: str, number: int) -> None:
        try:
            if self.fast is not None and self.fast.line(raw, number):
                return
        except NgcError as err:
            raise err.locate(file=self.file, line=number, source=raw.rstrip(C_SPACE)) from None
        self.execute_line(raw, number)

    def _compile_line(self, raw: str, number: int) -> Plain | Block | Compiled:
        """A line read once for running many times (a loop or subroutine body)."""
        if self.fast is None:
            return self.parse(raw, number)
        return self.fast.compile(raw, number, self.parse)

    def parse(self, raw: str, number: int) -> Block:
        try:
            return parse_line(raw, number, self.table, self.fast is not None)
        except NgcError:
            # rs274 computes values as it reads: one that fails before the read error wins.
            parse_line(raw, number, self.table, False, eager=self.params)
            raise

    def execute_line(self, raw: str, number: int) -> None:
        try:
            block = self.parse(raw, number)
        except NgcError as err:
            raise err.locate(file=self.file, line=number, source=raw.rstrip(C_SPACE)) from None
        self.execute(block)

    def execute(self, block: Block) -> None:
        """Resolve, check and convert one block."""
        if block.delete and self.state.blocks_deleted:
            return
        if block.oword is not None:
            self.flow.enter(block, self.numbered, self.reader)
            return
        m = self.machine
        m.label = block.label
        m.line = self.state.line = block.line
        try:
            r = block.resolved or resolve(block, self.params, self.table)
            fast = self.fast
            if fast is not None and fast.is_plain(r):
                fast.convert(r.w, r.g.get(codes.G_MOTION))
                return
            if r.assigns:
                assign = self.params.assign
                for target, value in r.assigns:
                    assign(target, value)
                if not (r.g or r.m or r.w) and r.comment is None:
                    return  # parameter settings only
            check(self.state, r, self.table)
            if codes.M_USER in r.m and r.m[codes.M_USER] in (98, 99):
                self._convert_fanuc(block, r)
                return
            self.dispatcher.convert(m, r)
        except NgcError as err:
            raise err.locate(file=self.file, line=block.line, source=block.source) from None

    def _work(self) -> None:
        """One iteration of a code's loop (``Machine.work``), against this run's budget."""
        self.flow.again()

    def _run_text(self, text: str) -> None:
        """A line a handler has the interpreter run (an M72 restore), at the running line."""
        self.execute(self.parse(text, self.machine.line))

    def _run_profile(self, q: float) -> tuple[str | None, int, str]:
        """A lathe cycle's ``o<q> call``, every line of it read and run as a profile line (see
        handlers/lathe.py): rs274 runs the line ``O<q> CALL`` (a Q that is not a whole number
        fails as that line).  Returns where the subroutine returned (file, line, text)."""
        m = self.machine
        text = f"O{q:f} CALL"
        try:
            block = parse_line(text, m.line, self.table, False)
        except NgcError as err:
            raise err.locate(file=self.file, line=m.line, source=text) from None
        flow = self.flow
        if flow.tape is None:  # the first o-word line of the program: control flow starts here
            flow.enter(block, self.numbered, self.reader)
            flow.frames[-1].pc = m.line + 1
        fast, self.fast = self.fast, None
        try:
            return flow.run_profile(block, self.parse_profile)
        finally:
            self.fast = fast

    def parse_profile(self, raw: str, number: int) -> Block:
        """A line of a lathe cycle's profile (U and W are words there)."""
        return parse_line(raw, number, self.table, False, profile=True)

    def _run_plain(self, w: dict[str, float], code: int | None) -> None:
        """A compiled plain line (see :meth:`FastPath.convert`)."""
        assert self.fast is not None
        self.fast.convert(w, code)

    def _convert_fanuc(self, block: Block, r: Resolved) -> None:
        """M98 calls at once (the rest of its line is not run); M99 runs its line, then returns."""
        code = r.m[codes.M_USER]
        if code == 98:
            self.flow.fanuc(block, 98, r.w.get("p"), r.w.get("l"))
            return
        rest = copy.copy(r)
        rest.m = {group: value for group, value in r.m.items() if group != codes.M_USER}
        in_sub = self.flow.tape is not None and len(self.flow.frames) > 1
        if in_sub and (rest.g or rest.w or rest.m):
            self.dispatcher.convert(self.machine, rest)
            raise NgcSemanticError("Bug:  Reached convert_stop() from M99 as subprogram return")
        if not in_sub:
            self.dispatcher.convert(self.machine, rest)  # in a subprogram the return comes first
        if not self.flow.fanuc(block, 99, None, None):
            program.program_end(self.machine, 2)
