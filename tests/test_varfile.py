"""The parameter file (``-v file.var``): reading, the exact bytes rs274 writes, and atomic saving.

Expected values are what LinuxCNC's ``rs274`` 2.9.0~pre1 was observed to do; the golden folders
under ``golden/varfiles/`` hold files it wrote (``record.py`` there re-records or checks them).
"""

from __future__ import annotations

import io
import os
import shutil
import signal
import stat
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from ngc.commands import rs274
from ngc.config import varfile
from ngc.config.varfile import (
    REQUIRED_PARAMETERS,
    format_var_file,
    parse_var_file,
    persistent_numbers,
    read_var_file,
    write_var_file,
)
from ngc.errors import NgcConfigError

GOLDEN = Path(__file__).resolve().parent / "golden" / "varfiles"
SCENARIOS = sorted(p.name for p in GOLDEN.iterdir() if (p / "input.var").exists())
# Scenarios whose program ("%" "%") changes no parameter: rs274's file is a pure re-write.
UNCHANGED = [name for name in SCENARIOS if name != "program"]
RS274 = "/usr/bin/rs274"


def numbered_from(values: dict[int, float]) -> list[float]:
    numbered = [0.0] * (varfile.PARAMETER_MAX + 1)
    for number, value in values.items():
        numbered[number] = value
    return numbered


# -- which parameters persist --------------------------------------------------------------------


def test_required_parameters_are_the_119_rs274_writes_for_an_empty_file() -> None:
    # rs274 was observed to save an empty parameter file as exactly these lines.
    assert len(REQUIRED_PARAMETERS) == 119
    assert REQUIRED_PARAMETERS[:10] == (5161, 5162, 5163, 5164, 5165, 5166, 5167, 5168, 5169, 5181)
    assert REQUIRED_PARAMETERS[18:30] == tuple(range(5210, 5222))
    assert REQUIRED_PARAMETERS[-10:] == tuple(range(5381, 5391))
    assert 5231 not in REQUIRED_PARAMETERS and 5240 not in REQUIRED_PARAMETERS
    assert list(REQUIRED_PARAMETERS) == sorted(REQUIRED_PARAMETERS)


def test_persistent_numbers_add_the_file_numbers_in_order() -> None:
    numbers = persistent_numbers([5500, 1, 5170, 5161])
    assert numbers[:3] == [1, 5161, 5162]
    assert 5170 in numbers and numbers[-1] == 5500
    assert len(numbers) == 122


# -- golden files written by rs274 ---------------------------------------------------------------


@pytest.mark.parametrize("name", UNCHANGED)
def test_round_trip_matches_rs274(name: str, tmp_path: Path) -> None:
    case = GOLDEN / name
    values = read_var_file(case / "input.var")
    target = tmp_path / "b.var"
    assert write_var_file(target, numbered_from(values), values.keys(), backup=False) == []
    assert target.read_bytes() == (case / "expected.var").read_bytes()


@pytest.mark.parametrize("name", UNCHANGED)
def test_two_saves_leave_rs274s_file_and_backup(name: str, tmp_path: Path) -> None:
    # rs274 saves right after reading and again at exit, each time re-reading the old file.
    case = GOLDEN / name
    target = tmp_path / "b.var"
    shutil.copy(case / "input.var", target)
    numbered = numbered_from(read_var_file(target))
    assert write_var_file(target, numbered) == []
    assert write_var_file(target, numbered) == []
    assert target.read_bytes() == (case / "expected.var").read_bytes()
    assert (tmp_path / "b.var.bak").read_bytes() == (case / "expected.var.bak").read_bytes()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["b.var", "b.var.bak"]


@pytest.mark.parametrize("name", [name for name in SCENARIOS if name != "values"])
def test_rs274s_own_file_is_a_fixed_point(name: str) -> None:
    expected = (GOLDEN / name / "expected.var").read_bytes()
    values = parse_var_file(expected)
    assert format_var_file(values, persistent_numbers(values)) == expected


