"""Measure programs on LinuxCNC's own trajectory planner and write their cycle times as JSON.

Runs the measuring tool ``lcnc_time.py`` (``../shared/timing/lcnc-timing`` beside the repository,
or ``--tool``) once per program, on the machine of ``../shared/timing/README.md`` (X and Y 200 mm/s
and 1000 mm/s², Z 100 mm/s and 500 mm/s², 1 ms servo period, start at machine 0,0,0), and writes
``reference.json`` in the programs' folder with the fields of ``../shared/timing/reference.json``.

A program with a dwell (``G4``, ``G82``/``G89`` with ``P``), a tool change or any M-code between the
first and the last line runs at real time, because task and io carry those out in wall-clock
time; the others run at ``--speed 2`` (``--speed`` forces one speed for all).  Each record keeps
the speed and the tool's options it was measured with.

    python tests/timing/measure.py                       # every tests/timing/cases/*.ngc
    python tests/timing/measure.py tests/timing/cases/05_contour_plate_b.ngc   # update one entry

Where ``/usr/bin/python3`` with the ``linuxcnc`` module, or the tool, is missing, it prints why and
exits with status 0 without measuring anything.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
DEFAULT_TOOL = REPO.parent / "shared" / "timing" / "lcnc-timing" / "lcnc_time.py"
SYS_PYTHON = "/usr/bin/python3"
MACHINE_OPTIONS = ["--vel", "X=200,Y=200,Z=100", "--acc", "X=1000,Y=1000,Z=500"]
MACHINE = {
    "kinematics": "trivkins XYZ",
    "linear_units": "mm",
    "max_velocity": {"X": 200.0, "Y": 200.0, "Z": 100.0},
    "max_acceleration": {"X": 1000.0, "Y": 1000.0, "Z": 500.0},
    "joint_limits": "same as the axis limits",
    "servo_period_s": 0.001,
    "traj_max_linear_velocity": None,
    "traj_max_linear_acceleration": None,
    "traj_blending": "LinuxCNC defaults (ARC_BLEND_ENABLE=1, ARC_BLEND_KINK_RATIO=0.1, ...)",
    "task_cycle_time_s": 0.001,
    "io_cycle_time_s": 0.001,
    "start_position": [0.0, 0.0, 0.0],
    "feed_override": 1.0,
}
UNITS = {"motion_time": "s", "stopped_time_inside": "s", "busy_time": "s", "path_length": "mm",
         "peak_speed": "mm/s (largest per-servo-cycle displacement / period)", "start_pos": "mm",
         "end_pos": "mm"}


def unavailable(tool: Path) -> str | None:
    """Why measuring is not possible here, or None."""
    if not Path(SYS_PYTHON).exists():
        return f"{SYS_PYTHON} not found"
    if not tool.exists():
        return f"measuring tool not found: {tool}"
    probe = subprocess.run([SYS_PYTHON, "-c", "import linuxcnc"], capture_output=True, text=True)
    if probe.returncode != 0:
        return f"{SYS_PYTHON} has no linuxcnc module (package linuxcnc-uspace)"
    return None


def code_lines(text: str) -> list[str]:
    """The program's lines without comments and blank lines, upper case."""
    out = []
    for line in text.splitlines():
        line = re.sub(r"\([^)]*\)", "", line.split(";")[0]).strip().upper()
        if line:
            out.append(line)
    return out


def needs_real_time(text: str) -> bool:
    """A dwell, a tool change or an M-code between the first and the last line."""
    lines = code_lines(text)
    for i, line in enumerate(lines):
        words = line.replace(" ", "")
        if re.search(r"G0*4(?!\d|\.)", words) or re.search(r"G(82|89)(?!\d|\.)", words):
            return True
        if re.search(r"M0*6(?!\d)", words):
            return True
        start = i < 3 and re.fullmatch(r"S[\d.]+M0*3", words)
        if re.search(r"M\d", words) and not (start or i == len(lines) - 1):
            return True
    return False


def lcnc_package() -> str | None:
    """The Debian version of linuxcnc-uspace (upstream version and Debian revision)."""
    r = subprocess.run(["dpkg-query", "-W", "-f", "${Version}", "linuxcnc-uspace"],
                       capture_output=True, text=True)
    return (r.stdout.strip() or None) if r.returncode == 0 else None


def tags() -> dict[str, list[str]]:
    """The generator's tags of what each generated program exercises, by file name."""
    sys.path.insert(0, str(HERE))
    try:
        import generate
    finally:
        sys.path.pop(0)
    return {c.file: list(c.tags) for c in generate.CASES}


