"""Log files written by program text: ``(LOGOPEN,name)``, ``(LOGAPPEND,name)``, ``(LOG,text)``,
``(LOGCLOSE)`` (overview.adoc "Logging") and the probe log ``(PROBEOPEN name)`` / ``(PROBECLOSE)``
(overview.adoc "Probe Logging", g-code.adoc "G38").

rs274 hands the LOG comments to the machine as canonical calls (``LOGOPEN("name")``,
``LOGAPPEND("name")``, ``LOG("text")``, ``LOGCLOSE()``) and PROBEOPEN / PROBECLOSE as ordinary
``COMMENT`` calls; it writes no file itself.  ngc emits the same calls and also writes the files,
kept on the interpreter (``log``, ``probe_log``) until closed by the program or by
``Machine.close()``:

* LOGOPEN truncates, LOGAPPEND appends; opening a log while one is open closes the old one.
* Each LOG writes its text (parameters substituted like DEBUG) and a newline; without an open log
  it only emits the call.  Every write is flushed, so the file is complete even if the run stops.
* The name is the text after the comma, as rs274 passes it (spaces included).  The probe log name
  is the text after ``PROBEOPEN`` and white space, trimmed; each successful straight probe writes
  a line of the nine coordinates X Y Z A B C U V W (:func:`write_probe`).
* Files are confined to the working directory: a name that is absolute, or that resolves outside
  the working directory (``..``, a symbolic link leading out), is refused with
  :class:`NgcRuntimeError`, as are an empty name and a file that cannot be opened.
* Only a regular file with exactly one link is written (:func:`open_log`): a FIFO, a device or a
  socket is refused (``LOGOPEN: 'x' is not a regular file``), and so is a hard link that shares its
  data with another name, possibly outside the working directory (``LOGOPEN: 'x' has other hard
  links``).  The file is opened without following a symbolic link, without blocking and without
  truncating; it is checked on the open descriptor, and only then truncated (LOGOPEN, PROBEOPEN).
  A refused file is left as it was.  With ``Machine.write_files`` false no file is opened at all.

Text is written byte for byte as ``ngc rs274`` reads the program (latin-1: one character per byte).
"""

from __future__ import annotations

import contextlib
import errno
import os
import re
import stat
from collections.abc import Sequence
from typing import TYPE_CHECKING, Literal, TextIO

from ...canon import ops
from ...errors import NgcRuntimeError

if TYPE_CHECKING:
    from ..machine import Machine

# (PROBEOPEN name) / (PROBECLOSE): the keyword, then white space and the name (or the end).
_PROBE = re.compile(r"probe(open|close)(?:[ \t]+|\Z)", re.IGNORECASE)
# The nine coordinates of a probe-log line.
PROBE_LINE = " ".join(["%f"] * 9) + "\n"


def log_open(it: Machine, name: str, append: bool) -> None:
    """``(LOGOPEN,name)`` truncates the file, ``(LOGAPPEND,name)`` appends to it."""
    if not it.write_files:
        it.emit(ops.LogAppend(name) if append else ops.LogOpen(name))
        return
    handle = _open(it, "LOGAPPEND" if append else "LOGOPEN", name, "a" if append else "w")
    if it.log is not None:
        it.log.close()
    it.log = handle
    it.emit(ops.LogAppend(name) if append else ops.LogOpen(name))


def log(it: Machine, text: str) -> None:
    """``(LOG,text)``: the text (already substituted) and a newline, if a log is open."""
    it.emit(ops.Log(text))
    if it.log is not None:
        _write(it.log, "LOG", text + "\n")


def log_close(it: Machine) -> None:
    """``(LOGCLOSE)``: close the log, if one is open."""
    it.emit(ops.LogClose())
    if it.log is not None:
        it.log.close()
        it.log = None


def probe_comment(it: Machine, text: str) -> None:
    """Open or close the probe log if the comment ``text`` is PROBEOPEN / PROBECLOSE."""
    m = _PROBE.match(text)
    if m is None:
        return
    rest = text[m.end() :].strip(" \t")
    if m.group(1).lower() == "close":
        if not rest:
            _close_probe_log(it)
        return
    if not it.write_files:
        return
    handle = _open(it, "PROBEOPEN", rest, "w")
    _close_probe_log(it)
    it.probe_log = handle


