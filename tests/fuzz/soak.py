#!/usr/bin/env python3
"""Soak: hostile input through the API and the command line, by the hundred thousand.

    python tests/fuzz/soak.py --api 1000000 --cli 10000 --seed 1 --jobs 2
    python tests/fuzz/soak.py --replay tests/fuzz/found/soak-1-api-17.ngc [--decoding utf-8]
    python tests/fuzz/soak.py --shrink tests/fuzz/found/soak-1-api-17.ngc
    python tests/fuzz/soak.py --api 0 --time 20000 --time-cli 1000 --seed 1 --jobs 2
    python tests/fuzz/soak.py --api 0 --engine 200000 --lathe 50000 --seed 1 --jobs 2

Inputs come from tests/fuzz/hostile.py (random bytes, token soup, mutated golden programs); input
``i`` of a seed is always the same program.  API inputs run in worker processes, each on a fresh
``Interpreter`` (``write_files=False``), under a time limit; CLI inputs run ``python -m ngc rs274
-g`` / ``canon`` / ``check`` (with ``--format json`` and the options each command offers, picked at
random) in a fresh folder, with random tool tables, var and INI files next to the program.

A failure is: an exception other than ``NgcError`` (API); exit 70, any other unexpected exit code,
a traceback on stderr, JSON output that is not strict JSON in valid UTF-8 (CLI); a run over the
time limit (CPU time, user and system, so that a machine shared with other work does not make runs
slow; a command line run is killed after 10 s of wall time too); a worker over the RSS limit; a
file left behind where none may be written. Every failing input is saved to ``--out`` (up to
``--keep`` per class) with a text file that says what happened and how to replay it. Exit status 1
if anything failed.

``--time N`` and ``--time-cli N`` soak ``ngc time`` (tests/fuzz/timed.py): each input is a random
legal machine (a TOML file, an INI file or both, values at the ends of their ranges, axes left
out, every blending setting) and a program (the inputs above, unmutated golden programs and the
timing cases), timed in a worker through the API with a trajectory, or run as ``python -m ngc
time`` with the machine files, ``--format json`` and ``--trajectory`` picked at random.  Beside
the checks above: every time finite and non-negative, the parts adding up to the total within
the documented rounding, trajectory rows finite with ``t`` non-decreasing, reports without NaN,
no trajectory file left by a failed run.

``--engine N`` soaks the engine dialect (tests/fuzz/engined.py): random setup sheets (legal ones
at the ends of their ranges, keys left out, hostile TOML) and engine programs (token soup of the
dialect's words, mutated examples of the seed and golden cases), each run in a worker as ``ngc
canon --dialect engine`` (text and JSON) and ``ngc check --dialect engine`` run it.  ``--lathe
N`` soaks lathe programs (tests/fuzz/lathed.py): the fuzzers' lathe jobs and G71/G72 profiles,
as generated and mutated (numbers made extreme, lines dropped or duplicated), with their tool
tables, checked, canon'd and timed (with a trajectory) on random lathes.  Beside the checks
above: segments, dwells and summaries finite and non-negative, outputs without NaN; the lathe's
times pass the ``--time`` checks.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import math
import multiprocessing
import os
import random
import re
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import traceback
from collections import Counter, deque
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from multiprocessing.connection import Connection, wait
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent
for _p in (str(REPO / "src"), str(HERE)):
    if _p not in sys.path:
        sys.path.insert(0, _p)

import engined  # noqa: E402
import hostile  # noqa: E402
import lathed  # noqa: E402
import timed  # noqa: E402

from ngc.errors import NgcError  # noqa: E402

DEFAULT_OUT = HERE / "found"
API_CHUNK = 250  # API inputs per task sent to a worker
TIME_CHUNK = 50  # ngc time inputs per task (each takes longer)
TIME_SOURCES = ("time", "time-cli")
SURFACE_CHUNK = 50  # engine and lathe inputs per task
SURFACES = ("engine", "lathe")  # run in the worker by surface_input
SOURCES = ("api", "cli", *TIME_SOURCES, *SURFACES)
IN_WORKER = ("api", "time", *SURFACES)  # sources run in the worker itself, under the time limit
GRACE_S = 10.0  # a worker this much CPU time past its own time limit is stuck (in C code): killed
CLI_TIMEOUT_S = 10.0  # a command line run is killed after this CPU time (over --time-limit fails)
# ... and after this wall time, however little CPU it took (blocked, or starved on a busy machine)
WALL_BACKSTOP_S = 300.0
OUTPUT_LIMIT = 64 << 20  # ... or after this many bytes of output
KILLED_TIME, KILLED_OUTPUT = -1000, -1001  # the exit code of a run killed for one of those
WHOLE_JSON_LIMIT = 8 << 20  # JSON output up to this size may be one document
KIND_WEIGHTS = {"soup": 2, "golden": 2, "bytes": 1}
OK_EXITS = (0, 1, 2)
TOOL_TABLE = b"T1 P1 Z0.5 D3 ;mill\nT2 P2 Z1 D6 I45 J1 Q2\nT99999 P3 X1 Y2\n"
VAR_FILE = b"5161 1.0\n5220 1.000000\n5221 0.5\n5222 0\n31 7\n1000 3\n"
INI_FILE = b"[RS274NGC]\nPARAMETER_FILE = vars.var\nSUBROUTINE_PATH = .:sub\nFEATURES = 12\n" \
           b"[EMC]\nDEBUG = 0\n[a]\nb = 1\n"


@dataclass
class Config:
    seed: int
    kinds: list[str]
    max_iterations: int
    time_limit: float
    rss_limit_mb: float
    mem_limit_mb: int
    keep: int
    corpus: list[bytes] = field(default_factory=hostile.golden_corpus)
    timing: list[bytes] = field(default_factory=timed.timing_corpus)
    engine_programs: list[bytes] = field(default_factory=engined.corpus)
    cli_variants: list[CliVariant] = field(default_factory=list)
    python: list[str] = field(default_factory=lambda: [sys.executable])


@dataclass
class CliVariant:
    """One command and what it accepts: found in its ``--help``."""

    name: str  # rs274, canon, check
    options: set[str]
    stdin: bool = False


@dataclass
class Failure:
    source: str  # api or cli
    index: int
    kind: str
    klass: str
    detail: str
    data: bytes
    seconds: float
    how: dict[str, Any] = field(default_factory=dict)


@dataclass
class Task:
    source: str
    start: int
    stop: int


@dataclass
class TaskResult:
    task: Task
    counts: Counter[str] = field(default_factory=Counter)
    failures: list[Failure] = field(default_factory=list)
    slowest: tuple[float, str] = (0.0, "")
    rss_kb: int = 0
    child_rss_kb: int = 0
    api_seconds: float = 0.0  # time spent on API inputs (making and running them)


# ---- inputs -------------------------------------------------------------------------------------


def make_input(cfg: Config, source: str, index: int) -> tuple[random.Random, str, bytes]:
    """Input ``index`` of a seed: its random source (for the run's choices too), kind, bytes."""
    rng = random.Random(f"{cfg.seed}/{source}/{index}")
    if source in TIME_SOURCES:
        kind, data = timed.program(rng, cfg.corpus, cfg.timing)
        return rng, kind, data
    if source == "engine":
        kind, data = engined.program(rng, cfg.engine_programs)
        return rng, kind, data
    if source == "lathe":
        kind, data = lathed.program(rng)
        return rng, kind, data
    weighted = [k for k in cfg.kinds for _ in range(KIND_WEIGHTS[k])]
    kind = rng.choice(weighted)
    return rng, kind, hostile.generate(kind, rng, cfg.corpus)


# ---- the API ------------------------------------------------------------------------------------


def _swept(klass: str, detail: str) -> tuple[str, str]:
    """Remove what a run left in the working directory: a run that left anything fails ("wrote
    files", unless it failed otherwise), its detail naming the files."""
    left = os.listdir()
    if left:
        for name in left:
            if os.path.isdir(name):
                shutil.rmtree(name, ignore_errors=True)
            else:
                with contextlib.suppress(OSError):
                    os.unlink(name)
        klass = klass or "wrote files"
        detail += f"\nfiles left in the working directory: {sorted(left)}"
    return klass, detail


def guarded(call: Callable[[], str], time_limit: float,
            check_error: type[Exception] | tuple[()] = (),
            describe: Callable[[NgcError], str] = NgcError.render,
            cleanup: Callable[[], object] | None = None) -> tuple[str, float, str, str]:
    """Run one input in this process under the time limit (CPU seconds): (outcome, seconds,
    failure class or "", detail).  ``call`` gives the outcome; a ``check_error`` is a failed
    check of its results; ``cleanup`` runs after it, within the time counted."""
    start = cpu_seconds()
    klass = detail = ""
    outcome = "ok"
    try:
        with hostile.time_limit(time_limit, cpu=True):
            outcome = call()
    except NgcError as exc:
        outcome, detail = "NgcError", describe(exc)
    except check_error as exc:
        klass, detail = f"check: {str(exc).split(':')[0]}", str(exc)
    except hostile.Overtime:
        klass = f"over {time_limit:g} s"
    except Exception as exc:
        klass, detail = hostile.failure_class(exc), traceback.format_exc()
    finally:
        if cleanup is not None:
            cleanup()
    seconds = cpu_seconds() - start
    klass, detail = _swept(klass, detail)
    return ("fail" if klass else outcome), seconds, klass, detail


def record(cfg: Config, result: TaskResult, rss_flagged: list[bool], source: str, index: int,
           kind: str, data: bytes, run: tuple[str, float, str, str], how: dict[str, Any]) -> None:
    """Count one input's outcome (``run``, as ``guarded`` gives it), keep it if it failed, and
    flag the input that took the worker's peak RSS over the limit (once per worker)."""
    outcome, seconds, klass, detail = run
    result.counts[f"{source} {kind} {outcome}"] += 1
    if seconds > result.slowest[0]:
        result.slowest = (seconds, f"{source} {index}")
    if klass:
        add_failure(result, cfg, Failure(source, index, kind, f"{source} {klass}", detail, data,
                                         seconds, how))
    rss_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    if rss_mb > cfg.rss_limit_mb and not rss_flagged[0]:
        rss_flagged[0] = True
        add_failure(result, cfg, Failure(source, index, kind,
                                         f"{source} RSS over {cfg.rss_limit_mb:g} MB",
                                         f"the worker's peak RSS reached {rss_mb:.1f} MB with "
                                         f"this input ({klass or outcome})", data, seconds, how))


def api_run(data: bytes, decoding: str, feed: str, max_iterations: int,
            time_limit: float) -> tuple[str, float, str, str]:
    """Run one program in this process: (outcome, seconds, failure class or "", detail)."""
    text = hostile.decode(data, decoding)

    def call() -> str:
        hostile.run_api(text, feed=feed, max_iterations=max_iterations)
        return "ok"

    return guarded(call, time_limit, describe=lambda exc: exc.message)


def api_input(cfg: Config, index: int, result: TaskResult, rss_flagged: list[bool]) -> None:
    rng, kind, data = make_input(cfg, "api", index)
    decoding, feed = rng.choice(hostile.DECODINGS), rng.choice(hostile.FEEDS)
    run = api_run(data, decoding, feed, cfg.max_iterations, cfg.time_limit)
    record(cfg, result, rss_flagged, "api", index, kind, data, run,
           {"decoding": decoding, "feed": feed})


def time_input(cfg: Config, index: int, result: TaskResult, rss_flagged: list[bool],
               base: Path) -> None:
    """One ``ngc time`` input through the API: a machine (files in a folder of its own, not in
    the working directory the program might write to) and a program."""
    rng, kind, data = make_input(cfg, "time", index)
    folder = base / f"time-{index}"
    folder.mkdir()
    try:
        files = timed.machine_files(rng, folder)
        configs = {path.name: path.read_bytes() for path in files.values()}
        run = time_api_run(data, files, rng, cfg)
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    record(cfg, result, rss_flagged, "time", index, kind, data, run, {"configs": configs})


def time_api_run(data: bytes, files: dict[str, Path], rng: random.Random, cfg: Config
                 ) -> tuple[str, float, str, str]:
    """(outcome, seconds, failure class or "", detail) of one program timed through the API."""
    text = hostile.decode(data, "utf-8")
    return guarded(lambda: timed.run_api(text, files, rng, cfg.max_iterations), cfg.time_limit,
                   timed.TimeCheckError)


def surface_input(cfg: Config, source: str, index: int, result: TaskResult,
                  rss_flagged: list[bool], base: Path) -> None:
    """One input of the engine or the lathe surface, in this process: its machine inputs in a
    folder of its own (tests/fuzz/engined.py, lathed.py: ``soak_run``)."""
    rng, kind, data = make_input(cfg, source, index)
    module = engined if source == "engine" else lathed
    folder = base / f"{source}-{index}"
    folder.mkdir()
    configs: dict[str, bytes] = {}
    run = guarded(lambda: module.soak_run(rng, data, folder, cfg.max_iterations, configs),
                  cfg.time_limit, module.CheckError,
                  cleanup=lambda: shutil.rmtree(folder, ignore_errors=True))
    record(cfg, result, rss_flagged, source, index, kind, data, run, {"configs": configs})


def add_failure(result: TaskResult, cfg: Config, failure: Failure) -> None:
    """Keep the input (up to ``keep`` per class and task); the count is kept regardless."""
    result.counts[f"failure {failure.klass}"] += 1
    if sum(f.klass == failure.klass for f in result.failures) < cfg.keep:
        result.failures.append(failure)


# ---- the command line ---------------------------------------------------------------------------


def find_variants(python: list[str], env: dict[str, str]) -> list[CliVariant]:
    """The commands and options the ngc under test offers (from their ``--help``)."""
    variants = [CliVariant("rs274", {"-b", "-s", "-t", "-v", "-i", "--max-iterations"})]
    for name in ("canon", "check"):
        proc = subprocess.run([*python, "-m", "ngc", name, "--help"], capture_output=True,
                              env=env, stdin=subprocess.DEVNULL, timeout=CLI_TIMEOUT_S)
        text = proc.stdout.decode("utf-8", "replace")
        options = set(re.findall(r"(?<![\w-])(--?[A-Za-z][\w-]*)", text)) - {"-h", "--help"}
        if "json" not in text:
            options.discard("--format")
        stdin = bool(re.search(r"standard input|stdin|'-'|\"-\"", text, re.IGNORECASE))
        variants.append(CliVariant(name, options, stdin))
    return variants


def cli_env(rng: random.Random, home: Path) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items()
           if k not in ("INI_FILE_NAME", "PYTHONIOENCODING", "LC_ALL", "LANG")}
    env["PYTHONPATH"] = os.pathsep.join([str(REPO / "src"), *filter(None, [env.get("PYTHONPATH")])])
    env["HOME"] = str(home)
    locale = rng.choice(("C", "C.UTF-8", "C.UTF-8", ""))
    if locale:
        env["LC_ALL"] = locale
    if rng.random() < 0.03:
        env["PYTHONIOENCODING"] = rng.choice(("ascii", "latin-1"))
    return env


