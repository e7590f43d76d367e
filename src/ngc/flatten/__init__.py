"""``ngc flatten``: a program written out plain for a simpler controller, and verified.

:func:`flatten` runs the program through the interpreter and the toolpath layer, writes each
move with :class:`~ngc.flatten.writer.Flattener` for a target of
:data:`~ngc.flatten.targets.TARGETS`, and runs what it writes through the interpreter again as
it is written, on the same machine inputs, comparing the two machine paths move by move
(:mod:`.verify`, :mod:`.channel`).  A program that cannot be written truthfully raises
:class:`~ngc.flatten.writer.Refused`.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import NamedTuple, TextIO

from ..canon.ops import Sink
from ..config.tooltable import ToolEntry, scaled_entry
from ..errors import NgcError
from ..interp.interpreter import Interpreter
from ..interp.parameters import COORD_STRIDE, G54_ORIGIN
from ..interp.source import ProgramReader
from ..toolpath.held import Held
from ..toolpath.tracker import Toolpath
from . import channel
from .targets import TARGETS
from .verify import FINE, Moves, Verified
from .writer import MM_PER_INCH, SYSTEMS, Flattener, Refused

__all__ = ["TARGETS", "Flattened", "Refused", "Verified", "flatten"]

COORD_SYSTEM = 5220
CHUNK = 4096  # lines written before they go to the output and the verification


class Flattened(NamedTuple):
    """The program written out (``text``), its lines, and its verification (None if not
    asked)."""

    text: str
    lines: int
    verified: Verified | None


class _Buffer:
    """The writer's output, held until a chunk is full (``full()``) and taken."""

    def __init__(self) -> None:
        self.parts: list[str] = []
        self.write = self.parts.append

    def full(self) -> bool:
        return len(self.parts) >= CHUNK

    def take(self) -> str:
        text = "".join(self.parts)
        self.parts.clear()
        return text


def flatten(source: str | Iterable[str], name: str,
            new_interpreter: Callable[[Sink], Interpreter], *, target: str = "linuxcnc",
            inch: bool = False, decimals: int | None = None, source_lines: bool = False,
            verify: bool = True, tolerance: float = 0.002, toolchange: str | None = None,
            fold_lengths: bool = False,
            out: TextIO | None = None, reader: ProgramReader | None = None,
            parallel: bool = True) -> Flattened:
    """The program ``source`` (its text, or its lines; named ``name``) written plain for
    ``target``, run by ``new_interpreter(sink)`` (the machine inputs:
    :func:`ngc.options.new_interpreter`); raises :class:`Refused` for a program that cannot be
    written truthfully, :class:`ValueError` for an unknown target, and
    :class:`~ngc.errors.NgcError` for a program error.

    Curves the target cannot run as they are become lines within ``tolerance`` mm;
    ``toolchange`` is ``pause``, ``strip`` or ``keep`` (default: keep where the target has M6,
    else pause); ``fold_lengths`` writes tool lengths into the coordinates rather than as the
    target's tool length offset.  The text is returned, or written to ``out`` as it is made (``text`` is then
    empty; the caller keeps it only if the result is verified).  The verification runs beside
    the writing, in a second process if ``parallel`` and the system forks (see
    :mod:`.channel`); ``reader`` is the program file's reader when ``source`` reads from one
    (see :meth:`Interpreter.run`)."""
    row = TARGETS.get(target)
    if row is None:
        raise ValueError(f"unknown target {target!r}: choose one of {', '.join(TARGETS)}")
    buffer = _Buffer()
    held = Held()  # (the interpreter and the writer each run a stretch at a time)
    toolpath = Toolpath(held)
    view = held.follow(toolpath)
    original = Moves(view, tolerance * FINE)
    interp = new_interpreter(toolpath)
    origins, system = _origins(interp, 0)
    slots = list(interp.machine.state.tools.slots)  # (the operator's table: G10 L1 in the
    # program changes the interpreter's copy, not what the machine will have)

    def tool(number: int) -> ToolEntry | None:  # (in mm)
        entry = next((e for e in slots[1:] if e.number == number), None)
        return None if entry is None else scaled_entry(entry, MM_PER_INCH)

    writer = Flattener(view, buffer, row, origins=origins, system=system, tool=tool,
                       inch=inch, decimals=decimals, source_lines=source_lines,
                       tolerance=tolerance, toolchange=toolchange, fold_lengths=fold_lengths)
    original.source = writer  # (how many moves it wrote for each)
    kept: list[str] = []
    checker: list[channel.Checker] = []  # (started with the first chunk)
    first = [True]

    def flush() -> None:
        text = buffer.take()
        if first[0]:
            first[0] = False
            if interp.percent and row.percent:  # (a program between % lines: so is this one)
                text = "%\n" + text
            if verify:
                checker.append(channel.start(new_interpreter, tolerance, parallel))
        if out is None:
            kept.append(text)
        else:
            out.write(text)
        if checker:
            checker[0].send(text, original.moves)
            original.moves = []
        else:
            original.moves.clear()

    def handed() -> None:  # (after each batch of moves: a full chunk goes on)
        if buffer.full():
            flush()

    held.add(writer)
    if verify:  # (the original's moves, kept to compare)
        held.add(original)
    held.after = handed
    try:
        writer.header(name)
        interp.startup()
        lines = source.splitlines() if isinstance(source, str) else source
        try:
            interp.run(lines, file=name, reader=reader)
        except NgcError:
            held.settle()  # (a refusal of a line before the error comes first)
            raise
        held.settle()
        if not writer.ended:  # (a program ended by %: so is the one written, or by M2)
            writer.write("%" if row.percent else "M2")
        flush()
        checked = checker[0].finish() if checker else None
    except BaseException:
        if checker:
            checker[0].close()
        raise
    return Flattened("".join(kept), writer.lines, checked)


def _origins(interp: Interpreter, line: int) -> tuple[list[list[float]], int]:
    """The work offsets' origins as the program finds them (machine coordinates in mm) and the
    system selected; a rotated one is refused (its rotation is the operator's, and this writer
    does not write rotated coordinates yet)."""
    numbered = interp.params.numbered
    origins = []
    for k in range(9):
        base = G54_ORIGIN + k * COORD_STRIDE
        values = [numbered[base + i] * (MM_PER_INCH if i < 3 else 1.0) for i in range(6)]
        if numbered[base + 9] != 0.0:
            raise Refused(line, f"{SYSTEMS[k]} is rotated (R) in the parameter file: not "
                          "flattened yet")
        origins.append(values)
    system = int(numbered[COORD_SYSTEM]) or 1
    return origins, min(max(system, 1), 9)


