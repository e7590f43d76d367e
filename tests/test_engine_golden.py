"""The engine dialect's golden cases (``tests/engine/cases``; ``tests/engine/golden.py`` records
them) and the coverage of codes and names they give."""

from __future__ import annotations

import re
import sys
from pathlib import Path

import pytest

from ngc.engine.names import MOVE, NAMES, code_of, split_name
from ngc.engine.reading import strip, tokens

sys.path.insert(0, str(Path(__file__).with_name("engine")))
import golden

CASES = golden.cases()


@pytest.mark.parametrize("program", CASES, ids=[p.stem for p in CASES])
def test_golden_case(program: Path) -> None:
    out, err = golden.outcome(program)
    assert out == program.with_suffix(".out").read_text()
    assert err == program.with_suffix(".err").read_text()
    # an error case fails at its 4th line or later, never before its subject
    assert bool(err) == program.stem.startswith("error-")
    if err:
        assert re.match(rf"{re.escape(program.name)}:(\d+):", err)


def test_every_case_says_what_it_shows() -> None:
    for program in CASES:
        lines = program.read_text().splitlines()
        assert lines[0] == "(dialect: engine)" and lines[1].startswith("; "), program.name


def _leading_codes() -> list[tuple[int, str, str]]:
    """(code, how it was written, the words) of each line's leading code in the cases."""
    out = []
    for program in CASES:
        for raw in program.read_text().splitlines():
            text = strip(raw)
            m = re.match(r"g\s*(\d+)(?![\d.])", text, re.IGNORECASE)
            if m:
                out.append((int(m.group(1)), "number", m.group(0)))
                continue
            words = tokens(text)
            named = split_name(words) if words else None
            if named is not None:
                out.append((named[0], "name", " ".join(words[: named[1]])))
    return out


def _squeeze(text: str) -> str:
    return re.sub(r"[\s,]+", "", text.lower())


def test_every_code_by_number_and_by_name() -> None:
    used = _leading_codes()
    by_number = {code for code, how, _ in used if how == "number"}
    by_name = {code for code, how, _ in used if how == "name"}
    assert set(NAMES) - by_number == set()
    assert set(NAMES) - by_name == set()
    assert MOVE in by_name


def test_every_name_in_its_short_and_full_forms() -> None:
    written = {(code, _squeeze(words)) for code, how, words in _leading_codes() if how == "name"}
    missing = []
    for code, names in NAMES.items():
        for name in names:
            short = _squeeze(re.sub(r"\([^)]*\)", "", name))
            full = _squeeze(name.replace("(", "").replace(")", ""))
            for form in (short, full):
                assert code_of(form) == code
                if (code, form) not in written:
                    missing.append(f"G{code}: {form}")
    assert missing == []
