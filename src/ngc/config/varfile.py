"""The parameter file (``rs274 -v file.var``), read and written byte for byte like rs274 2.9.0~pre1.

The format (overview.adoc, "Numbered Parameters Persistence"): one parameter per line, its number
and its value.  rs274 writes ``"%d\\t%f\\n"`` (``5161\\t0.000000``), in ascending order, for the
required parameters (:data:`REQUIRED_PARAMETERS`) and every other parameter the old file listed,
with the values the interpreter holds when it saves.  Parameters set by a program but absent from
the file are not written.  Without ``-v`` rs274 reads and writes no parameter file at all
(``[RS274NGC]PARAMETER_FILE`` is not consulted).

Reading (:func:`read_var_file`) follows C ``sscanf(line, "%d %lf")`` on lines read with a 256-byte
buffer (observed):

* A line that does not start with an integer followed by a number is skipped silently (blank
  lines, comments, ``5161``, ``5161 abc``, ``abc 1``).  Anything after the number is ignored
  (``5161 1 # note``), the number may be glued to the value (``5161-1`` is -1, and ``5161.5 1``
  is #5161 = 0.5), hexadecimal values, ``inf`` and ``nan`` are read, ``1e`` reads as 1.
* A line longer than 255 bytes is read in pieces of 255 bytes, each piece parsed as a line.
* A number outside 1..5601 stops rs274 with ``Parameter number out of range``; a number not
  greater than the previous one with ``Parameter file out of order``; a file that exists but
  cannot be opened with ``Unable to open parameter file: '<path>'``.  In each case rs274 has
  printed only ``USE_LENGTH_UNITS(CANON_UNITS_MM)``; it reports the message and an empty line,
  writes nothing and exits 1.
* A file that does not exist is an empty parameter file (no message); so is a directory.

Saving (:func:`write_var_file`) happens twice in rs274: once right after the file is read (before
the program is opened) and once at exit (also when the program failed, but not when the program
file could not be opened).  Each save writes ``<path>.new``, replaces ``<path>.bak`` by a hard link
to the old file and renames the new file over ``<path>``; a failing link or rename is reported
(``link (updating variable file): <reason>``) and the run goes on, a ``.new`` file that cannot be
created makes the save do nothing, silently.  The old file is read again at each save to know which
numbers it lists, this time with a 4096-byte buffer.  :func:`write_var_file` does the same, except
that its temporary file has a name of its own (``<path>.<random>.new``) and is fsync'ed, and that
it never leaves a temporary file behind when the save fails.

Where rs274 would block, or write where it should not, ngc differs (the parameter file may come
from anyone):

* Only a regular file (or a directory, or nothing) is a parameter file.  A FIFO, a device or a
  socket, also behind a symbolic link, is refused when it is read (``Unable to open parameter
  file: '<path>'``, before the program runs, exit 1) without waiting: a device is not even opened
  and a FIFO is opened with ``O_NONBLOCK``; where rs274 waits forever on a FIFO and, with the
  rights to, renames its file over ``/dev/null``.  A save never replaces one with a regular file
  (:data:`NOT_REGULAR`).  A symbolic link to a regular file is read through and, as by rs274,
  replaced by the new file; its target is not written.
* A save keeps the permission bits of the file it replaces (a 0444 file stays 0444); rs274's new
  file has 0666 less the umask, which is what a new parameter file gets here too.
* The new content is written into an unnamed file (Linux ``O_TMPFILE``) in the file's directory,
  which gets its ``<path>.<random>.new`` name only for the moment of the rename; a process killed
  while writing leaves nothing.  Where unnamed files cannot be made or linked (another system, no
  ``/proc``) a named temporary file is written, and removed when the save fails or is interrupted
  by an exception (``ngc`` turns SIGTERM and SIGHUP into one).
"""

from __future__ import annotations

import contextlib
import math
import os
import re
import stat
from collections.abc import Iterable, Iterator, Mapping, Sequence

from ..errors import NgcConfigError

__all__ = [
    "NOT_REGULAR",
    "PARAMETER_MAX",
    "PARAMETER_MIN",
    "REQUIRED_PARAMETERS",
    "format_var_file",
    "parse_var_file",
    "persistent_numbers",
    "read_var_file",
    "write_var_file",
]

