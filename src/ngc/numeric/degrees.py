"""SIN, COS and TAN of degrees as rs274 computes them, to the last bit.

rs274 takes the angle to radians in x87 long double (a 64-bit mantissa): ``x * pi / 180`` with pi
as a long double holds it and each product rounded to 64 bits; then the C library's ``sinl``,
``cosl`` or ``tanl`` of that angle (accurate to the long double's last bit), and the result
rounded to a double.  So SIN[315] is the double nearest -sqrt(2)/2, where the double computation
is an ulp or two away, and SIN[180] is the tiny sine of the long double nearest pi.

This does the same in integer arithmetic: the long double angle exactly, its remainder from the
nearest multiple of pi/2 against pi to 1,300 bits, sine and cosine of the remainder by their
series in fixed point to 2**-160 (from a table of sin and cos of j/32), rounded to 64 bits, then to
53.

Each integer operation costs about as much as a few lines of Python, so the steps are written out
in one function (:func:`_turns`), and :class:`Trig` keeps the last angle's sine and cosine: a
line that takes both of one angle (``X[R * COS[A]] Y[R * SIN[A]]``, a point on a circle) reduces
it once.
"""

from __future__ import annotations

# pi as the long double nearest to it: 0xC90FDAA22168C235 / 2**62
_PI_LD = 0xC90FDAA22168C235
_FRAC = 160  # fixed-point bits of the remainder and of the series
_PI_BITS = 1300  # enough to reduce the largest long double angle a double's degrees can give


def _pi_fixed(bits: int) -> int:
    """floor(pi * 2**bits), by Machin's formula in integers (guard bits absorb the truncations)."""
    guard = bits + 20
    one = 1 << guard

    def arctan_inv(n: int) -> int:
        total, term, k, n2 = 0, one // n, 1, n * n
        while term:
            total += term // k if k % 4 == 1 else -(term // k)
            term //= n2
            k += 2
        return total

    return (16 * arctan_inv(5) - 4 * arctan_inv(239)) >> 20


_HALF_PI = _pi_fixed(_PI_BITS) >> 1  # pi/2 * 2**_PI_BITS


def _round_bits(n: int, shift: int, bits: int) -> tuple[int, int]:
    """``n * 2**shift`` (n > 0) rounded to ``bits`` significant bits, ties to even, as (m, e)."""
    extra = n.bit_length() - bits
    if extra <= 0:
        return n, shift
    m, rest = n >> extra, n & ((1 << extra) - 1)
    half = 1 << (extra - 1)
    if rest > half or (rest == half and m & 1):
        m += 1
    return m, shift + extra


def _angle(x: float) -> tuple[int, int]:
    """The long double angle in radians of ``x`` degrees (x > 0): ld(ld(x * pi) / 180) as (m, e)."""
    num, den = x.as_integer_ratio()  # den is a power of two
    m, e = _round_bits(num * _PI_LD, -62 - (den.bit_length() - 1), 64)
    q, r = divmod(m << 72, 180)  # 72 more bits than the quotient needs to round once
    m, e = _round_bits(2 * q + (r != 0), e - 73, 64)  # the low bit keeps a remainder's trace
    return m, e


def _series(r: int) -> tuple[int, int]:
    """sin and cos of ``r * 2**-_FRAC`` by their series, in the same fixed point (slow: for the
    table)."""
    one = 1 << _FRAC
    r2 = (r * r) >> _FRAC
    s = term = r
    k = 2
    while term:
        term = -((term * r2) >> _FRAC) // (k * (k + 1))
        s += term
        k += 2
    c = term = one
    k = 1
    while term:
        term = -((term * r2) >> _FRAC) // (k * (k + 1))
        c += term
        k += 2
    return s, c


