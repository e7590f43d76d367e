"""The progress line (``ngc.progress``): what it says, when it shows, that it is erased; and, on
a pseudo-terminal, ``ngc canon``/``check``/``rs274`` showing it and ending cleanly on Ctrl-C."""

from __future__ import annotations

import fcntl
import io
import os
import pty
import select
import signal
import struct
import subprocess
import sys
import termios
import time
from pathlib import Path

import pytest

from ngc import progress
from ngc.progress import ERASE, Progress

SRC = Path(__file__).resolve().parent.parent / "src"


class Clock:
    """A clock that moves only when told to."""

    def __init__(self) -> None:
        self.now = 100.0

    def __call__(self) -> float:
        return self.now


class Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_inactive_returns_the_lines_themselves() -> None:
    lines = ["G0 X1", "M2"]
    shown = Terminal()
    with Progress(shown, "f.ngc", None, active=False) as p:
        assert p.lines(lines) is lines
    assert shown.getvalue() == ""


def test_same_lines_through_the_wrapper() -> None:
    for count in (0, 1, progress.STEP - 1, progress.STEP, progress.STEP + 1, 3 * progress.STEP):
        lines = [f"N{i}" for i in range(count)]
        p = Progress(Terminal(), "f.ngc", None, active=True, clock=Clock())
        assert list(p.lines(lines)) == lines
        assert p.count == count - count % progress.STEP


def test_a_short_run_shows_nothing() -> None:
    shown, clock = Terminal(), Clock()
    with Progress(shown, "f.ngc", None, active=True, clock=clock) as p:
        for _ in p.lines(["G0 X1"] * (5 * progress.STEP)):
            clock.now += 0.00001  # 0.2 s in all
    assert shown.getvalue() == ""


def test_a_long_run_shows_then_erases(tmp_path: Path) -> None:
    path = tmp_path / "big.ngc"
    path.write_text("G1 X1\n" * (4 * progress.STEP))  # 6 bytes a line: 98,304 bytes
    shown, clock = Terminal(), Clock()
    with open(path) as handle, Progress(shown, "big.ngc", handle.fileno(), active=True,
                                        clock=clock) as p:
        for _ in p.lines(handle):
            clock.now += 0.001  # 4.096 s per look at the clock: each one paints
        painted = shown.getvalue()
    paints = painted.split(ERASE)[1:]
    assert len(paints) == 4
    assert paints[0].startswith("big.ngc: ")
    assert paints[0].endswith(" / 98.3 kB (8%), 4,096 lines, 0:04") or "%), 4,096 lines" in paints[0]
    assert paints[3].endswith(" / 98.3 kB (100%), 16,384 lines, 0:16")
    assert shown.getvalue() == painted + ERASE


def test_repaints_are_throttled() -> None:
    shown, clock = Terminal(), Clock()
    p = Progress(shown, "f.ngc", None, active=True, clock=clock)
    clock.now += progress.DELAY
    lines = p.lines(["x"] * (10 * progress.STEP))
    for i, _ in enumerate(lines):
        if i % progress.STEP == 0:
            clock.now += progress.REPAINT / 2
    assert shown.getvalue().count(ERASE) == 5  # every other look at the clock


def test_text() -> None:
    clock = Clock()
    p = Progress(Terminal(), "big.ngc", None, active=True, clock=clock)
    p.count = 1_576_960
    assert p.text(clock.now + 63.9) == "big.ngc: 1,576,960 lines, 1:03"


def test_text_with_size(tmp_path: Path) -> None:
    path = tmp_path / "f.ngc"
    path.write_bytes(b"x" * 40_000_000)
    clock = Clock()
    with open(path, "rb") as handle:
        handle.seek(12_600_000)
        p = Progress(Terminal(), "f.ngc", handle.fileno(), active=True, clock=clock)
        assert p.text(clock.now + 3) == "f.ngc: 12.6 MB / 40.0 MB (31%), 0 lines, 0:03"


def test_byte_counts() -> None:
    sizes = [0, 999, 1000, 999_949, 999_950, 12_345_678, 4_200_000_000]
    assert [progress._bytes(n) for n in sizes] == [
        "0 B", "999 B", "1.0 kB", "999.9 kB", "1.0 MB", "12.3 MB", "4.2 GB",
    ]  # fmt: skip


@pytest.mark.parametrize(("columns", "cut"), [(30, 29), (5, progress.MIN_WIDTH - 1),
                                              (0, progress.FALLBACK_WIDTH - 1)])
def test_the_line_fits_the_terminal(columns: int, cut: int) -> None:
    """Cut to the terminal's width (a size of 0 columns means none was set)."""
    master, slave = pty.openpty()
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 24, columns, 0, 0))
    with open(slave, "w") as terminal:
        clock = Clock()
        p = Progress(terminal, "x" * 200, None, active=True, clock=clock)
        clock.now += progress.DELAY
        for _ in p.lines(["G0"] * progress.STEP):
            pass
        terminal.flush()
        painted = os.read(master, 4096)
    os.close(master)
    assert painted == (ERASE + "x" * cut).encode()


