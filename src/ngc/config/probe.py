"""A simulated probe input for G38.2-G38.5: the solids the probe touches, read from a small TOML
file (``ngc canon --probe FILE``, ``Interpreter(..., probe=...)``).

rs274's standalone machine has no probe input: its probe never trips (``ngc rs274`` does the same).
With a :class:`Surfaces`, a straight probe stops where it first touches material (G38.2, G38.3)
or first leaves it (G38.4, G38.5), and #5061-#5070 say so.

The file, in machine coordinates (where G53 goes; the controlled point, tool length offset
included) and in the ``units`` it names (``"mm"``, the default, or ``"inch"``)::

    units = "mm"

    [[plane]]             # material below z = z + slope_x * X + slope_y * Y, everywhere
    z = -1.0
    slope_x = 0.002
    slope_y = 0.0

    [[grid]]              # a height map: material below a surface through these heights,
    origin = [0.0, 0.0]   # bilinear between them; heights[j][i] at origin + (i, j) * step
    step = [10.0, 10.0]
    heights = [[0.0, 0.1, 0.0],
               [0.05, 0.2, 0.1]]

    [[box]]               # a block
    min = [0.0, 0.0, -20.0]
    max = [100.0, 50.0, 0.0]

    [[cylinder]]          # a vertical round boss (or, with cut = true, a hole)
    center = [50.0, 25.0]
    radius = 10.0
    bottom = -20.0        # optional: unbounded below / above if left out
    top = 0.0
    cut = true            # any shape: removes material instead of adding it

The probe touches where a point is inside some shape without ``cut`` and inside none with it
(surfaces included).  Outside a grid there is no material of that grid.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from itertools import pairwise
from typing import Any, Protocol

from .tomlfile import read_toml

Point = Sequence[float]
_UNITS = {"mm": 1.0, "inch": 25.4}
NUDGE_MM = 1e-7  # how far behind its start a probe move looks for the surface it stopped on


class Shape(Protocol):
    cut: bool

    def inside(self, p: Point) -> bool: ...

    def crossings(self, s: Point, d: Point) -> list[float]:
        """The fractions ``t`` in [0, 1] where ``s + t * d`` may cross the shape's surface."""
        ...


class Plane:
    """Material below ``z = z0 + sx * x + sy * y``."""

    def __init__(self, z0: float, sx: float, sy: float, cut: bool) -> None:
        self.z0, self.sx, self.sy, self.cut = z0, sx, sy, cut

    def _gap(self, p: Point) -> float:
        return p[2] - (self.z0 + self.sx * p[0] + self.sy * p[1])

    def inside(self, p: Point) -> bool:
        return self._gap(p) <= 0.0

    def crossings(self, s: Point, d: Point) -> list[float]:
        g0 = self._gap(s)
        g1 = self._gap([s[i] + d[i] for i in range(3)])
        return [g0 / (g0 - g1)] if g0 != g1 else []


class Box:
    """An axis-aligned block."""

    def __init__(self, low: Point, high: Point, cut: bool) -> None:
        self.low, self.high, self.cut = list(low), list(high), cut

    def inside(self, p: Point) -> bool:
        return all(self.low[i] <= p[i] <= self.high[i] for i in range(3))

    def crossings(self, s: Point, d: Point) -> list[float]:
        return [(bound - s[i]) / d[i] for i in range(3) if d[i] for bound in (self.low[i], self.high[i])]


class Cylinder:
    """A vertical round solid between ``bottom`` and ``top``."""

    def __init__(self, center: Point, radius: float, bottom: float, top: float, cut: bool) -> None:
        self.cx, self.cy = center[0], center[1]
        self.radius, self.bottom, self.top, self.cut = radius, bottom, top, cut

    def inside(self, p: Point) -> bool:
        return (math.hypot(p[0] - self.cx, p[1] - self.cy) <= self.radius
                and self.bottom <= p[2] <= self.top)

    def crossings(self, s: Point, d: Point) -> list[float]:
        ts = [(z - s[2]) / d[2] for z in (self.bottom, self.top) if d[2] and math.isfinite(z)]
        ox, oy = s[0] - self.cx, s[1] - self.cy
        a = d[0] * d[0] + d[1] * d[1]
        if a:
            ts += _roots(a, 2 * (ox * d[0] + oy * d[1]), ox * ox + oy * oy - self.radius ** 2)
        return ts