def cli_command(rng: random.Random, variant: CliVariant, work: Path, data: bytes,
                ) -> tuple[list[str], bytes | None, str]:
    """The arguments of one run (files written into ``work``), its stdin, its output format."""
    name = rng.choice(("prog.ngc",) * 12 + ("with space.ngc", "é.ngc", "€.ngc", "prog"))
    args: list[str] = [variant.name]
    fmt = "text"
    if variant.name == "rs274":
        args.append("-g")
    if "--format" in variant.options and rng.random() < 0.6:
        fmt = "json"
        args += ["--format", "json"]
    for flag in ("-b", "-s"):
        if flag in variant.options and rng.random() < 0.15:
            args.append(flag)
    if "--max-iterations" in variant.options:
        # Always a budget: at the default (10,000,000) a runaway loop runs for tens of seconds
        # by design, where the time limit is 2 s.
        budget = rng.choice((1, 2, 10, 100, 1000)) if rng.random() < 0.4 else hostile.MAX_ITERATIONS
        args += ["--max-iterations", str(budget)]
    for flag, file, template in (("-t", "tools.tbl", TOOL_TABLE), ("-v", "vars.var", VAR_FILE),
                                 ("-i", "x.ini", INI_FILE)):
        if flag in variant.options and rng.random() < 0.2:
            if rng.random() < 0.8:
                (work / file).write_bytes(hostile.mutate(rng, template) if rng.random() < 0.7
                                          else template)
            args += [flag, file]
    stdin = None
    if variant.stdin and rng.random() < 0.15:
        stdin, name = data, "-"
    else:
        (work / name).write_bytes(data)
    return [*args, name], stdin, fmt


