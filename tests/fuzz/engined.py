"""The engine dialect's surface of the soak (tests/fuzz/soak.py ``--engine N``): random setup
sheets and engine programs, run the ways ``ngc canon --dialect engine`` (text and JSON) and
``ngc check --dialect engine`` run them, and the checks their results must pass.

``setup_sheet(rng)`` is a setup sheet's bytes: most are legal, their values at the ends of what a
number holds (0, tiny, huge, negative, every tool axis and sign), with tables and keys left out;
some hold an unknown key, a value of the wrong type or hostile TOML (deep nesting, bytes that are
not UTF-8, a cut-off file).  ``program(rng, corpus)`` is an engine program: token soup from the
dialect's words (codes by number and by name, references, clauses of any length, M codes,
parameters, separators), lines built from the grammar with extreme numbers, or a mutation of the
corpus (the examples of ``spec/seeds/003``, ``docs/engine/`` and ``tests/engine/cases/``).

The checks, beside the soak's (no exception but NgcError, no run over the limit, RSS):

* a setup sheet is read or refused with :class:`NgcConfigError`;
* every segment's duration and control points finite, durations and dwells non-negative (so
  the time along the program never goes back);
* the check's summary: time, lengths and extents finite and non-negative where they must be,
  the parts by kind adding up to the total;
* the text and JSON outputs (canon and check) hold no NaN or infinity (JSON without ``null`` for
  a number), and the JSON is strict.
"""

from __future__ import annotations

import io
import json
import math
import random
from collections.abc import Iterable
from pathlib import Path
from typing import Any

import hostile

from ngc import dialects
from ngc.canon.jsonl import JsonSink
from ngc.canon.text import TextSink
from ngc.commands import check_engine as engine_report
from ngc.engine import Dwell, EngineSegment, ModeChange, Setup, read_setup
from ngc.engine.names import NAMES
from ngc.errors import NgcConfigError, NgcError

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent
SEED_TEXT = REPO.parent / "shared" / "spec" / "seeds"
CASES = REPO / "tests" / "engine" / "cases"
EXAMPLES = REPO / "docs" / "engine"
MARKS = ("(dialect: engine)\n", "; dialect: engine\n", "")

# ---- setup sheets --------------------------------------------------------------------------------
# Numbers of a legal sheet: offsets and lengths at the ends of their range and in between
# (ngc.engine.setup: within 1e9 either way), speeds likewise (1e-6 to 1e6); and numbers a sheet
# may not hold, now and then.
SETUP_NUMBERS = ("0", "0.0", "-0.0", "1", "-1", "42.5", "1e-300", "5e-324", "1e-9", "1e9", "-1e9",
                 "999999999.9999999", "1000000000", "-1000000000", "0.001", "25", "360")
SPEEDS = ("1e-6", "0.000001", "1e6", "1000000", "1.0000001e-6", "0.001", "1", "25", "360",
          "999999.9999")
HOSTILE_NUMBERS = ("inf", "-inf", "nan", "+nan", '"1"', "true", "[1]", "{a = 1}", "1979-05-27",
                   "1e300", "-1.7976931348623157e308", "1.0000001e9", "5e-324", "1e7", "0", "-1")
TOOLS = ("0", "1", "2", "-1", "99999", "2147483648", "9223372036854775807", "-9223372036854775808")
SETUP_AXES = "XYZABCUVW"


def _setup_number(rng: random.Random) -> str:
    return rng.choice(HOSTILE_NUMBERS) if rng.random() < 0.03 else rng.choice(SETUP_NUMBERS)


def _legal_sheet(rng: random.Random) -> list[str]:
    lines: list[str] = []
    tools = rng.sample(TOOLS, rng.randint(0, 3))
    if rng.random() < 0.6:
        lines.append(f"tool = {rng.choice(tools or TOOLS)}")
    for tool in tools:
        lines.append(f"[tools.{tool}]")
        if rng.random() < 0.9:
            lines.append(f"length = {_setup_number(rng)}")
    for fixture in rng.sample(range(7), rng.randint(0, 4)):
        lines.append(f"[fixtures.{fixture}]")
        for axis in rng.sample(SETUP_AXES, rng.randint(0, 4)):
            lines.append(f"{axis} = {_setup_number(rng)}")
        if rng.random() < 0.4:
            axis = rng.choice(("", "+", "-", " -")) + rng.choice(SETUP_AXES + "xz")
            lines.append(f"tool_axis = {json.dumps(axis)}")
    for axis in rng.sample(SETUP_AXES, rng.randint(0, 5)):
        speed = rng.choice(HOSTILE_NUMBERS) if rng.random() < 0.03 else rng.choice(SPEEDS)
        lines += [f"[axes.{axis}]", f"max_speed = {speed}"]
    return lines


