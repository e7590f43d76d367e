"""ngc — a pure-Python RS274/NGC (LinuxCNC dialect) G-code interpreter.

It reads a program the way LinuxCNC's standalone ``rs274`` does and describes what the machine
does as a stream of canonical machine operations, sent to a *sink*.

Interpreting:

* :func:`interpret` — run a whole program given as text; flushes the sink at the end.
  ``dialect="engine"`` (or the program's first line ``(dialect: engine)``) runs it in the engine
  dialect (:mod:`ngc.engine`, :mod:`ngc.dialects`) on the machine of ``setup``.
* :class:`Interpreter` — one interpreter with all its state: ``startup()``, then
  ``run(lines, file=...)`` for a program given line by line (any iterable of lines, such as an
  open file); ``configure(settings, ini)`` and ``load_parameters(values)`` apply an INI file's
  settings and a parameter file.  Several interpreters can run in one process.
* :class:`NgcError` — every problem with a program or its inputs: ``message``, ``file``,
  ``line``, ``column``, ``source``; ``render()`` draws the source line with a caret.

Canonical operations and sinks:

* :class:`Op` — each operation is a ``NamedTuple`` from :mod:`ngc.canon.ops` (``StraightFeed``,
  ``ArcFeed``, ...) whose fields are the arguments rs274 prints.
* :class:`Sink` — the protocol a sink follows: ``emit(op, label, line)``, ``print_text(text)``,
  ``flush()``.  Sinks provided: ``ngc.canon.text.TextSink`` (rs274's transcript),
  ``ngc.canon.jsonl.JsonSink`` (strict JSON lines), ``ngc.canon.jsonl.ListSink`` (in memory).

The front door, :class:`Program`: ``Program.load(path_or_text, tools=..., ini=..., vars=...,
probe=..., dialect=...)``, then ``check()``, ``moves()`` (the toolpath in machine coordinates,
:mod:`ngc.toolpath`), ``walk(on_move)`` (the same, streamed), ``time(machine)`` and
``plot(output, view=...)``; in Jupyter a program shows as its drawing.

Timing (``ngc time``): :func:`time_text` (a program's text) and :func:`time_file` (a file, with
the machine inputs) give a :class:`TimeResult` (``total_s``, ``by_kind``, ``by_tool``,
``by_line``) on a machine (:mod:`ngc.planner.machine`; None: the default).

Checking and summing up motion:

* :func:`check_file` — run a program file (writing no file), returning a :class:`CheckResult`:
  the line count, a :class:`Summary` and the first error; for an engine-dialect program an
  :class:`EngineCheckResult` with an :class:`EngineSummary` (segments, time, lengths, extents).
* :func:`summarize` — a :class:`Summary` of a sequence of operations: move counts, rapid and feed
  lengths, extents.

>>> from ngc.canon.jsonl import ListSink
>>> sink = ListSink()
>>> interpret("G0 X1\\nM2\\n", sink)
>>> sink.ops[5][0]
StraightTraverse(x=1.0, y=0.0, z=0.0, a=0.0, b=0.0, c=0.0)

The command line (``ngc rs274``, ``ngc canon``, ``ngc check``) is described in ``README.md``.
"""

from __future__ import annotations

import sys
import types
from typing import TYPE_CHECKING, Any

from .canon.ops import Op, Sink
from .errors import NgcError
from .interp.interpreter import Interpreter

if TYPE_CHECKING:
    from .commands.check import CheckResult, Summary, check_file, summarize
    from .commands.check_engine import EngineCheckResult, EngineSummary
    from .config.probe import Probe
    from .engine import Setup as EngineSetup
    from .planner.timing import TimeResult, time_file, time_text
    from .program import Program

__version__ = "0.1.0"

