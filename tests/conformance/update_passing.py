#!/usr/bin/env python3
"""Grow the conformance ratchet: run the whole corpus and ADD the cases ngc now passes to
``passing.txt`` (next to this file).  Cases are never removed: a listed case that fails is a
regression to fix, and is reported (exit status 1).

Usage (from anywhere; ``../shared`` must sit beside the repository)::

    python tests/conformance/update_passing.py [--shared DIR] [--jobs N]

The implementation run is ``<this python> -m ngc rs274`` with the repository's ``src`` on
``PYTHONPATH``, so an installed ``ngc`` is not needed.  ``tests/test_conformance_ratchet.py``
uses the same functions.
"""

from __future__ import annotations

import argparse
import json
import os
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent
PASSING = HERE / "passing.txt"
DEFAULT_SHARED = REPO.parent / "shared"
HEADER = (
    "# Conformance cases (../shared/conformance/cases/<name>) that ngc passes.\n"
    "# The list only grows: tests/conformance/update_passing.py adds, nobody removes.\n"
)


def runner(shared: Path = DEFAULT_SHARED) -> Path:
    return shared / "conformance" / "run.py"


def read_passing(path: Path = PASSING) -> list[str]:
    """The listed case names (blank lines and ``#`` comments skipped)."""
    if not path.is_file():
        return []
    names = (line.split("#", 1)[0].strip() for line in path.read_text().splitlines())
    return [name for name in names if name]


def write_passing(names: set[str], path: Path = PASSING) -> None:
    path.write_text(HEADER + "".join(f"{name}\n" for name in sorted(names)))


def run_corpus(
    cases: list[str] | None, shared: Path = DEFAULT_SHARED, jobs: int | None = None
) -> tuple[dict[str, bool], str]:
    """Run the conformance runner on ``cases`` (all when ``None``); returns
    ``({case name: passed}, runner stdout)``."""
    impl = f"{shlex.quote(sys.executable)} -m ngc rs274"
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(REPO / "src"), env.get("PYTHONPATH")]))
    with tempfile.TemporaryDirectory(prefix="ngc-ratchet-") as tmp:
        out = Path(tmp) / "results.json"
        cmd = [sys.executable, str(runner(shared)), "--impl", impl, "--json", str(out)]
        if cases is not None:
            cmd += ["--cases", ",".join(cases)]
        if jobs is not None:
            cmd += ["--jobs", str(jobs)]
        proc = subprocess.run(cmd, env=env, capture_output=True, text=True, check=False)
        if not out.is_file():
            raise RuntimeError(
                f"conformance runner failed (rc {proc.returncode}):\n{proc.stdout}{proc.stderr}"
            )
        results = json.loads(out.read_text())
    return {case["name"]: bool(case["passed"]) for case in results["cases"]}, proc.stdout


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument(
        "--shared",
        type=Path,
        default=DEFAULT_SHARED,
        help=f"the shared folder (default {DEFAULT_SHARED})",
    )
    ap.add_argument("--jobs", type=int, help="parallel cases (default: the runner's)")
    opts = ap.parse_args(argv)
    if not runner(opts.shared).is_file():
        print(f"update_passing: no conformance runner at {runner(opts.shared)}", file=sys.stderr)
        return 2
    listed = set(read_passing())
    results, _ = run_corpus(None, opts.shared, opts.jobs)
    passed = {name for name, ok in results.items() if ok}
    added = passed - listed
    regressed = sorted(name for name in listed if not results.get(name, False))
    write_passing(listed | passed)
    print(
        f"{len(passed)} of {len(results)} cases pass; {len(added)} added to {PASSING.name}"
        f" ({len(listed | passed)} listed)"
    )
    for name in sorted(added):
        print(f"  + {name}")
    if regressed:
        print(f"{len(regressed)} listed cases FAIL (kept in the list; fix them):")
        for name in regressed:
            print(f"  ! {name}")
    return 1 if regressed else 0


if __name__ == "__main__":
    sys.exit(main())
