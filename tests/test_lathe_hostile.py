"""Lathe cycles on inputs the soak found to end in an internal error: each is now an answer or a
program error (exit 0 or 1), never exit 70."""

from __future__ import annotations

import math
import time
from pathlib import Path

import pytest

from cli_helpers import run, write
from ngc.errors import NgcSemanticError
from ngc.interp.lathe.finishing import _crossing
from ngc.interp.lathe.profile import CW, LINE, Seg
from ngc.numeric.longdouble import long_sum

PROGRAMS = {
    # a fillet about its arc's own centre (rs274: "G7X error: Not monotonic")
    "fillet-about-arc-centre": "G18 G21 F100\nG0 X20 Z2\no100 sub\nG1 X10 Z0\nG1 X11 Z-10\n"
    "G2 X11 Z-12 I0 K-1 A1.\nG3 X11 Z-14 I0 K-1\nG1 Z-20\no100 endsub\nG70 Q100\nM2\n",
    # G70 under compensation with a tool of no radius, a fillet in the profile
    "comp-no-radius-fillet": "O10 SUB\nG1 X21.400 Z-0.6\nG1 X17.550\nG1 X17.550 Z-2.2 A0.5\n"
    "G1 X14.750\nO10 ENDSUB\nG18 G21 G90 G40 G80 G8 G54\nG96 D800 S150 M3\nG95 F0.120\nG42\n"
    "G70 Q10 X24 Z2 D1 P2\nM2\n",
    # a distance past what a double holds
    "huge-distance": "O110 SUB\nG0 X27 Z0\nG1 U-3.3 Z-4.400\nG3 X23.036 Z-12.566 I-4.2 K0\n"
    "O110 ENDSUB\ng18 g21 g90 g40 g80 g8 f0.2\ng71.2 q110 x1.700 z2 d[EXP[709]] i1.000 r0.3\nM2\n",
    # a profile point at 1e300 under compensation: NaN where the arcs are compensated
    "huge-point-comp": "O10 SUB\nG0 X3.200 Z[10**300]\nG1 X4.5 Z-1.300\n"
    "G3 X7.600 Z-6.894 I-8.202 K-8.202\nO10 ENDSUB\nG18 G21 G90 G40 G80 G8 G54\nG97 S800 M3\n"
    "G95 F0.25\nG71.2 Q10 X24 Z1 D0.2 I1.5\nG42\nG70 Q10 X24.000 Z1.000 D0.500 P2 E0\nM2\n",
}


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_no_internal_error(name: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = write(tmp_path, f"{name}.ngc", PROGRAMS[name])
    for argv in (("rs274", "-g", path), ("check", path)):
        code, _, err = run(capsys, *argv)
        assert code in (0, 1), (argv, err)
        assert "internal error" not in err


def test_fillet_about_arc_centre_is_not_monotonic(tmp_path: Path,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    path = write(tmp_path, "p.ngc", PROGRAMS["fillet-about-arc-centre"])
    code, _, err = run(capsys, "rs274", "-g", path)
    assert code == 1 and "G7X error: Not monotonic" in err


def test_crossing_of_huge_moves_is_not_an_overflow() -> None:
    line = Seg(LINE, 1e200, 0.0, 2e200, 1e200)
    arc = Seg(CW, 2e200, 1e200, 3e200, 2e200, 3e200, 1e200)
    try:
        x, z = _crossing(line, arc, 1.0, 1e200)
    except NgcSemanticError:
        return
    assert isinstance(x, float) and isinstance(z, float)


def test_crossing_with_a_line_of_no_length_is_a_program_error() -> None:
    line = Seg(LINE, 1.0, 1.0, 1.0, 1.0)
    arc = Seg(CW, 1.0, 1.0, 2.0, 0.0, 2.0, 1.0)
    with pytest.raises(NgcSemanticError):
        _crossing(line, arc, 1.0, 1.0)


def test_long_sum_of_nan_or_infinity() -> None:
    assert math.isnan(long_sum(math.nan, math.pi))
    assert long_sum(math.inf, 1.0) == math.inf


def test_profile_past_a_doubles_range_is_refused_not_nan(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # a profile line to Z EXP[709]: its moved and crossed ends were NaN in G72.2's passes
    path = write(tmp_path, "exp709.ngc", "G18 G90 G40 G21 F200\nG0 X40 Z20\no101 sub\n"
                 "G0 X1.9 Z3.6\nX5.42\nG1 X5.42 Z[EXP[709]]\no101 endsub\n"
                 "G72.2 Q101 X1.4 Z6.1 D0.2 I1 R0.3\nM2\n")
    code, out, err = run(capsys, "canon", path)
    assert code == 1
    assert "nan" not in out
    assert "The cycle's profile is too large to compute its moves" in err


def test_check_says_a_length_past_a_doubles_range(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = write(tmp_path, "far.ngc", "G0 X[EXP[709]]\nG0 X[0-EXP[709]]\nM2\n")
    code, out, _ = run(capsys, "check", path)
    assert code == 0
    assert "rapid length: past a double's range (mm), feed length: 0.0000 mm" in out
    assert "inf" not in out and "nan" not in out
    code, out, _ = run(capsys, "check", "--format", "json", path)
    assert code == 0 and '"rapid_length": null' in out


def test_crossing_of_two_arcs_about_one_centre_is_a_program_error() -> None:
    # (two moved arcs of one centre met in a mutated job: a division by zero)
    a = Seg(CW, 3.0, 0.0, 2.0, -1.0, 2.0, 0.0)
    b = Seg(CW, 2.0, -1.0, 1.0, 0.0, 2.0, 0.0)
    with pytest.raises(NgcSemanticError, match="Not monotonic"):
        _crossing(a, b, 1.0)


def test_offset_steps_count_against_the_work_budget(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # a billion G70 passes, each moving a filleted profile in up to 200 steps: the steps count,
    # so the budget stops it at once rather than after 2000 passes of 200 steps
    path = write(tmp_path, "passes.ngc", "G18 G90 G40 G21 F200\nG0 X40 Z20\no100 sub\n"
                 "G0 X4.3 Z6.3\nG1 X2.79 Z5.83 A0.15\nG1 X0.04 Z4.34\nG1 X0.04 Z3.4892\n"
                 "o100 endsub\nG70 Q100 X5.1 Z1.5 D0.5 P1000000000\nM2\n")
    started = time.process_time()
    code, _, err = run(capsys, "canon", "--max-iterations", "2000", path)
    assert code == 1 and "Work limit reached: 2000" in err
    assert time.process_time() - started < 1.0


def test_check_record_has_null_for_a_length_past_a_doubles_range() -> None:
    import io
    import json

    from ngc.commands import check as report
    from ngc.interp.interpreter import Interpreter

    result = report.check_lines(io.StringIO("G0 X[EXP[709]]\nG0 X[0-EXP[709]]\nM2\n"), "far.ngc",
                                lambda sink: Interpreter(sink))
    record = report.record(result)
    assert record["summary"]["rapid_length"] is None  # type: ignore[index]
    json.loads(json.dumps(record), parse_constant=lambda name: pytest.fail(name))