def json_problem(path: Path) -> str:
    """Why an output file is not strict JSON in valid UTF-8 ("" if it is): one document (a small
    file), or one document per line."""
    if path.stat().st_size <= WHOLE_JSON_LIMIT and not json_value_problem(path.read_bytes()):
        return ""
    with path.open("rb") as fh:
        for number, line in enumerate(fh, 1):
            if line.strip() and (problem := json_value_problem(line)):
                return f"{problem} (line {number})"
    return ""


def json_value_problem(raw: bytes) -> str:
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        return f"json output is not UTF-8 ({exc.reason})"

    def constant(name: str) -> Any:
        raise ValueError(f"holds {name}")

    try:
        value = json.loads(text, parse_constant=constant)
    except ValueError as exc:
        return f"json output is not strict JSON ({str(exc).split(':')[0]})"
    for s in strings(value):
        try:
            s.encode("utf-8")
        except UnicodeEncodeError:
            return "json output holds a lone surrogate"
    return ""


def strings(value: Any) -> Iterator[str]:
    """Every string in a JSON value, keys too."""
    if isinstance(value, str):
        yield value
    elif isinstance(value, dict):
        for k, v in value.items():
            yield k
            yield from strings(v)
    elif isinstance(value, list):
        for v in value:
            yield from strings(v)


