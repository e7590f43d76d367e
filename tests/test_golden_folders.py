"""Golden folder cases: ``tests/golden/folders/<name>/`` with rs274's recorded results.

Each case folder holds its input files (programs, subroutine files, INI, var files), a
``case.json`` with the command line, and rs274's ``expected.out`` / ``expected.err`` /
``expected.rc`` plus ``expected.files/`` (every file the run created or changed, byte for
byte).  The inputs are copied into a temporary folder, ``ngc rs274 <args>`` runs in-process
there, and stdout (without the counter column), stderr lines other than ``executing``, the exit
code and the created/changed files are compared.

rs274's standalone canon only prints ``LOGOPEN``/``LOG``/...; ngc also writes the log file, as a
LinuxCNC machine does.  What ngc writes beyond rs274 is in ``ngc.files/`` (reviewed by hand, not
recorded from rs274) and is compared the same way.
"""

from __future__ import annotations

import io
import json
import shutil
from pathlib import Path

import pytest

from ngc.commands import rs274
from transcript import messages, normalize

FOLDERS = Path(__file__).parent / "golden" / "folders"
FILES_DIR = "expected.files"
NGC_FILES_DIR = "ngc.files"


def is_input(rel: Path) -> bool:
    first = rel.parts[0]
    return first not in ("case.json", NGC_FILES_DIR) and not first.startswith("expected.")


def snapshot(root: Path) -> dict[str, bytes]:
    return {p.relative_to(root).as_posix(): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


# Known differences, each with its reason; strict, so a case that starts passing is noticed.
KNOWN: dict[str, str] = {}


def _cases() -> list[object]:
    names = sorted(p.parent.name for p in FOLDERS.glob("*/case.json"))
    return [
        pytest.param(name, marks=pytest.mark.xfail(reason=KNOWN[name], strict=True))
        if name in KNOWN
        else name
        for name in names
    ]


@pytest.mark.parametrize("fast", [True, False], ids=["fast", "general"])
@pytest.mark.parametrize("name", _cases())
def test_golden_folder(name: str, fast: bool, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Every folder case, with the fast path on and off."""
    case = FOLDERS / name
    args = json.loads((case / "case.json").read_text())["args"]
    work = tmp_path / "work"
    work.mkdir()
    for src in sorted(case.rglob("*")):
        src_rel = src.relative_to(case)
        if src.is_file() and is_input(src_rel):
            (work / src_rel).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(src, work / src_rel)
    before = snapshot(work)
    monkeypatch.chdir(work)
    out, err = io.StringIO(), io.StringIO()
    rc = rs274.run(list(args), stdout=out, stderr=err, fast=fast, stdin=io.StringIO())
    after = snapshot(work)

    expected_out = (case / "expected.out").read_text(encoding="latin-1")
    expected_err = (case / "expected.err").read_text(encoding="latin-1")
    expected_rc = int((case / "expected.rc").read_text())
    expected_files = snapshot(case / FILES_DIR) if (case / FILES_DIR).is_dir() else {}
    if (case / NGC_FILES_DIR).is_dir():
        expected_files.update(snapshot(case / NGC_FILES_DIR))
    changed = {path: data for path, data in after.items() if before.get(path) != data}

    assert messages(err.getvalue()) == messages(expected_err)
    assert normalize(out.getvalue()) == expected_out
    assert rc == expected_rc
    assert sorted(set(before) - set(after)) == [], "input files deleted"
    assert sorted(changed) == sorted(expected_files), "created/changed files"
    for path, data in expected_files.items():
        # latin-1 maps bytes 1:1, so this is a byte comparison with a readable diff
        assert changed[path].decode("latin-1") == data.decode("latin-1"), f"contents of {path}"
