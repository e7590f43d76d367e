"""The signs rs274's lathe cycles give a coordinate of 0: each cycle works in a frame that may turn
an axis round, and a 0 comes back from such an axis as -0, from the others as +0."""

from __future__ import annotations

from collections.abc import Callable

# a coordinate this near 0 is 0 (an R arc's centre or a moved point a few ulps off, where
# rs274's own arithmetic gives 0 and its frame the sign)
_ZERO = 1e-12


def turning_zeros(flip_x: bool, flip_z: bool) -> Callable[[float, float], tuple[float, float]]:
    """G71's signs of zero: rs274 turns an axis round in its frame when the passes step up X or
    cut toward +Z, and a coordinate of 0 comes back from such an axis as -0, from the others as
    +0 (a -0 of the program too)."""
    def zeros(x: float, z: float) -> tuple[float, float]:
        if -_ZERO < x < _ZERO:
            x = -0.0 if flip_x else 0.0
        if -_ZERO < z < _ZERO:
            z = -0.0 if flip_z else 0.0
        return x, z
    return zeros


def facing_zeros(x_round: bool, z_by_x: bool) -> Callable[[float, float], tuple[float, float]]:
    """G72's signs of zero: rs274's frame is turned a quarter round, and what comes back as 0
    takes its sign from that turn.  Cutting toward +X an X of 0 prints -0; where the passes step
    the way the cut goes round (down Z cutting toward -X, up Z toward +X) a Z of 0 prints -0
    where X is positive, +0 where it is not; every other 0 prints +0 (a -0 of the program too)."""
    def zeros(x: float, z: float) -> tuple[float, float]:
        if -_ZERO < x < _ZERO:
            x = -0.0 if x_round else 0.0
        if -_ZERO < z < _ZERO:
            z = -0.0 if z_by_x and x > 0.0 else 0.0
        return x, z
    return zeros