def run_bounded(argv: list[str], work: Path, env: dict[str, str], stdin: Path | None,
                out: Path, err: Path) -> tuple[int, float]:
    """Run a command with its output in files; kill it past ``CLI_TIMEOUT_S`` of CPU time or
    ``WALL_BACKSTOP_S`` of wall time (exit ``KILLED_TIME``: a busy machine does not make a run
    slow) or ``OUTPUT_LIMIT`` bytes of output (``KILLED_OUTPUT``).  Returns the exit code and the
    CPU seconds (user and system) the command took."""
    before = children_cpu_seconds()
    with (open(stdin or os.devnull, "rb") as fin, out.open("wb") as fout,
          err.open("wb") as ferr):
        proc = subprocess.Popen(argv, cwd=work, env=env, stdin=fin, stdout=fout, stderr=ferr)
        deadline = time.monotonic() + WALL_BACKSTOP_S
        while True:
            try:
                rc = proc.wait(timeout=0.05)
                break
            except subprocess.TimeoutExpired:
                big = os.fstat(fout.fileno()).st_size + os.fstat(ferr.fileno()).st_size
                slow = (process_cpu_seconds(proc.pid) > CLI_TIMEOUT_S
                        or time.monotonic() > deadline)
                if slow or big > OUTPUT_LIMIT:
                    proc.kill()
                    proc.wait()
                    rc = KILLED_OUTPUT if big > OUTPUT_LIMIT else KILLED_TIME
                    break
    return rc, children_cpu_seconds() - before


def process_cpu_seconds(pid: int) -> float:
    """The CPU time (user and system) another running process has taken, s (from /proc; 0 where
    it cannot be read, which leaves the wall-time backstop)."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as fh:
            stat = fh.read()
    except OSError:
        return 0.0
    fields = stat[stat.rfind(b")") + 2:].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def cpu_seconds() -> float:
    """This process's CPU time (user and system), s."""
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