PARAMETER_MIN, PARAMETER_MAX = 1, 5601

# The parameters every saved file lists (the "persistent range" of overview.adoc, "Parameters";
# observed: an empty file is saved as exactly these 119 lines):
REQUIRED_PARAMETERS: tuple[int, ...] = (
    *range(5161, 5170),  # G28 home, X Y Z A B C U V W
    *range(5181, 5190),  # G30 home, X .. W
    *range(5210, 5221),  # 5210 G92 applied, 5211-5219 G92 offset X .. W, 5220 coordinate system 1-9
    # G54 .. G59.3: X .. W at 5221 + 20 * k .. 5229 + 20 * k, XY rotation R at 5230 + 20 * k
    *(number for base in range(5221, 5382, 20) for number in range(base, base + 10)),
)

OUT_OF_RANGE = "Parameter number out of range"
OUT_OF_ORDER = "Parameter file out of order"
UNABLE_TO_OPEN = "Unable to open parameter file: '{}'"
# What a save returns instead of replacing a FIFO, device or socket (rs274 has no such message).
NOT_REGULAR = "Unable to save parameter file: '{}' is not a regular file"

# rs274 reads the file with fgets() into 256 bytes when it loads it, into 4096 when it saves.
LOAD_PIECE = 255
SAVE_PIECE = 4095
WRITE_BLOCK = 1 << 16

_SPACE = rb"[ \t\n\v\f\r]*"
_INTEGER = re.compile(_SPACE + rb"([+-]?[0-9]+)")
# What C scanf("%lf") takes from the text (glibc, observed): at least one digit or a hexadecimal
# prefix followed by a hex digit or point; an exponent without digits is ignored ("1e" is 1).
_DOUBLE = re.compile(
    _SPACE
    + rb"(?P<sign>[+-]?)(?:(?P<inf>infinity|inf(?![iI]))|(?P<nan>nan)"
    + rb"|0[xX](?P<hex>[0-9a-fA-F]*)(?:\.(?P<hexfrac>[0-9a-fA-F]*))?(?:[pP](?P<hexexp>[+-]?[0-9]*))?"
    + rb"|(?P<dec>[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE](?P<exp>[+-]?[0-9]*))?)",
    re.IGNORECASE,
)
_LONG_MIN, _LONG_MAX = -(2**63), 2**63 - 1


def _pieces(data: bytes, size: int) -> Iterator[bytes]:
    """The successive results of ``fgets(buffer, size + 1, file)``."""
    start = 0
    while start < len(data):
        newline = data.find(b"\n", start, start + size)
        stop = start + size if newline < 0 else newline + 1
        yield data[start:stop]
        start = stop


def _exponent(text: bytes | None) -> int:
    """An exponent as scanf takes it: a sign without digits counts as no exponent."""
    return int(text) if text and text.lstrip(b"+-") else 0


def _scan_double(line: bytes, position: int) -> float | None:
    """``%lf`` at ``position``: the value, or ``None`` when no number is there."""
    match = _DOUBLE.match(line, position)
    if match is None:
        return None
    if match.group("inf") or match.group("nan"):
        magnitude = math.inf if match.group("inf") else math.nan
    elif match.group("dec") is not None:
        magnitude = float(match.group("dec") + b"e%d" % _exponent(match.group("exp")))
    else:
        whole, fraction = match.group("hex"), match.group("hexfrac") or b""
        if not whole and match.group("hexfrac") is None:
            return None  # "0x" not followed by a hexadecimal digit or point
        exponent = _exponent(match.group("hexexp"))
        try:
            magnitude = float.fromhex(f"0x{whole.decode() or '0'}.{fraction.decode()}p{exponent}")
        except OverflowError:
            magnitude = math.inf
    return math.copysign(magnitude, -1.0 if match.group("sign") == b"-" else 1.0)


def _c_int(value: int) -> int:
    """What ``%d`` stores: the number as a C long (saturated), truncated to a 32-bit int."""
    value = min(max(value, _LONG_MIN), _LONG_MAX)
    return (value + 2**31) % 2**32 - 2**31