class Grid:
    """A height map: material below the bilinear surface through ``heights`` (rows along Y)."""

    def __init__(self, origin: Point, step: Point, heights: list[list[float]], cut: bool) -> None:
        self.x0, self.y0 = origin[0], origin[1]
        self.dx, self.dy = step[0], step[1]
        self.heights, self.cut = heights, cut
        self.nx, self.ny = len(heights[0]), len(heights)

    def height(self, x: float, y: float) -> float | None:
        u = (x - self.x0) / self.dx
        v = (y - self.y0) / self.dy
        if not (0.0 <= u <= self.nx - 1 and 0.0 <= v <= self.ny - 1):
            return None
        i = min(int(u), self.nx - 2) if self.nx > 1 else 0
        j = min(int(v), self.ny - 2) if self.ny > 1 else 0
        fu, fv = u - i, v - j
        h = self.heights
        i1, j1 = min(i + 1, self.nx - 1), min(j + 1, self.ny - 1)
        return ((h[j][i] * (1 - fu) + h[j][i1] * fu) * (1 - fv)
                + (h[j1][i] * (1 - fu) + h[j1][i1] * fu) * fv)

    def inside(self, p: Point) -> bool:
        z = self.height(p[0], p[1])
        return z is not None and p[2] <= z

    def crossings(self, s: Point, d: Point) -> list[float]:
        """The grid lines crossed, and in each piece between them (where the gap to the
        surface is a quadratic in t) its roots."""
        cuts = [0.0, 1.0]
        for axis, origin, step, count in ((0, self.x0, self.dx, self.nx), (1, self.y0, self.dy, self.ny)):
            if d[axis]:
                cuts += [(origin + k * step - s[axis]) / d[axis] for k in range(count)]
        cuts = sorted(t for t in cuts if 0.0 <= t <= 1.0)
        found = list(cuts)
        for ta, tb in pairwise(cuts):
            found += _piece_roots(lambda t: self._gap(s, d, t), ta, tb)
        return found

    def _gap(self, s: Point, d: Point, t: float) -> float | None:
        z = self.height(s[0] + t * d[0], s[1] + t * d[1])
        return None if z is None else s[2] + t * d[2] - z


def _piece_roots(gap: Callable[[float], float | None], ta: float, tb: float) -> list[float]:
    """The roots in [ta, tb] of a quadratic known by three values."""
    tm = (ta + tb) / 2
    ga, gm, gb = gap(ta), gap(tm), gap(tb)
    if ga is None or gm is None or gb is None or tb <= ta:
        return []
    # g(ta + u * h), u in [0, 1]: through (0, ga), (1/2, gm), (1, gb)
    a = 2 * ga - 4 * gm + 2 * gb
    b = -3 * ga + 4 * gm - gb
    us = _roots(a, b, ga) if a else ([-ga / b] if b else [])
    return [ta + u * (tb - ta) for u in us if 0.0 <= u <= 1.0]


def _roots(a: float, b: float, c: float) -> list[float]:
    disc = b * b - 4 * a * c
    if disc < 0.0:
        return []
    r = math.sqrt(disc)
    return [(-b - r) / (2 * a), (-b + r) / (2 * a)]


class Surfaces:
    """The shapes the simulated probe touches (lengths in mm, machine coordinates)."""

    def __init__(self, shapes: Sequence[Shape]) -> None:
        self.shapes = list(shapes)

    def touching(self, p: Point) -> bool:
        solid = False
        for shape in self.shapes:
            if shape.inside(p):
                if shape.cut:
                    return False
                solid = True
        return solid

    def first_change(self, start_mm: Point, end_mm: Point) -> tuple[bool, float | None]:
        """Whether the probe touches at ``start_mm``, and the fraction of the way to ``end_mm``
        where that first changes (None: nowhere on the way).

        A probe that stopped on a surface touches it: the start counts as touching if the
        point :data:`NUDGE_MM` behind it (against the move) does."""
        d = [end_mm[i] - start_mm[i] for i in range(3)]
        at = self._at(start_mm, d)
        length = math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2])
        was = self.touching(start_mm) or (length > 0.0 and self.touching(at(-NUDGE_MM / length)))
        ts = sorted({t for shape in self.shapes for t in shape.crossings(start_mm, d)
                     if 0.0 <= t <= 1.0} | {0.0, 1.0})
        for k, t in enumerate(ts):
            if t > 0.0 and self.touching(at(t)) != was:
                return was, t
            if k + 1 < len(ts) and self.touching(at((t + ts[k + 1]) / 2)) != was:
                return was, t
        return was, None

    @staticmethod
    def _at(s: Point, d: Point) -> Callable[[float], list[float]]:
        return lambda t: [s[i] + t * d[i] for i in range(3)]


