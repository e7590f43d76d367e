"""One file, both dialects: the codes they share with one meaning give the same canon (the end of
every G0 and G1, G4, G17-G19, G90/G91); where the seed gives a code another meaning (G21's feed
units, G53, G61) they differ as it says."""

from __future__ import annotations

import math

from ngc.canon.jsonl import ListSink
from ngc.engine import Dwell, Engine, EngineSegment, ModeChange, Setup, Stop, run
from ngc.engine.setup import Fixture
from ngc.interp.interpreter import Interpreter

SHARED = """%
G17
G21
G90
G0 X1 Y2 Z3
G1 X4 Y6 F100
G4 P0.5
G18
G91
G0 X1 Z-1
G1 Y2 Z0.5
G19
G90
G1 X0 Y0 Z0
G4 P2
G17
G0 X-1.5 Y2.25
%
"""

_PLANES = {"CANON_PLANE_XY": "XY", "CANON_PLANE_XZ": "ZX", "CANON_PLANE_YZ": "YZ"}


def linuxcnc(text: str) -> list[tuple[object, ...]]:
    """The program's own operations under the LinuxCNC dialect (after start-up), as
    (kind, line, values)."""
    sink = ListSink()
    interp = Interpreter(sink)
    interp.startup()
    interp.run(text.splitlines())
    out: list[tuple[object, ...]] = []
    for op, _label, line in sink.ops:
        name = type(op).__name__
        if not line:
            continue
        if name in ("StraightTraverse", "StraightFeed"):
            kind = "rapid" if name == "StraightTraverse" else "feed"
            out.append((kind, line, (op.x, op.y, op.z)))  # type: ignore[union-attr]
        elif name == "Dwell":
            out.append(("dwell", line, op.seconds))  # type: ignore[union-attr]
        elif name == "SelectPlane":
            out.append(("plane", line, _PLANES[op.plane]))  # type: ignore[union-attr]
        elif name == "SetMotionControlMode":
            out.append(("exact", line, op.mode))  # type: ignore[union-attr]
    return out


def engine(text: str, setup: Setup | None = None) -> list[tuple[object, ...]]:
    """The same under the engine dialect."""
    pos = {"X": 0.0, "Y": 0.0, "Z": 0.0}
    out: list[tuple[object, ...]] = []
    for op in run(text, Engine(setup=setup or Setup())):
        if isinstance(op, EngineSegment):
            pos.update({a: c[3] for a, c in op.axes.items() if a in pos})
            out.append((op.motion, op.line, (pos["X"], pos["Y"], pos["Z"])))
        elif isinstance(op, Dwell):
            out.append(("dwell", op.line, op.seconds))
        elif isinstance(op, ModeChange) and op.name == "PLANE":
            out.append(("plane", op.line, op.value))
        elif isinstance(op, Stop):
            out.append(("stop", op.line))
    return out


def _close(a: list[tuple[object, ...]], b: list[tuple[object, ...]]) -> bool:
    if len(a) != len(b):
        return False
    for x, y in zip(a, b, strict=True):
        if x[:2] != y[:2]:
            return False
        if isinstance(x[2], tuple):
            if not all(math.isclose(p, q, abs_tol=1e-9)
                       for p, q in zip(x[2], y[2], strict=True)):  # type: ignore[arg-type]
                return False
        elif x[2] != y[2]:
            return False
    return True


def test_shared_codes_give_the_same_canon() -> None:
    ours, theirs = engine(SHARED), linuxcnc(SHARED)
    assert len(ours) == 12
    assert _close(ours, theirs), (ours, theirs)


def test_g21_feed_is_per_second_in_the_engine() -> None:
    program = "%\nG21\nG1 X10 F100\n%\n"
    (feed,) = [op for op in run(program) if isinstance(op, EngineSegment)]
    assert abs(feed.duration - 0.1) < 1e-12  # 10 mm at 100 mm/s
    sink = ListSink()
    interp = Interpreter(sink)
    interp.startup()
    interp.run(program.splitlines())
    (rate,) = [op.rate for op, _, _ in sink.ops if type(op).__name__ == "SetFeedRate"]
    assert 10.0 / rate * 60.0 == 6.0  # LinuxCNC: 100 mm/min, 6 s


def test_g53_selects_fixture_0_for_good_in_the_engine() -> None:
    program = "%\nG54\nG0 X1\nG53 G0 X1\nG0 X1\n%\n"
    # G54's X offset 10: the engine's from its setup sheet, LinuxCNC's from G10 L2 (which the
    # engine does not have)
    offset = Fixture(offsets=(10.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0))
    ours = engine(program, Setup(fixtures=(Fixture(), offset, *(Fixture(),) * 5)))
    theirs = linuxcnc(program.replace("%\n", "%\nG10 L2 P1 X10\n", 1))
    # machine X: the engine stays in fixture 0 after G53 ...
    assert [x[2][0] for x in ours] == [11.0, 1.0, 1.0]  # type: ignore[index]
    # ... LinuxCNC's G53 is for its line alone (its canon is in G54's frame: -9 is machine 1)
    assert [x[2][0] for x in theirs] == [1.0, -9.0, 1.0]  # type: ignore[index]


def test_g61_stops_after_every_move_in_the_engine() -> None:
    program = "%\nG61\nG0 X1\nG0 X2\n%\n"
    assert engine(program) == [("rapid", 3, (1.0, 0.0, 0.0)), ("stop", 3),
                               ("rapid", 4, (2.0, 0.0, 0.0)), ("stop", 4)]
    assert linuxcnc(program) == [("exact", 2, "CANON_EXACT_PATH"),
                                 ("rapid", 3, (1.0, 0.0, 0.0)), ("rapid", 4, (2.0, 0.0, 0.0))]
