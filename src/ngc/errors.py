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

import unicodedata


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
        # What the message is about, said after it where ngc explains (check, canon, time, plot;
        # not ``ngc rs274``, which keeps rs274's text): set, or found from ``word`` (the word
        # being read, letter and value: ``("g", 78.0)``) or ``char`` (a character refused);
        # ``token``, the text the error is about, places the caret where ``word`` cannot.
        self.about: str | None = None
        self.word: tuple[str, float] | None = None
        self.char: str | None = None
        self.token: str | None = None

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
        if self.column is None and self.source:
            if self.word is not None:
                self.column = word_column(self.source, *self.word)
            elif self.token:
                at = self.source.find(self.token)
                self.column = at + 1 if at >= 0 else None
        return self

    def where(self) -> str:
        """``file:line:col`` (parts that are unknown are left out: an error found running a line
        has a line and no column)."""
        parts = [self.file or "<string>"]
        if self.line is not None:
            parts.append(str(self.line))
            if self.column is not None:
                parts.append(str(self.column))
        return ":".join(parts)

    def explained(self) -> str:
        """The message and then what it is about, if that is known and the message does not say
        it: ``Unknown g code used: G78``, ``Bad character '\\342' used: '—' (EM DASH, U+2014)``."""
        about = self.about_text()
        message = self.text_message()
        return message if about is None else f"{message}: {about}"

    def text_message(self) -> str:
        """rs274's message for a program read as UTF-8 text, as ngc's commands and library read
        it (``ngc rs274`` reads bytes, one character each): a refused character past ASCII is
        shown by its first byte in UTF-8, which for U+0080..U+00FF is not the character's code
        (``é``, U+00E9, is the bytes ``\\303\\251``)."""
        char = self.char
        if char is None or not 0x80 <= ord(char) <= 0xFF:
            return self.message
        shown = f"'\\{ord(char):03o}'"
        return self.message.replace(shown, f"'\\{char.encode()[0]:03o}'", 1)

    def about_text(self) -> str | None:
        """What :meth:`explained` adds to the message, or None."""
        if self.about is not None:
            return self.about
        if self.word is not None:
            letter, value = self.word
            text = f"{letter.upper()}{value:.10g}"
            return None if text.lower() in self.message.lower() else text
        char = self.char
        if char is None and self.column is not None and self.source is not None \
                and 0 < self.column <= len(self.source):
            char = self.source[self.column - 1]  # (a character where a number was expected)
        if char is None or char.isascii():
            return None
        return describe_char(char)

    def render(self) -> str:
        """The explained message, then the source line and a caret under the column when it is
        known."""
        text = f"{self.where()}: {self.explained()}"
        if self.source is None:
            return text
        if self.column is None:
            return f"{text}\n    {self.source}"
        caret = " " * max(self.column - 1, 0) + "^"
        return f"{text}\n    {self.source}\n    {caret}"

    def __str__(self) -> str:
        return self.message


def describe_char(char: str) -> str:
    """A character and its Unicode name and code point (an en dash: ``'\u2013' (EN DASH,
    U+2013)``); a byte that is not UTF-8 (read as a lone surrogate) as the byte."""
    code = ord(char)
    if 0xDC80 <= code <= 0xDCFF:
        return f"the byte 0x{code - 0xDC00:02X}, which is not UTF-8 text"
    name = unicodedata.name(char, "")
    shown = repr(char) if char.isprintable() else "a control character"
    return f"{shown} ({name}, U+{code:04X})" if name else f"{shown} (U+{code:04X})"


def word_column(source: str, letter: str, value: float) -> int | None:
    """The 1-based column of the word ``letter`` with the literal ``value`` in a source line
    (outside comments, spaces in the number allowed as rs274 allows them; the last such word, as
    the second of two is the one refused); failing that, of the first ``letter`` whose value is
    not a literal; None if neither is on the line."""
    lowered = source.lower()
    n = len(lowered)
    found = fallback = None
    i = 0
    while i < n:
        c = lowered[i]
        if c == "(":
            close = lowered.find(")", i)
            i = n if close < 0 else close + 1
            continue
        if c == ";":
            break
        i += 1
        if c != letter:
            continue
        j = i
        while j < n and lowered[j] in " \t+-.0123456789":
            j += 1
        digits = lowered[i:j].replace(" ", "").replace("\t", "")
        try:
            if float(digits) == value:
                found = i
        except ValueError:
            if fallback is None and not digits:
                fallback = i
    return found or fallback


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
