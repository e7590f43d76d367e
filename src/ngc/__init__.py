"""ngc — a pure-Python RS274/NGC (LinuxCNC dialect) G-code interpreter.

>>> from ngc.canon.jsonl import ListSink
>>> sink = ListSink()
>>> interpret("G0 X1\\nM2\\n", sink)
>>> sink.ops[5][0]
StraightTraverse(x=1.0, y=0.0, z=0.0, a=0.0, b=0.0, c=0.0)
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from .canon.ops import Op, Sink
from .errors import NgcError
from .interp.interpreter import Interpreter

if TYPE_CHECKING:
    from .report import CheckResult, Summary, check_file, summarize

__version__ = "0.1.0"

# The report module (paths, dataclasses) loads on first use: ``ngc rs274`` starts without it.
_REPORT_NAMES = frozenset({"CheckResult", "Summary", "check_file", "summarize"})


def __getattr__(name: str) -> Any:
    if name in _REPORT_NAMES:
        from . import report

        return getattr(report, name)
    raise AttributeError(f"module 'ngc' has no attribute {name!r}")


def interpret(text: str, sink: Sink, *, file: str | None = None) -> None:
    """Interpret a whole program given as text, sending canonical operations to ``sink``.

    Raises :class:`NgcError` at the first error.
    """
    interp = Interpreter(sink)
    interp.startup()
    interp.run(text.splitlines(), file=file)


__all__ = [
    "CheckResult",
    "Interpreter",
    "NgcError",
    "Op",
    "Sink",
    "Summary",
    "check_file",
    "interpret",
    "summarize",
]
