"""What the commands share on the command line: exit codes, the machine inputs as options, a
program file opened with its dialect, the progress line."""

from __future__ import annotations

import argparse
import io
import os
import sys
from collections.abc import Callable
from typing import TYPE_CHECKING, NamedTuple, TextIO

from .. import dialects
from ..canon.jsonl import JsonSink
from ..canon.ops import Sink
from ..canon.text import TextSink
from ..dialects import ENGINE, LINUXCNC
from ..options import MachineOptions, Setup, load_setup
from ..progress import Progress, descriptor, is_terminal

if TYPE_CHECKING:
    from ..engine import Setup as EngineSetup
    from ..interp.interpreter import Interpreter

EXIT_OK = 0
EXIT_PROGRAM_ERROR = 1
EXIT_USAGE = 2

SINKS: dict[str, Callable[[TextIO], Sink]] = {"text": TextSink, "json": JsonSink}
STDIN_NAME = "<stdin>"  # how a program read from standard input (``-``) is named


def load_inputs(command: str, options: argparse.Namespace,
                program: str | None = None) -> tuple[MachineOptions, Setup]:
    """The machine inputs of the command line, loaded; raises :class:`NgcConfigError`.  What
    rs274 would report about the INI file's settings is printed as a warning.  ``program`` is
    the program file's path (``-``: standard input), whose folder is searched for subroutine
    files."""
    machine = MachineOptions(ini_file=options.ini_file, tool_table=options.tool_table,
                             var_file=options.var_file, max_iterations=options.max_iterations,
                             probe_file=options.probe_file,
                             program_file=None if program == "-" else program,
                             unknown_tool=any_tool_warning(command, options))
    setup = load_setup(machine)
    for message in setup.settings.messages:
        sys.stderr.write(f"ngc {command}: warning: {message}\n")
    return machine, setup


def clock(seconds: float) -> str:
    """``h:mm:ss.sss``.

    >>> clock(83.4564), clock(3600.0), clock(0.0)
    ('0:01:23.456', '1:00:00.000', '0:00:00.000')
    """
    ms = round(seconds * 1000.0)
    hours, ms = divmod(ms, 3_600_000)
    minutes, ms = divmod(ms, 60_000)
    return f"{hours}:{minutes:02d}:{ms // 1000:02d}.{ms % 1000:03d}"


def any_tool_warning(command: str, options: argparse.Namespace) -> Callable[[int], None] | None:
    """With ``--any-tool``, what tells of a tool the table lacks, taken as one with no offsets."""
    if not getattr(options, "any_tool", False):
        return None

    def warn(number: int) -> None:
        sys.stderr.write(f"ngc {command}: warning: tool {number} is not in the tool table: taken "
                         "as a tool with no offsets and no diameter (--any-tool)\n")
    return warn


class Recorded:
    """An interpreter factory (``new_interpreter(sink)``) that keeps the interpreter it made, to
    ask it after the run what the program defined."""

    def __init__(self, make: Callable[[Sink], Interpreter]) -> None:
        self.make = make
        self.made: Interpreter | None = None

    def __call__(self, sink: Sink) -> Interpreter:
        self.made = self.make(sink)
        return self.made

    def subroutines(self) -> tuple[str, ...]:
        """The subroutines the program defined, as it names them (``o<name>``, ``o100``)."""
        if self.made is None:
            return ()
        return defined_names(self.made)


def defined_names(interp: Interpreter) -> tuple[str, ...]:
    """The subroutines a run defined, as a program names them (``o<name>``, ``o100``)."""
    return tuple(f"o{label}" if label.isdigit() else f"o<{label}>" for label in interp.flow.subs)


def warn_only_defines(command: str, name: str, subroutines: tuple[str, ...]) -> None:
    """The warning for a program that moved nothing and defined subroutines: a subroutine file
    run on its own."""
    if subroutines:
        sys.stderr.write(f"ngc {command}: warning: {name} moves nothing: it defines "
                         f"{', '.join(subroutines)} (a subroutine file is run through a program "
                         "that calls it)\n")


def open_binary(path: str) -> io.BufferedReader:
    """A program file (``-``: standard input) as bytes.  Raises ``OSError``."""
    if path == "-":
        return open(sys.stdin.fileno(), "rb", closefd=False)
    return open(path, "rb")


class OpenedProgram(NamedTuple):
    """A program file, opened, and its dialect: the one given, else its first line's (see
    :mod:`ngc.dialects`); ``handle`` reads it from its start, ``error`` says why it could not be
    opened (it is reported after the machine inputs are loaded, as before dialects)."""

    name: str
    dialect: str
    handle: io.BufferedReader | None
    error: OSError | None

    def close(self) -> None:
        if self.handle is not None:
            self.handle.close()


