"""The narrow context a code's handler works on: the modal state, the parameters and the canon.

Handlers (``interp/handlers``) see a :class:`Machine`, never the interpreter: what they may read
and change is listed here.  The interpreter owns one and sets ``label`` and ``line`` for each block
it runs, so every operation a handler emits carries its block's N column and source line.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, TextIO

from ..canon.ops import mover
from .comp import HELD
from .parameters import COORD_SYSTEM, Parameters
from .snapshot import Context
from .state import State

if TYPE_CHECKING:
    from ..canon.ops import Op, Sink
    from ..config.probe import Probe
    from ..config.tooltable import ToolEntry, Tools
    from .comp import Compensation


def _unbounded() -> None:
    """No work budget: a machine run without an interpreter."""


class Machine:
    """State, parameters, the sink, and the files a program opens (logs)."""

    __slots__ = ("comp", "contexts", "encoding", "ended", "held", "label", "line", "log",
                 "message", "move", "params", "probe", "probe_log", "profile", "run_profile",
                 "run_text", "sink", "state", "work", "write_files")

    def __init__(self, sink: Sink, write_files: bool = True) -> None:
        self.sink = sink
        # move(kind, fields, label, line): a StraightTraverse, StraightFeed or ArcFeed to the sink
        self.move = mover(sink)
        self.state = State()
        self.params = Parameters(self.state)
        self.params.numbered[COORD_SYSTEM] = 1.0
        self.label = "N..... "  # the running block's N column
        self.line = 0  # the running block's source line
        self.ended = False  # M2 / M30 ran
        # The line and text of the last (DEBUG,...) or (PRINT,...) shown (handlers/program.py).
        self.message: tuple[int, str] = (-1, "")
        # The file of (LOGOPEN,...) / (LOGAPPEND,...), until (LOGCLOSE) or the end of the run.
        self.log: TextIO | None = None
        # The file of (PROBEOPEN ...), until (PROBECLOSE) or the end of the run.
        self.probe_log: TextIO | None = None
        # False: LOGOPEN, LOGAPPEND and PROBEOPEN emit their calls but open no file (``ngc check``
        # writes nothing to disk).
        self.write_files = write_files
        # How the program's text was decoded from its file's bytes (encoding, errors), so that a
        # file name in it names the file those bytes name; None: text given as str.
        self.encoding: tuple[str, str] | None = None
        # Cutter radius compensation (interp/comp.py): None while off; the moves and calls it
        # holds back until the next move decides where the held move ends.
        self.comp: Compensation | None = None
        self.held: list[Any] = []
        # The simulated probe input of G38.2-G38.5 (None: rs274's, which never trips).
        self.probe: Probe | None = None
        # M70-M73 (interp/context.py): the saved state of each call level, the main program's
        # first; and how a restore runs a line of G code (the interpreter sets it).
        self.contexts = [Context()]
        self.run_text: Callable[[str], None] | None = None
        # A lathe cycle's profile while its subroutine runs (handlers/lathe.py): the moves are
        # recorded here, nothing else of the subroutine's lines runs; None otherwise.  How the
        # cycle runs its subroutine ``o<q> call`` (the interpreter sets it).
        self.profile: list[Any] | None = None
        self.run_profile: Callable[[float], tuple[str | None, int, str]] | None = None
        # One iteration of a loop inside a code whose count the program's numbers set (a canned
        # cycle's repeats and pecks, G76's passes, G70-G72's passes), against the run's work
        # budget (flow.py, ``--max-iterations``); the interpreter sets it, a machine alone has
        # no budget.
        self.work: Callable[[], None] = _unbounded

    @property
    def tools(self) -> Tools:
        """The tool data: ``tools.find(number)`` gives a tool's entry (diameter in inches,
        orientation, front and back angle) or None."""
        return self.state.tools

    def current_tool(self) -> ToolEntry:
        """The entry of the tool in the spindle (what #5400-#5413 read; tool 0 when empty)."""
        return self.state.tools.spindle

    def file_name(self, text: str) -> str:
        """A file name written in the program, as the operating system is to be given it: the
        bytes the program holds (``(LOGOPEN,€.log)`` in a file read as latin-1 names ``€.log``)."""
        if self.encoding is None:
            return text
        try:
            return os.fsdecode(text.encode(*self.encoding))
        except UnicodeError:
            return text

    def emit(self, op: Op) -> None:
        if self.held and type(op) in HELD:
            self.held.append(op)  # behind a move held by cutter radius compensation
        else:
            self.sink.emit(op, self.label, self.line)

    def close(self) -> None:
        """Release what the program opened (the log and probe log files)."""
        for handle in (self.log, self.probe_log):
            if handle is not None:
                handle.close()
        self.log = self.probe_log = None
