"""Drawings of engine-dialect toolpaths as SVG (``python -m ngc.engine.svg FILE``).

Every axis of an engine segment is a cubic Bézier in the same normalised time, so the projection
of a segment on a plane is exactly the planar cubic Bézier with the two axes' control points: each
segment is written as one SVG ``C`` command, without sampling.  Consecutive segments of the same
kind of motion share a ``<path>``; rapids are dashed.  The drawing's y axis is flipped so that the
plane's second axis points up, and its viewBox is fitted to the curves' true extents.  Numbers are
written with at most ``DECIMALS`` decimals, trailing zeros trimmed, so that drawings of the same
program are equal byte for byte.
"""

from __future__ import annotations

import argparse
import math
import sys
from collections.abc import Iterable, Iterator
from typing import NamedTuple

from ..errors import NgcError
from .bezier import Cubic, point
from .interp import run
from .state import EngineSegment, ModeChange, Op

PLANES = ("XY", "XZ", "YZ")
DECIMALS = 10
MARGIN = 0.05  # around the curves, as a fraction of the drawing's larger extent
SIZE = 480  # pixels along the drawing's larger side
STROKE = 1.0 / 300.0  # the stroke's width, as a fraction of the larger extent
_EXIT_PROGRAM_ERROR = 1
_EXIT_USAGE = 2

Point = tuple[float, float]
Curve = tuple[Point, Point, Point, Point]


class Run(NamedTuple):
    """Consecutive segments of one kind of motion: their projected cubics, in order."""

    motion: str
    curves: list[Curve]


def number(x: float) -> str:
    """``x`` with at most ``DECIMALS`` decimals, trailing zeros and a negative zero's sign
    dropped."""
    if not math.isfinite(x):
        raise ValueError(f"cannot draw the coordinate {x}")
    text = f"{x:.{DECIMALS}f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def style(motion: str) -> tuple[str, bool]:
    """The colour of a kind of motion and whether it is dashed."""
    match motion:
        case "rapid":
            return "#d62728", True
        case "feed":
            return "#1f77b4", False
        case "arc":
            return "#2ca02c", False
        case "probe":
            return "#ff7f0e", False
        case "run":
            return "#9467bd", False
    return "#7f7f7f", False


def _axis(seg: EngineSegment, axis: str, pos: dict[str, float]) -> Cubic:
    """The segment's cubic for ``axis``, or the axis held where it was."""
    held = pos.get(axis, 0.0)
    return seg.axes.get(axis, (held, held, held, held))


def runs(ops: Iterable[Op], plane: str = "XY") -> Iterator[Run]:
    """The segments of ``ops`` projected on ``plane`` (first axis right, second up, as in the
    program), grouped into runs of one kind of motion.  An axis a segment does not name holds its
    position (0 at the start, or where G92 (SET_POSITION) puts it)."""
    if plane not in PLANES:
        raise ValueError(f"the plane is one of {', '.join(PLANES)}, not {plane!r}")
    across, up = plane[0], plane[1]
    pos: dict[str, float] = {}
    current: Run | None = None
    for op in ops:
        if isinstance(op, ModeChange) and op.name == "SET_POSITION" and isinstance(op.value, dict):
            pos.update({str(a): float(v) for a, v in op.value.items()})
        if not isinstance(op, EngineSegment):
            continue
        xs, ys = _axis(op, across, pos), _axis(op, up, pos)
        for a, c in op.axes.items():
            pos[a] = c[3]
        curve = ((xs[0], ys[0]), (xs[1], ys[1]), (xs[2], ys[2]), (xs[3], ys[3]))
        if current is None or current.motion != op.motion:
            if current is not None:
                yield current
            current = Run(op.motion, [])
        current.curves.append(curve)
    if current is not None:
        yield current


def _turning_points(c: Cubic) -> list[float]:
    """The times in (0, 1) where the cubic's derivative is zero."""
    p0, p1, p2, p3 = c
    # B'(t) / 3 = a t^2 + b t + k
    a = -p0 + 3.0 * p1 - 3.0 * p2 + p3
    b = 2.0 * (p0 - 2.0 * p1 + p2)
    k = p1 - p0
    if a == 0.0:
        roots = [-k / b] if b != 0.0 else []
    else:
        disc = b * b - 4.0 * a * k
        if disc < 0.0:
            return []
        q = -0.5 * (b + math.copysign(math.sqrt(disc), b))
        roots = [q / a] + ([k / q] if q != 0.0 else [])
    return [t for t in roots if 0.0 < t < 1.0]


def extent(c: Cubic) -> tuple[float, float]:
    """The smallest and largest value the cubic takes over [0, 1]."""
    values = [c[0], c[3]] + [point(c, t) for t in _turning_points(c)]
    return min(values), max(values)


