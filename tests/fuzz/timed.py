"""The ``ngc time`` surface of the soak (tests/fuzz/soak.py ``--time N``, ``--time-cli N``):
random machine files, and the checks a timed program's results must pass.

``machine_files(rng)`` writes a legal machine: a TOML file, a LinuxCNC INI file, or both (the TOML
file over the INI file's machine), whose values go to the ends of their ranges (0, the smallest,
the largest), with axes left out, every blending setting, start positions far out.  Programs are
the soak's (hostile.py) with unmutated golden programs and the timing cases (tests/timing) added.

The checks, beside the soak's (no exception but NgcError, no exit 70, no run over the limit, RSS):

* every time finite and non-negative (total, naive, by kind, by tool, by line);
* the parts (by kind, by tool, by line) add up to the total but for the rounding docs/time.md
  documents: each stop is rounded up to a whole servo period, at most one per planned move, and
  JSON numbers are rounded to 1e-6;
* trajectory rows finite, ``t`` non-decreasing, velocities non-negative, as many columns as the
  header names; the report (text and JSON) holds no NaN or infinity;
* a run that fails leaves no trajectory file (and no temporary one) behind.
"""

from __future__ import annotations

import io
import json
import math
import random
import re
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

import hostile

from ngc.canon.ops import Sink
from ngc.config.ini import Ini
from ngc.errors import NgcConfigError
from ngc.interp.interpreter import Interpreter
from ngc.planner.config import machine_from_ini, machine_from_toml
from ngc.planner.machine import DEFAULT_MACHINE, Machine
from ngc.planner.timing import TimeResult, time_lines
from ngc.planner.trajectory import TooManyRows, TrajectoryWriter

HERE = Path(__file__).resolve().parent
TIMING = HERE.parent / "timing"
MAX_ROWS = 20_000  # a trajectory's rows in the soak: past them is an accepted outcome
AXES = "XYZABC"
MORE_AXES = "UVW"

# The ends of each range (docs/machine.md), and values in between.
VELOCITY = (1e-6, 1.0000001e-6, 1e6, 0.01, 1.0, 200.0, 25000.0)
ACCELERATION = (1e-6, 1e9, 0.001, 1.0, 1000.0, 1e6)
PERIOD = (1e-6, 1.0, 0.001, 0.0005, 0.00025, 0.1)
CYCLE = (1e-6, 10.0, 0.001, 0.1)
STANDSTILL = (0.0, 1e-6, 1e6, 0.5, 6.0)
DEPTH = (0, 1, 2, 50, 200, 1000)
GAP_CYCLES = (0.0, 1e6, 4.0, 0.5)
RAMP_FREQ = (1e-6, 1e6, 100.0, 20.0)
KINK_RATIO = (0.0, 1e-9, 0.1, 0.5, 0.999, 1.0, 2.0, 614.0, 1e6)
POSITION = (0.0, 1e9, -1e9, 1.5, -250.0, 1e6)


def pick(rng: random.Random, values: tuple[float, ...]) -> float:
    """One of ``values``, or a number spread over their span on a log scale."""
    if rng.random() < 0.8:
        return rng.choice(values)
    positive = [abs(v) for v in values if v != 0.0]
    low, high = math.log10(min(positive)), math.log10(max(positive))
    return 10.0 ** rng.uniform(low, high)


def axis_letters(rng: random.Random) -> str:
    """The machine's axes: X Y Z and some of A B C, or a few of X Y Z A B C (U V W now and then),
    in order."""
    if rng.random() < 0.6:
        return "XYZ" + "".join(axis for axis in "ABC" if rng.random() < 0.2)
    pool = AXES + (MORE_AXES if rng.random() < 0.1 else "")
    count = rng.choice((1, 2, 3, 3, 3, 4, 6))
    chosen = set(rng.sample(pool, min(count, len(pool))))
    return "".join(axis for axis in AXES + MORE_AXES if axis in chosen)


# ---- the TOML machine file -----------------------------------------------------------------------
def toml_value(value: float | int | bool | str) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return json.dumps(value)
    return repr(value)


