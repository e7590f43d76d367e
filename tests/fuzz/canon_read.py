"""A reader of rs274's canon text (the ``rs274 -g`` transcript) into ngc's canonical operations,
and the machine path of a run through ngc's toolpath layer.

Each line of the transcript is a counter (``%5d ``), the N column (``N..... ``, ``N10    ``, or
``N123456`` when the number fills it) and a call printed with one of the templates of
:data:`ngc.canon.ops.TEMPLATES`.  The reader turns each template into a pattern once, so a call
is read back with exactly the fields the template prints: ``read`` gives the operations, and
:func:`machine_path` feeds them to :class:`~ngc.toolpath.tracker.Toolpath` and keeps the moves
as ngc flatten's verification does (:class:`ngc.flatten.verify.Moves`: kind, end, an arc's
centre, turns, line, axis, shape), the line being the transcript's counter.

rs274 prints lengths with four decimals in the program's units, so every number read is off by
up to half a unit of the fourth decimal (:data:`PRINTED`).  :func:`machine_path` gives each move
the bound of that rounding in machine coordinates (:class:`Bound`): the move's own coordinates,
the offsets it is shifted by (each printed in the units of its own time) and the XY rotation
(printed in degrees with four decimals: an error that grows with the distance from the origin
of the rotation).  A NURBS curve is printed as its number of points alone: ngc's own call for
it may be given (:func:`machine_path`), else it is kept as a ``nurbs`` move whose end is not
known.

Standard library and ngc only; ``python tests/fuzz/canon_read.py FILE`` prints the moves read
from a transcript.
"""

from __future__ import annotations

import math
import re
import sys
from collections import Counter
from collections.abc import Callable, Iterable, Iterator
from pathlib import Path
from typing import Any, NamedTuple

HERE = Path(__file__).resolve().parent
SRC = HERE.parent.parent / "src"
if str(SRC) not in sys.path:
    sys.path.insert(0, str(SRC))

from ngc.canon import ops  # noqa: E402
from ngc.flatten.curves import ArcShape  # noqa: E402
from ngc.flatten.verify import FINE, Move, Moves  # noqa: E402
from ngc.toolpath.tracker import ARC, Tee, Toolpath  # noqa: E402

# half a unit of the last decimal rs274 prints lengths and angles with (%.4f)
PRINTED = 0.5e-4

_LINE = re.compile(r"^ *(\d+) (N(?:\.{5} |\d+ *))(.*)$")
_NAME = re.compile(r"[A-Z][A-Z0-9_.]*(?=\()")
_FIELD = re.compile(r"(%[-+ #0-9.]*[dfs])")
# glibc's %f and %d: digits, and nan / inf with their signs
_PATTERNS = {"d": r"([-+]?\d+)", "f": r"([-+]?(?:\d+(?:\.\d*)?|nan|inf))", "s": r"(.*)"}
_CONVERT: dict[str, Callable[[str], Any]] = {"d": int, "f": float, "s": str}


class Unread(NamedTuple):
    """A call that no template matches: its name and its text."""

    name: str
    text: str


class Canon(NamedTuple):
    """One call of the transcript: its counter, N column, the operation and the line."""

    counter: int
    label: str
    op: Any
    text: str


class Template(NamedTuple):
    kind: type
    pattern: re.Pattern[str]
    convert: tuple[Callable[[str], Any], ...]


def _template(kind: type, template: str) -> Template:
    parts = _FIELD.split(template)
    pattern = []
    convert = []
    for i, part in enumerate(parts):
        if i % 2:
            pattern.append(_PATTERNS[part[-1]])
            convert.append(_CONVERT[part[-1]])
        else:
            pattern.append(re.escape(part))
    return Template(kind, re.compile("".join(pattern) + r"\Z"), tuple(convert))


