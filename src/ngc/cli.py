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
import importlib
import io
import math
import os
import sys
from collections.abc import Callable
from typing import TYPE_CHECKING

from . import __version__, dialects
from .commands import rs274
from .commands.common import (  # noqa: F401 (the exit-code policy)
    EXIT_OK,
    EXIT_PROGRAM_ERROR,
    EXIT_USAGE,
    default_jobs,
)
from .errors import NgcError
from .interp.flow import DEFAULT_MAX_ITERATIONS
from .options import parse_positive
from .termination import Terminated, signals_raise

EXIT_INTERNAL = 70  # EX_SOFTWARE (sysexits.h)
EXIT_INTERRUPTED = 130  # 128 + SIGINT, what shells report for Ctrl-C
EXIT_BROKEN_PIPE = 141  # 128 + SIGPIPE, what a C filter killed by SIGPIPE reports

if TYPE_CHECKING:
    pass



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
    # (each command's module is loaded when it runs: ``ngc rs274`` starts without the others)
    module = importlib.import_module(f".commands.{RUNNERS[options.command]}", __package__)
    command: Callable[[argparse.Namespace], int] = module.run
    return command(options)


def _write_bytes_as_read() -> None:
    """Programs are read as UTF-8 with undecodable bytes kept as surrogates, file names are
    bytes: write both back as the bytes they were, in UTF-8 whatever the locale's encoding (a
    text that came in as bytes goes out as the same bytes; everything ngc adds is ASCII)."""
    for stream in (sys.stdout, sys.stderr):
        if isinstance(stream, io.TextIOWrapper):
            stream.reconfigure(encoding="utf-8", errors="surrogateescape")


# the module that runs each command (``ngc.commands``), by its name
RUNNERS = {"canon": "canon", "check": "check_run", "time": "time_run", "plot": "plot_run",
           "view": "view_run", "flatten": "flatten_run"}


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
        choices=("json", "text"),
        default="text",
        help="text: rs274's transcript format (default); json: JSON lines",
    )
    check = sub.add_parser(
        "check", parents=[_machine_options(), _dialect_options(dialects.CHECK_DIALECTS)],
        help="validate programs and summarize their motion",
        description="Run programs through the interpreter, writing nothing to disk: per file, "
        "the first error (on stderr) and a summary of the motion (on stdout). Each file is in "
        "the dialect --dialect gives, else in the one its first line names. With --dialect "
        "grbl (or grblhal): every line Grbl 1.1 (grblHAL) would reject, as its check mode ($C) "
        "answers it "
        "(file:line: error:N message (line), on stderr), and a summary line per file.",
        epilog=PROGRAM_HELP,
    )
    check.add_argument("files", metavar="FILE", nargs="+", help="programs (- for standard input)")
    check.add_argument("--machine", metavar="TOML", dest="machine_file",
                       help="ngc's TOML machine file, over -i's machine: its axes' travel is "
                       "held against the moves (docs/machine.md)")
    _add_jobs(check)
    check.add_argument(
        "--format",
        choices=("json", "text"),
        default="text",
        help="text: a paragraph per file (default); json: one JSON object per file and line",
    )
    _add_time(sub, [_machine_options()])
    _add_plot(sub, [_machine_options(), _dialect_options()])
    _add_view(sub, [_machine_options(), _dialect_options()])
    _add_flatten(sub, [_machine_options(), _dialect_options()])
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
                      help="ngc's TOML machine file, over the default machine or -i's: its "
                      "axes' travel is held against the moves, and --time times on it")


VIEW_NAMES = ("top", "front", "side", "iso", "lathe")
FLATTEN_TARGETS = ("linuxcnc", "grbl", "grblhal", "fluidnc")  # (ngc.flatten.TARGETS, unloaded)


