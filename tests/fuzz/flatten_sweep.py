#!/usr/bin/env python3
"""``ngc flatten`` checked with LinuxCNC's ``rs274``: the program written out runs in rs274 with
the machine path of the original.

    python tests/fuzz/flatten_sweep.py --conformance [--cases GLOB] [--jobs 2]
    python tests/fuzz/flatten_sweep.py --kinds motion,offsets --count 350 --seed 1 [--jobs 2]
    python tests/fuzz/flatten_sweep.py --programs motion:19,conformance:interp-g71-with-g70

Each program (a conformance case that rs274 runs to the end, or a program of tests/fuzz/gen.py)
is run by ``rs274 -g`` with its inputs (``-t``, ``-v``, ``-i``: each run on fresh copies, rs274
writes the parameter file back); flattened in this process as ``ngc flatten`` does it (the same
inputs, :func:`ngc.flatten.flatten` with its own verification); the written program is checked
to be plain (:func:`not_plain`) and run by rs274 with the same inputs.  Both transcripts are
read back into machine paths (tests/fuzz/canon_read.py) and compared move by move
(:func:`compare_runs`).

How close is the same: every number rs274 prints is rounded to four decimals in the units of
its time, and the program written is rounded to the target's decimals.  A move's end may differ
on each coordinate by the sum of the rounding bounds of the two transcripts (canon_read.Bound:
the move's own print, the offsets' prints, the rotation's print) and half a unit of the last
decimal written (``W``).  An arc keeps its axis, direction and turns; its path (each of 32
points of one arc measured to the other, both ways) may differ by :data:`ARC_SHAPE` times the
larger bound of its start and end (an arc made from printed numbers runs that far from the
true one at most); its centre, by the same bound with ``W`` once (the centre written is the
start as written plus I J K rounded) across the axis, else it is counted as moved (a nearly
straight arc's centre slides far for a small change of its ends).  An arc whose printed start
and end are a rounding apart may end a whole turn or a sliver (the prints cannot tell): either
is taken, and counted.  A curve (or arc) written as lines must stay within ngc flatten's
tolerance (0.002 mm) plus the bounds; a straight move of no length (within its transcript's
rounding) that one side has and the other not is left out, and counted.

Outcomes: ``same path``; ``refused`` (ngc flatten's reason); ``ngc error`` (ngc stops where
rs274 ran to the end); ``not verified`` (ngc flatten's own verification failed); ``not plain``;
``rs274 error`` (rs274 stops in the written program); ``path differs``; ``ngc != rs274`` (a
difference or an error that starts in ngc's own reading of the original: ``ngc rs274``'s path of
it is not rs274's, a matter for the interpreter, not the writer); for the generated programs
also ``original fails`` (rs274 does not run the original to the end: nothing to compare) and
``rs274 hung``.  The summary gives them by kind, the refusals by reason, the worst
deviations, and each failure; ``--out`` keeps the programs of each failure.  Exit status 1 if
anything failed.
"""

from __future__ import annotations

import argparse
import contextlib
import dataclasses
import fnmatch
import inspect
import json
import math
import multiprocessing
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import traceback
from collections import Counter
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, NamedTuple

HERE = Path(__file__).resolve().parent
if str(HERE) not in sys.path:
    sys.path.insert(0, str(HERE))

import canon_read  # noqa: E402
import gen  # noqa: E402
import run as fuzzrun  # noqa: E402  (sets the paths of src/ and tests/golden/)

from ngc.canon import ops  # noqa: E402
from ngc.flatten.curves import ArcShape, arc_points  # noqa: E402
from ngc.flatten.targets import TARGETS  # noqa: E402
from ngc.flatten.verify import CURVE  # noqa: E402
from ngc.render import curves  # noqa: E402
from ngc.toolpath.tracker import ARC, FEED, RAPID  # noqa: E402

CONFORMANCE = Path("/work/shared/conformance/cases")
META_FILES = {"case.json", "expected.out", "expected.err", "expected.rc"}
DEFAULT_OUT = HERE / "found" / "flatten"
TIMEOUT_S = 20.0
FLATTEN_TIMEOUT_S = 120.0
FLAT_NAME = "flat.ngc"
CURVE_TOLERANCE_MM = 0.002  # ngc flatten's --tolerance: lines for a curve stay this close
ARC_AXIS = 1e-9  # two arcs' axes (unit vectors) that are the same
SQRT2, SQRT3 = math.sqrt(2.0), math.sqrt(3.0)
# How far an arc made from printed numbers (start, end, centre, each off by up to b on a
# coordinate) may run from the true one, in b: the centre across the axis by sqrt 2, each radius
# by the start's (or end's) sqrt 3 and the centre's sqrt 2, the angle along by as much again.
ARC_SHAPE = 2.0 * (SQRT2 + SQRT3)

SAME = "same path"
REFUSED = "refused"
NGC_ERROR = "ngc error"
NOT_VERIFIED = "not verified"
NOT_PLAIN = "not plain"
RS274_ERROR = "rs274 error"
DIFFERS = "path differs"
ORIGINAL_FAILS = "original fails"
HUNG = "rs274 hung"
INTERNAL = "internal error"
NGC_OTHERWISE = "ngc != rs274"
OUTCOMES = (SAME, REFUSED, NGC_ERROR, NOT_VERIFIED, NOT_PLAIN, RS274_ERROR, DIFFERS,
            NGC_OTHERWISE, ORIGINAL_FAILS, HUNG, INTERNAL)
FAILURES = (NGC_ERROR, NOT_VERIFIED, NOT_PLAIN, RS274_ERROR, DIFFERS, NGC_OTHERWISE, INTERNAL)

# rs274's options that take a value (its usage line); the first other word is the program
VALUED = frozenset({"-p", "-t", "-v", "-n", "-i", "-l"})


# -- the programs -----------------------------------------------------------------------------


class Program(NamedTuple):
    """A program to sweep: its kind (``conformance`` or a generator's), its name (the case or
    the seed), its files (name -> bytes, the program among them), the arguments rs274 takes and
    the index of the program's name among them."""

    kind: str
    name: str
    files: dict[str, bytes]
    args: list[str]
    program: int


