"""The ``ngc`` command line: parses arguments, calls the library, maps errors to exit codes.

Exit codes (one policy for every subcommand, see :func:`main`):

==  ==============================================================================
0   success
1   the program has an error (``file:line:col: message`` on stderr / in the report)
2   bad command line, or a file that cannot be read
70  internal error: a bug in ngc (``ngc: internal error: ...``, never a traceback)
130 interrupted (Ctrl-C)
141 stdout was closed early (``ngc canon big.ngc | head``)
143 terminated by SIGTERM (129: SIGHUP), after the normal cleanup
==  ==============================================================================

``ngc rs274`` keeps the exit codes of LinuxCNC's ``rs274``; its arguments go to
:func:`ngc.commands.rs274.run` untouched.
"""

from __future__ import annotations

import argparse
import gc
import io
import math
import os
import sys
from collections.abc import Callable
from typing import TYPE_CHECKING, NamedTuple, TextIO

from . import __version__, dialects
from .canon.jsonl import JsonSink, dumps
from .canon.ops import Sink
from .canon.text import TextSink
from .commands import rs274
from .dialects import ENGINE, LINUXCNC
from .errors import NgcConfigError, NgcError
from .interp.flow import DEFAULT_MAX_ITERATIONS
from .interp.interpreter import Interpreter
from .interp.source import text_reader
from .options import MachineOptions, Setup, load_setup, new_interpreter, parse_positive
from .progress import Progress, descriptor, is_terminal
from .termination import Terminated, signals_raise

EXIT_OK = 0
EXIT_PROGRAM_ERROR = 1
EXIT_USAGE = 2
EXIT_INTERNAL = 70  # EX_SOFTWARE (sysexits.h)
EXIT_INTERRUPTED = 130  # 128 + SIGINT, what shells report for Ctrl-C
EXIT_BROKEN_PIPE = 141  # 128 + SIGPIPE, what a C filter killed by SIGPIPE reports

if TYPE_CHECKING:
    from .commands.plot import PlotOptions
    from .commands.time_report import TrajectoryFile
    from .engine import Setup as EngineSetup
    from .planner.machine import Machine as PlannerMachine
    from .planner.timing import TimeResult

SINKS: dict[str, Callable[[TextIO], Sink]] = {"text": TextSink, "json": JsonSink}
STDIN_NAME = "<stdin>"  # how a program read from standard input (``-``) is named


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``ngc`` console script and ``python -m ngc``; returns the exit code.

    The guard of last resort: an :class:`NgcError` that escapes a subcommand is reported like any
    program error, anything else as an internal error, Ctrl-C quietly, a closed pipe
    (``ngc canon big.ngc | head``) quietly too.
    """
    args = sys.argv[1:] if argv is None else argv
    # A program's lines make short-lived lists and dicts by the thousand, and hardly a cycle: the
    # cycle collector is asked in less often (by default it runs every 700 allocations).
    gc.set_threshold(10000, 50, 100)
    try:
        with signals_raise():
            code = dispatch(args)
        sys.stdout.flush()
    except NgcError as exc:
        sys.stderr.write(exc.render() + "\n")
        code = EXIT_PROGRAM_ERROR
    except KeyboardInterrupt:
        code = EXIT_INTERRUPTED
    except Terminated as exc:
        code = exc.exit_code
    except BrokenPipeError:
        _silence_stdout()
        code = EXIT_BROKEN_PIPE
    except Exception as exc:  # the CLI never shows a traceback (STYLE.md, habit 4)
        sys.stderr.write(f"ngc: internal error: {type(exc).__name__}: {exc}\n")
        code = EXIT_INTERNAL
    return code


def _silence_stdout() -> None:
    """After EPIPE, point stdout at /dev/null so that the interpreter's final flush is quiet."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):
        pass


def dispatch(args: list[str]) -> int:
    """Run one subcommand.  ``rs274`` bypasses argparse: its options are rs274's own (getopt)."""
    if args and args[0] == "rs274":
        return rs274.run(args[1:])
    _write_bytes_as_read()
    parser = build_parser()
    try:
        options = parser.parse_args(args)
    except SystemExit as exc:  # argparse's --help (0) and usage errors (2)
        return exc.code if isinstance(exc.code, int) else EXIT_USAGE
    if options.command is None:
        parser.print_help(sys.stderr)
        return EXIT_USAGE
    command: Callable[[argparse.Namespace], int] = options.run
    return command(options)


