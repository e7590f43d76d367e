"""Helpers the command-line tests share: running ``ngc`` in-process and writing input files."""

from __future__ import annotations

from pathlib import Path

import pytest

from ngc import cli


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    """``ngc ARGV`` in this process: its exit code, stdout and stderr."""
    code = cli.main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def write(tmp_path: Path, name: str, text: str | bytes) -> str:
    """``text`` (as it is, bytes or text) in the file ``name`` under ``tmp_path``; its path."""
    path = tmp_path / name
    if isinstance(text, bytes):
        path.write_bytes(text)
    else:
        path.write_text(text)
    return str(path)