def program_index(args: list[str]) -> int:
    """Where the input file is among rs274's arguments."""
    i = 0
    while i < len(args):
        if args[i] in VALUED:
            i += 2
        elif args[i].startswith("-"):
            i += 1
        else:
            return i
    raise ValueError(f"no program among {args}")


def case_files(folder: Path) -> dict[str, bytes]:
    files = {}
    for path in sorted(folder.rglob("*")):
        if path.is_file() and path.relative_to(folder).parts[0] not in META_FILES:
            files[str(path.relative_to(folder))] = path.read_bytes()
    return files


def conformance_program(folder: Path) -> Program:
    args = list(json.loads((folder / "case.json").read_text(encoding="utf-8"))["args"])
    return Program("conformance", folder.name, case_files(folder), args, program_index(args))


def generated_program(kind: str, seed: int) -> Program:
    text = gen.generate(kind, seed)
    files = {fuzzrun.PROGRAM_NAME: text.encode("latin-1")}
    table = gen.table_of(text)
    if table is not None:
        files[gen.TABLE_NAME] = table.encode("latin-1")
    args = fuzzrun.arguments(text)
    return Program(kind, str(seed), files, args, program_index(args))


def conformance_cases(root: Path, globs: list[str]) -> list[Path]:
    """The cases rs274 runs to the end (expected exit 0)."""
    found = []
    for folder in sorted(p for p in root.iterdir() if (p / "case.json").is_file()):
        if globs and not any(fnmatch.fnmatchcase(folder.name, g) for g in globs):
            continue
        if (folder / "expected.rc").read_text().strip() == "0":
            found.append(folder)
    return found


# -- running ----------------------------------------------------------------------------------


class Rs274(NamedTuple):
    out: str
    err: list[str]  # the lines other than "executing"
    rc: int
    timed_out: bool


@contextlib.contextmanager
def workspace(files: dict[str, bytes]) -> Iterator[Path]:
    """A fresh folder holding the files (and a private HOME beside it: rs274 keeps its tool
    table in $HOME/.tool.mmap)."""
    with tempfile.TemporaryDirectory(prefix="ngc-flatten-sweep-") as tmp:
        work = Path(tmp) / "work"
        for name, data in files.items():
            path = work / name
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_bytes(data)
        (Path(tmp) / "home").mkdir()
        yield work


def run_rs274(rs274: str, files: dict[str, bytes], args: list[str]) -> Rs274:
    with workspace(files) as work:
        try:
            proc = subprocess.run([rs274, *args], cwd=work,
                                  env=fuzzrun.child_env(work.parent / "home"),
                                  stdin=subprocess.DEVNULL, capture_output=True,
                                  timeout=TIMEOUT_S)
        except subprocess.TimeoutExpired:
            return Rs274("", [], -1, True)
    err = [line for line in proc.stderr.decode("latin-1").splitlines() if line != "executing"]
    return Rs274(proc.stdout.decode("latin-1"), err, proc.returncode, False)


def ngc_transcript(program: Program) -> str:
    """``ngc rs274`` on the original, in this process, as rs274 runs it (its transcript)."""
    import io

    from ngc.commands import rs274

    out, err = io.StringIO(), io.StringIO()
    old, home = os.getcwd(), os.environ.get("HOME")
    with workspace(program.files) as work:
        os.chdir(work)
        os.environ["HOME"] = str(work.parent / "home")
        try:
            rs274.run(program.args, stdout=out, stderr=err)
        finally:
            os.chdir(old)
            if home is not None:
                os.environ["HOME"] = home
    return out.getvalue()


class _Timeout(Exception):
    pass


def _alarm(signum: int, frame: object) -> None:
    raise _Timeout


class _Curves:
    """A canon sink in front of another that keeps the NURBS calls (rs274 prints only their
    number of points)."""

    def __init__(self, sink: Any, kept: list[ops.NurbsFeed]) -> None:
        self.sink = sink
        self.kept = kept
        self.emit_move = sink.emit_move
        self.print_text = sink.print_text
        self.flush = sink.flush

    def emit(self, op: Any, label: str, line: int) -> None:
        if type(op) is ops.NurbsFeed:
            self.kept.append(op)
        self.sink.emit(op, label, line)


def _serial() -> dict[str, bool]:
    """flatten's verification in this process: the sweep's workers take the cores already,
    and a pool's worker may not start processes of its own."""
    from ngc.flatten import flatten

    return {"parallel": False} if "parallel" in inspect.signature(flatten).parameters else {}


_SERIAL = _serial()


class Flat(NamedTuple):
    """ngc flatten's outcome: the text written (or None), the NURBS calls of the original run,
    and what went wrong (an outcome and its text) if anything."""

    text: str | None
    curves: list[ops.NurbsFeed]
    outcome: str | None
    detail: str