def _add_flatten(sub: argparse._SubParsersAction[argparse.ArgumentParser],
                 parents: list[argparse.ArgumentParser]) -> None:
    flat = sub.add_parser(
        "flatten", parents=parents, help="write the program plain for a simpler controller",
        description="Write the program out plain (no parameters, O-words, cycles or "
        "compensation: G0 G1 G2 G3 in the coordinates of the work offset the operator set, "
        "G43 H where a tool's length is the table's), then run what was written and compare "
        "its machine path with the original's. A program that cannot be written truthfully "
        "(probing, ...) is refused with its line; nothing is written then.",
        epilog=PROGRAM_HELP,
    )
    flat.add_argument("file", metavar="FILE", help="the program (- for standard input)")
    flat.add_argument("-o", "--output", metavar="OUT", default=None,
                      help="write the program to OUT (default, or -: standard output)")
    flat.add_argument("--target", default="linuxcnc", choices=FLATTEN_TARGETS,
                      help="the controller (default linuxcnc)")
    flat.add_argument("--units", choices=("mm", "inch"), default="mm",
                      help="the units the program is written in (default mm)")
    flat.add_argument("--decimals", type=int, default=None,
                      help="decimals of the numbers (default: the target's for the units)")
    flat.add_argument("--tolerance", type=float, default=0.002,
                      help="mm: how close lines written for a curve the target cannot run stay "
                      "to it, and the largest difference of the paths that verifies (default "
                      "0.002)")
    flat.add_argument("--toolchange", choices=("pause", "strip", "keep"), default=None,
                      help="a tool change: pause (M5, a comment naming the tool and its "
                      "diameter, M0), strip (a comment only) or keep (T M6); default keep where "
                      "the target has M6 (linuxcnc), else pause")
    flat.add_argument("--fold-tool-length", action="store_true",
                      help="write tool lengths into the coordinates (no G43 H or G43.1)")
    flat.add_argument("--source-lines", action="store_true",
                      help="a (line N) comment on each line, the line of the program it comes from")
    flat.add_argument("--no-verify", action="store_true",
                      help="do not run what was written to compare the paths")


def _add_view(sub: argparse._SubParsersAction[argparse.ArgumentParser],
              parents: list[argparse.ArgumentParser]) -> None:
    view = sub.add_parser(
        "view", parents=parents, help="the program in 3D in a browser page",
        description="Write one self-contained HTML page (no server, no network when opened): "
        "the toolpath in 3D, the program text beside it (click a segment to find its line), "
        "the machine's time on a slider, the summary, the error where it stopped; and open it "
        "in the default browser.",
        epilog=PROGRAM_HELP,
    )
    view.add_argument("file", metavar="FILE", help="the program (- for standard input)")
    view.add_argument("-o", "--output", metavar="PAGE", default=None,
                      help="write the page to PAGE.html (and do not open it); default: a "
                      "temporary file, opened in the browser")
    view.add_argument("--no-open", action="store_true", help="do not open the browser")
    view.add_argument("--machine", metavar="TOML", dest="machine_file",
                      help="ngc's TOML machine file, over the default machine or -i's: the "
                      "time and the trajectory on it, its travel held against the moves")
    view.add_argument("--watch", action="store_true",
                      help="serve the page on 127.0.0.1 and rebuild it when FILE changes "
                      "(the page reloads itself); Ctrl-C stops")
    view.add_argument("--port", type=int, default=0,
                      help="with --watch: the port (default: a free one, printed)")


def _add_jobs(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-j", "--jobs", metavar="N", type=_positive, default=default_jobs(),
                        help="run N programs at once, on N processes (default: one per core); "
                        "the output comes in the files' order, as with -j 1")


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
    time.add_argument("files", metavar="FILE", nargs="+",
                      help="programs (- for standard input), each timed in turn")
    _add_jobs(time)
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
                       help="the machine's INI file: its [RS274NGC] settings (subroutine path, "
                       "Fanuc-style programs, #<_ini[SECTION]NAME> parameters), its units "
                       "([TRAJ]LINEAR_UNITS: the tool table's and offsets'), PROGRAM_PREFIX "
                       "and SUBROUTINE_PATH from the INI file's folder, its soft limits")
    group.add_argument("-t", metavar="TOOLS", dest="tool_table",
                       help="the tool table, in LinuxCNC's format (T P X Y Z A B C U V W D I J Q "
                       ";comment), in the machine's units (inches without -i); default: rs274's "
                       "sample table (tools 1, 2, 3, 99999)")
    group.add_argument("--any-tool", action="store_true",
                       help="take a tool the table does not have as a tool with no offsets and "
                       "no diameter, with a warning (default: LinuxCNC's error)")
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


def _dialect_options(choices: tuple[str, ...] = dialects.DIALECTS) -> argparse.ArgumentParser:
    """The dialect and the engine dialect's machine input (see :mod:`ngc.dialects`); ``choices``:
    the dialects the command takes (``ngc check`` also takes grbl)."""
    parent = argparse.ArgumentParser(add_help=False)
    group = parent.add_argument_group("dialect")
    grbl = (", or grbl or grblhal (each line held against what Grbl 1.1 or grblHAL accepts: "
            "docs/grbl.md)" if dialects.GRBL in choices else "")
    group.add_argument("--dialect", choices=choices, default=None,
                       help="the program's dialect: linuxcnc (LinuxCNC's rs274, the default) or "
                       f"engine (seed 003's codes by name and engine segments){grbl}; without "
                       "it, a program whose first line is '(dialect: engine)' or '; dialect: "
                       "engine' is in the engine dialect (ngc check: per file)")
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


