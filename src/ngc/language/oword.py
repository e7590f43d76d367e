"""O-words: the control-flow line ``o<label> <keyword> [args]`` (o-code.adoc).

An o-word line holds the label (a number, ``<name>`` or ``[expression]``), a keyword and, for some
keywords, bracketed expressions: a condition (``if``, ``elseif``, ``while``), a count
(``repeat``), arguments (``call``) or a return value (``return``, ``endsub``).  Comments may follow;
anything else is an error.  A number label and the same number written as a name are one label
(``o100`` is ``o<100>``).
"""

from __future__ import annotations

from . import expressions as ex

# Keywords, longest first where one is the prefix of another.
KEYWORDS = (
    "endrepeat",
    "endwhile",
    "continue",
    "elseif",
    "endsub",
    "repeat",
    "return",
    "endif",
    "break",
    "while",
    "call",
    "else",
    "sub",
    "do",
    "if",
)
# Keywords followed by one bracketed expression (a missing one is an error).
CONDITION = frozenset({"if", "elseif", "while", "repeat"})
# Keywords followed by an optional bracketed value.
OPTIONAL_VALUE = frozenset({"return", "endsub"})
# The keyword of a Fanuc-style numbered program start: ``o100`` alone on its line.
PROGRAM = ""
# An o-word line that does nothing (``o<name`` without its ``>``).
NOTHING = "nothing"
# Arguments a call may pass (o-code.adoc, "O- Call").
MAX_ARGS = 30


class OWord:
    """One parsed o-word.  ``label`` is the label text when constant, else None (see ``label_of``)."""

    __slots__ = ("args", "keyword", "label", "label_expr")

    def __init__(self, keyword: str, label: str | None, label_expr: ex.Value | None) -> None:
        self.keyword = keyword
        self.label = label
        self.label_expr = label_expr
        self.args: list[ex.Value] = []

    def label_of(self, params: ex.ParamContext) -> str:
        """The label: constant, or computed from the current parameters (``o[#1+2]``)."""
        if self.label is not None:
            return self.label
        assert self.label_expr is not None
        return number_label(ex.evaluate(self.label_expr, params))


def number_label(value: float) -> str:
    """The name of a numbered label: ``o100`` and ``o[99+1]`` are ``o<100>``."""
    from .words import integer_value

    return str(integer_value(value))
