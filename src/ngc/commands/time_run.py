"""``ngc time`` on the command line: its options read, the library called, its exit code."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable
from typing import TYPE_CHECKING

from ..canon.ops import Sink
from ..dialects import ENGINE
from ..errors import NgcConfigError, NgcError
from ..interp.interpreter import Interpreter
from ..interp.source import text_reader
from ..options import new_interpreter
from .common import (
    EXIT_OK,
    EXIT_PROGRAM_ERROR,
    EXIT_USAGE,
    NOT_LINUXCNC,
    OpenedProgram,
    Recorded,
    cannot_open,
    display_name,
    each_file,
    load_inputs,
    open_marked,
    progress_of,
    warn_only_defines,
)

if TYPE_CHECKING:
    from ..planner.machine import Machine as PlannerMachine
    from ..planner.timing import TimeResult
    from .time_report import TrajectoryFile


def run(options: argparse.Namespace) -> int:
    """``ngc time FILE``: the program's cycle time on the machine, as a paragraph or a JSON
    object on stdout, and with ``--trajectory`` the sampled motion in a CSV file.  Exit 2 for a
    bad machine input, a file that cannot be read or written, or an engine-dialect program; 1
    for a program error (nothing is printed on stdout then)."""
    for name, value in (("--every", options.every), ("--max-rows", options.max_rows)):
        if value is not None and options.trajectory is None:
            sys.stderr.write(f"ngc time: {name} needs --trajectory\n")
            return EXIT_USAGE
    if options.trajectory is not None and len(options.files) > 1:
        sys.stderr.write("ngc time: --trajectory takes one program\n")
        return EXIT_USAGE
    return each_file(options, _time_one, "" if options.format == "json" else "\n")


def _time_one(options: argparse.Namespace, path: str) -> int:
    """One program of ``ngc time FILE...``: its report, or its error; its exit code."""
    program = open_marked(path, options.dialect)
    try:
        if program.dialect == ENGINE:
            sys.stderr.write(f"ngc time: {NOT_LINUXCNC.format(name=program.name)}\n")
            return EXIT_USAGE
        return _time_linuxcnc(options, program, path)
    finally:
        program.close()


def _time_linuxcnc(options: argparse.Namespace, program: OpenedProgram, path: str) -> int:
    from ..planner.config import load_machine
    from ..planner.trajectory import TooManyRows
    from . import time_report  # loaded on use, as the planner is

    try:
        inputs, setup = load_inputs("time", options, path)
        machine = load_machine(setup.ini, options.machine_file)
    except NgcConfigError as exc:
        sys.stderr.write(f"ngc time: {exc.message}\n")
        return EXIT_USAGE
    if program.handle is None:
        return cannot_open("time", program)
    try:
        csv = None if options.trajectory is None else time_report.TrajectoryFile(options.trajectory)
    except OSError as exc:
        sys.stderr.write(f"ngc time: cannot write {display_name(options.trajectory)}: {exc.strerror}\n")
        return EXIT_USAGE
    try:
        interpreter = Recorded(lambda sink: new_interpreter(sink, inputs, setup,
                                                            write_files=False))
        result = _time_program(options, program, machine, interpreter, csv)
        _print_time(options, program.name, result, machine, path)
        if result.segments == 0:
            warn_only_defines("time", program.name, interpreter.subroutines())
        if result.limits:  # (past the machine's travel: not a program it can run)
            return EXIT_PROGRAM_ERROR
        if csv is not None:
            csv.commit()  # the trajectory takes its name once everything else has gone well
    except NgcError as exc:
        sys.stderr.write(exc.render() + "\n")
        return EXIT_PROGRAM_ERROR
    except (time_report.TrajectoryWriteError, TooManyRows) as exc:
        sys.stderr.write(f"ngc time: {exc}\n")
        return EXIT_USAGE
    finally:
        if csv is not None:
            csv.discard()  # after commit: nothing left to do
    return EXIT_OK


def _time_program(options: argparse.Namespace, program: OpenedProgram, machine: PlannerMachine,
                  interpreter: Callable[[Sink], Interpreter],
                  csv: TrajectoryFile | None) -> TimeResult:
    """Run the program through the planner, with the progress line; the trajectory, if asked
    for, is written to ``csv`` (not committed).  Raises :class:`NgcError` on a program error."""
    from ..planner.timing import time_lines

    writer = None
    if csv is not None:
        from ..planner.trajectory import (  # loaded only for --trajectory
            DEFAULT_MAX_ROWS,
            TrajectoryWriter,
        )

        every = machine.servo_period if options.every is None else options.every
        writer = TrajectoryWriter(csv, machine, every, options.max_rows or DEFAULT_MAX_ROWS)
    assert program.handle is not None
    handle = text_reader(program.handle)
    with handle, progress_of(program.name, handle, output_to_terminal=False) as progress:
        result = time_lines(progress.lines(handle), machine, interpreter, file=program.name,
                            reader=handle, on_segment=None if writer is None else writer.segment,
                            on_wait=None if writer is None else writer.wait)
    if writer is not None:
        writer.finish(result.total_s)
    return result


def _print_time(options: argparse.Namespace, name: str, result: TimeResult,
                machine: PlannerMachine, path: str) -> None:
    """``ngc time``'s report on stdout, with the text of the slowest lines if it is at hand."""
    from . import time_report

    rows = time_report.slowest(result, options.top)
    sources = time_report.source_lines(path, (line for line, _ in rows))
    if options.format == "json":
        time_report.write_json(sys.stdout, name, result, machine, options.top, sources)
    else:
        report = time_report.render(name, result, machine, options.top, sources)
        sys.stdout.write(report + "\n")
    sys.stdout.flush()
