#!/usr/bin/env python3
"""Side-by-side throughput benchmark: ``ngc rs274 -g`` against LinuxCNC's ``rs274 -g``.

For every generated program (``../shared/bench/benchgen.py``) the two commands are first run
once each with their output captured, to check that both exit 0 and print the same canon
(after stripping the counter column, as ``../shared/conformance/run.py`` does).  Then, after
one discarded warm-up each, they run alternately A B A B ... with output sent to /dev/null.
Each run is timed by wall clock (``time.perf_counter``) and by the CPU time of the child
(``getrusage(RUSAGE_CHILDREN)`` deltas, user + sys).

The speed ratio is ``ref_time / impl_time`` per A/B pair; the median of the pair ratios is
reported, so a ratio above 1.0 means ngc is faster than rs274.

Standard library only.  See ``benchmarks/README.md``.
"""

from __future__ import annotations

import argparse
import datetime
import hashlib
import json
import os
import platform
import re
import resource
import shlex
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
REPO_ROOT = HERE.parent
DEFAULT_SHARED = REPO_ROOT.parent / "shared"
DEFAULT_OUT_DIR = HERE / "out"
DEFAULT_RESULTS = HERE / "RESULTS.md"
KINDS = ("surface", "contour", "macro", "ccomp")
# Kinds that benchmarks/programs.py makes; the others come from ../shared/bench/benchgen.py.
LOCAL_KINDS = ("ccomp",)

# Same normalization as ../shared/conformance/run.py: rs274 prints every canonical call as
# "%5d " (a running counter) + the call; strip leading spaces, digits and one space, once.
COUNTER_RE = re.compile(rb"^ *[0-9]+ ")

RESULTS_HEADER = (
    "# Benchmark results\n\n"
    "Written by `python benchmarks/bench.py --write`; one section per machine, date and set of\n"
    "commands (a re-run with the same ones replaces its section).  Ratio = rs274 time / ngc time,\n"
    "median of A/B pairs: above 1.0 means ngc is faster.  See `benchmarks/README.md`.\n"
)


class CommandError(Exception):
    """A benchmarked command could not be started or did not exit 0."""


# --------------------------------------------------------------------------
# data
# --------------------------------------------------------------------------


@dataclass
class Timing:
    wall_s: float
    cpu_s: float


@dataclass
class Side:
    """Timings of one command on one program."""

    runs: list[Timing] = field(default_factory=list)

    def median_wall_s(self) -> float:
        return statistics.median(t.wall_s for t in self.runs)

    def median_cpu_s(self) -> float:
        return statistics.median(t.cpu_s for t in self.runs)


@dataclass
class ProgramResult:
    kind: str
    lines: int
    path: str
    impl: Side = field(default_factory=Side)
    ref: Side | None = None
    identical: bool | None = None  # None: no reference to compare with
    difference: str = ""
    error: str = ""

    def pair_ratios(self, attr: str) -> list[float]:
        if self.ref is None:
            return []
        return [
            getattr(r, attr) / getattr(i, attr)
            for i, r in zip(self.impl.runs, self.ref.runs, strict=True)
            if getattr(i, attr) > 0
        ]

    def ratio(self, attr: str = "wall_s") -> float | None:
        ratios = self.pair_ratios(attr)
        return statistics.median(ratios) if ratios else None


# --------------------------------------------------------------------------
# programs
# --------------------------------------------------------------------------


def program_path(out_dir: Path, kind: str, lines: int) -> Path:
    return out_dir / f"{kind}-{lines}.ngc"


def ensure_program(shared: Path, out_dir: Path, kind: str, lines: int) -> Path:
    """Generate ``KIND-LINES.ngc`` (benchgen.py, or programs.py for a local kind) unless it
    already exists."""
    path = program_path(out_dir, kind, lines)
    if path.is_file():
        return path
    gen = HERE / "programs.py" if kind in LOCAL_KINDS else shared / "bench" / "benchgen.py"
    if not gen.is_file():
        raise SystemExit(f"bench.py: generator not found: {gen} (use --shared DIR)")
    out_dir.mkdir(parents=True, exist_ok=True)
    # Write under a temporary name so an interrupted run never leaves a truncated file behind
    # that a later run would reuse.
    tmp = path.with_suffix(".ngc.part")
    log(f"generating {path.name} ...")
    subprocess.run([sys.executable, str(gen), kind, str(lines), str(tmp)], check=True)
    os.replace(tmp, path)
    return path


