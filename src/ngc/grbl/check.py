"""Grbl in check mode (``$C``): each line of a program sent to it, answered ``ok`` or
``error:N`` as Grbl 1.1 answers it, its parser state carried from line to line.

A rejected line changes nothing (Grbl drops the whole block), so the lines after it are checked
against the state before it, as on the machine.  A line that starts with ``$`` is a system
command, not G code: it is not checked (:attr:`Checker.system_lines` lists them); on the
machine most of them answer ``error:8`` in check mode (they need Grbl idle), and ``$C`` would
leave check mode.
"""

from __future__ import annotations

import io
from collections.abc import Iterable, Iterator
from typing import NamedTuple

from .block import Reader, Rejected
from .checks import Check
from .codes import LINE_OVERFLOW, MESSAGES
from .lines import grbl_lines, kept, without_end
from .rules import GRBL, Rules
from .state import GrblState, execute

OK = 0


class GrblError(NamedTuple):
    """A line Grbl rejects: its number in the file (from 1), the status code (``error:N``),
    the code's message (Grbl's ``error_codes_en_US.csv``) and the line as the file has it."""

    line: int
    code: int
    message: str
    text: str


class Grbl:
    """One Grbl in check mode, from power-up: :meth:`send` it lines one at a time.

    >>> grbl = Grbl()
    >>> grbl.send("G1 X10"), grbl.send("G1 X10 F500"), grbl.send("G2 X0 Y0 I-5 J0")
    (22, 0, 0)
    """

    def __init__(self, rules: Rules = GRBL) -> None:
        self.rules = rules
        self.state = GrblState(rules)
        self._reader = Reader(rules)
        self._check = Check(rules)

    def send(self, line: str) -> int | None:
        """Grbl's answer to one line (no line end in it): 0 (``ok``), an error code, or None
        for a ``$`` system command, which is not checked."""
        text = kept(line)
        if len(text) > self.rules.line_chars:
            return LINE_OVERFLOW
        if not text:
            return OK
        if text[0] == "$":
            return None
        state = self.state
        try:
            plan = self._check.block(self._reader.read(text, state.modes), state)
        except Rejected as exc:
            return exc.code
        execute(plan, state, self.rules)
        return OK


class Checker:
    """Checks the lines of one program; counts them (:attr:`lines`) and the rejected ones
    (:attr:`rejected`), and notes the lines of system commands (:attr:`system_lines`) as
    :meth:`errors` reads them."""

    def __init__(self, rules: Rules = GRBL) -> None:
        self.grbl = Grbl(rules)
        self.lines = 0
        self.rejected = 0
        self.system_lines: list[int] = []

    def errors(self, lines: Iterable[str]) -> Iterator[GrblError]:
        """The rejected lines of ``lines`` (each one line of a file, its line end kept or not),
        in order, as they are read."""
        send = self.grbl.send
        for number, line in enumerate(lines, self.lines + 1):
            self.lines = number
            text = without_end(line)
            for part in grbl_lines(text):
                status = send(part)
                if status is None:
                    if not self.system_lines or self.system_lines[-1] != number:
                        self.system_lines.append(number)
                elif status:
                    self.rejected += 1
                    yield GrblError(number, status, MESSAGES[status], text)


def check_lines(lines: Iterable[str], rules: Rules = GRBL) -> Iterator[GrblError]:
    """The lines of a program that Grbl (``rules``: Grbl 1.1's default build) rejects in check
    mode, as they are read: ``lines`` is any iterable of lines, such as an open file."""
    return Checker(rules).errors(lines)


def check_text(text: str, rules: Rules = GRBL) -> list[GrblError]:
    """The lines of a program given as text that Grbl 1.1 (by default) rejects in check mode;
    lines end at ``\\n``, ``\\r\\n`` or ``\\r``, as Grbl ends them.

    >>> for error in check_text("G21 G90\\nG1 X10 Y0\\nG1 X10 Y0 F300\\nG2 X20 Y0 I3 J0\\nM2\\n"):
    ...     print(error.line, error.code, error.message)
    2 22 Feed rate has not yet been set or is undefined.
    4 33 Motion command target is invalid.
    """
    return list(check_lines(io.StringIO(text, newline=""), rules))