def test_rs274_refuses_its_own_file_with_a_value_longer_than_a_line() -> None:
    # values/expected.var has #11 = 1e308, printed with 316 characters: read back in 255-byte
    # pieces, the rest of that line is a number out of range.  Observed: rs274 -v on that file
    # stops with "Parameter number out of range".
    with pytest.raises(NgcConfigError, match="Parameter number out of range"):
        parse_var_file((GOLDEN / "values" / "expected.var").read_bytes())


def test_program_changes_are_saved_but_new_parameters_are_not() -> None:
    # program.ngc sets #31 (listed in input.var) and #32 (not listed): rs274 saved only #31.
    values = parse_var_file((GOLDEN / "program" / "expected.var").read_bytes())
    assert values[31] == 7.0 and 32 not in values
    assert values[5161] == 9.0
    assert values[5221] == pytest.approx(1 / 25.4, abs=5e-7)  # G10 L2 P1 X1 in G21: stored in inches


def test_golden_normalize_scenario_facts() -> None:
    # Observed in golden/varfiles/normalize: bad lines dropped, tails of long lines read, and so on.
    values = read_var_file(GOLDEN / "normalize" / "input.var")
    assert values[31] == 2.0  # trailing words ignored
    assert values[4999] == 16.0  # "0x10" read as hexadecimal
    assert values[5000] == -6.0  # "5000-6"
    assert values[5161] == 0.25  # "5161.25 8": the value is ".25"
    assert values[5162] == 7.0  # the last bytes of a 262-byte line
    assert values[5500] == 1.0  # "1e"
    assert 101 not in values and 102 not in values and 5001 not in values


@pytest.mark.skipif(not os.path.exists(RS274), reason="needs LinuxCNC's rs274")
def test_recorded_files_are_what_rs274_writes() -> None:
    done = subprocess.run(
        [sys.executable, str(GOLDEN / "record.py"), "--check", "--rs274", RS274],
        capture_output=True,
        text=True,
        check=False,
    )
    assert done.returncode == 0, done.stdout + done.stderr


# -- reading -------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # Each was observed with rs274 (the value it then saved).
        (b"5161 1\n", {5161: 1.0}),
        (b"5161\n", {}),
        (b"5161 abc\n", {}),
        (b"abc 1\n5161 2\n", {5161: 2.0}),
        (b"5161 1 2 # trailing\n", {5161: 1.0}),
        (b"  5161\t\t1  \r\n", {5161: 1.0}),
        (b"5161,1\n", {}),
        (b"5161 1,5\n", {5161: 1.0}),
        (b"5161-1\n", {5161: -1.0}),
        (b"5161.5 1\n", {5161: 0.5}),
        (b"+5161 +1\n", {5161: 1.0}),
        (b"05161 .5\n", {5161: 0.5}),
        (b"5161 0x10\n", {5161: 16.0}),
        (b"5161 0x1.8\n", {5161: 1.5}),
        (b"5161 0x1p\n", {5161: 1.0}),
        (b"5161 1e\n", {5161: 1.0}),
        (b"5161 1e+5x\n", {5161: 100000.0}),
        (b"5161 1abc\n", {5161: 1.0}),
        (b"5161 infx\n", {5161: float("inf")}),
        (b"5161 1e400\n", {5161: float("inf")}),
        (b"5161 1e-400\n", {5161: 0.0}),
        (b"5161 1", {5161: 1.0}),
        (b"5161 1\x00 junk\n", {5161: 1.0}),
        (b"4294972457 1\n", {5161: 1.0}),  # %d keeps the low 32 bits
        (b"-4294962135 1\n", {5161: 1.0}),
        (b"5601 1\n31 2\n", {5601: 1.0}),  # after 5601 nothing more is read
        (b"\xef\xbb\xbf5161 1\n5162 2\n", {5162: 2.0}),
        (b"x" * 255 + b"5162 7\n", {5162: 7.0}),  # read in 255-byte pieces
        (b"x" * 254 + b"5162 7\n", {162: 7.0}),
    ],
)
def test_parse_like_rs274(text: bytes, expected: dict[int, float]) -> None:
    assert parse_var_file(text) == expected