# --------------------------------------------------------------------------
# running
# --------------------------------------------------------------------------


def child_env(home: Path) -> dict[str, str]:
    """Environment of every run, as in the conformance runner."""
    env = dict(os.environ)
    env["HOME"] = str(home)  # rs274 keeps its tool table mmap in $HOME/.tool.mmap
    env["LC_ALL"] = "C"
    env.pop("LANGUAGE", None)
    env.pop("INI_FILE_NAME", None)
    # An installed package runs from its compiled bytecode: let the warm-up run write it, as
    # pip does at install time, so start-up is measured as a user meets it (not recompiling
    # every module on every run).
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    return env


@contextmanager
def private_home() -> Iterator[Path]:
    with tempfile.TemporaryDirectory(prefix="ngc-bench-home-") as tmp:
        yield Path(tmp)


def command_for(prefix: list[str], program: Path) -> list[str]:
    return [*prefix, program.name]


def describe_failure(prefix: list[str], rc: int, stderr: bytes) -> str:
    tail = stderr.decode("utf-8", "replace").strip().splitlines()[-5:]
    msg = f"{shlex.join(prefix)} exited {rc}"
    if tail:
        msg += ":\n    " + "\n    ".join(tail)
    if b"No module named ngc" in stderr:
        msg += "\n    (install the package: pip install -e . -- or set PYTHONPATH=src)"
    return msg


def run_captured(prefix: list[str], program: Path, timeout_s: float | None) -> bytes:
    """Run once with output captured; return stdout or raise CommandError."""
    with private_home() as home:
        try:
            proc = subprocess.run(
                command_for(prefix, program),
                cwd=program.parent,
                env=child_env(home),
                stdin=subprocess.DEVNULL,
                capture_output=True,
                timeout=timeout_s,
                check=False,
            )
        except (OSError, subprocess.TimeoutExpired) as exc:
            raise CommandError(f"{shlex.join(prefix)}: {exc}") from exc
    if proc.returncode != 0:
        raise CommandError(describe_failure(prefix, proc.returncode, proc.stderr))
    return proc.stdout


def run_timed(prefix: list[str], program: Path, timeout_s: float | None) -> Timing:
    """Run once with output to /dev/null; return wall and child CPU time."""
    cmd = command_for(prefix, program)
    with private_home() as home:
        env = child_env(home)
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        try:
            proc = subprocess.run(
                cmd,
                cwd=program.parent,
                env=env,
                stdin=subprocess.DEVNULL,
                stdout=subprocess.DEVNULL,
                stderr=subprocess.DEVNULL,
                timeout=timeout_s,
                check=False,
            )
        except (OSError, subprocess.TimeoutExpired) as exc:
            raise CommandError(f"{shlex.join(prefix)}: {exc}") from exc
        wall_s = time.perf_counter() - t0
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode != 0:
        raise CommandError(f"{shlex.join(prefix)} exited {proc.returncode} during a timed run")
    cpu_s = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return Timing(wall_s=wall_s, cpu_s=cpu_s)


def normalize_stdout(data: bytes) -> list[bytes]:
    lines = data.split(b"\n")
    if lines and lines[-1] == b"":
        lines.pop()
    return [COUNTER_RE.sub(b"", line, count=1) for line in lines]


def first_difference(impl_out: bytes, ref_out: bytes) -> str:
    """Empty if the normalized outputs are identical, else where they first differ."""
    a, b = normalize_stdout(impl_out), normalize_stdout(ref_out)
    if a == b:
        return ""
    for n, (x, y) in enumerate(zip(a, b, strict=False), start=1):
        if x != y:
            return f"line {n}: impl {x[:80]!r} vs ref {y[:80]!r}"
    return f"impl printed {len(a)} lines, ref {len(b)}"


