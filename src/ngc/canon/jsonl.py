r"""The JSON-lines sink: one object per canonical operation, for programs that consume ngc.

Every line is strict JSON (RFC 8259) in ASCII, so valid UTF-8 whatever the stream's encoding:

* a number that is not finite (an infinity or NaN) is ``null``: JSON has no such numbers;
* a program is read as UTF-8, with a byte that is not UTF-8 kept as a lone surrogate
  (``surrogateescape``).  In JSON such a byte is the text ``\xNN`` (a backslash, ``x``, two
  lowercase hex digits): the Latin-1 comment ``(café)``, whose ``é`` is the byte E9, is the
  JSON string ``"caf\\xe9"`` (JSON writes a backslash as ``\\``).  Any other lone surrogate
  (only an API caller can make one) is the text ``\uNNNN``.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Mapping
from typing import TextIO

from .ops import Op, op_name

_SURROGATE = re.compile(r"[\ud800-\udfff]")
_ESCAPED_BYTES = range(0xDC80, 0xDD00)  # what surrogateescape makes of the bytes 0x80-0xFF


def _byte_text(match: re.Match[str]) -> str:
    code = ord(match.group())
    return f"\\x{code - 0xDC00:02x}" if code in _ESCAPED_BYTES else f"\\u{code:04x}"


def text_of(value: str) -> str:
    r"""``value`` with every lone surrogate written out as text (see the module docstring).

    >>> text_of(b"caf\xe9 \xe2\x82\xac".decode("utf-8", "surrogateescape"))
    'caf\\xe9 €'
    """
    return _SURROGATE.sub(_byte_text, value)


def _strict(value: object) -> object:
    """``value`` with non-finite numbers as ``None`` and strings through :func:`text_of`."""
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, str):
        return text_of(value)
    if isinstance(value, Mapping):
        return {text_of(str(k)): _strict(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_strict(v) for v in value]
    return value


def dumps(record: Mapping[str, object]) -> str:
    r"""``record`` as one line of strict JSON (no newline); see the module docstring.

    >>> print(dumps({"x": float("inf"), "text": "caf\udce9"}))
    {"x": null, "text": "caf\\xe9"}
    """
    try:
        text = json.dumps(record, allow_nan=False)
    except ValueError:  # an infinity or NaN
        return json.dumps(_strict(record), allow_nan=False)
    if "\\ud" in text:  # maybe a lone surrogate; cleaning is right in any case
        return json.dumps(_strict(record), allow_nan=False)
    return text


class JsonSink:
    """Writes ``{"op": ..., "line": ..., "n": ..., <fields>}`` per operation, one per line
    (strict JSON, see the module docstring); ``(PRINT,...)`` text is ``{"op": "PRINT", "text":
    ...}``.  An engine-dialect operation (:mod:`ngc.engine`) is written as
    ``ngc canon --dialect engine --format json`` writes it (:func:`ngc.engine.output.as_dict`);
    anything else is a ``TypeError``."""

    __slots__ = ("_write",)

    def __init__(self, stream: TextIO) -> None:
        self._write = stream.write

    def emit(self, op: Op, label: str, line: int) -> None:
        try:
            name = op_name(op)
        except KeyError:  # not a canonical operation: an engine-dialect one, or a TypeError
            from ..dialects import engine_record

            self._write(dumps(engine_record(op)) + "\n")
            return
        n = label[1:].strip()
        record: dict[str, object] = {"op": name, "line": line}
        record["n"] = int(n) if n.isdigit() else None
        record.update(op._asdict())
        self._write(dumps(record) + "\n")

    def print_text(self, text: str) -> None:
        self._write(dumps({"op": "PRINT", "text": text}) + "\n")

    def flush(self) -> None:
        """Nothing is held back."""


class ListSink:
    """Collects ``(op, label, line)`` in memory (tests, library users); in the engine dialect
    (``ngc.interpret(..., dialect="engine")``) the ops are the engine's (:mod:`ngc.engine`) and
    the label is the operation's name (``ENGINE_SEGMENT``, ``DWELL``, ...)."""

    __slots__ = ("ops", "printed")

    def __init__(self) -> None:
        self.ops: list[tuple[Op, str, int]] = []
        self.printed: list[str] = []

    def emit(self, op: Op, label: str, line: int) -> None:
        self.ops.append((op, label, line))

    def print_text(self, text: str) -> None:
        self.printed.append(text)

    def flush(self) -> None:
        """Nothing is held back."""
