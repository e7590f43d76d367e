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
from ..errors import NgcError, NgcOpenError, NgcProgramError, NgcSemanticError, NgcSyntaxError
from ..language import codes
from ..language.parser import Block, n_label, parse_line, split_plain, words_of
from ..language.words import FREE_LETTERS, G_BY_VALUE, Words
from .check import check
from .compiled import specialise
from .flow import DEFAULT_MAX_ITERATIONS, MAX_CALL_DEPTH, Flow
from .handlers import coordinates, modes, motion, program
from .parameters import COORD_SYSTEM, DEBUG_ENABLE, G92_APPLIED, Parameters
from .resolve import Resolved, resolve
from .state import State

if TYPE_CHECKING:
    from ..canon.ops import Op, Sink
    from ..config.ini import Ini, Rs274ngcSettings

_new = tuple.__new__
PLAIN_CACHE_SIZE = 1024
# rs274 reads lines into a 256-byte buffer: a line of 253 characters or more is refused.
MAX_LINE = 252


def _too_long_echo(raw: str) -> str:
    """What rs274 echoes of a line that is too long: what its buffer held."""
    return raw[:254] if len(raw) > MAX_LINE + 1 else raw + "\n"

_AXES = frozenset(codes.AXIS_LETTERS)
# Lines of only these letters and a motion code (or none) take the fast path ...
_PLAIN_LETTERS = FREE_LETTERS
# ... and, with G2/G3 on the line, these.
_ARC_LETTERS = FREE_LETTERS | frozenset("ijkrp")
_ARCS = (20, 30)
_MOTION_BY_VALUE = {v: code for v, (group, code) in G_BY_VALUE.items() if group == codes.G_MOTION}


def _plain_entry(
    found: tuple[dict[str, float], float | None, str | None],
) -> tuple[dict[str, float], int | None, str] | None:
    """What :func:`split_plain` read, as (words, motion code, N column) when the line can take
    :meth:`Interpreter.convert_plain`: a motion code (or none) and only its plain letters."""
    w, g, digits = found
    code = None if g is None else _MOTION_BY_VALUE.get(g)
    if (g is None or code is not None) and (
        _PLAIN_LETTERS.issuperset(w) or (code in _ARCS and _ARC_LETTERS.issuperset(w))
    ):
        return w, code, "N..... " if digits is None else n_label(digits)
    return None


