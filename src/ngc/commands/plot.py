"""``ngc plot``: a picture of a program's toolpath, as SVG or PNG.

The program runs through the interpreter with the machine inputs of every command; its
toolpath (:mod:`ngc.toolpath`) becomes a scene in one view (:mod:`ngc.render.scene`), written as
SVG (:mod:`ngc.render.svg`) and, for a ``.png`` output, rendered by resvg
(:mod:`ngc.render.png`).  A program that stops on an error is drawn up to the error, the point
marked and the message written on the drawing.
"""

from __future__ import annotations

import os
import re
import tempfile
from collections.abc import Callable, Iterable, Mapping
from typing import TYPE_CHECKING, NamedTuple

from .. import dialects
from ..budget import DEFAULT_MAX_ITERATIONS
from ..canon.ops import Sink
from ..errors import NgcError
from ..interp.interpreter import Interpreter
from ..interp.source import ProgramReader
from ..render import svg
from ..render.png import svg_to_png
from ..render.scene import VIEWS, Scene
from ..toolpath.limits import Excess, LimitWatch
from ..toolpath.tracker import Tee, Toolpath

if TYPE_CHECKING:
    from ..engine import Setup as EngineSetup
    from ..planner.machine import Machine as PlannerMachine
    from ..planner.timing import Timer

FORMATS = ("svg", "png")

# G7 or G8 (a lathe's diameter or radius mode) outside comments: a lathe program
_LATHE_WORD = re.compile(rb"[gG][ \t]*0*[78](?![0-9. \t]*[0-9])")
_COMMENT = re.compile(rb"\([^)\n]*\)|;[^\n]*")


def auto_view(data: bytes) -> str:
    """The view ``--view auto`` takes for a program (its bytes): ``lathe`` for one that sets a
    lathe's diameter or radius mode (G7, G8), else ``top``.

    >>> auto_view(b"G18 G7\\nG1 X20 Z-5 F0.1\\n"), auto_view(b"G17 (G7 is a lathe code)\\nG1 X1\\n")
    ('lathe', 'top')
    """
    return "lathe" if _LATHE_WORD.search(_COMMENT.sub(b"", data)) else "top"


def auto_view_of_file(path: str) -> str:
    """:func:`auto_view` of a regular file (``top`` for standard input or a file that cannot be
    read: its error comes when it runs)."""
    try:
        if path == "-" or not os.path.isfile(path):
            return "top"
        with open(path, "rb") as handle:
            return auto_view(handle.read())
    except OSError:
        return "top"


class PlotResult(NamedTuple):
    """What was drawn: the output file, the moves' length (machine units) and the error the
    program stopped with, if any."""

    output: str
    length: float
    error: NgcError | None
    time_s: float | None = None
    limits: tuple[Excess, ...] = ()  # where the moves go past the machine's travel
    units: str = "mm"  # the limits'


class PlotOptions(NamedTuple):
    """How to draw: the view (a name of :data:`~ngc.render.scene.VIEWS`), what colours key
    (``kind``, ``tool``, ``feed``, ``line``), the picture's size in pixels, the PNG's dpi (0:
    96), whether the approach before the first cut is drawn."""

    view: str = "top"
    color: str = "kind"
    width: int = 1200
    height: int = 900
    dpi: float = 0.0
    approach: bool = False


def output_format(path: str) -> str:
    """``svg`` or ``png``, from the output's extension; ValueError for anything else."""
    ext = os.path.splitext(path)[1].lower().lstrip(".")
    if ext not in FORMATS:
        raise ValueError(f"the output must end in .svg or .png, not {path!r}")
    return ext


