"""Tools: T, M6, M61, G43/G43.1/G43.2/G49, G10 L0/L1/L10/L11, G7/G8 (g-code.adoc, m-code.adoc,
other-code.adoc), as rs274 2.9.0~pre1 does them.

The machine's tool data is ``state.tools``: slot 0 is the spindle's entry (what #5400-#5413
read), slots 1..n the table's entries in file order.  ``CHANGE_TOOL`` and ``CHANGE_TOOL_NUMBER``
print a slot, not a tool number.  Tool data are in inches; the tool length offset in effect
(``state.tlo``) is in program units, as ``USE_TOOL_LENGTH_OFFSET`` prints it.

A change of the tool length offset keeps the machine still: the current point, in program
coordinates, moves by the change.  The canon does not follow that (nor a rotation change), and
M6 and M61 take the canon's current point back (``state.canon_pos``, :func:`hold_canon`), as
rs274 does.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ...canon import ops
from ...config.tooltable import ToolEntry, length_from_program, length_to_program
from ...errors import NgcSemanticError
from ...language.codes import AXIS_LETTERS
from ..frames import from_parameters, rotate, to_machine
from ..parameters import COORD_STRIDE, G54_ORIGIN
from ..state import AXES, LINEAR, MM_PER_INCH

if TYPE_CHECKING:
    from ...language.words import Words
    from ..machine import Machine
    from ..state import State

# Which of the nine offsets X Y Z A B C U V W are lengths (converted between units).
_LINEAR9 = (True, True, True, False, False, False, True, True, True)
_G59_3 = 9  # the coordinate system G10 L11 measures from


def not_found(number: int, letter: str = "t") -> NgcSemanticError:
    """LinuxCNC's error for a tool the table lacks, and what to do about it; ``letter`` is the
    word that named it (T, or D for G41/G42, P for G10 L1)."""
    err = NgcSemanticError(f"Requested tool {number} not found in the tool table")
    err.about = MISSING_TOOL_ADVICE
    err.word = (letter, float(number))
    return err


MISSING_TOOL_ADVICE = ("give the machine's tool table with -t FILE (without it, rs274's sample "
                       "table: tools 1, 2, 3 and 99999), or --any-tool to take a tool it lacks "
                       "as one with no offsets")


def _to_program_units(st: State, offsets: tuple[float, ...]) -> list[float]:
    metric = st.metric
    return [length_to_program(v, metric) if _LINEAR9[i] else v for i, v in enumerate(offsets)]


def _lookup(it: Machine, number: int, letter: str = "h") -> ToolEntry:
    """The entry of tool ``number`` (named by the word ``letter``); 0 is the tool in the
    spindle."""
    tools = it.state.tools
    if number == 0:
        return _current(it.state)
    entry = tools.find(number) if number > 0 else None
    if entry is None:
        raise not_found(number, letter)
    return entry


def _current(st: State) -> ToolEntry:
    """The tool G43 applies: the spindle's entry, which M6 loads.  M61 loads none: only G43 on
    its own line applies the slot M61 named (at the end of the line rs274 takes the tool data
    back from the canon, whose spindle M61 did not change)."""
    return st.tools.slots[st.tool_index] if st.tool_changed else st.tools.spindle


# -- T, M6, M61 ---------------------------------------------------------------------------------
def select_tool(it: Machine, t: float) -> None:
    """T: select the tool the next M6 loads (T0: none).  A negative T was refused by the check."""
    st = it.state
    number = int(t)
    if number == 0:
        index = 0
    else:
        found = st.tools.index(number)
        if found is None:
            raise not_found(number)
        index = found
    it.emit(ops.SelectTool(number))
    st.selected_index = index
    st.selected_tool = number


def change_tool(it: Machine) -> None:
    """M6: load the selected slot (the spindle keeps its entry when none is selected)."""
    st = it.state
    index = st.selected_index
    it.emit(ops.StartChange())
    st.spindle = 0  # the spindle stops for the change
    it.emit(ops.StopSpindleTurning(0))
    it.emit(ops.ChangeTool(index))
    st.tools.load(index)
    st.tool_index = index
    st.tool_changed = True


def set_tool_number(it: Machine, r: Words) -> None:
    """M61 Q: the spindle holds tool Q, without a change (its entry is not loaded)."""
    st = it.state
    q = r.w.get("q")
    number = None if q is None else whole(q)
    if number is None or number < 0:
        raise NgcSemanticError("Need non-negative Q-word to specify tool number with M61")
    index = 0 if number == 0 else st.tools.index(number)
    if index is None:
        raise not_found(number, "q")
    it.emit(ops.ChangeToolNumber(index))
    st.tool_index = index
    st.tool_changed = True


def whole(value: float) -> int:
    """The nearest whole number, halves away from zero, as rs274 rounds a tool number."""
    return int(value + 0.5) if value >= 0 else -int(-value + 0.5)


def canon_position(st: State) -> None:
    """At the end of a line with M6 or M61 rs274 takes the canon's current point as its own,
    and the spindle's entry as the canon has it."""
    st.tool_changed = False
    st.tools.reload()
    if st.canon_pos is not None and st.canon_anchor is st.pos:
        metric = st.metric
        st.pos = [_from_mm(v, i, metric) - st.g5x[i] - st.g92[i] for i, v in enumerate(st.canon_pos)]
    st.canon_pos = st.canon_anchor = None