def children_cpu_seconds() -> float:
    """The CPU time (user and system) of the finished child processes, s."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def read_bounded(path: Path, limit: int = 256 * 1024) -> bytes:
    """A file, or its head and tail if it is big."""
    size = path.stat().st_size
    with path.open("rb") as fh:
        if size <= 2 * limit:
            return fh.read()
        head = fh.read(limit)
        fh.seek(size - limit)
        return head + b"\n[...]\n" + fh.read()


def cli_input(cfg: Config, index: int, result: TaskResult, base: Path) -> None:
    rng, kind, data = make_input(cfg, "cli", index)
    variant = rng.choice(cfg.cli_variants)
    work, home = base / f"cli-{index}", base / f"home-{index}"
    out, err, stdin_file = base / "stdout", base / "stderr", base / "stdin"
    work.mkdir()
    home.mkdir()
    try:
        argv, stdin, fmt = cli_command(rng, variant, work, data)
        if stdin is not None:
            stdin_file.write_bytes(stdin)
        env = cli_env(rng, home)
        before = set(os.listdir(work))
        rc, seconds = run_bounded([*cfg.python, "-m", "ngc", *argv], work, env,
                                  stdin_file if stdin is not None else None, out, err)
        extra = sorted(set(os.listdir(work)) - before)
        configs = {f: (work / f).read_bytes() for f in ("tools.tbl", "vars.var", "x.ini")
                   if f in before}
        errors = read_bounded(err)
        klass = cli_verdict(cfg, variant.name, fmt, rc, out, errors, seconds, extra)
    finally:
        shutil.rmtree(work, ignore_errors=True)
        shutil.rmtree(home, ignore_errors=True)
    label = f"cli {variant.name}{' json' if fmt == 'json' else ''}"
    result.counts[f"{label} {'fail' if klass else f'exit {rc}'}"] += 1
    if seconds > result.slowest[0]:
        result.slowest = (seconds, f"cli {index}")
    if klass:
        tail = errors.decode("utf-8", "backslashreplace")[-3000:]
        how = {"argv": ["python", "-m", "ngc", *argv], "stdin": stdin is not None,
               "env": {k: env[k] for k in ("LC_ALL", "PYTHONIOENCODING") if k in env},
               "exit": rc, "configs": configs}
        add_failure(result, cfg, Failure("cli", index, kind, f"{label}: {klass}",
                                         f"stderr (tail):\n{tail}", data, seconds, how))


def time_cli_input(cfg: Config, index: int, result: TaskResult, base: Path) -> None:
    """One ``python -m ngc time`` run on a random machine and program."""
    rng, kind, data = make_input(cfg, "time-cli", index)
    work, home = base / f"tcli-{index}", base / f"home-{index}"
    out, err = base / "stdout", base / "stderr"
    work.mkdir()
    home.mkdir()
    try:
        files = timed.machine_files(rng, work)
        configs = {path.name: path.read_bytes() for path in files.values()}
        budget = rng.choice((1, 10, 1000)) if rng.random() < 0.3 else hostile.MAX_ITERATIONS
        args, fmt_json, trajectory = timed.cli_arguments(rng, files, budget)
        argv = [*args, "prog.ngc"]
        (work / "prog.ngc").write_bytes(data)
        env = cli_env(rng, home)
        rc, seconds = run_bounded([*cfg.python, "-m", "ngc", *argv], work, env, None, out, err)
        errors = read_bounded(err)
        klass = cli_verdict(cfg, "time", "json" if fmt_json else "text", rc, out, errors,
                            seconds, [p.name for p in work.iterdir()])
        if not klass and rc not in (KILLED_TIME, KILLED_OUTPUT):
            klass = timed.cli_verdict(rc, read_bounded(out, 64 << 20), errors, work,
                                      fmt_json, trajectory)
    finally:
        shutil.rmtree(work, ignore_errors=True)
        shutil.rmtree(home, ignore_errors=True)
    label = f"time-cli{' json' if fmt_json else ''}"
    result.counts[f"{label} {'fail' if klass else f'exit {rc}'}"] += 1
    if seconds > result.slowest[0]:
        result.slowest = (seconds, f"time-cli {index}")
    if klass:
        tail = errors.decode("utf-8", "backslashreplace")[-3000:]
        how = {"argv": ["python", "-m", "ngc", *argv], "stdin": False,
               "env": {k: env[k] for k in ("LC_ALL", "PYTHONIOENCODING") if k in env},
               "exit": rc, "configs": configs}
        add_failure(result, cfg, Failure("time-cli", index, kind, f"{label}: {klass}",
                                         f"stderr (tail):\n{tail}", data, seconds, how))


def cli_verdict(cfg: Config, command: str, fmt: str, rc: int, out: Path, err: bytes,
                seconds: float, extra: list[str]) -> str:
    """The failure class of one command-line run, "" if it passed."""
    text = err.decode("utf-8", "replace")
    if rc == KILLED_TIME:
        return f"over {CLI_TIMEOUT_S:g} s (killed)"
    if rc == KILLED_OUTPUT:
        return f"over {OUTPUT_LIMIT >> 20} MB of output (killed)"
    if rc == 70:
        m = re.search(r"internal error: (\w+)", text)
        return f"exit 70 ({m.group(1) if m else 'no message'})"
    if "Traceback (most recent call last)" in text:
        last = [line for line in text.splitlines() if re.match(r"\w+(Error|Exception)\b", line)]
        return f"traceback ({last[-1].split(':')[0] if last else 'unknown'})"
    if rc not in OK_EXITS:
        return f"exit {rc}"
    if seconds > cfg.time_limit:
        return f"over {cfg.time_limit:g} s"
    if fmt == "json" and (problem := json_problem(out)):
        return problem
    left = [f for f in extra if f.endswith((".new", ".tmp", "~"))]
    if left:
        return "temporary file left behind"
    if command == "check" and extra:
        return "check wrote files"
    return ""


# ---- workers ------------------------------------------------------------------------------------


def worker_main(conn: Connection, status: Any, cfg: Config) -> None:
    """Run tasks until told to stop; ``status`` holds the input being run and when it started."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the parent handles Ctrl-C
    limit = cfg.mem_limit_mb * 1024 * 1024
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    with tempfile.TemporaryDirectory(prefix="ngc-soak-") as tmp:
        base = Path(tmp)
        work = base / "api"
        work.mkdir()
        os.chdir(work)
        rss_flagged = [False]
        while (task := conn.recv()) is not None:
            result = TaskResult(task)
            began = time.perf_counter()
            for index in range(task.start, task.stop):
                status[0], status[1], status[2] = index, time.monotonic(), time.process_time()
                if task.source == "api":
                    api_input(cfg, index, result, rss_flagged)
                elif task.source == "time":
                    time_input(cfg, index, result, rss_flagged, base)
                elif task.source == "time-cli":
                    time_cli_input(cfg, index, result, base)
                elif task.source in SURFACES:
                    surface_input(cfg, task.source, index, result, rss_flagged, base)
                else:
                    cli_input(cfg, index, result, base)
            status[0] = -1
            if task.source == "api":
                result.api_seconds = time.perf_counter() - began
            result.rss_kb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
            result.child_rss_kb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
            conn.send(result)
        os.chdir(base.parent)


@dataclass
class Worker:
    process: Any
    conn: Connection
    status: Any
    task: Task | None = None


def start_worker(ctx: Any, cfg: Config) -> Worker:
    parent, child = ctx.Pipe()
    status = ctx.RawArray("d", 3)  # the input, and the wall and CPU times it started at
    status[0] = -1
    process = ctx.Process(target=worker_main, args=(child, status, cfg), daemon=True)
    process.start()
    child.close()
    return Worker(process, parent, status)


@dataclass
class Totals:
    counts: Counter[str] = field(default_factory=Counter)
    failures: list[Failure] = field(default_factory=list)
    slowest: tuple[float, str] = (0.0, "")
    rss_kb: int = 0
    child_rss_kb: int = 0
    done: Counter[str] = field(default_factory=Counter)
    api_seconds: float = 0.0
    interrupted: bool = False  # stopped by Ctrl-C or SIGTERM: the counts are of finished tasks

    def add(self, r: TaskResult, cfg: Config) -> None:
        self.counts.update(r.counts)
        self.api_seconds += r.api_seconds
        for f in r.failures:
            if sum(g.klass == f.klass for g in self.failures) < cfg.keep:
                self.failures.append(f)
        self.slowest = max(self.slowest, r.slowest)
        self.rss_kb = max(self.rss_kb, r.rss_kb)
        self.child_rss_kb = max(self.child_rss_kb, r.child_rss_kb)
        self.done[r.task.source] += r.task.stop - r.task.start


