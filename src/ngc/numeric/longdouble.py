"""x87 long double arithmetic, where rs274's results depend on it.

rs274 computes some values in 80-bit long double (a 64-bit mantissa) and stores them as doubles:
trigonometry of expressions (``language/expressions.py``) and some of cutter compensation's
angles (``interp/comp.py``).  These helpers give the same doubles: exact rational arithmetic
rounded to 64 bits, and a fast sum that takes the exact path only where rounding twice can differ
from rounding once.
"""

from __future__ import annotations

import math
from fractions import Fraction

# pi to 254 bits, and as a long double holds it
PI = Fraction(0xC90FDAA22168C234C4C6628B80DC1CD129024E088A67CC74020BBEA63B139B22, 1 << 254)
PI_LONG_DOUBLE = Fraction(0xC90FDAA22168C235, 1 << 62)


def round_long_double(q: Fraction) -> Fraction:
    """``q`` rounded to a 64-bit mantissa, ties to even (x87 extended precision)."""
    if q == 0:
        return q
    sign = -1 if q < 0 else 1
    n, d = abs(q.numerator), q.denominator
    shift = 63 - (n.bit_length() - d.bit_length())
    if (n << shift if shift >= 0 else n) < (d if shift >= 0 else d << -shift) << 63:
        shift += 1
    num, den = (n << shift, d) if shift >= 0 else (n, d << -shift)
    m, rem = divmod(num, den)
    if 2 * rem > den or (2 * rem == den and m & 1):
        m += 1
    return sign * Fraction(m) / (Fraction(2) ** shift)


# pi, pi/2 and 2 pi as long doubles hold them: the double nearest, plus the (exact) rest
PI_REST = float(PI_LONG_DOUBLE - Fraction(math.pi))
HALF_PI_REST = float(PI_LONG_DOUBLE / 2 - Fraction(math.pi / 2))
TWO_PI_REST = float(PI_LONG_DOUBLE * 2 - Fraction(2 * math.pi))


def long_sum(*terms: float) -> float:
    """The sum of ``terms`` (doubles) rounded to a long double, then to a double."""
    total = math.fsum(terms)  # the exact sum rounded once
    if not math.isfinite(total):
        return total
    half = math.ulp(total) / 2
    # rounded twice, the sum differs only near a tie between two doubles (or at a power of two)
    if abs(abs(math.fsum((*terms, -total))) - half) > half / 512 and math.frexp(total)[0] != 0.5:
        return total
    return float(round_long_double(sum(map(Fraction, terms), Fraction(0))))
