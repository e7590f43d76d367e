"""The lathe surface of the soak (tests/fuzz/soak.py ``--lathe N``): lathe programs run the ways
``ngc check``, ``ngc canon`` and ``ngc time`` run them, with their tool table, on a lathe (a
machine of X and Z), and the checks their results must pass.

``program(rng)`` is a lathe program: a whole job (tests/fuzz/lathejob.py: tool table, G7x
roughing and finishing, G76 and G33 threading, grooving, drilling, compensation) or a profile
with its G71/G72 cycle (tests/fuzz/lathe.py), as generated or mutated: numbers made extreme (0,
tiny, huge, negative, past any float, expressions that give NaN), lines dropped or duplicated, or
the soak's byte and token mutations.  The job's tool table (its ``;tooltable:`` lines) goes to a
tool table file, now and then with its numbers made extreme too.  ``machine_files(rng)`` is a
legal lathe: X and Z (now and then Y too) with values at the ends of their ranges
(tests/fuzz/timed.py).

The checks, beside the soak's: ``ngc check``'s paragraph and JSON hold numbers only; ``ngc canon
--format json`` is strict JSON; ``ngc time``'s are tests/fuzz/timed.py's (times finite and
non-negative, parts adding up to the total, trajectory rows finite with t non-decreasing).
"""

from __future__ import annotations

import contextlib
import io
import json
import random
import re
from pathlib import Path
from typing import Any

import hostile
import lathe
import lathejob
import timed

from ngc.canon.jsonl import JsonSink
from ngc.canon.ops import Sink
from ngc.canon.text import TextSink
from ngc.commands import check as report
from ngc.errors import NgcConfigError, NgcError
from ngc.interp.interpreter import Interpreter
from ngc.options import MachineOptions, Setup, load_setup, new_interpreter
from ngc.planner.config import machine_from_toml
from ngc.planner.machine import DEFAULT_MACHINE, Machine
from ngc.planner.timing import time_file
from ngc.planner.trajectory import TooManyRows, TrajectoryWriter

TABLE_MARK = lathejob.TABLE_MARK
# What a number in a program or a tool table becomes: 0, tiny, huge, negative, past any float,
# and expressions that give NaN or infinity.
EXTREME = ("0", "-0", "0.0000000001", "0.000001", "-0.000001", "1000000000", "-1000000000",
           "99999999999999", "1" + "0" * 300, "-1" + "0" * 300, "9" * 400, "-5", "-0.5",
           "[10**300]", "[-10**300]", "[EXP[710]]", "[0/0]", "[SQRT[-1]]", "[LN[0]]",
           "[1e308*10]", "[EXP[709]]", "[ASIN[2]]", "[1/3]", "[-1/3]", "#1", "#<_x>")
_NUMBER = re.compile(r"(?<=[A-Za-z])\s*([-+]?(?:\d+\.?\d*|\.\d+))")


def _extreme_numbers(rng: random.Random, text: str) -> str:
    spans = [m.span(1) for m in _NUMBER.finditer(text)]
    for i, j in sorted(rng.sample(spans, min(len(spans), rng.choice((1, 1, 2, 3, 8)))),
                       reverse=True):
        text = text[:i] + rng.choice(EXTREME) + text[j:]
    return text


def _lines_changed(rng: random.Random, text: str) -> str:
    lines = text.splitlines(keepends=True)
    for _ in range(rng.choice((1, 1, 2, 4))):
        if not lines:
            break
        i = rng.randrange(len(lines))
        if rng.random() < 0.5:
            del lines[i]
        else:
            lines.insert(i, lines[i] * rng.choice((1, 1, 2, 50)))
    return "".join(lines)


def program(rng: random.Random) -> tuple[str, bytes]:
    """A lathe program: its kind (job or profile, and how it was changed) and bytes."""
    source = "job" if rng.random() < 0.7 else "profile"
    seed = rng.randrange(1 << 30)
    text = lathejob.gen_lathejob(seed) if source == "job" else lathe.gen_lathe(seed)
    how = rng.choice(("plain", "numbers", "numbers", "lines", "both", "bytes"))
    if how in ("numbers", "both"):
        text = _extreme_numbers(rng, text)
    if how in ("lines", "both"):
        text = _lines_changed(rng, text)
    data = text.encode("utf-8")
    if how == "bytes":
        data = hostile.mutate(rng, data)
    return f"{source} {how}", data


def tool_table(rng: random.Random, data: bytes) -> bytes | None:
    """The program's tool table (its ``;tooltable:`` lines), now and then with a number made
    extreme; None when it has none."""
    rows = [line[len(TABLE_MARK):].strip() for line in data.decode("utf-8", "replace").splitlines()
            if line.startswith(TABLE_MARK)]
    if not rows:
        return None
    text = "\n".join(rows) + "\n"
    if rng.random() < 0.15:
        text = _extreme_numbers(rng, text)
    return text.encode("utf-8")


def lathe_toml(rng: random.Random) -> str:
    """A lathe's TOML machine file: X and Z (Y now and then), values at the ends of their
    ranges."""
    axes = "XYZ" if rng.random() < 0.15 else "XZ"
    lines = [f'coordinates = "{axes}"'] if rng.random() < 0.8 else []
    for key, values in (("servo_period", timed.PERIOD), ("tool_change_time", timed.STANDSTILL),
                        ("spindle_start_time", timed.STANDSTILL),
                        ("spindle_stop_time", timed.STANDSTILL),
                        ("max_linear_velocity", timed.VELOCITY)):
        if rng.random() < 0.3:
            lines.append(f"{key} = {timed.toml_value(timed.pick(rng, values))}")
    if rng.random() < 0.2:
        lines.append(f'units = "{rng.choice(("mm", "inch"))}"')
    for axis in axes:
        lines += [f"[axes.{axis}]",
                  f"max_velocity = {timed.toml_value(timed.pick(rng, timed.VELOCITY))}",
                  f"max_acceleration = {timed.toml_value(timed.pick(rng, timed.ACCELERATION))}"]
    lines += timed.blending_toml(rng)
    return "\n".join(lines) + "\n"