@pytest.mark.parametrize(
    "text",
    [b"5161 0x\n", b"5161 .\n", b"5161 +-1\n", b"5161 -\n", b"5161 in\n", b"5161 infin\n", b"0x1429 1\n"],
)
def test_lines_rs274_skips(text: bytes) -> None:
    # Observed: a following "5160 1" line is accepted, so the line was not read.
    assert parse_var_file(text + b"5160 1\n") == {5160: 1.0}


def test_nan_values_keep_their_sign() -> None:
    values = parse_var_file(b"1 nan\n2 -nan\n3 nan(12)\n")
    assert format_var_file(values, [1, 2, 3]) == b"1\tnan\n2\t-nan\n3\tnan\n"


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (b"0 1\n", "Parameter number out of range"),
        (b"-1 1\n", "Parameter number out of range"),
        (b"5602 1\n", "Parameter number out of range"),
        (b"2147483648 1\n", "Parameter number out of range"),
        (b"99999999999999999999 1\n", "Parameter number out of range"),
        (b"5601 1\n9999 1\n", "Parameter number out of range"),
        (b"5161 1\n0 1\n", "Parameter number out of range"),
        (b"5161 1\n5161 2\n", "Parameter file out of order"),
        (b"5162 1\n5161 2\n", "Parameter file out of order"),
        (b"5161 1\n31 2\n", "Parameter file out of order"),
        (b"5162 5\n5161 inf\n", "Parameter file out of order"),
    ],
)
def test_files_rs274_refuses(text: bytes, message: str, tmp_path: Path) -> None:
    # rs274 prints the message and an empty line, exits 1 and leaves the file alone.
    path = tmp_path / "b.var"
    path.write_bytes(text)
    with pytest.raises(NgcConfigError) as caught:
        read_var_file(path)
    assert caught.value.message == message
    assert caught.value.source == ""
    assert caught.value.file == str(path)


def test_missing_file_and_directory_read_as_empty(tmp_path: Path) -> None:
    assert read_var_file(tmp_path / "missing.var") == {}
    assert read_var_file(tmp_path) == {}


