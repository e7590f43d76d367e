#!/usr/bin/env python3
"""Differential fuzzing: generated programs through LinuxCNC's ``rs274 -g`` and ``ngc rs274 -g``.

    python tests/fuzz/run.py --kinds motion,offsets,oword,failing --count 300 --seed 1 \\
        [--jobs 2] [--shrink] [--out DIR] [--rs274 CMD] [--ngc CMD|inproc]

Each program runs the way tests/golden/regen.py runs rs274: a fresh temporary cwd holding the
program (and ``table.tbl``, passed as ``-t table.tbl``, when the program carries a tool table),
stdin /dev/null, ``LC_ALL=C``, a private ``HOME``, ``INI_FILE_NAME`` removed, a timeout.
ngc runs in the worker process by default (``--ngc inproc``: ``ngc.commands.rs274.run(argv)`` with
in-memory streams, chdir'd into the same kind of folder); ``--ngc 'ngc rs274'`` or
``--ngc 'python -m ngc rs274'`` runs it as a command instead.  Compared: stdout without the counter
column, stderr lines other than ``executing``, the exit code.

Programs of seed ``S`` .. ``S+count-1`` are generated per kind (tests/fuzz/gen.py).  With
``--shrink``, one program per class of difference is minimized (tests/fuzz/shrink.py) and written
to ``--out`` (default tests/fuzz/found/) with both outputs.  Exit status: 0 no difference, 1 some.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import multiprocessing
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import traceback
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path

HERE = Path(__file__).resolve().parent
TESTS = HERE.parent
REPO = TESTS.parent
for _p in (str(REPO / "src"), str(TESTS), str(TESTS / "golden"), str(HERE)):
    if _p not in sys.path:
        sys.path.insert(0, _p)

import continued  # noqa: E402
import gen  # noqa: E402
from regen import child_env  # noqa: E402

from transcript import messages, normalize  # noqa: E402

DEFAULT_TIMEOUT_S = 20.0
DEFAULT_OUT = HERE / "found"
INPROC = "inproc"
PROGRAM_NAME = "prog.ngc"


@dataclass
class Outcome:
    """One side's run: normalized stdout lines, stderr lines (without ``executing``), exit code."""

    out: list[str]
    err: list[str]
    rc: int
    raw_out: str = ""
    raw_err: str = ""
    timed_out: bool = False

    def same(self, other: Outcome) -> bool:
        return self.out == other.out and self.err == other.err and self.rc == other.rc


@dataclass
class Result:
    kind: str
    seed: int
    text: str
    ref: Outcome
    ngc: Outcome
    hint: str = ""
    signature: tuple[str, ...] = field(default_factory=tuple)

    @property
    def hung(self) -> bool:
        """rs274 never finished (its G71/G72 can loop for ever): nothing to compare with."""
        return self.ref.timed_out

    @property
    def differs(self) -> bool:
        return not self.hung and not self.ref.same(self.ngc)

    @property
    def feeds_only(self) -> bool:
        """The two differ only in where they make feeds of no length (see ``without_idle_feeds``)."""
        return (self.differs and self.ref.err == self.ngc.err and self.ref.rc == self.ngc.rc
                and without_idle_feeds(self.ref.out) == without_idle_feeds(self.ngc.out))


@contextlib.contextmanager
def workspace(text: str) -> Iterator[tuple[Path, Path]]:
    """A fresh folder holding the program (and its tool table, if it carries one: see
    ``gen.table_of``), and a private HOME: rs274 keeps its tool table in $HOME/.tool.mmap."""
    with tempfile.TemporaryDirectory(prefix="ngc-fuzz-") as tmp:
        work, home = Path(tmp) / "work", Path(tmp) / "home"
        work.mkdir()
        home.mkdir()
        (work / PROGRAM_NAME).write_bytes(text.encode("latin-1"))
        table = gen.table_of(text)
        if table is not None:
            (work / gen.TABLE_NAME).write_bytes(table.encode("latin-1"))
        yield work, home


def arguments(text: str) -> list[str]:
    """The command line after the program name: ``-t table.tbl`` if the program carries a tool
    table, then ``-g prog.ngc``."""
    table = ["-t", gen.TABLE_NAME] if gen.table_of(text) is not None else []
    return [*continued.args_of(text), *table, "-g", PROGRAM_NAME]


def outcome(stdout: str, stderr: str, rc: int) -> Outcome:
    return Outcome(normalize(stdout).splitlines(), messages(stderr), rc, stdout, stderr)