def hold_canon(st: State) -> None:
    """Before the current point changes without a move (a tool length offset or rotation
    change): remember where the canon's point is, unless that is already known.

    The canon keeps the last move's end point, in program coordinates: it follows a change of
    the G5x origin or of the G92/G52 offset (by the change along each axis, unrotated) and of
    the units, not a rotation or tool length offset change.  It is kept here as the sum of the
    point and those offsets, in millimetres, which none of those changes alter; the ``pos``
    list it belongs to is ``canon_anchor`` (a move replaces ``pos``)."""
    if st.canon_pos is None or st.canon_anchor is not st.pos:
        metric = st.metric
        st.canon_pos = [_to_mm(st.pos[i] + st.g5x[i] + st.g92[i], i, metric) for i in range(AXES)]


def held(st: State) -> None:
    """After such a change: the canon's point belongs to the new current point."""
    st.canon_anchor = st.pos


def _to_mm(value: float, axis: int, metric: bool) -> float:
    return value if metric or not LINEAR[axis] else value * MM_PER_INCH


def _from_mm(value: float, axis: int, metric: bool) -> float:
    return value if metric or not LINEAR[axis] else value / MM_PER_INCH


# -- tool length offsets ------------------------------------------------------------------------
def tool_length(it: Machine, r: Words, code: int) -> None:
    """G43 [H], G43.1 axes, G43.2 H."""
    st = it.state
    w = r.w
    if code == 430:
        h = w.get("h")
        entry = _current(st) if h is None else _lookup(it, int(h))
        new = _to_program_units(st, entry.offsets)
    elif code == 431:
        new = list(st.tlo)
        for i, letter in enumerate(AXIS_LETTERS):
            if letter in w:
                new[i] = w[letter]
    else:
        has_axes = any(letter in w for letter in AXIS_LETTERS)
        h = w.get("h")
        if h is None and not has_axes:
            raise NgcSemanticError("G43.2: No axes specified and H word missing")
        if h is not None and has_axes:
            raise NgcSemanticError("G43.2: Can not have both H and axis words")
        # rs274 2.9.0~pre1 looks the axes form up as tool -1.
        entry = _lookup(it, -1 if h is None else int(h))
        added = _to_program_units(st, entry.offsets)
        new = [st.tlo[i] + added[i] for i in range(9)]
    _apply(it, new)


def tool_length_off(it: Machine) -> None:
    """G49: no tool length offset."""
    _apply(it, [0.0] * 9)


def _apply(it: Machine, new: list[float]) -> None:
    """Put a tool length offset in effect: the current point moves by the change."""
    st = it.state
    hold_canon(st)
    old = st.tlo
    st.tlo = new
    delta = [old[i] - new[i] for i in range(AXES)]  # machine axes
    if st.rotation:
        delta[0], delta[1] = rotate(delta[0], delta[1], -st.rotation)
    st.pos = [st.pos[i] + delta[i] for i in range(AXES)]
    held(st)
    it.emit(ops.UseToolLengthOffset(*new))