def test_unreadable_file(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # Observed (as an unprivileged user, mode 000): "Unable to open parameter file: 'x.var'", rc 1.
    path = tmp_path / "x.var"
    path.write_bytes(b"5161 1\n")

    def refuse(*args: object, **kwargs: object) -> None:
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(varfile, "open", refuse, raising=False)
    with pytest.raises(NgcConfigError) as caught:
        read_var_file(path)
    assert caught.value.message == f"Unable to open parameter file: '{path}'"


# -- writing -------------------------------------------------------------------------------------


def test_format_is_printf_d_tab_f() -> None:
    values = {1: -0.0, 2: 1e20, 3: 5e-7, 4: 123456.1234567, 5: float("-inf")}
    assert format_var_file(values, [1, 2, 3, 4, 5]) == (
        b"1\t-0.000000\n2\t100000000000000000000.000000\n3\t0.000000\n4\t123456.123457\n5\t-inf\n"
    )


def test_first_save_of_a_missing_file_reports_the_link(tmp_path: Path) -> None:
    # rs274 -v missing.var: "link (updating variable file): No such file or directory", rc 0.
    target = tmp_path / "missing.var"
    numbered = numbered_from({})
    assert write_var_file(target, numbered) == ["link (updating variable file): No such file or directory"]
    assert target.read_bytes() == format_var_file(numbered, REQUIRED_PARAMETERS)
    assert write_var_file(target, numbered) == []
    assert sorted(p.name for p in tmp_path.iterdir()) == ["missing.var", "missing.var.bak"]


def test_saving_over_a_directory(tmp_path: Path) -> None:
    # rs274 -v d.var where d.var is a directory: both messages, at each save; nothing replaced.
    target = tmp_path / "d.var"
    target.mkdir()
    assert write_var_file(target, numbered_from({})) == [
        "link (updating variable file): Operation not permitted",
        "rename (updating variable file): Is a directory",
    ]
    assert target.is_dir()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["d.var"]


def test_no_directory_no_save_no_message(tmp_path: Path) -> None:
    # rs274 -v nodir/x.var: the .new file cannot be created; rs274 says nothing, exits 0.
    assert write_var_file(tmp_path / "nodir" / "x.var", numbered_from({})) == []
    assert list(tmp_path.iterdir()) == []


def test_save_abandoned_when_the_old_file_reads_out_of_order(tmp_path: Path) -> None:
    # Read in 4096-byte lines at save time, this file lists 5161 then 31: rs274 stops the save.
    target = tmp_path / "b.var"
    original = b"5161 1\n" + b"x" * 4095 + b"31 1\n5162 2\n"
    target.write_bytes(original)
    numbered = numbered_from(read_var_file(target))
    assert write_var_file(target, numbered) == []
    assert target.read_bytes() == original
    assert [p.name for p in tmp_path.iterdir()] == ["b.var"]


def test_explicit_kept_numbers(tmp_path: Path) -> None:
    target = tmp_path / "b.var"
    numbered = numbered_from({31: 3.0, 32: 4.0})
    assert write_var_file(target, numbered, [31], backup=False) == []
    data = target.read_bytes()
    assert data.startswith(b"31\t3.000000\n5161\t0.000000\n") and b"\n32\t" not in data
    assert not (tmp_path / "b.var.bak").exists()


def test_failed_write_keeps_the_old_file(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    target = tmp_path / "b.var"
    target.write_bytes(b"5161 1\n")

    def full(fd: int) -> None:
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(varfile.os, "fsync", full)
    assert write_var_file(target, numbered_from({})) == [
        "write (updating variable file): No space left on device"
    ]
    assert target.read_bytes() == b"5161 1\n"
    assert [p.name for p in tmp_path.iterdir()] == ["b.var"]


def test_failed_rename_removes_the_temporary_file(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    target = tmp_path / "b.var"
    target.write_bytes(b"5161 1\n")

    def refuse(src: str, dst: str) -> None:
        raise OSError(30, "Read-only file system")

    monkeypatch.setattr(varfile.os, "replace", refuse)
    assert write_var_file(target, numbered_from({})) == [
        "rename (updating variable file): Read-only file system"
    ]
    assert target.read_bytes() == b"5161 1\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["b.var", "b.var.bak"]


KILLED_WRITER = textwrap.dedent(
    """
    import os, signal, sys
    from ngc.config import varfile

    if sys.argv[2] == "named":
        del os.O_TMPFILE
    real_write = os.write

    def write_half_then_die(fd, data):
        real_write(fd, bytes(data[: len(data) // 2]))
        os.kill(os.getpid(), signal.SIGKILL)

    os.write = write_half_then_die
    numbered = [n * 1.5 for n in range(varfile.PARAMETER_MAX + 1)]
    varfile.write_var_file(sys.argv[1], numbered, range(1, varfile.PARAMETER_MAX + 1))
    """
)


def killed_mid_write(target: Path, kind: str) -> list[Path]:
    """Kill a process writing ``target`` half-way; the old file is whole; what else is left."""
    original = format_var_file([float(n) for n in range(5602)], range(1, 5602))
    target.write_bytes(original)
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    done = subprocess.run(
        [sys.executable, "-c", KILLED_WRITER, str(target), kind], env=env, capture_output=True,
        check=False,
    )
    assert done.returncode == -signal.SIGKILL, done.stderr
    assert target.read_bytes() == original
    return [p for p in target.parent.iterdir() if p != target]


@pytest.mark.skipif(not hasattr(os, "O_TMPFILE"), reason="needs unnamed files (O_TMPFILE)")
def test_killed_mid_write_leaves_the_old_file_whole_and_nothing_else(tmp_path: Path) -> None:
    assert killed_mid_write(tmp_path / "big.var", "unnamed") == []


def test_killed_mid_write_of_a_named_temporary_file(tmp_path: Path) -> None:
    # Without unnamed files, only SIGKILL (which nothing can catch) leaves the temporary file.
    leftovers = killed_mid_write(tmp_path / "big.var", "named")
    assert len(leftovers) == 1 and leftovers[0].name.startswith("big.var.")
    assert leftovers[0].name.endswith(".new")
    partial = leftovers[0].read_bytes()
    assert 0 < len(partial) < 100000 and partial.startswith(b"1\t1.500000\n")


# -- files that are not regular files ------------------------------------------------------------


@pytest.fixture
def fifo(tmp_path: Path) -> Path:
    path = tmp_path / "f.var"
    os.mkfifo(path)
    return path


@pytest.fixture
def device(tmp_path: Path) -> Path:
    """A null device node of our own (creating one needs privileges) to write over, safely."""
    path = tmp_path / "null.var"
    try:
        os.mknod(path, 0o666 | stat.S_IFCHR, os.makedev(1, 3))
    except PermissionError:
        pytest.skip("creating a device node needs privileges")
    return path


def unable_to_open(path: Path | str) -> str:
    return f"Unable to open parameter file: '{path}'"


@pytest.mark.parametrize("path", ["fifo", "/dev/null", "/dev/zero", "link-to-fifo"])
def test_reading_refuses_fifos_and_devices_without_blocking(fifo: Path, path: str) -> None:
    if path == "fifo":
        name = str(fifo)
    elif path == "link-to-fifo":
        name = str(fifo.parent / "l.var")
        os.symlink(fifo, name)
    else:
        name = path
    with pytest.raises(NgcConfigError) as caught:
        read_var_file(name)
    assert (caught.value.message, caught.value.source, caught.value.file) == (
        unable_to_open(name), "", name
    )


def test_what_is_opened_is_checked_again(fifo: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # A FIFO put in place after the first look: opened without blocking, then refused.
    monkeypatch.setattr(varfile, "_not_regular", lambda name: False)
    with pytest.raises(NgcConfigError) as caught:
        read_var_file(fifo)
    assert caught.value.message == unable_to_open(fifo)


def test_a_symbolic_link_to_a_regular_file_is_read_and_replaced_like_rs274(tmp_path: Path) -> None:
    target = tmp_path / "real.var"
    target.write_bytes(b"31 2\n")
    link = tmp_path / "l.var"
    os.symlink(target, link)
    values = read_var_file(link)
    assert values == {31: 2.0}
    assert write_var_file(link, numbered_from(values)) == []
    assert not link.is_symlink() and read_var_file(link)[31] == 2.0
    assert target.read_bytes() == b"31 2\n"
    assert (tmp_path / "l.var.bak").is_symlink()


@pytest.mark.parametrize("kind", ["fifo", "device", "link-to-fifo"])
def test_a_save_never_replaces_a_fifo_or_a_device(
    kind: str, tmp_path: Path, request: pytest.FixtureRequest
) -> None:
    if kind == "link-to-fifo":
        path = tmp_path / "l.var"
        os.symlink(request.getfixturevalue("fifo"), path)
    else:
        path = request.getfixturevalue(kind)
    before = sorted(p.name for p in tmp_path.iterdir())
    mode = os.stat(path).st_mode
    assert write_var_file(path, numbered_from({})) == [
        f"Unable to save parameter file: '{path}' is not a regular file"
    ]
    assert write_var_file(path, numbered_from({}), [31], backup=False) == [
        varfile.NOT_REGULAR.format(path)
    ]
    assert os.stat(path).st_mode == mode
    assert sorted(p.name for p in tmp_path.iterdir()) == before


@pytest.mark.parametrize("unnamed", [True, False], ids=["unnamed", "named"])
def test_a_fifo_put_in_place_during_the_save_is_not_replaced(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, unnamed: bool
) -> None:
    if not unnamed:
        monkeypatch.delattr(os, "O_TMPFILE", raising=False)
    path = tmp_path / "b.var"
    path.write_bytes(b"5161 1\n")
    real = varfile._write_temp

    def swap(name: str, data: bytes, permissions: int | None) -> str | None:
        temp = real(name, data, permissions)
        os.unlink(path)
        os.mkfifo(path)
        return temp

    monkeypatch.setattr(varfile, "_write_temp", swap)
    assert write_var_file(path, numbered_from({})) == [varfile.NOT_REGULAR.format(path)]
    assert stat.S_ISFIFO(os.lstat(path).st_mode)
    assert [p.name for p in tmp_path.iterdir()] == ["b.var"]


def rs274_run(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, *args: str) -> tuple[int, str, str]:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "p.ngc").write_text("#31=5\nG0 X1\nM2\n")
    out, err = io.StringIO(), io.StringIO()
    code = rs274.run([*args, "-g", "p.ngc"], stdout=out, stderr=err)
    return code, out.getvalue(), err.getvalue()


@pytest.mark.parametrize("name", ["f.var", "/dev/null"])
def test_rs274_refuses_a_fifo_or_device_before_the_program(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, name: str
) -> None:
    # As for a var file rs274 cannot open: only USE_LENGTH_UNITS, the message, an empty line, rc 1.
    os.mkfifo(tmp_path / "f.var")
    code, out, err = rs274_run(tmp_path, monkeypatch, "-v", name)
    assert (code, err) == (1, f"executing\n{unable_to_open(name)}\n\n")
    assert out == "    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["f.var", "p.ngc"]
    assert stat.S_ISFIFO(os.lstat(tmp_path / "f.var").st_mode)


# -- permission bits -----------------------------------------------------------------------------


@pytest.mark.parametrize("mode", [0o444, 0o600, 0o640, 0o755])
@pytest.mark.parametrize("unnamed", [True, False], ids=["unnamed", "named"])
def test_a_save_keeps_the_permission_bits(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, mode: int, unnamed: bool
) -> None:
    if not unnamed:
        monkeypatch.delattr(os, "O_TMPFILE", raising=False)
    path = tmp_path / "b.var"
    path.write_bytes(b"31 1\n")
    path.chmod(mode)
    code, _, err = rs274_run(tmp_path, monkeypatch, "-v", "b.var")
    assert (code, err) == (0, "executing\n")
    assert stat.S_IMODE(os.stat(path).st_mode) == mode
    assert read_var_file(path)[31] == 5.0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["b.var", "b.var.bak", "p.ngc"]


@pytest.mark.parametrize("unnamed", [True, False], ids=["unnamed", "named"])
def test_a_new_file_gets_0666_less_the_umask_like_rs274(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, unnamed: bool
) -> None:
    if not unnamed:
        monkeypatch.delattr(os, "O_TMPFILE", raising=False)
    old = os.umask(0o027)
    try:
        write_var_file(tmp_path / "n.var", numbered_from({}))
    finally:
        os.umask(old)
    assert stat.S_IMODE(os.stat(tmp_path / "n.var").st_mode) == 0o640


# -- no temporary file outlives a save -----------------------------------------------------------


def test_without_unnamed_files_a_named_one_is_written(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.delattr(os, "O_TMPFILE", raising=False)
    test_two_saves_leave_rs274s_file_and_backup(UNCHANGED[0], tmp_path)


def test_when_an_unnamed_file_cannot_be_linked_a_named_one_is_written(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    real_link = os.link

    def no_proc(src: str, dst: str, **kwargs: object) -> None:
        if src.startswith("/proc/"):
            raise FileNotFoundError(2, "No such file or directory")
        real_link(src, dst, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(varfile.os, "link", no_proc)
    test_two_saves_leave_rs274s_file_and_backup(UNCHANGED[0], tmp_path)


@pytest.mark.parametrize("unnamed", [True, False], ids=["unnamed", "named"])
def test_a_failed_write_leaves_no_temporary_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, unnamed: bool
) -> None:
    if not unnamed:
        monkeypatch.delattr(os, "O_TMPFILE", raising=False)
    test_failed_write_keeps_the_old_file(tmp_path, monkeypatch)


@pytest.mark.parametrize("unnamed", [True, False], ids=["unnamed", "named"])
@pytest.mark.parametrize("where", ["write", "replace"])
def test_an_interrupted_save_leaves_no_temporary_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, unnamed: bool, where: str
) -> None:
    if not unnamed:
        monkeypatch.delattr(os, "O_TMPFILE", raising=False)
    target = tmp_path / "b.var"
    target.write_bytes(b"5161 1\n")

    def interrupt(*args: object) -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr(varfile.os, "fsync" if where == "write" else "replace", interrupt)
    with pytest.raises(KeyboardInterrupt):
        write_var_file(target, numbered_from({}))
    assert target.read_bytes() == b"5161 1\n"
    assert [p.name for p in tmp_path.iterdir()] == ["b.var"] if where == "write" else ["b.var", "b.var.bak"]