def open_marked(path: str, given: str | None) -> OpenedProgram:
    name = display_name(path)
    try:
        handle = open_binary(path)
    except OSError as exc:
        return OpenedProgram(name, given or LINUXCNC, None, exc)
    if given is not None:
        return OpenedProgram(name, given, handle, None)
    try:
        dialect, handle = dialects.of_stream(handle)
    except OSError as exc:
        handle.close()
        return OpenedProgram(name, LINUXCNC, None, exc)
    return OpenedProgram(name, dialect, handle, None)


def display_name(path: str) -> str:
    """How a program file is named in messages: its bytes as UTF-8 text, like the program's."""
    return STDIN_NAME if path == "-" else os.fsencode(path).decode("utf-8", "surrogateescape")


def progress_of(name: str, handle: object, *, output_to_terminal: bool) -> Progress:
    """The progress line of a program file: on stderr, if it is a terminal and stdout is not
    (``ngc canon`` on a terminal shows its output instead)."""
    active = is_terminal(sys.stderr) and not output_to_terminal
    return Progress(sys.stderr, name, descriptor(handle), active=active)


# The LinuxCNC dialect's machine inputs, as options: (attribute, flag).
LINUXCNC_INPUTS = (("ini_file", "-i"), ("tool_table", "-t"), ("var_file", "-v"),
                   ("probe_file", "--probe"))


def inputs_conflict(options: argparse.Namespace, dialect: str) -> str | None:
    """Why the machine inputs given do not fit a program of ``dialect``, or None."""
    if dialect == ENGINE:
        given = [flag for attribute, flag in LINUXCNC_INPUTS
                 if getattr(options, attribute) is not None]
        if given:
            return dialects.linuxcnc_inputs_refused(given)
    elif options.setup_file is not None:
        return dialects.SETUP_IS_ENGINES
    return None


def engine_setup(options: argparse.Namespace) -> EngineSetup | None:
    """The engine's setup sheet (``--setup``), read; raises :class:`NgcConfigError`."""
    if options.setup_file is None:
        return None
    from ..engine import read_setup

    return read_setup(options.setup_file)


def flush_sink(sink: Sink) -> None:
    """Write what the sink holds back, then stdout, so that the operations before an error come
    out before the error."""
    sink.flush()
    sys.stdout.flush()


NOT_LINUXCNC = "ngc time runs LinuxCNC programs; {name} is in the engine dialect"


def cannot_open(command: str, program: OpenedProgram) -> int:
    reason = program.error.strerror if program.error is not None else None
    sys.stderr.write(f"ngc {command}: cannot open {program.name}: {reason}\n")
    return EXIT_USAGE


# -- several programs on several cores (check, time) --------------------------------------------
Worker = Callable[[argparse.Namespace, str], int]


def _run_captured(worker: Worker, options: argparse.Namespace, path: str,
                  stderr_too: bool) -> tuple[int, str, str]:
    """``worker(options, path)``'s exit code and what it wrote to stdout (and stderr)."""
    out, err = io.StringIO(), io.StringIO()
    real = sys.stdout, sys.stderr
    sys.stdout = out
    if stderr_too:
        sys.stderr = err
    try:
        code = worker(options, path)
    finally:
        sys.stdout, sys.stderr = real
    return code, out.getvalue(), err.getvalue()


def _in_worker(job: tuple[Worker, argparse.Namespace, str]) -> tuple[int, str, str]:
    worker, options, path = job
    return _run_captured(worker, options, path, stderr_too=True)


def each_file(options: argparse.Namespace, worker: Worker, separator: str) -> int:
    """Run ``worker(options, path)`` for each of ``options.files`` on ``options.jobs`` worker
    processes (one job, or one file: in this process), writing what each wrote in the files'
    order, the same as with one job; ``separator`` goes between the outputs of two files that
    wrote any (a blank line between paragraphs).  Returns the exit code of the worst: 2 (a file
    or an input that cannot be read), else 1 (a program error), else 0."""
    paths = list(options.files)
    jobs = min(getattr(options, "jobs", 1) or 1, len(paths))
    worst = EXIT_OK
    wrote = False

    def show(code: int, out: str, err: str) -> None:
        nonlocal worst, wrote
        if out:
            if wrote:
                sys.stdout.write(separator)
            sys.stdout.write(out)
            sys.stdout.flush()
            wrote = True
        if err:
            sys.stderr.write(err)
            sys.stderr.flush()
        worst = EXIT_USAGE if EXIT_USAGE in (worst, code) else max(worst, code)

    if jobs <= 1:
        for path in paths:
            show(*_run_captured(worker, options, path, stderr_too=False))
        return worst
    import concurrent.futures
    import multiprocessing

    with concurrent.futures.ProcessPoolExecutor(
            jobs, mp_context=multiprocessing.get_context("fork")) as pool:
        for result in pool.map(_in_worker, [(worker, options, p) for p in paths]):
            show(*result)
    return worst


def default_jobs() -> int:
    """The worker processes ``-j`` gives by default: one per core this process may use."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):
        return max(1, os.cpu_count() or 1)
