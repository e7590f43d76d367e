"""The machine inputs every command takes, and the one place a configured interpreter is built.

``ngc rs274``, ``ngc canon`` and ``ngc check`` share four options with one meaning:

``-i INI``
    apply the INI file's [RS274NGC] settings (:meth:`Interpreter.configure`): the subroutine
    path, Fanuc-style programs, ``#<_ini[SECTION]NAME>`` parameters.
``-t TOOLS``
    a tool table in LinuxCNC's format (:mod:`ngc.config.tooltable`), read at the start.  Without
    ``-t`` the table rs274 reads when given none (:data:`DEFAULT_TABLE`: tools 1, 2, 3 and
    99999).  ``rs274`` takes a file it cannot read as an empty table and reports a line it
    cannot read on stdout, as rs274 does; ``canon`` and ``check`` refuse both.
``-v VARS``
    a parameter file (LinuxCNC's ``.var``), loaded with :func:`read_var_file` and
    :meth:`Interpreter.load_parameters`.  Only ``rs274`` writes it back; ``canon`` and ``check``
    read it only.
``--probe FILE``
    a simulated probe input for G38.2-G38.5 (:mod:`ngc.config.probe`: the solids the probe
    touches).  ``canon`` and ``check`` only: ``rs274``'s probe never trips, as rs274's does.
``--max-iterations N``
    the work budget: loop iterations, subroutine calls, cycle passes and (engine dialect)
    segments a run may make before it stops with an error (a runaway program).

``rs274`` reports its inputs the way rs274 does; ``canon`` and ``check`` load them strictly with
:func:`load_setup`: a file given to ``-i``, ``-t`` or ``-v`` must be a regular file they can open
(never a FIFO or a device, which could block), else an :class:`NgcConfigError` (exit 2).
"""

from __future__ import annotations

import os
import stat
from typing import NamedTuple

from .canon.ops import Sink
from .config.ini import Ini, Rs274ngcSettings
from .config.probe import Surfaces, read_probe_file
from .config.tooltable import DEFAULT_TABLE, Tools, ToolTable, read_tool_table
from .config.varfile import read_var_file
from .errors import NgcConfigError
from .interp.flow import DEFAULT_MAX_ITERATIONS
from .interp.interpreter import Interpreter


class MachineOptions(NamedTuple):
    """The machine inputs of a command line: file names as given, ``None`` when not given."""

    ini_file: str | None = None
    tool_table: str | None = None
    var_file: str | None = None
    max_iterations: int = DEFAULT_MAX_ITERATIONS
    probe_file: str | None = None


class Setup(NamedTuple):
    """The machine inputs, loaded: the INI file and its settings, the parameter file's values."""

    settings: Rs274ngcSettings = Rs274ngcSettings()
    ini: Ini | None = None
    parameters: dict[int, float] | None = None
    tools: ToolTable = DEFAULT_TABLE
    probe: Surfaces | None = None


def parse_positive(text: str) -> int | None:
    """A positive decimal number written in ASCII digits, else ``None``.

    >>> parse_positive("100"), parse_positive("0"), parse_positive("-3"), parse_positive("1e3")
    (100, None, None, None)
    """
    if not (text.isascii() and text.isdigit()) or int(text) < 1:
        return None
    return int(text)


def require_regular_file(path: str, what: str) -> None:
    """Raise :class:`NgcConfigError` unless ``path`` is a regular file that can be opened.

    The file is opened without blocking, so a FIFO is refused instead of waiting for a writer.
    """
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK)
    except OSError as exc:
        raise NgcConfigError(f"cannot open {what} {path}: {exc.strerror}", file=path) from None
    try:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            raise NgcConfigError(f"{what} {path} is not a regular file", file=path)
    finally:
        os.close(fd)


def load_setup(options: MachineOptions) -> Setup:
    """Load the INI, tool table and parameter files strictly (``canon``, ``check``).

    Raises :class:`NgcConfigError` with a message naming the file.  What rs274 reports about an
    INI file's settings and carries on from is in ``settings.messages``.
    """
    for path, what in (
        (options.ini_file, "INI file"),
        (options.tool_table, "tool table"),
        (options.var_file, "parameter file"),
        (options.probe_file, "probe file"),
    ):
        if path is not None:
            require_regular_file(path, what)
    ini = None if options.ini_file is None else Ini.read(options.ini_file)
    parameters = None
    if options.var_file is not None:
        try:
            parameters = read_var_file(options.var_file)
        except NgcConfigError as exc:
            raise NgcConfigError(f"parameter file {options.var_file}: {exc.message}",
                                 file=options.var_file) from None
    tools = DEFAULT_TABLE
    if options.tool_table is not None:
        tools = read_tool_table(options.tool_table, strict=True)
    probe = None if options.probe_file is None else read_probe_file(options.probe_file)
    return Setup(Rs274ngcSettings.from_ini(ini, os.getcwd()), ini, parameters, tools, probe)


def new_interpreter(
    sink: Sink,
    options: MachineOptions,
    setup: Setup,
    *,
    block_delete: bool = False,
    fast: bool = True,
    write_files: bool = True,
) -> Interpreter:
    """An interpreter with the options and loaded inputs applied (it has emitted nothing yet)."""
    interp = Interpreter(sink, block_delete=block_delete, max_iterations=options.max_iterations,
                         fast=fast, write_files=write_files, probe=setup.probe)
    interp.configure(setup.settings, setup.ini)
    interp.machine.state.tools = Tools(setup.tools)
    if setup.parameters is not None:
        interp.load_parameters(setup.parameters, setup.settings.disable_g92_persistence)
    return interp
