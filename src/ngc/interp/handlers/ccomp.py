"""Cutter radius compensation: G40, G41 / G42 (a tool of the table), G41.1 / G42.1 (a diameter
given), and the codes rs274 refuses while it is on (g-code.adoc G40-G42.1; the geometry is
``interp/comp.py``)."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from types import MappingProxyType
from typing import TYPE_CHECKING

from ...canon import ops
from ...config.tooltable import length_to_program
from ...errors import NgcSemanticError
from .. import comp
from ..comp import Compensation
from ..state import MM_PER_INCH
from .tools import not_found, whole

if TYPE_CHECKING:
    from ..machine import Machine
    from ..resolve import Resolved

_ON = {1: ops.Comment("interpreter: cutter radius compensation on left"),
       -1: ops.Comment("interpreter: cutter radius compensation on right")}
_OFF = ops.Comment("interpreter: cutter radius compensation off")


def is_on(it: Machine) -> bool:
    c = it.comp
    return c is not None and c.side != 0


def dynamic(it: Machine, r: Resolved, code: int) -> None:
    """G41.1 / G42.1 D diameter [L orientation]."""
    w = r.w
    name = "G41.1" if code == 411 else "G42.1"
    if w.get("l", 0.0) < 0.0:
        raise NgcSemanticError("Negative l word used")
    if "d" not in w:
        raise NgcSemanticError(f"{name} with no D word")
    plane = it.state.plane
    if plane not in (170, 180):
        raise NgcSemanticError("Cutter radius compensation allowed only in XY, XZ planes")
    if "l" in w and plane != 180:
        raise NgcSemanticError(f"{name} with L word, but plane is not G18")
    if is_on(it):
        raise NgcSemanticError("Cannot turn cutter radius comp on when on")
    start(it, 1 if code == 411 else -1, w["d"], int(w.get("l", 0.0)))


def from_table(it: Machine, r: Resolved, code: int) -> None:
    """G41 / G42 [D tool number]: the diameter and orientation of a tool of the table (D0 or no D:
    the tool in the spindle)."""
    name = "G41" if code == 410 else "G42"
    st = it.state
    if st.plane not in (170, 180):
        raise NgcSemanticError("Cutter radius compensation allowed only in XY, XZ planes")
    if is_on(it):
        raise NgcSemanticError("Cannot turn cutter radius comp on when on")
    d = r.w.get("d", 0.0)
    number = whole(d)
    if number < 0 or abs(d - number) >= WHOLE_TOLERANCE:
        raise NgcSemanticError(f"{name} requires D word to be a whole number")
    entry = it.current_tool() if number == 0 else it.tools.find(number)
    if entry is None:
        raise not_found(number, "d")
    if entry.orientation not in (0, 9) and st.plane != 180:
        raise NgcSemanticError(f"{name} with lathe tool, but plane is not G18")
    start(it, 1 if code == 410 else -1, length_to_program(entry.diameter, st.metric),
          entry.orientation)


# How far from a whole number a G41 / G42 D word may be.
WHOLE_TOLERANCE = 0.0001


def start(it: Machine, side: int, diameter: float, orientation: int) -> None:
    """Turn compensation on to the left (``side`` 1) or right (-1) of the programmed path, with a
    tool of ``diameter`` (program units; a negative one takes the other side).  The caller
    has refused it while compensation is on."""
    if diameter < 0.0:
        side = -side
    st = it.state
    it.comp = Compensation(side, abs(diameter) / 2.0, st.plane, st.pos, orientation,
                           st.metric)
    st.ccomp = 410 if side > 0 else 420
    it.emit(_ON[side])


def stop(it: Machine) -> None:
    """G40: the held moves go out; the next move (straight) leaves the compensated path (with a
    tool of no radius, compensation just ends)."""
    st = it.state
    c = it.comp
    if c is not None and c.side != 0:
        comp.check_held(c)
        comp.flush(it)
        pos = st.pos.copy()  # the canon's point: the compensated one, shifted by an orientation
        pos[c.a] = c.ca + c.shift_a
        pos[c.b] = c.cb + c.shift_b
        st.pos = c.prog.copy()  # the current point is the programmed one again
        # a tool of no radius leaves no exit move: the next move may be an arc
        it.comp = None if c.radius == 0.0 else Compensation.exit(st.plane, st, pos)
    st.ccomp = 400
    it.emit(_OFF)


def end(it: Machine) -> None:
    """M2 / M30: what is held goes out; compensation ends without a word."""
    if is_on(it):
        comp.check_held(it.comp)  # type: ignore[arg-type]
    comp.flush(it)
    if it.comp is not None:
        it.comp = None
        it.state.ccomp = 400


def refuse(it: Machine, message: str) -> None:
    """The codes rs274 does not run while compensation is on."""
    if is_on(it):
        raise NgcSemanticError(message)


# -- the codes refused while compensation is on (handler name -> check, run as the code's step) --
def _plane(it: Machine, r: Resolved, code: int) -> None:
    # rs274 lets G17.1, G18.1 and G19.1 pass (it selects CANON_PLANE_UNKNOWN)
    if code != it.state.plane and code % 10 == 0:
        refuse(it, "Cannot change planes with cutter radius compensation on")


def _overrides(it: Machine, r: Resolved, code: int) -> None:
    on = code == 48 or (code != 49 and r.w.get("p", 1.0) != 0.0)
    refuse(it, f"Cannot {'enable' if on else 'disable'} overrides with cutter radius compensation on")


def _g10(it: Machine, r: Resolved, code: int) -> None:
    p = int(r.w.get("p", 0.0))
    if r.w.get("l") in (2.0, 20.0) and p in (0, it.state.coord_index):
        refuse(it, "Cannot change the active coordinate system with cutter radius compensation on")


def _always(message: str) -> Callable[[Machine, Resolved, int], None]:
    def check(it: Machine, r: Resolved, code: int) -> None:
        refuse(it, message)

    return check


REFUSED: Mapping[str, Callable[[Machine, Resolved, int], None]] = MappingProxyType({
    "plane": _plane,
    "overrides": _overrides,
    "g10": _g10,
    "control_mode": _always("Cannot change control mode with cutter radius compensation on"),
    "select_system": _always("Cannot change coordinate systems with cutter radius compensation on"),
    "g92": _always("Cannot change axis offsets with cutter radius comp"),
    "g52": _always("Cannot change axis offsets with cutter radius comp"),
    "home": _always("Cannot use g28 or g30 with cutter radius comp"),
    "home_store": _always("Cannot set reference point with cutter compensation in effect"),
    "tool_length": _always("Cannot change tool offset with cutter radius compensation on"),
    "tool_length_off": _always("Cannot change tool offset with cutter radius compensation on"),
    "change_tool": _always("Cannot change tools with cutter radius compensation on"),
    "retract_mode": _always("Cannot change retract mode with cutter radius compensation on"),
})


# The codes rs274 passes over without a word while compensation is on (handler names): G92.1,
# G92.2 and G92.3 leave the offsets and their parameters as they are.
IGNORED = frozenset({"g92_reset"})


def units_changed(it: Machine) -> None:
    """G20 / G21 changed the units: the held moves and the compensation's points follow."""
    comp.convert(it, MM_PER_INCH if it.state.metric else 1.0 / MM_PER_INCH)


def tool_changed(it: Machine) -> None:
    """A line with M6 or M61 ran: the current point is the canon's."""
    comp.take_canon_point(it)


def machine_move(it: Machine) -> None:
    """G53."""
    refuse(it, "Cannot use g53 with cutter radius comp")