def draw(lines: Iterable[str], name: str, output: str,
         new_interpreter: Callable[[Sink], Interpreter], options: PlotOptions | None = None, *,
         reader: ProgramReader | None = None, machine: PlannerMachine | None = None,
         travel: Mapping[str, tuple[float, float]] | None = None,
         units: str = "mm") -> PlotResult:
    """Run the program ``lines`` (named ``name`` in errors and on the drawing) through
    ``new_interpreter(sink)`` and draw it to ``output`` (``.svg`` or ``.png``); with a
    ``machine``, time it on that machine in the same run and print the cycle time on it.  With a
    ``travel`` (the machine's soft limits, in ``units``; the ``machine``'s units if given), the
    moves that go past it are in :attr:`PlotResult.limits`."""
    output_format(output)  # (refused before the program runs)
    options = PlotOptions() if options is None else options
    if options.view not in VIEWS:
        raise ValueError(f"the view must be one of {', '.join(VIEWS)}, not {options.view!r}")
    view = VIEWS[options.view]
    timer: Timer | None = None
    watch: LimitWatch | None = None
    if machine is None and not travel:
        scene = Scene(view, color=options.color, approach=options.approach)
    else:
        tee = Tee()
        if machine is not None:
            units = machine.linear_units
        toolpath = Toolpath(tee, inch_machine=units == "inch")
        scene = Scene(view, color=options.color, approach=options.approach, toolpath=toolpath)
        tee.readers.append(scene)
        if machine is not None:
            from ..planner.timing import Timer  # (loaded for --time only)

            timer = Timer(machine, toolpath=toolpath)
            tee.readers.append(timer.path)
        if travel:
            watch = LimitWatch(travel, toolpath)
            tee.readers.append(watch)
    interp = new_interpreter(scene.toolpath)
    error: NgcError | None = None
    time_s: float | None = None
    try:
        interp.startup()
        interp.run(lines, file=name, reader=reader)
        if timer is not None:
            time_s = timer.finish().total_s
    except NgcError as exc:
        error = exc
        scene.stop_at()
    result = _write(scene, name, output, options, error, time_s,
                    diameter=interp.machine.state.lathe_diameter)
    return result if watch is None else result._replace(limits=tuple(watch.excesses()),
                                                        units=units)


def draw_engine(text: str, name: str, output: str, options: PlotOptions | None = None, *,
                setup: EngineSetup | None = None,
                max_iterations: int = DEFAULT_MAX_ITERATIONS) -> PlotResult:
    """Draw an engine-dialect program (its text; ``setup``: its machine, None: the default)
    to ``output``: each engine segment is the cubic Bézier it is, projected."""
    output_format(output)
    options = PlotOptions() if options is None else options
    view = "top" if options.view == "auto" else options.view
    if view not in VIEWS:
        raise ValueError(f"the view must be one of {', '.join(VIEWS)}, not {options.view!r}")
    scene = Scene(VIEWS[view], color=options.color, approach=options.approach)
    error: NgcError | None = None
    try:
        dialects.interpret_engine(text, scene.toolpath, setup=setup, file=name,
                                  max_iterations=max_iterations)
    except NgcError as exc:
        error = exc
        scene.stop_at()
    return _write(scene, name, output, options, error, None)


def _write(scene: Scene, name: str, output: str, options: PlotOptions, error: NgcError | None,
           time_s: float | None, *, diameter: bool = False) -> PlotResult:
    scene.finish()
    frame = scene.toolpath.frame
    labels = svg.Labels(
        name=os.path.basename(name), units="inch" if frame.inch_program else "mm",
        mm_per_unit=25.4 if frame.inch_program else 1.0, time_s=time_s,
        error=None if error is None else _error_text(error), diameter=diameter)
    try:
        if output_format(output) == "svg":
            _write_svg(output, scene, labels, options)
        else:
            _write_png(output, scene, labels, options)
    finally:
        scene.spool.close()
        scene.marks.close()
    return PlotResult(output, scene.length, error, time_s)


def _error_text(error: NgcError) -> str:
    where = f"line {error.line}: " if error.line else ""
    return f"stopped at {where}{error.message}"


def _write_svg(output: str, scene: Scene, labels: svg.Labels, options: PlotOptions) -> None:
    with open(output, "w", encoding="utf-8") as out:
        svg.write(out, scene, labels, options.width, options.height)


def _write_png(output: str, scene: Scene, labels: svg.Labels, options: PlotOptions) -> None:
    fd, tmp = tempfile.mkstemp(suffix=".svg")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as out:
            svg.write(out, scene, labels, options.width, options.height)
        scale = options.dpi / 96.0 if options.dpi > 0 else 1.0
        data = svg_to_png(tmp, width=round(options.width * scale),
                          height=round(options.height * scale))
    finally:
        os.unlink(tmp)
    with open(output, "wb") as out:
        out.write(data)
