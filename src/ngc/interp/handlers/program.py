"""Comments and program flow: COMMENT, (MSG,…), (DEBUG,…), (PRINT,…), (ABORT,…), the log comments
(see :mod:`.logfile`), M0/M1/M60 stops and the M2/M30 program end (overview.adoc "Comments",
"Messages", "Logging"; m-code.adoc "M2, M30")."""

from __future__ import annotations

import re
from collections.abc import Callable
from types import MappingProxyType
from typing import TYPE_CHECKING

from ...canon import ops
from ...config.varfile import c_float
from ...errors import NgcProgramError
from .. import frames
from ..parameters import DEBUG_ENABLE
from . import ccomp, coordinates, logfile

if TYPE_CHECKING:
    from ..machine import Machine

# An active comment: white space (C's isspace), the keyword (any case), a comma and the text;
# or LOGCLOSE alone.  Anything else (a space before the comma, text after LOGCLOSE) is a COMMENT.
_COMMAND = re.compile(
    r"[ \t\n\v\f\r]*(?:(msg|debug|print|abort|logopen|logappend|log),|(logclose)\Z)", re.IGNORECASE
)
# In DEBUG/PRINT/LOG/ABORT text: a format (%d, %f, %.Nf) or a parameter (#123, #<name>); a "%"
# before a "." that does not start a format is dropped (rs274 does so).
# The comment formats and the printf format each stands for (%.Nf stands for itself).
_FORMATS = MappingProxyType({"%d": "%.0f", "%f": "%.4f"})
_SUBSTITUTION = re.compile(r"%(?:d|f|\.[0-9]f|(?=\.))|#(?:<[^>]*>|[0-9]+)")
# rs274 reads a parameter number in a comment as a C long (saturating) and keeps an int of it.
_LONG_MAX = 2**63 - 1
_SHOWN_MIN = 0.0001
_SHOWN_WIDTH = 29
_INT_WRAP = 2**32


def comment(it: Machine, text: str) -> None:
    """Convert the (last) comment of a block."""
    body = text[1:-1]
    m = _COMMAND.match(body)
    if m is None:
        if not body:
            return  # "()" is no comment; "( )" is an empty one
        body = body.lstrip(" \t")
        if body:
            logfile.probe_comment(it, body)
        it.emit(ops.Comment(body))
        _pass_message(it)
        return
    kind = (m.group(1) or m.group(2)).lower()
    _ACTIVE[kind](it, body[m.end() :])


def _msg(it: Machine, rest: str) -> None:
    it.emit(ops.Message(rest))
    _pass_message(it)


def _pass_message(it: Machine) -> None:
    """A comment or MSG line leaves rs274's DEBUG/PRINT buffer as it was (see _shown_text)."""
    line, text = it.message
    if line == it.line - 1:
        it.message = (it.line, text)


def _debug(it: Machine, rest: str) -> None:
    if it.params.numbered[DEBUG_ENABLE] != 0.0:
        it.emit(ops.Message(_shown_text(it, rest)))


def _print(it: Machine, rest: str) -> None:
    it.sink.print_text(_shown_text(it, rest))


def _shown_text(it: Machine, rest: str) -> str:
    """The text of a DEBUG or PRINT comment as rs274 shows it.

    rs274 builds both in one buffer and ends the text there, except after a ``#`` that is the
    comment's last character: that ``#`` is not shown, and the text runs on into what the buffer
    held.  Right after another DEBUG or PRINT line (comment and MSG lines between) that is the
    rest of its text: ``(debug, abcdef)`` then ``(print, x#)`` prints `` xbcdef``.  After other
    lines rs274 shows what was left in its memory, often nothing, sometimes stray bytes, which
    is not modelled: the text ends there."""
    text = substitute(it, rest)
    if rest.endswith("#"):
        text = text[:-1]
        line, before = it.message
        if line == it.line - 1 and len(before) > len(text):
            text += before[len(text):]
    it.message = (it.line, text)
    return text


def _abort(it: Machine, rest: str) -> None:
    raise NgcProgramError(substitute(it, rest))


def _log(it: Machine, rest: str) -> None:
    logfile.log(it, substitute(it, rest))


def _log_open(it: Machine, rest: str) -> None:
    logfile.log_open(it, rest, append=False)


def _log_append(it: Machine, rest: str) -> None:
    logfile.log_open(it, rest, append=True)


def _log_close(it: Machine, rest: str) -> None:
    logfile.log_close(it)


_ACTIVE: MappingProxyType[str, Callable[[Machine, str], None]] = MappingProxyType({
    "msg": _msg,
    "debug": _debug,
    "print": _print,
    "abort": _abort,
    "log": _log,
    "logopen": _log_open,
    "logappend": _log_append,
    "logclose": _log_close,
})


def substitute(it: Machine, text: str) -> str:
    """Replace parameters by their values; ``%d`` / ``%f`` / ``%.Nf`` set the format of the rest.

    A parameter that does not exist (an undefined name, a number out of range) reads ``######``.
    """
    fmt = "%f"
    out: list[str] = []
    pos = 0
    for m in _SUBSTITUTION.finditer(text):
        out.append(text[pos : m.start()])
        pos = m.end()
        token = m.group()
        if token[0] == "%":
            if token != "%":
                fmt = _FORMATS.get(token, token)
            continue
        value = _parameter(it, token)
        out.append("######" if value is None else _shown(fmt, value))
    out.append(text[pos:])
    return "".join(out)


def _shown(fmt: str, value: float) -> str:
    """A value as rs274 prints it: under 0.0001 in size as 0 (SIN[0.005] prints 0.000000), NaN
    with its sign as C's printf shows it (``-nan``), and ``######`` when it takes more than the
    29 characters rs274 has room for (``[10**22]`` with six decimals)."""
    text = c_float(value if not abs(value) < _SHOWN_MIN else 0.0, fmt)
    return text if len(text) <= _SHOWN_WIDTH else "######"


def _parameter(it: Machine, token: str) -> float | None:
    """The value a ``#...`` in a comment stands for; None ("######") if there is no such parameter."""
    params = it.params
    if token[1] == "<":
        name = "".join(token[2:-1].split()).lower()
        if not params.exists(name):
            return None
        return params.named(name)
    index = (min(int(token[1:]), _LONG_MAX) + _INT_WRAP // 2) % _INT_WRAP - _INT_WRAP // 2
    if not 0 <= index < len(params.numbered):
        return None
    return params.shown(index)


def stop(it: Machine, code: int) -> None:
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


def program_end(it: Machine, code: int) -> None:
    """M2 / M30: G54 origin, XY plane, G90, G94, feed 0, spindle and coolant off, G1."""
    ccomp.end(it)
    st = it.state
    machine = frames.to_machine(st, st.pos)
    coordinates.load_system(it, 1)
    it.params.numbered[5220] = 1.0
    st.pos = frames.to_program(st, machine)
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
    if not st.feed_override:  # rs274 turns the feed override back on, and says so
        st.feed_override = True
        it.emit(ops.EnableFeedOverride())
    st.spindle = 0
    it.emit(ops.StopSpindleTurning(0))
    st.css, st.css_max = False, 0.0
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