def test_not_a_terminal() -> None:
    assert not progress.is_terminal(io.StringIO())
    assert progress.is_terminal(Terminal())
    assert progress.descriptor(io.StringIO()) is None
    assert progress.descriptor(object()) is None


# -- on a pseudo-terminal ------------------------------------------------------------------------
QUICK = "import sys, ngc.progress as p; p.DELAY = 0.0; import ngc.cli; sys.exit(ngc.cli.main())"


@pytest.fixture(scope="module")
def big(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("progress") / "big.ngc"
    body = "".join(f"G1 X{i % 97} Y{i % 89}\n" for i in range(60_000))
    path.write_text("G21 F100\n" + body + "M2\n")
    return path


def on_terminal(argv: list[str], *, interrupt: bool = False, quick: bool = True,
                cwd: Path | None = None) -> tuple[int, bytes, bytes]:
    """Run ngc with stderr on a pseudo-terminal and stdout into a pipe; with ``interrupt``, send
    SIGINT once the progress line shows.  Returns the exit code, stdout, what the terminal got."""
    master, slave = pty.openpty()
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 24, 250, 0, 0))
    command = [sys.executable, "-c", QUICK] if quick else [sys.executable, "-m", "ngc"]
    proc = subprocess.Popen([*command, *argv], stdout=subprocess.PIPE, stderr=slave,
                            stdin=subprocess.DEVNULL, cwd=cwd,
                            env={**os.environ, "PYTHONPATH": str(SRC)})
    os.close(slave)
    assert proc.stdout is not None
    terminal, out = b"", b""
    try:
        deadline = time.monotonic() + 60
        sent = False
        streams = [master, proc.stdout.fileno()]
        while streams and time.monotonic() < deadline:
            ready, _, _ = select.select(streams, [], [], 1.0)
            for fd in ready:
                try:
                    chunk = os.read(fd, 65536)
                except OSError:  # the terminal's other end is closed
                    chunk = b""
                if not chunk:
                    streams.remove(fd)
                elif fd == master:
                    terminal += chunk
                else:
                    out += chunk
            if interrupt and not sent and b" lines, " in terminal:
                proc.send_signal(signal.SIGINT)
                sent = True
        code = proc.wait(timeout=10)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
        os.close(master)
        proc.stdout.close()
    return code, out, terminal


def painted_and_erased(terminal: bytes) -> None:
    assert terminal.startswith(b"\r\x1b[K")
    assert b" lines, 0:0" in terminal
    assert terminal.endswith(b"\r\x1b[K")
    assert b"Traceback" not in terminal


@pytest.mark.parametrize("command", [["canon"], ["check"], ["canon", "--format", "json"]])
def test_progress_on_a_terminal(big: Path, command: list[str]) -> None:
    code, out, terminal = on_terminal([*command, str(big)])
    assert code == 0
    painted_and_erased(terminal)
    assert f"{big}: ".encode() in terminal
    assert b"%), " in terminal  # the size of a regular file is known
    assert out  # the output itself is untouched


def test_progress_of_rs274_on_a_terminal(big: Path) -> None:
    code, out, terminal = on_terminal(["rs274", "-g", str(big)])
    assert code == 0
    assert terminal.startswith(b"executing\r\n")
    painted_and_erased(terminal[len(b"executing\r\n"):])
    assert out.endswith(b"ON_RESET()\n")


def test_no_progress_for_a_short_run(tmp_path: Path) -> None:
    (tmp_path / "f.ngc").write_text("G0 X1\nM2\n")
    code, _, terminal = on_terminal(["check", "f.ngc"], quick=False, cwd=tmp_path)
    assert (code, terminal) == (0, b"")


def test_errors_come_after_the_erased_line(big: Path, tmp_path: Path) -> None:
    bad = tmp_path / "bad.ngc"
    bad.write_text(big.read_text().replace("M2\n", "G2 X2 R0.1\nM2\n"))
    code, _, terminal = on_terminal(["canon", str(bad)])
    assert code == 1
    before, _, error = terminal.rpartition(b"\r\x1b[K")
    assert before.startswith(b"\r\x1b[K")
    assert error.startswith(f"{bad}:60002: Arc radius too small".encode())


@pytest.mark.parametrize("command", [["canon"], ["check"], ["rs274", "-g"]])
def test_ctrl_c_ends_cleanly(tmp_path: Path, command: list[str]) -> None:
    """Exit 130, no traceback, the progress line erased last."""
    path = tmp_path / "huge.ngc"
    path.write_text("G21 F100\n" + "G1 X1 Y2\nG1 X2 Y1\n" * 500_000 + "M2\n")
    code, _, terminal = on_terminal([*command, str(path)], interrupt=True)
    assert code == 130
    assert b"Traceback" not in terminal and b"KeyboardInterrupt" not in terminal
    assert terminal.endswith(b"\r\x1b[K")
