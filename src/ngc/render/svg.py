"""A :class:`~ngc.render.scene.Scene` written as SVG: the toolpath in the view's coordinates
(machine units, four decimals) inside one transformed group, so arcs stay exact SVG arcs; the
title, legend, dimension lines, scale bar and marks in pixels around it.  Primitives stream
from the scene's spool to the file; runs of lines shorter than half a pixel are joined.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from html import escape
from typing import NamedTuple, TextIO

from .scene import (
    ARC_2D,
    COLOR_KEYS,
    CUBIC,
    DRILL,
    KINDS,
    LINE,
    QUAD,
    STOPPED,
    TOOL_CHANGE,
    Scene,
    Spool,
)

KIND_COLORS = ("#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#17becf")
TOOL_COLORS = ("#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2",
               "#7f7f7f", "#bcbd22", "#17becf")
RAPID_GREY = "#999999"
# viridis at five stops: the colour of a feed or a line number along its range
RAMP = ((0.267, 0.005, 0.329), (0.230, 0.322, 0.546), (0.128, 0.567, 0.551),
        (0.370, 0.789, 0.383), (0.993, 0.906, 0.144))

FONTS = "DejaVu Sans, Liberation Sans, Arial, Helvetica, sans-serif"
MARGIN = (70.0, 190.0, 60.0, 90.0)  # left, right (the legend), top, bottom (px)
STROKE_PX = 1.2
DASH_PX = 4.0
JOIN_PX = 0.5  # lines shorter than this on the drawing are joined into the next
PATH_SEGMENTS = 2000  # primitives in one <path> at most


class Layout(NamedTuple):
    """Model (view) coordinates to pixels: px = tx + s u, py = ty - s v."""

    width: float
    height: float
    s: float
    tx: float
    ty: float

    def px(self, u: float, v: float) -> tuple[float, float]:
        return (self.tx + self.s * u, self.ty - self.s * v)


class Labels(NamedTuple):
    """What the drawing says about the program: its name, the units its values are given in
    (and millimetres per unit), the cycle time if known, the error it stopped with, whether
    its X values are diameters."""

    name: str
    units: str = "mm"
    mm_per_unit: float = 1.0
    time_s: float | None = None
    error: str | None = None
    diameter: bool = False  # X is given as a diameter (a lathe's G7): its extent shown so


def layout(scene: Scene, width: float, height: float) -> Layout:
    left, right, top, bottom = MARGIN
    aw, ah = width - left - right, height - top - bottom
    box = scene.box
    if box.empty:
        return Layout(width, height, 1.0, left + aw / 2, top + ah / 2)
    w = box.high[0] - box.low[0]
    h = box.high[1] - box.low[1]
    if not (math.isfinite(w) and math.isfinite(h)):
        # (extents past a double's range: drawn about the origin at one pixel a unit)
        return Layout(width, height, 1.0, left + aw / 2, top + ah / 2)
    candidates = [aw / w if w > 0 else math.inf, ah / h if h > 0 else math.inf]
    s = min(candidates)
    if s == math.inf:
        s = 1.0
    tx = left + (aw - s * w) / 2 - s * box.low[0]
    ty = top + (ah - s * h) / 2 + s * box.high[1]
    return Layout(width, height, s, tx, ty)


def _n(v: float) -> str:
    text = f"{v:.4f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def _p(v: float) -> str:
    text = f"{v:.2f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def ramp(t: float) -> str:
    """The colour at ``t`` in [0, 1] along :data:`RAMP`."""
    t = min(max(t, 0.0), 1.0) * (len(RAMP) - 1)
    i = min(int(t), len(RAMP) - 2)
    f = t - i
    a, b = RAMP[i], RAMP[i + 1]
    r, g, bl = (a[k] + (b[k] - a[k]) * f for k in range(3))
    return f"#{round(r * 255):02x}{round(g * 255):02x}{round(bl * 255):02x}"


class Colors:
    """The colour of a key, as ``scene.color`` keys moves."""

    def __init__(self, scene: Scene) -> None:
        self.key = scene.color
        self.lo, self.hi = scene.key_range

    def __call__(self, key: float, dashed: bool) -> str:
        if self.key == "kind":
            return KIND_COLORS[int(key)]
        if self.key == "tool":
            return TOOL_COLORS[int(key) % len(TOOL_COLORS)]
        if dashed and self.key == "feed":
            return RAPID_GREY
        span = self.hi - self.lo
        return ramp((key - self.lo) / span if span > 0 else 0.5)


def write(out: TextIO, scene: Scene, labels: Labels, width: float = 1200.0,
          height: float = 900.0) -> None:
    """Write ``scene`` as an SVG document of ``width`` x ``height`` pixels."""
    lay = layout(scene, width, height)
    colors = Colors(scene)
    stroke = STROKE_PX / lay.s
    out.write(f'<svg xmlns="http://www.w3.org/2000/svg" width="{_p(width)}" '
              f'height="{_p(height)}" viewBox="0 0 {_p(width)} {_p(height)}" '
              f'font-family="{FONTS}" font-size="13">\n')
    out.write(f"<title>{escape(labels.name)}</title>\n")
    out.write(f'<style>.p{{fill:none;stroke-width:{_n(stroke) if stroke < 1e4 else "1"};'
              f"stroke-linecap:round;stroke-linejoin:round}}"
              f".r{{stroke-dasharray:{_n(DASH_PX / lay.s)} {_n(DASH_PX / lay.s)}}}</style>\n")
    out.write('<rect width="100%" height="100%" fill="white"/>\n')
    out.write(f'<g id="toolpath" transform="matrix({_n(lay.s)} 0 0 {_n(-lay.s)} '
              f'{_n(lay.tx)} {_n(lay.ty)})">\n')
    _paths(out, scene.spool, colors, JOIN_PX / lay.s)
    out.write("</g>\n")
    _marks(out, scene.marks, lay)
    _frame(out, scene, labels, lay)
    out.write("</svg>\n")


def _paths(out: TextIO, records: Iterable[tuple[float, ...]], colors: Colors,
           join: float) -> None:
    """Write the primitives as paths, one per run of one colour and dash (at most
    :data:`PATH_SEGMENTS` each).  Lines that end within ``join`` (half a pixel) of the pen are
    held and drawn as one."""
    key = dashed = math.nan  # the path's style
    parts: list[str] = []
    count = 0
    pu = pv = math.nan  # where the pen is
    hu = hv = math.nan  # the end of lines joined since, not yet drawn (nan: none)
    held = False

    def close() -> None:
        if parts:
            cls = "p r" if dashed else "p"
            out.write(f'<path class="{cls}" stroke="{colors(key, bool(dashed))}" '
                      f'd="{"".join(parts)}"/>\n')

    for rec in records:
        kind = rec[0]
        total = sum(rec[3:])
        if total - total != 0.0:
            continue  # (a coordinate past a double's range, or not a number: nothing to draw)
        if rec[1] != key or rec[2] != dashed or count >= PATH_SEGMENTS:
            if held:
                parts.append(f"L{_n(hu)} {_n(hv)}")
                held = False
            close()
            parts, count, pu, pv = [], 0, math.nan, math.nan
            key, dashed = rec[1], rec[2]
        x0, y0 = rec[3], rec[4]
        if held:
            if hu != x0 or hv != y0:
                parts.append(f"L{_n(hu)} {_n(hv)}M{_n(x0)} {_n(y0)}")
                pu, pv, held = x0, y0, False
        elif pu != x0 or pv != y0:
            parts.append(f"M{_n(x0)} {_n(y0)}")
            pu, pv = x0, y0
        count += 1
        if kind == LINE:
            x1, y1 = rec[5], rec[6]
            if abs(x1 - pu) + abs(y1 - pv) < join:
                hu, hv, held = x1, y1, True
            else:
                parts.append(f"L{_n(x1)} {_n(y1)}")
                pu, pv, held = x1, y1, False
            continue
        if held:
            parts.append(f"L{_n(hu)} {_n(hv)}")
            pu, pv, held = hu, hv, False
        if kind == ARC_2D:
            r = _n(rec[7])
            parts.append(f"A{r} {r} 0 {int(rec[8])} {int(rec[9])} {_n(rec[5])} {_n(rec[6])}")
            pu, pv = rec[5], rec[6]
        elif kind == CUBIC:
            parts.append(f"C{_n(rec[5])} {_n(rec[6])} {_n(rec[7])} {_n(rec[8])} "
                         f"{_n(rec[9])} {_n(rec[10])}")
            pu, pv = rec[9], rec[10]
        elif kind == QUAD:
            parts.append(f"Q{_n(rec[5])} {_n(rec[6])} {_n(rec[7])} {_n(rec[8])}")
            pu, pv = rec[7], rec[8]
    if held:
        parts.append(f"L{_n(hu)} {_n(hv)}")
    close()


def _marks(out: TextIO, marks: Spool, lay: Layout) -> None:
    if not marks.count:
        return
    out.write('<g id="marks">\n')
    for rec in marks:
        x, y = lay.px(rec[3], rec[4])
        if not (math.isfinite(x) and math.isfinite(y)):
            continue
        if rec[1] == DRILL:
            out.write(f'<circle cx="{_p(x)}" cy="{_p(y)}" r="3.5" fill="none" '
                      f'stroke="#333" stroke-width="1"/>\n')
        elif rec[1] == TOOL_CHANGE:
            out.write(f'<path d="M{_p(x)} {_p(y - 6)}l6 6l-6 6l-6 -6z" fill="#ff7f0e" '
                      f'stroke="#333" stroke-width="0.8"/>'
                      f'<text x="{_p(x + 8)}" y="{_p(y - 6)}">T{int(rec[5])}</text>\n')
        elif rec[1] == STOPPED:
            out.write(f'<path id="stopped" d="M{_p(x - 7)} {_p(y - 7)}l14 14m0 -14l-14 14" '
                      f'stroke="#d62728" stroke-width="3"/>\n')
    out.write("</g>\n")


def _nice(length: float) -> float:
    """The greatest of 1, 2, 5 times a power of ten not above ``length``."""
    if not length > 0:
        return 0.0
    base = 10.0 ** math.floor(math.log10(length))
    for k in (5.0, 2.0, 1.0):
        if k * base <= length:
            return k * base
    return base


def _frame(out: TextIO, scene: Scene, labels: Labels, lay: Layout) -> None:
    """Title, legend, dimension lines, scale bar and the error, in pixels."""
    u = labels.mm_per_unit
    title = f"{labels.name}: path {_length(scene.length / u, labels.units)}"
    title += f" (rapid {_length(scene.rapid_length / u, '')})"
    if labels.time_s is not None:
        title += f", cycle time {labels.time_s:.2f} s"
    title += f", {scene.view.name} view"
    out.write(f'<text id="title" x="{_p(MARGIN[0])}" y="28" font-size="16">'
              f"{escape(title)}</text>\n")
    _legend(out, scene, lay)
    box = scene.box
    shown = (*box.low, *box.high)
    if scene.view.axes is None:  # (the isometric view gives the X Y Z extents)
        shown += (*scene.extents.low, *scene.extents.high)
    if not box.empty and all(math.isfinite(v) for v in shown):
        _dimensions(out, scene, labels, lay)
        _scale_bar(out, labels, lay)
    if labels.error is not None:
        out.write(f'<text id="error" x="{_p(MARGIN[0])}" y="{_p(lay.height - 12)}" '
                  f'fill="#d62728">{escape(labels.error)}</text>\n')


def _length(value: float, units: str) -> str:
    text = f"{value:.3f} {units}" if math.isfinite(value) else "past a double's range"
    return text.rstrip()


def _legend(out: TextIO, scene: Scene, lay: Layout) -> None:
    x = lay.width - MARGIN[1] + 20.0
    y = 50.0
    out.write('<g id="legend">\n')
    colors = Colors(scene)
    if scene.color in ("kind", "tool"):
        for key in sorted(scene.keys):
            name = KINDS[int(key)] if scene.color == "kind" else f"T{int(key)}"
            dashed = scene.color == "kind" and name == "rapid"
            dash = f' stroke-dasharray="{_p(DASH_PX)} {_p(DASH_PX)}"' if dashed else ""
            out.write(f'<line x1="{_p(x)}" y1="{_p(y)}" x2="{_p(x + 30)}" y2="{_p(y)}" '
                      f'stroke="{colors(key, dashed)}" stroke-width="2"{dash}/>'
                      f'<text x="{_p(x + 38)}" y="{_p(y + 4)}">{escape(name)}</text>\n')
            y += 18.0
    else:
        lo, hi = scene.key_range
        what = "feed" if scene.color == "feed" else "line"
        for i in range(5):
            value = lo + (hi - lo) * i / 4
            out.write(f'<rect x="{_p(x)}" y="{_p(y - 6)}" width="30" height="12" '
                      f'fill="{ramp(i / 4)}"/><text x="{_p(x + 38)}" y="{_p(y + 4)}">'
                      f"{what} {value:g}</text>\n")
            y += 18.0
    out.write("</g>\n")


def _dimensions(out: TextIO, scene: Scene, labels: Labels, lay: Layout) -> None:
    """The extents along the screen's axes, in the program's units, where they are machine
    axes; in the isometric view, the X Y Z extents as text."""
    box, u = scene.box, labels.mm_per_unit
    axes = scene.view.axes
    out.write('<g id="dimensions" stroke="#555" fill="#333" stroke-width="1">\n')
    if axes is None:
        e = scene.extents
        text = ", ".join(f"{a} {(e.high[i] - e.low[i]) / u:.3f}" for i, a in enumerate("XYZ"))
        out.write(f'<text x="{_p(MARGIN[0])}" y="{_p(lay.height - 40)}" stroke="none">'
                  f"extents {escape(text)} {labels.units}</text>\n")
    else:
        x0, y0 = lay.px(box.low[0], box.low[1])
        x1, y1 = lay.px(box.high[0], box.high[1])
        yd = y0 + 24.0
        w = (box.high[0] - box.low[0]) / u
        wname = axes[0]
        if labels.diameter and wname == "X":
            w, wname = 2.0 * w, "X diameter"
        out.write(f'<path d="M{_p(x0)} {_p(yd)}H{_p(x1)}M{_p(x0)} {_p(yd - 5)}v10'
                  f'M{_p(x1)} {_p(yd - 5)}v10"/>'
                  f'<text x="{_p((x0 + x1) / 2)}" y="{_p(yd + 16)}" text-anchor="middle" '
                  f'stroke="none">{wname} {w:.3f} {labels.units}</text>\n')
        xd = x0 - 24.0
        h = (box.high[1] - box.low[1]) / u
        name = axes[1]
        if labels.diameter and name == "X":
            h, name = 2.0 * h, "X diameter"
        ym = (y0 + y1) / 2
        out.write(f'<path d="M{_p(xd)} {_p(y0)}V{_p(y1)}M{_p(xd - 5)} {_p(y0)}h10'
                  f'M{_p(xd - 5)} {_p(y1)}h10"/>'
                  f'<text x="{_p(xd - 8)}" y="{_p(ym)}" text-anchor="middle" stroke="none" '
                  f'transform="rotate(-90 {_p(xd - 8)} {_p(ym)})">{name} {h:.3f} '
                  f"{labels.units}</text>\n")
    out.write("</g>\n")


def _scale_bar(out: TextIO, labels: Labels, lay: Layout) -> None:
    """A bar of a round length, about a fifth of the drawing's width."""
    units = _nice(0.2 * (lay.width - MARGIN[0] - MARGIN[1]) / lay.s / labels.mm_per_unit)
    if not units > 0:
        return
    px = units * labels.mm_per_unit * lay.s
    x = lay.width - MARGIN[1] - px
    y = lay.height - 30.0
    out.write(f'<g id="scale"><path d="M{_p(x)} {_p(y)}h{_p(px)}" stroke="#333" '
              f'stroke-width="3"/><text x="{_p(x + px / 2)}" y="{_p(y - 6)}" '
              f'text-anchor="middle">{units:g} {labels.units}</text></g>\n')


__all__ = ["COLOR_KEYS", "Labels", "Layout", "layout", "write"]
