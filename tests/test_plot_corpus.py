"""Every program of ``../shared/conformance`` and of every fuzzer kind plots without an internal
error (an error in the program stops the drawing, as it should), as SVG and as PNG, in every
view."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

pytest.importorskip("resvg_py")

from ngc.commands.plot import PlotOptions, draw
from ngc.config.tooltable import parse_tool_table
from ngc.interp.interpreter import Interpreter
from ngc.options import MachineOptions, Setup, new_interpreter

FUZZ = Path(__file__).parent / "fuzz"
sys.path.insert(0, str(FUZZ))

import gen  # noqa: E402

CASES = Path(__file__).resolve().parents[2] / "shared" / "conformance" / "cases"
VIEWS = ("top", "front", "side", "iso", "lathe")


def _plot(text: str, name: str, out: Path, table: str | None, view: str) -> None:
    setup = Setup() if table is None else Setup(tools=parse_tool_table(table))

    def interpreter(sink: object) -> Interpreter:
        return new_interpreter(sink, MachineOptions(), setup, write_files=False)  # type: ignore[arg-type]

    draw(text.splitlines(), name, str(out), interpreter, PlotOptions(view=view))
    assert out.stat().st_size > 0


def _cases() -> list[Path]:
    return sorted(p for p in CASES.iterdir() if (p / "case.json").exists()) if CASES.is_dir() else []


@pytest.mark.skipif(not CASES.is_dir(), reason="no ../shared/conformance")
def test_every_conformance_program_plots(tmp_path: Path) -> None:
    cases = _cases()
    assert len(cases) >= 300
    for i, case in enumerate(cases):
        spec = json.loads((case / "case.json").read_text())
        args = spec["args"]
        program = case / args[-1]
        table = None
        if "-t" in args:
            tbl = case / args[args.index("-t") + 1]
            table = tbl.read_text(encoding="latin-1") if tbl.exists() else None
        text = program.read_bytes().decode("utf-8", "surrogateescape")
        view = VIEWS[i % len(VIEWS)]
        for ext in ("svg", "png"):
            _plot(text, str(program), tmp_path / f"{case.name}.{ext}", table, view)


@pytest.mark.parametrize("kind", sorted(gen.KINDS))
def test_every_fuzzer_kind_plots(kind: str, tmp_path: Path) -> None:
    for seed in range(1, 9):
        text = gen.generate(kind, seed)
        view = VIEWS[seed % len(VIEWS)]
        for ext in ("svg", "png"):
            _plot(text, f"{kind}-{seed}.ngc", tmp_path / f"{kind}-{seed}.{ext}",
                  gen.table_of(text), view)
