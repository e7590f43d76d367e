"""The conformance ratchet (DESIGN.md, "Quality bars"): every case listed in
``tests/conformance/passing.txt`` must still pass ``../shared/conformance/run.py`` with
``ngc rs274``.  Skipped when ``../shared`` is not beside the repository.

To grow the list: ``python tests/conformance/update_passing.py`` (adds, never removes).
"""

from __future__ import annotations

import importlib.util
from pathlib import Path
from types import ModuleType

import pytest


def _load_tool() -> ModuleType:
    path = Path(__file__).resolve().parent / "conformance" / "update_passing.py"
    spec = importlib.util.spec_from_file_location("update_passing", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


tool = _load_tool()


def test_listed_conformance_cases_pass() -> None:
    if not tool.runner().is_file():
        pytest.skip(f"no conformance corpus at {tool.runner()}")
    listed = tool.read_passing()
    if not listed:
        pytest.skip("tests/conformance/passing.txt lists no cases")
    results, transcript = tool.run_corpus(listed)
    missing = sorted(set(listed) - set(results))
    failed = sorted(name for name in listed if not results.get(name, True))
    assert not missing, f"listed cases not in the corpus: {', '.join(missing)}"
    assert not failed, (
        f"{len(failed)} listed conformance cases fail: {', '.join(failed)}\n{transcript}"
    )


def test_passing_list_is_sorted_and_unique() -> None:
    listed = tool.read_passing()
    assert listed == sorted(set(listed))