def run_flatten(program: Program, target: str, inch: bool) -> Flat:
    """``ngc flatten`` in this process, in a fresh copy of the inputs, as the command does it
    (:mod:`ngc.commands.flatten_run`), with a time limit."""
    from ngc.errors import NgcConfigError, NgcError
    from ngc.flatten import Refused, flatten
    from ngc.options import MachineOptions, load_setup, new_interpreter

    args = program.args
    value = {args[i]: args[i + 1] for i in range(len(args) - 1) if args[i] in VALUED}
    name = args[program.program]
    curves: list[ops.NurbsFeed] = []
    old = os.getcwd()
    with workspace(program.files) as work:
        os.chdir(work)
        previous = signal.signal(signal.SIGALRM, _alarm)
        signal.setitimer(signal.ITIMER_REAL, FLATTEN_TIMEOUT_S)
        try:
            machine = MachineOptions(ini_file=value.get("-i"), tool_table=value.get("-t"),
                                     var_file=value.get("-v"), program_file=name)
            setup = load_setup(machine)
            text = Path(name).read_bytes().decode("utf-8", "surrogateescape").removeprefix(
                "\ufeff")
            made = []

            def factory(sink: Any) -> Any:
                if not made:  # (the original's run; the second is the verification's)
                    sink = _Curves(sink, curves)
                made.append(sink)
                return new_interpreter(sink, machine, setup, block_delete="-b" in args,
                                       write_files=False)

            result = flatten(text, name, factory, target=target, inch=inch, **_SERIAL)
        except Refused as exc:
            return Flat(None, curves, REFUSED, exc.reason)
        except NgcConfigError as exc:
            return Flat(None, curves, NGC_ERROR, f"inputs: {exc.message}")
        except NgcError as exc:
            detail = exc.render().splitlines()[0].replace(str(work) + os.sep, "")
            if value.get("-n") == "0":
                detail += " (rs274 runs it with -n 0: on past its errors)"
            return Flat(None, curves, NGC_ERROR, detail)
        except _Timeout:
            return Flat(None, curves, INTERNAL, f"ngc flatten took over {FLATTEN_TIMEOUT_S:g}s")
        except Exception:
            return Flat(None, curves, INTERNAL, traceback.format_exc())
        finally:
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, previous)
            os.chdir(old)
    checked = result.verified
    if checked is not None and (checked.difference is not None
                                or checked.deviation > CURVE_TOLERANCE_MM):
        what = checked.difference or f"deviation {checked.deviation:.6f} mm"
        return Flat(result.text, curves, NOT_VERIFIED, what)
    return Flat(result.text, curves, None, "")


# -- plain ------------------------------------------------------------------------------------

_COMMENT = re.compile(r"\([^()]*\)")
_WORDS = re.compile(r"(?:\s*[A-Z][-+]?(?:\d+\.?\d*|\.\d+))*\s*")
_WORD = re.compile(r"([A-Z])([-+]?(?:\d+\.?\d*|\.\d+))")
# what a plain program says: moves G0-G3 and spindle-synchronised G33 / G33.1, the dwell,
# planes, units, modes, the work offsets, a table tool's length, blending; spindle (G96 D S,
# G97, M19 R Q P), coolant, tool change, stops, the end and the outputs
PLAIN_G = frozenset({"0", "1", "2", "3", "4", "17", "18", "19", "20", "21", "33", "33.1", "40",
                     "43", "43.1", "49", "54", "55", "56", "57", "58", "59", "59.1", "59.2",
                     "59.3", "61", "61.1", "64", "80", "90", "91.1", "94", "95", "96", "97"})
PLAIN_M = frozenset({"0", "1", "2", "3", "4", "5", "6", "7", "8", "9", "19", "30", "60", "61",
                     "62", "63", "64", "65", "67", "68"})
PLAIN_LETTERS = frozenset("XYZABCIJKPQFSTHE")
# letters plain only beside a code: G96's D (the spindle's top speed), M19's R (its angle)
PLAIN_BESIDE = {"D": ("G", "96"), "R": ("M", "19")}
# comments rs274 acts on (rs274ngc.adoc, "Comments"; its name then the comma at once, as rs274
# reads them: "(print ,x)" is a comment): MSG is written on purpose
ACTIVE_COMMENT = re.compile(r"\(\s*(?:(?:debug|print|log|logopen|logappend|probeopen),|"
                            r"(?:logclose|probeclose)\s*\))", re.IGNORECASE)


def _code(number: str) -> str:
    value = float(number)
    return f"{value:g}" if value != int(value) else str(int(value))


def not_plain(text: str) -> str | None:
    """Why the written program is not plain (its first such line), or None."""
    for n, line in enumerate(text.splitlines(), 1):
        active = ACTIVE_COMMENT.search(line)
        if active:
            return f"line {n}: an active comment: {line}"
        bare = _COMMENT.sub(" ", line)
        if "(" in bare or ")" in bare or ";" in bare:
            return f"line {n}: a comment not closed or nested: {line}"
        if bare.strip() == "%":
            continue
        if not _WORDS.fullmatch(bare):
            return f"line {n}: not words alone: {line}"
        words = [(letter, _code(number) if letter in "GM" else number)
                 for letter, number in _WORD.findall(bare)]
        for letter, number in words:
            if letter == "G" and number not in PLAIN_G:
                return f"line {n}: G{number}: {line}"
            if letter == "M" and number not in PLAIN_M:
                return f"line {n}: M{number}: {line}"
            if (letter not in "GM" and letter not in PLAIN_LETTERS
                    and PLAIN_BESIDE.get(letter) not in words):
                return f"line {n}: the word {letter}{number}: {line}"
    return None


# -- comparing --------------------------------------------------------------------------------


class Written(NamedTuple):
    """Half a unit of the last decimal the program is written with: mm, and degrees."""

    linear: float
    angle: float


def written_rounding(target: str, inch: bool) -> Written:
    """(A target that keeps to so many significant digits writes fewer decimals only past
    10 ** (digits - decimals) units: 100 m for Grbl's 8 and 3.)"""
    row = TARGETS[target]
    decimals = row.decimals_inch if inch else row.decimals_mm
    half = 0.5 * 10.0 ** -decimals
    return Written(half * (25.4 if inch else 1.0), half)


class Compared(NamedTuple):
    """The written run's path against the original's: the moves compared, the largest
    distance of an end (mm, on one coordinate), the largest ratio of a distance to its bound,
    the arcs whose centre moved past its bound while their path stayed within it (and the
    largest such move, mm), the moves of no length left out of each, the arcs taken as whole
    turns (their printed end a rounding off their start), the largest distance of lines
    written for a curve or an arc from it (mm), and the first difference."""

    moves: int
    worst: float
    ratio: float
    centres: int
    centre_worst: float
    idle: tuple[int, int]
    whole_turns: int
    curve_worst: float
    difference: str | None


@dataclass
class _Tally:
    worst: float = 0.0
    ratio: float = 0.0
    centres: int = 0
    centre_worst: float = 0.0
    whole_turns: int = 0
    curve_worst: float = 0.0


def _limits(a: canon_read.Bound, b: canon_read.Bound, w: Written) -> list[float]:
    xy, z, angle = a.xy + b.xy + w.linear, a.z + b.z + w.linear, a.angle + b.angle + w.angle
    return [xy, xy, z, angle, angle, angle]


