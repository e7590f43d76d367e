"""``ngc rs274 -n 1`` (MDI after an error) with input, and ``-n 0`` at an end of file.

rs274's answers, recorded by hand (the golden folders run with no input): MDI lines run until
``quit``, then ``y`` goes on with the program and anything else stops it (exit 1)."""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from ngc.commands import rs274

PROGRAM = "g1 x1 f1\ng1 x[1/0]\nm2\n"
MOVE5 = "N..... STRAIGHT_TRAVERSE(5.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)"


def _run(tmp_path: Path, program: str, args: list[str], given: str) -> tuple[str, str, int]:
    path = tmp_path / "p.ngc"
    path.write_text(program)
    out, err = io.StringIO(), io.StringIO()
    rc = rs274.run([*args, "-g", str(path)], stdout=out, stderr=err, stdin=io.StringIO(given))
    lines = [line.split(" ", 1)[1].lstrip() for line in out.getvalue().splitlines()]
    return "\n".join(lines), err.getvalue(), rc


@pytest.mark.parametrize(("given", "rc", "ended"), [
    ("g0 x5\nquit\ny\n", 0, True),
    ("g0 x5\nquit\nn\n", 1, False),
    ("g0 x5\n", 1, False),
])
def test_mdi_then_answer(tmp_path: Path, given: str, rc: int, ended: bool) -> None:
    out, err, code = _run(tmp_path, PROGRAM, ["-n", "1"], given)
    assert code == rc
    assert MOVE5 in out
    assert ("PROGRAM_END()" in out) == ended
    assert err == ("executing\nAttempt to divide by zero\ng1 x[1/0]\nstarting MDI\n"
                   "continue program? y/n =>")


def test_mdi_error_is_reported(tmp_path: Path) -> None:
    _, err, code = _run(tmp_path, PROGRAM, ["-n", "1"], "g0 x[1/0]\nquit\ny\n")
    assert code == 0
    assert err.endswith("starting MDI\nAttempt to divide by zero\ng0 x[1/0]\n"
                        "continue program? y/n =>")


def test_end_of_file_stops_once(tmp_path: Path) -> None:
    """rs274 -n 0 repeats this error for ever; ngc reports it once and stops."""
    _, err, code = _run(tmp_path, "g1 x1 f1\ng1 x[1/0]\n", ["-n", "0"], "")
    assert code == 1
    assert err == ("executing\nAttempt to divide by zero\ng1 x[1/0]\n"
                   "File ended with no percent sign or program end\ng1 x[1/0]\n")
