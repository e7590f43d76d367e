"""Where the verification runs while the program is written: in a second process where the
system can fork one (the two interpretations then take the machine's two cores), else in a
thread.  Either way the written text goes over in chunks with the original's moves it was
written from, through a bounded channel, so that neither side holds the whole program (to the
process as ``marshal`` bytes: the moves are plain tuples, and it is quicker than pickle).
"""

from __future__ import annotations

import contextlib
import gc
import marshal
import math
import multiprocessing
import queue
import signal
import threading
from collections.abc import Callable, Iterator
from multiprocessing.connection import Connection
from typing import Any

try:
    import fcntl
except ImportError:  # (not on Windows, which has no fork either)
    fcntl = None  # type: ignore[assignment]

from ..canon.ops import Sink
from ..interp.interpreter import Interpreter
from .verify import Move, Verified, check

Chunk = tuple[str, list[Move]]
NewInterpreter = Callable[[Sink], Interpreter]
_END = None  # (the message after the last chunk)
_DEPTH = 4  # chunks a thread's queue holds before the writer waits
PIPE_BYTES = 1 << 20  # (Linux's largest for a user by default: a chunk is 0.4 MB)


class Checker:
    """The verification running beside the writer: :meth:`send` each chunk, then
    :meth:`finish` for the result (or :meth:`close` to stop it)."""

    def send(self, text: str, moves: list[Move]) -> None:
        raise NotImplementedError

    def finish(self) -> Verified:
        raise NotImplementedError

    def close(self) -> None:
        """Stop the verification whatever it is doing."""


class _ProcessChecker(Checker):
    def __init__(self, new_interpreter: NewInterpreter, tolerance: float) -> None:
        context = multiprocessing.get_context("fork")
        self._chunks_in, self._chunks_out = context.Pipe(duplex=False)
        self._result_in, self._result_out = context.Pipe(duplex=False)
        self._process = context.Process(
            target=_serve, args=(self._chunks_in, self._result_out, new_interpreter, tolerance),
            daemon=True)
        self._process.start()
        self._chunks_in.close()
        self._result_out.close()
        _widen(self._chunks_out)

    def send(self, text: str, moves: list[Move]) -> None:
        with contextlib.suppress(OSError):  # (the checker stopped: finish says so)
            self._chunks_out.send_bytes(marshal.dumps((text, moves)))

    def finish(self) -> Verified:
        try:
            self._chunks_out.send_bytes(marshal.dumps(_END))
            result: Verified = self._result_in.recv()
        except (OSError, EOFError):
            result = Verified(0, math.inf, "the verification stopped before its end")
        self.close()
        return result

    def close(self) -> None:
        self._chunks_out.close()
        if self._process.is_alive():
            self._process.kill()  # (it holds nothing to clean up; a SIGTERM could come before
            # it set its own handler, while it still had the writer's)
        self._process.join()
        self._result_in.close()


def _widen(end: Connection) -> None:
    """A pipe that holds a few chunks where the system allows (Linux): the writer goes on
    while the checker reads the chunk before."""
    size = getattr(fcntl, "F_SETPIPE_SZ", None) if fcntl is not None else None
    if size is not None:
        with contextlib.suppress(OSError):
            fcntl.fcntl(end.fileno(), size, PIPE_BYTES)


def _serve(chunks: Connection, result: Connection, new_interpreter: NewInterpreter,
           tolerance: float) -> None:
    """The second process: check the chunks as they come, send the result back.  The writer's
    side stops it (SIGKILL) and answers for Ctrl-C and SIGTERM itself."""
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    gc.freeze()  # (the writer's objects, copied at the fork: the collector leaves them be)

    def received() -> Iterator[Chunk]:
        while True:
            message: Chunk | None = marshal.loads(chunks.recv_bytes())
            if message is _END:
                return
            assert message is not None
            yield message

    try:
        verified = check(received(), new_interpreter, tolerance)
    except Exception as exc:  # (reported to the writer's side as the verification's failure)
        verified = Verified(0, math.inf, f"the verification failed: {exc!r}")
    result.send(verified)


class _ThreadChecker(Checker):
    def __init__(self, new_interpreter: NewInterpreter, tolerance: float) -> None:
        self._queue: queue.Queue[Chunk | None] = queue.Queue(_DEPTH)
        self._result: list[Any] = []
        self._stopped = threading.Event()
        self._thread = threading.Thread(target=self._serve, args=(new_interpreter, tolerance),
                                        daemon=True)
        self._thread.start()

    def _serve(self, new_interpreter: NewInterpreter, tolerance: float) -> None:
        def received() -> Iterator[Chunk]:
            while not self._stopped.is_set():
                message = self._queue.get()
                if message is _END:
                    return
                yield message

        try:
            self._result.append(check(received(), new_interpreter, tolerance))
        except Exception as exc:  # (reported as the verification's failure)
            self._result.append(Verified(0, math.inf, f"the verification failed: {exc!r}"))

    def send(self, text: str, moves: list[Move]) -> None:
        if self._thread.is_alive():
            self._queue.put((text, moves))

    def finish(self) -> Verified:
        if self._thread.is_alive():
            self._queue.put(_END)
        self._thread.join()
        return self._result[0]  # type: ignore[no-any-return]

    def close(self) -> None:
        self._stopped.set()
        while self._thread.is_alive():
            try:
                self._queue.put(_END, timeout=0.05)
            except queue.Full:
                with contextlib.suppress(queue.Empty):
                    self._queue.get_nowait()
            self._thread.join(0.05)


def start(new_interpreter: NewInterpreter, tolerance: float, parallel: bool = True) -> Checker:
    """The verification started: in a second process if ``parallel`` and the system forks,
    else in a thread."""
    if parallel and "fork" in multiprocessing.get_all_start_methods():
        return _ProcessChecker(new_interpreter, tolerance)
    return _ThreadChecker(new_interpreter, tolerance)