def _check_pair(m: Any, n: Any, limits: list[float], shape: float, w: Written,
                tally: _Tally) -> str | None:
    """Compare two moves meant to be the same: their ends within ``limits``, an arc's path
    within ``shape`` on a coordinate (the bound of its start and of its end, the larger); what
    differs, or None."""
    if m[0] != n[0] or m[3] != n[3]:
        turns = (f" of {m[3]} turns", f" of {n[3]} turns") if m[0] == ARC == n[0] else ("", "")
        return f"a {m[0]}{turns[0]} became a {n[0]}{turns[1]}"
    for k in range(6):
        d = abs(m[1][k] - n[1][k])
        if k < 3:
            tally.worst = max(tally.worst, d)
        if d > limits[k]:
            return f"the end is off by {d:.6f} on {'XYZABC'[k]} (bound {limits[k]:.6f})"
        if limits[k] > 0.0:
            tally.ratio = max(tally.ratio, d / limits[k])
    if m[0] != ARC or m[5] is None or n[5] is None:
        return None
    if math.dist(m[5], n[5]) > ARC_AXIS:
        return "the arc turns about another axis or the other way"
    if m[6] is None or n[6] is None:
        return None
    path_limit = ARC_SHAPE * shape
    path = _path_gap(m[6], n[6])
    if path > path_limit:
        path = _path_gap(m[6], n[6], near=True)
    if path > path_limit:
        # (a whole turn whose end, printed, is a rounding away from its start reads as a
        # sliver: what the prints cannot tell apart is taken as the whole turn on both sides)
        whole = [_whole_turn(arc, shape) for arc in (m[6], n[6])]
        if any(x is not arc for x, arc in zip(whole, (m[6], n[6]), strict=True)):
            path = min(path, _path_gap(*whole, near=True))
            tally.whole_turns += path <= path_limit
    if path > path_limit:
        return f"the arc's path is off by {path:.6f} (bound {path_limit:.6f})"
    tally.ratio = max(tally.ratio, path / path_limit)
    across = SQRT2 * max(limits[:3])
    gap = _axis_gap(m, n)
    if gap > across:
        tally.centres += 1
        tally.centre_worst = max(tally.centre_worst, gap)
    else:
        tally.ratio = max(tally.ratio, gap / across)
    return None


def _frame(arc: Any) -> curves.Frame:
    return curves.frame(arc.start, arc.end, arc.centre, arc.normal, arc.turns)


def _path_gap(m: Any, n: Any, near: bool = False) -> float:
    f, g = _frame(m), _frame(n)
    return max(_off_arc(f, g, near=near), _off_arc(g, f, near=near))


def _whole_turn(arc: Any, bound: float) -> Any:
    """The arc with its end on its start's line along the axis, if the two are within twice
    the bound of each other across it (else the arc itself)."""
    d = [arc.end[i] - arc.start[i] for i in range(3)]
    rise = sum(d[i] * arc.normal[i] for i in range(3))
    across = [d[i] - rise * arc.normal[i] for i in range(3)]
    if math.hypot(*across) > 2.0 * bound:
        return arc
    end = tuple(arc.start[i] + rise * arc.normal[i] for i in range(3)) + tuple(arc.end[3:])
    return ArcShape(arc.start, end, arc.centre, arc.normal, arc.turns)


def _off_arc(f: curves.Frame, g: curves.Frame, samples: int = 32, near: bool = False) -> float:
    """How far the arc ``g`` (its points at ``samples`` steps) strays from the arc ``f``: the
    distance of each from the point of ``f`` at the same angle about its axis (or from an end
    of ``f``), at most; ``near``: from the nearest point of ``f`` about there (a steep helix
    runs close to itself at an angle a little off)."""
    worst = 0.0
    for k in range(samples + 1):
        p = g.point(g.sweep * k / samples)
        worst = max(worst, _to_arc(f, p, near))
    return worst


def _to_arc(f: curves.Frame, p: Any, near: bool) -> float:
    v = (p[0] - f.centre[0], p[1] - f.centre[1], p[2] - f.centre[2])
    angle = math.atan2(sum(v[i] * f.e2[i] for i in range(3)),
                       sum(v[i] * f.e1[i] for i in range(3))) % curves.TAU
    best = min(math.dist(p, f.point(0.0)), math.dist(p, f.point(f.sweep)))
    t = angle
    while t <= f.sweep:
        best = min(best, _nearest_on(f, p, t) if near else math.dist(p, f.point(t)))
        t += curves.TAU
    return best


def _nearest_on(f: curves.Frame, p: Any, t: float, width: float = 0.5) -> float:
    """The distance of ``p`` from ``f`` near its angle ``t`` (within ``width`` radians, on the
    arc): a golden-section search."""
    lo, hi = max(0.0, t - width), min(f.sweep, t + width)
    ratio = (math.sqrt(5.0) - 1.0) / 2.0
    for _ in range(60):
        x1, x2 = hi - ratio * (hi - lo), lo + ratio * (hi - lo)
        if math.dist(p, f.point(x1)) < math.dist(p, f.point(x2)):
            hi = x2
        else:
            lo = x1
    return min(math.dist(p, f.point(0.5 * (lo + hi))), math.dist(p, f.point(t)))


def _axis_gap(m: Any, n: Any) -> float:
    """How far apart the axes of two arcs about parallel axes are (their centres, less the part
    along the axis: a helix's centre may be given at any height)."""
    c, d, axis = m[2], n[2], m[5]
    gap = [c[i] - d[i] for i in range(3)]
    along = sum(gap[i] * axis[i] for i in range(3))
    return math.sqrt(sum((gap[i] - along * axis[i]) ** 2 for i in range(3)))