def _scan_line(line: bytes) -> tuple[int, float] | None:
    """``sscanf(line, "%d %lf")`` when it converts both, else ``None``."""
    line = line.split(b"\0", 1)[0]
    number = _INTEGER.match(line)
    if number is None:
        return None
    value = _scan_double(line, number.end())
    return None if value is None else (_c_int(int(number.group(1))), value)


def _config_error(message: str, path: str | None) -> NgcConfigError:
    # rs274 reports these like a program error whose source line is empty.
    return NgcConfigError(message, file=path, source="")


def _walk(data: bytes, piece: int, path: str | None) -> dict[int, float]:
    """Parse like rs274 with a ``piece + 1``-byte line buffer; raise on a number it refuses."""
    values: dict[int, float] = {}
    previous = 0
    for line in _pieces(data, piece):
        parsed = _scan_line(line)
        if parsed is None:
            continue
        number, value = parsed
        if not PARAMETER_MIN <= number <= PARAMETER_MAX:
            raise _config_error(OUT_OF_RANGE, path)
        if previous == PARAMETER_MAX:
            continue  # rs274's table is full: later lines are only range-checked
        if number <= previous:
            raise _config_error(OUT_OF_ORDER, path)
        values[number] = value
        previous = number
    return values


def parse_var_file(data: bytes, path: str | None = None) -> dict[int, float]:
    """The parameters a parameter file's bytes set, in ascending order (see the module docstring).

    >>> parse_var_file(b"# note\\n31 1.5\\n5161\\t-2 mm\\nbad\\n")
    {31: 1.5, 5161: -2.0}
    """
    return _walk(data, LOAD_PIECE, path)


def read_var_file(path: str | os.PathLike[str]) -> dict[int, float]:
    """The parameters set by the file at ``path``; ``{}`` when it does not exist or is a directory.

    Raises :class:`NgcConfigError` with rs274's message (``Parameter number out of range``,
    ``Parameter file out of order``, ``Unable to open parameter file: '<path>'``) and ``source``
    ``""``: rs274 prints the message, then an empty line, and exits 1 without running the program.
    A FIFO, device or socket is a file that cannot be opened; reading it never blocks.
    """
    name = os.fspath(path)
    if not os.path.exists(name):
        return {}
    try:
        data = _read_regular(name)
    except OSError as exc:
        raise _config_error(UNABLE_TO_OPEN.format(name), name) from exc
    return {} if data is None else parse_var_file(data, name)


def _read_regular(name: str) -> bytes | None:
    """The bytes of the regular file ``name`` (a symbolic link followed), ``None`` for a directory.

    OSError when it cannot be read or is not a regular file: a device is refused before it is
    opened, and what was opened is checked again, so that a FIFO put there since does not block.
    """
    if _not_regular(name):
        raise OSError(f"'{name}' is not a regular file")
    try:
        with open(name, "rb", opener=_open_nonblocking) as handle:
            if not stat.S_ISREG(os.fstat(handle.fileno()).st_mode):
                raise OSError(f"'{name}' is not a regular file")
            return handle.read()
    except IsADirectoryError:
        return None


def _open_nonblocking(name: str, flags: int) -> int:
    return os.open(name, flags | os.O_NONBLOCK | os.O_NOCTTY)


def _status(name: str) -> os.stat_result | None:
    """``stat`` (following a symbolic link), ``None`` when there is nothing to look at."""
    try:
        return os.stat(name)
    except OSError:
        return None


def _not_regular(name: str) -> bool:
    """Whether ``name`` is a FIFO, a device or a socket (what rs274 blocks on or replaces)."""
    status = _status(name)
    return status is not None and not (stat.S_ISREG(status.st_mode) or stat.S_ISDIR(status.st_mode))


def _permissions(name: str) -> int | None:
    """The permission bits a save keeps: those of the regular file it replaces."""
    status = _status(name)
    if status is None or not stat.S_ISREG(status.st_mode):
        return None
    return stat.S_IMODE(status.st_mode) & 0o777


def persistent_numbers(kept: Iterable[int]) -> list[int]:
    """The numbers a save writes: :data:`REQUIRED_PARAMETERS` and ``kept``, ascending.

    >>> persistent_numbers([31, 5161])[:3], len(persistent_numbers([]))
    ([31, 5161, 5162], 119)
    """
    wanted = {n for n in kept if PARAMETER_MIN <= n <= PARAMETER_MAX}
    return sorted(wanted.union(REQUIRED_PARAMETERS))


