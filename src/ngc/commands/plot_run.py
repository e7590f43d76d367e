"""``ngc plot`` on the command line: its options read, the library called, its exit code."""

from __future__ import annotations

import argparse
import sys
from typing import TYPE_CHECKING

from .. import dialects
from ..dialects import ENGINE
from ..errors import NgcConfigError
from ..interp.source import text_reader
from ..options import new_interpreter
from .common import (
    EXIT_OK,
    EXIT_PROGRAM_ERROR,
    EXIT_USAGE,
    OpenedProgram,
    Recorded,
    cannot_open,
    display_name,
    engine_setup,
    inputs_conflict,
    load_inputs,
    open_marked,
    progress_of,
    warn_only_defines,
)

if TYPE_CHECKING:
    from .plot import PlotOptions


def run(options: argparse.Namespace) -> int:
    """``ngc plot FILE -o OUT``: the toolpath drawn to OUT (.svg or .png).  Exit 2 for a bad
    command line or machine input, a file that cannot be read or written, ``--time`` with an
    engine-dialect program or a missing PNG renderer; 1 when the program stopped on an error
    (the picture is written all the same, the error also on stderr)."""
    from . import plot

    try:
        plot.output_format(options.output)
    except ValueError as exc:
        sys.stderr.write(f"ngc plot: {exc}\n")
        return EXIT_USAGE
    program = open_marked(options.file, options.dialect)
    try:
        conflict = inputs_conflict(options, program.dialect)
        if conflict is not None:
            sys.stderr.write(f"ngc plot: {conflict}\n")
            return EXIT_USAGE
        if program.dialect == ENGINE:
            return _plot_engine(options, program)
        try:
            inputs, setup = load_inputs("plot", options, options.file)
            machine = None
            travel, units = None, "mm"
            if options.time:
                from ..planner.config import load_machine

                machine = load_machine(setup.ini, options.machine_file)
                travel, units = machine.travel, machine.linear_units
            elif setup.ini is not None or options.machine_file is not None:
                from ..planner.config import machine_travel

                travel, units = machine_travel(setup.ini, options.machine_file)
        except NgcConfigError as exc:
            sys.stderr.write(f"ngc plot: {exc.message}\n")
            return EXIT_USAGE
        if program.handle is None:
            return cannot_open("plot", program)
        view = (plot.auto_view_of_file(options.file) if options.view == "auto"
                else options.view)
        how = _plot_options(options, view)
        handle = text_reader(program.handle)
        try:
            with handle, progress_of(program.name, handle, output_to_terminal=False) as progress:
                interpreter = Recorded(lambda sink: new_interpreter(sink, inputs, setup,
                                                                    write_files=False))
                result = plot.draw(progress.lines(handle), program.name, options.output,
                                   interpreter, how, reader=handle,
                                   machine=machine, travel=travel, units=units)
        except NgcConfigError as exc:
            sys.stderr.write(f"ngc plot: {exc.message}\n")
            return EXIT_USAGE
        except OSError as exc:
            sys.stderr.write(f"ngc plot: cannot write {display_name(options.output)}: "
                             f"{exc.strerror}\n")
            return EXIT_USAGE
    finally:
        program.close()
    if result.error is not None:
        sys.stderr.write(result.error.render() + "\n")
        return EXIT_PROGRAM_ERROR
    if result.length == 0.0:
        warn_only_defines("plot", program.name, interpreter.subroutines())
    for excess in result.limits:  # (drawn all the same; not a program the machine can run)
        sys.stderr.write(f"ngc plot: {program.name}: {excess.text(result.units)}\n")
    return EXIT_PROGRAM_ERROR if result.limits else EXIT_OK


def _plot_options(options: argparse.Namespace, view: str) -> PlotOptions:
    from .plot import PlotOptions

    return PlotOptions(view=view, color=options.color, width=options.size[0],
                       height=options.size[1], dpi=options.dpi, approach=options.approach)


def _plot_engine(options: argparse.Namespace, program: OpenedProgram) -> int:
    """An engine-dialect program drawn from its segments (``--time`` is ngc time's: refused)."""
    from . import plot

    if options.time:
        sys.stderr.write(f"ngc plot: --time needs a LinuxCNC program; {program.name} is in the "
                         "engine dialect (ngc check prints its time)\n")
        return EXIT_USAGE
    try:
        setup = engine_setup(options)
    except NgcConfigError as exc:
        sys.stderr.write(f"ngc plot: {exc.message}\n")
        return EXIT_USAGE
    if program.handle is None:
        return cannot_open("plot", program)
    text = dialects.read_text(program.handle)
    view = "top" if options.view == "auto" else options.view
    try:
        result = plot.draw_engine(text, program.name, options.output,
                                  _plot_options(options, view), setup=setup,
                                  max_iterations=options.max_iterations)
    except NgcConfigError as exc:
        sys.stderr.write(f"ngc plot: {exc.message}\n")
        return EXIT_USAGE
    except OSError as exc:
        sys.stderr.write(f"ngc plot: cannot write {display_name(options.output)}: {exc.strerror}\n")
        return EXIT_USAGE
    if result.error is not None:
        sys.stderr.write(result.error.render() + "\n")
        return EXIT_PROGRAM_ERROR
    return EXIT_OK