def _write_bytes_as_read() -> None:
    """Programs are read as UTF-8 with undecodable bytes kept as surrogates, file names are
    bytes: write both back as the bytes they were, in UTF-8 whatever the locale's encoding (a
    text that came in as bytes goes out as the same bytes; everything ngc adds is ASCII)."""
    for stream in (sys.stdout, sys.stderr):
        if isinstance(stream, io.TextIOWrapper):
            stream.reconfigure(encoding="utf-8", errors="surrogateescape")


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="ngc", description="A pure-Python RS274/NGC (LinuxCNC dialect) G-code interpreter."
    )
    parser.add_argument("--version", action="version", version=f"ngc {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    sub.add_parser(
        "rs274",
        help="drop-in for LinuxCNC's standalone rs274 (batch mode); ngc rs274 --help for more",
        usage="ngc rs274 [-t TBL] [-v VAR] [-i INI] [-n 0|1|2] [-b] [-s] [-g] "
        "[--max-iterations N] [--dialect linuxcnc|engine] [--setup FILE] FILE [OUT]",
        add_help=False,
    )
    machine = [_machine_options(), _dialect_options()]
    canon = sub.add_parser(
        "canon", parents=machine, help="print the canonical machine operations of a program",
        description="Print the canonical machine operations of a program: interpreter start-up, "
        "then the program, as rs274 prints them (text) or as JSON lines. In the engine dialect: "
        "the engine's operations (ENGINE_SEGMENT, DWELL, ...), one per line.",
        epilog=PROGRAM_HELP,
    )
    canon.add_argument("file", metavar="FILE", help="the program (- for standard input)")
    canon.add_argument(
        "--format",
        choices=sorted(SINKS),
        default="text",
        help="text: rs274's transcript format (default); json: JSON lines",
    )
    canon.set_defaults(run=run_canon)
    check = sub.add_parser(
        "check", parents=machine, help="validate programs and summarize their motion",
        description="Run programs through the interpreter, writing nothing to disk: per file, "
        "the first error (on stderr) and a summary of the motion (on stdout). Each file is in "
        "the dialect --dialect gives, else in the one its first line names.",
        epilog=PROGRAM_HELP,
    )
    check.add_argument("files", metavar="FILE", nargs="+", help="programs (- for standard input)")
    check.add_argument(
        "--format",
        choices=("json", "text"),
        default="text",
        help="text: a paragraph per file (default); json: one JSON object per file and line",
    )
    check.set_defaults(run=run_check)
    _add_time(sub, [_machine_options()])
    _add_plot(sub, [_machine_options(), _dialect_options()])
    return parser


def _add_plot(sub: argparse._SubParsersAction[argparse.ArgumentParser],
              parents: list[argparse.ArgumentParser]) -> None:
    plot = sub.add_parser(
        "plot", parents=parents, help="draw a program's toolpath as SVG or PNG",
        description="Run a program and draw its toolpath in machine coordinates: "
        "rapids dashed, feeds solid, arcs exact, drill points and tool changes marked, the "
        "extents as dimension lines in the program's units. A program that stops on an error "
        "is drawn up to the error, the point marked and the message on the drawing (exit 1).",
        epilog=PROGRAM_HELP,
    )
    plot.add_argument("file", metavar="FILE", help="the program (- for standard input)")
    plot.add_argument("-o", "--output", metavar="OUT", required=True,
                      help="the picture: OUT.svg, or OUT.png (needs: pip install 'ngc[png]')")
    plot.add_argument("--view", choices=("auto", *VIEW_NAMES), default="auto",
                      help="top (XY), front (XZ), side (YZ), iso (isometric) or lathe (Z right, "
                      "X up); default auto: lathe for a program with G7 or G8, else top")
    plot.add_argument("--color", choices=("kind", "tool", "feed", "line"), default="kind",
                      help="what the colours show: the kind of move (default), the tool, the "
                      "feed or the line number")
    plot.add_argument("--size", metavar="WxH", type=_size, default=(1200, 900),
                      help="the picture's size in pixels (default 1200x900)")
    plot.add_argument("--dpi", type=float, default=0.0,
                      help="PNG only: render at this many dots per inch (96: the SVG's size)")
    plot.add_argument("--approach", action="store_true",
                      help="draw the rapids before the first cut too (left out by default)")
    plot.add_argument("--time", action="store_true",
                      help="time the program on the machine (as ngc time) and print the cycle "
                      "time on the drawing")
    plot.add_argument("--machine", metavar="TOML", dest="machine_file",
                      help="with --time: ngc's TOML machine file, over the default machine")
    plot.set_defaults(run=run_plot)


