"""Control-flow safety: runaway loops, call depth, deep nesting, parse-once re-execution."""

from __future__ import annotations

import io
import time
from pathlib import Path

import pytest

from ngc.canon.jsonl import ListSink
from ngc.commands import rs274
from ngc.errors import NgcRuntimeError, NgcSemanticError
from ngc.interp.flow import Body
from ngc.interp.interpreter import Interpreter


def run(text: str, **options: int) -> Interpreter:
    interp = Interpreter(ListSink(), **options)
    interp.startup()
    interp.run(io.StringIO(text), file="t.ngc")
    return interp


def test_runaway_while_ends_with_an_error_at_its_line() -> None:
    with pytest.raises(NgcRuntimeError) as caught:
        run("G0 X1\no100 while [1]\n  G0 X2\no100 endwhile\nM2\n", max_iterations=500)
    err = caught.value
    assert "Work limit reached: 500 loop iterations and subroutine calls" in err.message
    assert (err.file, err.line, err.source) == ("t.ngc", 4, "o100 endwhile")


@pytest.mark.parametrize(
    "program",
    [
        "o1 do\no1 while [1]\nM2\n",
        "o1 repeat [1e9]\no1 endrepeat\nM2\n".replace("1e9", "1000000000"),
        "o1 while [1]\no1 continue\no1 endwhile\nM2\n",
        "M98 P1 L1000000000\nM30\no1\nM99\n",
    ],
)
def test_every_kind_of_loop_is_bounded(program: str) -> None:
    with pytest.raises(NgcRuntimeError, match="Work limit reached"):
        run(program, max_iterations=100)


# A subroutine that calls itself ten times per level: about 10**8 calls at nine levels.
FAN_OUT = (
    "o100 sub\n"
    "o101 if [#1 LT 8]\n"
    + "o100 call [#1+1]\n" * 10
    + "o101 endif\n"
    "o100 endsub\n"
    "o100 call [0]\n"
    "M2\n"
)


def test_subroutine_calls_count_against_the_work_budget() -> None:
    started = time.process_time()  # (CPU time: a busy machine does not make it slow)
    with pytest.raises(NgcRuntimeError, match="Work limit reached: 1000 loop") as caught:
        run(FAN_OUT, max_iterations=1000)
    assert time.process_time() - started < 2.0
    assert caught.value.source == "o100 call [#1+1]"


def test_calls_within_the_budget_run() -> None:
    # One call, then ten at the next level: 11 calls, one if per call.
    interp = run(FAN_OUT.replace("LT 8", "LT 1"), max_iterations=11)
    assert interp.ended
    with pytest.raises(NgcRuntimeError, match="Work limit reached: 10 loop"):
        run(FAN_OUT.replace("LT 8", "LT 1"), max_iterations=10)


def test_a_loop_within_the_bound_runs_to_the_end() -> None:
    interp = run("#1=0\no1 while [#1 LT 100]\n#1=[#1+1]\no1 endwhile\nM2\n", max_iterations=100)
    assert interp.ended and interp.params.numbered[1] == 100.0


def test_rs274_command_line_bound(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "r.ngc").write_text("o100 while [1]\no100 endwhile\nM2\n")
    out, err = io.StringIO(), io.StringIO()
    rc = rs274.run(["-g", "--max-iterations", "50", "r.ngc"], stdout=out, stderr=err)
    assert rc == 1
    assert err.getvalue().splitlines()[1:] == [
        "Work limit reached: 50 loop iterations and subroutine calls; the program looks like it "
        "runs forever (raise the limit with --max-iterations)",
        "o100 endwhile",
    ]


def test_bad_bound_on_the_command_line() -> None:
    out, err = io.StringIO(), io.StringIO()
    assert rs274.run(["--max-iterations", "0", "x.ngc"], stdout=out, stderr=err) == 1
    assert "--max-iterations needs a positive number" in err.getvalue()


def test_endless_recursion_stops_at_the_call_depth() -> None:
    with pytest.raises(NgcRuntimeError, match="Too many subroutine levels"):
        run("o1 sub\no1 call\no1 endsub\no1 call\nM2\n")


