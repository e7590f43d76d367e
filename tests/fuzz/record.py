#!/usr/bin/env python3
"""Turn a fuzz finding into a golden case: copy the program, record rs274's output.

    python tests/fuzz/record.py tests/fuzz/found/motion-123.ngc arc-r-format-rounding

copies the program to ``tests/golden/cases/fuzz-<name>.ngc`` and runs
``python3 tests/golden/regen.py --cases fuzz-<name>``, which writes the ``.out``, ``.err`` and
``.rc`` files beside it.  The name should say what the case is about (lower case, digits and
dashes).  An existing case is not overwritten unless ``--force`` is given.
"""

from __future__ import annotations

import argparse
import re
import shutil
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
GOLDEN = HERE.parent / "golden"
CASES = GOLDEN / "cases"
NAME = re.compile(r"^[a-z0-9][a-z0-9.-]*$")


def record(program: Path, name: str, force: bool = False, rs274: str = "rs274") -> Path:
    """Copy ``program`` to ``cases/fuzz-<name>.ngc`` and record rs274 on it; returns the copy."""
    name = name.removeprefix("fuzz-")
    if not NAME.match(name):
        raise ValueError(f"bad case name {name!r}: use lower case letters, digits and dashes")
    target = CASES / f"fuzz-{name}.ngc"
    if target.exists() and not force:
        raise FileExistsError(f"{target} exists (use --force to replace it)")
    shutil.copyfile(program, target)
    subprocess.run([sys.executable, str(GOLDEN / "regen.py"), "--cases", f"fuzz-{name}",
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
    for ext in (".ngc", ".out", ".err", ".rc"):
        print(target.with_suffix(ext).relative_to(HERE.parent.parent))
    return 0


if __name__ == "__main__":
    sys.exit(main())