VIEW_NAMES = ("top", "front", "side", "iso", "lathe")


def _size(text: str) -> tuple[int, int]:
    parts = text.lower().split("x")
    try:
        w, h = int(parts[0]), int(parts[1])
    except (IndexError, ValueError):
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT in pixels, got {text!r}") from None
    if len(parts) != 2 or not (16 <= w <= 20000 and 16 <= h <= 20000):
        raise argparse.ArgumentTypeError(f"a size from 16x16 to 20000x20000 pixels, not {text!r}")
    return w, h


def _add_time(sub: argparse._SubParsersAction[argparse.ArgumentParser],
              parents: list[argparse.ArgumentParser]) -> None:
    time = sub.add_parser(
        "time", parents=parents, help="estimate a program's cycle time on a machine",
        description="Plan a LinuxCNC program's motion on a machine (axis limits, blending, servo "
        "period, tool change and spindle times) and print how long it takes: in total, beside "
        "the naive distance / feed figure, by kind, by tool and by line. The machine is the "
        "default machine, or -i INI's, with --machine's TOML file over it (docs/machine.md).",
        epilog=PROGRAM_HELP,
    )
    time.add_argument("file", metavar="FILE", help="the program (- for standard input)")
    time.add_argument("--dialect", choices=dialects.DIALECTS, default=None,
                      help="the program's dialect; ngc time runs LinuxCNC programs only, and "
                      "refuses one in the engine dialect (given here, or by its first line)")
    time.add_argument("--machine", metavar="TOML", dest="machine_file",
                      help="ngc's TOML machine file, over the default machine or -i INI's")
    time.add_argument("--format", choices=("json", "text"), default="text",
                      help="text: a paragraph (default); json: one JSON object")
    time.add_argument("--trajectory", metavar="OUT.csv",
                      help="write the sampled trajectory as CSV: t, x, y, z (a, b, c for the "
                      "machine's rotary axes), velocity, line")
    time.add_argument("--every", metavar="SECONDS", type=_seconds,
                      help="the trajectory's sample spacing (default: the servo period)")
    time.add_argument("--max-rows", metavar="N", type=_positive, default=None,
                      help="the most rows the trajectory may have: a program that would make "
                      "more stops with an error and leaves no file (default 10000000)")
    time.add_argument("--top", metavar="N", type=_count, default=10,
                      help="how many of the slowest lines to list (default 10)")
    time.set_defaults(run=run_time)


PROGRAM_HELP = (
    "Programs are read as UTF-8 (a leading byte-order mark is skipped; bytes that are not UTF-8 "
    "are written back as they are, and in JSON as the text \\xNN). On a terminal, a run longer "
    "than about a second shows a progress line on stderr."
)


def _machine_options() -> argparse.ArgumentParser:
    """The machine inputs every command takes (see :mod:`ngc.options`)."""
    parent = argparse.ArgumentParser(add_help=False)
    group = parent.add_argument_group("machine inputs")
    group.add_argument("-i", metavar="INI", dest="ini_file",
                       help="apply the INI file's [RS274NGC] settings (subroutine path, "
                       "Fanuc-style programs, #<_ini[SECTION]NAME> parameters)")
    group.add_argument("-t", metavar="TOOLS", dest="tool_table",
                       help="the tool table, in LinuxCNC's format (T P X Y Z A B C U V W D I J Q "
                       ";comment, inches); default: rs274's sample table (tools 1, 2, 3, 99999)")
    group.add_argument("-v", metavar="VARS", dest="var_file",
                       help="read the parameter file (only ngc rs274 writes it back)")
    group.add_argument("--probe", metavar="FILE", dest="probe_file",
                       help="a simulated probe input for G38.2-G38.5: a TOML file of the solids "
                       "the probe touches (planes, height grids, boxes, cylinders; see README); "
                       "default: rs274's probe, which never trips")
    group.add_argument("--max-iterations", metavar="N", type=_positive,
                       default=DEFAULT_MAX_ITERATIONS,
                       help="the work budget: loop iterations, subroutine calls, cycle passes "
                       "and (engine dialect) segments a run may make before it stops with an "
                       f"error (default {DEFAULT_MAX_ITERATIONS})")
    return parent


