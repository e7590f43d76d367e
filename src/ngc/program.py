"""``ngc.Program``: the library's front door.  Load a program once, with the machine inputs the
command line takes, then ask it things: ``check()``, ``moves()``, ``time()``, ``plot()``; in
Jupyter it shows as its drawing.

>>> import ngc
>>> p = ngc.Program.load("G21 G0 X10 Y5\\nG1 Z-1 F100\\nG2 X20 Y5 I5 J0\\nM2\\n")
>>> [(m.line, m.kind, m.end[:3]) for m in p.moves()]
[(1, 'rapid', (10.0, 5.0, 0.0)), (2, 'feed', (10.0, 5.0, -1.0)), (3, 'arc', (20.0, 5.0, -1.0))]
>>> p.check().ok
True
"""

from __future__ import annotations

import os
import tempfile
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

from . import dialects
from .canon.ops import Sink
from .interp.interpreter import Interpreter
from .interp.source import open_text_program
from .options import MachineOptions, Setup, load_setup, new_interpreter
from .toolpath.moves import Event, Move, MoveList

if TYPE_CHECKING:
    from .commands.check import CheckResult
    from .flatten import Flattened
    from .planner.machine import Machine
    from .planner.timing import TimeResult


@dataclass(frozen=True)
class Program:
    """A program and the machine it runs on (see :meth:`load`)."""

    name: str
    text: str | None  # the program's text, or None: read from ``path`` each run
    path: str | None
    options: MachineOptions
    dialect: str

    @classmethod
    def load(cls, source: str | os.PathLike[str], *, tools: str | None = None,
             ini: str | None = None, vars: str | None = None, probe: str | None = None,
             dialect: str | None = None, max_iterations: int | None = None) -> Program:
        """A program from a file (a path, or a string naming a file that exists and holding no
        line break) or from its text (any other string).  ``tools``, ``ini``, ``vars`` and
        ``probe`` are the files of ``-t``, ``-i``, ``-v`` and ``--probe``; ``dialect`` is
        ``"linuxcnc"`` or ``"engine"`` (None: the one the program's first line names).  The
        inputs are checked now (:class:`~ngc.errors.NgcConfigError` names a bad one); the
        program runs when asked something."""
        is_file = isinstance(source, os.PathLike) or (
            "\n" not in source and "\r" not in source and os.path.isfile(source))
        options = MachineOptions(ini_file=ini, tool_table=tools, var_file=vars,
                                 probe_file=probe,
                                 program_file=os.fspath(source) if is_file else None)
        if max_iterations is not None:
            options = options._replace(max_iterations=max_iterations)
        load_setup(options)
        if is_file:
            path = os.fspath(source)
            found = dialects.checked(dialect) or dialects.of_file(path)
            return cls(path, None, path, options, found)
        text = str(source)
        return cls("<text>", text, None, options, dialects.of_text(text, dialect))

    # -- running ----------------------------------------------------------------------------------
    def _setup(self) -> Setup:
        return load_setup(self.options)

    def run(self, sink: Sink) -> None:
        """Run the program into a canon ``sink`` (``ngc canon``'s: ``TextSink(sys.stdout)``,
        ``JsonSink``, ``ListSink``, or a toolpath reader's ``toolpath``); raises
        :class:`NgcError` where it stops.  The sink is not flushed."""
        if self.dialect != dialects.LINUXCNC:
            dialects.interpret_engine(self._source_text(), sink, file=self.name,
                                      max_iterations=self.options.max_iterations)
            return
        setup = self._setup()
        interp = new_interpreter(sink, self.options, setup, write_files=False)
        interp.startup()
        if self.text is not None:
            interp.run(self.text.splitlines(), file=self.name)
            return
        assert self.path is not None
        with open_text_program(self.path) as reader:
            interp.run(reader, file=self.name, reader=reader)

    def _linuxcnc_only(self) -> None:
        if self.dialect != dialects.LINUXCNC:
            raise ValueError(f"{self.name} is in the engine dialect: time() takes LinuxCNC "
                             "programs (check() gives an engine program's time)")

    def _interpreter(self, sink: Sink) -> Interpreter:
        return new_interpreter(sink, self.options, self._setup(), write_files=False)

    # -- what it does -----------------------------------------------------------------------------
    def check(self) -> CheckResult:
        """Run it and sum up its motion: :class:`~ngc.commands.check.CheckResult` (``ok``, ``error``,
        ``summary``), as ``ngc check``; an engine program gives an ``EngineCheckResult``."""
        from .commands.check import check_lines

        if self.dialect != dialects.LINUXCNC:
            from .commands.check_engine import check_text

            return check_text(self._source_text(), self.name,  # type: ignore[return-value]
                              max_iterations=self.options.max_iterations)
        if self.text is not None:
            return check_lines(self.text.splitlines(), self.name, self._interpreter)
        assert self.path is not None
        with open_text_program(self.path) as reader:
            return check_lines(reader, self.name, self._interpreter, reader=reader)

    def summary(self) -> object:
        """What ``ngc check`` sums up: :class:`~ngc.commands.check.Summary` (counts, lengths,
        extents), or an engine program's ``EngineSummary``."""
        return self.check().summary

    def _source_text(self) -> str:
        if self.text is not None:
            return self.text
        assert self.path is not None
        with open_text_program(self.path) as reader:
            return "".join(reader)

    def moves(self, *, events: bool = False) -> list[Move | Event]:
        """The toolpath: a :class:`~ngc.toolpath.moves.Move` for each move, in machine
        coordinates (mm) and program ones, with its file, line, tool and feed; with ``events``,
        the dwells, tool changes, stops and the end as :class:`~ngc.toolpath.moves.Event`\\ s
        too.  Raises :class:`NgcError` where the program stops on an error (:meth:`walk`
        hands the moves on before it)."""
        out: list[Move | Event] = []
        self.walk(out.append if events else _moves_only(out))
        return out

    def walk(self, on_move: Callable[[Move | Event], object]) -> None:
        """Hand each move and event to ``on_move`` as the program runs (memory flat in the
        program's length); raises :class:`NgcError` where the program stops."""
        reader = MoveList(on_move, file=self.name)
        self.run(reader.toolpath)

    def time(self, machine: Machine | None = None) -> TimeResult:
        """The cycle time on ``machine`` (:class:`ngc.planner.machine.Machine`, e.g. from
        :func:`ngc.planner.config.load_machine`; None: the default, or the INI file's), as
        ``ngc time``: ``total_s``, ``by_kind``, ``by_tool``, ``by_line``."""
        from .planner.config import load_machine
        from .planner.timing import Timer

        self._linuxcnc_only()
        if machine is None:
            machine = load_machine(self._setup().ini, None)
        timer = Timer(machine)
        self.run(timer.sink)
        return timer.finish()

    def plot(self, output: str | None = None, *, view: str = "auto", color: str = "kind",
             size: tuple[int, int] = (1200, 900)) -> str:
        """Draw the toolpath (see ``ngc plot``) to ``output`` (``.svg`` or ``.png``) and return
        its path; with no ``output``, return the SVG text.  ``view``: ``top``, ``front``,
        ``side``, ``iso``, ``lathe`` or ``auto`` (lathe for a program with G7 or G8, else top).
        A program that stops on an error is drawn up to it, the error written on the drawing."""
        from .commands.plot import PlotOptions, auto_view, auto_view_of_file

        if view == "auto":
            view = (auto_view(self.text.encode("utf-8", "surrogateescape"))
                    if self.text is not None else auto_view_of_file(str(self.path)))
        how = PlotOptions(view=view, color=color, width=size[0], height=size[1])
        if output is not None:
            self._draw(output, how)
            return output
        with tempfile.TemporaryDirectory(prefix="ngc-plot-") as tmp:
            path = os.path.join(tmp, "plot.svg")
            self._draw(path, how)
            with open(path, encoding="utf-8") as handle:
                return handle.read()

    def flatten(self, target: str = "linuxcnc", *, inch: bool = False,
                decimals: int | None = None, source_lines: bool = False,
                verify: bool = True, tolerance: float = 0.002,
                toolchange: str | None = None, fold_lengths: bool = False) -> Flattened:
        """The program written plain for ``target`` (see ``ngc flatten``): ``text``, ``lines``
        and ``verified`` (the written program run again and its machine path compared with
        this one's, within ``tolerance`` mm, which is also how close lines written for a curve
        stay to it); ``toolchange``: ``pause``, ``strip`` or ``keep``; ``fold_lengths``: tool
        lengths in the coordinates rather than the target's offset.  Raises
        :class:`~ngc.flatten.Refused` with the line and the reason for a
        program that cannot be written truthfully, :class:`ValueError` for a target not written
        yet, :class:`NgcError` for a program error."""
        from .flatten import flatten

        if self.dialect != dialects.LINUXCNC:
            raise ValueError(f"{self.name} is in the engine dialect: flatten() takes LinuxCNC "
                             "programs")
        return flatten(self._source_text(), self.name, self._interpreter, target=target,
                       inch=inch, decimals=decimals, source_lines=source_lines, verify=verify,
                       tolerance=tolerance, toolchange=toolchange, fold_lengths=fold_lengths)

    def _draw(self, output: str, how: object) -> None:
        from .commands.plot import PlotOptions, draw, draw_engine

        assert isinstance(how, PlotOptions)
        if self.dialect != dialects.LINUXCNC:
            draw_engine(self._source_text(), self.name, output, how,
                        max_iterations=self.options.max_iterations)
            return
        if self.text is not None:
            draw(self.text.splitlines(), self.name, output, self._interpreter, how)
            return
        assert self.path is not None
        with open_text_program(self.path) as reader:
            draw(reader, self.name, output, self._interpreter, how, reader=reader)

    def _repr_svg_(self) -> str:
        """Jupyter shows a program as its drawing."""
        return self.plot(size=(800, 600))


def _moves_only(out: list[Move | Event]) -> Callable[[Move | Event], None]:
    def keep(record: Move | Event) -> None:
        if isinstance(record, Move):
            out.append(record)
    return keep


__all__ = ["Program"]
