"""The work budget (``--max-iterations``) bounds the loops inside codes whose counts the program's
numbers set, as it bounds loops and calls: a canned cycle's repeats (L) and pecks (Q), G76's passes
(J K R, H), G70's passes (P), G71/G72's levels (I, every form).  Each iteration counts one, so a
program needing N of them runs with a budget of N and stops with N - 1."""

from __future__ import annotations

import io
import time

import pytest

from ngc.canon.jsonl import ListSink
from ngc.errors import NgcRuntimeError
from ngc.interp.interpreter import Interpreter

LIMIT = "Work limit reached"
# a profile for G70-G72: down the face, along Z, up a shoulder
PROFILE = "o100 sub\nG1 X0 Z0\nX5 Z-1\nZ-10\nX8\no100 endsub\n"
# one with a pocket (G7x.2 passes only in pockets)
POCKET = "o100 sub\nG1 X0 Z0\nX5 Z-1\nX3 Z-5\nX5 Z-8\nX8\no100 endsub\n"
SPINDLE = "G18 G21 S500 M3 F100\n"


def run(text: str, max_iterations: int) -> int:
    """The operations the program emits under the budget."""
    sink = ListSink()
    interp = Interpreter(sink, max_iterations=max_iterations)
    interp.startup()
    interp.run(io.StringIO(text), file="t.ngc")
    return len(sink.ops)


# a program whose count {n} sets how many iterations its code makes (one more for n + 1)
COUNTED = {
    "canned-repeats": "G17 G21 F100 G91\nG81 X1 R0 Z-1 L{n}\nG80\nM2\n",
    "g83-pecks": "G17 G21 F100\nG0 Z1\nG83 X1 R0 Z-{n} Q1\nG80\nM2\n",
    "g73-pecks": "G17 G21 F100\nG0 Z1\nG73 X1 R0 Z-{n} Q1\nG80\nM2\n",
    "g76-passes": SPINDLE + "G0 X10 Z2\nG76 P1.5 Z-5 I-0.5 J1 K{n}.5 H0\nM2\n",
    "g76-spring-passes": SPINDLE + "G0 X10 Z2\nG76 P1.5 Z-5 I-0.5 J1 K1.5 H{n}\nM2\n",
    # (D0: no pass moves the profile, whose steps count too: see below)
    "g70-passes": SPINDLE + PROFILE + "G0 X10 Z2\nG70 Q100 P{n} D0\nM2\n",
    "g71-levels": SPINDLE + PROFILE + "G0 X{n}0 Z2\nG71 Q100 I10\nM2\n",
}


def needs(program: str) -> int:
    """The least budget the program runs with."""
    for budget in range(1, 100):
        try:
            run(program, max_iterations=budget)
        except NgcRuntimeError as err:
            assert LIMIT in err.message
            continue
        return budget
    raise AssertionError("needs more than 99")


@pytest.mark.parametrize("name", sorted(COUNTED))
def test_each_iteration_counts_one(name: str) -> None:
    template = COUNTED[name]
    assert needs(template.format(n=6)) + 1 == needs(template.format(n=7))


@pytest.mark.parametrize("program", [
    "G17 G21 F100 G91\nG81 X1 R0 Z-1 L1000000000\nG80\nM2\n",
    "G17 G21 F100\nG0 Z1\nG83 X1 R0 Z-10 Q0.000000001\nG80\nM2\n",
    "G17 G21 F100\nG0 Z1\nG73 X1 R0 Z-10 Q0.000000001\nG80\nM2\n",
    SPINDLE + "G0 X10 Z2\nG76 P1.5 X12 I-0.5 J0.00001 K70 Q30\nM2\n",
    SPINDLE + "G0 X10 Z2\nG76 P1.5 Z-5 I-0.5 J1 K1.5 H1000000000\nM2\n",
    SPINDLE + PROFILE + "G0 X10 Z2\nG70 Q100 P1000000000 D1\nM2\n",
    *(SPINDLE + profile + f"G0 X10 Z2\n{code} Q100 D0.5 I0.000000001\nM2\n"
      for code, profile in (("G71", PROFILE), ("G71.1", POCKET), ("G71.2", POCKET))),
    SPINDLE + "o100 sub\nG1 X8 Z-10\nX5 Z-1\nX0 Z0\no100 endsub\n"
    + "G0 X10 Z2\nG72 Q100 D0.5 I0.000000001\nM2\n",
])
def test_runaway_counts_end_with_the_work_limit(program: str) -> None:
    started = time.process_time()  # (CPU time: a busy machine does not make it slow)
    with pytest.raises(NgcRuntimeError, match=LIMIT) as caught:
        run(program, max_iterations=1000)
    assert time.process_time() - started < 5.0
    assert caught.value.line is not None


def test_offset_steps_count() -> None:
    """Each step that moves a G7x profile by its D counts against the budget (how many there are
    depends on the profile's numbers: half its shortest move or smallest radius at a time)."""
    still = SPINDLE + PROFILE + "G0 X10 Z2\nG70 Q100 P1 D0 E0\nM2\n"
    moved = SPINDLE + PROFILE + "G0 X10 Z2\nG70 Q100 P1 D1 E1\nM2\n"
    assert needs(moved) > needs(still)