def _dialect_options() -> argparse.ArgumentParser:
    """The dialect and the engine dialect's machine input (see :mod:`ngc.dialects`)."""
    parent = argparse.ArgumentParser(add_help=False)
    group = parent.add_argument_group("dialect")
    group.add_argument("--dialect", choices=dialects.DIALECTS, default=None,
                       help="the program's dialect: linuxcnc (LinuxCNC's rs274, the default) or "
                       "engine (seed 003's codes by name and engine segments); without it, a "
                       "program whose first line is '(dialect: engine)' or '; dialect: engine' "
                       "is in the engine dialect (ngc check: per file)")
    group.add_argument("--setup", metavar="FILE", dest="setup_file",
                       help="the engine dialect's machine setup sheet (TOML: fixtures, tool "
                       "lengths, the selected tool, maximum speeds); the LinuxCNC dialect's "
                       "machine inputs are -i, -t, -v and --probe")
    return parent


def _positive(text: str) -> int:
    number = parse_positive(text)
    if number is None:
        raise argparse.ArgumentTypeError(f"needs a positive number, not {text!r}")
    return number


def _seconds(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not (value > 0.0 and math.isfinite(value)):
        raise argparse.ArgumentTypeError(f"needs a positive number of seconds, not {text!r}")
    return value


def _count(text: str) -> int:
    if not (text.isascii() and text.isdigit()):
        raise argparse.ArgumentTypeError(f"needs a whole number, 0 or more, not {text!r}")
    return int(text)


def _setup(command: str, options: argparse.Namespace) -> tuple[MachineOptions, Setup]:
    """The machine inputs of the command line, loaded; raises :class:`NgcConfigError`.  What
    rs274 would report about the INI file's settings is printed as a warning."""
    machine = MachineOptions(ini_file=options.ini_file, tool_table=options.tool_table,
                             var_file=options.var_file, max_iterations=options.max_iterations,
                             probe_file=options.probe_file)
    setup = load_setup(machine)
    for message in setup.settings.messages:
        sys.stderr.write(f"ngc {command}: warning: {message}\n")
    return machine, setup


def _open_binary(path: str) -> io.BufferedReader:
    """A program file (``-``: standard input) as bytes.  Raises ``OSError``."""
    if path == "-":
        return open(sys.stdin.fileno(), "rb", closefd=False)
    return open(path, "rb")


class Program(NamedTuple):
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


def _open_marked(path: str, given: str | None) -> Program:
    name = _name(path)
    try:
        handle = _open_binary(path)
    except OSError as exc:
        return Program(name, given or LINUXCNC, None, exc)
    if given is not None:
        return Program(name, given, handle, None)
    try:
        dialect, handle = dialects.of_stream(handle)
    except OSError as exc:
        handle.close()
        return Program(name, LINUXCNC, None, exc)
    return Program(name, dialect, handle, None)


def _name(path: str) -> str:
    """How a program file is named in messages: its bytes as UTF-8 text, like the program's."""
    return STDIN_NAME if path == "-" else os.fsencode(path).decode("utf-8", "surrogateescape")


def _progress(name: str, handle: object, *, output_to_terminal: bool) -> Progress:
    """The progress line of a program file: on stderr, if it is a terminal and stdout is not
    (``ngc canon`` on a terminal shows its output instead)."""
    active = is_terminal(sys.stderr) and not output_to_terminal
    return Progress(sys.stderr, name, descriptor(handle), active=active)


# The LinuxCNC dialect's machine inputs, as options: (attribute, flag).
LINUXCNC_INPUTS = (("ini_file", "-i"), ("tool_table", "-t"), ("var_file", "-v"),
                   ("probe_file", "--probe"))


def _inputs_conflict(options: argparse.Namespace, dialect: str) -> str | None:
    """Why the machine inputs given do not fit a program of ``dialect``, or None."""
    if dialect == ENGINE:
        given = [flag for attribute, flag in LINUXCNC_INPUTS
                 if getattr(options, attribute) is not None]
        if given:
            return dialects.linuxcnc_inputs_refused(given)
    elif options.setup_file is not None:
        return dialects.SETUP_IS_ENGINES
    return None


def _engine_setup(options: argparse.Namespace) -> EngineSetup | None:
    """The engine's setup sheet (``--setup``), read; raises :class:`NgcConfigError`."""
    if options.setup_file is None:
        return None
    from .engine import read_setup

    return read_setup(options.setup_file)


def run_canon(options: argparse.Namespace) -> int:
    """``ngc canon FILE``: interpreter start-up and program, streamed to stdout; or, in the
    engine dialect, the engine's operations."""
    program = _open_marked(options.file, options.dialect)
    try:
        conflict = _inputs_conflict(options, program.dialect)
        if conflict is not None:
            sys.stderr.write(f"ngc canon: {conflict}\n")
            return EXIT_USAGE
        if program.dialect == ENGINE:
            return _canon_engine(options, program)
        return _canon_linuxcnc(options, program)
    finally:
        program.close()


def _canon_engine(options: argparse.Namespace, program: Program) -> int:
    try:
        setup = _engine_setup(options)
    except NgcConfigError as exc:
        sys.stderr.write(f"ngc canon: {exc.message}\n")
        return EXIT_USAGE
    if program.handle is None:
        return _cannot_open("canon", program)
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


def _cannot_open(command: str, program: Program) -> int:
    reason = program.error.strerror if program.error is not None else None
    sys.stderr.write(f"ngc {command}: cannot open {program.name}: {reason}\n")
    return EXIT_USAGE


def _canon_linuxcnc(options: argparse.Namespace, program: Program) -> int:
    try:
        machine, setup = _setup("canon", options)
    except NgcConfigError as exc:
        sys.stderr.write(f"ngc canon: {exc.message}\n")
        return EXIT_USAGE
    if program.handle is None:
        return _cannot_open("canon", program)
    name = program.name
    handle = text_reader(program.handle)
    sink = SINKS[options.format](sys.stdout)
    interp = new_interpreter(sink, machine, setup)
    with handle, _progress(name, handle, output_to_terminal=is_terminal(sys.stdout)) as progress:
        try:
            interp.startup()
            interp.run(progress.lines(handle), file=name, reader=handle)
        except NgcError as exc:
            _flush(sink)
            progress.close()
            sys.stderr.write(exc.render() + "\n")
            return EXIT_PROGRAM_ERROR
    _flush(sink)
    return EXIT_OK


def _flush(sink: Sink) -> None:
    """Write what the sink holds back, then stdout, so that the operations before an error come
    out before the error."""
    sink.flush()
    sys.stdout.flush()


def run_check(options: argparse.Namespace) -> int:
    """``ngc check FILE...``: per file, the error (if any) on stderr and a summary (a paragraph,
    or a JSON object on one line) on stdout.  Nothing is written to disk.

    Each file is in the dialect ``--dialect`` gives, else in the one its first line names; the
    machine inputs of each dialect apply to its files (with ``--dialect``, those of the other
    dialect are a usage error).  Exit 2 if a file or a machine input cannot be read, else 1 if a
    program has an error, else 0.
    """
    from .commands import check as report  # loaded on use: ``ngc rs274`` starts without it

    conflict = None if options.dialect is None else _inputs_conflict(options, options.dialect)
    if conflict is not None:
        sys.stderr.write(f"ngc check: {conflict}\n")
        return EXIT_USAGE
    try:
        machine, setup = _setup("check", options) if options.dialect != ENGINE else (None, None)
        engine_setup = _engine_setup(options)
    except NgcConfigError as exc:
        sys.stderr.write(f"ngc check: {exc.message}\n")
        return EXIT_USAGE

    def quiet(sink: Sink) -> Interpreter:
        assert machine is not None and setup is not None
        return new_interpreter(sink, machine, setup, write_files=False)

    json_lines = options.format == "json"
    code = EXIT_OK
    for i, path in enumerate(options.files):
        if i and not json_lines:
            sys.stdout.write("\n")
        program = _open_marked(path, options.dialect)
        if program.handle is None:
            assert program.error is not None
            _cannot_open("check", program)
            if json_lines:
                sys.stdout.write(dumps(_unreadable(program.name, program.error)) + "\n")
            code = EXIT_USAGE
            continue
        if program.dialect == ENGINE:
            error, paragraph = _check_engine(program, engine_setup, json_lines,
                                             options.max_iterations)
        else:
            handle = text_reader(program.handle)
            with handle, _progress(program.name, handle, output_to_terminal=False) as progress:
                result = report.check_lines(progress.lines(handle), program.name, quiet,
                                            reader=handle)
            error = result.error
            paragraph = dumps(report.record(result)) if json_lines else report.render(result)
        if error is not None:
            sys.stderr.write(error.render() + "\n")
            if code == EXIT_OK:
                code = EXIT_PROGRAM_ERROR
        sys.stdout.write(paragraph + "\n")
        sys.stdout.flush()
    return code


def _check_engine(program: Program, setup: EngineSetup | None, json_lines: bool,
                  max_iterations: int) -> tuple[NgcError | None, str]:
    """``ngc check`` on an engine-dialect program: its first error and its report."""
    from .commands import check_engine as engine_report

    assert program.handle is not None
    with program.handle:
        text = dialects.read_text(program.handle)
    result = engine_report.check_text(text, program.name, setup, max_iterations)
    return result.error, (dumps(engine_report.record(result)) if json_lines
                          else engine_report.render(result))


def _unreadable(name: str, exc: OSError) -> dict[str, object]:
    """``ngc check --format json``'s object for a file that cannot be opened."""
    error = {"message": f"cannot open: {exc.strerror}", "file": name, "line": None,
             "column": None, "source": None}
    return {"file": name, "ok": False, "lines": None, "error": error, "summary": None}


NOT_LINUXCNC = "ngc time runs LinuxCNC programs; {name} is in the engine dialect"


def run_plot(options: argparse.Namespace) -> int:
    """``ngc plot FILE -o OUT``: the toolpath drawn to OUT (.svg or .png).  Exit 2 for a bad
    command line or machine input, a file that cannot be read or written, ``--time`` with an
    engine-dialect program or a missing PNG renderer; 1 when the program stopped on an error
    (the picture is written all the same, the error also on stderr)."""
    from .commands import plot

    try:
        plot.output_format(options.output)
    except ValueError as exc:
        sys.stderr.write(f"ngc plot: {exc}\n")
        return EXIT_USAGE
    program = _open_marked(options.file, options.dialect)
    try:
        conflict = _inputs_conflict(options, program.dialect)
        if conflict is not None:
            sys.stderr.write(f"ngc plot: {conflict}\n")
            return EXIT_USAGE
        if program.dialect == ENGINE:
            return _plot_engine(options, program)
        try:
            inputs, setup = _setup("plot", options)
            machine = None
            if options.time:
                from .planner.config import load_machine

                machine = load_machine(setup.ini, options.machine_file)
        except NgcConfigError as exc:
            sys.stderr.write(f"ngc plot: {exc.message}\n")
            return EXIT_USAGE
        if program.handle is None:
            return _cannot_open("plot", program)
        view = (plot.auto_view_of_file(options.file) if options.view == "auto"
                else options.view)
        how = _plot_options(options, view)
        handle = text_reader(program.handle)
        try:
            with handle, _progress(program.name, handle, output_to_terminal=False) as progress:
                result = plot.draw(progress.lines(handle), program.name, options.output,
                                   lambda sink: new_interpreter(sink, inputs, setup,
                                                                write_files=False),
                                   how, reader=handle, machine=machine)
        except NgcConfigError as exc:
            sys.stderr.write(f"ngc plot: {exc.message}\n")
            return EXIT_USAGE
        except OSError as exc:
            sys.stderr.write(f"ngc plot: cannot write {_name(options.output)}: "
                             f"{exc.strerror}\n")
            return EXIT_USAGE
    finally:
        program.close()
    if result.error is not None:
        sys.stderr.write(result.error.render() + "\n")
        return EXIT_PROGRAM_ERROR
    return EXIT_OK


def _plot_options(options: argparse.Namespace, view: str) -> PlotOptions:
    from .commands.plot import PlotOptions

    return PlotOptions(view=view, color=options.color, width=options.size[0],
                       height=options.size[1], dpi=options.dpi, approach=options.approach)


def _plot_engine(options: argparse.Namespace, program: Program) -> int:
    """An engine-dialect program drawn from its segments (``--time`` is ngc time's: refused)."""
    from .commands import plot

    if options.time:
        sys.stderr.write(f"ngc plot: --time needs a LinuxCNC program; {program.name} is in the "
                         "engine dialect (ngc check prints its time)\n")
        return EXIT_USAGE
    try:
        setup = _engine_setup(options)
    except NgcConfigError as exc:
        sys.stderr.write(f"ngc plot: {exc.message}\n")
        return EXIT_USAGE
    if program.handle is None:
        return _cannot_open("plot", program)
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
        sys.stderr.write(f"ngc plot: cannot write {_name(options.output)}: {exc.strerror}\n")
        return EXIT_USAGE
    if result.error is not None:
        sys.stderr.write(result.error.render() + "\n")
        return EXIT_PROGRAM_ERROR
    return EXIT_OK


def run_time(options: argparse.Namespace) -> int:
    """``ngc time FILE``: the program's cycle time on the machine, as a paragraph or a JSON
    object on stdout, and with ``--trajectory`` the sampled motion in a CSV file.  Exit 2 for a
    bad machine input, a file that cannot be read or written, or an engine-dialect program; 1
    for a program error (nothing is printed on stdout then)."""
    for name, value in (("--every", options.every), ("--max-rows", options.max_rows)):
        if value is not None and options.trajectory is None:
            sys.stderr.write(f"ngc time: {name} needs --trajectory\n")
            return EXIT_USAGE
    program = _open_marked(options.file, options.dialect)
    try:
        if program.dialect == ENGINE:
            sys.stderr.write(f"ngc time: {NOT_LINUXCNC.format(name=program.name)}\n")
            return EXIT_USAGE
        return _time_linuxcnc(options, program)
    finally:
        program.close()


def _time_linuxcnc(options: argparse.Namespace, program: Program) -> int:
    from .commands import time_report  # loaded on use, as the planner is
    from .planner.config import load_machine
    from .planner.trajectory import TooManyRows

    try:
        inputs, setup = _setup("time", options)
        machine = load_machine(setup.ini, options.machine_file)
    except NgcConfigError as exc:
        sys.stderr.write(f"ngc time: {exc.message}\n")
        return EXIT_USAGE
    if program.handle is None:
        return _cannot_open("time", program)
    try:
        csv = None if options.trajectory is None else time_report.TrajectoryFile(options.trajectory)
    except OSError as exc:
        sys.stderr.write(f"ngc time: cannot write {_name(options.trajectory)}: {exc.strerror}\n")
        return EXIT_USAGE
    try:
        result = _time_program(options, program, machine,
                               lambda sink: new_interpreter(sink, inputs, setup, write_files=False),
                               csv)
        _print_time(options, program.name, result, machine)
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


def _time_program(options: argparse.Namespace, program: Program, machine: PlannerMachine,
                  interpreter: Callable[[Sink], Interpreter],
                  csv: TrajectoryFile | None) -> TimeResult:
    """Run the program through the planner, with the progress line; the trajectory, if asked
    for, is written to ``csv`` (not committed).  Raises :class:`NgcError` on a program error."""
    from .planner.timing import time_lines

    writer = None
    if csv is not None:
        from .planner.trajectory import (  # loaded only for --trajectory
            DEFAULT_MAX_ROWS,
            TrajectoryWriter,
        )

        every = machine.servo_period if options.every is None else options.every
        writer = TrajectoryWriter(csv, machine, every, options.max_rows or DEFAULT_MAX_ROWS)
    assert program.handle is not None
    handle = text_reader(program.handle)
    with handle, _progress(program.name, handle, output_to_terminal=False) as progress:
        result = time_lines(progress.lines(handle), machine, interpreter, file=program.name,
                            reader=handle, on_segment=None if writer is None else writer.segment,
                            on_wait=None if writer is None else writer.wait)
    if writer is not None:
        writer.finish(result.total_s)
    return result


def _print_time(options: argparse.Namespace, name: str, result: TimeResult,
                machine: PlannerMachine) -> None:
    """``ngc time``'s report on stdout, with the text of the slowest lines if it is at hand."""
    from .commands import time_report

    rows = time_report.slowest(result, options.top)
    sources = time_report.source_lines(options.file, (line for line, _ in rows))
    if options.format == "json":
        time_report.write_json(sys.stdout, name, result, machine, options.top, sources)
    else:
        report = time_report.render(name, result, machine, options.top, sources)
        sys.stdout.write(report + "\n")