def lost_input(cfg: Config, w: Worker, totals: Totals, why: str) -> None:
    """A worker died or was killed on an input: that input is a failure; the rest of its task
    (and the part before, whose results died with it) goes back to the queue."""
    assert w.task is not None
    index = int(w.status[0])
    source = w.task.source
    _, kind, data = make_input(cfg, source, index)
    r = TaskResult(Task(source, index, index + 1))
    r.counts[f"{source} {kind} fail"] += 1
    add_failure(r, cfg, Failure(source, index, kind, f"{source} {why}", why, data,
                                time.monotonic() - w.status[1]))
    totals.add(r, cfg)


def run_campaign(cfg: Config, tasks: list[Task], jobs: int, progress: bool) -> Totals:
    ctx = multiprocessing.get_context("fork")
    totals = Totals()
    pending = deque(tasks)
    workers = [start_worker(ctx, cfg) for _ in range(max(1, jobs))]
    total = Counter({s: sum(t.stop - t.start for t in tasks if t.source == s) for s in SOURCES})
    started = time.monotonic()
    try:
        run_tasks(cfg, ctx, workers, pending, totals, total, started, progress)
    except KeyboardInterrupt:
        totals.interrupted = True
    finally:
        for w in workers:
            with contextlib.suppress(OSError, BrokenPipeError):
                w.conn.send(None)
        for w in workers:
            w.process.join(timeout=5)
            if w.process.is_alive():
                w.process.kill()
        if progress:
            show_progress(totals, total, time.monotonic() - started)
            print(file=sys.stderr)
    return totals


def run_tasks(cfg: Config, ctx: Any, workers: list[Worker], pending: deque[Task], totals: Totals,
              total: Counter[str], started: float, progress: bool) -> None:
    """Hand out tasks and collect their results until none is left."""
    shown = 0.0
    while pending or any(w.task for w in workers):
        for w in workers:
            if w.task is None and pending:
                w.task = pending.popleft()
                w.conn.send(w.task)
        busy = [w for w in workers if w.task is not None]
        ready = wait([w.conn for w in busy], timeout=0.25)
        for i, w in enumerate(workers):
            if w.conn in ready or w.task is None:
                if w.conn in ready:
                    workers[i] = collect(ctx, cfg, w, totals, pending)
                continue
            if w.status[0] >= 0 and stuck(cfg, w):
                w.process.kill()
                w.process.join()
                workers[i] = requeue(ctx, cfg, w, totals, pending, "stuck (killed)")
        if progress and time.monotonic() - shown > 0.5:
            shown = time.monotonic()
            show_progress(totals, total, shown - started)


def stuck(cfg: Config, w: Worker) -> bool:
    """A worker is stuck on an input it runs itself when it has taken ``GRACE_S`` of CPU time past
    the time limit on it (its own timer did not stop it: C code); any worker is after
    ``WALL_BACKSTOP_S`` plus that of wall time on one input (command line runs are bounded by
    ``run_bounded``)."""
    assert w.task is not None
    if w.task.source in IN_WORKER:
        cpu = process_cpu_seconds(w.process.pid) - w.status[2]
        if cpu > cfg.time_limit + GRACE_S:
            return True
    return time.monotonic() - w.status[1] > WALL_BACKSTOP_S + GRACE_S


def collect(ctx: Any, cfg: Config, w: Worker, totals: Totals, pending: deque[Task]) -> Worker:
    try:
        result = w.conn.recv()
    except (EOFError, OSError):
        w.process.join()
        code = w.process.exitcode
        why = f"worker died (signal {-code})" if code and code < 0 else f"worker died (exit {code})"
        return requeue(ctx, cfg, w, totals, pending, why)
    totals.add(result, cfg)
    w.task = None
    return w


def requeue(ctx: Any, cfg: Config, w: Worker, totals: Totals, pending: deque[Task],
            why: str) -> Worker:
    assert w.task is not None
    index = int(w.status[0])
    if index < 0:  # died between tasks: run the whole task again
        pending.appendleft(w.task)
    else:
        lost_input(cfg, w, totals, why)
        if index + 1 < w.task.stop:
            pending.appendleft(Task(w.task.source, index + 1, w.task.stop))
        if index > w.task.start:
            pending.appendleft(Task(w.task.source, w.task.start, index))
    w.conn.close()
    return start_worker(ctx, cfg)


def show_progress(totals: Totals, total: Counter[str], elapsed: float) -> None:
    fails = sum(n for k, n in totals.counts.items() if k.startswith("failure "))
    rate = totals.done["api"] / max(elapsed, 1e-9)
    timing = "".join(f"  {s} {totals.done[s]}/{total[s]}" for s in (*TIME_SOURCES, *SURFACES)
                     if total[s])
    print(f"\r  api {totals.done['api']}/{total['api']}  cli {totals.done['cli']}/{total['cli']}"
          f"{timing}  failures {fails}  {rate:.0f} API inputs/s  {elapsed:.0f}s ", end="", file=sys.stderr,
          flush=True)


# ---- reporting ----------------------------------------------------------------------------------