def _follow(points: list[Any], b: list[Any], j: int, tolerance: float,
            angle: float) -> tuple[int, float, str | None]:
    """Follow the curve through ``points`` (its start first) along the straight feeds of ``b``
    from ``j`` to its end.  Each line's end stands at the point of the curve nearest to it
    within the stretch the line can cover (from where the line before stood, as far along the
    curve as half again the line's length and some tolerance); that point and the curve's
    points the line passes are measured to the line, its A B C to the curve's.  The index
    after the last line, the largest distance, and what went wrong if anything."""
    last, at, worst = len(points) - 1, 0, 0.0
    along = [0.0]
    for k in range(1, len(points)):
        along.append(along[-1] + math.dist(points[k - 1][:3], points[k][:3]))
    previous = points[0]
    while True:
        if j >= len(b) or b[j][0] != FEED:
            kind = "nothing" if j >= len(b) else f"a {b[j][0]}"
            return j, worst, f"a curve became {kind} before its end"
        q = b[j][1]
        reach = along[at] + 1.5 * math.dist(previous[:3], q[:3]) + 10.0 * tolerance
        k, best = at, math.inf
        for i in range(at, len(points)):
            if along[i] > reach:
                break
            d = math.dist(points[i][:3], q[:3])
            if d <= best:  # (of points as near, the later: a sliver's end is its start)
                k, best = i, d
        if k != last and along[last] <= tolerance and _ends_near(points[last], b, j, tolerance):
            k = last  # (a curve within the tolerance of its start, a sliver whose printed start
            # and end are a rounding apart: the last of the lines that end within the tolerance
            # of its end ends it)
        gap = min(_to_segment(q, points[max(k - 1, 0)], points[k]),
                  _to_segment(q, points[k], points[min(k + 1, last)]))
        for p in points[at + 1:k]:
            gap = max(gap, _to_segment(p, previous, q))
        worst = max(worst, gap)
        j += 1
        if gap > tolerance:
            return j, worst, f"a line leaves the curve by {gap:.6f} (bound {tolerance:.6f})"
        turned = max(abs(q[i] - points[k][i]) for i in (3, 4, 5))
        if turned > angle:
            return j, worst, f"a line's A B C are off the curve's by {turned:.6f}"
        if k == last:
            return j, worst, None
        previous, at = q, k


def _ends_near(end: Any, b: list[Any], j: int, tolerance: float) -> bool:
    """The straight feed ``b[j]`` ends within ``tolerance`` of ``end`` and the move after it
    does not (it is the last of the lines there)."""
    if math.dist(end[:3], b[j][1][:3]) > tolerance:
        return False
    after = b[j + 1] if j + 1 < len(b) else None
    return after is None or after[0] != FEED or math.dist(end[:3], after[1][:3]) > tolerance


def _to_segment(p: Any, a: Any, b: Any) -> float:
    """The distance of ``p`` from the segment ``a`` ``b`` (X Y Z)."""
    d = [b[i] - a[i] for i in range(3)]
    w = [p[i] - a[i] for i in range(3)]
    dd = sum(v * v for v in d)
    t = 0.0 if dd == 0.0 else max(0.0, min(1.0, sum(w[i] * d[i] for i in range(3)) / dd))
    return math.dist(p[:3], [a[i] + t * d[i] for i in range(3)])


def _joined(a: Any, b: list[Any], j: int) -> tuple[Any, int]:
    """``b[j]`` (and the index after it), or the run of one-turn arcs from ``j`` a target
    without P wrote for ``a``'s arc of several turns, as one arc."""
    k, n = a[3], b[j]
    if not (a[0] == ARC and k > 1 and n[0] == ARC and n[3] == 1):
        return n, j + 1
    run = b[j:j + k]
    if len(run) == k and all(r[0] == ARC and r[3] == 1 and r[5] == n[5]
                             and _axis_gap(r, n) < 1e-6 for r in run):
        return (ARC, run[-1][1], n[2], k, n[4], n[5], None, n[7]), j + k
    return n, j + 1


def _idle(run: canon_read.Run, k: int) -> bool:
    """A straight move of no length, but for the rounding of the two points its transcript
    printed (rs274's G7x cycles make or leave out such feeds by rounding noise, see
    tests/fuzz/README.md, ``lathejob``; and a move of a few microns in an inch program may be
    written as none)."""
    move, bound = run.moves[k], run.bounds[k]
    if move[0] not in (RAPID, FEED) or k == 0:
        return False
    before = run.moves[k - 1][1]
    limits = (2 * bound.xy, 2 * bound.xy, 2 * bound.z, *(3 * (2 * bound.angle,)))
    return all(abs(move[1][i] - before[i]) <= limits[i] for i in range(6))


def _follow_move(m: Any, b: list[Any], j: int, span: float, angle: float,
                 tally: _Tally) -> tuple[int, str | None]:
    """A curve, or an arc, of the original written as straight lines: followed along its
    points.  The curve's points are ngc's, from its control points: the bound of the curve's
    frame (sqrt 3 on a coordinate) beside the tolerance.  An arc's are made from printed numbers
    (:data:`ARC_SHAPE`); one whose printed start and end are a rounding apart may end a whole
    turn or a sliver past its last full turn (the prints cannot tell): either is taken."""
    if m[0] == CURVE:
        shapes, tolerance = [m[6]], CURVE_TOLERANCE_MM + SQRT3 * span
    else:
        arc, tolerance = m[6], CURVE_TOLERANCE_MM + ARC_SHAPE * span
        whole = _whole_turn(arc, span)
        shapes = [[arc.start, *arc_points(arc, CURVE_TOLERANCE_MM * 0.02)]]
        if whole is not arc:
            shapes.append([arc.start, *arc_points(whole, CURVE_TOLERANCE_MM * 0.02)])
            turns = abs(arc.turns)
            if turns > 1:  # (a turn less and a sliver)
                fewer = whole._replace(turns=(turns - 1) * (1 if arc.turns > 0 else -1))
                shapes.append([arc.start, *arc_points(fewer, CURVE_TOLERANCE_MM * 0.02)])
            else:
                shapes.append([arc.start, arc.end])
    first: tuple[int, str | None] | None = None
    for k, points in enumerate(shapes):
        after, deviation, followed = _follow(points, b, j, tolerance, angle)
        if followed is None:
            tally.curve_worst = max(tally.curve_worst, deviation)
            tally.ratio = max(tally.ratio, deviation / tolerance)
            tally.whole_turns += k > 0
            return after, None
        first = first or (after, followed)
    assert first is not None
    return first