def benchmark_program(
    kind: str,
    lines: int,
    path: Path,
    impl: list[str],
    ref: list[str] | None,
    args: argparse.Namespace,
) -> ProgramResult:
    res = ProgramResult(kind=kind, lines=lines, path=str(path))
    log(f"{path.name}: checking outputs ...")
    try:
        impl_out = run_captured(impl, path, args.timeout)
        if ref is not None:
            res.ref = Side()
            res.difference = first_difference(impl_out, run_captured(ref, path, args.timeout))
            res.identical = not res.difference
        sides: list[tuple[list[str], Side]] = [(impl, res.impl)]
        if ref is not None and res.ref is not None:
            sides.append((ref, res.ref))
        for _ in range(args.warmup):
            for prefix, _side in sides:
                run_timed(prefix, path, args.timeout)
        for n in range(args.runs):
            log(f"{path.name}: run {n + 1}/{args.runs}")
            for prefix, side in sides:
                side.runs.append(run_timed(prefix, path, args.timeout))
    except CommandError as exc:
        res.error = str(exc)
    return res


# --------------------------------------------------------------------------
# reporting
# --------------------------------------------------------------------------


def log(msg: str) -> None:
    print(msg, file=sys.stderr, flush=True)


def machine_name() -> str:
    proc = platform.processor()
    if not proc:
        try:
            with open("/proc/cpuinfo", encoding="utf-8") as fh:
                for line in fh:
                    if line.startswith("model name"):
                        proc = line.split(":", 1)[1].strip()
                        break
        except OSError:
            pass
    return f"{proc or platform.machine()} ({os.cpu_count()} CPUs)"


def fmt_s(value: float | None) -> str:
    return "—" if value is None else f"{value:.3f}"


def fmt_ratio(res: ProgramResult) -> str:
    ratio = res.ratio()
    if ratio is None:
        return "n/a"
    text = f"{ratio:.2f}"
    return text if res.identical else f"{text} (!)"


def fmt_identical(res: ProgramResult) -> str:
    if res.identical is None:
        return "n/a (no rs274)"
    return "yes" if res.identical else "**no**"


def markdown_table(results: list[ProgramResult]) -> str:
    head = (
        "| program | lines | ngc wall s | ngc cpu s | rs274 wall s | rs274 cpu s "
        "| ratio (wall) | ratio (cpu) | outputs identical |\n"
        "|---|---:|---:|---:|---:|---:|---:|---:|---|\n"
    )
    rows = []
    for r in results:
        if r.error:
            rows.append(f"| {r.kind} | {r.lines} | failed | | | | | | |")
            continue
        ref_wall = r.ref.median_wall_s() if r.ref else None
        ref_cpu = r.ref.median_cpu_s() if r.ref else None
        cpu_ratio = r.ratio("cpu_s")
        rows.append(
            f"| {r.kind} | {r.lines} | {fmt_s(r.impl.median_wall_s())} "
            f"| {fmt_s(r.impl.median_cpu_s())} | {fmt_s(ref_wall)} | {fmt_s(ref_cpu)} "
            f"| {fmt_ratio(r)} | {'n/a' if cpu_ratio is None else f'{cpu_ratio:.2f}'} "
            f"| {fmt_identical(r)} |"
        )
    return head + "\n".join(rows) + "\n"


def notes(results: list[ProgramResult], ref_missing: str) -> list[str]:
    out = []
    if ref_missing:
        out.append(f"rs274 not found ({ref_missing}): ngc measured alone, ratio can't be computed.")
    for r in results:
        if r.error:
            out.append(f"{r.kind}-{r.lines}: FAILED: {r.error}")
        elif r.identical is False:
            out.append(
                f"{r.kind}-{r.lines}: outputs differ ({r.difference}); "
                "its speed figures are not comparable."
            )
    return out