def save_failure(out: Path, cfg: Config, f: Failure) -> Path:
    out.mkdir(parents=True, exist_ok=True)
    stem = f"soak-{cfg.seed}-{f.source}-{f.index}"
    program = out / f"{stem}.ngc"
    program.write_bytes(f.data)
    lines = [f"class: {f.klass}", f"input: {f.source} {f.index} of seed {cfg.seed} ({f.kind})",
             f"time: {f.seconds:.3f} s"]
    if f.source == "api":
        lines.append(f"read as {f.how.get('decoding')}, fed as {f.how.get('feed')}, "
                     f"max_iterations {cfg.max_iterations}")
        lines.append(f"replay: python tests/fuzz/soak.py --replay {program} "
                     f"--decoding {f.how.get('decoding')} --feed {f.how.get('feed')} "
                     f"--max-iterations {cfg.max_iterations}")
    else:
        for name, body in f.how.get("configs", {}).items():
            (out / f"{stem}.{name}").write_bytes(body)
            lines.append(f"{name}: saved as {stem}.{name}")
        if "argv" in f.how:
            lines.append(f"command: {' '.join(f.how['argv'])}"
                         f"{' < program' if f.how.get('stdin') else ''}")
            lines.append(f"environment: {f.how.get('env')}; exit {f.how.get('exit')}")
        flag = {"time": "--time", "time-cli": "--time-cli", "engine": "--engine",
                "lathe": "--lathe"}.get(f.source, "--cli")
        lines.append(f"rerun: python tests/fuzz/soak.py --seed {cfg.seed} --api 0 {flag} 1 "
                     f"--start {f.index} --out <dir>")
    lines += ["", f.detail]
    (out / f"{stem}.txt").write_text("\n".join(lines) + "\n", encoding="utf-8",
                                     errors="backslashreplace")
    return program


def summarize(cfg: Config, totals: Totals, elapsed: float, out: Path) -> int:
    api_n, cli_n = totals.done["api"], totals.done["cli"]
    rate = f"; API inputs run at {api_n / totals.api_seconds:.0f}/s per worker" if api_n else ""
    timing = "".join(f", {totals.done[s]} {s} inputs" for s in (*TIME_SOURCES, *SURFACES)
                     if totals.done[s])
    print(f"soak: seed {cfg.seed}, {api_n} API inputs, {cli_n} CLI runs{timing} in "
          f"{elapsed:.1f} s{rate}")
    print("outcomes:")
    for key, n in sorted(totals.counts.items()):
        if not key.startswith("failure "):
            print(f"  {key:32} {n:9}")
    classes = Counter({k[len("failure "):]: n for k, n in totals.counts.items()
                       if k.startswith("failure ")})
    saved: dict[str, list[Path]] = {}
    for f in totals.failures:
        saved.setdefault(f.klass, []).append(save_failure(out, cfg, f))
    if classes:
        print(f"failures: {sum(classes.values())} in {len(classes)} classes")
        for klass, n in classes.most_common():
            paths = saved.get(klass, [])
            where = f"e.g. {paths[0]} ({len(paths)} saved)" if paths else ""
            print(f"  {n:7}  {klass}\n           {where}")
    else:
        print("failures: none")
    seconds, which = totals.slowest
    print(f"slowest input: {seconds:.3f} s ({which or '-'})")
    print(f"peak RSS: API workers {totals.rss_kb / 1024:.1f} MB, "
          f"CLI processes {totals.child_rss_kb / 1024:.1f} MB")
    return 1 if classes else 0


# ---- replay and shrink --------------------------------------------------------------------------


@contextlib.contextmanager
def scratch_dir() -> Iterator[Path]:
    old = os.getcwd()
    with tempfile.TemporaryDirectory(prefix="ngc-soak-") as tmp:
        os.chdir(tmp)
        try:
            yield Path(tmp)
        finally:
            os.chdir(old)


def replay(paths: list[Path], opts: argparse.Namespace) -> int:
    failed = 0
    with scratch_dir():
        for path in paths:
            outcome, seconds, klass, detail = api_run(path.read_bytes(), opts.decoding, opts.feed,
                                                      opts.max_iterations, opts.time_limit)
            print(f"{path}: {klass or outcome} ({seconds:.3f} s)")
            if detail:
                print("  " + detail.strip().replace("\n", "\n  "))
            failed += bool(klass)
    return 1 if failed else 0


def ddmin(items: list[bytes], still_fails: Callable[[list[bytes]], bool]) -> list[bytes]:
    """Zeller's delta debugging (complements only): a 1-minimal sublist that still fails."""
    n = 2
    while len(items) >= 2:
        size = math.ceil(len(items) / n)
        for start in range(0, len(items), size):
            rest = items[:start] + items[start + size:]
            if still_fails(rest):
                items, n = rest, max(n - 1, 2)
                break
        else:
            if n >= len(items):
                break
            n = min(2 * n, len(items))
    return items


def shrink(path: Path, opts: argparse.Namespace) -> int:
    """Minimize a failing API input (lines, then bytes) keeping its failure class."""
    data = path.read_bytes()
    deadline = time.monotonic() + opts.shrink_seconds
    with scratch_dir():
        def klass(candidate: bytes) -> str:
            return api_run(candidate, opts.decoding, opts.feed, opts.max_iterations,
                           opts.time_limit)[2]

        target = klass(data)
        if not target:
            print(f"{path}: does not fail through the API (read as {opts.decoding}, fed as "
                  f"{opts.feed})")
            return 1

        def same(parts: list[bytes]) -> bool:
            return time.monotonic() < deadline and klass(b"".join(parts)) == target

        lines = ddmin(data.splitlines(keepends=True), same)
        small = b"".join(ddmin([bytes([b]) for b in b"".join(lines)], same))
    out = path.with_suffix(".min.ngc")
    out.write_bytes(small)
    print(f"{path}: {target}\n{len(data)} -> {len(small)} bytes, written to {out}:")
    print(small.decode("latin-1"))
    return 0


# ---- main ---------------------------------------------------------------------------------------