def toml_text(rng: random.Random, over_ini: bool) -> str:
    lines: list[str] = []
    top: dict[str, float | str] = {}
    for key, values in (("max_linear_velocity", VELOCITY), ("max_linear_acceleration", ACCELERATION),
                        ("servo_period", PERIOD), ("task_cycle_time", CYCLE),
                        ("io_cycle_time", CYCLE), ("tool_change_time", STANDSTILL),
                        ("spindle_start_time", STANDSTILL), ("spindle_stop_time", STANDSTILL)):
        if rng.random() < 0.4:
            top[key] = pick(rng, values)
    if rng.random() < 0.3:
        top["units"] = rng.choice(("mm", "inch"))
    axes = "" if over_ini and rng.random() < 0.6 else axis_letters(rng)
    if axes and rng.random() < 0.7:
        top["coordinates"] = axes
    lines += [f"{key} = {toml_value(value)}" for key, value in top.items()]
    for axis in axes:
        lines += [f"[axes.{axis}]", f"max_velocity = {toml_value(pick(rng, VELOCITY))}",
                  f"max_acceleration = {toml_value(pick(rng, ACCELERATION))}"]
    lines += blending_toml(rng)
    if axes and rng.random() < 0.3:
        lines.append("[start]")
        lines += [f"{axis} = {toml_value(pick(rng, POSITION))}" for axis in axes
                  if rng.random() < 0.6]
    return "\n".join(lines) + "\n"


def blending_toml(rng: random.Random) -> list[str]:
    if rng.random() < 0.4:
        return []
    settings: dict[str, float | int | bool] = {
        "enable": rng.random() < 0.7, "fallback_enable": rng.random() < 0.3,
        "optimization_depth": int(rng.choice(DEPTH)), "gap_cycles": pick(rng, GAP_CYCLES),
        "ramp_freq": pick(rng, RAMP_FREQ), "kink_ratio": pick(rng, KINK_RATIO)}
    kept = [f"{key} = {toml_value(value)}" for key, value in settings.items()
            if rng.random() < 0.6]
    return ["[blending]", *kept]


# ---- the INI file --------------------------------------------------------------------------------
def ini_text(rng: random.Random) -> str:
    axes = axis_letters(rng)
    joints = rng.random() < 0.2  # (joints follow the coordinates: then they are given)
    traj = [f"COORDINATES = {' '.join(axes)}" if joints or rng.random() < 0.8 else ""]
    if rng.random() < 0.5:
        traj.append("LINEAR_UNITS = " + rng.choice(("mm", "inch", "1.0", "0.03937", "metric")))
    for key, values in (("MAX_LINEAR_VELOCITY", VELOCITY),
                        ("MAX_LINEAR_ACCELERATION", ACCELERATION),
                        ("ARC_BLEND_GAP_CYCLES", GAP_CYCLES), ("ARC_BLEND_RAMP_FREQ", RAMP_FREQ),
                        ("ARC_BLEND_KINK_RATIO", KINK_RATIO)):
        if rng.random() < 0.3:
            traj.append(f"{key} = {pick(rng, values)!r}")
    for key in ("ARC_BLEND_ENABLE", "ARC_BLEND_FALLBACK_ENABLE"):
        if rng.random() < 0.3:
            traj.append(f"{key} = {rng.choice(('1', '0', 'TRUE', 'no', 'On'))}")
    if rng.random() < 0.3:
        traj.append(f"ARC_BLEND_OPTIMIZATION_DEPTH = {rng.choice(DEPTH)}")
    sections = ["[TRAJ]", *filter(None, traj)]
    if rng.random() < 0.5:
        nanoseconds = round(pick(rng, PERIOD) * 1e9)
        sections += ["[EMCMOT]", f"SERVO_PERIOD = {min(max(nanoseconds, 1000), 10**9)}"]
    for section in ("TASK", "EMCIO"):
        if rng.random() < 0.3:
            sections += [f"[{section}]", f"CYCLE_TIME = {pick(rng, CYCLE)!r}"]
    for number, axis in enumerate(axes):
        section = f"JOINT_{number}" if joints and rng.random() < 0.5 else f"AXIS_{axis}"
        sections += [f"[{section}]", f"MAX_VELOCITY = {pick(rng, VELOCITY)!r}",
                     f"MAX_ACCELERATION = {pick(rng, ACCELERATION)!r}"]
    return "\n".join(sections) + "\n"


def machine_files(rng: random.Random, folder: Path) -> dict[str, Path]:
    """A legal machine in ``folder``: ``{"ini": ...}``, ``{"toml": ...}`` or both."""
    which = rng.choice(("toml", "toml", "ini", "both"))
    files: dict[str, Path] = {}
    if which in ("ini", "both"):
        files["ini"] = folder / "m.ini"
        files["ini"].write_text(ini_text(rng))
    if which in ("toml", "both"):
        files["toml"] = folder / "m.toml"
        files["toml"].write_text(toml_text(rng, over_ini=which == "both"))
    return files


def load(files: Mapping[str, Path]) -> Machine:
    """The machine of ``files``, as ``ngc time`` loads it."""
    machine = DEFAULT_MACHINE
    if "ini" in files:
        machine = machine_from_ini(Ini.read(files["ini"]))
    if "toml" in files:
        machine = machine_from_toml(str(files["toml"]), machine)
    return machine