def impl_python(impl: list[str]) -> str:
    """The Python that runs the ngc command: its version and where it is installed (a virtual
    environment's base).  The command's first word is taken as a Python, or as a script whose
    ``#!`` line names one; otherwise (a shim, a wrapper) the Python running this script."""
    interpreter = sys.executable
    program = shutil.which(impl[0]) if impl else None
    if program is not None:
        if Path(program).name.startswith("python"):
            interpreter = program
        else:
            try:
                with open(program, "rb") as fh:
                    first = fh.readline(512).decode("utf-8", "replace")
            except OSError:
                first = ""
            words = first[2:].split() if first.startswith("#!") else []
            if words and Path(words[0]).name.startswith("python"):
                interpreter = words[0]
    try:
        found = subprocess.run(
            [interpreter, "-c", "import platform, sys; print(platform.python_version(), sys.base_prefix)"],
            capture_output=True, text=True, timeout=30, check=True,
        ).stdout.split()
    except (OSError, subprocess.SubprocessError):
        return f"Python {platform.python_version()}"
    return f"Python {found[0]} ({found[1]})" if len(found) == 2 else f"Python {platform.python_version()}"


def meta(args: argparse.Namespace, impl: list[str], ref: list[str] | None) -> dict[str, Any]:
    return {
        "date": datetime.date.today().isoformat(),
        "machine": f"{machine_name()} / {impl_python(impl)}",
        "impl": shlex.join(impl),
        "ref": shlex.join(ref) if ref is not None else None,
        "lines": args.lines,
        "kinds": args.kinds,
        "runs": args.runs,
        "warmup": args.warmup,
    }


def report(
    info: dict[str, Any],
    table: str,
    results: list[ProgramResult],
    note_lines: list[str],
) -> str:
    """What is printed on stdout: a heading line, the table, the verdicts and the notes."""
    lines = [
        f"ngc: `{info['impl']}` vs rs274: `{info['ref'] or 'not found'}` -- {info['machine']}, "
        f"{info['lines']} lines, median of {info['runs']} runs",
        "",
        table.rstrip("\n"),
        "",
    ]
    lines += [
        f"{r.kind}: outputs identical: {'yes' if r.identical else 'NO'}"
        for r in results
        if r.identical is not None and not r.error
    ]
    lines += note_lines
    return "\n".join(lines) + "\n"


def results_section(info: dict[str, Any], table: str, note_lines: list[str]) -> str:
    ref = f"`{info['ref']} FILE`" if info["ref"] else "(rs274 not found)"
    body = [
        f"## {info['date']} — {info['machine']}",
        "",
        f"- ngc: `{info['impl']} FILE`; rs274: {ref}",
        f"- lines: {info['lines']}; {info['runs']} alternated A/B runs after "
        f"{info['warmup']} warm-up each; times are medians",
        "",
        table.rstrip("\n"),
    ]
    body += ["", *(f"- {n}" for n in note_lines)] if note_lines else []
    return "\n".join(body) + "\n"


def write_results(path: Path, info: dict[str, Any], section: str) -> None:
    """Append the section to RESULTS.md, replacing an earlier one with the same key."""
    key_src = json.dumps([info[k] for k in ("date", "machine", "impl", "ref", "kinds", "lines")])
    key = hashlib.sha1(key_src.encode()).hexdigest()[:12]
    begin, end = f"<!-- bench-result {key} -->", f"<!-- /bench-result {key} -->"
    block = f"{begin}\n{section}{end}\n"
    text = path.read_text(encoding="utf-8") if path.is_file() else RESULTS_HEADER
    start = text.find(begin)
    stop = text.find(end, start) if start >= 0 else -1
    if start >= 0 and stop >= 0:
        text = text[:start] + block + text[stop + len(end) :].lstrip("\n")
    else:
        text = text.rstrip("\n") + "\n\n" + block
    path.write_text(text, encoding="utf-8")


# --------------------------------------------------------------------------
# main
# --------------------------------------------------------------------------