def _templates() -> dict[str, tuple[Template, ...]]:
    """Each call's name -> the templates printed under it (SET_MOTION_CONTROL_MODE has two;
    a name with a field in it, SPINDLE.%d.WAIT_ORIENT_COMPLETE, is under ``""``)."""
    found: dict[str, list[Template]] = {}
    for kind, template in ops.TEMPLATES.items():
        name = template.split("(", 1)[0]
        found.setdefault("" if "%" in name else name, []).append(_template(kind, template))
    # (a template of literal text first: SET_MOTION_CONTROL_MODE(%s) would take the other's line)
    return {name: tuple(sorted(ts, key=lambda t: r"(.*)" in t.pattern.pattern))
            for name, ts in found.items()}


TEMPLATES = _templates()


def _nurbs(size: int) -> ops.NurbsFeed:
    """NURBS_FEED as printed: the number of control points alone."""
    return ops.NurbsFeed(size, 0, (), (), ())


def parse_call(call: str) -> Any:
    """The operation of a call's text (``STRAIGHT_FEED(1.0000, ...)``), or :class:`Unread`."""
    m = _NAME.match(call)
    if m is None:
        return Unread("", call)
    for t in TEMPLATES.get(m.group(), ()) or TEMPLATES[""]:
        fields = t.pattern.match(call)
        if fields is None:
            continue
        values = [f(v) for f, v in zip(t.convert, fields.groups(), strict=True)]
        if t.kind is ops.NurbsFeed:
            return _nurbs(values[0])
        return t.kind(*values)
    return Unread(m.group(), call)


def read(text: str) -> Iterator[Canon]:
    """The calls of a transcript, in order; lines without a counter (the text of
    ``(print,...)``) are left out."""
    for line in text.splitlines():
        m = _LINE.match(line)
        if m is not None:
            counter, label, call = m.groups()
            yield Canon(int(counter), label, parse_call(call), line)


# -- the machine path -----------------------------------------------------------------------------


class Bound(NamedTuple):
    """How far a move's machine end (and an arc's centre) may be from the one rs274 computed,
    from the rounding of what it printed: mm on X and Y, on Z, and degrees on A B C."""

    xy: float
    z: float
    angle: float


class Run(NamedTuple):
    """A transcript's machine path: the moves (as :class:`ngc.flatten.verify.Moves` keeps
    them; their line is the transcript's counter), each move's :class:`Bound`, the text of
    each call by counter, and the calls no template matches, by name."""

    moves: list[Move]
    bounds: list[Bound]
    lines: dict[int, str]
    unread: Counter[str]


class _Rounding:
    """The bounds of the offsets in effect, as printed: each offset op's linear components were
    printed in the units of its time (0 when all were printed as 0: an offset not set), the
    angular ones in degrees; the XY rotation in degrees."""

    def __init__(self, toolpath: Toolpath) -> None:
        self.toolpath = toolpath
        self.linear: dict[type, float] = {}
        self.angular: dict[type, float] = {}

    def offset(self, op: Any) -> None:
        kind = type(op)
        values = op[1:] if kind is ops.SetG5xOffset else op
        scale = self.toolpath.frame.scale
        self.linear[kind] = PRINTED * scale if any(values[:3]) else 0.0
        self.angular[kind] = PRINTED if any(values[3:6]) else 0.0

    def bound(self, end: Any, centre: Any = None) -> Bound:
        """The bound of a move ending at ``end`` (machine mm; an arc's ``centre`` too)."""
        frame = self.toolpath.frame
        own = PRINTED * frame.scale
        g92 = self.linear.get(ops.SetG92Offset, 0.0)
        fixed = (self.linear.get(ops.SetG5xOffset, 0.0)
                 + self.linear.get(ops.UseToolLengthOffset, 0.0))
        angle = PRINTED + sum(self.angular.values())
        if not frame.rotation:
            return Bound(own + g92 + fixed, own + g92 + fixed, angle)
        # the program point and the G92 offset are turned: an error e, f on X, Y becomes
        # e cos - f sin, e sin + f cos, at most (|cos| + |sin|) times as large; the rotation's
        # own error moves a point at r mm from its origin by r times it (radians)
        turned = abs(frame.cos_r) + abs(frame.sin_r)
        origin = [frame.g5x[i] + frame.tlo[i] for i in range(2)]
        radius = max(math.hypot(p[0] - origin[0], p[1] - origin[1])
                     for p in (end, centre) if p is not None)
        xy = turned * (own + g92) + fixed + radius * math.radians(PRINTED)
        return Bound(xy, own + g92 + fixed, angle)


