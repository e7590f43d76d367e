#!/usr/bin/env python3
"""Record (or check) the golden outputs of the reference ``rs274`` for folder cases.

A folder case is a directory ``folders/<name>/`` (next to this file) holding

    case.json        {"args": [...], "note": "...", optional "timeout_s": N}
    <input files>    programs, subroutine files, INI, var files, subfolders ...
    expected.out     stdout, normalized by normalize_stdout() below
    expected.err     stderr, verbatim
    expected.rc      the exit code and a newline
    expected.files/  every file the run created or changed in the folder,
                     byte for byte, at its path relative to the folder

Inputs are every file of the folder except ``case.json`` and ``expected.*``.
Each case runs as

    rs274 <args...>

with cwd = a fresh temporary copy of the inputs, stdin = /dev/null,
``LC_ALL=C``, ``HOME`` = a private empty temporary folder (rs274 keeps a tool
table mmap in $HOME; concurrent runs sharing one HOME corrupt each other) and
``INI_FILE_NAME`` removed from the environment.  After the run, every file of
the copy that is new or whose bytes changed is recorded under
``expected.files/`` (stale files there are removed).  An input file deleted
by the run is reported as an error.

Usage:
    regen_folders.py [--cases GLOB] [--check] [--diff] [--rs274 CMD] [--jobs N] [--timeout S]

``--cases`` takes fnmatch globs on the case name; it may be repeated or
comma-separated.  ``--check`` writes nothing: it reports every case whose
recorded files differ from a fresh run and exits 1 if any do.
Exit status 2: usage error (no case matched, rs274 cannot be started).

Standard library only (Python >= 3.11); shares regen.py's normalization and
child environment and does not depend on anything outside this folder.
"""

from __future__ import annotations

import argparse
import concurrent.futures
import difflib
import fnmatch
import json
import os
import shlex
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
# The transcript normalization and the child's environment are regen.py's (this folder).
from regen import DEFAULT_TIMEOUT_S, child_env, normalize_stdout  # noqa: E402

FOLDERS_DIR = HERE / "folders"
EXPECTED = ("expected.out", "expected.err", "expected.rc")
FILES_DIR = "expected.files"

def is_input(rel: Path) -> bool:
    """True for the case's input files (not case.json, the expected.* results or ngc.files)."""
    first = rel.parts[0]
    return first not in ("case.json", "ngc.files") and not first.startswith("expected.")