# -- the file ---------------------------------------------------------------------------------
def read_probe_file(path: str) -> Surfaces:
    """Read a probe file (module docstring); :class:`NgcConfigError` names what is wrong."""
    return read_toml(path, "probe file", surfaces_from, (ValueError, TypeError, KeyError,
                                                         IndexError))


def surfaces_from(data: dict[str, Any]) -> Surfaces:
    """:class:`Surfaces` from a probe file's parsed TOML; ValueError names what is wrong."""
    unknown = set(data) - {"units", *_READERS}
    if unknown:
        raise ValueError(f"unknown key {sorted(unknown)[0]!r}")
    units = data.get("units", "mm")
    if units not in _UNITS:
        raise ValueError(f"units must be \"mm\" or \"inch\", not {units!r}")
    k = _UNITS[units]
    shapes: list[Shape] = []
    for kind, reader in _READERS.items():
        tables = data.get(kind, [])
        if not isinstance(tables, list):
            raise ValueError(f"{kind} must be an array of tables ([[{kind}]])")
        for table in tables:
            shapes.append(reader(_Table(kind, table), k))
    return Surfaces(shapes)


class _Table:
    """One shape's table, read key by key; unknown keys are refused at the end."""

    def __init__(self, kind: str, table: dict[str, Any]) -> None:
        self.kind, self.table, self.used = kind, table, {"cut"}

    def number(self, key: str, default: float | None = None) -> float:
        value = self.table.get(key, default)
        if value is None:
            raise ValueError(f"[[{self.kind}]] needs {key}")
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise ValueError(f"[[{self.kind}]] {key} must be a number")
        self.used.add(key)
        return float(value)

    def numbers(self, key: str, count: int) -> list[float]:
        value = self.table.get(key)
        if (not isinstance(value, list) or len(value) != count
                or not all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value)):
            raise ValueError(f"[[{self.kind}]] {key} must be {count} numbers")
        self.used.add(key)
        return [float(v) for v in value]

    def done(self) -> bool:
        unknown = set(self.table) - self.used
        if unknown:
            raise ValueError(f"[[{self.kind}]] has an unknown key {sorted(unknown)[0]!r}")
        cut = self.table.get("cut", False)
        if not isinstance(cut, bool):
            raise ValueError(f"[[{self.kind}]] cut must be true or false")
        return cut


def _plane(t: _Table, k: float) -> Shape:
    z, sx, sy = t.number("z"), t.number("slope_x", 0.0), t.number("slope_y", 0.0)
    return Plane(z * k, sx, sy, t.done())


def _box(t: _Table, k: float) -> Shape:
    low, high = t.numbers("min", 3), t.numbers("max", 3)
    return Box([v * k for v in low], [v * k for v in high], t.done())


def _cylinder(t: _Table, k: float) -> Shape:
    center, radius = t.numbers("center", 2), t.number("radius")
    bottom, top = t.number("bottom", -math.inf), t.number("top", math.inf)
    return Cylinder([v * k for v in center], radius * k, bottom * k, top * k, t.done())


def _grid(t: _Table, k: float) -> Shape:
    origin, step = t.numbers("origin", 2), t.numbers("step", 2)
    rows = t.table.get("heights")
    if (not isinstance(rows, list) or not rows or not all(isinstance(r, list) and r for r in rows)
            or len({len(r) for r in rows}) != 1):
        raise ValueError("[[grid]] heights must be rows of numbers, all of one length")
    t.used.add("heights")
    if step[0] <= 0 or step[1] <= 0:
        raise ValueError("[[grid]] step must be positive")
    heights = [[float(v) * k for v in row] for row in rows]
    return Grid([v * k for v in origin], [v * k for v in step], heights, t.done())


_READERS: dict[str, Callable[[_Table, float], Shape]] = {
    "plane": _plane, "grid": _grid, "box": _box, "cylinder": _cylinder,
}


class Probe(Protocol):
    """A simulated probe input, as G38.2-G38.5 use it (:class:`Surfaces` is one)."""

    def first_change(self, start_mm: Point, end_mm: Point) -> tuple[bool, float | None]: ...
