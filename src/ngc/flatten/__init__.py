"""``ngc flatten``: a program written out plain for a simpler controller, and verified.

:func:`flatten` runs the program through the interpreter and the toolpath layer, writes each
move with :class:`~ngc.flatten.writer.Flattener` for a target of :data:`~ngc.flatten.targets.TARGETS`,
then runs what it wrote through the interpreter again, on the same machine inputs, and compares
the two machine paths move by move (:class:`Verified`).  A program that cannot be written
truthfully raises :class:`~ngc.flatten.writer.Refused`.
"""

from __future__ import annotations

import io
import math
from collections.abc import Callable
from typing import NamedTuple

from ..canon import ops
from ..canon.ops import Sink
from ..config.tooltable import ToolEntry, scaled_entry
from ..errors import NgcError
from ..interp.interpreter import Interpreter
from ..interp.parameters import COORD_STRIDE, G54_ORIGIN
from ..toolpath.frame import Pos
from ..toolpath.tracker import ARC, ArcMove, Cubics, Tee, Toolpath
from .targets import TARGETS, Target
from .writer import MM_PER_INCH, Flattener, Refused

__all__ = ["TARGETS", "Flattened", "Refused", "Verified", "flatten"]

COORD_SYSTEM = 5220


class Verified(NamedTuple):
    """The comparison of the written program's machine path with the original's: the moves
    compared, the largest distance between corresponding points (mm), and the first difference
    that is not a distance (a move of another kind, a missing move), if any."""

    moves: int
    deviation: float
    difference: str | None


class Flattened(NamedTuple):
    """The program written out (``text``), its lines, and its verification (None if not
    asked)."""

    text: str
    lines: int
    verified: Verified | None


Move = tuple[str, Pos, "tuple[float, ...] | None", int, int, "tuple[float, ...] | None"]


class _Path:
    """A reader of the toolpath keeping each move's kind, end, and an arc's centre and turns."""

    def __init__(self) -> None:
        # kind, end, an arc's centre, its turns, line, and its axis: the normal, pointing so
        # that the arc turns counterclockwise about it (an arc about -X turning one way is the
        # same arc as one about +X turning the other)
        self.moves: list[Move] = []

    def straight(self, kind: str, start: Pos, end: Pos, line: int) -> None:
        self.moves.append((kind, end, None, 0, line, None))

    def arc(self, arc: ArcMove, line: int) -> None:
        sign = 1.0 if arc.turns > 0 else -1.0
        axis = tuple(sign * v for v in arc.normal)
        self.moves.append((ARC, arc.end, arc.centre, abs(arc.turns), line, axis))

    def nurbs(self, curve: ops.NurbsFeed, start: Pos, line: int) -> None:
        self.moves.append(("nurbs", start, None, 0, line, None))

    def tap(self, start: Pos, bottom: Pos, line: int) -> None:
        self.moves.append(("tap", bottom, None, 0, line, None))

    def bezier(self, cubics: Cubics, motion: str, start: Pos, line: int) -> None:
        self.moves.append(("bezier", start, None, 0, line, None))

    def other(self, op: ops.Op, line: int) -> None:
        """Only the moves are compared."""

    def finish(self) -> None:
        """Nothing is held back."""


def flatten(text: str, name: str, new_interpreter: Callable[[Sink], Interpreter], *,
            target: str = "linuxcnc", inch: bool = False, decimals: int | None = None,
            source_lines: bool = False, verify: bool = True) -> Flattened:
    """The program ``text`` (named ``name``) written plain for ``target``, run by
    ``new_interpreter(sink)`` (the machine inputs: :func:`ngc.options.new_interpreter`); raises
    :class:`Refused` for a program that cannot be written truthfully, :class:`ValueError` for a
    target not written yet, and :class:`~ngc.errors.NgcError` for a program error."""
    row = TARGETS.get(target)
    if row is None or not row.written:
        known = ", ".join(t for t, r in TARGETS.items() if r.written)
        raise ValueError(f"--target {target} is not supported yet (written: {known})")
    tee = Tee()
    toolpath = Toolpath(tee)
    original = _Path()
    out = io.StringIO()
    interp = new_interpreter(toolpath)
    origins, system = _origins(interp, 0)
    slots = list(interp.machine.state.tools.slots)  # (the operator's table: G10 L1 in the
    # program changes the interpreter's copy, not what the machine will have)

    def tool(number: int) -> ToolEntry | None:  # (in mm)
        entry = next((e for e in slots[1:] if e.number == number), None)
        return None if entry is None else scaled_entry(entry, MM_PER_INCH)

    writer = Flattener(toolpath, out, row, origins=origins, system=system, tool=tool,
                       inch=inch, decimals=decimals, source_lines=source_lines)
    tee.readers.extend((writer, original))
    writer.header(name)
    interp.startup()
    interp.run(text.splitlines(), file=name)
    written = out.getvalue()
    if not writer.ended:  # (a program ended by %: so is the one written, or by M2)
        written = "%\n" + written + "%\n" if row.percent else written + "M2\n"
    checked = None
    if verify:
        checked = _verify(original, written, new_interpreter, row)
    return Flattened(written, writer.lines, checked)


