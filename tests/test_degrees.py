"""SIN, COS and TAN of degrees (``ngc.numeric.degrees``): the doctests, the reduction written out against
the helpers it was made of, and the kept reduction of :class:`Trig`, which answers as a fresh
computation does."""

from __future__ import annotations

import doctest
import random
import struct

from ngc.numeric import degrees
from ngc.numeric.degrees import Trig, cos_degrees, sin_degrees, tan_degrees


def _bits(*values: float) -> bytes:
    return struct.pack(f"{len(values)}d", *values)  # -0.0 is not 0.0


def _angles(seed: int, count: int) -> list[float]:
    """Angles of every size: multiples of simple steps, quarter turns and their neighbours,
    random doubles of any exponent."""
    rng = random.Random(seed)
    out: list[float] = []
    while len(out) < count:
        kind = rng.randrange(4)
        if kind == 0:
            v = rng.randint(-10**6, 10**6) * rng.choice((0.5, 0.1, 0.001, 45.0, 22.5))
        elif kind == 1:
            v = rng.randint(-10**6, 10**6) * 90.0 * rng.choice((1.0, 1.0 + 2**-52, 1.0 - 2**-53))
        elif kind == 2:
            v = rng.uniform(-1.0, 1.0) * 10.0 ** rng.randint(-30, 25)
        else:
            v = struct.unpack("d", struct.pack("Q", rng.getrandbits(64)))[0]
        if v and v - v == 0.0:
            out.append(v)
    return out


def _reference_sin(x: float) -> float:
    """SIN from the step functions one at a time (angle, reduction, series, rounding)."""
    m, e = degrees._angle(abs(x))
    if e + 64 < -70:
        return degrees._to_double(m if x > 0 else -m, e)
    width = degrees._FRAC + max(0, e + 64) + 8
    half_pi = degrees._HALF_PI >> (degrees._PI_BITS - width)
    a = m << (e + width)
    k = (2 * a + half_pi) // (2 * half_pi)
    r = (a - k * half_pi) >> (width - degrees._FRAC)
    u = abs(r)
    j = (u + (1 << (degrees._STEP - 1))) >> degrees._STEP
    sj, cj = degrees._series(j << degrees._STEP)
    s, c = degrees._series(u - (j << degrees._STEP))
    v = (sj * c + cj * s) >> degrees._FRAC if k % 2 == 0 else (cj * c - sj * s) >> degrees._FRAC
    if k % 2 == 0 and r < 0:
        v = -v
    return degrees._to_double(v if (k % 4 < 2) == (x > 0) else -v, -degrees._FRAC)


def test_doctests() -> None:
    failed, attempted = doctest.testmod(degrees)
    assert attempted > 0
    assert failed == 0


def test_sine_as_the_steps_give_it() -> None:
    for x in _angles(1, 3000):
        assert _bits(sin_degrees(x)) == _bits(_reference_sin(x)), x


def test_kept_reduction_answers_as_a_fresh_one() -> None:
    trig = Trig()
    rng = random.Random(2)
    angles = _angles(3, 2000)
    for i, x in enumerate(angles):
        x = rng.choice((x, -x, angles[i - 1]))  # the same angle again, of either sign
        for name in rng.sample(("sin", "cos", "tan"), 3):
            fresh = {"sin": sin_degrees, "cos": cos_degrees, "tan": tan_degrees}[name](x)
            assert _bits(getattr(trig, name)(x)) == _bits(fresh), (name, x)


def test_tiny_angles() -> None:
    trig = Trig()
    for x in (1e-300, -1e-300, 5e-324, 1e-25, -1e-25):
        assert _bits(trig.sin(x), trig.cos(x), trig.tan(x)) == _bits(
            sin_degrees(x), cos_degrees(x), tan_degrees(x))
        assert cos_degrees(x) == 1.0
