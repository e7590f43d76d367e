"""Write the golden flattened programs: ``ngc flatten`` of each ``tests/golden/flatten/NAME.ngc``
for each target, on ``machine.ini`` and ``tools.tbl`` there, to ``NAME.TARGET.nc`` (or, for a
program that is refused, its message to ``NAME.TARGET.err``).  Run after a change to the
writer that is meant, and read what changed.

    python tests/golden/flatten_regen.py
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent / "flatten"
TARGETS = ("linuxcnc", "grbl", "grblhal", "fluidnc")
INPUTS = ("-i", "machine.ini", "-t", "tools.tbl")


def programs() -> list[Path]:
    return sorted(HERE.glob("*.ngc"))


def flatten(program: Path, target: str) -> subprocess.CompletedProcess[str]:
    """``ngc flatten`` of ``program`` for ``target``, run in the golden folder."""
    return subprocess.run([sys.executable, "-m", "ngc", "flatten", *INPUTS, "--target", target,
                           program.name], cwd=HERE, capture_output=True, text=True, check=False)


def golden(program: Path, target: str) -> tuple[Path, Path]:
    """The files of ``program``'s golden output for ``target``: the program written, and the
    refusal."""
    return (HERE / f"{program.stem}.{target}.nc", HERE / f"{program.stem}.{target}.err")


def main() -> None:
    for program in programs():
        for target in TARGETS:
            done = flatten(program, target)
            written, refused = golden(program, target)
            written.unlink(missing_ok=True)
            refused.unlink(missing_ok=True)
            if done.returncode == 0:
                written.write_text(done.stdout)
            else:
                refused.write_text(done.stderr)
            print(f"{program.name} {target}: exit {done.returncode}")


if __name__ == "__main__":
    main()