def run_command(cmd: list[str], text: str, timeout: float) -> Outcome:
    with workspace(text) as (work, home):
        try:
            proc = subprocess.run([*cmd, *arguments(text)], cwd=work, env=child_env(home),
                                  stdin=subprocess.DEVNULL, capture_output=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return Outcome([], [f"<timed out after {timeout:g}s>"], -1, timed_out=True)
    return outcome(proc.stdout.decode("latin-1"), proc.stderr.decode("latin-1"), proc.returncode)


class _Timeout(Exception):
    pass


def _alarm(signum: int, frame: object) -> None:
    raise _Timeout


def run_inproc(text: str, timeout: float) -> Outcome:
    """``ngc rs274 -g prog.ngc`` in this process; an exception counts as an internal error (70)."""
    from ngc.commands import rs274

    out, err = io.StringIO(), io.StringIO()
    old_cwd = os.getcwd()
    with workspace(text) as (work, home):
        old_home = os.environ.get("HOME")
        os.environ["HOME"] = str(home)
        os.chdir(work)
        use_alarm = hasattr(signal, "SIGALRM") and _main_thread()
        if use_alarm:
            old = signal.signal(signal.SIGALRM, _alarm)
            signal.setitimer(signal.ITIMER_REAL, timeout)
        try:
            rc = rs274.run(arguments(text), stdout=out, stderr=err)
        except _Timeout:
            return Outcome([], [f"<timed out after {timeout:g}s>"], -1)
        except Exception:
            err.write("<internal error>\n" + traceback.format_exc())
            rc = 70
        finally:
            if use_alarm:
                signal.setitimer(signal.ITIMER_REAL, 0)
                signal.signal(signal.SIGALRM, old)
            os.chdir(old_cwd)
            if old_home is None:
                os.environ.pop("HOME", None)
            else:
                os.environ["HOME"] = old_home
    return outcome(out.getvalue(), err.getvalue(), rc)


def _main_thread() -> bool:
    import threading

    return threading.current_thread() is threading.main_thread()


# ---- comparing ----------------------------------------------------------------------------------

# ARC_FEED's first two numbers are the end on the plane's first and second axes.
_ARC_AXES = {"CANON_PLANE_XY": (0, 1), "CANON_PLANE_YZ": (1, 2), "CANON_PLANE_XZ": (2, 0)}


def without_idle_feeds(lines: list[str]) -> list[str]:
    """The lines without the STRAIGHT_FEEDs that go to where the tool already is, as printed.

    rs274's G7x.1 makes such feeds, or leaves them out, depending on rounding noise in
    its own arithmetic (a change of 1e-14 in a fillet's radius 20 mm away turns them on or off);
    this lets a run tell those differences from the rest."""
    kept: list[str] = []
    pos: list[str] = ["", "", ""]
    axes = _ARC_AXES["CANON_PLANE_XY"]
    for line in lines:
        body = _LABEL.sub("", line)
        name, _, rest = body.partition("(")
        if name == "SELECT_PLANE":
            axes = _ARC_AXES.get(rest.rstrip(")"), axes)
        elif name in ("STRAIGHT_FEED", "STRAIGHT_TRAVERSE"):
            args = rest.rstrip(")").split(", ")
            if name == "STRAIGHT_FEED" and args[:3] == pos:
                continue
            pos = args[:3]
        elif name == "ARC_FEED":
            args = rest.rstrip(")").split(", ")
            pos[axes[0]], pos[axes[1]] = args[0], args[1]
            pos[3 - axes[0] - axes[1]] = args[5]
        kept.append(line)
    return kept


_NUMBER = re.compile(r"[-+]?\d+(?:\.\d*)?|[-+]?\.\d+")
_LABEL = re.compile(r"^N(?:\.\.\.\.\.|\d+)\s*")


def _shape(line: str | None) -> str:
    """A line with its N label and numbers masked: ``ARC_FEED(#, #, ...)``, ``Bad ... '#'``."""
    if line is None:
        return "<none>"
    line = _LABEL.sub("", line)
    if "(" in line and line.split("(", 1)[0].isupper():
        return line.split("(", 1)[0]
    return _NUMBER.sub("#", line)


def first_difference(a: list[str], b: list[str]) -> tuple[str | None, str | None] | None:
    for x, y in zip(a, b, strict=False):
        if x != y:
            return x, y
    if len(a) != len(b):
        n = min(len(a), len(b))
        return (a[n] if n < len(a) else None), (b[n] if n < len(b) else None)
    return None


def compare(ref: Outcome, ngc: Outcome) -> tuple[str, tuple[str, ...]]:
    """A one-line hint and a signature of how two outcomes differ ("" and () if they don't)."""
    parts: list[str] = []
    sig: list[str] = []
    d = first_difference(ref.out, ngc.out)
    if d is not None:
        parts.append(f"stdout rs274: {d[0]!r} | ngc: {d[1]!r}")
        sig += ["out", _shape(d[0]), _shape(d[1])]
    ref_msg = ref.err[0] if ref.err else None
    ngc_msg = ngc.err[0] if ngc.err else None
    if ref.err != ngc.err:
        e = first_difference(ref.err, ngc.err)
        assert e is not None
        parts.append(f"stderr rs274: {e[0]!r} | ngc: {e[1]!r}")
        sig += ["err", _shape(ref_msg), _shape(ngc_msg)]
    elif ref_msg is not None and d is not None:
        sig += ["msg", _shape(ref_msg)]
    if ref.rc != ngc.rc:
        parts.append(f"rc rs274: {ref.rc} | ngc: {ngc.rc}")
        sig += ["rc", str(ref.rc), str(ngc.rc)]
    return "; ".join(parts), tuple(sig)


# ---- running ------------------------------------------------------------------------------------


@dataclass
class Config:
    rs274: list[str]
    ngc: list[str] | None  # None: in-process
    timeout: float = DEFAULT_TIMEOUT_S


def run_pair(cfg: Config, text: str) -> tuple[Outcome, Outcome]:
    ref = run_command(cfg.rs274, text, cfg.timeout)
    if cfg.ngc is None:
        ours = run_inproc(text, cfg.timeout)
    else:
        ours = run_command(cfg.ngc, text, cfg.timeout)
    return ref, ours


_CFG: Config | None = None


def _init_worker(cfg: Config) -> None:
    """Keep the config; import ngc once per worker (a failure shows up in each run instead: an
    initializer that raises would make the pool start new workers forever)."""
    global _CFG
    _CFG = cfg
    if cfg.ngc is None:
        with contextlib.suppress(Exception):
            import ngc.commands.rs274  # noqa: F401


def check_ngc(cfg: Config) -> str | None:
    """Why ngc cannot run here (None if it can): an import error of the in-process ngc."""
    if cfg.ngc is not None:
        return None
    try:
        import ngc.commands.rs274  # noqa: F401
    except Exception:
        return traceback.format_exc(limit=1)
    return None


def run_job(job: tuple[str, int]) -> Result:
    kind, seed = job
    assert _CFG is not None
    text = gen.generate(kind, seed)
    ref, ours = run_pair(_CFG, text)
    hint, sig = compare(ref, ours)
    return Result(kind, seed, text, ref, ours, hint, sig)


def make_config(opts: argparse.Namespace) -> Config:
    ngc_cmd = None if opts.ngc == INPROC else shlex.split(opts.ngc)
    return Config(shlex.split(opts.rs274), ngc_cmd, opts.timeout)


def run_all(cfg: Config, jobs: list[tuple[str, int]], workers: int,
            progress: bool = True) -> list[Result]:
    results: list[Result] = []
    start = time.monotonic()
    if workers <= 1:
        _init_worker(cfg)
        iterator: Iterator[Result] = map(run_job, jobs)
        results = _collect(iterator, len(jobs), start, progress)
    else:
        ctx = multiprocessing.get_context("fork")
        with ctx.Pool(workers, initializer=_init_worker, initargs=(cfg,)) as pool:
            results = _collect(pool.imap(run_job, jobs, chunksize=4), len(jobs), start, progress)
    return results


def _collect(it: Iterator[Result], total: int, start: float, progress: bool) -> list[Result]:
    results = []
    n_diff = 0
    for r in it:
        results.append(r)
        n_diff += r.differs
        if progress and (len(results) % 25 == 0 or len(results) == total):
            rate = len(results) / max(time.monotonic() - start, 1e-9)
            print(f"  {len(results)}/{total} programs, {n_diff} differ ({rate:.1f}/s)",
                  file=sys.stderr, flush=True)
    return results


def summarize(results: list[Result], kinds: list[str]) -> dict[tuple[str, ...], list[Result]]:
    """Print the per-kind table and the classes of difference; returns the classes."""
    print(f"{'kind':10} {'run':>5} {'same':>5} {'differ':>6} {'idle feeds':>10} {'rs274 ok':>9}"
          f" {'rs274 hung':>10}")
    for kind in kinds:
        rs = [r for r in results if r.kind == kind]
        hung = sum(r.hung for r in rs)
        same = sum(not r.differs and not r.hung for r in rs)
        idle = sum(r.feeds_only for r in rs)
        ok = sum(r.ref.rc == 0 for r in rs)
        pct = 100 * ok / len(rs) if rs else 0
        print(f"{kind:10} {len(rs):5} {same:5} {len(rs) - same - hung:6} {idle:10} {ok:5}"
              f" ({pct:.0f}%) {hung:10}")
    print("(idle feeds: of those that differ, the ones that differ only in feeds of no length)")
    classes: dict[tuple[str, ...], list[Result]] = {}
    for r in results:
        if r.differs:
            classes.setdefault(r.signature, []).append(r)
    if classes:
        print(f"\n{len(classes)} classes of difference:")
    for sig, rs in sorted(classes.items(), key=lambda kv: -len(kv[1])):
        first = rs[0]
        counts = ", ".join(f"{k} {sum(r.kind == k for r in rs)}" for k in kinds
                           if any(r.kind == k for r in rs))
        print(f"- {len(rs)}x ({counts}) e.g. {first.kind} seed {first.seed}")
        print(f"    {first.hint}")
        print(f"    signature: {sig}")
    return classes


def write_finding(out_dir: Path, name: str, text: str, ref: Outcome, ours: Outcome) -> Path:
    out_dir.mkdir(parents=True, exist_ok=True)
    prog = out_dir / f"{name}.ngc"
    prog.write_bytes(text.encode("latin-1"))
    for side, o in (("rs274", ref), ("ngc", ours)):
        body = "\n".join(o.out) + ("\n" if o.out else "")
        (out_dir / f"{name}.{side}.out").write_bytes(body.encode("latin-1"))
        (out_dir / f"{name}.{side}.err").write_bytes(
            ("\n".join(o.err) + ("\n" if o.err else "") + f"rc={o.rc}\n").encode("latin-1"))
    return prog


def show_diff(ref: Outcome, ours: Outcome) -> list[str]:
    import difflib

    a = [*ref.out, *(f"stderr: {m}" for m in ref.err), f"rc: {ref.rc}"]
    b = [*ours.out, *(f"stderr: {m}" for m in ours.err), f"rc: {ours.rc}"]
    return list(difflib.unified_diff(a, b, "rs274", "ngc", lineterm="", n=1))


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    # `continue` (-n 0) has known differences and programs rs274 never finishes: asked for by name.
    default_kinds = ",".join(kind for kind in gen.KINDS if kind != "continue")
    ap.add_argument("--kinds", default=default_kinds,
                    help=f"comma-separated kinds (default: {default_kinds})")
    ap.add_argument("--count", type=int, default=20, help="programs per kind (default 20)")
    ap.add_argument("--seed", type=int, default=1, help="first seed (default 1)")
    ap.add_argument("--jobs", "-j", type=int, default=2, help="worker processes (default 2)")
    ap.add_argument("--out", type=Path, default=DEFAULT_OUT,
                    help="where --shrink writes findings (default tests/fuzz/found/)")
    ap.add_argument("--rs274", default="rs274", help="reference command (default: rs274)")
    ap.add_argument("--ngc", default=INPROC,
                    help="ngc command, e.g. 'ngc rs274' (default: inproc, run in the worker)")
    ap.add_argument("--timeout", type=float, default=DEFAULT_TIMEOUT_S)
    ap.add_argument("--shrink", action="store_true",
                    help="minimize one program per class of difference and write it to --out")
    ap.add_argument("--exclude", default="",
                    help="preamble codes to leave out, e.g. G40,G49 (to look past known issues)")
    ap.add_argument("--quiet", "-q", action="store_true", help="no progress lines")
    opts = ap.parse_args(argv)

    kinds = [k for k in opts.kinds.split(",") if k]
    unknown = [k for k in kinds if k not in gen.KINDS]
    if unknown:
        ap.error(f"unknown kind(s) {', '.join(unknown)}; known: {', '.join(gen.KINDS)}")
    if shutil.which(shlex.split(opts.rs274)[0]) is None:
        print(f"run.py: cannot find {opts.rs274!r}", file=sys.stderr)
        return 2
    gen.EXCLUDE.update(c.strip().upper() for c in opts.exclude.split(",") if c.strip())
    cfg = make_config(opts)
    problem = check_ngc(cfg)
    if problem is not None:
        print(f"run.py: cannot import ngc in-process:\n{problem}", file=sys.stderr)
        return 2
    jobs = [(k, s) for k in kinds for s in range(opts.seed, opts.seed + opts.count)]
    start = time.monotonic()
    results = run_all(cfg, jobs, opts.jobs, progress=not opts.quiet)
    print(f"{len(results)} programs in {time.monotonic() - start:.1f}s")
    classes = summarize(results, kinds)
    if opts.shrink and classes:
        import shrink

        reps = [rs[0] for rs in classes.values()]
        print(f"\nshrinking {len(reps)} programs ...", flush=True)
        for r, small in shrink.shrink_many(cfg, reps, opts.jobs):
            ref, ours = run_pair(cfg, small)
            name = f"{r.kind}-{r.seed}"
            path = write_finding(opts.out, name, small, ref, ours)
            print(f"\n== {path} ({len(r.text.splitlines())} -> {len(small.splitlines())} lines)")
            print(f"   {r.hint}")
            for line in small.splitlines():
                print(f"   | {line}")
            for line in show_diff(ref, ours):
                print(f"   {line}")
    return 1 if classes else 0


if __name__ == "__main__":
    sys.exit(main())
