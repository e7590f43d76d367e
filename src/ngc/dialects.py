"""Which dialect a program is in, and running the engine dialect for the API and the commands.

ngc reads two dialects: ``linuxcnc`` (rs274's, the default) and ``engine`` (``spec/seeds/003``,
:mod:`ngc.engine`).  A program names its dialect in three ways, the first that applies wins:

1. the caller says so: ``--dialect linuxcnc|engine`` on every command, ``dialect=`` in
   :func:`ngc.interpret` and :func:`ngc.check_file`;
2. the program's first line is a marker, alone on its line, in any case:
   ``(dialect: engine)`` or ``; dialect: engine`` (``linuxcnc`` names the default the same way);
   both are comments in either dialect, so the marked program runs unchanged;
3. otherwise, the LinuxCNC dialect.

``ngc check`` also takes ``--dialect grbl`` and ``--dialect grblhal``: each line held against
what Grbl 1.1 (or grblHAL) accepts (:mod:`ngc.grbl`, a row of ``ngc.grbl.DIALECTS`` each),
nothing run.  They are dialects of that command only, and only when given.

The engine dialect has its own machine input, the setup sheet (:func:`ngc.engine.read_setup`,
``--setup FILE``); the LinuxCNC inputs (INI file, tool table, parameter file, probe) are the
other dialect's.  This module loads :mod:`ngc.engine` only when a program needs it, so that
``ngc rs274`` starts without it.
"""

from __future__ import annotations

import io
import os
import re
import stat
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any, BinaryIO

from .budget import DEFAULT_MAX_ITERATIONS
from .interp.source import BOM, LINE_BYTES

if TYPE_CHECKING:
    from .engine import Op as EngineOp
    from .engine import Setup as EngineSetup

LINUXCNC = "linuxcnc"
ENGINE = "engine"
DIALECTS = (LINUXCNC, ENGINE)
GRBL = "grbl"  # ngc check's only: the controller's acceptance of each line (ngc.grbl.DIALECTS)
# the rows of ngc.grbl.DIALECTS, by name (ngc.grbl is not loaded here); GRBL is the first
GRBL_ROWS = (GRBL, "grblhal")
CHECK_DIALECTS = (*DIALECTS, *GRBL_ROWS)

_MARK = re.compile(r"\s*(?:\(\s*dialect\s*:\s*(\w+)\s*\)|;\s*dialect\s*:\s*(\w+))\s*",
                   re.IGNORECASE)


def checked(name: str | None) -> str | None:
    """``name`` if it is a dialect (or None: not said); ``ValueError`` naming the choices.

    >>> checked("engine"), checked(None)
    ('engine', None)
    >>> checked("fanuc")
    Traceback (most recent call last):
    ValueError: unknown dialect 'fanuc': choose 'linuxcnc' or 'engine'
    """
    if name is None or name in DIALECTS:
        return name
    raise ValueError(f"unknown dialect {name!r}: choose 'linuxcnc' or 'engine'")


def marked(first_line: str) -> str | None:
    """The dialect a program's first line names, or None (a leading byte-order mark and the
    line end are ignored).

    >>> marked("(Dialect: Engine)\\n"), marked("; dialect: linuxcnc"), marked("G0 X1")
    ('engine', 'linuxcnc', None)
    """
    m = _MARK.fullmatch(first_line.removeprefix("\ufeff"))
    if m is None:
        return None
    name = (m.group(1) or m.group(2)).lower()
    return name if name in DIALECTS else None


def of_text(text: str, given: str | None = None) -> str:
    """The dialect of a program given as text: ``given`` if said, else its marker, else
    ``linuxcnc``; ``ValueError`` for an unknown ``given``."""
    if checked(given) is not None:
        return str(given)
    end = text.find("\n", 0, 4096)
    return marked(text[:end] if end >= 0 else text[:4096]) or LINUXCNC


def _first_line(data: bytes) -> str:
    return data.decode("utf-8", "replace")


def of_file(path: str) -> str:
    """The dialect a program file's first line names, ``linuxcnc`` if none.  Only a regular file
    is looked at (a FIFO or a device would lose what is read); one that cannot be read is
    ``linuxcnc`` (its error comes when it is run)."""
    try:
        if not stat.S_ISREG(os.stat(path).st_mode):
            return LINUXCNC
        with open(path, "rb") as handle:
            return marked(_first_line(handle.readline(4096))) or LINUXCNC
    except (OSError, ValueError):
        return LINUXCNC


class _Replayed(io.RawIOBase):
    """A stream that cannot go back (a pipe), its first line read already: that line again,
    then the rest of the stream."""

    def __init__(self, first: bytes, rest: io.BufferedReader) -> None:
        super().__init__()
        self._first = first
        self._rest = rest

    def readable(self) -> bool:
        return True

    def readinto(self, buffer: Any) -> int:
        view = memoryview(buffer).cast("B")
        if self._first:
            n = min(len(view), len(self._first))
            view[:n] = self._first[:n]
            self._first = self._first[n:]
            return n
        data = self._rest.read1(len(view))
        view[:len(data)] = data
        return len(data)

    def fileno(self) -> int:
        return self._rest.fileno()

    def close(self) -> None:
        if not self.closed:
            self._rest.close()
        super().close()