class Interpreter:
    """One RS274/NGC interpreter: state, parameters and a sink for its canonical operations."""

    def __init__(
        self,
        sink: Sink,
        *,
        block_delete: bool = False,
        max_iterations: int = DEFAULT_MAX_ITERATIONS,
        max_call_depth: int = MAX_CALL_DEPTH,
    ) -> None:
        """``max_iterations`` bounds the loop iterations of a run (a runaway loop is an error);
        ``max_call_depth`` the subroutine levels below the main program (rs274: 9)."""
        self.sink = sink
        self.state = State()
        self.state.blocks_deleted = block_delete
        self.params = Parameters(self.state)
        self.params.numbered[COORD_SYSTEM] = 1.0
        self.label = "N..... "
        self.line = 0
        self.ended = False
        self.file: str | None = None
        # Plain lines already read: raw text -> (words, motion code, N column).
        self._plain_lines: dict[str, tuple[dict[str, float], int | None, str]] = {}
        # The file of (LOGOPEN,...) / (LOGAPPEND,...), until (LOGCLOSE) or the end of the run.
        self.log: TextIO | None = None
        # The file of (PROBEOPEN ...), until (PROBECLOSE) or the end of the run.
        self.probe_log: TextIO | None = None
        self.percent = False
        self.finished = False  # the closing % was read
        self.flow = Flow(self)
        self.flow.max_iterations = max_iterations
        self.flow.max_call_depth = max_call_depth
        self.numbered: Iterator[tuple[int, str]] = iter(())

    def close(self) -> None:
        """Release what the program opened (the log and probe log files)."""
        for handle in (self.log, self.probe_log):
            if handle is not None:
                handle.close()
        self.log = self.probe_log = None

    def emit(self, op: Op) -> None:
        self.sink.emit(op, self.label, self.line)

    # -- program ------------------------------------------------------------------------------
    def configure(self, settings: Rs274ngcSettings, ini: Ini | None = None) -> None:
        """Apply INI settings: the subroutine path, Fanuc-style programs, ``#<_ini[...]...>``."""
        self.flow.subroutine_path = list(settings.subroutine_path)
        self.flow.fanuc_enabled = not settings.disable_fanuc_style_sub
        self.params.ini = ini if settings.ini_vars else None

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
        coordinates.load_system(self, int(numbered[COORD_SYSTEM]))
        coordinates.load_g92(self)
        self.state.pos = coordinates.to_program(self.state, [0.0] * len(self.state.pos))

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
    ) -> None:
        """Execute a program line by line until M2/M30, the closing ``%`` or an error.

        The program is "open" once its first non-blank line is read (``on_open`` is called then);
        an empty program raises :class:`NgcOpenError`.  Raises :class:`NgcError` (with file and
        line) on the first error.  Plain lines stream; from the first o-word line (or M98/M99)
        on, :mod:`.flow` runs the rest of the program.  Files the program opened (logs) are
        closed at the end, whatever the outcome.
        """
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
        numbered = enumerate(lines, 1)
        self.numbered = numbered
        number, raw = 0, ""
        for number, raw in numbered:
            raw = self._checked(raw, number, opening=True)
            if raw.strip():
                break
        else:
            raise NgcOpenError("File ended with no percent sign", file=file, line=number,
                               source=raw.rstrip("\r\n"))
        if on_open is not None:
            on_open()
        self.percent = percent = raw.strip() == "%"
        flow = self.flow
        if not percent:
            self._execute_raw(raw, number)
            if self.ended or flow.tape is not None:
                self._finish_run()
                return
        plain = self.execute_plain
        for number, raw in numbered:
            raw = raw.rstrip("\n")
            if "\x00" in raw or len(raw) > MAX_LINE:
                raw = self._checked(raw, number, opening=False)
            if percent and raw.strip() == "%":
                self.finish_percent()
                return
            if not plain(raw, number):
                self.execute_line(raw, number)
            if self.ended or flow.tape is not None:
                self._finish_run()
                return
        message = "File ended with no percent sign" if percent else (
            "File ended with no percent sign or program end"
        )
        raise NgcProgramError(message, file=file, line=number, source=raw.rstrip())

    def _finish_run(self) -> None:
        """The program ended, or control flow took it over: it runs the rest, to the end."""
        if not self.ended:
            self.flow.run()
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

    def finish_percent(self) -> None:
        """The closing ``%`` of a ``%``-delimited program."""
        self.label = "N..... "
        self.emit(ops.Finish())
        self.ended = self.finished = True

    def checked_line(self, raw: str, number: int) -> str:
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
        if not self.execute_plain(raw, number):
            self.execute_line(raw, number)

    def execute_plain(self, raw: str, number: int) -> bool:
        """Execute ``raw`` if it is a line of plain words (see :func:`split_plain`); else False.

        Comments, ``;``, ``/`` and other characters fail :func:`split_plain`'s number reading.
        """
        try:
            hit = self._plain_lines.get(raw)
            if hit is not None:
                w, code, self.label = hit
                self.line = self.state.line = number
                self.convert_plain(w, code)
                return True
            found = split_plain(raw.replace(" ", "").lower())
            if found is None:
                return self.execute_comment_line(raw, number)
            hit = _plain_entry(found)
            if hit is not None:
                w, code, self.label = hit
                self.line = self.state.line = number
                self.convert_plain(w, code)
                self._remember_plain(raw, hit)
                return True
            w, g, digits = found
            block = Block(number, raw.rstrip())
            block.resolved = words_of(w, g)
            if digits is not None:
                block.n_number = int(digits)
                block.label = n_label(digits)
            self.execute(block)
            return True
        except NgcError as err:
            raise err.locate(file=self.file, line=number, source=raw.rstrip()) from None

    def compile_line(self, raw: str, number: int) -> tuple[dict[str, float], int | None, str, str] | Block:
        """A line read once for running many times: a plain-words tuple or a parsed block."""
        found = split_plain(raw.replace(" ", "").lower())
        hit = None if found is None else _plain_entry(found)
        if hit is not None:
            return (*hit, raw.rstrip())
        block = parse_line(raw, number)
        block.fast = specialise(self, block)
        return block

    def _remember_plain(self, raw: str, words: tuple[dict[str, float], int | None, str]) -> None:
        """Keep recently read plain lines (CAM output repeats its retracts and plunges)."""
        cache = self._plain_lines
        if len(cache) >= PLAIN_CACHE_SIZE:
            cache.clear()
        cache[raw] = words

    def execute_comment_line(self, raw: str, number: int) -> bool:
        """Execute ``raw`` if it holds nothing but one ``( ... )`` comment; else False."""
        text = raw.strip(" \t\r")
        if not (text[:1] == "(" and text[-1:] == ")" and text.count("(") == 1):
            return False
        if text.count(")") != 1 or not text.isascii():
            return False
        self.label = "N..... "
        self.line = self.state.line = number
        program.comment(self, text)
        return True

    def execute_line(self, raw: str, number: int) -> None:
        try:
            block = parse_line(raw, number)
        except NgcError as err:
            raise err.locate(file=self.file, line=number, source=raw.rstrip()) from None
        self.execute(block)

    def execute(self, block: Block) -> None:
        """Resolve, check and convert one block."""
        if block.delete and self.state.blocks_deleted:
            return
        if block.oword is not None:
            self.flow.enter(block, self.numbered)
            return
        self.label = block.label
        self.line = self.state.line = block.line
        try:
            r = block.resolved or resolve(block, self.params)
            if r.plain:
                self.convert_plain(r.w, r.g.get(codes.G_MOTION))
                return
            if r.assigns:
                assign = self.params.assign
                for target, value in r.assigns:
                    assign(target, value)
                if not (r.g or r.m or r.w) and r.comment is None:
                    return  # parameter settings only
            check(self.state, r)
            if codes.M_USER in r.m and r.m[codes.M_USER] in (98, 99):
                self.convert_fanuc(block, r)
                return
            self.convert(r)
        except NgcError as err:
            raise err.locate(file=self.file, line=block.line, source=block.source) from None

    # -- convert ------------------------------------------------------------------------------
    def convert_plain(self, w: dict[str, float], code: int | None) -> None:
        """The hot path: a block of only a motion code and axis/F/S words (most CAM output).

        Same checks and order as :meth:`convert` for such a block, without the general dispatch.
        """
        st = self.state
        if "f" in w:
            f = w["f"]
            if f >= 0.0 and st.feed_mode == 940:
                st.feed = f
                self.sink.emit(_new(ops.SetFeedRate, (f,)), self.label, self.line)
            else:
                modes.feed_rate(self, f)
        if "s" in w:
            modes.spindle_speed(self, w["s"])
        has_axes = not _AXES.isdisjoint(w)
        if code is None:
            if not has_axes:
                return
            code = st.motion
            if code == 800:
                raise NgcSemanticError("Cannot use axis values without a g code that uses them")
        elif code == 800:
            if has_axes:
                raise NgcSemanticError("Cannot use axis values with g80")
            st.motion = code
            self.emit(ops.Comment("interpreter: motion mode set to none"))
            return
        if code > 10:
            if code in _ARCS:
                st.motion = code
                motion.arc(self, w, motion.end_point(self, w, False), code)
                return
            r = Words()
            r.g[codes.G_MOTION] = code
            r.w = w
            self.convert_motion(r.g, r.finish())
            return
        st.motion = code
        pos = st.pos
        if st.absolute:
            end = [w.get("x", pos[0]), w.get("y", pos[1]), w.get("z", pos[2]),
                   w.get("a", pos[3]), w.get("b", pos[4]), w.get("c", pos[5])]
        else:
            end = motion.relative_end(st.pos, w)
        if code == 0:
            self.sink.emit(_new(ops.StraightTraverse, end), self.label, self.line)
        elif st.feed_mode == 940 and st.feed != 0.0:
            self.sink.emit(_new(ops.StraightFeed, end), self.label, self.line)
        else:
            motion.feed(self, w, end)
            return
        st.pos = end

    def convert(self, r: Resolved) -> None:
        """Execute a checked block in the order of overview.adoc, "G-code Order of Execution"."""
        if r.comment is not None:
            program.comment(self, r.comment)
        g = r.g
        m = r.m
        w = r.w
        if codes.G_FEED_MODE in g:
            modes.feed_mode(self, g[codes.G_FEED_MODE])
        if "f" in w:
            modes.feed_rate(self, w["f"])
        if "s" in w:
            modes.spindle_speed(self, w["s"])
        if m:
            self.convert_m_before_motion(m, w)
        if len(g) > 1 or codes.G_MOTION not in g:
            self.convert_modes(g, r)
        self.convert_motion(g, r)
        if codes.M_STOP in m:
            program.stop(self, m[codes.M_STOP])

    def convert_fanuc(self, block: Block, r: Resolved) -> None:
        """M98 calls at once (the rest of its line is not run); M99 runs its line, then returns."""
        code = r.m[codes.M_USER]
        if code == 98:
            self.flow.fanuc(block, 98, r.w.get("p"), r.w.get("l"))
            return
        rest = copy.copy(r)
        rest.m = {group: value for group, value in r.m.items() if group != codes.M_USER}
        in_sub = self.flow.tape is not None and len(self.flow.frames) > 1
        if in_sub and (rest.g or rest.w or rest.m):
            self.convert(rest)
            raise NgcSemanticError("Bug:  Reached convert_stop() from M99 as subprogram return")
        if not in_sub:
            self.convert(rest)  # in a subprogram the return comes first; its comment is not run
        if not self.flow.fanuc(block, 99, None, None):
            program.program_end(self, 2)

    def convert_m_before_motion(self, m: dict[int, int], w: dict[str, float]) -> None:
        for group in (codes.M_IO, codes.M_TOOL, codes.M_STATE, codes.M_USER):
            if group in m:
                raise NgcSemanticError(f"M{m[group]} is not supported yet")
        if codes.M_SPINDLE in m:
            code = m[codes.M_SPINDLE]
            if not codes.M_CODES[code].implemented:
                raise NgcSemanticError(f"M{code} is not supported yet")
            modes.spindle(self, code)
        if codes.M_COOLANT in m:
            modes.coolant(self, m[codes.M_COOLANT])
        if codes.M_OVERRIDE in m:
            modes.overrides(self, m[codes.M_OVERRIDE], w.get("p"))

    def convert_modes(self, g: dict[int, int], r: Resolved) -> None:
        if g.get(codes.G_NON_MODAL) == 40:
            modes.dwell(self, r)
        if codes.G_PLANE in g:
            modes.plane(self, g[codes.G_PLANE])
        if codes.G_UNITS in g:
            modes.units(self, g[codes.G_UNITS])
        for group in (codes.G_LATHE, codes.G_CUTTER_COMP, codes.G_TOOL_LENGTH, codes.G_SPINDLE_MODE):
            code = g.get(group)
            if code is not None and not codes.G_CODES[code].implemented:
                raise NgcSemanticError(f"{codes.g_name(code)} is not supported yet")
        if codes.G_COORD_SYSTEM in g:
            coordinates.select_system(self, g[codes.G_COORD_SYSTEM])
        if codes.G_CONTROL in g:
            modes.control_mode(self, g[codes.G_CONTROL], r)
        if codes.G_DISTANCE in g:
            modes.distance_mode(self, g[codes.G_DISTANCE])
        if codes.G_ARC_DISTANCE in g:
            modes.arc_distance_mode(self, g[codes.G_ARC_DISTANCE])
        if codes.G_RETRACT in g:
            self.state.retract_r = g[codes.G_RETRACT] == 980
        code = g.get(codes.G_NON_MODAL)
        if code is not None and code != 40:
            self.convert_non_modal(code, r)

    def convert_non_modal(self, code: int, r: Resolved) -> None:
        if code == 100:
            coordinates.g10(self, r)
        elif code == 920:
            coordinates.g92(self, r)
        elif code == 520:
            coordinates.g52(self, r)
        elif code in (921, 922, 923):
            coordinates.g92_reset(self, code)
        elif code in (281, 301):
            coordinates.home_store(self, code)
        elif code in (280, 300):
            middle, home = coordinates.home_targets(self, code, r)
            motion.traverse(self, middle)
            motion.traverse(self, home)

    def convert_motion(self, g: dict[int, int], r: Resolved) -> None:
        st = self.state
        code = g.get(codes.G_MOTION)
        if code is None:
            if st.motion == 800 or not r.has_axes or g.get(codes.G_NON_MODAL) in codes.G_AXIS_USERS_NON_MODAL:
                return
            code = st.motion
        elif not codes.G_CODES[code].implemented:
            raise NgcSemanticError(f"{codes.g_name(code)} is not supported yet")
        st.motion = code
        if code == 800:
            if codes.G_MOTION in g:
                self.emit(ops.Comment("interpreter: motion mode set to none"))
            return
        end = motion.end_point(self, r.w, g.get(codes.G_NON_MODAL) == 530)
        if code == 0:
            motion.traverse(self, end)
        elif code == 10:
            motion.feed(self, r.w, end)
        else:
            motion.arc(self, r.w, end, code)