# -- G10 L0 / L1 / L10 / L11 ----------------------------------------------------------------------
def g10_tools(it: Machine, r: Words, l_word: int) -> None:
    """G10 L0 reloads the tool data (a no-op here); L1 sets a tool's entry from the words; L10 and
    L11 set its offsets so the current point has the given coordinates (L10 with the current
    offsets, L11 in G59.3 without G52/G92)."""
    st = it.state
    w = r.w
    tools = st.tools
    if l_word == 0:
        if tools.spindle.number != 0:
            raise NgcSemanticError(f"G10 L0 not allowed with loaded tool <{tools.spindle.number}>\n")
        it.emit(ops.ReloadTooldata())
        return
    number = whole(w["p"])
    index = tools.index(number)
    if index is None:
        raise not_found(number, "p")
    axes = [(i, w[letter]) for i, letter in enumerate(AXIS_LETTERS) if letter in w]
    if not axes and not any(letter in w for letter in "rijq"):
        raise NgcSemanticError("G10 L1 without offsets has no effect")
    entry = tools.slots[index]
    orientation = entry.orientation
    q = w.get("q")
    if q is not None and q != -1.0:
        if q < 0 or abs(q - whole(q)) > 0.0001:
            raise NgcSemanticError("Q number in G10 is not an integer")
        if whole(q) > 9:
            raise NgcSemanticError("Invalid tool orientation")
        orientation = whole(q)
    offsets = list(entry.offsets)
    metric = st.metric
    if l_word == 1:
        values = {i: v for i, v in axes}
    else:
        values = _measured(it, dict(axes), l_word, entry)
    for i, v in values.items():
        offsets[i] = length_from_program(v, metric) if LINEAR[i] else v
    diameter = length_from_program(2.0 * w["r"], metric) if "r" in w else entry.diameter
    entry = entry._replace(offsets=tuple(offsets), diameter=diameter,
                           frontangle=w.get("i", entry.frontangle),
                           backangle=w.get("j", entry.backangle), orientation=orientation)
    tools.slots[index] = entry
    _emit_entry(it, index, entry)
    if index == st.tool_index:
        tools.slots[0] = entry  # with its pocket (the canon's copy keeps its own)
        _emit_entry(it, 0, entry)


def _emit_entry(it: Machine, index: int, e: ToolEntry) -> None:
    x, y, z, a, b, c, u, v, w = e.offsets
    it.emit(ops.SetToolTableEntry(index, e.number, x, y, z, a, b, c, u, v, w, e.frontangle,
                                  e.backangle, e.orientation))


def _measured(
    it: Machine, given: dict[int, float], l_word: int, entry: ToolEntry
) -> dict[int, float]:
    """L10 / L11: the offsets (program units) that make the current point read ``given``: L10 in
    the current coordinate system, L11 in G59.3 (its origin and rotation, without G52/G92).

    An axis not given keeps the coordinate the current point would have with the tool's entry
    as the offset (with a rotation, a given X or Y sets both)."""
    st = it.state
    tool = _to_program_units(st, entry.offsets)
    changed = set(given)
    if l_word == 10:
        # The point with the entry's offset in effect (as G43 would move it), and the offset
        # that moves it to the given coordinates: rs274's arithmetic, to the last bit.
        delta = [st.tlo[i] - tool[i] for i in range(AXES)]
        if st.rotation:
            delta[0], delta[1] = rotate(delta[0], delta[1], -st.rotation)
        point = [st.pos[i] + delta[i] for i in range(AXES)]
        diff = [point[i] - given.get(i, point[i]) for i in range(AXES)]
        if st.rotation:
            diff[0], diff[1] = rotate(diff[0], diff[1], st.rotation)
            if changed & {0, 1}:
                changed |= {0, 1}  # a rotated X or Y moves the offset along both
        return {i: tool[i] + diff[i] for i in changed}
    machine = to_machine(st, st.pos, rotary=True)
    base = G54_ORIGIN + COORD_STRIDE * (_G59_3 - 1)
    numbered = it.params.numbered
    origin = from_parameters(st, numbered[base:base + AXES])
    rotation = numbered[base + 9]
    # The point in G59.3, with the entry's offset.
    point = [machine[i] - origin[i] - (tool[i] if i < 3 else 0.0) for i in range(AXES)]
    point[0], point[1] = rotate(point[0], point[1], -rotation)
    for i, v in given.items():
        point[i] = v
    # Back to the machine, without a tool length offset.
    if rotation:
        point[0], point[1] = rotate(point[0], point[1], rotation)
    if rotation and changed & {0, 1}:
        changed |= {0, 1}  # a rotated X or Y moves the offset along both
    return {i: machine[i] - (point[i] + origin[i]) for i in changed}


# -- G7 / G8 ------------------------------------------------------------------------------------
def lathe_mode(it: Machine, code: int) -> None:
    """G7 diameter mode (X words are halved), G8 radius mode; rs274 comments on a change."""
    st = it.state
    diameter = code == 70
    if diameter != st.lathe_diameter:
        word = "diameter" if diameter else "radius"
        it.emit(ops.Comment(f"interpreter: Lathe diameter mode changed to {word}"))
    st.lathe_diameter = diameter