def parse_args(argv: list[str] | None) -> argparse.Namespace:
    ap = argparse.ArgumentParser(
        description="Benchmark ngc rs274 -g against LinuxCNC's rs274 -g (ratio = ref/impl)."
    )
    ap.add_argument(
        "--impl",
        default="ngc rs274 -g",
        help="implementation command, the file is appended (default: %(default)s)",
    )
    ap.add_argument(
        "--ref",
        default="rs274 -g",
        help="reference command, the file is appended (default: %(default)s)",
    )
    ap.add_argument(
        "--kinds",
        default="surface,contour,macro",
        help=f"comma-separated program kinds of {','.join(KINDS)} (default: %(default)s)",
    )
    ap.add_argument(
        "--lines", type=int, default=200_000, help="program size (default: %(default)s)"
    )
    ap.add_argument("--runs", type=int, default=5, help="timed runs per command (default: 5)")
    ap.add_argument("--warmup", type=int, default=1, help="discarded runs per command (default: 1)")
    ap.add_argument("--timeout", type=float, default=None, help="seconds allowed per run")
    ap.add_argument(
        "--shared",
        type=Path,
        default=DEFAULT_SHARED,
        help="the shared directory holding bench/benchgen.py (default: ../shared)",
    )
    ap.add_argument(
        "--out-dir",
        type=Path,
        default=DEFAULT_OUT_DIR,
        help="where generated programs go (default: benchmarks/out)",
    )
    ap.add_argument("--write", action="store_true", help="append/update benchmarks/RESULTS.md")
    ap.add_argument("--results", type=Path, default=DEFAULT_RESULTS, help=argparse.SUPPRESS)
    ap.add_argument("--json", type=Path, metavar="OUT", help="also write the raw results as JSON")
    args = ap.parse_args(argv)
    kinds = [k for k in args.kinds.split(",") if k]
    bad = [k for k in kinds if k not in KINDS]
    if bad or not kinds:
        ap.error(f"--kinds: unknown kind(s) {bad}; choose from {','.join(KINDS)}")
    if args.lines <= 0 or args.runs <= 0 or args.warmup < 0:
        ap.error("--lines and --runs must be positive, --warmup not negative")
    args.kind_list = kinds
    return args


def resolve(cmd: str) -> tuple[list[str], str]:
    """Split a command; return it and '' if its program exists, else why not."""
    argv = shlex.split(cmd)
    if not argv:
        return argv, "empty command"
    if shutil.which(argv[0]) is None:
        return argv, f"{argv[0]!r} is not on PATH"
    return argv, ""


def main(argv: list[str] | None = None) -> int:
    args = parse_args(argv)
    impl, impl_missing = resolve(args.impl)
    if impl_missing:
        hint = ""
        if impl and impl[0] == "ngc":
            hint = " -- install ngc (pip install -e .) or use --impl 'python -m ngc rs274 -g'"
        log(f"bench.py: cannot run the implementation: {impl_missing}{hint}")
        return 1
    ref: list[str] | None
    ref, ref_missing = resolve(args.ref)
    if ref_missing:
        log(f"bench.py: reference not found ({ref_missing}); measuring the implementation alone")
        ref = None

    programs = [
        (k, ensure_program(args.shared, args.out_dir, k, args.lines)) for k in args.kind_list
    ]
    results = [benchmark_program(k, args.lines, p, impl, ref, args) for k, p in programs]

    info = meta(args, impl, ref)
    table = markdown_table(results)
    note_lines = notes(results, ref_missing)
    print(report(info, table, results, note_lines), end="")
    if args.write:
        write_results(args.results, info, results_section(info, table, note_lines))
        log(f"bench.py: updated {args.results}")
    if args.json:
        payload = {
            **info,
            "programs": [
                {
                    **asdict(r),
                    "ratio_wall": r.ratio("wall_s"),
                    "ratio_cpu": r.ratio("cpu_s"),
                    "pair_ratios_wall": r.pair_ratios("wall_s"),
                }
                for r in results
            ],
        }
        args.json.write_text(json.dumps(payload, indent=2) + "\n", encoding="utf-8")
    return 1 if any(r.error for r in results) else 0


if __name__ == "__main__":
    sys.exit(main())
