#!/usr/bin/env python3
"""Turn a fuzz finding into a golden case: copy the program, record rs274's output.

    python tests/fuzz/record.py tests/fuzz/found/motion-123.ngc arc-r-format-rounding

copies the program to ``tests/golden/cases/fuzz-<name>.ngc`` and runs
``python3 tests/golden/regen.py --cases fuzz-<name>``, which writes the ``.out``, ``.err`` and
``.rc`` files beside it.  A program that carries a tool table (``;tooltable:`` lines, see
``gen.table_of``) runs with ``-t``, so it becomes a folder case instead:
``tests/golden/folders/fuzz-<name>/`` with ``prog.ngc``, ``table.tbl`` and a ``case.json`` giving
``-t table.tbl -g prog.ngc``, recorded with ``tests/golden/regen_folders.py``.  The name should
say what the case is about (lower case, digits and dashes).  An existing case is not
overwritten unless ``--force`` is given.
"""

from __future__ import annotations

import argparse
import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
GOLDEN = HERE.parent / "golden"
CASES = GOLDEN / "cases"
FOLDERS = GOLDEN / "folders"
sys.path.insert(0, str(HERE))
import gen  # noqa: E402

NAME = re.compile(r"^[a-z0-9][a-z0-9.-]*$")


def record(program: Path, name: str, force: bool = False, rs274: str = "rs274") -> Path:
    """Copy ``program`` to ``cases/fuzz-<name>.ngc`` and record rs274 on it; returns the copy."""
    name = name.removeprefix("fuzz-")
    if not NAME.match(name):
        raise ValueError(f"bad case name {name!r}: use lower case letters, digits and dashes")
    table = gen.table_of(program.read_bytes().decode("latin-1"))
    if table is not None:
        return _record_folder(program, table, name, force, rs274)
    target = CASES / f"fuzz-{name}.ngc"
    if target.exists() and not force:
        raise FileExistsError(f"{target} exists (use --force to replace it)")
    shutil.copyfile(program, target)
    subprocess.run([sys.executable, str(GOLDEN / "regen.py"), "--cases", f"fuzz-{name}",
                    "--rs274", rs274], check=True)
    return target


def _record_folder(program: Path, table: str, name: str, force: bool, rs274: str) -> Path:
    """The folder case of a program with its own tool table; returns the program's copy."""
    folder = FOLDERS / f"fuzz-{name}"
    if folder.exists() and not force:
        raise FileExistsError(f"{folder} exists (use --force to replace it)")
    folder.mkdir(parents=True, exist_ok=True)
    target = folder / "prog.ngc"
    shutil.copyfile(program, target)
    (folder / gen.TABLE_NAME).write_bytes(table.encode("latin-1"))
    case = {"args": ["-t", gen.TABLE_NAME, "-g", "prog.ngc"],
            "note": f"a fuzz finding ({program.name}) with its own tool table"}
    (folder / "case.json").write_text(json.dumps(case, indent=2) + "\n")
    subprocess.run([sys.executable, str(GOLDEN / "regen_folders.py"), "--cases", f"fuzz-{name}",
                    "--rs274", rs274], check=True)
    return target


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("program", type=Path, help="the (minimized) program, e.g. found/oword-7.ngc")
    ap.add_argument("name", help="short descriptive name; the case is fuzz-<name>")
    ap.add_argument("--force", action="store_true", help="replace an existing case")
    ap.add_argument("--rs274", default="rs274", help="reference command (default: rs274)")
    opts = ap.parse_args(argv)
    try:
        target = record(opts.program, opts.name, opts.force, opts.rs274)
    except (ValueError, FileExistsError, OSError, subprocess.CalledProcessError) as exc:
        print(f"record.py: {exc}", file=sys.stderr)
        return 2
    if target.name == "prog.ngc":
        for path in sorted(target.parent.iterdir()):
            print(path.relative_to(HERE.parent.parent))
        return 0
    for ext in (".ngc", ".out", ".err", ".rc"):
        print(target.with_suffix(ext).relative_to(HERE.parent.parent))
    return 0


if __name__ == "__main__":
    sys.exit(main())
