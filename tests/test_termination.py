"""SIGTERM and SIGHUP end a run through its cleanup code (``ngc.termination``): a parameter file
being saved when the signal comes leaves no temporary file, and the exit code is 128 + the signal."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
import threading
from pathlib import Path

import pytest

from ngc.termination import SIGNALS, Terminated, signals_raise

# Runs ``ngc rs274 -v b.var -g p.ngc`` and sends itself a signal in the middle of the first save:
# while the data is written (argv[2] == "write") or just before the rename ("replace").
SIGNALLED_SAVE = textwrap.dedent(
    """
    import os, signal, sys
    from ngc import cli

    where, signum, unnamed = sys.argv[1], int(sys.argv[2]), sys.argv[3] == "unnamed"
    if not unnamed:
        del os.O_TMPFILE
    real = {"write": os.write, "replace": os.replace}

    def signalled(*args):
        os.kill(os.getpid(), signum)
        return real[where](*args)

    setattr(os, where, signalled)
    sys.exit(cli.main(["rs274", "-v", "b.var", "-g", "p.ngc"]))
    """
)


@pytest.mark.parametrize("unnamed", [True, False], ids=["unnamed", "named"])
@pytest.mark.parametrize("where", ["write", "replace"])
@pytest.mark.parametrize("signum", SIGNALS, ids=[s.name for s in SIGNALS])
def test_a_signal_during_the_save_leaves_no_temporary_file(
    tmp_path: Path, unnamed: bool, where: str, signum: signal.Signals
) -> None:
    (tmp_path / "b.var").write_bytes(b"31 1\n")
    (tmp_path / "p.ngc").write_text("#31=2\nM2\n")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    done = subprocess.run(
        [sys.executable, "-c", SIGNALLED_SAVE, where, str(int(signum)), "unnamed" if unnamed else "named"],
        cwd=tmp_path, env=env, capture_output=True, check=False, timeout=60,
    )
    assert done.returncode == 128 + signum, done.stderr
    assert b"Traceback" not in done.stderr
    assert (tmp_path / "b.var").read_bytes() == b"31 1\n"
    # Before the rename, the backup link is made: that is all a save left behind.
    backup = ["b.var.bak"] if where == "replace" else []
    assert sorted(p.name for p in tmp_path.iterdir()) == ["b.var", *backup, "p.ngc"]


def test_the_signals_raise_inside_and_the_old_handlers_come_back() -> None:
    before = [signal.getsignal(s) for s in SIGNALS]
    with signals_raise():
        for signum in SIGNALS:
            with pytest.raises(Terminated) as caught:
                signal.raise_signal(signum)
            assert caught.value.signum == signum
            assert caught.value.exit_code == 128 + signum
    assert [signal.getsignal(s) for s in SIGNALS] == before


def test_an_ignored_signal_stays_ignored() -> None:
    previous = signal.signal(signal.SIGHUP, signal.SIG_IGN)
    try:
        with signals_raise():
            assert signal.getsignal(signal.SIGHUP) is signal.SIG_IGN
            signal.raise_signal(signal.SIGHUP)  # ignored: nothing happens
        assert signal.getsignal(signal.SIGHUP) is signal.SIG_IGN
    finally:
        signal.signal(signal.SIGHUP, previous)


def test_outside_the_main_thread_nothing_changes() -> None:
    seen: list[object] = []

    def body() -> None:
        with signals_raise():
            seen.append(signal.getsignal(signal.SIGTERM))

    before = signal.getsignal(signal.SIGTERM)
    thread = threading.Thread(target=body)
    thread.start()
    thread.join()
    assert seen == [before]
