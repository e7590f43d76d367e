"""``ngc check``'s summary as a machinist reads it: the tools a program cuts with (diameter and
length from the tool table, the length each cuts and the time at the programmed feed), the feeds
and spindle speeds it programs while cutting, every number with its unit."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from cli_helpers import run, write

TABLE = "T1 P1 D6.0 Z25.0 ;end mill\nT2 P2 D3.0 Z40.0 ;drill\n"
METRIC = "[TRAJ]\nLINEAR_UNITS = mm\n"
PROGRAM = """G21 G17 G90
T1 M6
S8000 M3
G0 X0 Y0 Z5
G1 Z-1 F100
G1 X60 F600
G2 X60 Y20 I0 J10
T2 M6
S2000 M3
G1 Z-10 F150
G0 Z5
M2
"""


def _check(tmp_path: Path, capsys: pytest.CaptureFixture[str], program: str,
           *args: str) -> tuple[int, str]:
    ini = write(tmp_path, "mill.ini", METRIC)
    tools = write(tmp_path, "tools.tbl", TABLE)
    path = write(tmp_path, "p.ngc", program)
    code, out, _ = run(capsys, "check", "-j", "1", "-i", ini, "-t", tools, *args, path)
    return code, out


def test_tools_feeds_and_speeds(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, out = _check(tmp_path, capsys, PROGRAM)
    assert code == 0
    # T1: 6 (Z-1 at F100: 3.6 s) + 60 (X60 at F600: 6 s) + a half circle of r 10 (31.4159 at
    # F600: 3.1416 s); T2: 9 (Z-1 to Z-10) at F150 (3.6 s)
    assert out.splitlines()[4:] == [
        "  T1 (diameter 6.0000 mm, length 25.0000 mm): cuts 97.4159 mm, 0:00:12.742 at the "
        "programmed feed",
        "  T2 (diameter 3.0000 mm, length 40.0000 mm): cuts 9.0000 mm, 0:00:03.600 at the "
        "programmed feed",
        "  feed: 100 .. 600 mm/min",
        "  spindle: 2000 .. 8000 rpm",
    ]


def test_json(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    _, out = _check(tmp_path, capsys, PROGRAM, "--format", "json")
    summary = json.loads(out)["summary"]
    assert [(t["tool"], t["diameter"], t["length"], round(t["cut_length"], 4),
             round(t["cut_seconds"], 3)) for t in summary["tools"]] == [
        (1, pytest.approx(6.0), pytest.approx(25.0), 97.4159, 12.742),
        (2, pytest.approx(3.0), pytest.approx(40.0), 9.0, 3.6)]
    assert summary["feed_per_minute"] == [100.0, 600.0] and summary["feed_per_rev"] is None
    assert summary["spindle_rpm"] == [2000.0, 8000.0] and summary["surface_speed"] is None


def test_an_inch_program_reads_in_inches(tmp_path: Path,
                                         capsys: pytest.CaptureFixture[str]) -> None:
    program = "G20\nT1 M6\nS1000 M3\nG1 X1 F10\nM2\n"
    _, out = _check(tmp_path, capsys, program)
    lines = out.splitlines()
    assert lines[4] == ("  T1 (diameter 0.2362 inch, length 0.9843 inch): cuts 1.0000 inch, "
                        "0:00:06.000 at the programmed feed")
    assert lines[5:] == ["  feed: 10 .. 10 inch/min", "  spindle: 1000 .. 1000 rpm"]


def test_feed_per_revolution_and_surface_speed(tmp_path: Path,
                                               capsys: pytest.CaptureFixture[str]) -> None:
    program = ("G18 G21 G7\nT1 M6\nG97 S500 M3\nG95 G1 X10 F0.2\nG96 S120 D2000\nG1 Z-5\n"
               "G97 S500\nG33 Z-10 K1.5\nM2\n")
    _, out = _check(tmp_path, capsys, program)
    lines = out.splitlines()
    # 5 at 0.2 mm/rev and 500 rpm: 3 s; the G96 cut's time is unknown; the thread: 5 at 1.5 mm/rev
    assert lines[4].endswith(": cuts 15.0000 mm, time unknown (G95 under G96)")
    assert lines[5:] == ["  feed: 0.2 .. 0.2 mm/rev", "  spindle: 500 .. 500 rpm",
                         "  spindle: 120 .. 120 m/min (constant surface speed)"]


def test_a_tool_not_in_the_table_and_no_tool(tmp_path: Path,
                                             capsys: pytest.CaptureFixture[str]) -> None:
    _, out = _check(tmp_path, capsys, "G21\nG1 X10 F100\nT7 M6\nG1 X20\nM2\n", "--any-tool")
    assert out.splitlines()[4:6] == [
        "  no tool: cuts 10.0000 mm, 0:00:06.000 at the programmed feed",
        "  T7 (diameter 0.0000 mm, length 0.0000 mm): cuts 10.0000 mm, 0:00:06.000 at the "
        "programmed feed"]


def test_nothing_cut_nothing_said(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    _, out = _check(tmp_path, capsys, "G21\nG0 X10\nM2\n")
    assert len(out.splitlines()) == 4