def c_float(value: float, fmt: str = "%f") -> str:
    """C ``printf(fmt)`` of a double (``%f``, ``%.Nf``), including glibc's ``-nan``.

    >>> c_float(-0.5), c_float(2.0, "%.1f"), c_float(-float("nan"))
    ('-0.500000', '2.0', '-nan')
    """
    if math.isnan(value):
        return "-nan" if math.copysign(1.0, value) < 0 else "nan"
    return fmt % value


def format_var_file(numbered: Sequence[float] | Mapping[int, float], numbers: Iterable[int]) -> bytes:
    """The bytes rs274 writes for ``numbers`` (ascending) with the values in ``numbered``.

    ``numbered`` is indexed by parameter number: the interpreter's array, or a mapping in which a
    missing number reads 0.

    >>> format_var_file({5161: 1.0, 5162: -0.0}, [5161, 5162, 5163])
    b'5161\\t1.000000\\n5162\\t-0.000000\\n5163\\t0.000000\\n'
    """
    if isinstance(numbered, Mapping):
        text = "".join(f"{n}\t{c_float(numbered.get(n, 0.0))}\n" for n in numbers)
    else:
        text = "".join(f"{n}\t{c_float(numbered[n])}\n" for n in numbers)
    return text.encode("ascii")


def _saved_numbers(path: str) -> list[int] | None:
    """The numbers of the old file that a save keeps, or ``None`` when rs274 abandons the save.

    rs274 reads the old file again, with 4096-byte lines, while it writes the new one; a number out
    of range or out of order there (possible only where long lines are cut differently than at
    load time) makes it stop writing, silently, and keep the old file.
    """
    try:
        data = _read_regular(path)
    except OSError:
        return []
    try:
        return [] if data is None else list(_walk(data, SAVE_PIECE, path))
    except NgcConfigError:
        return None


def _reason(exc: OSError) -> str:
    return os.strerror(exc.errno) if exc.errno else str(exc)


def _temp_name(path: str) -> str:
    """A temporary name next to ``path``: ``<path>.<random>.new``."""
    return f"{path}.{os.urandom(6).hex()}.new"


def _create_temp(path: str) -> tuple[int, str]:
    """A new file next to ``path``, created 0666 less the umask like rs274's ``<path>.new``."""
    while True:
        temp = _temp_name(path)
        try:
            return os.open(temp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_CLOEXEC, 0o666), temp
        except FileExistsError:
            continue


def _write_all(fd: int, data: bytes, permissions: int | None) -> None:
    """Write ``data``, give the file its permission bits and flush it to the disk."""
    view = memoryview(data)
    while view:
        view = view[os.write(fd, view[:WRITE_BLOCK]) :]
    if permissions is not None:
        os.fchmod(fd, permissions)
    os.fsync(fd)


def _write_temp(path: str, data: bytes, permissions: int | None) -> str | None:
    """The name of a new file next to ``path`` that holds ``data``; ``None`` when no file can be
    created there.  OSError when the data cannot be written (no file is left then)."""
    temp = _write_unnamed(path, data, permissions)
    return temp if temp is not None else _write_named(path, data, permissions)


def _write_unnamed(path: str, data: bytes, permissions: int | None) -> str | None:
    """Write ``data`` into an unnamed file in the directory of ``path`` and only then give it a
    temporary name; ``None`` when the system cannot, so that the caller writes a named file."""
    tmpfile: int = getattr(os, "O_TMPFILE", 0)
    if not tmpfile:
        return None
    try:
        directory = os.open(os.path.dirname(os.path.abspath(path)),
                            os.O_RDONLY | os.O_DIRECTORY | os.O_CLOEXEC)
    except OSError:
        return None
    try:
        try:
            fd = os.open(".", tmpfile | os.O_WRONLY | os.O_CLOEXEC, 0o666, dir_fd=directory)
        except OSError:
            return None
        try:
            _write_all(fd, data, permissions)
            return _link_unnamed(fd, directory, path)
        finally:
            os.close(fd)
    finally:
        os.close(directory)