def of_stream(handle: io.BufferedReader) -> tuple[str, io.BufferedReader]:
    """The dialect a program's first line names (``linuxcnc`` if none), and a stream that reads
    the program from its start: ``handle`` itself, put back, if it can seek; else a stream that
    gives the line read again (without a leading byte-order mark, which is read past here as
    :class:`ngc.interp.source.ProgramReader` would), then the rest of ``handle``.

    The first line is read in rs274's pieces (:data:`LINE_BYTES`), so the reader sees the same
    pieces as it would have.
    """
    try:
        seekable = handle.seekable()
    except (OSError, ValueError):
        seekable = False
    if seekable:
        start = handle.tell()
        first = handle.readline(4096)
        handle.seek(start)
        return marked(_first_line(first)) or LINUXCNC, handle
    if handle.peek(3)[:3] == BOM:
        handle.read(3)
    first = handle.readline(LINE_BYTES)
    return marked(_first_line(first)) or LINUXCNC, io.BufferedReader(_Replayed(first, handle))


def read_text(handle: BinaryIO) -> str:
    """A whole engine-dialect program, as UTF-8 text (a leading byte-order mark skipped, bytes
    that are not UTF-8 kept as surrogates, as :func:`ngc.interp.source.text_reader` reads)."""
    return handle.read().decode("utf-8", "surrogateescape").removeprefix("\ufeff")


# -- the machine inputs of each dialect ----------------------------------------------------------
SETUP_IS_ENGINES = ("--setup is the engine dialect's machine setup sheet, not an input of the "
                    "LinuxCNC dialect (give --dialect engine, or start the program with the line "
                    "'(dialect: engine)')")

API_SETUP_IS_ENGINES = ("setup is the engine dialect's machine setup sheet, not an input of the "
                        "LinuxCNC dialect (give dialect='engine', or start the program with the "
                        "line '(dialect: engine)')")
API_PROBE_IS_LINUXCNCS = ("probe is an input of the LinuxCNC dialect, not of the engine dialect "
                          "(whose machine is described by setup)")


def linuxcnc_inputs_refused(flags: list[str]) -> str:
    """What to say when the LinuxCNC dialect's options ``flags`` come with an engine program.

    >>> linuxcnc_inputs_refused(["-t", "-v"])[:56]
    '-t, -v are inputs of the LinuxCNC dialect, not of the en'
    """
    what = "is an input" if len(flags) == 1 else "are inputs"
    return (f"{', '.join(flags)} {what} of the LinuxCNC dialect, not of the engine dialect "
            "(whose machine is described by --setup FILE)")


# -- engine operations, for sinks -----------------------------------------------------------------
def _not_engine_op(op: object) -> TypeError:
    return TypeError(f"{type(op).__name__} is neither a canonical operation (ngc.canon.ops) nor "
                     "an engine-dialect operation (ngc.engine)")


def engine_record(op: object) -> dict[str, object]:
    """An engine operation as :func:`ngc.engine.output.as_dict` has it (``{"op": ..., "line":
    ..., ...}``); ``TypeError`` for anything else."""
    from .engine import output

    if not output.is_op(op):
        raise _not_engine_op(op)
    return output.as_dict(op)


def engine_text(op: object) -> str:
    """An engine operation as ``ngc canon --dialect engine`` prints it; ``TypeError`` for
    anything else."""
    from .engine import output

    if not output.is_op(op):
        raise _not_engine_op(op)
    return output.as_text(op)


def engine_ops(text: str, setup: EngineSetup | None = None, file: str | None = None,
               max_iterations: int = DEFAULT_MAX_ITERATIONS) -> Iterable[EngineOp]:
    """The operations of an engine-dialect program, on the machine ``setup`` describes (None:
    the default machine), within the work budget ``max_iterations`` (segments and pecks)."""
    from . import engine

    machine = (engine.Engine(max_iterations=max_iterations) if setup is None
               else engine.Engine(setup=setup, max_iterations=max_iterations))
    return engine.run(text.removeprefix("\ufeff"), machine, file=file)


def interpret_engine(text: str, sink: Any, *, setup: EngineSetup | None = None,
                     file: str | None = None,
                     max_iterations: int = DEFAULT_MAX_ITERATIONS) -> None:
    """Send each engine operation to ``sink.emit(op, label, line)`` (``label``: the operation's
    name, as in its JSON ``"op"``), then flush the sink (also after an error)."""
    from .engine import output

    try:
        for op in engine_ops(text, setup, file, max_iterations):
            sink.emit(op, output.name(op), op.line)
    finally:
        sink.flush()

