"""Grbl 1.1's acceptance of a program, offline: each line checked as Grbl's check mode (``$C``)
answers it, ``ok`` or ``error:N`` (``ngc check --dialect grbl``).

* :func:`check_text` — the rejected lines of a program given as text, as :class:`GrblError`
  (line, code, message, text); :func:`check_lines` — the same from any iterable of lines,
  streamed.
* :class:`Grbl` — one controller in check mode: ``send(line)`` answers one line;
  :class:`Checker` — a program's lines through one, counting them.
* :class:`Rules` — what a build of Grbl accepts (line length, axes, M7, largest tool, ...);
  :data:`GRBL` is Grbl 1.1h's default build, :data:`DIALECTS` the builds by name.

Grbl's own reading is followed to the letter (its ``protocol.c``, ``gcode.c`` and
``nuts_bolts.c``): what the line reader keeps of a line (:mod:`ngc.grbl.lines`), the words read
(:mod:`ngc.grbl.block`), the checks in Grbl's order (:mod:`ngc.grbl.checks`), the state a block
leaves (:mod:`ngc.grbl.state`), numbers in single precision (:mod:`ngc.grbl.numbers`), the codes
and messages (:mod:`ngc.grbl.codes`).

>>> [(e.line, e.code) for e in check_text("G0 X1\\nM6 T1\\nG1 X2 F100 P3\\n")]
[(2, 20), (3, 36)]
"""

from __future__ import annotations

from .check import Checker, Grbl, GrblError, check_lines, check_text
from .codes import MESSAGES
from .rules import DIALECTS, GRBL, Rules

__all__ = ["DIALECTS", "GRBL", "MESSAGES", "Checker", "Grbl", "GrblError", "Rules", "check_lines",
           "check_text"]
