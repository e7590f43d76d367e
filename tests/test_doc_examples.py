"""Every ``ngc`` command line shown in the README and in ``docs/`` runs (exit 0), in a scratch
directory holding a copy of ``examples/``; the pictures the README shows are what ``ngc plot``
makes of them now."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
DOCS = [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]
BLOCK = re.compile(r"```(?:sh|bash)\n(.*?)```", re.S)


def _commands() -> list[tuple[str, str]]:
    found = []
    for doc in DOCS:
        for block in BLOCK.findall(doc.read_text()):
            for line in block.splitlines():
                command = line.split("  #", 1)[0].strip()
                if re.search(r"(^|\| )ngc ", command):
                    found.append((doc.relative_to(ROOT).as_posix(), command))
    return found


COMMANDS = _commands()


def test_the_docs_show_commands() -> None:
    assert len(COMMANDS) >= 10


@pytest.mark.parametrize(("doc", "command"), COMMANDS, ids=[f"{d}: {c}" for d, c in COMMANDS])
def test_command_runs(doc: str, command: str, tmp_path: Path) -> None:
    shutil.copytree(ROOT / "examples", tmp_path / "examples")
    script = f'ngc() {{ "{sys.executable}" -m ngc "$@"; }}\n{command}\n'
    done = subprocess.run(["bash", "-c", script], cwd=tmp_path, capture_output=True, text=True,
                          timeout=300, env={"PATH": "/usr/bin:/bin", "PYTHONPATH": str(ROOT / "src"),
                                            "HOME": str(tmp_path)})
    assert done.returncode == 0, done.stderr


SHOWN = re.compile(r"<!-- (output|stderr|json) of: (ngc [^>]*?) -->\n```\n(.*?)```", re.S)


def _shown_outputs() -> list[tuple[str, str, str, str]]:
    return [(doc.relative_to(ROOT).as_posix(), stream, command, text) for doc in DOCS
            for stream, command, text in SHOWN.findall(doc.read_text())]


SHOWN_OUTPUTS = _shown_outputs()


def test_docs_show_outputs() -> None:
    assert SHOWN_OUTPUTS


@pytest.mark.parametrize(("doc", "stream", "command", "text"), SHOWN_OUTPUTS,
                         ids=[f"{d}: {s} of {c}" for d, s, c, _ in SHOWN_OUTPUTS])
def test_shown_output_is_the_commands(doc: str, stream: str, command: str, text: str) -> None:
    """A block after ``<!-- output of: ngc ... -->`` is what the command prints now on stdout,
    after ``<!-- stderr of: ... -->`` on stderr; after ``<!-- json of: ... -->`` the same JSON
    (shown on several lines)."""
    done = subprocess.run([sys.executable, "-m", "ngc", *command.split()[1:]], cwd=ROOT,
                          capture_output=True, text=True, timeout=300)
    drifted = f"{doc}: the {stream} shown for `{command}` has drifted"
    if stream == "json":
        assert json.loads(done.stdout) == json.loads(text), drifted
    else:
        assert (done.stderr if stream == "stderr" else done.stdout) == text, drifted


PYTHON = re.compile(r"```python\n(.*?)```", re.S)


def _python_blocks() -> list[tuple[str, int, str]]:
    return [(doc.relative_to(ROOT).as_posix(), i, block) for doc in DOCS
            for i, block in enumerate(PYTHON.findall(doc.read_text()))]


PYTHON_BLOCKS = _python_blocks()


@pytest.mark.parametrize(("doc", "index", "code"), PYTHON_BLOCKS,
                         ids=[f"{d}: python block {i + 1}" for d, i, _ in PYTHON_BLOCKS])
def test_python_block_runs(doc: str, index: int, code: str, tmp_path: Path) -> None:
    shutil.copytree(ROOT / "examples", tmp_path / "examples")
    done = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, capture_output=True,
                          text=True, timeout=300,
                          env={"PATH": "/usr/bin:/bin", "PYTHONPATH": str(ROOT / "src"),
                               "HOME": str(tmp_path)})
    assert done.returncode == 0, done.stderr


PICTURES = re.compile(r"!\[[^\]]*\]\((docs/images/[^)]+\.svg)\)<!-- (ngc plot [^>]*) -->")


def test_readme_pictures_are_current(tmp_path: Path) -> None:
    """Each picture in the README is followed by the command that made it."""
    shown = PICTURES.findall((ROOT / "README.md").read_text())
    assert shown
    for image, command in shown:
        args = command.split()[2:]
        out = tmp_path / Path(image).name
        done = subprocess.run([sys.executable, "-m", "ngc", "plot", *args, "-o", str(out)],
                              cwd=ROOT, capture_output=True, text=True, timeout=300)
        assert done.returncode == 0, done.stderr
        assert out.read_text() == (ROOT / image).read_text(), f"{image} is out of date: {command}"
