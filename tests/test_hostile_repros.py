"""The reproducing programs of the hostile-input reports on the newer surfaces (the engine
dialect's reader and segments, the lathe cycles, the loops inside codes), through the commands
under a small ``--max-iterations``: each ends at once, cleanly (no traceback), with the work
limit where its numbers ask for more work than that."""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from ngc import cli

BUDGET = "100"
LIMIT = "Work limit reached: 100 "
# name -> (dialect, program, the message it ends with; None: it runs to its end)
PROGRAMS = {
    "engine-a-comma": ("engine", ",\n", None),
    "lathe-empty-profile": ("linuxcnc", "o100sub\no100endsub\nG18G71Q100\nM2\n", None),
    "g76-first-cut-1e-5": ("linuxcnc", "G18 G21\nS500 M3\nG0 X10 Z2\n"
                           "G76 P1.5 X12 I-0.5 J0.00001 K70 Q30\nM2\n", LIMIT),
    "engine-arc-radius-1e11": ("engine", "move PZ 0 360 100000000000 0\n", LIMIT),
    "engine-arc-angle-3.6e8": ("engine", "move PZ 0 360000000 1 0\n", LIMIT),
}


@pytest.mark.parametrize("command", ["canon", "check", "rs274"])
@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_repro_ends_cleanly_and_at_once(name: str, command: str, tmp_path: Path,
                                        capsys: pytest.CaptureFixture[str]) -> None:
    dialect, text, message = PROGRAMS[name]
    program = tmp_path / "p.ngc"
    program.write_text(text)
    started = time.monotonic()
    code = cli.main([command, "--max-iterations", BUDGET, "--dialect", dialect, str(program)])
    elapsed = time.monotonic() - started
    _, err = capsys.readouterr()
    assert elapsed < 5.0
    assert "Traceback" not in err and "internal error" not in err
    if message is None:
        assert code == 0, err
    else:
        assert code == 1
        assert message in err
