"""Dispatch: a checked block's codes and words, run in the order of execution, through the table.

Each row of the code table (:mod:`ngc.language.codes`) names a handler; :data:`HANDLERS` maps the
names to functions of one shape, ``handler(machine, words, code)``.  :class:`Dispatcher` binds a
table to the handlers once; :meth:`Dispatcher.convert` collects the steps a block needs (its codes,
the F/S words and comment, and the modal motion its axis words imply), sorts them by step and runs
them (overview.adoc, "G-code Order of Execution").
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from operator import itemgetter
from types import MappingProxyType

from ..errors import NgcSemanticError
from ..language import codes
from ..language.codes import CodeTable
from ..language.words import Words
from . import context
from .check import implied_motion
from .handlers import (
    ccomp,
    coordinates,
    cycles,
    g76,
    io,
    lathe,
    modes,
    motion,
    probe,
    program,
    spindle,
    splines,
    threading,
    tools,
)
from .machine import Machine

Handler = Callable[[Machine, Words, int], None]


def _comment(m: Machine, r: Words, code: int) -> None:
    program.comment(m, r.comment or "")


def _feed_rate(m: Machine, r: Words, code: int) -> None:
    modes.feed_rate(m, r.w["f"])


def _spindle_speed(m: Machine, r: Words, code: int) -> None:
    if "$" in r.w:
        spindle.speed(m, r.w)
    else:
        modes.spindle_speed(m, r.w["s"])


def _overrides(m: Machine, r: Words, code: int) -> None:
    if code == 51:
        spindle.check_override(r.w)
    modes.overrides(m, code, r.w.get("p"))


def _traverse(m: Machine, r: Words, code: int) -> None:
    machine = r.g.get(codes.G_NON_MODAL) == 530
    if machine and m.comp is not None:
        ccomp.machine_move(m)
    motion.traverse(m, motion.end_point(m, r.w, machine))
    m.state.motion = code  # once the move is made (see fastpath)


def _feed(m: Machine, r: Words, code: int) -> None:
    machine = r.g.get(codes.G_NON_MODAL) == 530
    if machine and m.comp is not None:
        ccomp.machine_move(m)
    motion.feed(m, r.w, motion.end_point(m, r.w, machine))
    m.state.motion = code


def _arc(m: Machine, r: Words, code: int) -> None:
    motion.arc(m, r.w, motion.end_point(m, r.w, False), code)
    m.state.motion = code


def _units(m: Machine, r: Words, code: int) -> None:
    metric = m.state.metric
    modes.units(m, code)
    if m.comp is not None and m.state.metric != metric:
        ccomp.units_changed(m)


def _cancel_motion(m: Machine, r: Words, code: int) -> None:
    m.state.motion = code
    m.emit(modes.MOTION_NONE)


def _home(m: Machine, r: Words, code: int) -> None:
    middle, home = coordinates.home_targets(m, code, r)
    motion.traverse(m, middle)
    motion.traverse(m, home)


def _user_m(m: Machine, r: Words, code: int) -> None:
    raise NgcSemanticError(f"Unknown m code used: M{code}")  # no user M file (USER_M_PATH)


def _subprogram(m: Machine, r: Words, code: int) -> None:
    raise AssertionError("M98/M99 are run by the control flow")


_HANDLERS: dict[str, Handler] = {
    "comment": _comment,
    "feed_rate": _feed_rate,
    "spindle_speed": _spindle_speed,
    "feed_mode": lambda m, r, code: modes.feed_mode(m, code),
    "spindle": lambda m, r, code: spindle.turn(m, r.w, code),
    "speed_mode": lambda m, r, code: spindle.speed_mode(m, r.w, code),
    "orient": lambda m, r, code: spindle.orient(m, r.w),
    "coolant": lambda m, r, code: modes.coolant(m, code),
    "overrides": _overrides,
    "subprogram": _subprogram,
    "user_m": _user_m,
    "dwell": lambda m, r, code: modes.dwell(m, r),
    "plane": lambda m, r, code: modes.plane(m, code),
    "units": _units,
    "cutter_comp_off": lambda m, r, code: modes.cutter_comp_off(m),
    "tool_length_off": lambda m, r, code: tools.tool_length_off(m),
    "tool_length": tools.tool_length,
    "select_tool": lambda m, r, code: tools.select_tool(m, r.w["t"]),
    "change_tool": lambda m, r, code: tools.change_tool(m),
    "set_tool_number": lambda m, r, code: tools.set_tool_number(m, r),
    "lathe_mode": lambda m, r, code: tools.lathe_mode(m, code),
    "cutter_comp": ccomp.from_table,
    "cutter_comp_dynamic": ccomp.dynamic,
    "select_system": lambda m, r, code: coordinates.select_system(m, code),
    "control_mode": lambda m, r, code: modes.control_mode(m, code, r),
    "distance_mode": lambda m, r, code: modes.distance_mode(m, code),
    "arc_distance_mode": lambda m, r, code: modes.arc_distance_mode(m, code),
    "retract_mode": lambda m, r, code: modes.retract_mode(m, code),
    "g10": lambda m, r, code: coordinates.g10(m, r),
    "g92": lambda m, r, code: coordinates.g92(m, r),
    "g52": lambda m, r, code: coordinates.g52(m, r),
    "g92_reset": lambda m, r, code: coordinates.g92_reset(m, code),
    "home_store": lambda m, r, code: coordinates.home_store(m, code),
    "home": _home,
    "traverse": _traverse,
    "feed": _feed,
    "arc": _arc,
    "cancel_motion": _cancel_motion,
    "sync_feed": lambda m, r, code: threading.sync_feed(m, r.w, motion.end_point(m, r.w, False)),
    "rigid_tap": lambda m, r, code: threading.rigid_tap(m, r.w, motion.end_point(m, r.w, False)),
    "cubic_spline": splines.cubic,
    "quadratic_spline": splines.quadratic,
    "nurbs": splines.nurbs,
    "nurbs_end": splines.nurbs_end,
    "probe": probe.straight_probe,
    "threading_cycle": lambda m, r, code: g76.run(m, r.w, motion.end_point(m, r.w, False)),
    "lathe_cycle": lathe.cycle,
    **{name: cycles.handler(name) for name in cycles.CYCLES},
    "stop": lambda m, r, code: program.stop(m, code),
    "modal_state": lambda m, r, code: context.m_code(m, code),
    "output_bit": io.output_bit,
    "output_value": io.output_value,
    "wait_input": io.wait_input,
}


def _refusing(check: Handler, run: Handler) -> Handler:
    """A handler that first refuses its code while cutter radius compensation is on."""
    def handler(m: Machine, r: Words, code: int) -> None:
        if m.comp is not None:
            check(m, r, code)
        run(m, r, code)

    return handler


def _comp_refusal(message: str, code_name: str) -> Handler:
    """A code not supported yet that rs274 refuses while compensation is on."""
    def handler(m: Machine, r: Words, code: int) -> None:
        ccomp.refuse(m, message)
        raise NgcSemanticError(f"{code_name} is not supported yet")

    return handler


def _ignored(run: Handler) -> Handler:
    """A handler that does nothing while cutter radius compensation is on."""
    def handler(m: Machine, r: Words, code: int) -> None:
        if not ccomp.is_on(m):
            run(m, r, code)

    return handler


def _wrapped(name: str, fn: Handler) -> Handler:
    if name in ccomp.REFUSED:
        return _refusing(ccomp.REFUSED[name], fn)
    if name in ccomp.IGNORED:
        return _ignored(fn)
    return fn


HANDLERS: Mapping[str, Handler] = MappingProxyType({
    name: _wrapped(name, fn) for name, fn in _HANDLERS.items()
})

_by_step = itemgetter(0)


class Dispatcher:
    """A code table bound to its handlers: ``g``/``m`` code -> (step, handler or None)."""

    __slots__ = ("g", "m", "table", "words")

    def __init__(self, table: CodeTable, handlers: Mapping[str, Handler] = HANDLERS) -> None:
        self.table = table
        self.g = {code: (row.step, _bind(row, codes.g_name(code), handlers))
                  for code, row in table.g.items()}
        self.m = {code: (row.step, _bind(row, f"M{code}", handlers))
                  for code, row in table.m.items()}
        # The words that run (F, S, T).
        self.words = {letter: (step, handlers[name])
                      for letter, (step, name) in codes.WORD_STEPS.items() if name is not None}

    def convert(self, m: Machine, r: Words) -> None:
        """Run a checked block's steps in the order of execution."""
        mode = r.g.get(codes.G_LATHE)
        if "x" in r.w and (m.state.lathe_diameter if mode is None else mode == 70):
            r = _diameter_x(r)
        if m.profile is not None:
            lathe.record(m, r)  # a line of a lathe cycle's profile: only its move counts
            return
        self.run(m, r, self.plan(m, r))

    @staticmethod
    def run(m: Machine, r: Words, plan: list[tuple[int, Handler, int]]) -> None:
        """Run the steps of :meth:`plan` (then the position an M6 or M61 line leaves)."""
        try:
            for _, fn, code in plan:
                fn(m, r, code)
        except context.LineReplaced:
            return  # M72 restored the modal state: its block was replaced (interp/context.py)
        if m.state.tool_changed:
            tools.canon_position(m.state)
            if m.comp is not None:
                ccomp.tool_changed(m)

    def plan(self, m: Machine, r: Words) -> list[tuple[int, Handler, int]]:
        """The steps a checked block runs, in the order of execution: (step, handler, code).
        It depends on the machine's state only through the modal motion axis words run."""
        calls: list[tuple[int, Handler, int]] = []
        if r.comment is not None:
            calls.append((codes.STEP_COMMENT, _comment, 0))
        g = r.g
        for code in g.values():
            step, fn = self.g[code]
            if fn is not None:
                calls.append((step, fn, code))
        for code in r.m.values():
            step, fn = self.m[code]
            if fn is not None:
                calls.append((step, fn, code))
        words = self.words
        for letter in r.w:
            if letter in words:
                step, word_fn = words[letter]
                calls.append((step, word_fn, 0))
        modal = implied_motion(m.state, r, self.table)
        if modal is not None and modal != codes.G_CANCEL_MOTION:
            step, fn = self.g[modal]
            if fn is not None:
                calls.append((step, fn, modal))
        calls.sort(key=_by_step)
        return calls


