"""Comparing an ``ngc rs274`` run with rs274's recorded one, the way the conformance runner does:
stdout without the counter column, stderr lines other than ``executing``."""

from __future__ import annotations

import re

COUNTER = re.compile(r"^ *[0-9]+ ")


def _lines(text: str) -> list[str]:
    """Lines split on newline; a missing newline after the last line counts as present."""
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    return lines


def normalize(text: str) -> str:
    """stdout with the running counter removed from each line."""
    return "".join(COUNTER.sub("", line, count=1) + "\n" for line in _lines(text))


def messages(text: str) -> list[str]:
    """stderr lines, without rs274's ``executing`` banner."""
    return [line for line in _lines(text) if line != "executing"]
