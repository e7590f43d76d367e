"""``ngc rs274``: a drop-in for LinuxCNC's standalone ``rs274`` in batch mode.

Same options (GNU getopt: options may follow the file), same stdout transcript, same stderr
(``executing``, then per error the message and the offending source line), same exit code, byte
for byte: the program is read as bytes and its bytes are written back as they are, and so are
file names (``os.fsencode``), whatever the locale.  A UTF-8 byte-order mark is three bytes like
any others: rs274 stops on it with ``Bad character '\\357' used`` and so does ``ngc rs274``
(``ngc canon`` and ``ngc check`` skip it).

Differences, all on purpose: ``-h``/``--help`` prints :data:`HELP` on stdout (rs274 has no such
option), ``--max-iterations N`` bounds the loop iterations and calls of a run, and on a terminal a long run
shows a progress line on stderr (:mod:`ngc.progress`; never when stderr is not a terminal, so
the output stays byte-exact).  ``-n 0`` and ``-n 1`` go on after errors as rs274 does
(:mod:`ngc.commands.recovery`); ``-s`` and interactive mode are parsed but not modelled: ngc always runs
the program in batch mode.
"""

from __future__ import annotations

import getopt
import io
import os
import sys
from collections.abc import Iterable
from typing import TextIO

from ..canon import ops
from ..canon.text import TextSink
from ..config.ini import Ini, Rs274ngcSettings
from ..config.tooltable import DEFAULT_TABLE, read_tool_table
from ..config.varfile import read_var_file, write_var_file
from ..dialects import DIALECTS, ENGINE, SETUP_IS_ENGINES, linuxcnc_inputs_refused, of_file
from ..errors import NgcConfigError, NgcError, NgcOpenError
from ..interp.flow import DEFAULT_MAX_ITERATIONS
from ..interp.interpreter import Interpreter
from ..interp.source import BOM, ProgramReader, open_program
from ..options import MachineOptions, Setup, new_interpreter, parse_positive
from ..progress import Progress, descriptor, is_terminal
from .recovery import Recovery, report

# What rs274 prints after a bad command line (on stderr, exit 1).
USAGE = """\
Usage: rs274 [-p interp.so] [-t tool.tbl] [-v var-file.var] [-n 0|1|2]
          [-b] [-s] [-g] [input file [output file]]

    -p: Specify the pluggable interpreter to use
    -t: Specify the .tbl (tool table) file to use
    -v: Specify the .var (parameter) file to use
    -n: Specify the continue mode:
           0: continue
           1: enter MDI mode
           2: stop (default)
    -b: Toggle the 'block delete' flag (default: OFF)
    -s: Toggle the 'print stack' flag (default: OFF)
    -g: Toggle the 'go (batch mode)' flag (default: OFF)
    -i: specify the INI file (default: no INI file)
    -T: call task_init()
    -l: specify the log_level (default: -1)
"""

HELP = f"""\
Usage: ngc rs274 [-t tool.tbl] [-v var-file.var] [-i file.ini] [-n 0|1|2] [-b] [-s] [-g]
                 [--max-iterations N] [input file [output file]]

A drop-in for LinuxCNC's standalone rs274 interpreter: it runs the input file and prints the
canonical machine operations (the transcript) on stdout, or into the output file; errors go to
stderr, the exit status is 0 or 1; all as rs274 does, byte for byte.

Options (rs274's own; options may also follow the file names):
    -t FILE   the tool table (LinuxCNC's format: T P X Y Z A B C U V W D I J Q ;comment); a
              file that cannot be read is an empty table; without -t, rs274's sample table
              (T1 D0.125 Z0.511, T2 D0.0625 Z0.1, T3 D0.201 Z1.273, T99999 Z0.1; inches)
    -v FILE   the parameter file: read at the start, written back at the start and at the end
    -i FILE   the INI file: its [RS274NGC] settings (SUBROUTINE_PATH, DISABLE_FANUC_STYLE_SUB,
              ...) and the #<_ini[SECTION]NAME> parameters
    -n 0|1|2  what to do after an error: 0 continue with the next line, 1 run MDI commands
              from standard input until 'quit', then ask whether to continue, 2 stop (the
              default)
    -b        toggle the block delete switch (default: off): lines starting with / are skipped
    -s        toggle printing the interpreter's call stack after an error: accepted, no effect
    -g        toggle batch mode (rs274 asks what to do without it): ngc always runs in batch mode
    -p FILE   rs274's pluggable interpreter: not supported (an error)

Options of ngc:
    --max-iterations N
              the work budget of a run: loop iterations, subroutine calls, cycle passes
              and (engine dialect) segments it may make before it stops with an error (a
              runaway program); default {DEFAULT_MAX_ITERATIONS}
    --dialect linuxcnc|engine
              the program's dialect: linuxcnc (rs274's, the default) or engine (seed 003's
              codes by name; prints its operations as ngc canon does, errors as file:line:col);
              without it, a program whose first line is '(dialect: engine)' is in the engine
              dialect
    --setup FILE
              the engine dialect's machine setup sheet (TOML); -t, -v, -i, -b and -n 0|1 are
              the LinuxCNC dialect's
    -h, --help
              print this help and exit

Reading a program from standard input (rs274's MDI mode, no input file) is not supported.
On a terminal, a run longer than about a second shows a progress line on stderr.
"""

