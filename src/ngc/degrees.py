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


def _sin_cos(r: int) -> tuple[int, int]:
    """sin and cos of ``r * 2**-_FRAC`` (|r| <= pi/4), in the same fixed point, to about 2**-72
    of the result: from the table's nearest j/32, and the series of the rest u (|u| <= 1/64),
    whose terms past u and u**2/2 are small enough for doubles."""
    a = -r if r < 0 else r
    j = (a + (1 << (_STEP - 1))) >> _STEP
    u = a - (j << _STEP)
    sj, cj = _TABLE[j]
    uf = u / _SCALE
    uf2 = uf * uf
    sin_u = u - int(uf * uf2 * (1 / 6 - uf2 * (1 / 120 - uf2 / 5040)) * _SCALE)
    cos_u = (1 << _FRAC) - ((u * u) >> (_FRAC + 1)) + int(
        uf2 * uf2 * (1 / 24 - uf2 * (1 / 720 - uf2 / 40320)) * _SCALE)
    s = (sj * cos_u + cj * sin_u) >> _FRAC
    c = (cj * cos_u - sj * sin_u) >> _FRAC
    return (-s if r < 0 else s), c


def _reduced(m: int, e: int) -> tuple[int, int]:
    """(k mod 4, r): ``m * 2**e`` is k times pi/2 plus ``r * 2**-_FRAC`` (|r| <= pi/4)."""
    width = _FRAC + max(0, e + 64) + 8
    half_pi = _HALF_PI >> (_PI_BITS - width)
    a = m << (e + width) if e + width >= 0 else m >> -(e + width)
    k = (2 * a + half_pi) // (2 * half_pi)
    return k % 4, (a - k * half_pi) >> (width - _FRAC)


def _to_double(v: int, shift: int) -> float:
    """``v * 2**shift`` rounded to a long double, then to a double."""
    if v == 0:
        return 0.0
    m, e = _round_bits(abs(v), shift, 64)
    d = m / (1 << -e) if e < 0 else float(m << e)  # int / int rounds once, subnormals included
    return d if v > 0 else -d


def _tiny(e: int) -> bool:
    """An angle (exponent ``e`` of its 64-bit mantissa) so small that its sine is itself and its
    cosine 1, to the long double."""
    return e + 64 < -70


def sin_degrees(x: float) -> float:
    """SIN of ``x`` degrees (finite, not zero).

    >>> sin_degrees(315.0)  # the double nearest -sqrt(2)/2 (in doubles: -0.7071067811865477)
    -0.7071067811865476
    >>> sin_degrees(180.0)
    -5.016557612668332e-20
    """
    m, e = _angle(abs(x))
    if _tiny(e):
        return _to_double(m if x > 0 else -m, e)
    k, r = _reduced(m, e)
    s, c = _sin_cos(r)
    v = s if k % 2 == 0 else c
    return _to_double(v if (k < 2) == (x > 0) else -v, -_FRAC)


def cos_degrees(x: float) -> float:
    """COS of ``x`` degrees (finite).

    >>> cos_degrees(90.0)
    -2.508278806334166e-20
    """
    m, e = _angle(abs(x)) if x else (0, 0)
    if _tiny(e):
        return 1.0
    k, r = _reduced(m, e)
    s, c = _sin_cos(r)
    v = c if k % 2 == 0 else s
    return _to_double(v if k in (0, 3) else -v, -_FRAC)


def tan_degrees(x: float) -> float:
    """TAN of ``x`` degrees (finite, not zero).

    >>> tan_degrees(45.0), tan_degrees(90.0)
    (1.0, -3.98679762981171e+19)
    """
    m, e = _angle(abs(x))
    if _tiny(e):
        return _to_double(m if x > 0 else -m, e)
    k, r = _reduced(m, e)
    s, c = _sin_cos(r)
    if k % 2:
        s, c = c, -s
    q = (abs(s) << _FRAC) // abs(c)
    return _to_double(q if ((s >= 0) == (c > 0)) == (x > 0) else -q, -_FRAC)
