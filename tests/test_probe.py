"""The simulated probe (``--probe FILE``, ``Interpreter(probe=...)``): its solids, where a straight
probe stops with it, #5061-#5070, the probe log, and the errors of a probe that does not trip.
(rs274's own probe, which never trips, is covered by the golden cases ``probe-*``.)"""

from __future__ import annotations

from pathlib import Path

import pytest

import ngc
from ngc.canon.jsonl import ListSink
from ngc.cli import main
from ngc.config.probe import Surfaces, read_probe_file, surfaces_from
from ngc.errors import NgcConfigError
from ngc.interp.interpreter import Interpreter

PLANE = {"units": "mm", "plane": [{"z": -1.0, "slope_x": 0.01, "slope_y": -0.005}]}
PART = {
    "box": [{"min": [0, 0, -10], "max": [50, 50, 0]}],
    "cylinder": [{"center": [25, 25], "radius": 5, "cut": True}],
    "grid": [{"origin": [100, 0], "step": [10, 10], "heights": [[0, 1], [2, 3]]}],
}


def _run(program: str, surfaces: Surfaces) -> tuple[Interpreter, ListSink]:
    sink = ListSink()
    interp = Interpreter(sink, probe=surfaces, write_files=False)
    interp.startup()
    interp.run(program.splitlines())
    return interp, sink


def _results(interp: Interpreter) -> list[float]:
    return [round(interp.params.numbered[n], 9) for n in range(5061, 5071)]


def test_plane_stops_at_contact() -> None:
    interp, sink = _run("G21 F100\nG0 X40 Y20 Z2\nG38.2 Z-5\nM2\n", surfaces_from(PLANE))
    assert _results(interp) == [40.0, 20.0, -0.7, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0]
    assert round(interp.state.pos[2], 9) == -0.7
    names = [type(op).__name__ for op, _, _ in sink.ops]
    assert names.count("StraightProbe") == 1


def test_inch_program_mm_surfaces() -> None:
    interp, _ = _run("G20 F10\nG0 Z1\nG38.2 Z-1\nM2\n", surfaces_from(PLANE))
    assert round(interp.params.numbered[5063], 9) == round(-1.0 / 25.4, 9)


def test_offsets_move_the_program_not_the_part() -> None:
    interp, _ = _run("G21 F10\nG10 L2 P1 Z-3\nG0 Z5\nG38.2 Z-5\nM2\n", surfaces_from(PLANE))
    assert round(interp.params.numbered[5063], 9) == 2.0  # machine -1 is program 2


def test_hole_wall_and_leaving_it() -> None:
    interp, _ = _run("G21 F10\nG0 X25 Y25 Z-5\nG38.2 X40\n#1=#5061\nG38.4 X25\n#2=#5070\nM2\n",
                     surfaces_from(PART))
    assert interp.params.numbered[1] == pytest.approx(30.0)
    assert interp.params.numbered[2] == 1.0  # left the wall at once
    assert interp.state.pos[0] == pytest.approx(30.0)


def test_height_grid_is_bilinear() -> None:
    interp, _ = _run("G21 F10\nG0 X105 Y5 Z5\nG38.2 Z-5\nM2\n", surfaces_from(PART))
    assert interp.params.numbered[5063] == pytest.approx(1.5)


def test_g38_3_and_g38_5_without_change_end_at_the_point() -> None:
    interp, _ = _run("G21 F10\nG0 X60 Z5\nG38.3 Z-5\n#1=#5070\nM2\n", surfaces_from(PART))
    assert interp.params.numbered[1] == 0.0
    assert interp.state.pos[2] == -5.0


@pytest.mark.parametrize(("program", "message"), [
    ("G0 X60 Z5\nG38.2 Z-5", "G38.2 move finished without making contact"),
    ("G0 X10 Y10 Z-1\nG38.4 X20", "G38.4 move finished without breaking contact"),
    ("G0 X10 Y10 Z-5\nG38.3 X0", "Probe is already tripped when starting G38.2 or G38.3 move"),
    ("G0 X60 Z5\nG38.5 Z-5", "Probe is not tripped when starting G38.4 or G38.5 move"),
])
def test_errors_of_a_simulated_probe(program: str, message: str) -> None:
    with pytest.raises(ngc.NgcError) as caught:
        _run(f"G21 F10\n{program}\nM2\n", surfaces_from(PART))
    assert caught.value.message == message


def test_probe_log_gets_each_contact(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    sink = ListSink()
    interp = Interpreter(sink, probe=surfaces_from(PLANE))
    interp.startup()
    interp.run("G21 F10\n(PROBEOPEN p.txt)\nG0 Z1\nG38.2 Z-5\nG0 Z1\nG38.3 X1 Z2\n(PROBECLOSE)\nM2\n"
               .splitlines())
    interp.close()
    assert (tmp_path / "p.txt").read_text() == "0.000000 0.000000 -1.000000" + " 0.000000" * 6 + "\n"


def test_interpret_takes_a_probe() -> None:
    sink = ListSink()
    ngc.interpret("F10\nG38.2 Z-5\n#1=#5063\nM2\n", sink, probe=surfaces_from(PLANE))


@pytest.mark.parametrize(("data", "message"), [
    ({"units": "cm"}, "units must be"),
    ({"sphere": []}, "unknown key 'sphere'"),
    ({"box": [{"min": [0, 0], "max": [1, 1, 1]}]}, "min must be 3 numbers"),
    ({"box": [{"min": [0, 0, 0], "max": [1, 1, 1], "colour": 1}]}, "unknown key 'colour'"),
    ({"plane": [{"slope_x": 1}]}, "needs z"),
    ({"plane": [{"z": 0, "cut": "yes"}]}, "cut must be true or false"),
    ({"grid": [{"origin": [0, 0], "step": [1, 1], "heights": [[1], [1, 2]]}]}, "heights must be"),
    ({"grid": [{"origin": [0, 0], "step": [0, 1], "heights": [[1]]}]}, "step must be positive"),
])
def test_bad_probe_data(data: dict[str, object], message: str) -> None:
    with pytest.raises(ValueError, match=message):
        surfaces_from(data)


def test_probe_file_errors(tmp_path: Path) -> None:
    bad = tmp_path / "bad.toml"
    bad.write_text("units = \n")
    with pytest.raises(NgcConfigError, match="probe file"):
        read_probe_file(str(bad))


def test_cli_probe_option(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    probe = tmp_path / "probe.toml"
    probe.write_text('units = "inch"\n[[plane]]\nz = -0.5\n')
    program = tmp_path / "p.ngc"
    program.write_text("G20 F10\nG38.2 Z-2\n(print,#5063 #5070)\nM2\n")
    assert main(["canon", "--probe", str(probe), str(program)]) == 0
    assert "-0.500000 1.000000" in capsys.readouterr().out
    assert main(["check", "--probe", str(tmp_path / "none.toml"), str(program)]) == 2