def test_call_depth_is_configurable() -> None:
    program = "o1 sub\n#<_d>=[#<_d>+1]\no2 if [#<_d> LT 5]\no1 call\no2 endif\no1 endsub\n" \
        "#<_d>=0\no1 call\nM2\n"
    assert run(program).ended
    with pytest.raises(NgcRuntimeError, match="Too many subroutine levels"):
        run(program, max_call_depth=3)


@pytest.mark.parametrize(
    "expression",
    ["[" * 120 + "1" + "]" * 120, "-" * 240 + "1", "[1+" * 60 + "1" + "]" * 60],
)
def test_deep_nesting_in_a_line_is_not_a_crash(expression: str) -> None:
    # The longest line rs274 reads (252 characters) bounds nesting; no Python recursion limit is
    # reachable from program text.
    interp = run(f"#1={expression}\nM2\n")
    assert interp.params.numbered[1] == (1.0 if "+" not in expression else 61.0)


def test_loop_body_is_parsed_once(monkeypatch: pytest.MonkeyPatch) -> None:
    from ngc.interp import interpreter

    calls = []
    real = interpreter.parse_line

    def counting(raw: str, number: int = 0, *more):  # type: ignore[no-untyped-def]
        calls.append(number)
        return real(raw, number, *more)

    monkeypatch.setattr(interpreter, "parse_line", counting)
    run("#1=0\no1 while [#1 LT 50]\nG1 X[#1] F100\n#1=[#1+1]\no1 endwhile\nM2\n")
    assert len(calls) == len(set(calls))  # every line parsed at most once


@pytest.mark.parametrize(
    "name", ["../elsewhere/evil", "/ABS/elsewhere/evil", "sub/../../elsewhere/evil"])
def test_subroutine_names_stay_inside_the_working_directory(
        name: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "work").mkdir()
    (tmp_path / "elsewhere").mkdir()
    (tmp_path / "elsewhere" / "evil.ngc").write_text("o<evil> sub\n(debug,ran)\no<evil> endsub\n")
    monkeypatch.chdir(tmp_path / "work")
    name = name.replace("/ABS", str(tmp_path))
    with pytest.raises(NgcSemanticError, match="outside the working directory") as caught:
        run(f"o<{name}> call\nM2\n")
    assert caught.value.line == 1


def test_a_subroutine_name_may_name_a_folder_inside(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "lib").mkdir()
    (tmp_path / "lib" / "part.ngc").write_text("o<lib/part> sub\nG0 X7\no<lib/part> endsub\n")
    monkeypatch.chdir(tmp_path)
    interp = run("o<lib/part> call\nM2\n")
    assert interp.state.pos[0] == 7.0


def test_a_subroutine_file_name_is_the_bytes_the_program_holds(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "€.ngc").write_text("o<€> sub\nG0 X4\no<€> endsub\n")
    (tmp_path / "prog.ngc").write_text("o<€> call\nM2\n")
    out, err = io.StringIO(), io.StringIO()
    assert rs274.run(["-g", "prog.ngc"], stdout=out, stderr=err) == 0, err.getvalue()
    assert "STRAIGHT_TRAVERSE(4.0000" in out.getvalue()


def _nested_whiles(depth: int) -> str:
    lines = [f"#<v{k}>=0" for k in range(depth)]
    for k in range(depth):
        lines += [f"o{k + 1} while [#<v{k}> LT 1]", f"#<v{k}>=[#<v{k}>+1]"]
    lines += [f"o{k + 1} endwhile" for k in reversed(range(depth))]
    return "\n".join([*lines, "M2"]) + "\n"


@pytest.mark.parametrize("depth", [50, 400])
def test_skipping_nested_loops_reads_each_line_a_bounded_number_of_times(
        depth: int, monkeypatch: pytest.MonkeyPatch) -> None:
    # Each loop ends by skipping over the loops inside it: without leaping over what earlier
    # skips found, the lines read grow with the square of the depth.
    fetched = 0
    fetch = Body.fetch

    def counted(body: Body, number: int) -> object:
        nonlocal fetched
        fetched += 1
        return fetch(body, number)

    monkeypatch.setattr(Body, "fetch", counted)
    program = _nested_whiles(depth)
    interp = run(program)
    assert interp.ended
    assert fetched < 10 * program.count("\n")
