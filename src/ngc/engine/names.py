"""The engine dialect's codes and their readable names, as the seed lists them.

A name is matched case-insensitively, with white space and commas between its words optional and
each parenthesised part optional: ``rapid(move)(to)`` accepts ``rapid``, ``rapidmoveto`` and
``Rapid Move To``; ``or`` separates alternative names of one code.
"""

from __future__ import annotations

import re

# code -> the seed's names for it (parenthesised parts optional)
NAMES: dict[int, tuple[str, ...]] = {
    0: ("rapid(move)(to)",),
    1: ("feed(to)",),
    2: ("circle c(lock)w(ise)", "helical(motion) c(lock)w(ise)"),
    3: ("circle c(ounter)(-)c(lock)w(ise)", "helical(motion) c(ounter)(-)c(lock)w(ise)"),
    4: ("dwell", "pause"),
    15: ("cancel polar(coordinates)(mode)",),
    16: ("set polar(origin)(to)",),
    17: ("(use)X(-)Y(plane)",),
    18: ("(use)Z(-)X(plane)",),
    19: ("(use)Y(-)Z(plane)",),
    20: ("(set)inch(units)",),
    21: ("(set)metric(units)",),
    31: ("probe(ing)(move)(to)",),
    43: ("apply tool(length)(offset)",),
    49: ("cancel tool(length)(offset)",),
    53: ("(select)(default)fixture(0)",),
    54: ("(select)fixture 1",),
    55: ("(select)fixture 2",),
    56: ("(select)fixture 3",),
    57: ("(select)fixture 4",),
    58: ("(select)fixture 5",),
    59: ("(select)fixture 6",),
    61: ("exact(stop)(mode)",),
    64: ("cancel exact(stop)(mode)", "constant(velocity)(mode)", "maintain(motor) momentum(mode)"),
    69: ("cancel(coordinate) rotation",),
    73: ("chip breaking drill",),
    80: ("cancel fixed cycles",),
    81: ("drill",),
    82: ("drill, dwell",),
    83: ("chip clearing drill",),
    85: ("drill, feed out",),
    86: ("drill, dwell, spindle off, out",),
    89: ("drill, dwell, feed out",),
    90: ("(set)abs(olute)(coordinate)(s)(mode)",),
    91: ("(set)inc(remental)(coordinate)(s)(mode)",),
    92: ("preload(coordinate)(s)", "preset(coordinate)(s)"),
    100: ("run",),
    101: ("rotate vector(s)",),
    102: ("set vector",),
    103: ("set polar center",),
    104: ("set polar axis",),
    105: ("set polar zero",),
    107: ("set drill vector",),
    108: ("set vector position",),
}

# "move": a motion in the current motion mode (G0 or G1), as the seed's examples use it
MOVE = -1
# the most words a name has
LONGEST = 6


def _pattern(name: str) -> str:
    out = []
    for part in re.split(r"(\([^)]*\))", name.lower()):
        if part.startswith("("):
            out.append(f"(?:{re.escape(_squeeze(part[1:-1]))})?")
        else:
            out.append(re.escape(_squeeze(part)))
    return "".join(out)


def _squeeze(text: str) -> str:
    return re.sub(r"[\s,]+", "", text)


def _table() -> tuple[re.Pattern[str], dict[str, int]]:
    groups: dict[str, int] = {"move": MOVE}
    alternatives = [r"(?P<move>move)"]
    for code, names in NAMES.items():
        for k, name in enumerate(names):
            group = f"g{code}_{k}"
            groups[group] = code
            alternatives.append(f"(?P<{group}>{_pattern(name)})")
    return re.compile("|".join(alternatives)), groups


_NAMES, _GROUPS = _table()


def code_of(words: str) -> int | None:
    """The code the words name (``MOVE`` for "move"), or None."""
    m = _NAMES.fullmatch(_squeeze(words.lower()))
    if m is None or m.lastgroup is None:
        return None
    return _GROUPS[m.lastgroup]


def split_name(words: list[str]) -> tuple[int, int] | None:
    """The code named by the longest run of leading ``words`` that names one, and how many words
    it took; None if no leading run does."""
    for k in range(min(LONGEST, len(words)), 0, -1):
        code = code_of(" ".join(words[:k]))
        if code is not None:
            return code, k
    return None