# sin and cos of j/32 for j = 0 .. 26 (up to pi/4), in fixed point
_STEP = _FRAC - 5
_TABLE = tuple(_series(j << _STEP) for j in range(27))
_SCALE = float(1 << _FRAC)
_ONE = 1 << _FRAC
_HALF_STEP = 1 << (_STEP - 1)
# pi/2 in the fixed point of a remainder taken from an angle below 2**w radians (w = 0 .. _WIDE):
# 8 bits more than _FRAC, and w more
_WIDE = 64
_HALF_PIS = tuple(_HALF_PI >> (_PI_BITS - (_FRAC + 8 + w)) for w in range(_WIDE + 1))
# 2**(e - _FRAC) for a result of e more bits than a long double's 64 (e = 0 .. _FRAC + 1)
_UNITS = tuple(2.0 ** (e - _FRAC) for e in range(_FRAC + 2))
# Up to this many quarter turns, the nearest is found from x / 90 in doubles (closer to a half
# than this margin, the exact division decides).
_QUARTERS = 1e9
_MARGIN = 0.499


def _turns(x: float) -> tuple[int, int, int] | None:
    """``x`` degrees (x > 0, finite) as rs274's long double angle: (k, s, c), the angle being k
    quarter turns (0 .. 3) plus r with |r| <= pi/4, s and c sin r and cos r in fixed point
    (2**-_FRAC), to about 2**-72; None for an angle so small that its sine is itself and its
    cosine 1, to the long double.

    The steps of :func:`_angle`, :func:`_round_bits` and the reduction written out (ties to
    even: ``n + half - 1 + lowest bit``, shifted).
    """
    num, den = x.as_integer_ratio()  # den is a power of two
    n = num * _PI_LD
    extra = n.bit_length() - 64  # (>= 0: _PI_LD has 64 bits)
    e = extra - 61 - den.bit_length()
    if extra:
        n = (n + (1 << (extra - 1)) - 1 + ((n >> extra) & 1)) >> extra
    q, rest = divmod(n << 72, 180)  # 72 more bits than the quotient needs to round once
    q = (q << 1) | (rest != 0)  # the low bit keeps a remainder's trace
    extra = q.bit_length() - 64
    m = (q + (1 << (extra - 1)) - 1 + ((q >> extra) & 1)) >> extra
    e += extra - 73
    # the angle is m * 2**e, below 2**w
    w = e + 64
    if w < -70:
        return None
    if w <= 0:
        width = _FRAC + 8
        half_pi = _HALF_PIS[0]
    else:
        width = _FRAC + 8 + w
        half_pi = _HALF_PIS[w] if w <= _WIDE else _HALF_PI >> (_PI_BITS - width)
    shift = e + width
    a = m << shift if shift >= 0 else m >> -shift
    quarters = x / 90.0
    k = int(quarters + 0.5)
    if not (quarters < _QUARTERS and -_MARGIN < quarters - k < _MARGIN):
        k = (2 * a + half_pi) // (2 * half_pi)
    r = (a - k * half_pi) >> (width - _FRAC) if k else a >> (width - _FRAC)
    # sin and cos of r: from the table's nearest j/32, and the series of the rest u
    # (|u| <= 1/64), whose terms past u and u**2/2 are small enough for doubles
    u = -r if r < 0 else r
    j = (u + _HALF_STEP) >> _STEP
    u -= j << _STEP
    sj, cj = _TABLE[j]
    uf = u / _SCALE
    uf2 = uf * uf
    sin_u = u - int(uf * uf2 * (1 / 6 - uf2 * (1 / 120 - uf2 / 5040)) * _SCALE)
    cos_u = _ONE - ((u * u) >> (_FRAC + 1)) + int(
        uf2 * uf2 * (1 / 24 - uf2 * (1 / 720 - uf2 / 40320)) * _SCALE)
    s = (sj * cos_u + cj * sin_u) >> _FRAC
    c = (cj * cos_u - sj * sin_u) >> _FRAC
    return k & 3, (-s if r < 0 else s), c


