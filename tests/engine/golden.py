#!/usr/bin/env python3
"""Golden cases of the engine dialect: run (or record) ``cases/<name>.ngc``.

The engine dialect has no reference implementation to record: each case's ``.out`` (the
operations as ``ngc canon --dialect engine`` prints them) and ``.err`` (the error, rendered, or
nothing) are ngc's own output, read and checked by hand when recorded; the semantics they rest on
are also checked independently of the recording in ``tests/test_engine.py``.  A case with a
``<name>.toml`` beside it runs with that machine setup sheet.  Each case begins with comments
that say what it shows and the seed's sentence it rests on.

Usage: ``golden.py [--check] [NAME ...]`` — record the named cases (all without names), or with
``--check`` report those whose recorded files differ and exit 1.
"""

from __future__ import annotations

import io
import sys
from pathlib import Path

import ngc
from ngc.canon.text import TextSink
from ngc.engine import read_setup
from ngc.errors import NgcError

CASES = Path(__file__).with_name("cases")


def outcome(program: Path) -> tuple[str, str]:
    """(operations as ``ngc canon --dialect engine`` prints them, rendered error or "") of a
    case."""
    sheet = program.with_suffix(".toml")
    setup = read_setup(str(sheet)) if sheet.exists() else None
    out = io.StringIO()
    err = ""
    try:
        ngc.interpret(program.read_text(), TextSink(out), dialect="engine", setup=setup,
                      file=program.name)
    except NgcError as exc:
        err = exc.render() + "\n"
    return out.getvalue(), err


def cases() -> list[Path]:
    return sorted(CASES.glob("*.ngc"))


def main(argv: list[str]) -> int:
    check = "--check" in argv
    names = [a for a in argv if a != "--check"]
    chosen = [p for p in cases() if not names or p.stem in names]
    stale = 0
    for program in chosen:
        out, err = outcome(program)
        for suffix, text in ((".out", out), (".err", err)):
            path = program.with_suffix(suffix)
            if check:
                if not path.exists() or path.read_text() != text:
                    print(f"{program.stem}{suffix} differs")
                    stale += 1
            else:
                path.write_text(text)
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