def setup_sheet(rng: random.Random) -> bytes:
    """A setup sheet's bytes (see the module docstring)."""
    lines = _legal_sheet(rng)
    roll = rng.random()
    if roll < 0.04:
        lines.insert(rng.randint(0, len(lines)), rng.choice(
            ("frobnicate = 1", "[fixtures.7]", "[fixtures.x]", "[axes.Q]", "[tools.a]",
             "tool = 1.5", "tool = true", "[axes]", "fixtures = 3", "[tools.1]\nwidth = 2",
             "[fixtures.1]\nQ = 1", "[axes.X]\nmax_speed = 0", "[axes.X]\nmax_speed = -1")))
    elif roll < 0.06:
        depth = rng.choice((10, 100, 1000, 5000))
        lines.append("a = " + "[" * depth + "]" * depth)
    text = "\n".join(lines) + "\n"
    data = text.encode()
    if roll > 0.97:
        data = hostile.mutate(rng, data)
    elif roll > 0.96:
        data = data[:rng.randint(0, len(data))] + rng.choice((b"\x80", b"\xff\xfe", b"\x00", b"="))
    return data


# ---- programs ------------------------------------------------------------------------------------
def corpus() -> list[bytes]:
    """Engine programs: the golden cases, the drawings' examples and the seed's example lines."""
    programs = [p.read_bytes() for p in sorted(CASES.glob("*.ngc"))]
    programs += [p.read_bytes() for p in sorted(EXAMPLES.glob("*.ngc"))]
    for seed in sorted(SEED_TEXT.glob("003_*.txt")):
        examples = [line for line in seed.read_text(encoding="utf-8").splitlines()
                    if line.startswith(("move ", "G0 ", "G1 "))]
        programs += [line.encode() + b"\n" for line in examples]
        programs.append("\n".join(examples).encode() + b"\n")
    return programs


REFERENCES = ("X", "Y", "Z", "A", "B", "C", "U", "V", "W", "I", "J", "K", "R", "P", "Q", "F", "S",
              "H", "D", "VX", "VY", "VZ", "PX", "PY", "PZ", "VQ", "PQ")
NUMBERS = ("0", "1", "-1", "0.5", "2", "90", "-90", "360", "-720", "3960", "0.125", "0.00001",
           "100", "101", "1000000", "360000000", "100000000000", "9" * 40, "-" + "9" * 60,
           "0." + "0" * 30 + "1", "#1", "#2", "#<x>", "#<__probe_stop>", "[1 + 2]", "[#1 * 2]")
SETTINGS = ("G15", "G17", "G18", "G19", "G20", "G21", "G43", "G49", "G53", "G54", "G59", "G61",
            "G64", "G69", "G80", "G90", "G91")
ODD = (",", ", ,", ";", "(", ")", "()", "[", "]", "#", "=", "G", "M", "G1.5", "G-1", "G999",
       "%", "\t", "X1Y2", "PZ-1", "move,X,1", "(dialect: engine)", "\u00e9", "\x00")


def _number(rng: random.Random) -> str:
    roll = rng.random()
    if roll < 0.15:
        return rng.choice(hostile.EXTREMES)
    if roll < 0.25:
        return f"{rng.uniform(-10, 10):.3f}"
    return rng.choice(NUMBERS)


def _name(rng: random.Random, code: int) -> str:
    """A code as written: by number, or by one of its names in some spelling."""
    if rng.random() < 0.4:
        return f"G{code}" if rng.random() < 0.9 else f"g {code}"
    name = rng.choice(NAMES[code])
    if rng.random() < 0.5:  # leave the optional parts out
        while "(" in name and ")" in name[name.index("("):]:
            i = name.index("(")
            name = name[:i] + name[name.index(")", i) + 1:]
    if rng.random() < 0.3:
        name = name.replace(" ", rng.choice(("", ",", "  ")))
    return rng.choice((name, name.upper(), name.title()))