def compare_runs(a: canon_read.Run, b: canon_read.Run, w: Written) -> Compared:
    """The written program's path ``b`` against the original's ``a``: one move for one, but
    for a curve (or an arc) written as straight lines, followed along its points, an arc of
    several turns written one turn an arc, and moves of no length (:func:`_idle`) on either
    side that the other does not have."""
    tally = _Tally()
    idle = [0, 0]
    i = j = 0

    def done(difference: str | None) -> Compared:
        return Compared(i, tally.worst, tally.ratio, tally.centres, tally.centre_worst,
                        (idle[0], idle[1]), tally.whole_turns, tally.curve_worst, difference)

    while i < len(a.moves) or j < len(b.moves):
        difference = "the moves differ in number"
        if i < len(a.moves) and j < len(b.moves):
            m, n = a.moves[i], b.moves[j]
            limits = _limits(a.bounds[i], b.bounds[j], w)
            # (an arc or a curve starts where the move before ended: its bound counts too)
            span = max(max(limits[:3]), max(_limits(a.bounds[i - 1], b.bounds[j - 1], w)[:3])
                        if i and j else 0.0)
            if (m[0] == CURVE and n[0] != CURVE) or (m[0] == ARC and n[0] == FEED):
                after, followed = _follow_move(m, b.moves, j, span, limits[3], tally)
                if followed is not None:
                    return done(_where(a, b, i, min(after, len(b.moves) - 1), followed))
                i, j = i + 1, after
                continue
            n, after = _joined(m, b.moves, j)
            trial = dataclasses.replace(tally)
            found = _check_pair(m, n, limits, span, w, trial)
            if found is None:
                tally = trial
                i, j = i + 1, after
                continue
            difference = found
        if i < len(a.moves) and _idle(a, i):
            idle[0] += 1
            i += 1
        elif j < len(b.moves) and _idle(b, j):
            idle[1] += 1
            j += 1
        else:
            if difference == "the moves differ in number":
                difference += (f": {len(a.moves) - i} more of the original's, "
                               f"{len(b.moves) - j} more of the written")
            at = min(i, len(a.moves) - 1), min(j, len(b.moves) - 1)
            return done(_where(a, b, *at, difference))
    return done(None)


def _where(a: canon_read.Run, b: canon_read.Run, i: int, j: int, what: str) -> str:
    """A difference with the moves and the transcript lines it is at."""
    text = [f"move {i + 1}: {what}"]
    for side, run, k in (("original", a, i), ("written ", b, j)):
        if 0 <= k < len(run.moves):
            move = run.moves[k]
            text.append(f"  {side}: {run.lines.get(move[4], '?').strip()}")
            text.append(f"            {canon_read.describe(move)}")
    return "\n".join(text)


# -- one program ------------------------------------------------------------------------------


@dataclass
class Outcome:
    kind: str
    name: str
    outcome: str
    detail: str = ""
    moves: int = 0
    worst: float = 0.0
    ratio: float = 0.0
    centres: int = 0
    centre_worst: float = 0.0
    curve_worst: float = 0.0
    unread: Counter[str] = field(default_factory=Counter)
    notes: list[str] = field(default_factory=list)
    files: dict[str, bytes] = field(default_factory=dict)  # kept for a failure


@dataclass(frozen=True)
class Config:
    rs274: str
    target: str
    inch: bool
    corpus: Path = CONFORMANCE


def sweep_one(program: Program, cfg: Config) -> Outcome:
    """One program through rs274, ngc flatten and rs274 again (see the module docstring)."""
    result = Outcome(program.kind, program.name, SAME)
    original = run_rs274(cfg.rs274, program.files, program.args)
    if original.timed_out:
        result.outcome = HUNG
        return result
    if original.rc != 0:
        result.outcome = ORIGINAL_FAILS
        result.detail = original.err[0] if original.err else f"exit {original.rc}"
        return result
    flat = run_flatten(program, cfg.target, cfg.inch)
    if flat.outcome is not None and (flat.outcome != NOT_VERIFIED or flat.text is None):
        result.outcome, result.detail = flat.outcome, flat.detail
        if flat.outcome != REFUSED:
            _keep(result, program, flat.text, original.out, None)
        return result
    assert flat.text is not None
    if flat.outcome == NOT_VERIFIED:  # (and what rs274 makes of it: see the note)
        result = compared_with_rs274(program, cfg, original, flat, result)
        result.notes.append(f"rs274: {result.outcome}"
                            + (f": {result.detail}" if result.detail else ""))
        result.outcome, result.detail = NOT_VERIFIED, flat.detail
        return result
    result = compared_with_rs274(program, cfg, original, flat, result)
    if result.outcome in (DIFFERS, RS274_ERROR):
        written = (result.files["flat.canon"].decode("latin-1") if result.outcome == DIFFERS
                   else None)
        _triage(program, original, flat, result, written,
                written_rounding(cfg.target, cfg.inch))
    return result


def _triage(program: Program, original: Rs274, flat: Flat, result: Outcome,
            written: str | None, w: Written) -> None:
    """A difference that starts in ngc's own reading of the original (its path there is not
    rs274's) is ngc's, not the flattening's; the written program's path (``written``, its
    transcript) is then held against ngc's of the original too."""
    a = canon_read.machine_path(original.out, flat.curves)
    own = canon_read.machine_path(ngc_transcript(program), flat.curves)
    compared = compare_runs(a, own, Written(0.0, 0.0))
    if compared.difference is not None:
        result.notes.insert(0, f"flattened: {result.outcome}: {result.detail}")
        if written is not None:
            kept = compare_runs(own, canon_read.machine_path(written), w)
            result.notes.insert(0, "the written program's path in rs274 against ngc's of the "
                                f"original: {kept.difference or 'the same'}")
        result.outcome = NGC_OTHERWISE
        result.detail = "ngc's path of the original is not rs274's: " + compared.difference