def _link_unnamed(fd: int, directory: int, path: str) -> str | None:
    """Name the unnamed file ``fd`` in ``directory`` (linkat of its ``/proc`` entry, which follows
    the link, as unprivileged processes may); ``None`` when that cannot be done."""
    while True:
        temp = _temp_name(path)
        try:
            os.link(f"/proc/self/fd/{fd}", os.path.basename(temp), dst_dir_fd=directory)
        except FileExistsError:
            continue
        except OSError:
            return None
        return temp


def _write_named(path: str, data: bytes, permissions: int | None) -> str | None:
    """Write ``data`` into a named temporary file, removed again if the write fails."""
    try:
        fd, temp = _create_temp(path)
    except OSError:
        return None
    try:
        _write_all(fd, data, permissions)
    except BaseException:
        _remove(temp)
        raise
    finally:
        os.close(fd)
    return temp


def _remove(path: str) -> None:
    with contextlib.suppress(OSError):
        os.unlink(path)


def _backup(path: str) -> list[str]:
    """``<path>.bak`` becomes a hard link to the current file (rs274 reports a failed link)."""
    backup = path + ".bak"
    _remove(backup)
    try:
        os.link(path, backup, follow_symlinks=False)
    except OSError as exc:
        return [f"link (updating variable file): {_reason(exc)}"]
    return []


def _sync_directory(path: str) -> None:
    """Make the rename durable; not every system can open a directory, which is harmless."""
    try:
        fd = os.open(os.path.dirname(os.path.abspath(path)), os.O_RDONLY)
    except OSError:
        return
    try:
        with contextlib.suppress(OSError):
            os.fsync(fd)
    finally:
        os.close(fd)


def write_var_file(
    path: str | os.PathLike[str],
    numbered: Sequence[float] | Mapping[int, float],
    kept: Iterable[int] | None = None,
    *,
    backup: bool = True,
) -> list[str]:
    """Save the parameters like rs274 does, atomically; return what rs274 prints on stderr.

    The file lists :data:`REQUIRED_PARAMETERS` and the numbers in ``kept`` with their values in
    ``numbered``.  ``kept=None`` does what rs274 does: it reads the numbers from the file being
    replaced (after a successful :func:`read_var_file`, that is the keys it returned).

    The new content goes to a temporary file in the same directory, is flushed and fsync'ed, and
    is renamed over ``path``, so an interrupted save leaves the old file whole; the new file keeps
    the old one's permission bits.  With ``backup``, ``<path>.bak`` is first made a hard link to
    the old file, as rs274 does.  Failures are not raised: a temporary file that cannot be created
    means nothing happens (rs274 is silent too); a failed link, rename or write returns its
    message, e.g. ``["link (updating variable file): No such file or directory"]`` when ``path``
    did not exist yet.  The temporary file never outlives a failure.  (Where rs274 would rename a
    partly written file over the old one after a failed write, this keeps the old file and reports
    ``write (updating variable file): ...``.)  A FIFO, device or socket at ``path`` is left as it
    is, with the message :data:`NOT_REGULAR`.
    """
    name = os.fspath(path)
    if _not_regular(name):
        return [NOT_REGULAR.format(name)]
    if kept is None:
        kept = _saved_numbers(name)
        if kept is None:
            return []
    data = format_var_file(numbered, persistent_numbers(kept))
    try:
        temp = _write_temp(name, data, _permissions(name))
    except OSError as exc:
        return [f"write (updating variable file): {_reason(exc)}"]
    if temp is None:
        return []
    try:
        messages = _replace(temp, name, backup)
    except BaseException:
        _remove(temp)
        raise
    _sync_directory(name)
    return messages


def _replace(temp: str, name: str, backup: bool) -> list[str]:
    """Link the backup and rename ``temp`` over ``name``; ``temp`` is removed if that fails."""
    if _not_regular(name):  # put there while the new file was written
        _remove(temp)
        return [NOT_REGULAR.format(name)]
    messages = _backup(name) if backup else []
    try:
        os.replace(temp, name)
    except OSError as exc:
        _remove(temp)
        return [*messages, f"rename (updating variable file): {_reason(exc)}"]
    return messages