def write_probe(it: Machine, coordinates: Sequence[float]) -> None:
    """Log a successful straight probe: X Y Z A B C U V W, if a probe log is open."""
    if it.probe_log is not None:
        _write(it.probe_log, "PROBEOPEN", PROBE_LINE % tuple(coordinates))


def _close_probe_log(it: Machine) -> None:
    if it.probe_log is not None:
        it.probe_log.close()
        it.probe_log = None


def _open(it: Machine, command: str, name: str, mode: Literal["w", "a"]) -> TextIO:
    """Open ``name`` for writing, refusing names outside the working directory."""
    path = confined_path(command, it.file_name(name))
    return open(path, mode, encoding="latin-1", errors="replace", newline="",
                opener=lambda resolved, _flags: open_log(command, name, resolved, mode == "a"))


# O_NONBLOCK: opening a FIFO must not wait for a reader (with none, the open fails with ENXIO);
# O_NOFOLLOW: ``path`` is already resolved, so a symbolic link there now was put in since.
_OPEN_FLAGS = (os.O_WRONLY | os.O_CREAT | os.O_NONBLOCK | os.O_NOFOLLOW | os.O_NOCTTY
               | os.O_CLOEXEC)


def open_log(command: str, name: str, path: str, append: bool) -> int:
    """A descriptor on the regular, singly linked file at the resolved ``path``, truncated unless
    ``append``; NgcRuntimeError naming ``name`` otherwise, the file left untouched."""
    with contextlib.suppress(OSError):
        _check(command, name, os.lstat(path))  # refuse a device before opening it
    try:
        fd = os.open(path, _OPEN_FLAGS | (os.O_APPEND if append else 0), 0o666)
    except OSError as exc:
        if exc.errno in (errno.ENXIO, errno.ELOOP):  # a FIFO without reader, a symbolic link
            raise NgcRuntimeError(f"{command}: '{name}' is not a regular file") from None
        raise _cannot_open(command, name, exc) from None
    try:
        _check(command, name, os.fstat(fd))  # what was opened, whatever lstat saw
        if not append:
            os.ftruncate(fd, 0)
    except OSError as exc:
        os.close(fd)
        raise _cannot_open(command, name, exc) from None
    except BaseException:
        os.close(fd)
        raise
    return fd  # O_NONBLOCK stays: it changes nothing for a regular file


def _cannot_open(command: str, name: str, exc: OSError) -> NgcRuntimeError:
    return NgcRuntimeError(f"{command}: cannot open '{name}': {exc.strerror}")


def _check(command: str, name: str, status: os.stat_result) -> None:
    if stat.S_ISDIR(status.st_mode):
        raise NgcRuntimeError(f"{command}: cannot open '{name}': {os.strerror(errno.EISDIR)}")
    if not stat.S_ISREG(status.st_mode):
        raise NgcRuntimeError(f"{command}: '{name}' is not a regular file")
    if status.st_nlink != 1:
        raise NgcRuntimeError(f"{command}: '{name}' has other hard links")


def confined_path(command: str, name: str) -> str:
    """The real path of ``name`` in the working directory; NgcRuntimeError if it is elsewhere."""
    if not name.strip():
        raise NgcRuntimeError(f"{command}: no file name")
    if os.path.isabs(name):
        raise NgcRuntimeError(
            f"{command}: file '{name}' is an absolute path; only files in the working directory "
            "can be written"
        )
    cwd = os.path.realpath(os.getcwd())
    path = os.path.realpath(os.path.join(cwd, name))
    if os.path.commonpath([cwd, path]) != cwd:
        raise NgcRuntimeError(f"{command}: file '{name}' is outside the working directory")
    return path


def _write(handle: TextIO, command: str, text: str) -> None:
    try:
        handle.write(text)
        handle.flush()
    except OSError as exc:
        raise NgcRuntimeError(f"{command}: cannot write '{handle.name}': {exc.strerror}") from None
