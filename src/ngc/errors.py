"""The error hierarchy of ngc.

Every problem ngc reports about a program or its configuration is an
:class:`NgcError` carrying where it happened (file, line, column) and the
message LinuxCNC's interpreter gives for the same condition::

    NgcError
     ├── NgcSyntaxError     the text of a line cannot be read (bad number, unclosed comment, ...)
     ├── NgcSemanticError   the line reads fine but breaks a rule (modal clash, missing word, ...)
     ├── NgcRuntimeError    evaluation or execution failed (divide by zero, arc radius mismatch, ...)
     ├── NgcProgramError    the program as a whole is wrong (no program end, ABORT comment)
     │    └── NgcOpenError  nothing to run: an empty file or an unreadable first line
     └── NgcConfigError     a tool table, parameter file, INI file or option is unusable

:meth:`NgcError.render` draws the source line with a caret under the column.
"""

from __future__ import annotations


class NgcError(Exception):
    """A problem with a place: message, file, 1-based line, 1-based column, source text."""

    def __init__(
        self,
        message: str,
        *,
        file: str | None = None,
        line: int | None = None,
        column: int | None = None,
        source: str | None = None,
    ) -> None:
        super().__init__(message)
        self.message = message
        self.file = file
        self.line = line
        self.column = column
        self.source = source

    def locate(
        self, *, file: str | None, line: int, source: str, column: int | None = None
    ) -> NgcError:
        """Fill in the place where it is not known yet; returns self for ``raise e.locate(...)``."""
        if self.file is None:
            self.file = file
        if self.line is None:
            self.line = line
            self.source = source
        if self.column is None:
            self.column = column
        return self

    def where(self) -> str:
        """``file:line:col`` (parts that are unknown are left out)."""
        parts = [self.file or "<string>"]
        if self.line is not None:
            parts.append(str(self.line))
            parts.append(str(self.column or 1))
        return ":".join(parts)

    def render(self) -> str:
        """The message, then the source line and a caret under the column."""
        text = f"{self.where()}: {self.message}"
        if self.source is None:
            return text
        caret = " " * max((self.column or 1) - 1, 0) + "^"
        return f"{text}\n    {self.source}\n    {caret}"

    def __str__(self) -> str:
        return self.message


class NgcSyntaxError(NgcError):
    """The characters of a line do not form a valid block."""


class NgcSemanticError(NgcError):
    """A well-formed block breaks a rule of the language (words, modal groups, ...)."""


class NgcRuntimeError(NgcError):
    """Evaluating or executing a block failed."""


class NgcProgramError(NgcError):
    """The program as a whole is wrong: no end, an ABORT comment, ..."""


class NgcEndOfFile(NgcProgramError):
    """The program ran off the end of its file: no ``%``, no ``M2``/``M30``.  rs274 told to
    continue after errors (``-n 0``) meets it again at every read, for ever: no run goes on
    after it."""


class NgcOpenError(NgcProgramError):
    """The program cannot be started: it is empty or its first line cannot be read."""


class NgcConfigError(NgcError):
    """A configuration input (tool table, parameter file, INI, option) is unusable."""
