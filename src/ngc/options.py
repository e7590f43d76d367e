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
from collections.abc import Callable
from typing import NamedTuple

from .canon.ops import Sink
from .config.ini import Ini, Rs274ngcSettings
from .config.probe import Surfaces, read_probe_file
from .config.tooltable import DEFAULT_TABLE, Tools, ToolTable, read_tool_table
from .config.units import stated_linear_units
from .config.varfile import read_var_file
from .errors import NgcConfigError
from .interp.flow import DEFAULT_MAX_ITERATIONS
from .interp.interpreter import Interpreter
from .interp.parameters import COORD_STRIDE, G28_HOME, G30_HOME, G54_ORIGIN, G92_OFFSET


class MachineOptions(NamedTuple):
    """The machine inputs of a command line: file names as given, ``None`` when not given."""

    ini_file: str | None = None
    tool_table: str | None = None
    var_file: str | None = None
    max_iterations: int = DEFAULT_MAX_ITERATIONS
    probe_file: str | None = None
    program_file: str | None = None  # the program (its folder is searched for subroutine files)
    # --any-tool: a tool the table lacks is taken as one with no offsets, and told to this
    unknown_tool: Callable[[int], None] | None = None


class Setup(NamedTuple):
    """The machine inputs, loaded: the INI file and its settings, the parameter file's values;
    ``units``, the machine's (its tool table's and offsets'), and ``home``, the folder a machine
    takes relative paths from (the INI file's)."""

    settings: Rs274ngcSettings = Rs274ngcSettings()
    ini: Ini | None = None
    parameters: dict[int, float] | None = None
    tools: ToolTable = DEFAULT_TABLE
    probe: Surfaces | None = None
    units: str = "inch"
    home: str | None = None


# The parameters that hold lengths in the machine's units (rs274ngc.adoc, "Offset parameters are
# INI file units"): the G28 and G30 homes, the G92 offset and the nine coordinate systems' origins,
# each X Y Z A B C U V W, of which A B C are angles.
LINEAR_OFFSETS = frozenset(
    start + i for start in (G28_HOME, G30_HOME, G92_OFFSET,
                            *range(G54_ORIGIN, G54_ORIGIN + 9 * COORD_STRIDE, COORD_STRIDE))
    for i in (0, 1, 2, 6, 7, 8))


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
    """Load the INI, tool table and parameter files strictly (``canon``, ``check``, ``time``,
    ``plot``, :class:`ngc.Program`) as the machine the INI describes reads them: the tool table
    and the parameter file's offsets in its units ([TRAJ]LINEAR_UNITS; rs274 alone, ngc without
    ``-i`` and an INI file that does not state them: an inch machine), SUBROUTINE_PATH and
    PROGRAM_PREFIX relative to the INI file's folder.  ``ngc rs274`` reads them as rs274 does
    (:mod:`ngc.commands.rs274`).

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
    ini = home = None
    units = "inch"
    if options.ini_file is not None:
        ini = Ini.read(options.ini_file)
        units = stated_linear_units(ini) or units  # (not stated: as rs274, inch)
        home = os.path.dirname(os.path.abspath(options.ini_file))
    to_inch = 1.0 / 25.4 if units == "mm" else 1.0  # (the interpreter's lengths are in inches)
    parameters = None
    if options.var_file is not None:
        try:
            parameters = read_var_file(options.var_file)
        except NgcConfigError as exc:
            raise NgcConfigError(f"parameter file {options.var_file}: {exc.message}",
                                 file=options.var_file) from None
        if to_inch != 1.0:
            parameters = {n: v * to_inch if n in LINEAR_OFFSETS else v
                          for n, v in parameters.items()}
    tools = DEFAULT_TABLE
    if options.tool_table is not None:
        tools = read_tool_table(options.tool_table, strict=True).scaled(to_inch)
    probe = None if options.probe_file is None else read_probe_file(options.probe_file)
    settings = Rs274ngcSettings.from_ini(ini, os.getcwd() if home is None else home)
    return Setup(settings, ini, parameters, tools, probe, units, home)


def search_path(setup: Setup, program_file: str | None) -> list[str]:
    """Where a machine looks for subroutine files: the INI file's folder (a machine's working
    directory), PROGRAM_PREFIX, SUBROUTINE_PATH, then the program's folder and the working
    directory (each once).

    >>> search_path(Setup(), "parts/a.ngc")
    ['.', 'parts']
    """
    settings = setup.settings
    found: list[str] = []
    for folder in (setup.home or ".", settings.program_prefix_dir, *settings.subroutine_path,
                   None if program_file is None else os.path.dirname(program_file) or ".", "."):
        if folder is not None and folder not in found:
            found.append(folder)
    return found


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
    interp.flow.search_path = search_path(setup, options.program_file)
    interp.machine.state.tools = Tools(setup.tools, options.unknown_tool)
    if setup.parameters is not None:
        interp.load_parameters(setup.parameters, setup.settings.disable_g92_persistence)
    return interp
