"""What ``ngc rs274`` does after an error with ``-n 0`` (continue) or ``-n 1`` (MDI), as rs274.

``-n 0``: the error is reported (its message and line, as always) and the run goes on with the
next line (:mod:`ngc.interp.unwind` says which and what is kept); the exit code is then that of
the end of the run: 0 after ``M2``/``M30``/``%``.

``-n 1``: after the report, ``starting MDI`` on stderr, then each line of standard input is run as
an MDI command (errors reported the same way) until a line ``quit`` or the end of the input; then
``continue program? y/n =>`` (no newline) and one more line is read: an answer starting with
``y`` goes on as ``-n 0`` does, any other (or none) stops the run as ``-n 2`` does (exit 1).

rs274 meets an end of file without ``%`` or ``M2`` again at every read and so never ends with
``-n 0``; ngc reports it once and stops (exit 1).
"""

from __future__ import annotations

import io
import sys
from typing import TextIO

from ..canon.text import TextSink
from ..errors import NgcError
from ..interp.interpreter import Interpreter

CONTINUE, MDI = 0, 1


class Recovery:
    """The interpreter's ``recover`` hook: report an error, then go on (True) or stop."""

    __slots__ = ("err", "interp", "mode", "reported", "sink", "stdin")

    def __init__(self, interp: Interpreter, sink: TextSink, err: TextIO, mode: int,
                 stdin: TextIO | None) -> None:
        self.interp = interp
        self.sink = sink
        self.err = err
        self.mode = mode
        self.stdin = stdin
        self.reported: NgcError | None = None  # the last error of the program reported

    def __call__(self, exc: NgcError) -> bool:
        self.report(exc)
        self.reported = exc
        return self.mode == CONTINUE or self.mdi()

    def report(self, exc: NgcError) -> None:
        self.sink.flush()
        report(self.err, exc)

    def mdi(self) -> bool:
        """rs274's MDI mode after an error: commands until ``quit``, then whether to go on."""
        stdin = self.input()
        self.err.write("starting MDI\n")
        for line in iter(stdin.readline, ""):
            text = line.rstrip("\n")
            if text == "quit":
                break
            try:
                self.interp.execute_line(text, 0)
            except NgcError as exc:
                self.report(exc)
        self.err.write("continue program? y/n =>")
        self.err.flush()
        return stdin.readline().startswith("y")

    def input(self) -> TextIO:
        if self.stdin is None:
            buffer = getattr(sys.stdin, "buffer", None)
            self.stdin = sys.stdin if buffer is None else io.TextIOWrapper(
                buffer, encoding="latin-1", newline="\n")
        return self.stdin


# rs274 keeps an error message in a 255-byte buffer: a longer one is cut.
MAX_MESSAGE = 254


def report(err: TextIO, exc: NgcError, message: str | None = None) -> None:
    """rs274's error report: the message (cut as rs274 cuts it), then the source line."""
    err.write(f"{(exc.message if message is None else message)[:MAX_MESSAGE]}\n")
    if exc.source is not None:
        err.write(f"{exc.source}\n")