_OFFSETS = (ops.SetG5xOffset, ops.SetG92Offset, ops.UseToolLengthOffset)
# how close the points kept of a G5.1 / G5.2 curve follow it (mm): ngc flatten's own measure
FINE_MM = 0.002 * FINE


def machine_path(calls: Iterable[Canon] | str, curves: Iterable[ops.NurbsFeed] = (),
                 fine: float = FINE_MM) -> Run:
    """The machine path (mm) of a transcript or of its calls (see :class:`Run`).

    rs274 prints a NURBS_FEED as its number of control points alone: ``curves`` are the whole
    calls, in order, as ngc made them for the same program; each is taken for the NURBS_FEED
    of its turn whose number of points it has (a G5 becomes its biarcs, a G5.1 / G5.2 the points
    of the curve, as :class:`ngc.flatten.verify.Moves` keeps them).  A NURBS_FEED without one
    is kept as a ``nurbs`` move whose end is not known (its bound is infinite), and counted in
    ``unread`` as ``NURBS_FEED``."""
    if isinstance(calls, str):
        calls = read(calls)
    known = iter(curves)
    tee = Tee()
    toolpath = Toolpath(tee)
    reader = Moves(toolpath, fine)
    tee.readers.append(reader)
    rounding = _Rounding(toolpath)
    bounds: list[Bound] = []
    lines: dict[int, str] = {}
    unread: Counter[str] = Counter()
    for call in calls:
        op = call.op
        lines[call.counter] = call.text
        if isinstance(op, Unread):
            unread[op.name] += 1
            continue
        if type(op) is ops.NurbsFeed:
            curve = next(known, None)
            if curve is None or curve.size != op.size:
                unread["NURBS_FEED"] += 1
                reader.moves.append(("nurbs", toolpath.pos, None, 0, call.counter, None, None,
                                     0.0, 1))
                bounds.append(Bound(math.inf, math.inf, math.inf))
                continue
            op = curve
        toolpath.emit(op, call.label, call.counter)
        if type(op) in _OFFSETS:  # (after: the toolpath's units are those of the op's time)
            rounding.offset(op)
        while len(bounds) < len(reader.moves):
            move = reader.moves[len(bounds)]
            bounds.append(rounding.bound(move[1], move[2]))
    # (an arc's shape is kept as a plain tuple: as ArcShape here, read by its names)
    moves = [m if not isinstance(m[6], tuple) else (*m[:6], ArcShape(*m[6]), *m[7:])
             for m in reader.moves]
    return Run(moves, bounds, lines, unread)


def describe(move: Move) -> str:
    """A move as a short text: kind, end (mm), and an arc's centre, turns and axis."""
    kind, end, centre, turns, axis = move[0], move[1], move[2], move[3], move[5]
    text = f"{kind} to ({', '.join(f'{v:.5f}' for v in end)})"
    if kind == ARC and centre is not None and axis is not None:
        text += (f" about ({', '.join(f'{v:.5f}' for v in centre)}) axis "
                 f"({', '.join(f'{v:g}' for v in axis)}) turns {turns}")
    return text


def main(argv: list[str]) -> int:
    if len(argv) != 1:
        print("usage: canon_read.py TRANSCRIPT (the output of rs274 -g)", file=sys.stderr)
        return 2
    run = machine_path(Path(argv[0]).read_text(encoding="latin-1"))
    for move, bound in zip(run.moves, run.bounds, strict=True):
        print(f"{move[4]:6d} {describe(move)}  +-{bound.xy:.6f} mm")
    for name, n in sorted(run.unread.items()):
        print(f"unread: {name or '<no name>'} x{n}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
