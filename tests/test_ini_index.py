"""The INI reader's index gives the answers of rs274's search from the start of the file on each
lookup (the reference below, the reader as it was), in time and memory in proportion to the
file; a file over the size limit is refused with a message."""

from __future__ import annotations

import random
import time
import tracemalloc
from pathlib import Path

import pytest

from ngc import cli
from ngc.config.ini import BLANKS, MAX_INI_BYTES, Ini, IniTooLarge

NAME_END = set(" \t\n\v\f\r=")


def reference_lines(text: str) -> list[str]:
    parts = text.split("\n")
    lines = [part + "\n" for part in parts[:-1]]
    if parts[-1]:
        lines.append(parts[-1])
    return lines


def ambiguous(line: str) -> bool:
    body = line[:-1] if line.endswith("\n") else line
    return "\r" in body[:-1]


def reference_get(text: str, section: str, name: str) -> str | None:
    """rs274's lookup: find the section's first header, then walk its logical lines."""
    lines = reference_lines(text)
    index = None
    for number, line in enumerate(lines):
        if ambiguous(line):
            return None
        stripped = line.lstrip(BLANKS)
        close = stripped.find("]")
        if stripped.startswith("[") and close > 0 and stripped[1:close] == section:
            index = number + 1
            break
    if index is None:
        return None
    while index < len(lines):
        joined = ""
        while True:
            if index >= len(lines):
                return None
            line = lines[index]
            index += 1
            if ambiguous(line):
                return None
            if not line.endswith("\\\n"):
                logical = joined + (line[:-1] if line.endswith("\n") else line)
                break
            joined += line[:-2]
        stripped = logical.lstrip(BLANKS)
        if stripped.startswith("["):
            return None
        if stripped.startswith(("#", ";")):
            continue
        end = next((i for i, c in enumerate(stripped) if c in NAME_END), len(stripped))
        if stripped[:end] != name:
            continue
        equals = stripped.find("=", end)
        return None if equals < 0 else stripped[equals + 1:].strip(BLANKS)
    return None


PIECES = ["[S]", "[T]", "[S", " [S] x", "A", "B", " A", "=", " = ", "1", "2", "\\", "\r", "#",
          ";", " ", "\t", "]", "[", "AB"]


def random_text(rng: random.Random) -> str:
    lines = ["".join(rng.choice(PIECES) for _ in range(rng.randint(0, 4)))
             for _ in range(rng.randint(0, 12))]
    return "\n".join(lines) + rng.choice(["", "\n", "\r\n", "\\\n"])


def test_the_index_answers_as_the_search_does() -> None:
    rng = random.Random(28)
    for _ in range(6000):
        text = random_text(rng)
        ini = Ini.parse(text)
        for section in ("S", "T", "U", "S "):
            for name in ("A", "B", "AB", "", "#", "1"):
                assert ini.get(section, name) == reference_get(text, section, name), (
                    text, section, name)
        lines = reference_lines(text)
        assert ini.lines == tuple(lines)
        assert ini.ambiguous_carriage_returns == any(ambiguous(line) for line in lines)
        assert ini.dos_line_endings == any(
            (line[:-1] if line.endswith("\n") else line).endswith("\r") for line in lines)


def big_ini(keys: int) -> str:
    body = "".join(f"KEY_{n} = {n}\n" for n in range(keys))
    return f"[TRAJ]\nCOORDINATES = X\n[BIG]\n{body}[AXIS_X]\nMAX_VELOCITY = 1\n"


def test_lookups_do_not_search_the_file_again(tmp_path: Path) -> None:
    # a thousand lookups in a file of 160,000 names: each search from the start took ~40 µs a
    # name (minutes); the index answers them all at once (well within a second on any machine)
    path = tmp_path / "big.ini"
    path.write_text(big_ini(160_000))
    started = time.process_time()  # (CPU time: a busy machine does not make it slow)
    ini = Ini.read(path)
    for n in range(0, 160_000, 160):
        assert ini.get("BIG", f"KEY_{n}") == str(n)
        assert ini.get("AXIS_X", "MAX_VELOCITY") == "1"
    assert time.process_time() - started < 20.0


def test_reading_takes_little_more_memory_than_the_text(tmp_path: Path) -> None:
    path = tmp_path / "big.ini"
    path.write_text(big_ini(150_000))
    size = path.stat().st_size
    tracemalloc.start()
    try:
        ini = Ini.read(path)
        assert ini.get("AXIS_X", "MAX_VELOCITY") == "1"
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < 3 * size  # the bytes and the text: a tuple of lines took ten times the size


def test_a_file_over_the_limit_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "huge.ini"
    with path.open("wb") as handle:
        handle.truncate(MAX_INI_BYTES + 1)
    with pytest.raises(IniTooLarge) as caught:
        Ini.read(path)
    assert caught.value.message == (f"INI file {path} is larger than {MAX_INI_BYTES} bytes: "
                                    "not read")
    with path.open("wb") as handle:
        handle.truncate(MAX_INI_BYTES)
    assert Ini.read(path).get("S", "A") is None  # up to the limit: read


def test_a_file_over_the_limit_on_the_command_line(capsys: pytest.CaptureFixture[str],
                                                   tmp_path: Path) -> None:
    path = tmp_path / "huge.ini"
    with path.open("wb") as handle:
        handle.truncate(MAX_INI_BYTES + 1)
    program = tmp_path / "p.ngc"
    program.write_text("G0 X1\nM2\n")
    code = cli.main(["time", "-i", str(path), str(program)])
    out, err = capsys.readouterr()
    assert (code, out) == (2, "")
    assert err == f"ngc time: INI file {path} is larger than {MAX_INI_BYTES} bytes: not read\n"
