"""The moves a lathe cycle makes, as canon in the XZ plane (program coordinates, X a radius)."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING

from ...canon import ops
from ...errors import NgcSemanticError
from .. import comp
from ..handlers import motion
from .profile import CCW

if TYPE_CHECKING:
    from ..machine import Machine


_NO_WORDS: dict[str, float] = {}


class Out:
    """Emits a cycle's moves on a machine; Y and the rotary axes stay where they are.  With
    cutter radius compensation on (G70 runs under it) the moves are compensated like programmed
    ones, from the programmed point."""

    __slots__ = ("m", "zeros")

    def __init__(self, m: Machine) -> None:
        self.m = m
        # the sign rs274 gives a coordinate of 0 of the cycle: (x, z) -> (x, z)
        self.zeros: Callable[[float, float], tuple[float, float]] | None = None

    @property
    def x(self) -> float:
        return self.m.state.pos[0]

    @property
    def z(self) -> float:
        return self.m.state.pos[2]

    def _end(self, x: float, z: float) -> list[float]:
        m = self.m
        pos = m.state.pos if m.comp is None else m.comp.prog
        return [x, pos[1], z, pos[3], pos[4], pos[5]]

    def traverse(self, x: float, z: float) -> None:
        self._straight(ops.StraightTraverse, x, z)

    def feed(self, x: float, z: float) -> None:
        # (a cycle's moves are blocks of their own: no F word, so none in G93)
        motion.check_feed(self.m, _NO_WORDS, "g1")
        self._straight(ops.StraightFeed, x, z)

    def _straight(self, kind: type, x: float, z: float) -> None:
        m = self.m
        _finite(x, z)
        if self.zeros is not None:
            x, z = self.zeros(x, z)
        end = self._end(x, z)
        if m.comp is not None:
            comp.straight(m, kind, end)
            return
        m.move(kind, end, m.label, m.line)
        m.state.pos = end

    def arc(self, x: float, z: float, cx: float, cz: float, kind: int,
            checked: bool = False) -> None:
        """G2 (kind CW) or G3 (CCW) to (x, z) around (cx, cz) in the XZ plane; ``checked``: its
        radii at start and end are held to a programmed arc's tolerance first."""
        m = self.m
        motion.check_arc_feed(m, _NO_WORDS)
        _finite(x, z, cx, cz)
        if checked:
            start = m.state.pos if m.comp is None else m.comp.prog
            check_radii(start[0], start[2], x, z, cx, cz, m.state.metric)
        if self.zeros is not None:
            x, z = self.zeros(x, z)
            cx, cz = self.zeros(cx, cz)
        end = self._end(x, z)
        rotation = 1 if kind == CCW else -1
        if m.comp is not None:
            comp.arc(m, end, cz, cx, rotation)
            return
        m.move(ops.ArcFeed, (z, x, cz, cx, rotation, end[1], end[3], end[4], end[5]), m.label,
               m.line)
        m.state.pos = end


def _finite(*coords: float) -> None:
    """A cycle's move is between numbers: a profile whose numbers are past a double's range when
    moved, joined or crossed (EXP[709] and the like) is refused rather than run as NaN."""
    for v in coords:
        if not math.isfinite(v):
            raise NgcSemanticError("The cycle's profile is too large to compute its moves")


def check_radii(x0: float, z0: float, x1: float, z1: float, cx: float, cz: float,
                metric: bool) -> None:
    """An arc's radii at its start and end must agree as a programmed centre-format arc's do,
    and neither be below the zero-radius tolerance (g-code.adoc G2/G3; rs274 holds G70's corner
    arcs and a moved profile's arcs to it)."""
    r1 = math.hypot(z0 - cz, x0 - cx)
    r2 = math.hypot(z1 - cz, x1 - cx)
    zero = motion.RADIUS_TOLERANCE_MM if metric else motion.RADIUS_TOLERANCE_INCH
    if r1 < zero or r2 < zero:
        raise NgcSemanticError(f"Zero-radius arc: {_where(x0, z0, x1, z1, cx, cz, r1, r2)}")
    abs_err = abs(r1 - r2)
    tol = motion.CENTER_ARC_TOLERANCE_MM if metric else motion.CENTER_ARC_TOLERANCE_INCH
    if abs_err <= tol:
        return
    rel_err = abs_err / max(r1, r2)
    if abs_err > 100 * tol or rel_err > motion.CENTER_ARC_RELATIVE_TOLERANCE:
        raise NgcSemanticError("Radius to end of arc differs from radius to start: "
                               f"{_where(x0, z0, x1, z1, cx, cz, r1, r2)} "
                               f"abs_err={abs_err:.4g} rel_err={rel_err * 100:.4f}%")


def _where(x0: float, z0: float, x1: float, z1: float, cx: float, cz: float, r1: float,
           r2: float) -> str:
    """The arc's points as rs274's arc errors show them, in the XZ plane (Z first)."""
    return motion.arc_where("ZX", z0, x0, cz, cx, z1, x1, r1, r2)
