#!/usr/bin/env python3
"""Record (or check) the parameter files the reference ``rs274`` writes.

Every folder next to this file holds ``input.var`` and ``program.ngc``.  The program is run as

    rs274 -v b.var -g program.ngc

in a fresh temporary folder holding ``program.ngc`` and a copy of ``input.var`` named ``b.var``
(cwd = that folder, stdin = /dev/null, ``LC_ALL=C``, ``HOME`` = a private empty folder).  rs274
saves the parameter file twice, right after reading it and at exit, each time turning the old file
into ``b.var.bak``.  Recorded beside the inputs:

    expected.var      b.var after the run
    expected.var.bak  b.var.bak after the run (the file as saved right after reading)
    expected.err      stderr, verbatim
    expected.rc       the exit code and a newline

Usage: record.py [--check] [--rs274 CMD].  ``--check`` writes nothing and exits 1 if a recorded
file differs from a fresh run.  Standard library only.
"""

from __future__ import annotations

import argparse
import os
import shlex
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent


def run(rs274: list[str], case: Path) -> dict[str, bytes]:
    """The files a run of ``case`` produces, by name."""
    with tempfile.TemporaryDirectory() as work, tempfile.TemporaryDirectory() as home:
        shutil.copy(case / "program.ngc", work)
        shutil.copy(case / "input.var", Path(work) / "b.var")
        env = {k: v for k, v in os.environ.items() if k != "INI_FILE_NAME"}
        env.update(HOME=home, LC_ALL="C")
        done = subprocess.run(
            [*rs274, "-v", "b.var", "-g", "program.ngc"],
            cwd=work,
            env=env,
            stdin=subprocess.DEVNULL,
            capture_output=True,
            timeout=20,
            check=False,
        )
        backup = Path(work) / "b.var.bak"
        return {
            "expected.var": (Path(work) / "b.var").read_bytes(),
            "expected.var.bak": backup.read_bytes() if backup.exists() else b"",
            "expected.err": done.stderr,
            "expected.rc": f"{done.returncode}\n".encode(),
        }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--rs274", default="rs274")
    args = parser.parse_args()
    differ = 0
    for case in sorted(p for p in HERE.iterdir() if (p / "input.var").exists()):
        for name, data in run(shlex.split(args.rs274), case).items():
            target = case / name
            if args.check:
                if not target.exists() or target.read_bytes() != data:
                    print(f"{case.name}/{name} differs")
                    differ += 1
            else:
                target.write_bytes(data)
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