# ---- the API -------------------------------------------------------------------------------------
def write_inputs(rng: random.Random, data: bytes, folder: Path) -> dict[str, Path]:
    """The program, its tool table and a lathe's machine file, written in ``folder``."""
    files = {"program": folder / "lathe.ngc", "toml": folder / "m.toml"}
    files["program"].write_bytes(data)
    files["toml"].write_text(lathe_toml(rng))
    table = tool_table(rng, data)
    if table is not None:
        files["tools"] = folder / "tools.tbl"
        files["tools"].write_bytes(table)
    return files


def run_input(rng: random.Random, files: dict[str, Path], max_iterations: int) -> str:
    """Check, canon and time the program of ``files`` as the command line does; checks
    everything.  Returns the outcome; raises :class:`NgcError` for a program error,
    :class:`timed.TimeCheckError` for a broken property, anything else for a crash."""
    tools = str(files["tools"]) if "tools" in files else None
    inputs = MachineOptions(tool_table=tools, max_iterations=max_iterations)
    try:
        setup = load_setup(inputs)
    except NgcConfigError as exc:
        exc.render()
        if "tools" not in files:
            raise
        inputs, setup = MachineOptions(max_iterations=max_iterations), Setup()
    try:
        machine = machine_from_toml(str(files["toml"]), DEFAULT_MACHINE)
    except NgcConfigError as exc:
        raise timed.TimeCheckError(f"a legal machine file refused: {exc.message}") from None
    path = files["program"]
    text = path.read_bytes().decode("utf-8", "surrogateescape")
    check(text, inputs, setup)
    canon(text, inputs, setup, rng.random() < 0.5)
    return time_program(str(path), machine, inputs, rng)


def check(text: str, inputs: MachineOptions, setup: Setup) -> None:
    """``ngc check`` (text and JSON): no NaN in either."""
    def quiet(sink: Sink) -> Interpreter:
        return new_interpreter(sink, inputs, setup, write_files=False)

    result = report.check_lines(io.StringIO(text, newline=""), "lathe.ngc", quiet)
    paragraph = report.render(result)
    if re.search(r"\bnan\b|\binf\b", paragraph):
        raise timed.TimeCheckError(f"check's paragraph holds a non-number: {paragraph[:300]!r}")

    def constant(name: str) -> Any:
        raise timed.TimeCheckError(f"check's JSON holds {name}")

    json.loads(json.dumps(report.record(result)), parse_constant=constant)


def canon(text: str, inputs: MachineOptions, setup: Setup, as_json: bool) -> None:
    """``ngc canon`` (text or JSON, written as the run goes): the JSON strict."""
    out = io.StringIO()
    sink: Sink = JsonSink(out) if as_json else TextSink(out)
    interp = new_interpreter(sink, inputs, setup, write_files=False)
    interp.startup()
    with contextlib.suppress(NgcError):  # (check saw it: the canon before it is checked)
        interp.run(io.StringIO(text, newline=""), file="lathe.ngc")
    sink.flush()
    if as_json:
        def constant(name: str) -> Any:
            raise timed.TimeCheckError(f"canon's JSON holds {name}")

        for line in out.getvalue().splitlines():
            json.loads(line, parse_constant=constant)


def time_program(path: str, machine: Machine, inputs: MachineOptions, rng: random.Random) -> str:
    """``ngc time`` without a trajectory, then with one: timed.py's checks."""
    result = time_file(path, machine, inputs)
    timed.check_result(result, machine)
    timed.check_report(result, machine)
    every = machine.servo_period if rng.random() < 0.5 else rng.choice((0.01, 0.1, 1.0))
    every = max(every, 2.0 * result.total_s / timed.MAX_ROWS)
    rows = timed.Rows()
    writer = TrajectoryWriter(rows, machine, every, timed.MAX_ROWS)
    try:
        again = time_file(path, machine, inputs, on_segment=writer.segment, on_wait=writer.wait)
        writer.finish(again.total_s)
    except TooManyRows:
        raise timed.TimeCheckError(f"more than {timed.MAX_ROWS} rows, a row every {every!r} s "
                                   f"over {result.total_s!r} s") from None
    rows.close()
    if (again.total_s, again.segments) != (result.total_s, result.segments):
        raise timed.TimeCheckError(f"with a trajectory: {again.total_s!r} s, without: "
                                   f"{result.total_s!r} s")
    return "ok"


# ---- the soak's entry --------------------------------------------------------------------------
CheckError = timed.TimeCheckError


def soak_run(rng: random.Random, data: bytes, folder: Path, max_iterations: int,
             configs: dict[str, bytes]) -> str:
    """One input of the soak: the program, its tool table and a lathe written in ``folder``
    (the last two into ``configs``), then :func:`run_input`."""
    files = write_inputs(rng, data, folder)
    configs.update({p.name: p.read_bytes() for key, p in files.items() if key != "program"})
    return run_input(rng, files, max_iterations)
