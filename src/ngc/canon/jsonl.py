"""The JSON-lines sink: one object per canonical operation, for programs that consume ngc."""

from __future__ import annotations

import json
from typing import TextIO

from .ops import Op, op_name


class JsonSink:
    """Writes ``{"op": ..., "line": ..., "n": ..., <fields>}`` per operation, one per line."""

    __slots__ = ("_write",)

    def __init__(self, stream: TextIO) -> None:
        self._write = stream.write

    def emit(self, op: Op, label: str, line: int) -> None:
        n = label[1:].strip()
        record: dict[str, object] = {"op": op_name(op), "line": line}
        record["n"] = int(n) if n.isdigit() else None
        record.update(op._asdict())
        self._write(json.dumps(record) + "\n")

    def print_text(self, text: str) -> None:
        self._write(json.dumps({"op": "PRINT", "text": text}) + "\n")

    def flush(self) -> None:
        """Nothing is held back."""


class ListSink:
    """Collects ``(op, label, line)`` in memory (tests, library users)."""

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
