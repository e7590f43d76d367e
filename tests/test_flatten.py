"""``ngc flatten --target linuxcnc``: the program written plain, run again and its machine path
compared with the original's; refusals say the line and the reason and write nothing."""

from __future__ import annotations

import io
import itertools
import math
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PROGRAMS = [*sorted((ROOT / "tests" / "golden" / "plot").glob("*.ngc")),
            ROOT / "examples" / "pocket.ngc"]
NOT_PLAIN = re.compile(r"[#\[\]]|\bO\d|\bO<|\bG(?:7[0-6]|8[1-9]|4[12](?:\.1)?|5\.[1-3]|52|92|10)\b",
                       re.IGNORECASE)


def _ngc(*argv: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "ngc", *argv], capture_output=True, text=True,
                          timeout=300, cwd=cwd)


def _code(text: str) -> str:
    return "\n".join(re.sub(r"\([^)]*\)", "", line) for line in text.splitlines())


@pytest.mark.parametrize("program", PROGRAMS, ids=[p.name for p in PROGRAMS])
def test_flattened_programs_are_plain_and_verified(tmp_path: Path, program: Path) -> None:
    out = tmp_path / "flat.ngc"
    done = _ngc("flatten", str(program), "-o", str(out))
    if done.returncode == 1 and "refused" in done.stderr:
        assert not out.exists()  # nothing written
        assert re.search(r":\d+: ngc flatten: refused: ", done.stderr)
        return
    if "error-stop" in program.name:  # (a program error: flatten stops on it, as check does)
        assert done.returncode == 1 and not out.exists()
        return
    assert done.returncode == 0, done.stderr
    assert "verified" in done.stderr and "largest deviation 0.00" in done.stderr
    text = out.read_text()
    assert not NOT_PLAIN.search(_code(text)), NOT_PLAIN.search(_code(text))
    # what was written flattens again, verified, to the same moves
    again = _ngc("flatten", str(out))
    assert again.returncode == 0, again.stderr
    moves = re.compile(r"^(?:G1[789] )?G[0-3]\b.*$", re.MULTILINE)
    assert moves.findall(_code(again.stdout)) == moves.findall(_code(text))


