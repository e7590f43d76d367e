"""A progress line for long runs, on a terminal only.

``big.ngc: 12.6 MB / 40.0 MB (31%), 1,576,960 lines, 0:03`` — the file, the bytes read and the
file's size, the lines read, the time since the start.  :meth:`Progress.lines` wraps the lines
given to :meth:`Interpreter.run`, which reads the whole program through that iterator (the part
after the first o-word too), so the line follows the reading.  It looks at the clock once every
:data:`STEP` lines (nothing else happens per line), shows itself once the run has taken
:data:`DELAY` seconds, repaints at most every :data:`REPAINT` seconds and is erased by
:meth:`Progress.close` (also when the run ends with an error or Ctrl-C).  A loop that runs for
long without reading new lines leaves the line as it is.
"""

from __future__ import annotations

import os
import stat
import time
from collections.abc import Callable, Iterable, Iterator
from itertools import islice
from types import TracebackType
from typing import TextIO

STEP = 4096  # lines between two looks at the clock
DELAY = 1.0  # seconds: shorter runs show nothing
REPAINT = 0.25  # seconds between two paints
ERASE = "\r\x1b[K"  # to the start of the line, then clear to its end
MIN_WIDTH = 20  # columns: the line is cut to the terminal's width, but not below this
FALLBACK_WIDTH = 80  # columns, when the terminal does not say


class Progress:
    """The progress line of one program file; a context manager that erases it on exit.

    ``stream`` is where it goes (stderr); ``active=False`` turns it off (nothing is wrapped, no
    cost).  ``fd`` is the program file's descriptor: its offset is the bytes read and, for a
    regular file, its size the total (``None``: lines and time only, e.g. a pipe).
    """

    __slots__ = ("_clock", "_due", "_fd", "_name", "_shown", "_size", "_start", "_stream",
                 "active", "count")

    def __init__(self, stream: TextIO, name: str, fd: int | None, *, active: bool,
                 clock: Callable[[], float] = time.monotonic) -> None:
        self._stream = stream
        self._name = name
        self._fd = fd
        self._size = _regular_size(fd)
        self._clock = clock
        self._start = clock()
        self._due = self._start + DELAY
        self._shown = False
        self.active = active
        self.count = 0  # lines read, as of the last look at the clock

    def lines(self, source: Iterable[str]) -> Iterable[str]:
        """``source`` itself when inactive, else the same lines with a look at the clock every
        :data:`STEP` lines."""
        return self._counted(source) if self.active else source

    def _counted(self, source: Iterable[str]) -> Iterator[str]:
        lines = iter(source)
        while True:
            yield from islice(lines, STEP - 1)
            line = next(lines, None)
            if line is None:
                return
            yield line
            self.count += STEP
            if self._clock() >= self._due:
                self._paint()

    def _paint(self) -> None:
        now = self._clock()
        self._due = now + REPAINT
        text = self.text(now)[: _width(self._stream) - 1]
        self._shown = True  # first: Ctrl-C while it is written still erases it
        self._stream.write(ERASE + text)
        self._stream.flush()

    def text(self, now: float) -> str:
        """What the line says at time ``now``."""
        parts = [f"{self._name}: "]
        done = _offset(self._fd)
        if done is not None:
            parts.append(_bytes(done))
            if self._size:
                parts.append(f" / {_bytes(self._size)} ({min(done * 100 // self._size, 100)}%)")
            parts.append(", ")
        seconds = int(now - self._start)
        parts.append(f"{self.count:,} lines, {seconds // 60}:{seconds % 60:02d}")
        return "".join(parts)

    def close(self) -> None:
        """Erase the line if it was shown."""
        if self._shown:
            self._shown = False
            self._stream.write(ERASE)
            self._stream.flush()

    def __enter__(self) -> Progress:
        return self

    def __exit__(self, kind: type[BaseException] | None, error: BaseException | None,
                 trace: TracebackType | None) -> None:
        self.close()


def is_terminal(stream: TextIO) -> bool:
    """Whether ``stream`` is a terminal (``False`` for anything that cannot say)."""
    try:
        return stream.isatty()
    except (AttributeError, ValueError, OSError):
        return False


def descriptor(handle: object) -> int | None:
    """The file descriptor under ``handle``, if it has one."""
    fileno = getattr(handle, "fileno", None)
    if fileno is None:
        return None
    try:
        return int(fileno())
    except (ValueError, OSError):  # a closed file, or a stream with no descriptor
        return None


def _regular_size(fd: int | None) -> int | None:
    if fd is None:
        return None
    try:
        info = os.fstat(fd)
    except OSError:
        return None
    return info.st_size if stat.S_ISREG(info.st_mode) else None


def _offset(fd: int | None) -> int | None:
    if fd is None:
        return None
    try:
        return os.lseek(fd, 0, os.SEEK_CUR)
    except OSError:  # a pipe or a terminal
        return None


def _width(stream: TextIO) -> int:
    fd = descriptor(stream)
    try:
        columns = os.get_terminal_size(fd if fd is not None else 2).columns
    except OSError:
        return FALLBACK_WIDTH
    return FALLBACK_WIDTH if columns == 0 else max(columns, MIN_WIDTH)  # 0: a size never set


def _bytes(count: int) -> str:
    """``812 B``, ``12.6 kB``, ``40.0 MB``, ``1.2 GB`` (powers of 1000)."""
    if count < 1000:
        return f"{count} B"
    for unit, scale in (("kB", 1e3), ("MB", 1e6)):
        if count < 999.95 * scale:
            return f"{count / scale:.1f} {unit}"
    return f"{count / 1e9:.1f} GB"