def _clause(rng: random.Random) -> str:
    ref = rng.choice(REFERENCES)
    count = rng.choice((1, 1, 3, 4, 4, 0, 2, 5))
    sep = rng.choice((" ", " ", ",", ", "))
    return sep.join([ref, *(_number(rng) for _ in range(count))])


def _line(rng: random.Random) -> str:
    roll = rng.random()
    settings = " ".join(rng.sample(SETTINGS, rng.choice((0, 0, 0, 1, 2))))
    if roll < 0.45:
        code = rng.choice((0, 1, 0, 1, 2, 3, 31, 73, 81, 82, 83, 85, 86, 89, 100))
        word = rng.choice(("move", "move", _name(rng, code)))
        clauses = " ".join(_clause(rng) for _ in range(rng.choice((0, 1, 1, 2, 3))))
        return f"{settings} {word} {clauses}".strip()
    if roll < 0.6:
        code = rng.choice(sorted(NAMES))
        return f"{settings} {_name(rng, code)} " + " ".join(
            rng.choice((_number(rng), rng.choice(REFERENCES), _clause(rng)))
            for _ in range(rng.randint(0, 4)))
    if roll < 0.7:
        return f"F {_number(rng)}" if rng.random() < 0.6 else f"{settings} F{_number(rng)}"
    if roll < 0.8:
        words = rng.sample(("M0", "M1", "M2", "M30", "M3", "M4", "M5", "M7", "M8", "M9", "M6",
                            f"S{_number(rng)}", "M 3"), rng.randint(1, 3))
        return " ".join(words)
    if roll < 0.88:
        return f"{rng.choice(('#1', '#2', '#<x>', '#3'))} = {_number(rng)}"
    return " ".join(rng.choice((*ODD, *hostile.COMMENTS, _clause(rng), _number(rng)))
                    for _ in range(rng.randint(1, 4)))


def soup(rng: random.Random) -> bytes:
    """Lines of the dialect's words in random order (see the module docstring)."""
    lines = [_line(rng) for _ in range(rng.choice((1, 2, 5, 10, 20, 40)))]
    end = rng.choice(hostile.LINE_ENDS)
    return (rng.choice(MARKS) + end.join(lines) + end).encode("utf-8", "surrogatepass")


def program(rng: random.Random, programs: list[bytes]) -> tuple[str, bytes]:
    """An engine program: its kind and bytes."""
    kind = rng.choice(("soup", "soup", "mutated", "mutated", "mixed", "bytes"))
    if kind == "soup":
        return kind, soup(rng)
    if kind == "mutated":
        return kind, hostile.mutate(rng, rng.choice(programs))
    if kind == "mixed":  # a corpus program with lines of soup among its own
        lines = rng.choice(programs).splitlines(keepends=True)
        for _ in range(rng.randint(1, 4)):
            lines.insert(rng.randint(0, len(lines)), _line(rng).encode("utf-8", "surrogatepass")
                         + b"\n")
        return kind, b"".join(lines)
    return kind, hostile.random_bytes(rng)


# ---- checks --------------------------------------------------------------------------------------
class EngineCheckError(Exception):
    """A result of the engine that breaks one of the surface's properties."""


def check_op(op: Any) -> None:
    if isinstance(op, EngineSegment):
        if not (math.isfinite(op.duration) and op.duration >= 0.0):
            raise EngineCheckError(f"segment duration {op.duration!r}: line {op.line}")
        for axis, points in op.axes.items():
            if not all(math.isfinite(v) for v in points):
                raise EngineCheckError(f"segment position not finite: line {op.line}, "
                                       f"{axis} {list(points)!r}")
    elif isinstance(op, Dwell):
        if not (math.isfinite(op.seconds) and op.seconds >= 0.0):
            raise EngineCheckError(f"dwell {op.seconds!r}: line {op.line}")
    elif isinstance(op, ModeChange):
        check_finite(op.value, op.name)


def _strict(text: str, what: str) -> None:
    """Each line of ``text`` strict JSON."""
    def constant(name: str) -> Any:
        raise EngineCheckError(f"{what} holds {name}")

    for line in text.splitlines():
        json.loads(line, parse_constant=constant)


def check_finite(value: Any, what: str) -> None:
    """Every number in ``value`` (numbers, strings, lists, tuples, dicts) finite."""
    if isinstance(value, float) and not math.isfinite(value):
        raise EngineCheckError(f"{what} holds {value!r}")
    if isinstance(value, dict):
        value = list(value.values())
    if isinstance(value, list | tuple):
        for item in value:
            check_finite(item, what)


