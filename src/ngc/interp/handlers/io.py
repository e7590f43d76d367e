"""Digital and analog I/O: M62-M65 set or clear an output bit (M62/M63 synchronized with motion,
M64/M65 at once), M66 waits on an input, M67/M68 set an analog output (m-code.adoc, "M62 to M65
Digital Output Control", "M66 Wait on Input", "M67 Synchronized Analog Output", "M68 Analog
Output").

The standalone machine has no inputs: M66 emits nothing and #5399 (the input's value) stays as
it was.  Indexes are rounded to the nearest integer, halves to even (``P2.5`` is output 2); rs274
checks the words when the code's step comes (after the F and S of its line have run).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ...canon import ops
from ...errors import NgcSemanticError
from ...language.codes import WAIT_COMP
from . import ccomp

if TYPE_CHECKING:
    from ...language.words import Words
    from ..machine import Machine

_Bit = type[ops.SetMotionOutputBit | ops.ClearMotionOutputBit | ops.SetAuxOutputBit
            | ops.ClearAuxOutputBit]
_BITS: dict[int, _Bit] = {62: ops.SetMotionOutputBit, 63: ops.ClearMotionOutputBit,
                          64: ops.SetAuxOutputBit, 65: ops.ClearAuxOutputBit}
_VALUES: dict[int, type[ops.SetMotionOutputValue | ops.SetAuxOutputValue]] = {
    67: ops.SetMotionOutputValue, 68: ops.SetAuxOutputValue}


def output_bit(it: Machine, r: Words, code: int) -> None:
    """M62 / M63 / M64 / M65 P-: set or clear digital output P."""
    p = r.w.get("p")
    if p is None:
        raise NgcSemanticError(f"No valid P word with M{code}")
    it.emit(_BITS[code](round(p)))


def output_value(it: Machine, r: Words, code: int) -> None:
    """M67 / M68 E- Q-: set analog output E to Q (no Q: -1, as rs274 has it)."""
    e = r.w.get("e")
    if e is None or round(e) < 0:
        raise NgcSemanticError(f"Invalid analog index with M{code}")
    it.emit(_VALUES[code](round(e), r.w.get("q", -1.0)))


def wait_input(it: Machine, r: Words, code: int) -> None:
    """M66 P- (digital) or E- (analog) input, L- wait type (0 at once, 1 rise, 2 fall, 3 high,
    4 low), Q- timeout in seconds; only checked here."""
    w = r.w
    digital = "p" in w and round(w["p"]) >= 0
    analog = "e" in w and round(w["e"]) >= 0
    if digital and analog:
        raise NgcSemanticError("Invalid to select both a digital and an analog input with M66")
    if not (digital or analog):
        raise NgcSemanticError("Need to have either a valid P or a valid E word with M66")
    if w.get("l", 0.0) != 0.0:
        if w.get("q", 0.0) <= 0.0:
            raise NgcSemanticError("Zero timeout with wait type != immediate return")
        if analog:
            raise NgcSemanticError("Can't select analog input with wait type != immediate return")
    ccomp.refuse(it, WAIT_COMP if digital else WAIT_COMP.replace("digital", "analog"))
