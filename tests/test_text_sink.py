"""The text sink: a move sent as its fields prints as the op does, each line as rs274's printf
prints it, and a kept tail never lends its text to another value (a -0.0 is not a 0.0)."""

from __future__ import annotations

import io
import random

from ngc.canon import ops
from ngc.canon.jsonl import ListSink
from ngc.canon.text import TextSink


def _moves(seed: int) -> list[tuple[type, list[float]]]:
    """Moves whose tails are often the same objects again, sometimes zeros of either sign."""
    rng = random.Random(seed)
    kept = [0.0, -0.0, 1.5, -2.25]
    moves = []
    for _ in range(400):
        tail = [rng.choice(kept) for _ in range(4)]
        if rng.random() < 0.3:
            tail[rng.randrange(4)] = float(rng.choice(("0.0", "-0.0")))  # a new zero object
        kind = rng.choice((ops.StraightTraverse, ops.StraightFeed, ops.ArcFeed))
        head: list[float] = [round(rng.uniform(-9, 9), 5) for _ in range(2)]
        if kind is ops.ArcFeed:
            head += [round(rng.uniform(-9, 9), 5) for _ in range(2)] + [rng.choice((1, -1, 2))]
        moves.append((kind, head + tail))
    return moves


def test_moves_print_as_printf_prints_them() -> None:
    by_op, by_fields = io.StringIO(), io.StringIO()
    a, b = TextSink(by_op), TextSink(by_fields)
    expected = []
    count = 0
    for i, (kind, fields) in enumerate(_moves(1)):
        a.emit(kind(*fields), "N..... ", i)
        b.emit_move(kind, fields, "N..... ", i)
        count += 1
        expected.append(("%5d %s" + ops.TEMPLATES[kind] + "\n") % (count, "N..... ", *fields))
        if i % 7 == 0:  # other calls in between
            a.emit(ops.Comment("c"), "N..... ", i)
            b.emit(ops.Comment("c"), "N..... ", i)
            count += 1
            expected.append(f'{count:5d} N..... COMMENT("c")\n')
    a.flush()
    b.flush()
    assert by_op.getvalue() == "".join(expected)
    assert by_fields.getvalue() == "".join(expected)


def test_kept_tail_keeps_the_sign_of_zero() -> None:
    out = io.StringIO()
    sink = TextSink(out)
    z = 0.0
    a = b = c = 0.0
    for i, zero in enumerate((z, z, z, -z, -z)):  # the text of 0.0 is kept from the third on
        sink.emit_move(ops.StraightFeed, [1.0, 2.0, zero, a, b, c], "N..... ", i)
    sink.flush()
    tails = [line.split("2.0000, ")[1] for line in out.getvalue().splitlines()]
    assert tails == ["0.0000, 0.0000, 0.0000, 0.0000)"] * 3 + ["-0.0000, 0.0000, 0.0000, 0.0000)"] * 2


def test_a_sink_without_emit_move_gets_the_ops() -> None:
    sink = ListSink()
    move = ops.mover(sink)
    move(ops.ArcFeed, [1.0, 2.0, 0.0, 0.0, -1, 0.0, 0.0, 0.0, 0.0], "N4 ", 4)
    assert sink.ops == [(ops.ArcFeed(1.0, 2.0, 0.0, 0.0, -1, 0.0, 0.0, 0.0, 0.0), "N4 ", 4)]
    assert type(sink.ops[0][0]) is ops.ArcFeed
