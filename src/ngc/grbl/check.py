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

from .block import NotChecked, Reader, Rejected
from .checks import Check
from .codes import LINE_OVERFLOW, MESSAGES
from .lines import grbl_lines, hal_normalized, hal_received, kept, past_ascii, without_end
from .rules import GRBL, Rules
from .state import GrblState, execute

OK = 0
NOT_CHECKED = -1  # a line the row reads but does not check (Grbl.unchecked says why)
# grblHAL's messages where they are not Grbl's (errors.c), and its 39
MESSAGES_GRBLHAL = {
    **MESSAGES,
    38: "Tool number greater than max supported value or undefined tool selected.",
    39: "Value out of range.",
}


class GrblError(NamedTuple):
    """A line Grbl rejects: its number in the file (from 1), the status code (``error:N``),
    the code's message (Grbl's ``error_codes_en_US.csv``) and the line as the file has it.
    ``code`` None: a line the row does not check, ``message`` says what it has that no check
    models (``not checked: ...``)."""

    line: int
    code: int | None
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
        self.unchecked = ""  # what the last line answered NOT_CHECKED has that no check models
        self.latched = OK  # grblHAL: the error G-code lines are answered with (Rules.error_latch)
        self._reader = Reader(rules)
        self._check = Check(rules)

    def send(self, line: str) -> int | None:
        """Grbl's answer to one line (no line end in it): 0 (``ok``), an error code, None
        for a ``$`` system command, which is not checked, or :data:`NOT_CHECKED`."""
        if self.rules.reader == "grblhal":
            return self._send_grblhal(line)
        text = kept(line)
        if len(text) > self.rules.line_chars:
            return LINE_OVERFLOW
        if not text:
            return OK
        if text[0] == "$":
            return None
        return self._block(text)

    def _block(self, text: str) -> int:
        """The answer to a block as the parser reads it."""
        state = self.state
        try:
            plan = self._check.block(self._reader.read(text, state.modes), state)
        except Rejected as exc:
            return exc.code
        except NotChecked as exc:
            self.unchecked = exc.what
            return NOT_CHECKED
        execute(plan, state, self.rules)
        return OK

    def _send_grblhal(self, line: str) -> int | None:
        """grblHAL's answer (protocol.c): the line's length as received (error 11); an empty
        line ``ok``, and it ends the error latch, as a ``$`` line is taken to; while an error
        is latched, each G-code line is answered with it unread; a ``%`` line is ``ok``."""
        if past_ascii(line):
            self.unchecked = "a character past 0x7F (what is kept of it is the driver's stream's)"
            return NOT_CHECKED
        received = hal_received(line)
        if len(received) > self.rules.line_chars:
            return self._latch(LINE_OVERFLOW)
        if not received or received[0] == "$":
            self.latched = OK
            return None if received else OK
        if self.latched:
            return self.latched
        text = hal_normalized(received)
        if not text or text == "%":  # gcode.c: "%" alone toggles file_run
            return OK
        status = self._block(text)
        return self._latch(status) if status > 0 else status

    def _latch(self, status: int) -> int:
        if self.rules.error_latch:
            self.latched = status
        return status

    def message(self, code: int) -> str:
        """The controller's message for an error code."""
        return (MESSAGES_GRBLHAL if self.rules.parser == "grblhal" else MESSAGES)[code]


class Checker:
    """Checks the lines of one program; counts them (:attr:`lines`) and the rejected ones
    (:attr:`rejected`), and notes the lines of system commands (:attr:`system_lines`) and the
    lines not checked (:attr:`unchecked_lines`) as :meth:`errors` reads them."""

    def __init__(self, rules: Rules = GRBL) -> None:
        self.grbl = Grbl(rules)
        self.lines = 0
        self.rejected = 0
        self.system_lines: list[int] = []
        self.unchecked_lines: list[int] = []

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
                elif status == NOT_CHECKED:
                    self.unchecked_lines.append(number)
                    yield GrblError(number, None, f"not checked: {self.grbl.unchecked}", text)
                elif status:
                    self.rejected += 1
                    yield GrblError(number, status, self.grbl.message(status), text)


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
