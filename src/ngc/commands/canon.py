"""``ngc canon``: a program's canonical operations on stdout, as text or JSON lines."""

from __future__ import annotations

import argparse
import sys

from .. import dialects
from ..dialects import ENGINE
from ..errors import NgcConfigError, NgcError
from ..interp.source import text_reader
from ..options import new_interpreter
from ..progress import is_terminal
from .common import (
    EXIT_OK,
    EXIT_PROGRAM_ERROR,
    EXIT_USAGE,
    SINKS,
    OpenedProgram,
    cannot_open,
    engine_setup,
    flush_sink,
    inputs_conflict,
    load_inputs,
    open_marked,
    progress_of,
)


def run(options: argparse.Namespace) -> int:
    """``ngc canon FILE``: interpreter start-up and program, streamed to stdout; or, in the
    engine dialect, the engine's operations."""
    program = open_marked(options.file, options.dialect)
    try:
        conflict = inputs_conflict(options, program.dialect)
        if conflict is not None:
            sys.stderr.write(f"ngc canon: {conflict}\n")
            return EXIT_USAGE
        if program.dialect == ENGINE:
            return _canon_engine(options, program)
        return _canon_linuxcnc(options, program)
    finally:
        program.close()


def _canon_engine(options: argparse.Namespace, program: OpenedProgram) -> int:
    try:
        setup = engine_setup(options)
    except NgcConfigError as exc:
        sys.stderr.write(f"ngc canon: {exc.message}\n")
        return EXIT_USAGE
    if program.handle is None:
        return cannot_open("canon", program)
    text = dialects.read_text(program.handle)
    try:
        dialects.interpret_engine(text, SINKS[options.format](sys.stdout), setup=setup,
                                  file=program.name, max_iterations=options.max_iterations)
    except NgcError as exc:
        sys.stdout.flush()
        sys.stderr.write(exc.render() + "\n")
        return EXIT_PROGRAM_ERROR
    sys.stdout.flush()
    return EXIT_OK


def _canon_linuxcnc(options: argparse.Namespace, program: OpenedProgram) -> int:
    try:
        machine, setup = load_inputs("canon", options, options.file)
    except NgcConfigError as exc:
        sys.stderr.write(f"ngc canon: {exc.message}\n")
        return EXIT_USAGE
    if program.handle is None:
        return cannot_open("canon", program)
    name = program.name
    handle = text_reader(program.handle)
    sink = SINKS[options.format](sys.stdout)
    interp = new_interpreter(sink, machine, setup)
    with handle, progress_of(name, handle, output_to_terminal=is_terminal(sys.stdout)) as progress:
        try:
            interp.startup()
            interp.run(progress.lines(handle), file=name, reader=handle)
        except NgcError as exc:
            flush_sink(sink)
            progress.close()
            sys.stderr.write(exc.render() + "\n")
            return EXIT_PROGRAM_ERROR
    flush_sink(sink)
    return EXIT_OK