def test_offsets_the_program_sets_are_resolved_and_the_operators_kept(tmp_path: Path) -> None:
    (tmp_path / "p.ngc").write_text(
        "G21 G90\nG10 L2 P2 X100 Y50\nG55\nG0 X1 Y2 Z3\nG92 X0\nG1 X5 F100\nG92.1\n"
        "G52 Y10\nG1 Y0\nG52 Y0\nT1 M6\nG43\nG1 Z-1\nG49\nM2\n")
    (tmp_path / "t.tbl").write_text("T1 P1 Z1.0 D0.25\n")
    done = _ngc("flatten", "-t", "t.tbl", "p.ngc", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    lines = _code(done.stdout).split("\n")
    body = [line.strip() for line in lines if line.strip()]
    assert "G55" in body  # the operator's work offset: still a reference
    assert "G0 X101 Y52 Z3" in body  # the program's G10 L2 P2 resolved (G55's own origin is 0)
    assert "G1 F100 X106" in body  # G92 X0 at X1: X5 is 4 further
    assert "G1 Y60" in body  # G52 Y10 at Y0: resolved
    assert "G43 H1" in body and "G49" in body  # the table's tool length: a reference


def test_a_probe_is_refused_and_nothing_is_written(tmp_path: Path) -> None:
    (tmp_path / "p.ngc").write_text("G21\nG0 Z5\nG38.2 Z-10 F100\nM2\n")
    done = _ngc("flatten", "p.ngc", "-o", "out.ngc", cwd=tmp_path)
    assert done.returncode == 1 and not (tmp_path / "out.ngc").exists()
    assert done.stderr == ("p.ngc:3: ngc flatten: refused: probing: where the probe stops is "
                           "known only at the machine\n")


def test_the_targets_are_the_rows_of_the_table(tmp_path: Path) -> None:
    from ngc.cli import FLATTEN_TARGETS
    from ngc.flatten import TARGETS

    assert tuple(TARGETS) == FLATTEN_TARGETS
    done = _ngc("flatten", "--target", "marlin", str(ROOT / "examples" / "pocket.ngc"))
    assert done.returncode == 2 and "invalid choice: 'marlin'" in done.stderr
    with pytest.raises(ValueError, match="unknown target 'marlin': choose one of linuxcnc, "
                       "grbl, grblhal, fluidnc"):
        _library_flatten("G0 X1\nM2\n", target="marlin")


def test_source_lines_percent_and_inch(tmp_path: Path) -> None:
    (tmp_path / "p.ngc").write_text("%\nG20\n#1 = 2\nG1 X#1 F10\n%\n")
    done = _ngc("flatten", "--source-lines", "--units", "inch", "p.ngc", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert lines[0] == "%" and lines[-1] == "%"
    assert "G1 F10 X2 Y0 Z0 (line 4)" in lines  # (the first move names every axis)
    assert "G20 G90 G91.1 G94 G40 G49 G80 G17 G97" in lines
    done = _ngc("flatten", "p.ngc", cwd=tmp_path)  # in mm
    assert "G1 F254 X50.8 Y0 Z0" in done.stdout.splitlines()


def test_a_tool_length_the_program_changes_is_folded(tmp_path: Path) -> None:
    """G10 L1 in the program changes the interpreter's table, not the machine's: the length the
    program set is folded into the coordinates, the table's stays G43 H."""
    (tmp_path / "p.ngc").write_text("G21\nT1 M6\nG43\nG0 Z0\nG10 L1 P1 Z30\nG43\nG0 Z0\nG49\nM2\n")
    (tmp_path / "t.tbl").write_text("T1 P1 Z1.0\n")
    done = _ngc("flatten", "-t", "t.tbl", "p.ngc", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    body = [line for line in _code(done.stdout).splitlines() if line.strip()]
    assert body[body.index("G43 H1") + 1].startswith("G0 ") and "G49" in body
    assert "G0 X0 Y0 Z30" in body  # (Z0 with the 30 mm length the program set: folded)


def _moves(text: str) -> list[tuple[str, dict[str, float]]]:
    """The motion lines written: the code and the words (modal motion carried)."""
    out, code = [], ""
    for line in _code(text).splitlines():
        words = dict((w[0], float(w[1:])) for w in line.split() if w[0] in "XYZIJKPF")
        codes = [w for w in line.split() if w[0] == "G" and w[1:] in ("0", "1", "2", "3")]
        code = codes[-1] if codes else code
        if any(k in words for k in "XYZ"):
            out.append((code, words))
    return out


@pytest.mark.parametrize("tolerance", ["0.002", "0.0005"])
def test_an_arc_turned_off_the_axes_becomes_lines_within_the_tolerance(
        tmp_path: Path, tolerance: str) -> None:
    # G18 under a 30 degree rotation: the arc's plane holds Z and the X axis turned by 30
    # degrees, which no plane word names
    (tmp_path / "p.ngc").write_text("G21 G18\nG10 L2 P1 R30\nG0 X0 Y0 Z0\n"
                                    "G2 X20 Z0 I10 K0 F100\nM2\n")
    done = _ngc("flatten", "p.ngc", "--tolerance", tolerance, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    moves = _moves(done.stdout)
    assert all(code == "G1" for code, _ in moves[1:])
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    centre = (10 * c, 10 * s, 0.0)
    points = [(0.0, 0.0, 0.0)]
    for _, w in moves[1:]:
        p = points[-1]
        points.append((w.get("X", p[0]), w.get("Y", p[1]), w.get("Z", p[2])))

    def off_circle(p: tuple[float, ...]) -> float:
        u = (p[0] - centre[0]) * c + (p[1] - centre[1]) * s  # along the turned X
        v = -(p[0] - centre[0]) * s + (p[1] - centre[1]) * c  # off the arc's plane
        return abs(math.hypot(u, p[2] - centre[2]) - 10.0) + abs(v)

    assert math.dist(points[-1], (20 * c, 20 * s, 0.0)) < 1e-4
    assert max(off_circle(p) for p in points) < 2e-4  # the ends on the arc
    sags = [off_circle(tuple((a[i] + b[i]) / 2 for i in range(3)))
            for a, b in itertools.pairwise(points)]
    assert max(sags) <= float(tolerance)  # the chords within the tolerance
    assert max(sags) > float(tolerance) / 3  # and not many more lines than it needs
    assert "largest deviation" in done.stderr


def test_the_library() -> None:
    import ngc

    result = ngc.Program.load(str(ROOT / "examples" / "pocket.ngc")).flatten(source_lines=True)
    assert result.verified is not None and result.verified.difference is None
    assert result.verified.deviation < 1e-3 and "(line 9)" in result.text
    from ngc.flatten import Refused

    with pytest.raises(Refused) as caught:
        ngc.Program.load("G21\nG38.2 Z-1 F10\nM2\n").flatten()
    assert caught.value.line == 2


def test_a_device_is_written_to_not_replaced(tmp_path: Path) -> None:
    import os
    import stat

    done = _ngc("flatten", str(ROOT / "examples" / "pocket.ngc"), "-o", os.devnull)
    assert done.returncode == 0, done.stderr
    assert stat.S_ISCHR(os.stat(os.devnull).st_mode)  # still the device


GRBL_WORDS = re.compile(r"\b(?:M6|G43 H|G61|G64|G95|G96|G97|G59\.[123]|P\d|M61|M60)\b")


def test_grbl_gets_what_grbl_takes(tmp_path: Path) -> None:
    (tmp_path / "t.tbl").write_text("T1 P1 Z1.0 D0.25\nT2 P2 Z2.0 D0.5\n")
    (tmp_path / "p.ngc").write_text(
        "G21 G64 P0.01\nT1 M6\nG43\nS1000 M3\nG0 X0 Y0 Z5\n"
        "G3 X0 Y0 Z-1 I5 J0 P3 F200\nT2 M6\nG43 H2\nG1 X10\nG61\nG1 Y10\nM2\n")
    done = _ngc("flatten", "--target", "grbl", "-t", "t.tbl", "p.ngc", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    text = done.stdout
    assert not GRBL_WORDS.search(_code(text)), GRBL_WORDS.search(_code(text))
    body = [line.strip() for line in text.splitlines()]
    assert "G43.1 Z25.4" in body and "G43.1 Z50.8" in body  # the table's lengths, Z only
    assert sum(1 for line in body if line.startswith("G3 ")) == 3  # P3: three arcs of a turn
    change = body.index("(tool change: put in tool 2, diameter 12.7, then resume)")
    assert body[change - 1] == "M5" and body[change + 1] == "M0"  # (M6 stops the spindle)
    assert body.count("M5") == 1  # (the spindle stops once: canon's stops of a standing
    # spindle, at the first change and at the end, are not written)
    assert all(len(re.sub(r"\([^)]*\)|\s", "", line)) <= 79 for line in body)
    assert "largest deviation 0.00" in done.stderr


def test_grbl_refuses_what_grbl_lacks(tmp_path: Path) -> None:
    (tmp_path / "a.ngc").write_text("G21\nG59.1\nG0 X1\nM2\n")
    done = _ngc("flatten", "--target", "grbl", "a.ngc", cwd=tmp_path)
    assert done.returncode == 1 and "a.ngc:2: ngc flatten: refused: G59.1: grbl has no such" in done.stderr
    (tmp_path / "b.ngc").write_text("G21\nS100\nG95 G1 X1 F0.1\nM2\n")  # (the spindle stands)
    done = _ngc("flatten", "--target", "grbl", "b.ngc", cwd=tmp_path)
    assert done.returncode == 1 and "feed per revolution (G95) for grbl, which has none" in done.stderr
    (tmp_path / "c.ngc").write_text(
        "G21\nG1 X-123456.789 Y-123456.789 Z-123456.789 A-123456.789 B-123456.789 "
        "C-123456.789 F12345.678\nM2\n")
    done = _ngc("flatten", "--target", "grbl", "c.ngc", cwd=tmp_path)
    assert done.returncode == 1 and "c.ngc:2: ngc flatten: refused: a move of the A axis: grbl " \
        "has X Y Z only" in done.stderr
    from ngc.flatten.targets import TARGETS, Target
    from ngc.flatten.writer import Flattener, Refused

    short = TARGETS["grbl"]._replace(max_line=16)
    assert isinstance(short, Target)
    writer = Flattener(None, io.StringIO(), short, origins=[[0.0] * 6] * 9, system=1,  # type: ignore[arg-type]
                       tool=lambda n: None)
    writer.write("G1 X1.234 Y5.678 (a comment is not counted)")
    with pytest.raises(Refused, match="a line of more than 16 characters for grbl"):
        writer.write("G1 X1.234 Y5.678 Z9.123", 7)


def test_outputs_m30_and_feed_per_revolution(tmp_path: Path) -> None:
    (tmp_path / "p.ngc").write_text("G21\nM62 P1\nM65 P2\nM68 E0 Q3\nS500 M3\nG95 G1 X2 F0.2\n"
                                    "M30\n")
    done = _ngc("flatten", "p.ngc", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    body = [line.strip() for line in _code(done.stdout).splitlines()]
    assert {"M62 P1", "M65 P2", "M68 E0 Q3", "G1 G95 F0.2 X2 Y0 Z0", "M30"} <= set(body)
    done = _ngc("flatten", "--target", "grbl", "p.ngc", cwd=tmp_path)
    assert done.returncode == 1 and "p.ngc:2: ngc flatten: refused: an output (M62): grbl has " \
        "none" in done.stderr
    (tmp_path / "q.ngc").write_text("G21\nS500 M3\nG95 G1 X2 F0.2\nM30\n")
    done = _ngc("flatten", "--target", "grbl", "q.ngc", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    body = [line.strip() for line in _code(done.stdout).splitlines()]
    assert "G1 F100 X2 Y0 Z0" in body and "M30" in body  # (0.2 mm a turn at 500 rpm)


def _library_flatten(text: str, **kw: object) -> object:
    from ngc.flatten import flatten
    from ngc.options import MachineOptions, load_setup, new_interpreter

    setup = load_setup(MachineOptions())
    return flatten(text, "p.ngc", lambda sink: new_interpreter(sink, MachineOptions(), setup,
                                                               write_files=False), **kw)


@pytest.mark.parametrize("parallel", [True, False])
def test_a_long_program_is_verified_chunk_by_chunk(parallel: bool) -> None:
    # 3 moves a turn of the loop, 12,000 lines written: three chunks and more
    program = ("G21 G90 F500\n#1=0\no1 while [#1 LT 4000]\nG1 X[#1 MOD 7] Y[#1 / 10]\n"
               "G2 X[#1 MOD 7 + 2] I1 J0\nG0 Z[#1 MOD 3]\n#1=[#1+1]\no1 endwhile\nM2\n")
    result = _library_flatten(program, parallel=parallel)
    verified = result.verified  # type: ignore[attr-defined]
    assert verified.difference is None and verified.moves == 12000
    assert verified.deviation < 1e-4
    assert result.lines > 12000  # type: ignore[attr-defined]


def test_the_comparison_finds_a_moved_end_and_a_missing_move() -> None:
    from ngc.flatten.verify import compare

    zero = (0.0,) * 6
    a = [("feed", (1.0, 0.0, 0.0, 0.0, 0.0, 0.0), None, 0, 3, None, None, 100.0, 1),
         ("rapid", (1.0, 2.0, 0.0, 0.0, 0.0, 0.0), None, 0, 4, None, None, 0.0, 1)]
    same = compare(a, list(a), 0.002)  # type: ignore[arg-type]
    assert same.difference is None and same.deviation == 0.0 and same.moves == 2
    moved = [a[0], ("rapid", (1.0, 2.01, 0.0, 0.0, 0.0, 0.0), None, 0, 9, None, None, 0.0, 1)]
    assert abs(compare(a, moved, 0.002).deviation - 0.01) < 1e-12  # type: ignore[arg-type]
    missing = compare(a, a[:1], 0.002)  # type: ignore[arg-type]
    assert missing.difference == "move 2 (line 4): the program written has no move for it"
    extra = compare(a[:1], a, 0.002)  # type: ignore[arg-type]
    assert extra.difference == "the program written has 1 moves more, after move 1"
    other = compare(a, [("rapid", zero, None, 0, 1, None, None, 0.0, 1), a[1]], 0.002)  # type: ignore[arg-type]
    assert other.difference == "move 1 (line 3): a feed became a rapid"
    slower = compare(a, [(*a[0][:7], 99.0, 1), a[1]], 0.002)  # type: ignore[arg-type]
    assert slower.difference == "move 1 (line 3): the feed 100 became 99"


sys.path.insert(0, str(ROOT / "tests" / "golden"))
import flatten_regen  # noqa: E402

GOLDEN = [(p, t) for p in flatten_regen.programs() for t in flatten_regen.TARGETS]


@pytest.mark.parametrize(("program", "target"), GOLDEN,
                         ids=[f"{p.stem}-{t}" for p, t in GOLDEN])
def test_golden_outputs(program: Path, target: str) -> None:
    done = flatten_regen.flatten(program, target)
    written, refused = flatten_regen.golden(program, target)
    if refused.exists():
        assert done.returncode == 1 and done.stdout == ""
        assert done.stderr == refused.read_text()
        return
    assert done.returncode == 0, done.stderr
    assert done.stdout == written.read_text()
    assert not NOT_PLAIN.search(_code(done.stdout))


RS274 = shutil.which("rs274")


@pytest.mark.skipif(RS274 is None, reason="rs274 (LinuxCNC) is not installed")
@pytest.mark.parametrize("program", [p for p, t in GOLDEN if t == "linuxcnc"],
                         ids=[p.stem for p, t in GOLDEN if t == "linuxcnc"])
def test_golden_linuxcnc_outputs_run_in_rs274(tmp_path: Path, program: Path) -> None:
    written, _refused = flatten_regen.golden(program, "linuxcnc")
    if not written.exists():
        pytest.skip("refused")
    assert RS274 is not None
    done = subprocess.run([RS274, "-i", "machine.ini", "-t", "tools.tbl", "-g", str(written)],
                          cwd=program.parent, capture_output=True, text=True, timeout=60)
    errors = [line for line in done.stderr.splitlines() if line.strip() not in ("", "executing")]
    assert done.returncode == 0 and not errors, done.stderr
    assert "PROGRAM_END" in done.stdout


def test_grbl_numbers_keep_to_its_eight_digits() -> None:
    result = _library_flatten("G21\nG1 X123456.789 Y-12345.6789 Z0.0004 F100\nM2\n",
                              target="grbl", tolerance=0.01)
    assert "G1 F100 X123456.79 Y-12345.679 Z0\n" in result.text  # type: ignore[attr-defined]
    assert not re.search(r"\d[eE][-+]?\d", result.text)  # type: ignore[attr-defined]
    linuxcnc = _library_flatten("G21\nG1 X123456.789 F100\nM2\n")
    assert "X123456.789" in linuxcnc.text  # type: ignore[attr-defined]


@pytest.mark.parametrize(("program", "target"), [(p, t) for p, t in GOLDEN
                                                 if t in ("grbl", "fluidnc")],
                         ids=[f"{p.stem}-{t}" for p, t in GOLDEN if t in ("grbl", "fluidnc")])
def test_golden_grbl_outputs_pass_grbls_check(program: Path, target: str) -> None:
    from ngc.grbl import check_text

    written, _refused = flatten_regen.golden(program, target)
    if not written.exists():
        pytest.skip("refused")
    assert check_text(written.read_text()) == []


def test_a_tool_of_no_length_after_one_with_a_length(tmp_path: Path) -> None:
    # G43 for a tool whose table entry has no offsets: G49, and the coordinates no longer
    # take the first tool's length off
    (tmp_path / "t.tbl").write_text("T1 P1 Z2.0 D0.25\nT2 P2 D0.5\n")
    (tmp_path / "p.ngc").write_text("G20\nT1 M6 G43\nG0 X1 Z1\nT2 M6 G43\nG0 X1 Z1\nM2\n")
    done = _ngc("flatten", "-t", "t.tbl", "p.ngc", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    body = [line for line in _code(done.stdout).splitlines() if line.strip()]
    assert body[body.index("G49") + 1] == "G0 X25.4 Y0 Z25.4"


def test_tool_lengths_folded_when_asked() -> None:
    folder = ROOT / "tests" / "golden" / "flatten"
    done = _ngc("flatten", "-i", "machine.ini", "-t", "tools.tbl", "--fold-tool-length",
                "--target", "grbl", "toolchange.ngc", cwd=folder)
    assert done.returncode == 0, done.stderr
    body = _code(done.stdout)
    assert "G43" not in body and "G0 X10 Y10 Z14.5" in body  # (Z2 on tool 1, 12.5 long)


def test_a_spline_under_inverse_time_and_g96_without_a_limit(tmp_path: Path) -> None:
    (tmp_path / "a.ngc").write_text("G21 G17 G90 G93\nG5 X10 Y0 I2 J2 P-2 Q2 F10\nM2\n")
    done = _ngc("flatten", "a.ngc", cwd=tmp_path)
    assert done.returncode == 1 and "a.ngc:2: ngc flatten: refused: a spline (G5, G5.1, G5.2) " \
        "with no feed rate (inverse time, G93)" in done.stderr
    (tmp_path / "b.ngc").write_text("G18 G21\nG96 S200 M3\nG1 X10 F100\nM2\n")
    done = _ngc("flatten", "b.ngc", cwd=tmp_path)
    assert done.returncode == 0 and "\nG96 S200\n" in done.stdout


def test_a_new_feed_mode_gets_its_feed_again(tmp_path: Path) -> None:
    # LinuxCNC sets the feed to 0 with G94/G95: the same F is written again after one
    (tmp_path / "p.ngc").write_text("G21 S1000 M3\nG95 G1 X1 F0.1\nG94 F100\nG1 X2\nG95 F0.1\n"
                                    "G1 X3\nM2\n")
    done = _ngc("flatten", "p.ngc", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert "G1 G95 F0.1 X1 Y0 Z0\nG1 G94 F100 X2\nG1 G95 F0.1 X3\n" in done.stdout
