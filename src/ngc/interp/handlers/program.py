"""Comments and program flow: COMMENT, (MSG,…), (DEBUG,…), (PRINT,…), (ABORT,…), M0/M1/M60 stops
and the M2/M30 program end (overview.adoc "Comments", "Messages"; m-code.adoc "M2, M30")."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from ...canon import ops
from ...errors import NgcProgramError, NgcRuntimeError
from ..parameters import DEBUG_ENABLE
from . import coordinates

if TYPE_CHECKING:
    from ..interpreter import Interpreter

_COMMAND = re.compile(r"\s*(msg|debug|print|abort),", re.IGNORECASE)
# In DEBUG/PRINT/ABORT text: a format (%d, %f, %.Nf) or a parameter (#123, #<name>).
# The comment formats and the printf format each stands for (%.Nf stands for itself).
_FORMATS = {"%d": "%.0f", "%f": "%.4f"}
_SUBSTITUTION = re.compile(r"%(?:d|f|\.[0-9]f)|#(?:<[^>]*>|[0-9]+)")


def comment(it: Interpreter, text: str) -> None:
    """Convert the (last) comment of a block."""
    body = text[1:-1]
    m = _COMMAND.match(body)
    if m is None:
        body = body.lstrip(" \t")
        if body:
            it.emit(ops.Comment(body))
        return
    kind = m.group(1).lower()
    rest = body[m.end() :]
    if kind == "msg":
        it.emit(ops.Message(rest))
    elif kind == "debug":
        if it.params.numbered[DEBUG_ENABLE] != 0.0:
            it.emit(ops.Message(substitute(it, rest)))
    elif kind == "print":
        it.sink.print_text(substitute(it, rest))
    else:
        raise NgcProgramError(substitute(it, rest))


def substitute(it: Interpreter, text: str) -> str:
    """Replace parameters by their values; ``%d`` / ``%f`` / ``%.Nf`` set the format of the rest."""
    fmt = "%f"
    out: list[str] = []
    pos = 0
    for m in _SUBSTITUTION.finditer(text):
        out.append(text[pos : m.start()])
        pos = m.end()
        token = m.group()
        if token[0] == "%":
            fmt = _FORMATS.get(token, token)
            continue
        value = _parameter(it, token)
        out.append("######" if value is None else fmt % (value + 0.0))
    out.append(text[pos:])
    return "".join(out)


def _parameter(it: Interpreter, token: str) -> float | None:
    """The value a ``#...`` in a comment stands for; None for an undefined name."""
    params = it.params
    if token[1] == "<":
        name = "".join(token[2:-1].split()).lower()
        if not params.exists(name):
            return None
        return params.named(name)
    index = int(token[1:])
    if index < 1 or index >= len(params.numbered):
        raise NgcRuntimeError("Parameter number out of range")
    return params.num(index)


def stop(it: Interpreter, code: int) -> None:
    """M0 / M1 / M60 pause; M2 / M30 end the program (LinuxCNC resets its modes)."""
    if code == 0:
        it.emit(ops.ProgramStop())
    elif code == 1:
        it.emit(ops.OptionalProgramStop())
    elif code == 60:
        it.emit(ops.PalletShuttle())
        it.emit(ops.ProgramStop())
    else:
        program_end(it, code)


def program_end(it: Interpreter, code: int) -> None:
    """M2 / M30: G54 origin, XY plane, G90, G94, feed 0, spindle and coolant off, G1."""
    st = it.state
    machine = coordinates.to_machine(st, st.pos)
    coordinates.load_system(it, 1)
    it.params.numbered[5220] = 1.0
    st.pos = coordinates.to_program(st, machine)
    coordinates.emit_g5x(it)
    coordinates.emit_rotation(it)
    if st.plane != 170:
        st.plane = 170
        it.emit(ops.SelectPlane("CANON_PLANE_XY"))
    st.absolute = True
    st.feed_mode = 940
    it.emit(ops.SetFeedMode(0, 0))
    st.feed = 0.0
    it.emit(ops.SetFeedRate(0.0))
    if not (st.feed_override and st.speed_override):
        st.feed_override = st.speed_override = True
        it.emit(ops.EnableFeedOverride())
    st.spindle = 0
    it.emit(ops.StopSpindleTurning(0))
    it.emit(ops.SetSpindleMode(0, 0.0))
    if st.mist:
        st.mist = False
        it.emit(ops.MistOff())
    if st.flood:
        st.flood = False
        it.emit(ops.FloodOff())
    st.motion = 10
    if code == 30:
        it.emit(ops.PalletShuttle())
    it.emit(ops.ProgramEnd())
    it.ended = True