def check_summary(result: engine_report.EngineCheckResult) -> None:
    s = result.summary
    values = [("time", s.time), *((f"time of {k}", v) for k, v in s.times.items()),
              ("length", s.length), *((f"length of {k}", v) for k, v in s.lengths.items())]
    for name, value in values:
        if not (math.isfinite(value) and value >= 0.0):
            raise EngineCheckError(f"check's {name} not finite or negative: {value!r}")
    for axis, (low, high) in s.extents.items():
        if not (math.isfinite(low) and math.isfinite(high) and low <= high):
            raise EngineCheckError(f"check's extents wrong: {axis} {low!r} .. {high!r}")
    found = math.fsum(s.times.values())
    if abs(found - s.time) > 1e-9 * max(1.0, s.time):
        raise EngineCheckError(f"check's times by kind do not add up: {found!r}, the time is "
                               f"{s.time!r}")
    text = engine_report.render(result)
    if "nan" in text or "inf" in text.replace("info", ""):
        raise EngineCheckError(f"check's paragraph holds a non-number: {text[:300]!r}")
    record = engine_report.record(result)
    check_finite(record, "check's JSON")
    _strict(json.dumps(record), "check's JSON")


class _Tee:
    """A sink that checks each operation and hands it to the text and the JSON sinks."""

    def __init__(self, sinks: Iterable[Any]) -> None:
        self.sinks = list(sinks)

    def emit(self, op: Any, label: str, line: int) -> None:
        check_op(op)
        for sink in self.sinks:
            sink.emit(op, label, line)

    def print_text(self, text: str) -> None:
        for sink in self.sinks:
            sink.print_text(text)

    def flush(self) -> None:
        for sink in self.sinks:
            sink.flush()


# ---- the API -------------------------------------------------------------------------------------
def load_setup(path: Path | None) -> tuple[Setup | None, str]:
    """The sheet at ``path`` (None: none) as ``--setup`` reads it, and "" or "setup refused"."""
    if path is None:
        return None, ""
    try:
        return read_setup(str(path)), ""
    except NgcConfigError as exc:
        exc.render()
        return None, "setup refused"


def run_api(text: str, setup: Setup | None, max_iterations: int) -> None:
    """Run ``text`` as ``ngc canon --dialect engine`` (text and JSON at once) and as ``ngc check
    --dialect engine`` do; checks everything.  Raises :class:`NgcError` for a program error (after
    both have run), :class:`EngineCheckError` for a broken property, anything else for a crash."""
    plain, lines = io.StringIO(), io.StringIO()
    error = None
    try:
        dialects.interpret_engine(text, _Tee((TextSink(plain), JsonSink(lines))), setup=setup,
                                  file="hostile.ngc", max_iterations=max_iterations)
    except EngineCheckError:
        raise
    except NgcError as exc:
        exc.render()
        error = exc
    out = plain.getvalue()
    if "nan" in out or "inf," in out or "inf]" in out:
        raise EngineCheckError(f"canon's text holds a non-number: {out[:300]!r}")
    _strict(lines.getvalue(), "canon's JSON")
    result = engine_report.check_text(text, "hostile.ngc", setup, max_iterations)
    check_summary(result)
    if (result.error is None) != (error is None):
        raise EngineCheckError(f"canon and check end differently: {error!r}, {result.error!r}")
    if error is not None:
        raise error


# ---- the soak's entry --------------------------------------------------------------------------
CheckError = EngineCheckError


def soak_run(rng: random.Random, data: bytes, folder: Path, max_iterations: int,
             configs: dict[str, bytes]) -> str:
    """One input of the soak: a setup sheet (most of the time) in ``folder`` (its bytes into
    ``configs``), then the program through :func:`run_api`, read as ``ngc canon`` reads a file.
    Returns the outcome; a refused sheet runs the program on the default machine."""
    path = None
    if rng.random() < 0.8:
        path = folder / "setup.toml"
        configs[path.name] = setup_sheet(rng)
        path.write_bytes(configs[path.name])
    setup, refused = load_setup(path)
    run_api(dialects.read_text(io.BytesIO(data)), setup, max_iterations)
    return "ok, setup refused" if refused else "ok"