def compared_with_rs274(program: Program, cfg: Config, original: Rs274, flat: Flat,
                        result: Outcome) -> Outcome:
    """The written program checked plain, run by rs274 and its path compared."""
    assert flat.text is not None
    files = dict(program.files)
    files[FLAT_NAME] = flat.text.encode("utf-8", "surrogateescape")
    args = list(program.args)
    args[program.program] = FLAT_NAME
    problem = not_plain(flat.text)
    if problem is not None:
        result.outcome, result.detail = NOT_PLAIN, problem
        _keep(result, program, flat.text, original.out, None)
        return result
    written = run_rs274(cfg.rs274, files, args)
    if written.timed_out or written.rc != 0:
        result.outcome = RS274_ERROR
        result.detail = ("timed out" if written.timed_out else
                         f"exit {written.rc}: {' | '.join(written.err) or 'no message'}")
        _keep(result, program, flat.text, original.out, written.out + "\n".join(written.err))
        return result
    extra = [line for line in written.err if line not in original.err]
    if extra:
        result.notes.append(f"rs274 says of the written program: {' | '.join(extra)}")
    a = canon_read.machine_path(original.out, flat.curves)
    b = canon_read.machine_path(written.out)
    result.unread = a.unread + b.unread
    compared = compare_runs(a, b, written_rounding(cfg.target, cfg.inch))
    result.moves, result.worst, result.ratio = compared.moves, compared.worst, compared.ratio
    result.centres, result.centre_worst = compared.centres, compared.centre_worst
    result.curve_worst = compared.curve_worst
    if compared.whole_turns:
        result.notes.append(f"arcs whose printed end is a rounding off their start, taken as "
                            f"a whole turn or a sliver: {compared.whole_turns}")
    if any(compared.idle):
        result.notes.append(f"moves of no length left out: {compared.idle[0]} of the "
                            f"original's, {compared.idle[1]} of the written's")
    if compared.difference is not None:
        result.outcome, result.detail = DIFFERS, compared.difference
        _keep(result, program, flat.text, original.out, written.out)
    return result


def _keep(result: Outcome, program: Program, text: str | None, original: str,
          written: str | None) -> None:
    result.files = {"orig.ngc": program.files[program.args[program.program]],
                    "orig.canon": original.encode("latin-1", "replace")}
    if text is not None:
        result.files["flat.ngc"] = text.encode("utf-8", "surrogateescape")
    if written is not None:
        result.files["flat.canon"] = written.encode("latin-1", "replace")


_CFG: Config | None = None


def _init(cfg: Config) -> None:
    global _CFG
    _CFG = cfg


def run_job(job: tuple[str, str]) -> Outcome:
    kind, name = job
    assert _CFG is not None
    try:
        if kind == "conformance":
            program = conformance_program(_CFG.corpus / name)
        else:
            program = generated_program(kind, int(name))
        return sweep_one(program, _CFG)
    except Exception:
        return Outcome(kind, name, INTERNAL, traceback.format_exc())


# -- the sweep --------------------------------------------------------------------------------


def run_all(cfg: Config, jobs: list[tuple[str, str]], workers: int) -> list[Outcome]:
    start = time.monotonic()
    results: list[Outcome] = []
    if workers <= 1:
        _init(cfg)
        iterator: Iterator[Outcome] = map(run_job, jobs)
        return _collect(iterator, len(jobs), start)
    ctx = multiprocessing.get_context("fork")
    with ctx.Pool(workers, initializer=_init, initargs=(cfg,)) as pool:
        results = _collect(pool.imap_unordered(run_job, jobs, chunksize=2), len(jobs), start)
    return results


def _collect(it: Iterator[Outcome], total: int, start: float) -> list[Outcome]:
    results = []
    counts: Counter[str] = Counter()
    for r in it:
        results.append(r)
        counts[r.outcome] += 1
        n = len(results)
        if n % 25 == 0 or n == total:
            rate = n / max(time.monotonic() - start, 1e-9)
            shown = ", ".join(f"{counts[o]} {o}" for o in OUTCOMES if counts[o])
            print(f"  {n}/{total} ({rate:.1f}/s): {shown}", file=sys.stderr, flush=True)
    return results


_NUMBERS = re.compile(r"[-+]?\d+(?:\.\d+)?")


def reason_class(reason: str) -> str:
    """A refusal's reason with its numbers (and a line quoted after its first colon) left
    out."""
    if reason.startswith("a line of more than"):
        reason = reason.split(":", 1)[0]
    return _NUMBERS.sub("#", reason)


def summarize(results: list[Outcome], kinds: list[str]) -> None:
    print(f"\n{'kind':13} {'run':>5} {'compared':>8} {'same':>5} {'differ':>6} {'ngc!=':>5} "
          f"{'refused':>7} {'ngc err':>7} {'not ver':>7} {'!plain':>6} {'rs274er':>7} "
          f"{'orig fails':>10} {'hung':>4} {'intern':>6}")
    for kind in [*kinds, "all"]:
        rs = results if kind == "all" else [r for r in results if r.kind == kind]
        c = Counter(r.outcome for r in rs)
        if kind == "all":
            print("-" * 114)
        compared = c[SAME] + c[DIFFERS] + c[NGC_OTHERWISE]
        print(f"{kind:13} {len(rs):5} {compared:8} {c[SAME]:5} {c[DIFFERS]:6} "
              f"{c[NGC_OTHERWISE]:5} {c[REFUSED]:7} {c[NGC_ERROR]:7} {c[NOT_VERIFIED]:7} "
              f"{c[NOT_PLAIN]:6} {c[RS274_ERROR]:7} {c[ORIGINAL_FAILS]:10} {c[HUNG]:4} "
              f"{c[INTERNAL]:6}")
    _refusals(results, kinds)
    _extremes(results)
    _failures(results)


def _refusals(results: list[Outcome], kinds: list[str]) -> None:
    reasons: dict[str, Counter[str]] = {}
    for r in results:
        if r.outcome == REFUSED:
            reasons.setdefault(reason_class(r.detail), Counter())[r.kind] += 1
    if not reasons:
        return
    print("\nrefused, by reason:")
    for reason, by_kind in sorted(reasons.items(), key=lambda kv: -sum(kv[1].values())):
        kinds_text = ", ".join(f"{k} {by_kind[k]}" for k in kinds if by_kind[k])
        print(f"  {sum(by_kind.values()):5}  {reason}  ({kinds_text})")


