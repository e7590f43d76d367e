"""Minimize a program on which rs274 and ngc differ, keeping the way they differ.

"The same way" is the signature ``run.compare`` gives: the shapes (N label and numbers masked,
canonical calls by name) of the first differing stdout line of each side, the first stderr
message of each side and the exit codes.  Delta debugging in three passes, each repeated until
nothing changes: remove chunks of lines (halves, quarters, ... single lines), remove words within
lines, simplify numbers (to integers, then 0 and 1).  A final M2/M30 line of the original stays.

    python tests/fuzz/shrink.py PROG.ngc      # prints the minimized program
"""

from __future__ import annotations

import dataclasses
import multiprocessing
import re
import sys
from collections.abc import Callable, Iterator

import run

# A word: a letter with a number or a bracketed expression or a parameter, or a comment, or an
# assignment #n=value; anything else is one character.
_TOKEN = re.compile(
    r"\([^)]*\)?"  # comment
    r"|;.*"  # end-of-line comment
    r"|#<?[\w]*>?\s*=\s*(?:\[[^\]]*\]+|[^\s\[]+)"  # assignment (rough)
    r"|[A-Za-z]\s*(?:\[(?:[^\[\]]|\[[^\]]*\])*\]|#<\w*>|#\d+|[-+]?[\d.]+)"  # word
    r"|\S"
)
_NUMBER = re.compile(r"(?<![\w#<.])[-+]?(?:\d+\.\d*|\.\d+|\d+)")
CANDIDATE_TIMEOUT_S = 2.0
_END = re.compile(r"^\s*(?:N\d+\s*)?M0*(?:2|30)\s*$", re.IGNORECASE)


class Shrinker:
    """Counts tests; ``still(lines)`` is true while the lines differ with the wanted signature."""

    def __init__(self, cfg: run.Config, signature: tuple[str, ...], budget: int = 600) -> None:
        # Removing lines easily makes an endless loop: candidates get a short timeout.
        self.cfg = dataclasses.replace(cfg, timeout=min(cfg.timeout, CANDIDATE_TIMEOUT_S))
        self.signature = signature
        self.tests = 0
        self.budget = budget

    def still(self, lines: list[str]) -> bool:
        if self.tests >= self.budget:
            return False
        self.tests += 1
        text = "".join(line + "\n" for line in lines)
        ref, ours = run.run_pair(self.cfg, text)
        if ref.same(ours):
            return False
        return run.compare(ref, ours)[1] == self.signature


def remove_lines(lines: list[str], tail: list[str],
                 test: Callable[[list[str]], bool]) -> list[str]:
    """ddmin-style: try dropping chunks of decreasing size from ``lines`` (``tail`` stays)."""
    n = max(len(lines) // 2, 1)
    while n >= 1 and lines:
        i = 0
        changed = False
        while i < len(lines):
            candidate = lines[:i] + lines[i + n:]
            if test(candidate + tail):
                lines = candidate
                changed = True
            else:
                i += n
        if not changed:
            n //= 2
    return lines


def tokens(line: str) -> list[str]:
    return _TOKEN.findall(line)


def join_tokens(toks: list[str]) -> str:
    """Words apart with a space; single characters (a function name, an o-word) kept together."""
    out = ""
    for k, t in enumerate(toks):
        if k and not (len(t) == 1 and len(toks[k - 1]) == 1):
            out += " "
        out += t
    return out


def remove_words(lines: list[str], tail: list[str],
                 test: Callable[[list[str]], bool]) -> list[str]:
    for i in range(len(lines)):
        j = 0
        while True:
            toks = tokens(lines[i])
            if j >= len(toks) or len(toks) < 2:
                break
            candidate_line = join_tokens([t for k, t in enumerate(toks) if k != j])
            candidate = [*lines[:i], candidate_line, *lines[i + 1:]]
            if test(candidate + tail):
                lines = candidate
            else:
                j += 1
    return lines


def simplify_numbers(lines: list[str], tail: list[str],
                     test: Callable[[list[str]], bool]) -> list[str]:
    for i in range(len(lines)):
        if lines[i].lstrip().startswith("("):
            continue
        k = 0
        while True:
            found = list(_NUMBER.finditer(lines[i]))
            if k >= len(found):
                break
            m = found[k]
            text = m.group()
            try:
                value = float(text)
            except ValueError:
                k += 1
                continue
            simpler = []
            if value != int(value) or text != str(int(value)):
                simpler.append(str(int(value)))
                if abs(value) >= 1 and round(value, 1) != value:
                    simpler.append(f"{round(value, 1):g}")
            for s in ("0", "1"):
                if s != text and s not in simpler:
                    simpler.append(s)
            for s in simpler:
                candidate_line = lines[i][:m.start()] + s + lines[i][m.end():]
                candidate = [*lines[:i], candidate_line, *lines[i + 1:]]
                if test(candidate + tail):
                    lines = candidate
                    break
            k += 1
    return lines


def shrink(cfg: run.Config, text: str, signature: tuple[str, ...] | None = None,
           budget: int = 600) -> str:
    """The smallest program found that still differs with ``signature`` (or its own)."""
    lines = text.splitlines()
    if signature is None:
        ref, ours = run.run_pair(cfg, text)
        signature = run.compare(ref, ours)[1]
    s = Shrinker(cfg, signature, budget)
    ends = [i for i, line in enumerate(lines) if _END.match(line)]
    cut = ends[-1] if ends else len(lines)
    lines, tail = lines[:cut], lines[cut:]
    if not s.still(lines + tail):  # flaky or changed: leave it
        return text
    previous: list[str] = []
    while previous != lines and s.tests < s.budget:
        previous = list(lines)
        lines = remove_lines(lines, tail, s.still)
        lines = remove_words(lines, tail, s.still)
        lines = simplify_numbers(lines, tail, s.still)
    return "".join(line + "\n" for line in lines + tail)


_SHRINK_CFG: run.Config | None = None


def _init(cfg: run.Config) -> None:
    global _SHRINK_CFG
    _SHRINK_CFG = cfg


def _one(args: tuple[str, tuple[str, ...]]) -> str:
    assert _SHRINK_CFG is not None
    return shrink(_SHRINK_CFG, args[0], args[1])


def shrink_many(cfg: run.Config, results: list[run.Result],
                workers: int) -> Iterator[tuple[run.Result, str]]:
    """Shrink each result's program (in ``workers`` processes), yielding them in order."""
    jobs = [(r.text, r.signature) for r in results]
    if workers <= 1:
        _init(cfg)
        yield from zip(results, map(_one, jobs), strict=True)
        return
    ctx = multiprocessing.get_context("fork")
    with ctx.Pool(workers, initializer=_init, initargs=(cfg,)) as pool:
        yield from zip(results, pool.imap(_one, jobs), strict=True)


def main(argv: list[str]) -> int:
    if len(argv) != 1:
        print(__doc__.rsplit("\n\n", 1)[-1], file=sys.stderr)
        return 2
    cfg = run.Config(["rs274"], None)
    with open(argv[0], encoding="latin-1", newline="") as f:
        text = f.read()
    print(shrink(cfg, text), end="")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
