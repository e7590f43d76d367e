"""Program files read in rs274's pieces, and bodies of lines that read their file again instead of
keeping it (``ngc.interp.source``, ``ngc.interp.flow.Body``)."""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from ngc.canon.jsonl import ListSink
from ngc.errors import NgcError
from ngc.interp.interpreter import Interpreter
from ngc.interp.source import CACHE_LINES, LINE_BYTES, MAX_PIECES, ProgramReader, open_program


def pieces(data: bytes) -> list[str]:
    return list(ProgramReader(io.BytesIO(data)))


def test_lines_keep_their_newline_and_carriage_return() -> None:
    assert pieces(b"G0 X1\r\nG0 X2\nM2") == ["G0 X1\r\n", "G0 X2\n", "M2"]


def test_a_line_is_read_in_pieces_of_rs274s_buffer() -> None:
    line = b"A" * 300 + b"\n"
    got = pieces(line)
    assert [len(p) for p in got] == [LINE_BYTES, 301 - LINE_BYTES]


def test_endless_input_without_a_newline_is_refused_not_held() -> None:
    data = b"\0" * (LINE_BYTES * (MAX_PIECES + 2))
    with pytest.raises(NgcError, match="Command too long"):
        pieces(data)


def test_the_zero_device_ends_with_an_error() -> None:
    with open_program("/dev/zero") as reader:
        interp = Interpreter(ListSink())
        with pytest.raises(NgcError, match="Command too long"):
            interp.run(reader)


def test_a_byte_order_mark_is_skipped_on_request() -> None:
    data = b"\xef\xbb\xbfG0 X1\n"
    assert list(ProgramReader(io.BytesIO(data), skip_bom=True)) == ["G0 X1\n"]
    assert next(iter(ProgramReader(io.BytesIO(data)))).startswith("\xef\xbb\xbf")


def test_read_at_restores_the_position() -> None:
    reader = ProgramReader(io.BytesIO(b"a\nb\nc\n"))
    it = iter(reader)
    assert next(it) == "a\n"
    assert reader.read_at(0, 2) == ["a\n", "b\n"]
    assert next(it) == "b\n"


def _program(filler: int) -> str:
    """A subroutine at the top, many lines, then calls and a loop that go back to it."""
    lines = ["o100 sub", "G1 X[#1] F100", "o100 endsub"]
    lines += [f"G0 Y{i % 97}" for i in range(filler)]
    lines += ["o100 call [1]", "#2=0", "o200 while [#2 LT 3]", "o100 call [#2]",
              "#2=[#2+1]", "o200 endwhile", "o100 call [7]", "M2"]
    return "\n".join(lines) + "\n"


def _ops(interp_input: object, reader: ProgramReader | None = None) -> list[object]:
    sink = ListSink()
    interp = Interpreter(sink)
    interp.run(interp_input, reader=reader)  # type: ignore[arg-type]
    return sink.ops


@pytest.mark.parametrize("fast", [True, False])
def test_lines_read_again_from_the_file_give_the_same_run(tmp_path: Path, fast: bool) -> None:
    text = _program(3 * CACHE_LINES)
    path = tmp_path / "p.ngc"
    path.write_text(text)
    kept = _ops(text.splitlines())
    with open_program(str(path)) as reader:
        sink = ListSink()
        interp = Interpreter(sink, fast=fast)
        interp.run(reader)
        tape = interp.flow.tape
        assert tape is not None and tape.reader is reader
        assert len(tape.cache) <= CACHE_LINES  # the cache started over: lines were read again
    assert sink.ops == kept


def test_a_subroutine_file_is_read_as_needed(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    body = ["o<far> sub"] + [f"G0 X{i % 13}" for i in range(2 * CACHE_LINES)] + ["o<far> endsub"]
    (tmp_path / "far.ngc").write_text("\n".join(body) + "\n")
    program = ["o<far> call", "o<far> call", "M2"]
    sink = ListSink()
    interp = Interpreter(sink)
    interp.run(program)
    assert interp.flow.opened == []  # closed at the end of the run
    moves = [op for op, _, _ in sink.ops if type(op).__name__ == "StraightTraverse"]
    assert len(moves) == 2 * 2 * CACHE_LINES


def test_unseekable_input_is_kept() -> None:
    class Pipe(io.BytesIO):
        def seekable(self) -> bool:
            return False

    text = _program(CACHE_LINES + 10)
    reader = ProgramReader(Pipe(text.encode()))
    assert reader.seekable is False
    assert _ops(reader) == _ops(text.splitlines())