def _extremes(results: list[Outcome]) -> None:
    compared = [r for r in results if r.outcome == SAME]
    if not compared:
        return
    worst = max(compared, key=lambda r: r.worst)
    ratio = max(compared, key=lambda r: r.ratio)
    moves = sum(r.moves for r in compared)
    print(f"\n{len(compared)} programs of the same path, {moves} moves compared")
    print(f"  largest end-point deviation: {worst.worst:.6f} mm ({worst.kind} {worst.name})")
    print(f"  largest deviation / its bound: {ratio.ratio:.3f} ({ratio.kind} {ratio.name})")
    curve = max(compared, key=lambda r: r.curve_worst)
    if curve.curve_worst:
        print(f"  largest distance of lines written for a curve or an arc from it: "
              f"{curve.curve_worst:.6f} mm ({curve.kind} {curve.name})")
    moved = [r for r in compared if r.centres]
    if moved:
        far = max(moved, key=lambda r: r.centre_worst)
        print(f"  arcs whose centre moved past its bound, their path within it: "
              f"{sum(r.centres for r in moved)} in {len(moved)} programs (largest "
              f"{far.centre_worst:.6f} mm, {far.kind} {far.name})")
    unread = Counter[str]()
    for r in results:
        unread.update(r.unread)
    if unread:
        print(f"  calls not read: {dict(unread)}")
    notes = Counter(_NUMBERS.sub("#", note) for r in compared for note in r.notes)
    for note, n in notes.most_common():
        first = next(r for r in compared if any(_NUMBERS.sub("#", t) == note for t in r.notes))
        print(f"  {n} programs with the note: {note} (e.g. {first.kind} {first.name})")


def _failures(results: list[Outcome]) -> None:
    failed = [r for r in results if r.outcome in FAILURES]
    if not failed:
        return
    print(f"\n{len(failed)} failures:")
    for r in sorted(failed, key=lambda r: (r.outcome, r.kind, _order(r.name))):
        print(f"- {r.outcome}: {r.kind} {r.name}")
        for text in (r.detail, *r.notes):
            for line in text.rstrip().splitlines():
                print(f"    {line}")


def _order(name: str) -> tuple[int, str]:
    return (int(name), "") if name.isdigit() else (0, name)


def keep_failures(results: list[Outcome], out: Path) -> None:
    for r in results:
        if not r.files:
            continue
        folder = out / f"{r.kind}-{r.name}"
        folder.mkdir(parents=True, exist_ok=True)
        for name, data in r.files.items():
            (folder / name).write_bytes(data)
        (folder / "outcome.txt").write_text(f"{r.outcome}\n{r.detail}\n", encoding="utf-8")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    kinds_default = ",".join(k for k in gen.KINDS if k != "continue")
    ap.add_argument("--conformance", action="store_true",
                    help="the conformance cases rs274 runs to the end")
    ap.add_argument("--cases", default="", help="only the conformance cases matching these "
                    "comma-separated globs")
    ap.add_argument("--corpus", type=Path, default=CONFORMANCE,
                    help=f"the conformance cases' folder (default {CONFORMANCE})")
    ap.add_argument("--kinds", default=None, help="comma-separated generator kinds (default: "
                    f"{kinds_default}; none with --conformance alone)")
    ap.add_argument("--count", type=int, default=20, help="programs per kind (default 20)")
    ap.add_argument("--seed", type=int, default=1, help="first seed (default 1)")
    ap.add_argument("--programs", default="", help="these programs alone, e.g. "
                    "motion:19,lathe:87 (a generator's kind and seed) or conformance:CASE")
    ap.add_argument("--target", default="linuxcnc", choices=list(TARGETS))
    ap.add_argument("--units", choices=("mm", "inch"), default="mm",
                    help="the units written (default mm)")
    ap.add_argument("--jobs", "-j", type=int, default=2)
    ap.add_argument("--rs274", default="rs274")
    ap.add_argument("--out", type=Path, default=DEFAULT_OUT,
                    help="where the programs of each failure go (default tests/fuzz/found/"
                    "flatten/)")
    opts = ap.parse_args(argv)

    if shutil.which(opts.rs274) is None:
        print(f"flatten_sweep.py: cannot find {opts.rs274!r}", file=sys.stderr)
        return 2
    kinds_text = opts.kinds if opts.kinds is not None else (
        "" if opts.conformance or opts.programs else kinds_default)
    kinds = [k for k in kinds_text.split(",") if k]
    unknown = [k for k in kinds if k not in gen.KINDS]
    if unknown:
        ap.error(f"unknown kind(s) {', '.join(unknown)}; known: {', '.join(gen.KINDS)}")
    jobs: list[tuple[str, str]] = []
    if opts.conformance:
        globs = [g for g in opts.cases.split(",") if g]
        jobs += [("conformance", p.name) for p in conformance_cases(opts.corpus, globs)]
    jobs += [(k, str(s)) for k in kinds for s in range(opts.seed, opts.seed + opts.count)]
    named = [tuple(p.split(":", 1)) for p in opts.programs.split(",") if p]
    if any(len(p) != 2 for p in named):
        ap.error("--programs: KIND:SEED or conformance:CASE, separated by commas")
    jobs += named  # type: ignore[arg-type]
    kinds = list(dict.fromkeys([*kinds, *(k for k, _ in named if k != "conformance")]))
    if any(k == "conformance" for k, _ in named):
        opts.conformance = True
    cfg = Config(opts.rs274, opts.target, opts.units == "inch", opts.corpus)
    start = time.monotonic()
    results = run_all(cfg, jobs, opts.jobs)
    print(f"{len(results)} programs in {time.monotonic() - start:.0f}s, --target {opts.target}, "
          f"written in {opts.units} (bound of the writing: "
          f"{written_rounding(opts.target, cfg.inch).linear:g} mm)")
    shown = (["conformance"] if opts.conformance else []) + kinds
    summarize(results, shown)
    keep_failures(results, opts.out)
    return 1 if any(r.outcome in FAILURES for r in results) else 0


if __name__ == "__main__":
    sys.exit(main())