def _to_double(v: int, shift: int) -> float:
    """``v * 2**shift`` rounded to a long double, then to a double."""
    if v == 0:
        return 0.0
    m, e = _round_bits(abs(v), shift, 64)
    d = m / (1 << -e) if e < 0 else float(m << e)  # int / int rounds once, subnormals included
    return d if v > 0 else -d


def _fixed_to_double(v: int) -> float:
    """``v * 2**-_FRAC`` (|v| <= 2**_FRAC) rounded to a long double, then to a double: the
    64-bit mantissa's float (rounded once, ties to even) scaled by a power of two, which is exact
    (no result of these functions is subnormal)."""
    a = -v if v < 0 else v
    extra = a.bit_length() - 64
    if extra <= 0:
        return _to_double(v, -_FRAC)
    d = float((a + (1 << (extra - 1)) - 1 + ((a >> extra) & 1)) >> extra) * _UNITS[extra]
    return -d if v < 0 else d


def _tiny(x: float) -> float:
    """The sine (and tangent) of an angle of ``x`` degrees too small for :func:`_turns`: the
    angle itself."""
    m, e = _angle(abs(x))
    return _to_double(m if x > 0 else -m, e)


def _sin(x: float, turns: tuple[int, int, int] | None) -> float:
    if turns is None:
        return _tiny(x)
    k, s, c = turns
    v = c if k & 1 else s
    return _fixed_to_double(v if (k < 2) == (x > 0) else -v)


def _cos(turns: tuple[int, int, int] | None) -> float:
    if turns is None:
        return 1.0
    k, s, c = turns
    v = s if k & 1 else c
    return _fixed_to_double(v if k == 0 or k == 3 else -v)


def _tan(x: float, turns: tuple[int, int, int] | None) -> float:
    if turns is None:
        return _tiny(x)
    k, s, c = turns
    if k & 1:
        s, c = c, -s
    q = (abs(s) << _FRAC) // abs(c)
    return _to_double(q if ((s >= 0) == (c > 0)) == (x > 0) else -q, -_FRAC)


def sin_degrees(x: float) -> float:
    """SIN of ``x`` degrees (finite, not zero).

    >>> sin_degrees(315.0)  # the double nearest -sqrt(2)/2 (in doubles: -0.7071067811865477)
    -0.7071067811865476
    >>> sin_degrees(180.0)
    -5.016557612668332e-20
    """
    return _sin(x, _turns(-x if x < 0 else x))


def cos_degrees(x: float) -> float:
    """COS of ``x`` degrees (finite).

    >>> cos_degrees(90.0)
    -2.508278806334166e-20
    """
    return _cos(_turns(-x if x < 0 else x)) if x else 1.0


def tan_degrees(x: float) -> float:
    """TAN of ``x`` degrees (finite, not zero).

    >>> tan_degrees(45.0), tan_degrees(90.0)
    (1.0, -3.98679762981171e+19)
    """
    return _tan(x, _turns(-x if x < 0 else x))


class Trig:
    """SIN, COS and TAN of degrees (finite, not zero) that keep the last angle's reduction."""

    __slots__ = ("_angle", "_turns")

    def __init__(self) -> None:
        self._angle = 0.0  # (never asked for: zero is answered before)
        self._turns: tuple[int, int, int] | None = None

    def _reduced(self, a: float) -> tuple[int, int, int] | None:
        """:func:`_turns` of ``a`` (> 0): kept from the last call for the same angle (floats that
        are equal and not zero are the same number)."""
        if a == self._angle:
            return self._turns
        turns = self._turns = _turns(a)
        self._angle = a
        return turns

    def sin(self, x: float) -> float:
        return _sin(x, self._reduced(-x if x < 0 else x))

    def cos(self, x: float) -> float:
        return _cos(self._reduced(-x if x < 0 else x))

    def tan(self, x: float) -> float:
        return _tan(x, self._reduced(-x if x < 0 else x))
