"""Program files read as rs274 reads them: in bounded pieces, never held whole.

rs274 reads a file line by line into a fixed buffer: a piece of at most :data:`LINE_BYTES` bytes
that ends after a newline or where the buffer is full.  A line that fills the buffer is refused
(``Command too long``, see the interpreter) unless a NUL byte cuts it short; then the rest of it
is read as the next line, as rs274 does.  :class:`ProgramReader` yields the same pieces, decoded,
so no input is held whole: an endless file with no newline (the zero device) ends with
``Command too long`` after :data:`MAX_PIECES` full pieces instead of growing without bound.

Control flow (o-words, M98) goes back to lines already read.  Rather than keeping them, a body of
lines keeps a compact index into its file (``flow.Body``): the byte position of every
:data:`CHECKPOINT`-th line, from which any line is read again, and a bounded cache of the lines
it has compiled, so a loop body is parsed once while the memory a program needs stays flat in its
length.  Input that cannot be read again (a pipe, lines given as strings) is kept in memory.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import BinaryIO

from ..errors import NgcSyntaxError

BOM = b"\xef\xbb\xbf"
# rs274 reads a line into a 255-byte buffer: 254 bytes at most, the newline included.
LINE_BYTES = 254
# Full pieces in a row (no newline in 64 KiB) after which a line is refused without more reading.
MAX_PIECES = 256
# Every this many lines, a body notes where the next line starts in its file.
CHECKPOINT = 32
# Compiled lines a body keeps at most; past this, the cache starts over.
CACHE_LINES = 4096


class ProgramReader:
    """The lines of a binary file as rs274 reads them (see the module docstring), decoded with
    ``encoding`` and ``errors``; each line keeps its newline.

    ``skip_bom`` drops a UTF-8 byte-order mark at the start of the file.  Iterate it once; a
    seekable file can also be read again at a position (:meth:`tell`, :meth:`read_at`).
    """

    def __init__(self, handle: BinaryIO, encoding: str = "latin-1", errors: str = "strict",
                 *, skip_bom: bool = False) -> None:
        self.handle = handle
        self.encoding = encoding
        self.errors = errors
        try:
            self.seekable = handle.seekable()
        except (OSError, ValueError):
            self.seekable = False
        if skip_bom:
            self._skip_bom()

    def _skip_bom(self) -> None:
        handle = self.handle
        peek = getattr(handle, "peek", None)
        if peek is not None:
            if peek(3)[:3] == BOM:
                handle.read(3)
        elif self.seekable:
            start = handle.tell()
            if handle.read(3) != BOM:
                handle.seek(start)

    def __iter__(self) -> Iterator[str]:
        readline = self.handle.readline
        encoding, errors = self.encoding, self.errors
        full = 0
        number = 0
        while True:
            piece = readline(LINE_BYTES)
            if not piece:
                return
            number += 1
            if len(piece) == LINE_BYTES and piece[-1] != 10:  # no newline: the buffer was full
                full += 1
                if full > MAX_PIECES:
                    text = piece.decode(encoding, errors)
                    raise NgcSyntaxError("Command too long", line=number,
                                         source=text.split("\0", 1)[0])
            else:
                full = 0
            yield piece.decode(encoding, errors)

    def fileno(self) -> int:
        return self.handle.fileno()

    def tell(self) -> int:
        """The byte position of the next line."""
        return self.handle.tell()

    def read_at(self, position: int, count: int) -> list[str]:
        """The ``count`` lines from byte ``position`` on (fewer at the end of the file); the
        reading position is restored."""
        handle = self.handle
        here = handle.tell()
        try:
            handle.seek(position)
            lines = []
            for _ in range(count):
                piece = handle.readline(LINE_BYTES)
                if not piece:
                    break
                lines.append(piece.decode(self.encoding, self.errors))
            return lines
        finally:
            handle.seek(here)

    def close(self) -> None:
        self.handle.close()

    def __enter__(self) -> ProgramReader:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def open_program(path: str) -> ProgramReader:
    """A program file read as rs274 reads it: bytes, one character each (latin-1).  Raises
    ``OSError``."""
    return ProgramReader(open(path, "rb"))


def text_reader(handle: BinaryIO) -> ProgramReader:
    """A program read as UTF-8 text (``ngc canon``, ``ngc check``): a leading byte-order mark
    skipped, bytes that are not UTF-8 kept as surrogates (written back as the same bytes)."""
    return ProgramReader(handle, "utf-8", "surrogateescape", skip_bom=True)


def open_text_program(path: str) -> ProgramReader:
    """A program file read as :func:`text_reader` reads it.  Raises ``OSError``."""
    return text_reader(open(path, "rb"))
