"""``ngc rs274``: a drop-in for LinuxCNC's standalone ``rs274`` in batch mode.

Same options (GNU getopt: options may follow the file), same stdout transcript, same stderr
(``executing``, then per error the message and the offending source line), same exit code.
"""

from __future__ import annotations

import getopt
import io
import os
import sys
from dataclasses import dataclass
from typing import TextIO

from .canon import ops
from .canon.text import TextSink
from .config.ini import Ini, Rs274ngcSettings
from .config.varfile import read_var_file, write_var_file
from .errors import NgcConfigError, NgcError, NgcOpenError
from .interp.flow import DEFAULT_MAX_ITERATIONS
from .interp.interpreter import Interpreter

USAGE = (
    "Usage: rs274 [-p interp.so] [-t tool.tbl] [-v var-file.var] [-n 0|1|2]\n"
    "          [-b] [-s] [-g] [input file [output file]]\n"
)


@dataclass
class Rs274Options:
    """The reference's command line, parsed."""

    program: str | None = None
    output: str | None = None
    tool_table: str | None = None
    var_file: str | None = None
    ini_file: str | None = None
    on_error: int = 2  # -n: 0 continue, 1 MDI, 2 stop
    block_delete: bool = False  # -b toggles
    print_stack: bool = False  # -s toggles
    batch: bool = False  # -g toggles
    max_iterations: int = DEFAULT_MAX_ITERATIONS  # --max-iterations (ngc only)


def parse_args(argv: list[str]) -> Rs274Options:
    """Parse rs274's options; raises ``ValueError`` with the usage text on a bad command line."""
    try:
        pairs, rest = getopt.gnu_getopt(argv, "p:t:v:i:n:bsg", ["max-iterations="])
    except getopt.GetoptError as err:
        raise ValueError(f"rs274: {err.msg}\n{USAGE}") from None
    o = Rs274Options()
    for flag, value in pairs:
        if flag == "-t":
            o.tool_table = value
        elif flag == "-v":
            o.var_file = value
        elif flag == "-i":
            o.ini_file = value
        elif flag == "-n":
            if value not in ("0", "1", "2"):
                raise ValueError(USAGE)
            o.on_error = int(value)
        elif flag == "-b":
            o.block_delete = not o.block_delete
        elif flag == "-s":
            o.print_stack = not o.print_stack
        elif flag == "-g":
            o.batch = not o.batch
        elif flag == "--max-iterations":
            if not value.isdigit() or int(value) < 1:
                raise ValueError(f"ngc rs274: --max-iterations needs a positive number\n{USAGE}")
            o.max_iterations = int(value)
        elif flag == "-p":
            raise ValueError("rs274: -p (pluggable interpreters) is not supported\n")
    if len(rest) > 2:
        raise ValueError(USAGE)
    if rest:
        o.program = rest[0]
    if len(rest) > 1:
        o.output = rest[1]
    return o


def run(argv: list[str], stdout: TextIO | None = None, stderr: TextIO | None = None, *,
        fast: bool = True) -> int:
    """Run like ``rs274 argv...``; returns the exit code.

    Without streams, writes to the process's stdout and stderr byte for byte (latin-1), as the
    program text is read.  ``fast=False`` runs every line on the interpreter's general path.
    """
    if stdout is None or stderr is None:
        out = stdout or _byte_stream(sys.stdout)
        err = stderr or _byte_stream(sys.stderr)
        try:
            return _run(argv, out, err, fast)
        finally:
            for stream, given in ((out, stdout), (err, stderr)):
                if given is None:
                    stream.flush()
                    if isinstance(stream, io.TextIOWrapper):
                        stream.detach()
    return _run(argv, stdout, stderr, fast)


def _byte_stream(stream: TextIO) -> TextIO:
    buffer = getattr(stream, "buffer", None)
    if buffer is None:
        return stream
    stream.flush()
    return io.TextIOWrapper(buffer, encoding="latin-1", newline="\n", line_buffering=False)


def _run(argv: list[str], out: TextIO, err: TextIO, fast: bool = True) -> int:
    try:
        o = parse_args(argv)
    except ValueError as exc:
        err.write(str(exc))
        return 1
    if o.program is None:
        err.write("ngc rs274: reading a program from standard input (MDI) is not supported\n")
        return 1
    try:
        # Bytes in, bytes out: rs274 reads a program as bytes (latin-1 maps each byte to one char).
        handle = open(o.program, encoding="latin-1", newline="")  # noqa: SIM115 (closed below)
    except OSError as exc:
        err.write(f"executing\nUnable to open file {o.program}: {exc.strerror}\n")
        return 1
    err.write("executing\n")
    settings, ini = _settings(o, err)
    transcript: TextIO | None = None
    if o.output is not None:
        try:
            transcript = open(o.output, "w", encoding="latin-1", newline="\n")  # noqa: SIM115
        except OSError as exc:
            err.write(f"Unable to open output file {o.output}: {exc.strerror}\n")
            handle.close()
            return 1
    try:
        with handle:
            return _interpret(o, handle, settings, ini, out if transcript is None else transcript,
                              None if transcript is None else out, err, fast)
    finally:
        if transcript is not None:
            transcript.close()


def _interpret(o: Rs274Options, handle: TextIO, settings: Rs274ngcSettings, ini: Ini | None,
               out: TextIO, prints: TextIO | None, err: TextIO, fast: bool) -> int:
    sink = TextSink(out, prints)
    interp = Interpreter(sink, block_delete=o.block_delete, max_iterations=o.max_iterations,
                         fast=fast)
    interp.configure(settings, ini)
    interp.emit(ops.UseLengthUnits("CANON_UNITS_MM"))
    if o.var_file is not None:
        try:
            values = read_var_file(o.var_file)
        except NgcConfigError as exc:
            sink.flush()
            report(err, exc)  # rs274: the message, then an empty line
            return 1
        interp.load_parameters(values, settings.disable_g92_persistence)
        _save(o.var_file, interp, err)
    interp.startup(units=False)
    failed = False
    try:
        interp.run(handle, file=o.program, on_open=lambda: interp.emit(ops.OnReset()))
    except NgcOpenError as exc:
        # rs274 could not open the program: it reports and exits without resetting.
        sink.flush()
        report(err, exc)
        return 1
    except NgcError as exc:
        failed = True
        sink.flush()
        report(err, exc)
    interp.label = "N..... "
    if ini is None:
        interp.emit(ops.OnReset())
    interp.emit(ops.OnReset())
    sink.flush()
    if o.var_file is not None:
        _save(o.var_file, interp, err)
    return 1 if failed else 0


def _settings(o: Rs274Options, err: TextIO) -> tuple[Rs274ngcSettings, Ini | None]:
    """The INI file (``-i``) and its settings; rs274 reports an INI file it cannot read."""
    if o.ini_file is None:
        return Rs274ngcSettings(), None
    try:
        ini = Ini.read(o.ini_file)
    except NgcConfigError as exc:
        err.write(f"{exc.message}\n")
        return Rs274ngcSettings(), None
    settings = Rs274ngcSettings.from_ini(ini, os.getcwd())
    for message in settings.messages:
        err.write(f"{message}\n\n")
    return settings, ini


def _save(path: str, interp: Interpreter, err: TextIO) -> None:
    """Write the parameter file (atomically); rs274 reports a failed link or rename and goes on."""
    for message in write_var_file(path, interp.params.numbered):
        err.write(f"{message}\n")


def report(err: TextIO, exc: NgcError) -> None:
    """rs274's error report: the message, then the source line."""
    err.write(f"{exc.message}\n")
    if exc.source is not None:
        err.write(f"{exc.source}\n")