# What rs274 (glibc's getopt) says where Python's getopt says "option -x <words>": by (dashes,
# words).  rs274 has no long options: to it, ``--foo`` starts with the unknown option ``-``.
GETOPT_MESSAGES = {
    ("-", "not recognized"): "invalid option -- '{0}'",
    ("--", "not recognized"): "invalid option -- '-'",
    ("-", "requires argument"): "option requires an argument -- '{0}'",
    ("--", "requires argument"): "option '--{0}' requires an argument",
    ("--", "must not have an argument"): "option '--{0}' doesn't allow an argument",
    ("--", "not a unique prefix"): "option '--{0}' is ambiguous",
}


class Rs274Options:
    """The reference's command line, parsed (the parser sets what it reads)."""

    __slots__ = ("batch", "block_delete", "dialect", "help", "ini_file", "max_iterations",
                 "on_error", "output", "print_stack", "program", "setup_file", "tool_table",
                 "var_file")

    def __init__(self) -> None:
        self.program: str | None = None
        self.output: str | None = None
        self.tool_table: str | None = None
        self.var_file: str | None = None
        self.ini_file: str | None = None
        self.on_error = 2  # -n: 0 continue, 1 MDI, 2 stop
        self.block_delete = False  # -b toggles
        self.print_stack = False  # -s toggles
        self.batch = False  # -g toggles
        self.max_iterations = DEFAULT_MAX_ITERATIONS  # --max-iterations (ngc only)
        self.help = False  # -h, --help (ngc only)
        self.dialect: str | None = None  # --dialect (ngc only); None: the program's marker
        self.setup_file: str | None = None  # --setup (ngc only): the engine's setup sheet

    def machine(self) -> MachineOptions:
        """The machine inputs, as every command takes them."""
        return MachineOptions(ini_file=self.ini_file, tool_table=self.tool_table,
                              var_file=self.var_file, max_iterations=self.max_iterations)


def parse_args(argv: list[str]) -> Rs274Options:
    """Parse rs274's options; raises ``ValueError`` with the text to print on a bad command line."""
    try:
        pairs, rest = getopt.gnu_getopt(argv, "p:t:v:i:n:bsgh",
                                        ["max-iterations=", "help", "dialect=", "setup="])
    except getopt.GetoptError as err:
        raise ValueError(f"rs274: {_getopt_message(err)}\n{USAGE}") from None
    o = Rs274Options()
    for flag, value in pairs:
        _apply(o, flag, value)
    if len(rest) > 2:
        raise ValueError(USAGE)
    if rest:
        o.program = rest[0]
    if len(rest) > 1:
        o.output = rest[1]
    return o


def _apply(o: Rs274Options, flag: str, value: str) -> None:
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
    elif flag in ("-h", "--help"):
        o.help = True
    elif flag == "--max-iterations":
        number = parse_positive(value)
        if number is None:
            raise ValueError(f"ngc rs274: --max-iterations needs a positive number\n{USAGE}")
        o.max_iterations = number
    elif flag == "--dialect":
        if value not in DIALECTS:
            raise ValueError(f"ngc rs274: --dialect must be linuxcnc or engine, not '{value}'\n"
                             f"{USAGE}")
        o.dialect = value
    elif flag == "--setup":
        o.setup_file = value
    elif flag == "-p":
        raise ValueError("rs274: -p (pluggable interpreters) is not supported\n")


def _getopt_message(err: getopt.GetoptError) -> str:
    """glibc's wording for what Python's getopt reports."""
    dashes = "--" if err.msg.startswith("option --") else "-"
    for (kind, words), template in GETOPT_MESSAGES.items():
        if kind == dashes and err.msg.endswith(words):
            return template.format(err.opt)
    return err.msg