# ---- programs ------------------------------------------------------------------------------------
def timing_corpus() -> list[bytes]:
    return [path.read_bytes() for path in sorted(TIMING.glob("*/*.ngc"))]


def program(rng: random.Random, corpus: list[bytes], timing: list[bytes]) -> tuple[str, bytes]:
    """A program for ``ngc time``: its kind and bytes."""
    kind = rng.choice(("golden", "golden", "plain", "timing", "soup", "bytes"))
    if kind == "plain":
        return kind, rng.choice(corpus)
    if kind == "timing":
        data = rng.choice(timing)
        return kind, hostile.mutate(rng, data) if rng.random() < 0.5 else data
    return kind, hostile.generate(kind, rng, corpus)


# ---- checks --------------------------------------------------------------------------------------
class TimeCheckError(Exception):
    """A timed result that breaks one of the surface's properties."""


def check_times(total: float, naive: float, parts: Mapping[str, Iterable[float]],
                segments: int, period: float, rounding: float) -> None:
    """Every time finite and non-negative; each set of parts adds up to the total but for the
    rounding of each stop (one per segment at most) and ``rounding`` per number."""
    for name, value in (("total", total), ("naive", naive)):
        if not (math.isfinite(value) and value >= 0.0):
            raise TimeCheckError(f"{name} time {value!r}")
    for name, values in parts.items():
        numbers = list(values)
        bad = [v for v in numbers if not (math.isfinite(v) and v >= 0.0)]
        if bad:
            raise TimeCheckError(f"{name} holds {bad[0]!r}")
        found = math.fsum(numbers)
        slack = rounding * (len(numbers) + 1) + 1e-9 * total
        if not total - (segments + 1) * period - slack <= found <= total + slack:
            raise TimeCheckError(f"{name} adds up to {found!r}, the total is {total!r} "
                                 f"({segments} segments, servo period {period!r})")


def check_result(result: TimeResult, machine: Machine) -> None:
    check_times(result.total_s, result.naive_s,
                {"by_kind": result.by_kind.values(), "by_tool": result.by_tool.values(),
                 "by_line": [seconds for _, seconds in result.by_line.items()]},
                result.segments, machine.servo_period, 1e-12)
    if not (math.isfinite(result.length) and result.length >= 0.0):
        raise TimeCheckError(f"path length {result.length!r}")


def check_record(record: Any) -> None:
    """``ngc time --format json``'s object."""
    if not isinstance(record, dict):
        raise TimeCheckError("the JSON report is not an object")
    machine = record["machine"]
    check_times(record["total_s"], record["naive_s"],
                {key: record[key].values() for key in ("by_kind", "by_tool", "by_line")},
                record["segments"], machine["servo_period"], 1e-6)


class Rows:
    """A trajectory's CSV text, checked row by row as it is written (nothing is kept)."""

    def __init__(self) -> None:
        self.pending = ""
        self.columns = 0
        self.last_t = -math.inf
        self.count = 0

    def write(self, text: str) -> int:
        self.pending += text
        *lines, self.pending = self.pending.split("\n")
        for line in lines:
            self.row(line)
        return len(text)

    def row(self, line: str) -> None:
        fields = line.split(",")
        if not self.columns:
            if fields[0] != "t" or fields[-2:] != ["velocity", "line"]:
                raise TimeCheckError(f"trajectory header {line!r}")
            self.columns = len(fields)
            return
        self.count += 1
        if len(fields) != self.columns:
            raise TimeCheckError(f"trajectory row {self.count}: {line!r}")
        try:
            numbers = [float(field) for field in fields[:-1]]
            int(fields[-1])
        except ValueError:
            raise TimeCheckError(f"trajectory row {self.count}: {line!r}") from None
        if not all(math.isfinite(n) for n in numbers):
            raise TimeCheckError(f"trajectory row {self.count} not finite: {line!r}")
        if numbers[0] < self.last_t:
            raise TimeCheckError(f"trajectory row {self.count}: t {numbers[0]} after "
                                 f"{self.last_t}")
        if numbers[-1] < 0.0:
            raise TimeCheckError(f"trajectory row {self.count}: velocity {numbers[-1]}")
        self.last_t = numbers[0]

    def close(self) -> None:
        if self.pending:
            raise TimeCheckError(f"trajectory ends in a partial row {self.pending!r}")
        if not self.columns:
            raise TimeCheckError("trajectory without a header")


def check_csv(path: Path) -> int:
    """A trajectory file's rows (see :class:`Rows`); the number of rows."""
    rows = Rows()
    with path.open(encoding="utf-8") as handle:
        for line in handle:
            if not line.endswith("\n"):
                raise TimeCheckError(f"trajectory ends in a partial row {line!r}")
            rows.row(line[:-1])
    rows.close()
    return rows.count