__all__ = [
    "CheckResult",
    "EngineCheckResult",
    "EngineSummary",
    "Interpreter",
    "NgcError",
    "Op",
    "Program",
    "Sink",
    "Summary",
    "TimeResult",
    "check_file",
    "interpret",
    "summarize",
    "time_file",
    "time_text",
]


def interpret(text: str, sink: Sink, *, dialect: str | None = None,
              setup: EngineSetup | None = None, file: str | None = None,
              probe: Probe | None = None) -> None:
    """Interpret a whole program given as text, sending canonical operations to ``sink``, and
    flush the sink (also when the program stops with an error).

    Raises :class:`NgcError` at the first error; ``file`` is the name errors carry; ``probe`` is
    a simulated probe input for G38.2-G38.5 (:class:`ngc.config.probe.Surfaces`, e.g. from
    ``read_probe_file``; None: rs274's probe, which never trips).

    ``dialect`` is ``"linuxcnc"`` or ``"engine"`` (``ValueError`` for anything else); None: the
    one the program's first line names (``(dialect: engine)``), else ``"linuxcnc"``.  In the
    engine dialect each of the engine's operations (:mod:`ngc.engine`: ``EngineSegment``,
    ``Dwell``, ...) goes to ``sink.emit(op, label, line)`` with ``label`` its name (its JSON
    ``"op"``: ``ENGINE_SEGMENT``, ...), on the machine ``setup`` describes
    (:func:`ngc.engine.read_setup`; None: the default machine).  ``ListSink`` collects them,
    ``TextSink`` and ``JsonSink`` write them as ``ngc canon --dialect engine`` does.  A
    ``setup`` for a LinuxCNC program, or a ``probe`` for an engine one, is a ``ValueError``.

    >>> import io
    >>> from ngc.canon.text import TextSink
    >>> out = io.StringIO()
    >>> interpret("G21 F100\\nG1 X2\\nM2\\n", TextSink(out))
    >>> out.getvalue().splitlines()[7]
    '    8 N..... STRAIGHT_FEED(2.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)'
    >>> out = io.StringIO()
    >>> interpret("F10\\nfeed X2\\n", TextSink(out), dialect="engine")
    >>> "ENGINE_SEGMENT(line=2, motion=feed, duration=0.200000" in out.getvalue()
    True
    """
    from . import dialects

    if dialects.of_text(text, dialect) == dialects.ENGINE:
        if probe is not None:
            raise ValueError(dialects.API_PROBE_IS_LINUXCNCS)
        dialects.interpret_engine(text, sink, setup=setup, file=file)
        return
    if setup is not None:
        raise ValueError(dialects.API_SETUP_IS_ENGINES)
    interp = Interpreter(sink, probe=probe)
    try:
        interp.startup()
        interp.run(text.splitlines(), file=file)
    finally:
        sink.flush()


class _Package(types.ModuleType):
    """The ``ngc`` module, with the report API (paths, dataclasses) loaded on first use, so
    that ``ngc rs274`` starts without it; ``help(ngc)`` lists it with the rest."""

    _LAZY = frozenset({"CheckResult", "Summary", "check_file", "summarize"})
    _LAZY_ENGINE = frozenset({"EngineCheckResult", "EngineSummary"})
    _LAZY_TIME = frozenset({"TimeResult", "time_file", "time_text"})

    def __getattr__(self, name: str) -> Any:
        if name in self._LAZY:
            from .commands import check as report

            return getattr(report, name)
        if name == "Program":
            from .program import Program

            return Program
        if name in self._LAZY_TIME:
            from .planner import timing

            return getattr(timing, name)
        if name in self._LAZY_ENGINE:
            from .commands import check_engine as engine_report

            return getattr(engine_report, name)
        raise AttributeError(f"module 'ngc' has no attribute {name!r}")

    def __dir__(self) -> list[str]:
        return sorted({*super().__dir__(), *self._LAZY, *self._LAZY_ENGINE, *self._LAZY_TIME,
                       "Program"})


sys.modules[__name__].__class__ = _Package
