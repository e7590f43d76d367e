"""Numbers as Grbl computes them on its AVR: in IEEE single precision (``float`` and ``double``
are both 32 bits there), read by its own ``read_float``, and turned into small unsigned
integers by C's conversions.

Python's floats are doubles: every result here is rounded to single precision where Grbl's
would be (:func:`f32` after each operation; a double holds a single-precision sum, product,
quotient or square root exactly enough that rounding it once gives the single-precision result).
"""

from __future__ import annotations

import math
import struct

_SINGLE = struct.Struct("<f")


def f32(x: float) -> float:
    """``x`` rounded to single precision; infinite past its range.

    >>> f32(0.1), f32(1e39), f32(-1e39)
    (0.10000000149011612, inf, -inf)
    """
    try:
        return float(_SINGLE.unpack(_SINGLE.pack(x))[0])
    except OverflowError:
        return math.copysign(math.inf, x)


MM_PER_INCH = f32(25.4)  # nuts_bolts.h MM_PER_INCH (25.40), a float on the AVR
HUNDREDTH = f32(0.01)  # read_float's 0.01f and 0.1f
TENTH = f32(0.1)
MAX_INT_DIGITS = 8  # read_float keeps the first 8 digits of a number and drops the rest
SINGLE_INTEGERS = 1 << 24  # the integers below this are exact in single precision


def read_value(sign: str, whole: str, fraction: str, digits: int = MAX_INT_DIGITS,
               leading_zeros: bool = True) -> float:
    """The value Grbl's ``read_float`` gives for ``sign whole.fraction`` (at least one digit):
    the first 8 digits as an integer, made a float, then scaled by 0.01f, 0.1f or 10.0f a step
    at a time, each step rounded; digits after the 8th count only as a power of ten before the
    point and not at all after it (``0.000000012`` is 0).

    >>> read_value("", "12", "5"), read_value("-", "", "25"), read_value("", "0000000012", "")
    (12.5, -0.25, 0.0)
    >>> read_value("", "123456789", "")  # 12345678 (rounded to single) times ten
    123456784.0

    ``digits`` other than 8 and ``leading_zeros`` false are grblHAL's ``read_float`` (9 digits,
    not counting the zeros before the first other digit).

    >>> read_value("", "0", "000000012", 9, False), read_value("", "123456789", "", 9, False)
    (1.2000000104706032e-08, 123456792.0)
    """
    if digits != MAX_INT_DIGITS or not leading_zeros:
        integer, exponent = _significant(whole, fraction, digits, leading_zeros)
    elif len(whole) >= MAX_INT_DIGITS:
        integer, exponent = int(whole[:MAX_INT_DIGITS]), len(whole) - MAX_INT_DIGITS
    else:
        kept = (whole + fraction)[:MAX_INT_DIGITS]
        integer, exponent = int(kept), len(whole) - len(kept)
    value = float(integer) if integer < SINGLE_INTEGERS else f32(float(integer))
    if exponent < 0 and integer:
        pack, unpack = _SINGLE.pack, _SINGLE.unpack  # (no overflow going down: f32 inlined)
        while exponent <= -2:
            value = unpack(pack(value * HUNDREDTH))[0]
            exponent += 2
        if exponent:
            value = unpack(pack(value * TENTH))[0]
    elif integer:
        for _ in range(exponent):
            value = f32(value * 10.0)
    return -value if sign == "-" else value


def _significant(whole: str, fraction: str, digits: int, leading_zeros: bool) -> tuple[int, int]:
    """``read_float``'s integer and power of ten, a digit at a time: a digit counts unless it is
    a leading zero and ``leading_zeros`` is false; past ``digits`` counted, a digit before the
    point adds a power of ten and one after it nothing."""
    integer = exponent = counted = 0
    for decimal, text in ((False, whole), (True, fraction)):
        for char in text:
            digit = ord(char) - 48
            if leading_zeros or digit or integer:
                counted += 1
            if counted <= digits:
                exponent -= decimal
                integer = integer * 10 + digit
            elif not decimal:
                exponent += 1
    return integer, exponent


def c_unsigned(value: float, bits: int) -> int:
    """C's conversion of a float to an unsigned integer of ``bits`` bits as avr-gcc makes it:
    truncated toward zero to a 32-bit integer, of which the low bits are kept (so ``G-1`` is
    ``G255``).  Past a 32-bit integer the conversion is undefined in C; it is taken as all bits
    set, which no code or word of Grbl's accepts.

    >>> c_unsigned(38.2, 8), c_unsigned(-1.0, 8), c_unsigned(256.0, 8), c_unsigned(1e10, 8)
    (38, 255, 0, 255)
    """
    if not abs(value) < 2.0**31:  # (NaN too)
        return (1 << bits) - 1
    return int(value) & ((1 << bits) - 1)


def c_round(value: float) -> float:
    """C's ``round``: halves away from zero (Python's rounds them to even).

    >>> c_round(2.5), c_round(-2.5), c_round(0.49999997)
    (3.0, -3.0, 0.0)
    """
    if not math.isfinite(value):
        return value
    return math.copysign(math.floor(abs(value) + 0.5), value)


def arm_unsigned(value: float) -> int:
    """A float converted to a 32-bit unsigned integer as an ARM does it (``vcvt.u32.f32``):
    truncated toward zero, saturating (a negative value or NaN is 0, past the range all bits
    set).

    >>> arm_unsigned(38.7), arm_unsigned(-1.0), arm_unsigned(1e10)
    (38, 0, 4294967295)
    """
    if not value > 0.0:
        return 0
    return min(int(value), (1 << 32) - 1)


def whole_and_hundredths(value: float, bits: int = 8) -> tuple[int, int]:
    """A G or M word's value as Grbl's parser splits it: the whole number (an 8-bit unsigned
    integer) and the hundredths left over (``round(100 * (value - whole))``, a 16-bit unsigned
    integer; not 0 for any value that is not whole).

    >>> whole_and_hundredths(f32(38.2)), whole_and_hundredths(f32(91.1)), whole_and_hundredths(2.0)
    ((38, 20), (91, 10), (2, 0))
    >>> whole_and_hundredths(-0.5)  # -50 as a 16-bit unsigned integer
    (0, 65486)

    With ``bits`` 32, grblHAL's ``uint32_t`` and ``uint_fast16_t`` (32 bits on an ARM), both
    converted saturating: ``G-0.5`` is G0.

    >>> whole_and_hundredths(-0.5, 32), whole_and_hundredths(f32(59.1), 32)
    ((0, 0), (59, 10))
    """
    if bits == 32:
        whole = arm_unsigned(value)
        return whole, arm_unsigned(c_round(f32(100.0 * f32(value - f32(float(whole))))))
    whole = c_unsigned(value, 8)
    return whole, c_unsigned(c_round(f32(100.0 * f32(value - whole))), 16)


def add(a: float, b: float) -> float:
    """``a + b`` in single precision (exact with a zero: no rounding to do).

    >>> add(0.1, 0.2), add(f32(0.1), 0.0) == f32(0.1)
    (0.30000001192092896, True)
    """
    if a == 0.0 or b == 0.0:
        return a + b
    return f32(a + b)


def hypot(x: float, y: float) -> float:
    """Grbl's ``hypot_f``: ``sqrtf(x*x + y*y)``, each step in single precision.

    >>> hypot(3.0, 4.0)
    5.0
    """
    return f32(math.sqrt(f32(f32(x * x) + f32(y * y))))
