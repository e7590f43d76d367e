"""Saved modal state: M70 save, M71 invalidate, M72 restore, M73 save and restore on return.

m-code.adoc, "M70 Save Modal State" ... "M73 Save and Autorestore Modal State".  Each call level
(the main program, each subroutine call) has one :class:`Context`: the state M70 or M73 saved
there, and whether a ``return`` / ``endsub`` / ``M99`` leaving the level restores it (M73).  A call
starts with nothing saved; the context goes away with the call.

How rs274 2.9.0~pre1 restores (seen from its output, and from its message when a restore fails,
which quotes the line it runs): it compares the saved state with the current one and writes
G-code lines for what differs, which it then runs as ordinary blocks in the order of execution:

1. ``G20`` / ``G21`` alone first, if the units differ (so the feed is read in the right units);
2. one line of the other differences: `` F%.1f`` and `` S%.0f`` (rounded: the restored feed and
   speed lose their digits), then the plane, cutter compensation (G41.1 / G42.1 are written
   G41 / G42, without a D word), distance mode, feed mode, coordinate system, tool length offset
   (``G43`` without an H word when one is in effect, G49), retract mode, G61 / G61.1, spindle
   mode, arc distance mode, lathe mode and last ``G64 P%f Q%f``; the first M code of the list
   below is glued to the end of this line;
3. each further M code as a line of its own: the spindle (M3 M4 M5), ``M7`` if mist was on and
   is off, ``M8`` likewise for flood, ``M9`` if both were off and one is on; ``M48`` if the feed
   override was on and is off, ``M51`` if it was off and is on (only the speed override turns on);
   ``M52`` if adaptive feed was on and is off, ``M53`` if feed hold was on and is off (their
   turning off is not restored).

When a restore runs any line, the rest of the M72 line (its steps after M72's) is not executed:
that line's block has been replaced by the restore's.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..errors import NgcError, NgcSemanticError
from .snapshot import Snapshot

if TYPE_CHECKING:
    from .machine import Machine

INVALID_FRAME = "Cannot restore context from invalid stack frame - missing M70/M73?"
_FAILED = "M7x: restore_settings failed executing: '{}': {}"

# G54 ... G59.3 by coordinate system index (1 ... 9)
_SYSTEMS = ("", "G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3")


class LineReplaced(Exception):
    """Raised by M72 after a restore ran lines: the rest of its block is not executed."""


def snapshot(m: Machine) -> Snapshot:
    """The machine's modal state now."""
    st = m.state
    return Snapshot(
        st.metric, st.plane, st.ccomp, st.absolute, st.feed_mode, st.coord_index, any(st.tlo),
        st.retract_r, st.control_mode, st.path_tolerance, st.naive_tolerance,
        # the spindle mode as the program reads it (#<_spindle_css_mode>)
        m.params.named("_spindle_css_mode") != 0.0,
        st.arc_absolute, st.lathe_diameter, st.feed, st.speed, st.spindle, st.mist, st.flood,
        st.feed_override, st.adaptive_feed, st.feed_hold,
    )


def _g(code: int) -> str:
    whole, tenth = divmod(code, 10)
    return f" G{whole}.{tenth}" if tenth else f" G{whole}"


def _g_words(s: Snapshot, now: Snapshot) -> str:
    """The G words (and F, S) of the restore line, in rs274's order."""
    out = []
    if s.feed != now.feed:
        out.append(f" F{s.feed:.1f}")
    if s.speed != now.speed:
        out.append(f" S{s.speed:.0f}")
    if s.plane != now.plane:
        out.append(_g(s.plane))
    if s.ccomp // 10 != now.ccomp // 10:
        out.append(_g(s.ccomp // 10 * 10))
    if s.absolute != now.absolute:
        out.append(" G90" if s.absolute else " G91")
    if s.feed_mode != now.feed_mode:
        out.append(_g(s.feed_mode))
    if s.coord_index != now.coord_index:
        out.append(" " + _SYSTEMS[s.coord_index])
    if s.tool_offset != now.tool_offset:
        out.append(" G43" if s.tool_offset else " G49")
    if s.retract_r != now.retract_r:
        out.append(" G99" if s.retract_r else " G98")
    if s.control_mode != now.control_mode and s.control_mode != 640:
        out.append(_g(s.control_mode))
    if s.css != now.css:
        out.append(" G96" if s.css else " G97")
    if s.arc_absolute != now.arc_absolute:
        out.append(" G90.1" if s.arc_absolute else " G91.1")
    if s.lathe_diameter != now.lathe_diameter:
        out.append(" G7" if s.lathe_diameter else " G8")
    if s.control_mode == 640 and (
        now.control_mode != 640 or s.path_tolerance != now.path_tolerance
        or s.naive_tolerance != now.naive_tolerance
    ):
        out.append(f" G64 P{s.path_tolerance:f} Q{s.naive_tolerance:f}")
    return "".join(out)


def _m_words(s: Snapshot, now: Snapshot) -> list[str]:
    """The M codes of the restore, in rs274's order."""
    out = []
    if s.spindle != now.spindle:
        out.append({1: "M3", -1: "M4"}.get(s.spindle, "M5"))
    if s.mist and not now.mist:
        out.append("M7")
    if s.flood and not now.flood:
        out.append("M8")
    if not (s.mist or s.flood) and (now.mist or now.flood):
        out.append("M9")
    if s.feed_override != now.feed_override:
        out.append("M48" if s.feed_override else "M51")
    if s.adaptive_feed and not now.adaptive_feed:
        out.append("M52")
    if s.feed_hold and not now.feed_hold:
        out.append("M53")
    return out


def restore(m: Machine, saved: Snapshot) -> bool:
    """Run the lines that restore ``saved``; True if there were any.  Each line is computed when
    the one before has run (a line can change what the next compares)."""
    ran = False
    if saved.metric != m.state.metric:
        _run(m, "G21" if saved.metric else "G20")
        ran = True
    now = snapshot(m)
    main = _g_words(saved, now)
    m_words = _m_words(saved, now)
    if m_words:
        main += m_words.pop(0)
    for text in ([main] if main else []) + m_words:
        _run(m, text)
        ran = True
    return ran


def _run(m: Machine, text: str) -> None:
    """Run one restore line; its error is told with the line, as rs274 does."""
    assert m.run_text is not None
    line = m.line
    try:
        m.run_text(text)
    except NgcError as err:
        raise type(err)(_FAILED.format(text, err.message), line=line, source=text) from None


def save(m: Machine, auto: bool) -> None:
    """M70 (``auto`` False) / M73: save the state at this call level."""
    context = m.contexts[-1]
    context.saved = snapshot(m)
    if auto:
        context.auto = True


def invalidate(m: Machine) -> None:
    """M71: nothing saved at this call level any more (an M73 there restores nothing)."""
    m.contexts[-1].saved = None


def restore_saved(m: Machine) -> None:
    """M72: restore the state saved at this call level; the rest of the line is dropped if
    anything was restored."""
    saved = m.contexts[-1].saved
    if saved is None:
        raise NgcSemanticError(INVALID_FRAME)
    if restore(m, saved):
        raise LineReplaced


def leave(m: Machine) -> None:
    """A return from a call level: M73's restore, then the level's context goes."""
    context = m.contexts.pop()
    if context.auto and context.saved is not None:
        restore(m, context.saved)


def m_code(m: Machine, code: int) -> None:
    """M70 / M71 / M72 / M73 (the table's ``modal_state`` handler)."""
    if code == 72:
        restore_saved(m)
    elif code == 71:
        invalidate(m)
    else:
        save(m, auto=code == 73)
