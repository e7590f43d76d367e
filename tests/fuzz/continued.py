"""The ``continue`` kind: programs run with ``-n 0``, rs274 going on after each error.

A program of another kind (``motion``, ``offsets``, ``mixed``, ``oword``, ``state``) gets one to
four of the ``failing`` kind's mutations, errors in the middle of lines, loops, conditionals and
subroutines, but never loses its end: rs274 meets an end of file again at every read with
``-n 0`` and never stops (ngc reports it once).  A last ``M2`` line stands after the program in
case the mutations broke its own end.  The first line, ``;args: -n 0``, tells run.py the options.
"""

from __future__ import annotations

import random
from collections.abc import Callable

ARGS_MARK = ";args:"


def args_of(text: str) -> list[str]:
    """The options a program asks for in its ``;args:`` lines (none: no line)."""
    return [word for line in text.splitlines() if line.startswith(ARGS_MARK)
            for word in line[len(ARGS_MARK):].split()]


def gen_continue(seed: int, kinds: dict[str, Callable[[int], str]],
                 mutate: Callable[[random.Random, list[str]], None]) -> str:
    rng = random.Random(f"continue-{seed}")
    base = rng.choice(["motion", "offsets", "mixed", "oword", "oword", "oword", "state"])
    lines = kinds[base](rng.randrange(1 << 30)).split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    for _ in range(rng.choice([1, 2, 2, 3, 4])):
        mutate(rng, lines)
    if not lines or lines[-1].strip() != "%":
        lines.append("M2")
    return "".join(line + "\n" for line in [f"{ARGS_MARK} -n 0", *lines])
