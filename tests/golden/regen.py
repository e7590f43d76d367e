#!/usr/bin/env python3
"""Record (or check) the golden outputs of the reference ``rs274``.

Every ``cases/<name>.ngc`` (next to this file) is run through LinuxCNC's
standalone interpreter exactly the way the golden tests expect:

    rs274 -g <name>.ngc

with cwd = a fresh temporary folder holding a copy of the program,
stdin = /dev/null, ``LC_ALL=C``, ``HOME`` = a private empty temporary folder
(rs274 keeps a tool table mmap in $HOME; concurrent runs sharing one HOME
corrupt each other) and ``INI_FILE_NAME`` removed from the environment.
The results are written beside the program:

    <name>.out   stdout, normalized by normalize_stdout() below
    <name>.err   stderr, verbatim
    <name>.rc    the exit code and a newline

Usage:
    regen.py [--cases GLOB] [--check] [--rs274 CMD] [--jobs N] [--timeout S]

``--cases`` takes fnmatch globs on the case name (without ``.ngc``); it may be
repeated or comma-separated.  ``--check`` writes nothing: it reports every
case whose recorded files differ from a fresh run and exits 1 if any do.
Exit status 2: usage error (no case matched, rs274 cannot be started).

Standard library only (Python >= 3.11); does not depend on anything outside
this folder.
"""

from __future__ import annotations

import argparse
import concurrent.futures
import difflib
import fnmatch
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
CASES_DIR = HERE / "cases"
DEFAULT_TIMEOUT_S = 20.0

# rs274 prints every canonical call as "%5d " (a running counter) followed by
# the call.  Remove leading spaces, at least one digit and exactly one space,
# once, at the start of each line.  (Same rule as the shared conformance
# runner's normalize_stdout; copied so this folder stands alone.)
COUNTER_RE = re.compile(rb"^ *[0-9]+ ")


def split_lines(data: bytes) -> list[bytes]:
    """Split on b'\\n'; a missing final newline is treated as present."""
    if not data:
        return []
    lines = data.split(b"\n")
    if lines[-1] == b"":
        lines.pop()
    return lines


def normalize_stdout(data: bytes) -> bytes:
    """Strip the counter column from each line; every line ends in b'\\n'."""
    return b"".join(COUNTER_RE.sub(b"", line, count=1) + b"\n"
                    for line in split_lines(data))


def child_env(home: Path) -> dict[str, str]:
    env = dict(os.environ)
    env["HOME"] = str(home)
    env["LC_ALL"] = "C"
    env.pop("LANGUAGE", None)
    env.pop("INI_FILE_NAME", None)
    return env


def discover(globs: list[str] | None) -> list[Path]:
    progs = sorted(CASES_DIR.glob("*.ngc"))
    if globs:
        pats = [p for g in globs for p in g.split(",") if p]
        progs = [p for p in progs
                 if any(fnmatch.fnmatchcase(p.stem, pat) or fnmatch.fnmatchcase(p.name, pat)
                        for pat in pats)]
    return progs


class StartError(Exception):
    pass


def run_case(cmd: list[str], prog: Path, timeout_s: float) -> dict[str, bytes]:
    """Run the reference on one program; return the three recorded files."""
    with tempfile.TemporaryDirectory(prefix="ngc-golden-") as tmp:
        work = Path(tmp) / "work"
        home = Path(tmp) / "home"
        work.mkdir()
        home.mkdir()
        shutil.copy2(prog, work / prog.name)
        try:
            proc = subprocess.run([*cmd, "-g", prog.name], cwd=work, env=child_env(home),
                                  stdin=subprocess.DEVNULL, capture_output=True,
                                  timeout=timeout_s)
        except OSError as exc:
            raise StartError(f"cannot start {cmd[0]!r}: {exc}") from exc
    return {
        ".out": normalize_stdout(proc.stdout),
        ".err": proc.stderr,
        ".rc": f"{proc.returncode}\n".encode(),
    }


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--cases", action="append", metavar="GLOB",
                    help="only cases whose name matches this fnmatch glob")
    ap.add_argument("--check", action="store_true",
                    help="report differences, write nothing")
    ap.add_argument("--rs274", default="rs274",
                    help="reference command, split with shlex (default: rs274)")
    ap.add_argument("--jobs", "-j", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--timeout", type=float, default=DEFAULT_TIMEOUT_S,
                    help=f"seconds per run (default {DEFAULT_TIMEOUT_S:g})")
    ap.add_argument("--diff", action="store_true",
                    help="with --check: show a unified diff of each difference")
    opts = ap.parse_args(argv)

    cmd = shlex.split(opts.rs274)
    progs = discover(opts.cases)
    if not progs:
        print("regen.py: no cases matched", file=sys.stderr)
        return 2

    def one(prog: Path):
        try:
            return prog, run_case(cmd, prog, opts.timeout), None
        except subprocess.TimeoutExpired:
            return prog, None, f"timed out after {opts.timeout:g}s"
        except StartError as exc:
            return prog, None, str(exc)

    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, opts.jobs)) as pool:
        results = list(pool.map(one, progs))

    n_same = n_diff = n_fail = 0
    for prog, new, error in results:
        if error is not None:
            n_fail += 1
            print(f"ERROR     {prog.stem}: {error}")
            continue
        changed = []
        diff_lines: list[str] = []
        for ext, data in new.items():
            path = prog.with_suffix(ext)
            old = path.read_bytes() if path.exists() else None
            if old == data:
                continue
            changed.append(ext)
            if opts.check:
                if opts.diff:
                    old_lines = (old or b"").decode("utf-8", "replace").splitlines()
                    new_lines = data.decode("utf-8", "replace").splitlines()
                    diff_lines += difflib.unified_diff(old_lines, new_lines,
                                                       f"recorded/{path.name}",
                                                       f"rs274/{path.name}", lineterm="")
            else:
                path.write_bytes(data)
        if changed:
            n_diff += 1
            verb = "differ" if opts.check else "written"
            print(f"{'DIFFERS' if opts.check else 'WRITTEN':9} {prog.stem}: "
                  f"{' '.join(changed)} {verb}")
            for line in diff_lines:
                print(f"    {line}")
        else:
            n_same += 1
    label = "differ" if opts.check else "written"
    print(f"{len(results)} cases: {n_same} unchanged, {n_diff} {label}, {n_fail} errors")
    if n_fail:
        return 2 if n_fail == len(results) else 1
    return 1 if (opts.check and n_diff) else 0


if __name__ == "__main__":
    sys.exit(main())