def parse_args(argv: list[str] | None) -> argparse.Namespace:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--api", type=int, default=10000, help="API inputs (default 10000)")
    ap.add_argument("--cli", type=int, default=0, help="CLI runs (default 0)")
    ap.add_argument("--time", type=int, default=0,
                    help="ngc time inputs through the API, on random machines (default 0)")
    ap.add_argument("--time-cli", type=int, default=0,
                    help="ngc time runs on the command line, on random machines (default 0)")
    ap.add_argument("--engine", type=int, default=0,
                    help="engine-dialect programs with random setup sheets, through the API as "
                    "canon and check run them (default 0)")
    ap.add_argument("--lathe", type=int, default=0,
                    help="lathe programs (generated and mutated) with their tool tables, checked, "
                    "canon'd and timed on random lathes through the API (default 0)")
    ap.add_argument("--seed", type=int, default=1, help="seed (default 1)")
    ap.add_argument("--start", type=int, default=0,
                    help="number of the first input (default 0): --api 1 --start 17 runs input 17")
    ap.add_argument("--jobs", "-j", type=int, default=2, help="worker processes (default 2)")
    ap.add_argument("--kinds", default=",".join(hostile.KINDS),
                    help=f"input kinds (default {','.join(hostile.KINDS)})")
    ap.add_argument("--max-iterations", type=int, default=hostile.MAX_ITERATIONS,
                    help=f"the API runs' loop budget (default {hostile.MAX_ITERATIONS})")
    ap.add_argument("--time-limit", type=float, default=2.0,
                    help="CPU seconds an input may take (default 2; a busy machine does not "
                    "make an input slow)")
    ap.add_argument("--rss-limit-mb", type=float, default=100.0,
                    help="a worker's peak RSS over this is a failure (default 100)")
    ap.add_argument("--mem-limit-mb", type=int, default=1024,
                    help="address-space cap of workers and CLI runs (default 1024)")
    ap.add_argument("--keep", type=int, default=10, help="inputs saved per class (default 10)")
    ap.add_argument("--out", type=Path, default=DEFAULT_OUT,
                    help="where failing inputs go (default tests/fuzz/found/)")
    ap.add_argument("--quiet", "-q", action="store_true", help="no progress line")
    ap.add_argument("--replay", type=Path, nargs="+", metavar="FILE",
                    help="run saved inputs through the API and say what happens")
    ap.add_argument("--shrink", type=Path, metavar="FILE",
                    help="minimize a failing input (API) to FILE's stem + .min.ngc")
    ap.add_argument("--shrink-seconds", type=float, default=60.0)
    ap.add_argument("--decoding", choices=hostile.DECODINGS, default="latin-1",
                    help="--replay/--shrink: how the bytes are read (default latin-1)")
    ap.add_argument("--feed", choices=hostile.FEEDS, default="file",
                    help="--replay/--shrink: file object or splitlines (default file)")
    opts = ap.parse_args(argv)
    unknown = set(opts.kinds.split(",")) - set(hostile.KINDS)
    if unknown:
        ap.error(f"unknown kind(s) {', '.join(sorted(unknown))}; known: {', '.join(hostile.KINDS)}")
    return opts


def interleave(a: list[Task], b: list[Task]) -> list[Task]:
    """``b`` spread evenly among ``a`` (API and CLI inputs make progress together)."""
    out: list[Task] = []
    every = len(a) / len(b) if b else 0.0
    j = 0
    for i, task in enumerate(a):
        while j < len(b) and j * every <= i:
            out.append(b[j])
            j += 1
        out.append(task)
    return out + b[j:]


def main(argv: list[str] | None = None) -> int:
    opts = parse_args(argv)
    if opts.replay:
        return replay(opts.replay, opts)
    if opts.shrink:
        return shrink(opts.shrink, opts)
    cfg = Config(opts.seed, opts.kinds.split(","), opts.max_iterations, opts.time_limit,
                 opts.rss_limit_mb, opts.mem_limit_mb, opts.keep)
    if opts.cli:
        with tempfile.TemporaryDirectory() as home:
            cfg.cli_variants = find_variants(cfg.python, cli_env(random.Random(0), Path(home)))
    first, api_end, cli_end = opts.start, opts.start + opts.api, opts.start + opts.cli
    api_tasks = [Task("api", i, min(i + API_CHUNK, api_end)) for i in range(first, api_end, API_CHUNK)]
    cli_tasks = [Task("cli", i, i + 1) for i in range(first, cli_end)]
    time_end = opts.start + opts.time
    time_tasks = [Task("time", i, min(i + TIME_CHUNK, time_end))
                  for i in range(first, time_end, TIME_CHUNK)]
    time_cli_tasks = [Task("time-cli", i, i + 1) for i in range(first, first + opts.time_cli)]
    tasks = interleave(interleave(api_tasks, cli_tasks), interleave(time_tasks, time_cli_tasks))
    for source in SURFACES:
        end = first + getattr(opts, source)
        tasks = interleave(tasks, [Task(source, i, min(i + SURFACE_CHUNK, end))
                                   for i in range(first, end, SURFACE_CHUNK)])
    progress = sys.stderr.isatty() and not opts.quiet
    start = time.monotonic()
    signal.signal(signal.SIGTERM, _interrupt)  # (workers, forked, stop on their own pipe)
    totals = run_campaign(cfg, tasks, opts.jobs, progress)
    code = summarize(cfg, totals, time.monotonic() - start, opts.out)
    if totals.interrupted:
        print("soak: interrupted; the figures above are of the inputs run to then", file=sys.stderr)
        return 130
    return code


def _interrupt(signum: int, frame: Any) -> None:
    """SIGTERM as Ctrl-C: the run stops and sums up what it has done."""
    raise KeyboardInterrupt


if __name__ == "__main__":
    sys.exit(main())