def run(argv: list[str], stdout: TextIO | None = None, stderr: TextIO | None = None, *,
        fast: bool = True, stdin: TextIO | None = None) -> int:
    """Run like ``rs274 argv...``; returns the exit code.

    Without streams, writes to the process's stdout and stderr byte for byte (latin-1), as the
    program text is read.  ``fast=False`` runs every line on the interpreter's general path.
    ``stdin`` (default: the process's, as latin-1) is where ``-n 1`` reads MDI lines.
    """
    if stdout is None or stderr is None:
        out = stdout or _byte_stream(sys.stdout)
        err = stderr or _byte_stream(sys.stderr)
        try:
            return _run(argv, out, err, fast, stdin)
        finally:
            for stream, given in ((out, stdout), (err, stderr)):
                if given is None:
                    stream.flush()
                    if isinstance(stream, io.TextIOWrapper):
                        stream.detach()
    return _run(argv, stdout, stderr, fast, stdin)


def _byte_stream(stream: TextIO) -> TextIO:
    """A latin-1 view of ``stream``'s bytes: each character of the program text is one byte.

    Every text written is latin-1 text already (file names through :func:`_as_read`); a
    character beyond U+00FF would be a bug, shown as ``\\uNNNN`` rather than ending the run."""
    buffer = getattr(stream, "buffer", None)
    if buffer is None:
        return stream
    stream.flush()
    return io.TextIOWrapper(buffer, encoding="latin-1", errors="backslashreplace", newline="\n",
                            line_buffering=False)


def _as_read(text: str) -> str:
    """A file name (or a message holding one) as the bytes it stands for, one character per
    byte like the program text: ``€.ngc`` is ``\\xe2\\x82\\xac.ngc``."""
    return os.fsencode(text).decode("latin-1")


def _open_program(path: str) -> ProgramReader:
    """The program file, read as bytes (latin-1 maps each byte to one character) in rs274's
    pieces; a directory reads as an empty file, as it does for rs274.  Raises ``OSError``."""
    try:
        return open_program(path)
    except IsADirectoryError:
        return ProgramReader(io.BytesIO())


def _run(argv: list[str], out: TextIO, err: TextIO, fast: bool = True,
         stdin: TextIO | None = None) -> int:
    try:
        o = parse_args(argv)
    except ValueError as exc:
        err.write(str(exc))
        return 1
    if o.help:
        out.write(HELP)
        return 0
    if o.program is None:
        err.write("ngc rs274: reading a program from standard input (MDI) is not supported\n")
        return 1
    dialect = o.dialect or of_file(o.program)
    conflict = _inputs_conflict(o, dialect)
    if conflict is not None:
        err.write(f"ngc rs274: {conflict}\n")
        return 1
    if dialect == ENGINE:
        return _run_engine(o, out, err)
    err.write("executing\n")
    transcript: TextIO | None = None
    if o.output is not None:
        try:
            transcript = open(o.output, "w", encoding="latin-1", newline="\n")  # noqa: SIM115
        except OSError:
            err.write(f"could not open output file {_as_read(o.output)}\n")
            return 1
    try:
        sink = TextSink(out, None) if transcript is None else TextSink(transcript, out)
        return _interpret(o, sink, err, fast, terminal_output=is_terminal(out), stdin=stdin)
    finally:
        if transcript is not None:
            transcript.close()


def _inputs_conflict(o: Rs274Options, dialect: str) -> str | None:
    """Why the options given do not fit a program of ``dialect``, or None."""
    if dialect == ENGINE:
        given = [flag for flag, value in (("-t", o.tool_table), ("-v", o.var_file),
                                          ("-i", o.ini_file)) if value is not None]
        given += ["-b"] if o.block_delete else []
        given += [f"-n {o.on_error}"] if o.on_error != 2 else []
        if given:
            return linuxcnc_inputs_refused(given)
    elif o.setup_file is not None:
        return SETUP_IS_ENGINES
    return None


