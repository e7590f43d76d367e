"""``ngc check`` on the command line: its options read, the library called, its exit code."""

from __future__ import annotations

import argparse
import sys
from typing import TYPE_CHECKING

from .. import dialects
from ..canon.jsonl import dumps
from ..canon.ops import Sink
from ..dialects import ENGINE
from ..errors import NgcConfigError, NgcError
from ..interp.interpreter import Interpreter
from ..interp.source import text_reader
from ..options import MachineOptions, load_setup, new_interpreter
from .common import (
    EXIT_OK,
    EXIT_PROGRAM_ERROR,
    EXIT_USAGE,
    OpenedProgram,
    any_tool_warning,
    cannot_open,
    each_file,
    engine_setup,
    inputs_conflict,
    load_inputs,
    open_marked,
    progress_of,
)

if TYPE_CHECKING:
    from ..engine import Setup as EngineSetup


def run(options: argparse.Namespace) -> int:
    """``ngc check FILE...``: per file, the error (if any) on stderr and a summary (a paragraph,
    or a JSON object on one line) on stdout.  Nothing is written to disk.

    Each file is in the dialect ``--dialect`` gives, else in the one its first line names; the
    machine inputs of each dialect apply to its files (with ``--dialect``, those of the other
    dialect are a usage error).  ``-j N`` checks N files at once, the output in the files'
    order as with one.  Exit 2 if a file or a machine input cannot be read, else 1 if a program
    has an error, else 0.  ``--dialect grbl`` (or ``grblhal``) holds each line against that
    controller's parser instead (:mod:`ngc.commands.check_grbl`).
    """
    if options.dialect in dialects.GRBL_ROWS:
        from . import check_grbl  # loaded on use, as the other reports

        return check_grbl.run(options)
    conflict = None if options.dialect is None else inputs_conflict(options, options.dialect)
    if conflict is not None:
        sys.stderr.write(f"ngc check: {conflict}\n")
        return EXIT_USAGE
    try:  # (read once here, for their messages and warnings; each file reads them again)
        if options.dialect != ENGINE:
            _, setup = load_inputs("check", options)
            if options.machine_file is not None:
                from ..planner.config import machine_travel

                machine_travel(setup.ini, options.machine_file)
        engine_setup(options)
    except NgcConfigError as exc:
        sys.stderr.write(f"ngc check: {exc.message}\n")
        return EXIT_USAGE
    return each_file(options, _check_file, "" if options.format == "json" else "\n")


def _check_file(options: argparse.Namespace, path: str) -> int:
    """``ngc check`` on one file: its paragraph on stdout, its error on stderr; its exit code."""
    from . import check as report  # loaded on use: ``ngc rs274`` starts without it

    json_lines = options.format == "json"
    program = open_marked(path, options.dialect)
    if program.handle is None:
        assert program.error is not None
        cannot_open("check", program)
        if json_lines:
            sys.stdout.write(dumps(_unreadable(program.name, program.error)) + "\n")
        return EXIT_USAGE
    code = EXIT_OK
    if program.dialect == ENGINE:
        error, paragraph = _check_engine(program, engine_setup(options), json_lines,
                                         options.max_iterations)
    else:
        inputs = MachineOptions(ini_file=options.ini_file, tool_table=options.tool_table,
                                var_file=options.var_file, max_iterations=options.max_iterations,
                                probe_file=options.probe_file,
                                program_file=None if path == "-" else path,
                                unknown_tool=any_tool_warning("check", options))
        setup = load_setup(inputs)

        def quiet(sink: Sink) -> Interpreter:
            return new_interpreter(sink, inputs, setup, write_files=False)

        limits, units, speeds = None, "mm", None
        if setup.ini is not None or options.machine_file is not None:
            from ..planner.config import axis_speeds, machine_travel

            limits, units = machine_travel(setup.ini, options.machine_file)  # (in its units)
            speeds = None if setup.ini is None else axis_speeds(setup.ini)
        handle = text_reader(program.handle)
        with handle, progress_of(program.name, handle, output_to_terminal=False) as progress:
            result = report.check_lines(progress.lines(handle), program.name, quiet,
                                        reader=handle, limits=limits, machine_units=units,
                                        speeds=speeds)
        error = result.error
        if error is None and result.limits:
            code = EXIT_PROGRAM_ERROR
        paragraph = dumps(report.record(result)) if json_lines else report.render(result)
    if error is not None:
        if program.dialect != ENGINE and result.lines == 0:
            # (rs274's message, then what it is about: there is nothing in the file)
            sys.stderr.write(f"{program.name}: {error.message}: the file is empty\n")
        else:
            sys.stderr.write(error.render() + "\n")
        code = EXIT_PROGRAM_ERROR
    sys.stdout.write(paragraph + "\n")
    return code


def _check_engine(program: OpenedProgram, setup: EngineSetup | None, json_lines: bool,
                  max_iterations: int) -> tuple[NgcError | None, str]:
    """``ngc check`` on an engine-dialect program: its first error and its report."""
    from . import check_engine as engine_report

    assert program.handle is not None
    with program.handle:
        text = dialects.read_text(program.handle)
    result = engine_report.check_text(text, program.name, setup, max_iterations)
    return result.error, (dumps(engine_report.record(result)) if json_lines
                          else engine_report.render(result))


def _unreadable(name: str, exc: OSError) -> dict[str, object]:
    """``ngc check --format json``'s object for a file that cannot be opened."""
    error = {"message": f"cannot open: {exc.strerror}", "about": None, "file": name,
             "line": None, "column": None, "source": None}
    return {"file": name, "ok": False, "lines": None, "error": error, "summary": None}
