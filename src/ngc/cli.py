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
:func:`ngc.rs274.run` untouched.
"""

from __future__ import annotations

import argparse
import io
import os
import sys
from collections.abc import Callable, Iterator
from typing import TextIO

from . import __version__, rs274
from .canon.jsonl import JsonSink
from .canon.ops import Sink
from .canon.text import TextSink
from .errors import NgcError
from .interp.interpreter import Interpreter
from .termination import Terminated, signals_raise

EXIT_OK = 0
EXIT_PROGRAM_ERROR = 1
EXIT_USAGE = 2
EXIT_INTERNAL = 70  # EX_SOFTWARE (sysexits.h)
EXIT_INTERRUPTED = 130  # 128 + SIGINT, what shells report for Ctrl-C
EXIT_BROKEN_PIPE = 141  # 128 + SIGPIPE, what a C filter killed by SIGPIPE reports

SINKS: dict[str, Callable[[TextIO], Sink]] = {"text": TextSink, "json": JsonSink}


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``ngc`` console script and ``python -m ngc``; returns the exit code.

    The guard of last resort: an :class:`NgcError` that escapes a subcommand is reported like any
    program error, anything else as an internal error, Ctrl-C quietly, a closed pipe
    (``ngc canon big.ngc | head``) quietly too.
    """
    args = sys.argv[1:] if argv is None else argv
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
    _pass_bytes_through()
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


def _pass_bytes_through() -> None:
    """Programs are read as UTF-8 with undecodable bytes kept as surrogates; write those bytes
    back as they were instead of failing (a UTF-8 locale's stdout is strict)."""
    for stream in (sys.stdout, sys.stderr):
        if isinstance(stream, io.TextIOWrapper):
            stream.reconfigure(errors="surrogateescape")


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="ngc", description="A pure-Python RS274/NGC (LinuxCNC dialect) G-code interpreter."
    )
    parser.add_argument("--version", action="version", version=f"ngc {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    sub.add_parser(
        "rs274",
        help="drop-in for LinuxCNC's standalone rs274 (batch mode)",
        usage="ngc rs274 [-t TBL] [-v VAR] [-i INI] [-n 0|1|2] [-b] [-s] [-g] FILE",
        add_help=False,
    )
    canon = sub.add_parser("canon", help="print the canonical machine operations of a program")
    canon.add_argument("file", metavar="FILE")
    canon.add_argument(
        "--format",
        choices=sorted(SINKS),
        default="text",
        help="text: rs274's transcript format (default); json: JSON lines",
    )
    canon.set_defaults(run=run_canon)
    check = sub.add_parser("check", help="validate programs and summarize their motion")
    check.add_argument("files", metavar="FILE", nargs="+")
    check.set_defaults(run=run_check)
    return parser


def run_canon(options: argparse.Namespace) -> int:
    """``ngc canon FILE``: interpreter start-up and program, streamed to stdout."""
    path: str = options.file
    try:
        handle = open(path, encoding="utf-8", errors="surrogateescape", newline="")  # noqa: SIM115
    except OSError as exc:
        sys.stderr.write(f"ngc canon: cannot open {path}: {exc.strerror}\n")
        return EXIT_USAGE
    sink = SINKS[options.format](sys.stdout)
    interp = Interpreter(sink)
    with handle:
        try:
            interp.startup()
            interp.run(_lines(handle), file=path)
        except NgcError as exc:
            _flush(sink)
            sys.stderr.write(exc.render() + "\n")
            return EXIT_PROGRAM_ERROR
    _flush(sink)
    return EXIT_OK


def _flush(sink: Sink) -> None:
    """Write what the sink holds back, then stdout, so that the operations before an error come
    out before the error."""
    sink.flush()
    sys.stdout.flush()


def _lines(handle: TextIO) -> Iterator[str]:
    for line in handle:
        yield line.rstrip("\n")


def run_check(options: argparse.Namespace) -> int:
    """``ngc check FILE...``: per file, the error (if any) and a summary paragraph, on stdout.

    Exit 2 if a file cannot be read, else 1 if a program has an error, else 0.
    """
    from . import report  # loaded on use: ``ngc rs274`` starts without it

    code = EXIT_OK
    for i, path in enumerate(options.files):
        if i:
            sys.stdout.write("\n")
        try:
            result = report.check_file(path)
        except OSError as exc:
            sys.stdout.write(f"{path}: cannot open: {exc.strerror}\n")
            code = EXIT_USAGE
            continue
        sys.stdout.write(report.render(result) + "\n")
        if not result.ok and code == EXIT_OK:
            code = EXIT_PROGRAM_ERROR
    return code