def measure(tool: Path, program: Path, speed: float, repeat: int) -> dict[str, Any]:
    opts = [*MACHINE_OPTIONS]
    if repeat > 1:
        opts += ["--repeat", str(repeat)]
    if speed != 1:
        opts += ["--speed", f"{speed:g}"]
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "result.json"
        cmd = [SYS_PYTHON, str(tool), str(program), *opts, "--json", str(out), "--quiet"]
        proc = subprocess.run(cmd, capture_output=True, text=True)
        if not out.exists():
            raise RuntimeError(f"{program.name}: the tool failed ({proc.returncode}): {proc.stderr[-2000:]}")
        res = json.loads(out.read_text())
    runs = res["runs"]
    bad = [r for r in runs if not r.get("ok")]
    if bad:
        errors = [e for r in bad for e in r.get("ui", {}).get("errors", [])] or [r.get("error") for r in bad]
        raise RuntimeError(f"{program.name}: run not ok: {errors}")
    text = program.read_text()
    title = re.match(r"\s*\(([^)]*)\)", text)
    mts = [r["motion_time"] for r in runs]

    def mean(key: str) -> float:
        return round(float(sum(r[key] for r in runs)) / len(runs), 6)

    return {
        "file": program.name,
        "title": title.group(1) if title else "",
        "program_units": "inch" if re.search(r"\bG20\b", text.upper()) else "mm",
        "lines": text.count("\n"),
        "motion_time": round(sum(mts) / len(mts), 6),
        "motion_time_min": min(mts),
        "motion_time_max": max(mts),
        "motion_time_spread": round(max(mts) - min(mts), 6),
        "motion_time_runs": mts,
        "n_runs": len(mts),
        "stopped_time_inside": mean("stopped_time_inside"),
        "path_length": round(sum(r["path_length"] for r in runs) / len(runs), 4),
        "peak_speed": round(max(r["peak_speed"] for r in runs), 3),
        "busy_time": mean("busy_time"),
        "start_pos": runs[0]["start_pos"],
        "end_pos": runs[0]["end_pos"],
        "wall_time_runs": [round(r["ui"]["wall_time"], 3) for r in runs],
        "lcnc_time_options": [*opts, "--json", "RESULT.json", "--quiet"],
        "speed": speed,
    }


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("programs", nargs="*", type=Path,
                    help="programs, or folders of *.ngc (default: tests/timing/cases)")
    ap.add_argument("--out", type=Path, help="JSON to write (default: reference.json beside the programs)")
    ap.add_argument("--tool", type=Path, default=Path(os.environ.get("LCNC_TIME", DEFAULT_TOOL)))
    ap.add_argument("--speed", type=float, help="one speed for every program (default: 1 or 2, see above)")
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--fresh", action="store_true", help="drop the entries of programs not measured now")
    args = ap.parse_args(argv)

    why = unavailable(args.tool)
    if why:
        print(f"measure.py: skipped, cannot run LinuxCNC here: {why}")
        return 0
    programs: list[Path] = []
    for p in args.programs or [HERE / "cases"]:
        programs += sorted(p.glob("[0-9]*.ngc")) if p.is_dir() else [p]
    if not programs:
        print("measure.py: no programs")
        return 1
    out = args.out or programs[0].parent / "reference.json"
    doc: dict[str, Any] = json.loads(out.read_text()) if out.exists() and not args.fresh else {}
    entries = {e["file"]: e for e in doc.get("programs", [])}
    package = lcnc_package()
    version = package.rsplit("-", 1)[0] if package else None
    kinds = tags() if all(p.parent.resolve() == (HERE / "cases").resolve() for p in programs) else {}
    failed = []
    for prog in programs:
        speed = args.speed or (1.0 if needs_real_time(prog.read_text()) else 2.0)
        t0 = time.monotonic()
        try:
            entry = measure(args.tool, prog.resolve(), speed, args.repeat)
        except RuntimeError as err:
            print(f"{prog.name:32s} FAILED: {err}", flush=True)
            failed.append(prog.name)
            continue
        entry["linuxcnc_version"] = version
        if prog.name in kinds:
            entry["kinds"] = kinds[prog.name]
        entries[prog.name] = entry
        print(f"{prog.name:32s} {entry['motion_time']:9.3f} s  speed {speed:g}  "
              f"({time.monotonic() - t0:.1f} s wall)", flush=True)
        write(out, doc, entries, version, package)
    write(out, doc, entries, version, package)
    print(f"wrote {out}")
    return 1 if failed else 0


def write(out: Path, doc: dict[str, Any], entries: dict[str, dict[str, Any]], version: str | None,
          package: str | None) -> None:
    doc.update({
        "what": "cycle times of G-code programs on LinuxCNC's own trajectory planner "
                "(headless simulated machine, servo-cycle exact)",
        "linuxcnc_version": version,
        "linuxcnc_package": f"linuxcnc-uspace {package} (Debian)" if package else None,
        "tool": "lcnc-timing/lcnc_time.py (../shared/timing)",
        "command": "/usr/bin/python3 lcnc_time.py PROGRAM.ngc " + " ".join(MACHINE_OPTIONS)
                   + " [--speed 2] --json RESULT.json --quiet",
        "command_note": "real time (speed 1) for programs with a dwell, a tool change or an M-code "
                        "mid-program, --speed 2 for the others; each entry has its own options",
        "machine": MACHINE,
        "units": UNITS,
    })
    doc["programs"] = [entries[k] for k in sorted(entries)]
    doc["total_motion_time"] = round(sum(e["motion_time"] for e in doc["programs"]), 6)
    out.write_text(json.dumps(doc, indent=1) + "\n")


if __name__ == "__main__":
    sys.exit(main())