def _origins(interp: Interpreter, line: int) -> tuple[list[list[float]], int]:
    """The work offsets' origins as the program finds them (machine coordinates in mm) and the
    system selected; a rotated one is refused (its rotation is the operator's, and this writer
    does not write rotated coordinates yet)."""
    numbered = interp.params.numbered
    origins = []
    for k in range(9):
        base = G54_ORIGIN + k * COORD_STRIDE
        values = [numbered[base + i] * (MM_PER_INCH if i < 3 else 1.0) for i in range(6)]
        if numbered[base + 9] != 0.0:
            raise Refused(line, f"{('G54', 'G55', 'G56', 'G57', 'G58', 'G59', 'G59.1', 'G59.2', 'G59.3')[k]} "
                          "is rotated (R) in the parameter file: not flattened yet")
        origins.append(values)
    system = int(numbered[COORD_SYSTEM]) or 1
    return origins, min(max(system, 1), 9)


def _axis_gap(m: Move, n: Move) -> float:
    """How far apart the axes of two arcs about parallel axes are (their centres, less the part
    along the axis: a helix's centre may be given at any height)."""
    c, d, axis = m[2], n[2], m[5]
    if c is None or d is None or axis is None:
        return 0.0
    gap = [c[i] - d[i] for i in range(3)]
    along = sum(gap[i] * axis[i] for i in range(3))
    return math.sqrt(sum((gap[i] - along * axis[i]) ** 2 for i in range(3)))


def _joined(a: list[Move], b: list[Move]) -> list[Move]:
    """``b`` with the arcs a target without P wrote one turn each (a run of single-turn arcs
    about the same axis and centre, where ``a`` has one arc of as many turns) joined again."""
    out: list[Move] = []
    j = 0
    for m in a:
        if j >= len(b):
            break
        n = b[j]
        k = m[3]
        if m[0] == ARC and k > 1 and n[0] == ARC and n[3] == 1:
            run = b[j:j + k]
            if len(run) == k and all(r[0] == ARC and r[3] == 1 and r[5] == n[5]
                                     and _axis_gap(r, n) < 1e-6 for r in run):
                last = run[-1]
                out.append((ARC, last[1], n[2], k, n[4], n[5]))
                j += k
                continue
        out.append(n)
        j += 1
    out.extend(b[j:])
    return out


def _verify(original: _Path, written: str, new_interpreter: Callable[[Sink], Interpreter],
            target: Target) -> Verified:
    """Run the written program on the same machine inputs and compare the machine paths."""
    again = _Path()
    interp = new_interpreter(Toolpath(again))
    interp.startup()
    try:
        interp.run(written.splitlines(), file="<flattened>")
    except NgcError as exc:
        return Verified(len(again.moves), math.inf,
                        f"the program written stops at its line {exc.line}: {exc.explained()}")
    a, b = original.moves, _joined(original.moves, again.moves)
    worst = 0.0
    for i, (m, n) in enumerate(zip(a, b, strict=False)):
        if m[0] != n[0] or m[3] != n[3]:
            return Verified(i, worst, f"move {i + 1} (line {m[4]}): a {m[0]} became a {n[0]}")
        worst = max(worst, math.dist(m[1][:3], n[1][:3]),
                    max(abs(x - y) for x, y in zip(m[1][3:], n[1][3:], strict=True)))
        if m[2] is not None and n[2] is not None and m[5] is not None and n[5] is not None:
            if math.dist(m[5], n[5]) > 1e-9:
                return Verified(i, worst, f"move {i + 1} (line {m[4]}): the arc turns the "
                                "other way")
            worst = max(worst, _axis_gap(m, n))
    if len(a) != len(b):
        return Verified(min(len(a), len(b)), worst,
                        f"{len(a)} moves became {len(b)}")
    return Verified(len(a), worst, None)
