"""SIGTERM and SIGHUP as an exception, so that a run they stop ends through its cleanup code.

Python's default for these signals kills the process at once: a parameter file being saved could
leave its temporary file behind (``config/varfile.py``) and open files were never closed.  Inside
:func:`signals_raise`, either signal raises :class:`Terminated` in the main thread instead; like
``KeyboardInterrupt`` it is not an ``Exception``, so only ``finally`` blocks and handlers of
``BaseException`` see it on its way out.  A signal the process was told to ignore (``nohup``) stays
ignored.
"""

from __future__ import annotations

import signal
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from types import FrameType

__all__ = ["SIGNALS", "Terminated", "signals_raise"]

SIGNALS: tuple[signal.Signals, ...] = (signal.SIGTERM, signal.SIGHUP)


class Terminated(BaseException):
    """The process got ``signum``; :attr:`exit_code` is what a shell reports for it (128 + n)."""

    def __init__(self, signum: int) -> None:
        super().__init__(signum)
        self.signum = signum

    @property
    def exit_code(self) -> int:
        return 128 + self.signum


def _raise(signum: int, frame: FrameType | None) -> None:
    raise Terminated(signum)


@contextmanager
def signals_raise() -> Iterator[None]:
    """Within the block, SIGTERM and SIGHUP raise :class:`Terminated`; the old handlers come back
    after it.  Outside the main thread (where Python cannot set handlers) nothing changes."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = {signum: signal.getsignal(signum) for signum in SIGNALS}
    for signum, handler in previous.items():
        if handler is not signal.SIG_IGN:
            signal.signal(signum, _raise)
    try:
        yield
    finally:
        for signum, handler in previous.items():
            signal.signal(signum, handler)