def snapshot(root: Path) -> dict[str, bytes]:
    """Every regular file under root: relative posix path -> bytes."""
    return {p.relative_to(root).as_posix(): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


def copy_inputs(case: Path, dest: Path) -> None:
    for src in sorted(case.rglob("*")):
        rel = src.relative_to(case)
        if not is_input(rel) or not src.is_file():
            continue
        target = dest / rel
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(src, target)


def discover(globs: list[str] | None) -> list[Path]:
    cases = sorted(p.parent for p in FOLDERS_DIR.glob("*/case.json"))
    if globs:
        pats = [p for g in globs for p in g.split(",") if p]
        cases = [c for c in cases if any(fnmatch.fnmatchcase(c.name, pat) for pat in pats)]
    return cases


class StartError(Exception):
    pass


class CaseError(Exception):
    pass


def run_case(cmd: list[str], case: Path, timeout_s: float) -> dict[str, bytes]:
    """Run the reference on one folder case; return {relative result path: bytes}."""
    spec = json.loads((case / "case.json").read_text())
    args = spec["args"]
    timeout_s = float(spec.get("timeout_s", timeout_s))
    with tempfile.TemporaryDirectory(prefix="ngc-golden-folder-") as tmp:
        work = Path(tmp) / "work"
        home = Path(tmp) / "home"
        work.mkdir()
        home.mkdir()
        copy_inputs(case, work)
        before = snapshot(work)
        try:
            proc = subprocess.run(
                [*cmd, *args],
                cwd=work,
                env=child_env(home),
                stdin=subprocess.DEVNULL,
                capture_output=True,
                timeout=timeout_s,
            )
        except OSError as exc:
            raise StartError(f"cannot start {cmd[0]!r}: {exc}") from exc
        after = snapshot(work)
    deleted = sorted(set(before) - set(after))
    if deleted:
        raise CaseError(f"the run deleted input files: {', '.join(deleted)}")
    result = {
        "expected.out": normalize_stdout(proc.stdout),
        "expected.err": proc.stderr,
        "expected.rc": f"{proc.returncode}\n".encode(),
    }
    for rel, data in after.items():
        if before.get(rel) != data:
            result[f"{FILES_DIR}/{rel}"] = data
    return result


def recorded(case: Path) -> dict[str, bytes]:
    """The results currently recorded in the case folder."""
    out = {name: (case / name).read_bytes() for name in EXPECTED if (case / name).exists()}
    files = case / FILES_DIR
    if files.is_dir():
        for rel, data in snapshot(files).items():
            out[f"{FILES_DIR}/{rel}"] = data
    return out


def write_results(case: Path, new: dict[str, bytes]) -> None:
    files = case / FILES_DIR
    if files.exists():
        shutil.rmtree(files)
    for rel, data in new.items():
        path = case / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(data)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument(
        "--cases", action="append", metavar="GLOB", help="only cases whose name matches this fnmatch glob"
    )
    ap.add_argument("--check", action="store_true", help="report differences, write nothing")
    ap.add_argument("--rs274", default="rs274", help="reference command, split with shlex (default: rs274)")
    ap.add_argument("--jobs", "-j", type=int, default=os.cpu_count() or 1)
    ap.add_argument(
        "--timeout",
        type=float,
        default=DEFAULT_TIMEOUT_S,
        help=f"seconds per run unless case.json sets timeout_s (default {DEFAULT_TIMEOUT_S:g})",
    )
    ap.add_argument(
        "--diff", action="store_true", help="with --check: show a unified diff of each difference"
    )
    opts = ap.parse_args(argv)

    cmd = shlex.split(opts.rs274)
    cases = discover(opts.cases)
    if not cases:
        print("regen_folders.py: no cases matched", file=sys.stderr)
        return 2

    def one(case: Path) -> tuple[Path, dict[str, bytes] | None, str | None]:
        try:
            return case, run_case(cmd, case, opts.timeout), None
        except subprocess.TimeoutExpired as exc:
            return case, None, f"timed out after {exc.timeout:g}s"
        except (StartError, CaseError, KeyError, ValueError) as exc:
            return case, None, str(exc)

    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, opts.jobs)) as pool:
        results = list(pool.map(one, cases))

    n_same = n_diff = n_fail = 0
    for case, new, error in results:
        if new is None:
            n_fail += 1
            print(f"ERROR     {case.name}: {error}")
            continue
        old = recorded(case)
        changed = sorted(k for k in set(old) | set(new) if old.get(k) != new.get(k))
        if not changed:
            n_same += 1
            continue
        n_diff += 1
        if opts.check:
            print(f"DIFFERS   {case.name}: {' '.join(changed)} differ")
            if opts.diff:
                for name in changed:
                    old_lines = old.get(name, b"").decode("utf-8", "replace").splitlines()
                    new_lines = new.get(name, b"").decode("utf-8", "replace").splitlines()
                    for line in difflib.unified_diff(
                        old_lines, new_lines, f"recorded/{name}", f"rs274/{name}", lineterm=""
                    ):
                        print(f"    {line}")
        else:
            write_results(case, new)
            print(f"WRITTEN   {case.name}: {' '.join(changed)} written")
    label = "differ" if opts.check else "written"
    print(f"{len(results)} cases: {n_same} unchanged, {n_diff} {label}, {n_fail} errors")
    if n_fail:
        return 2 if n_fail == len(results) else 1
    return 1 if (opts.check and n_diff) else 0


if __name__ == "__main__":
    sys.exit(main())