def _diameter_x(r: Words) -> Words:
    """G7: the block with its X word halved (a diameter), for every code that reads X."""
    half = Words()
    half.g, half.m, half.assigns, half.comment = r.g, r.m, r.assigns, r.comment
    half.w = {**r.w, "x": r.w["x"] / 2.0}
    return half.finish()


def _bind(row: codes.Code, code_name: str, handlers: Mapping[str, Handler]) -> Handler | None:
    """The handler a row names; None for a code that is not run by itself (G53 modifies motion)
    or not supported (the check refuses it before dispatch, unless compensation's refusal of it
    comes first: then the handler raises that)."""
    name = row.handler
    if name is None and row.comp_refusal:
        return _comp_refusal(row.comp_refusal, code_name)
    if not name:
        return None
    try:
        fn = handlers[name]
    except KeyError:
        raise NgcSemanticError(f"No handler named {name!r} for a code of the table") from None
    if row.comp_refusal and not row.cycle and name not in _REFUSE_THEMSELVES:
        return _refusing(_refusal(row.comp_refusal), fn)
    return fn


# Handlers that refuse their code while compensation is on by themselves, after checking their
# words (as a cycle's handler does).
_REFUSE_THEMSELVES = frozenset({"wait_input"})


def _refusal(message: str) -> Handler:
    def check(m: Machine, r: Words, code: int) -> None:
        ccomp.refuse(m, message)

    return check