def check_report(result: TimeResult, machine: Machine) -> None:
    """The text and JSON reports of ``result`` hold numbers only."""
    from ngc.commands import time_report

    text = time_report.render("p.ngc", result, machine)
    if "nan" in text or "inf " in text:
        raise TimeCheckError(f"the text report holds a non-number: {text[:300]!r}")
    out = io.StringIO()
    time_report.write_json(out, "p.ngc", result, machine)

    def constant(name: str) -> Any:
        raise TimeCheckError(f"the JSON report holds {name}")

    check_record(json.loads(out.getvalue(), parse_constant=constant))


# ---- the API -------------------------------------------------------------------------------------
def run_api(text: str, files: Mapping[str, Path], rng: random.Random,
            max_iterations: int) -> str:
    """Time ``text`` on the machine of ``files`` in this process, then again with a trajectory;
    checks everything.  Returns the outcome ("ok"); raises :class:`NgcError` for a program error,
    :class:`TimeCheckError` for a broken property, anything else for a crash."""
    try:
        machine = load(files)
    except NgcConfigError as exc:
        raise TimeCheckError(f"a legal machine file refused: {exc.message}") from None

    def interpreter(sink: Sink) -> Interpreter:
        return Interpreter(sink, write_files=False, max_iterations=max_iterations)

    result = time_lines(io.StringIO(text, newline=""), machine, interpreter, file="hostile.ngc")
    check_result(result, machine)
    check_report(result, machine)
    # again with a trajectory of at most MAX_ROWS rows: the same times, and rows that pass
    every = machine.servo_period if rng.random() < 0.7 else rng.choice((0.01, 0.1, 1.0))
    every = max(every, 2.0 * result.total_s / MAX_ROWS)
    rows = Rows()
    writer = TrajectoryWriter(rows, machine, every, MAX_ROWS)
    try:
        again = time_lines(io.StringIO(text, newline=""), machine, interpreter,
                           file="hostile.ngc", on_segment=writer.segment, on_wait=writer.wait)
        writer.finish(again.total_s)
    except TooManyRows:
        raise TimeCheckError(f"more than {MAX_ROWS} rows, a row every {every!r} s over "
                             f"{result.total_s!r} s") from None
    rows.close()
    if (again.total_s, again.naive_s, again.segments) != (result.total_s, result.naive_s,
                                                         result.segments):
        raise TimeCheckError(f"with a trajectory: {again.total_s!r} s, without: "
                             f"{result.total_s!r} s")
    return "ok"


# ---- the command line ----------------------------------------------------------------------------
def cli_arguments(rng: random.Random, files: Mapping[str, Path], budget: int
                  ) -> tuple[list[str], bool, bool]:
    """``ngc time``'s arguments (without the program); whether the report is JSON and whether a
    trajectory (``t.csv``) is asked for."""
    args = ["time", "--max-iterations", str(budget)]
    if "ini" in files:
        args += ["-i", files["ini"].name]
    if "toml" in files:
        args += ["--machine", files["toml"].name]
    fmt_json = rng.random() < 0.6
    if fmt_json:
        args += ["--format", "json"]
    trajectory = rng.random() < 0.5
    if trajectory:
        args += ["--trajectory", "t.csv", "--max-rows", str(MAX_ROWS)]
        if rng.random() < 0.6:  # (at the servo period most programs pass MAX_ROWS)
            args += ["--every", rng.choice(("0.01", "0.1", "1", "10"))]
    if rng.random() < 0.2:
        args += ["--top", rng.choice(("0", "1", "3"))]
    return args, fmt_json, trajectory


def cli_verdict(rc: int, out: bytes, err: bytes, folder: Path, fmt_json: bool,
                trajectory: bool) -> str:
    """What is wrong with one finished ``ngc time`` run ("" if nothing): the soak's own checks
    (exit codes, tracebacks, time) come first."""
    csv = folder / "t.csv"
    if rc == 2 and re.search(rb"^ngc time: (machine file|INI file|cannot open)", err, re.M):
        return "a legal machine file refused"
    left = [p.name for p in folder.iterdir() if p.name.endswith(".tmp")]
    if left:
        return "temporary file left behind"
    if rc != 0:
        if csv.exists():
            return f"exit {rc} left a trajectory file"
        return ""
    try:
        if fmt_json:
            check_record(json.loads(out.decode("utf-8")))
        elif b"nan" in out or b"inf " in out:
            return "text report holds a non-number"
        if trajectory:
            check_csv(csv)
    except TimeCheckError as exc:
        return f"check: {exc}"
    except (ValueError, KeyError) as exc:
        return f"report unreadable ({type(exc).__name__})"
    return ""
