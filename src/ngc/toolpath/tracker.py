"""The toolpath layer: a canon sink that follows the machine (units, offsets, rotation, the tool,
the plane) and hands each move on, in machine coordinates, to a consumer.

The consumer (:class:`Consumer`) hears of straight moves, arcs, NURBS curves and rigid taps as
they come, and of every other operation after the toolpath has taken what it needs from it.  It
reads the rest of the machine's state from the :class:`Toolpath` itself (``pos``, ``prog``,
``frame``, ``plane``, ``tool``, ...), so a move costs one call and no object: the planner, the
check summary and the drawing read one stream, and none of them follows offsets or units.
:class:`~ngc.toolpath.moves.MoveList` turns the stream into :class:`~ngc.toolpath.moves.Move`
records for a library user.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, Protocol

from ..canon import ops
from .frame import Frame, Pos

# kinds of move
RAPID = "rapid"
FEED = "feed"
ARC = "arc"
PROBE = "probe"
SYNC = "sync"  # spindle-synchronised: G33, G76 (a straight feed between START/STOP_SPEED_FEED_SYNCH)
TAP = "tap"  # G33.1 rigid tapping: down to the point and back
NURBS = "nurbs"
BEZIER = "bezier"  # an engine-dialect segment: a cubic Bézier on each axis

# Each plane's (first axis, second axis, normal axis) index, as ARC_FEED gives them.
PLANES = {"CANON_PLANE_XY": (0, 1, 2), "CANON_PLANE_YZ": (1, 2, 0),
          "CANON_PLANE_XZ": (2, 0, 1)}
PLANE_NAMES = {v: k[len("CANON_PLANE_"):] for k, v in PLANES.items()}
NORMALS = {(0, 1, 2): (0.0, 0.0, 1.0), (1, 2, 0): (1.0, 0.0, 0.0), (2, 0, 1): (0.0, 1.0, 0.0)}
XY = PLANES["CANON_PLANE_XY"]
Z_UP = NORMALS[XY]

Vec = tuple[float, float, float]
Cubic = tuple[float, float, float, float]
Cubics = tuple[Cubic, Cubic, Cubic, Cubic, Cubic, Cubic]  # X Y Z A B C
AXIS_INDEX = {a: i for i, a in enumerate("XYZABC")}


class ArcMove:
    """An ``ARC_FEED`` in machine coordinates: from ``start`` to ``end`` about the axis through
    ``centre`` along ``normal`` (the plane's normal, turned with the XY rotation), ``turns`` as
    ARC_FEED's rotation (> 0 counterclockwise seen from the normal's tip, |turns| - 1 extra full
    turns); ``op`` and ``prog_start`` are the call and its start in program coordinates."""

    __slots__ = ("centre", "end", "normal", "op", "prog_start", "start", "turns")

    def __init__(self, start: Pos, end: Pos, centre: Vec, normal: Vec, turns: int,
                 op: ops.ArcFeed, prog_start: Pos) -> None:
        self.start, self.end, self.centre, self.normal = start, end, centre, normal
        self.turns, self.op, self.prog_start = turns, op, prog_start


class Consumer(Protocol):
    """What reads the toolpath.  Positions are machine coordinates (:class:`Pos`); ``line`` is
    the program line the move comes from.  ``straight`` is called with ``kind`` one of RAPID,
    FEED, PROBE, SYNC; ``nurbs`` with a G5 / G5.1 / G5.2 curve (program coordinates: its points
    lie in the XY plane at the current Z) from ``start``; ``tap`` with a rigid tap from
    ``start`` to ``bottom`` and back; ``other`` with every other operation."""

    def straight(self, kind: str, start: Pos, end: Pos, line: int) -> None: ...

    def arc(self, arc: ArcMove, line: int) -> None: ...

    def nurbs(self, curve: ops.NurbsFeed, start: Pos, line: int) -> None: ...

    def tap(self, start: Pos, bottom: Pos, line: int) -> None: ...

    def bezier(self, cubics: Cubics, motion: str, start: Pos, line: int) -> None: ...

    def other(self, op: ops.Op, line: int) -> None: ...

    def finish(self) -> None: ...


class Toolpath:
    """A canon sink that follows the machine and hands moves to ``consumer``.

    State a consumer may read at any call: ``pos`` (the machine position before the move),
    ``prog`` (the same point in program units and coordinates; the move's own program end is
    ``prog_end``), ``frame`` (:class:`~ngc.toolpath.frame.Frame`: units, offsets, rotation),
    ``plane`` (first, second, normal axis index), ``tool`` (the slot in the spindle),
    ``selected``, ``synced`` (a spindle-synchronised motion is on).  ``start`` is where the
    machine is before the program moves it (machine coordinates)."""

    __slots__ = ("_consumer", "_handlers", "_straight", "frame", "plane", "pos", "prog",
                 "prog_end", "selected", "synced", "tool")

    def __init__(self, consumer: Consumer, *, inch_machine: bool = False,
                 start: Pos = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)) -> None:
        self._consumer = consumer
        self._straight = consumer.straight
        self.frame = Frame(inch_machine)
        self.pos: Pos = start
        self.prog: Pos = start
        self.prog_end: Pos = start
        self.plane = PLANES["CANON_PLANE_XY"]
        self.tool = 0
        self.selected = 0
        self.synced = False
        self._handlers = {
            ops.StraightFeed: self._feed, ops.StraightTraverse: self._traverse,
            ops.ArcFeed: self._arc, ops.NurbsFeed: self._nurbs,
            ops.StraightProbe: self._probe, ops.RigidTap: self._tap,
            ops.UseLengthUnits: self._units, ops.SetG5xOffset: self._g5x,
            ops.SetG92Offset: self._g92, ops.SetXYRotation: self._rotation,
            ops.UseToolLengthOffset: self._tool_offset, ops.SelectPlane: self._plane,
            ops.SelectTool: self._select, ops.ChangeTool: self._change,
            ops.ChangeToolNumber: self._change, ops.StartSpeedFeedSync: self._sync_on,
            ops.StopSpeedFeedSynch: self._sync_off,
        }

    # -- the sink protocol --------------------------------------------------------------------
    def emit(self, op: ops.Op, label: str, line: int) -> None:
        handler = self._handlers.get(type(op))
        if handler is not None:
            handler(op, line)
        elif label == "ENGINE_SEGMENT":
            self._engine_segment(op, line)
        else:
            if label == "SET_POSITION":
                self._set_position(op)
            self._consumer.other(op, line)

    def emit_move(self, kind: type, fields: Sequence[Any], label: str, line: int) -> None:
        """The interpreter's fast way in for moves (``ops.mover``)."""
        if kind is ops.StraightFeed:
            move = SYNC if self.synced else FEED
        elif kind is ops.StraightTraverse:
            move = RAPID
        elif kind is ops.ArcFeed:
            self._arc(kind._make(fields), line)
            return
        else:
            self.emit(kind(*fields), label, line)
            return
        if self.frame.identity:  # (``_line``'s common case, kept quick)
            end: Pos = tuple(fields)
            self.prog_end = end
            self._straight(move, self.pos, end, line)
            self.pos = self.prog = end
            return
        self._line(move, fields, line)

    def print_text(self, text: str) -> None:
        """``(PRINT,...)`` output does not move the machine."""

    def flush(self) -> None:
        self._consumer.finish()

    # -- moves --------------------------------------------------------------------------------
    def _line(self, kind: str, fields: Sequence[Any], line: int) -> None:
        frame = self.frame
        if frame.identity:
            end: Pos = tuple(fields)
            self.prog_end = end
        else:
            end = frame.to_machine(fields)
            self.prog_end = tuple(fields)
        self._straight(kind, self.pos, end, line)
        self.pos = end
        self.prog = self.prog_end

    def _feed(self, op: Any, line: int) -> None:
        self._line(SYNC if self.synced else FEED, op, line)

    def _traverse(self, op: Any, line: int) -> None:
        self._line(RAPID, op, line)

    def _probe(self, op: Any, line: int) -> None:
        """A probe move toward its programmed point (where it stops is not in the call)."""
        self._line(PROBE, op, line)

    def _arc(self, op: ops.ArcFeed, line: int) -> None:
        plane = self.plane
        frame = self.frame
        if plane is XY and frame.identity:  # (the common case, kept quick)
            end: Pos = (op[0], op[1], op[5], op[6], op[7], op[8])
            self.prog_end = end
            self._consumer.arc(ArcMove(self.pos, end, (op[2], op[3], op[5]), Z_UP, op[4], op,
                                       self.prog), line)
            self.pos = end
            self.prog = end
            return
        p1, p2, pn = plane
        prog = [0.0, 0.0, 0.0, op.a, op.b, op.c]
        prog[p1], prog[p2], prog[pn] = op.first_end, op.second_end, op.axis_end_point
        centre = [0.0, 0.0, 0.0]
        centre[p1], centre[p2], centre[pn] = op.first_axis, op.second_axis, op.axis_end_point
        end = tuple(prog)  # type: ignore[assignment]
        self.prog_end = end
        normal = NORMALS[plane]
        if frame.identity:
            c: Vec = (centre[0], centre[1], centre[2])
        else:
            end = frame.to_machine(prog)
            m = frame.to_machine((centre[0], centre[1], centre[2], 0.0, 0.0, 0.0))
            c, normal = (m[0], m[1], m[2]), frame.turn(normal)
        self._consumer.arc(ArcMove(self.pos, end, c, normal, op.rotation, op, self.prog), line)
        self.pos = end
        self.prog = self.prog_end

    def _nurbs(self, op: ops.NurbsFeed, line: int) -> None:
        """A curve in the XY plane at the current Z (its end is its last control point)."""
        x, y = op.points[-1]
        p = self.prog
        self.prog_end = (x, y, p[2], p[3], p[4], p[5])
        end = self.frame.to_machine(self.prog_end)
        self._consumer.nurbs(op, self.pos, line)
        self.pos = end
        self.prog = self.prog_end

    def _tap(self, op: ops.RigidTap, line: int) -> None:
        """G33.1: to the point (X Y Z; A B C stay) and back where it started."""
        p = self.prog
        bottom = self.frame.to_machine((op.x, op.y, op.z, p[3], p[4], p[5]))
        self._consumer.tap(self.pos, bottom, line)

    def _engine_segment(self, seg: Any, line: int) -> None:
        """An engine-dialect segment (:class:`ngc.engine.state.EngineSegment`): each named axis
        a cubic Bézier in mm over the segment's time; the others hold (U V W are not drawn)."""
        held = self.pos
        cubics = [(v, v, v, v) for v in held]
        for axis, cubic in seg.axes.items():
            i = AXIS_INDEX.get(axis)
            if i is not None:
                cubics[i] = tuple(cubic)
        end: Pos = tuple(c[3] for c in cubics)  # type: ignore[assignment]
        self.prog_end = end
        self._consumer.bezier(tuple(cubics), seg.motion, self.pos, line)  # type: ignore[arg-type]
        self.pos = self.prog = end

    def _set_position(self, op: Any) -> None:
        """The engine's G92: the axes named are where the value says, without moving."""
        value = getattr(op, "value", None)
        if isinstance(value, dict):
            pos = list(self.pos)
            for axis, v in value.items():
                i = AXIS_INDEX.get(str(axis))
                if i is not None:
                    pos[i] = float(v)
            self.pos = self.prog = self.prog_end = tuple(pos)  # type: ignore[assignment]

    # -- state --------------------------------------------------------------------------------
    def _reframed(self, op: ops.Op, line: int) -> None:
        """The frame changed: the machine stays where it is, its program coordinates follow."""
        self.prog = self.prog_end = self.frame.to_program(self.pos)
        self._consumer.other(op, line)

    def _units(self, op: ops.UseLengthUnits, line: int) -> None:
        self.frame.set_units(op.units == "CANON_UNITS_INCHES")
        self._reframed(op, line)

    def _g5x(self, op: ops.SetG5xOffset, line: int) -> None:
        self.frame.set_g5x((op.x, op.y, op.z, op.a, op.b, op.c))
        self._reframed(op, line)

    def _g92(self, op: ops.SetG92Offset, line: int) -> None:
        self.frame.set_g92(op)
        self._reframed(op, line)

    def _rotation(self, op: ops.SetXYRotation, line: int) -> None:
        self.frame.set_rotation(op.degrees)
        self._reframed(op, line)

    def _tool_offset(self, op: ops.UseToolLengthOffset, line: int) -> None:
        self.frame.set_tool_offset(op[:6])
        self._reframed(op, line)

    def _plane(self, op: ops.SelectPlane, line: int) -> None:
        self.plane = PLANES.get(op.plane, self.plane)
        self._consumer.other(op, line)

    def _select(self, op: ops.SelectTool, line: int) -> None:
        self.selected = op.tool
        self._consumer.other(op, line)

    def _change(self, op: ops.Op, line: int) -> None:
        """M6 (the selected tool goes in) or M61 (the spindle holds the selected one): the
        consumer hears of it with the new tool in ``tool`` (moves it holds back keep the tool
        they were made with)."""
        self.tool = self.selected
        self._consumer.other(op, line)

    def _sync_on(self, op: ops.Op, line: int) -> None:
        self._consumer.other(op, line)
        self.synced = True

    def _sync_off(self, op: ops.Op, line: int) -> None:
        self._consumer.other(op, line)
        self.synced = False


class Tee:
    """A consumer that hands everything to several readers in turn (``ngc plot --time`` draws
    and times one run): ``Toolpath(Tee())``, then each reader made with that toolpath and
    added to ``readers``."""

    def __init__(self, *readers: Consumer) -> None:
        self.readers = list(readers)

    def straight(self, kind: str, start: Pos, end: Pos, line: int) -> None:
        for r in self.readers:
            r.straight(kind, start, end, line)

    def arc(self, arc: ArcMove, line: int) -> None:
        for r in self.readers:
            r.arc(arc, line)

    def nurbs(self, curve: ops.NurbsFeed, start: Pos, line: int) -> None:
        for r in self.readers:
            r.nurbs(curve, start, line)

    def tap(self, start: Pos, bottom: Pos, line: int) -> None:
        for r in self.readers:
            r.tap(start, bottom, line)

    def bezier(self, cubics: Cubics, motion: str, start: Pos, line: int) -> None:
        for r in self.readers:
            r.bezier(cubics, motion, start, line)

    def other(self, op: ops.Op, line: int) -> None:
        for r in self.readers:
            r.other(op, line)

    def finish(self) -> None:
        for r in self.readers:
            r.finish()
