"""One Interpreter, several programs: each runs as it would alone, on the machine the last one left
(its modes and parameters), with none of the last one's control flow."""

from __future__ import annotations

import pytest

from ngc.canon.jsonl import ListSink
from ngc.errors import NgcError
from ngc.interp.interpreter import Interpreter

SUB = "o100 sub\nG1 X[#1] F100\no100 endsub\n"


def names(sink: ListSink) -> list[str]:
    return [type(op).__name__ for op, _, _ in sink.ops]


def alone(program: str) -> list[object]:
    sink = ListSink()
    Interpreter(sink).run(program.splitlines())
    return sink.ops


def test_a_second_program_with_owords_runs_as_it_would_alone() -> None:
    first = SUB + "o100 call [1]\nM2\n"
    second = "o200 sub\nG1 X[#1] F100\no200 endsub\no200 call [5]\no200 call [6]\nM2\n"
    sink = ListSink()
    interp = Interpreter(sink)
    interp.run(first.splitlines())
    done = len(sink.ops)
    interp.run(second.splitlines())
    assert sink.ops[done:] == alone(second)
    assert interp.state.pos[0] == 6.0


def test_the_same_labels_may_be_used_again() -> None:
    program = SUB + "o100 call [2]\no1 repeat [2]\no100 call [3]\no1 endrepeat\nM2\n"
    sink = ListSink()
    interp = Interpreter(sink)
    interp.run(program.splitlines())
    done = len(sink.ops)
    interp.run(program.splitlines())
    assert sink.ops[done:] == alone(program)


def test_modes_and_parameters_carry_over() -> None:
    interp = Interpreter(ListSink())
    interp.run(["G20 G91", "#<_kept>=7", "#31=2", "M0", "M2"])
    interp.run(["G0 X#31", "o1 if [#<_kept> EQ 7]", "G0 X1", "o1 endif", "M2"])
    assert interp.params.named("_kept") == 7.0


def test_a_program_after_an_error_in_a_subroutine_runs() -> None:
    interp = Interpreter(ListSink())
    with pytest.raises(NgcError, match="divide by zero"):
        interp.run((SUB.replace("X[#1]", "X[#1/0]") + "o100 call [1]\nM2\n").splitlines())
    interp.run(["o1 if [#<_call_level> EQ 0]", "G0 X3", "o1 endif", "M2"])
    assert interp.state.pos[0] == 3.0


def test_the_work_budget_is_per_run() -> None:
    loop = ["#1=0", "o1 while [#1 LT 40]", "#1=[#1+1]", "o1 endwhile", "M2"]
    interp = Interpreter(ListSink(), max_iterations=50)
    interp.run(loop)
    interp.run(loop)  # 40 + 40 iterations: over 50 in all, within it in each run


def test_a_kept_line_runs_as_the_general_path_runs_it() -> None:
    """The fast path keeps ``G41.1 D4`` and ``G40`` with their plans and runs them again."""
    program = ("G0 X0 Y-10\nG41.1 D4\nG1 X0 Y0 F100\nX10\nG40\nG1 X10 Y-10\nG41.1 D4\nG1 X0\n"
               "Y10\nG40\nG0 X-10\nM2\n")
    sink = ListSink()
    Interpreter(sink).run(program.splitlines())
    general = ListSink()
    Interpreter(general, fast=False).run(program.splitlines())
    assert sink.ops == general.ops