def bounds(curves: Iterable[Curve]) -> tuple[float, float, float, float]:
    """``(min x, min y, max x, max y)`` of the curves (the origin's point when there are none)."""
    lo_x = lo_y = math.inf
    hi_x = hi_y = -math.inf
    for curve in curves:
        x0, x1 = extent((curve[0][0], curve[1][0], curve[2][0], curve[3][0]))
        y0, y1 = extent((curve[0][1], curve[1][1], curve[2][1], curve[3][1]))
        lo_x, lo_y, hi_x, hi_y = min(lo_x, x0), min(lo_y, y0), max(hi_x, x1), max(hi_y, y1)
    if lo_x > hi_x:
        return 0.0, 0.0, 0.0, 0.0
    return lo_x, lo_y, hi_x, hi_y


def _pair(p: Point) -> str:
    """A point in the drawing's coordinates: y flipped, so that up is up."""
    return f"{number(p[0])},{number(-p[1])}"


def path_data(curves: list[Curve]) -> str:
    """``M`` to the first curve's start, then a ``C`` for each curve (and a new ``M`` where a
    curve does not start at the previous one's end), one command a line."""
    parts: list[str] = []
    pen: Point | None = None
    for curve in curves:
        if pen != curve[0]:
            parts.append(f"M{_pair(curve[0])}")
        parts.append(f"C{_pair(curve[1])} {_pair(curve[2])} {_pair(curve[3])}")
        pen = curve[3]
    return "\n".join(parts)


def _path(run_: Run, width: float) -> str:
    """A run as a ``<path>`` element of its motion's style."""
    colour, dashed = style(run_.motion)
    dash = f' stroke-dasharray="{number(6.0 * width)} {number(4.0 * width)}"' if dashed else ""
    return (f'<path class="{run_.motion}" fill="none" stroke="{colour}" '
            f'stroke-width="{number(width)}" stroke-linecap="round" stroke-linejoin="round"{dash}'
            f' d="{path_data(run_.curves)}"/>')


def draw(ops: Iterable[Op], *, plane: str = "XY", title: str | None = None) -> str:
    """A standalone SVG document of the toolpath of ``ops`` projected on ``plane`` ("XY", "XZ"
    or "YZ").  ``title`` defaults to the plane and the number of segments."""
    found = list(runs(ops, plane))
    curves = [c for r in found for c in r.curves]
    lo_x, lo_y, hi_x, hi_y = bounds(curves)
    size = max(hi_x - lo_x, hi_y - lo_y) or 1.0
    margin = MARGIN * size
    box = (lo_x - margin, -hi_y - margin, hi_x - lo_x + 2.0 * margin, hi_y - lo_y + 2.0 * margin)
    scale = SIZE / max(box[2], box[3])
    if title is None:
        title = f"Engine toolpath on the {plane} plane: {len(curves)} segments"
    lines = [
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{" ".join(number(v) for v in box)}" '
        f'width="{number(round(box[2] * scale, 1))}" height="{number(round(box[3] * scale, 1))}">',
        f"<title>{_escape(title)}</title>",
        *(_path(r, STROKE * size) for r in found),
        "</svg>",
    ]
    return "\n".join(lines) + "\n"


def _escape(text: str) -> str:
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="python -m ngc.engine.svg",
        description="Draw an engine-dialect program's toolpath as SVG.")
    parser.add_argument("file", metavar="FILE", help="the engine-dialect program")
    parser.add_argument("-o", "--output", metavar="OUT", help="the SVG file (default: stdout)")
    parser.add_argument("--plane", type=str.upper, choices=PLANES, default="XY",
                        help="the plane to project on (default: XY)")
    return parser


def main(argv: list[str] | None = None) -> int:
    """Draw FILE on stdout or in ``-o OUT``; returns the exit code: 1 for an error in the
    program (rendered with its line), 2 for a file that cannot be read or written or a usage
    error."""
    prog = "python -m ngc.engine.svg"
    try:
        options = _parser().parse_args(argv)
    except SystemExit as exc:  # --help (0) and usage errors (2)
        return exc.code if isinstance(exc.code, int) else _EXIT_USAGE
    try:
        with open(options.file, "rb") as f:
            text = f.read().decode("utf-8", "surrogateescape").removeprefix("\ufeff")
    except OSError as exc:
        sys.stderr.write(f"{prog}: cannot open {options.file}: {exc.strerror}\n")
        return _EXIT_USAGE
    try:
        drawing = draw(run(text, file=options.file), plane=options.plane)
    except NgcError as exc:
        sys.stderr.write(exc.render() + "\n")
        return _EXIT_PROGRAM_ERROR
    if options.output is None:
        sys.stdout.write(drawing)
        return 0
    try:
        with open(options.output, "w", encoding="utf-8", newline="\n") as out:
            out.write(drawing)
    except OSError as exc:
        sys.stderr.write(f"{prog}: cannot write {options.output}: {exc.strerror}\n")
        return _EXIT_USAGE
    return 0


if __name__ == "__main__":
    sys.exit(main())
