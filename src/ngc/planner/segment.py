"""One move as the planner holds it (:class:`Segment`): its shape, its limits, how it ends, and
what the look-ahead (:mod:`.lookahead`) and the arc blends (:mod:`.arcjoin`) work out for it."""

from __future__ import annotations

import math

from .geometry import Arc, BlendArc, Corner, Line, Piece, Vec

# How a move ends (LinuxCNC's "termination conditions").
STOP = 0  # exact stop (G61.1): speed 0 at the end
EXACT = 1  # exact path (G61): speed 0 at a corner, tangent joins passed
TANGENT = 2  # joined at speed to the next move
PARABOLIC = 3  # blend mode (G64) with no arc: half acceleration, ramps overlap the next move's

RAPID, FEED, ARC, BLEND = "rapid", "feed", "arc", "blend"

Shape = Line | Arc | Piece | Corner | BlendArc


class Segment:
    """One move for the planner."""

    __slots__ = (
        "accel",
        "cut0",
        "cut1",
        "end_dir",
        "full_length",
        "half",
        "kind",
        "length",
        "line",
        "mode",
        "naive",
        "overlap",
        "parts",
        "parts_length",
        "peak",
        "ramp",
        "ramp_in",
        "reduce",
        "shape",
        "soft",
        "start_dir",
        "t0",
        "term",
        "time",
        "tolerance",
        "tool",
        "vend",
        "vfeed",
        "vfinal",
        "vin",
        "vmax",
        "vout",
        "vreach",
        "vsoft",
        "wide",
    )

    # set when the segment is run: its time, start time, speeds, and how long its start runs
    # alongside the move before
    time: float
    t0: float
    vin: float
    vout: float
    peak: float
    overlap: float

    def __init__(self, kind: str, line: int, tool: int, shape: Shape, vmax: float, accel: float,
                 mode: int, tolerance: float, naive: float,
                 dirs: tuple[Vec, Vec] | None = None, term: int | None = None) -> None:
        self.kind = kind
        self.line = line
        self.tool = tool
        self.shape = shape
        self.length = shape.length
        self.full_length = shape.length
        self.vmax = vmax
        self.accel = accel  # tangential acceleration limit
        self.half = 0.5 * accel  # the limit next to a parabolic blend
        self.soft = False  # starts with a parabolic blend
        self.vsoft = math.inf  # the speed limit next to a parabolic blend
        self.mode = mode  # the term condition the mode in force asks for
        self.tolerance = tolerance
        self.term = mode if term is None else term
        self.vend = 0.0  # greatest speed at the join with the next move
        # the speed it was given (the feed within the axes' and the arc's limits), before a
        # parabolic blend halves its centripetal share
        self.vfeed = vmax
        self.vfinal = 0.0  # speed planned at the end (backward pass)
        # the greatest speed at the end from which it and the moves after it can still slow
        # down in time: vfinal, but for a corner blend before a slower feed, whose end may be
        # faster than that feed (the next move then slows down within itself)
        self.vreach = 0.0
        self.reduce = 1.0  # acceleration factor left after a kink or an exact-path corner
        if dirs is None:
            dirs = (shape.start_direction(), shape.end_direction())
        self.start_dir: Vec = dirs[0]
        self.end_dir: Vec = dirs[1]
        self.naive = naive
        # the (line, length) of the programmed moves merged into this one, and their sum
        self.parts: list[tuple[int, float]] | None = None
        self.parts_length = 0.0
        self.cut0 = 0.0  # how much of a line's start and end blends have taken (path())
        self.cut1 = 0.0
        self.ramp_in = False  # a line that starts with a corner blend
        # a wide arc's (accel, half) once another move follows it (see Moves.run_arc)
        self.wide: tuple[float, float] | None = None
        self.ramp = False  # a line between two corner blends: it may run as a ramp (ramp_time)

    def path(self) -> Shape:
        """The shape this segment runs along: a line without the parts corner blends took."""
        shape = self.shape
        if (self.cut0 or self.cut1) and isinstance(shape, Line):
            return Line(shape.point(self.cut0), shape.point(shape.length - self.cut1),
                        self.length)
        return shape

    def effective_accel(self) -> float:
        if self.term == PARABOLIC or self.soft:
            return self.half * self.reduce
        return self.accel * self.reduce