def _run_engine(o: Rs274Options, out: TextIO, err: TextIO) -> int:
    """An engine-dialect program: its operations as ``ngc canon --dialect engine`` prints them,
    on stdout or into the output file; an error as ``ngc canon`` reports it (exit 1).  The
    program is read as bytes, one character each (latin-1), and written back as such."""
    from ..dialects import interpret_engine
    from ..engine import read_setup

    try:
        setup = None if o.setup_file is None else read_setup(o.setup_file)
    except NgcConfigError as exc:
        err.write(f"ngc rs274: {_as_read(exc.message)}\n")
        return 1
    name = _as_read(o.program or "")
    try:
        with open(o.program or "", "rb") as handle:
            text = handle.read().removeprefix(BOM).decode("latin-1")
    except OSError as exc:
        err.write(f"ngc rs274: cannot open {name}: {exc.strerror}\n")
        return 1
    err.write("executing\n")
    try:
        target = out if o.output is None else open(  # noqa: SIM115 (closed below)
            o.output, "w", encoding="latin-1", newline="\n")
    except OSError:
        err.write(f"could not open output file {_as_read(o.output or '')}\n")
        return 1
    try:
        interpret_engine(text, TextSink(target), setup=setup, file=name,
                         max_iterations=o.max_iterations)
    except NgcError as exc:
        err.write(exc.render() + "\n")
        return 1
    finally:
        if target is not out:
            target.close()
    return 0


def _interpret(o: Rs274Options, sink: TextSink, err: TextIO, fast: bool,
               terminal_output: bool, stdin: TextIO | None = None) -> int:
    """From the INI file to the final ON_RESET, in rs274's order."""
    settings, ini = _settings(o, err)
    tools = DEFAULT_TABLE
    if o.tool_table is not None:
        tools = read_tool_table(o.tool_table)  # unreadable: an empty table, as rs274 has it
        for line in tools.skipped_report(_as_read(o.tool_table)).splitlines():
            sink.print_text(line)
    interp = new_interpreter(sink, o.machine(), Setup(settings, ini, tools=tools),
                             block_delete=o.block_delete, fast=fast)
    interp.emit(ops.UseLengthUnits("CANON_UNITS_MM"))
    if o.var_file is not None:
        try:
            values = read_var_file(o.var_file)
        except NgcConfigError as exc:
            sink.flush()
            report(err, exc, _as_read(exc.message))  # rs274: the message, then an empty line
            return 1
        interp.load_parameters(values, settings.disable_g92_persistence)
        _save(o.var_file, interp, err)
    interp.startup(units=False)
    name = _as_read(o.program or "")
    try:
        handle = _open_program(o.program or "")
    except OSError:
        sink.flush()
        err.write(f"Unable to open file <{name}>\n\n")
        return 1
    with handle, Progress(err, name, descriptor(handle),
                          active=is_terminal(err) and not terminal_output) as progress:
        failed = _execute(interp, progress.lines(handle), handle, name, sink, err, o.on_error,
                          stdin)
    if failed is None:
        return 1
    interp.label = "N..... "
    if ini is None:
        interp.emit(ops.OnReset())
    interp.emit(ops.OnReset())
    sink.flush()
    if o.var_file is not None:
        _save(o.var_file, interp, err)
    return 1 if failed else 0


def _execute(interp: Interpreter, lines: Iterable[str], reader: ProgramReader, name: str,
             sink: TextSink, err: TextIO, on_error: int = 2,
             stdin: TextIO | None = None) -> bool | None:
    """Run the program: ``False`` if it ran to its end, ``True`` after an error, ``None`` if
    there was nothing to run (rs274 then reports and exits without resetting)."""
    recovery = None
    if on_error != 2:
        interp.recover = recovery = Recovery(interp, sink, err, on_error, stdin)
    try:
        interp.run(lines, file=name, on_open=lambda: interp.emit(ops.OnReset()), reader=reader)
    except NgcOpenError as exc:
        sink.flush()
        report(err, exc)
        return None
    except NgcError as exc:
        sink.flush()
        if recovery is None or recovery.reported is not exc:  # -n 1 declined: reported already
            report(err, exc)
        return True
    return False


def _settings(o: Rs274Options, err: TextIO) -> tuple[Rs274ngcSettings, Ini | None]:
    """The INI file (``-i``) and its settings; rs274 reports an INI file it cannot read."""
    if o.ini_file is None:
        return Rs274ngcSettings(), None
    try:
        ini = Ini.read(o.ini_file)
    except NgcConfigError as exc:
        err.write(f"{_as_read(exc.message)}\n")
        return Rs274ngcSettings(), None
    settings = Rs274ngcSettings.from_ini(ini, os.getcwd())
    for message in settings.messages:
        err.write(f"{_as_read(message)}\n\n")
    return settings, ini


def _save(path: str, interp: Interpreter, err: TextIO) -> None:
    """Write the parameter file (atomically); rs274 reports a failed link or rename and goes on."""
    for message in write_var_file(path, interp.params.numbered):
        err.write(f"{_as_read(message)}\n")
