"""Long double emulation: the fast sum agrees with exact rounding to 64 bits, then to 53."""

from __future__ import annotations

import math
import random
from fractions import Fraction

from ngc.numeric.longdouble import (
    HALF_PI_REST,
    PI,
    PI_LONG_DOUBLE,
    TWO_PI_REST,
    long_sum,
    round_long_double,
)


def _exact(*terms: float) -> float:
    return float(round_long_double(sum(map(Fraction, terms), Fraction(0))))


def test_pi_as_a_long_double() -> None:
    assert round_long_double(PI) == PI_LONG_DOUBLE
    assert PI_LONG_DOUBLE.denominator == 1 << 62 and PI_LONG_DOUBLE.numerator.bit_length() == 64


def test_rounding_ties_to_even() -> None:
    one = Fraction(1)
    ulp = Fraction(1, 1 << 63)  # of a long double in [1, 2)
    assert round_long_double(one + ulp / 2) == one  # a tie: to the even mantissa
    assert round_long_double(one + ulp + ulp / 2) == one + 2 * ulp
    assert round_long_double(-(one + ulp / 2)) == -one
    assert round_long_double(Fraction(0)) == 0


def test_sum_of_random_angles() -> None:
    rng = random.Random(5)
    for _ in range(20000):
        t = rng.uniform(-math.pi, math.pi)
        assert long_sum(t, 2 * math.pi, TWO_PI_REST) == _exact(t, 2 * math.pi, TWO_PI_REST)
        assert long_sum(t, -math.pi / 2, -HALF_PI_REST) == _exact(t, -math.pi / 2, -HALF_PI_REST)


def test_sums_near_a_tie_between_two_doubles() -> None:
    rng = random.Random(6)
    for _ in range(5000):
        a = rng.uniform(1.0, 8.0)
        half = math.ulp(a) / 2
        # the exact sum within a long double's reach of a midpoint, on either side
        b = half + rng.choice((-1, 0, 1)) * rng.randint(0, 8) * half / 2048
        c = rng.choice((-1.0, 1.0)) * rng.randint(0, 4) * half / 4096
        assert long_sum(a, b, c) == _exact(a, b, c)
