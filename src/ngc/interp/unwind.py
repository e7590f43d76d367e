"""Going on after an error (rs274 ``-n 0``): what rs274 2.9.0~pre1 keeps and what it drops.

As the reference binary shows it (tests/golden/cases/continue-*):

* The calls under way are left without their ``endsub``: the caller's ``#1``-``#30`` come back,
  the subroutines' local parameters go, and an M73 of theirs restores nothing.
* The run reads on in the main program after the line that was running there: the ``call`` line
  when the error happened in a subroutine (or in the search for one), the line the error was in
  otherwise, or the line a skip (a false condition, a definition passed over) failed at.
* Every subroutine definition and every control label is forgotten: a subroutine must be found
  again (defined further down, or in its file), and an ``endwhile``, ``else`` or ``endif`` whose
  opening line ran before the error is an undefined label; a ``return`` in the main program is
  refused as before any call returned.
* The modes, the position and the parameters the failed line set before it failed stay set;
  the moves cutter compensation held back are dropped (the interpreter drops them).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .flow import ARGUMENT_PARAMETERS
from .snapshot import Context

if TYPE_CHECKING:
    from .flow import Flow


def unwind(flow: Flow) -> None:
    """Back to the main program after an error, with the control flow rs274 is left with."""
    frames = flow.frames
    main = frames[0]
    m = flow.interp.machine
    if len(frames) > 1:
        saved = frames[1].saved
        if saved:
            m.params.numbered[1 : ARGUMENT_PARAMETERS + 1] = saved
    elif flow.failed_at is not None and main.body is flow.tape:
        main.pc = max(main.pc, flow.failed_at + 1)
    flow.failed_at = None
    del frames[1:]
    del m.params.locals[1:]
    m.contexts = m.contexts[:1] or [Context()]
    m.state.call_level = 0
    flow.subs.clear()
    flow.active.clear()
    flow.resumed = None  # as if no call had returned: ``return`` in the main program is refused
    main.labels.clear()
