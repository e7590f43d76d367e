"""Expression values: constants and compiled closures, LinuxCNC's operators and functions.

A value read from a line is either a ``float`` (a constant, folded at read time) or an ``Expr``: a
closure taking the parameter context and returning a float.  Closures are built once when the line is
parsed and run each time the block executes.  Semantics follow overview.adoc "Expressions",
"Binary Operators" and "Functions", as rs274 evaluates them: angles in degrees, all operators
left-associative within their precedence group, comparisons equal within ``TOLERANCE_EQUAL``.
"""

from __future__ import annotations

import math
import operator
from collections.abc import Callable
from typing import Protocol

from ..errors import NgcRuntimeError
from ..numeric import degrees


class ParamContext(Protocol):
    """What an expression reads: parameters by number or name."""

    def num(self, index: int) -> float: ...

    def named(self, name: str) -> float: ...

    def local(self, name: str) -> float:
        """``named(name)`` for a name of the current scope (one not starting with ``_``)."""
        ...

    def exists(self, name: str) -> bool: ...

    def index(self, value: float) -> int: ...


Expr = Callable[[ParamContext], float]
Value = float | Expr

# rs274 treats two values as equal when they differ by less than this (EQ, NE, and friends).
TOLERANCE_EQUAL = 0.0001

# Precedence groups (overview.adoc, "Operators Precedence"); higher binds tighter.
PRECEDENCE: dict[str, int] = {
    "**": 4,
    "*": 3,
    "/": 3,
    "mod": 3,
    "+": 2,
    "-": 2,
    "eq": 1,
    "ne": 1,
    "gt": 1,
    "ge": 1,
    "lt": 1,
    "le": 1,
    "and": 0,
    "or": 0,
    "xor": 0,
}


def _div(a: float, b: float) -> float:
    if b == 0.0:
        raise NgcRuntimeError("Attempt to divide by zero")
    return a / b


def _mod(a: float, b: float) -> float:
    if b == 0.0 or a - a != 0.0:
        return math.nan  # C's fmod: the bracket that holds it is checked
    r = math.fmod(a, b)
    if r < 0.0:
        r += abs(b)
    return r


def _pow(a: float, b: float) -> float:
    """C's pow: an overflow or a pole is infinite (the bracket that holds it is checked)."""
    whole = math.floor(b) == b if b - b == 0.0 else b == b  # an infinite exponent counts as whole
    if a < 0.0 and not whole:
        raise NgcRuntimeError("Attempt to raise negative to non integer power")
    try:
        return math.pow(a, b)
    except (ValueError, OverflowError):
        odd = a < 0.0 and b - b == 0.0 and b % 2.0 == 1.0
        return -math.inf if odd else math.inf


# rs274 stops the program when a value it reads is infinite or not a number.
INFINITY = "Calculation resulted in 'infinity'"
NOT_A_NUMBER = "Calculation resulted in 'not a number'"
# rs274 converts to a C int: out of range (or NaN), the result is INT_MIN.
INT_MIN = -2147483648


def nonfinite(value: float) -> NgcRuntimeError:
    """rs274's error for a value that is infinite or NaN."""
    return NgcRuntimeError(NOT_A_NUMBER if value != value else INFINITY)


def finite(value: float) -> float:
    """``value`` if it is a finite number, else rs274's error.

    rs274 checks each value it reads as an operand: a number, a parameter's value, a bracketed
    expression, a function's result.  The operators inside a bracket are not checked
    (``[10**400 GT 0]`` is 1), nor is a function's bracketed argument (``SIN[EXP[709]*10]`` fails
    on SIN's NaN, not on the infinite argument), nor an o-word's bracket (``o1 repeat [10**400]``).

    >>> finite(1.5)
    1.5
    >>> finite(float("inf"))
    Traceback (most recent call last):
    ngc.errors.NgcRuntimeError: Calculation resulted in 'infinity'
    """
    if value - value == 0.0:
        return value
    raise nonfinite(value)


def c_int(value: float) -> int:
    """C's conversion of a rounded double to a 32-bit int: INT_MIN when out of range or NaN.

    >>> c_int(2.0), c_int(2147483648.0), c_int(float("nan"))
    (2, -2147483648, -2147483648)
    """
    if -2147483648.0 <= value < 2147483648.0:
        return int(value)
    return INT_MIN


def _bool(x: bool) -> float:
    return 1.0 if x else 0.0


BINARY: dict[str, Callable[[float, float], float]] = {
    "**": _pow,
    "*": operator.mul,
    "/": _div,
    "mod": _mod,
    "+": operator.add,
    "-": operator.sub,
    "eq": lambda a, b: _bool(abs(a - b) < TOLERANCE_EQUAL),
    "ne": lambda a, b: _bool(abs(a - b) >= TOLERANCE_EQUAL),
    "gt": lambda a, b: _bool(a > b),
    "ge": lambda a, b: _bool(a >= b),
    "lt": lambda a, b: _bool(a < b),
    "le": lambda a, b: _bool(a <= b),
    "and": lambda a, b: _bool(a != 0.0 and b != 0.0),
    "or": lambda a, b: _bool(a != 0.0 or b != 0.0),
    "xor": lambda a, b: _bool((a != 0.0) != (b != 0.0)),
}


def _acos(x: float) -> float:
    if x < -1.0 or x > 1.0:
        raise NgcRuntimeError("Argument to acos out of range")
    return math.degrees(math.acos(x))


def _asin(x: float) -> float:
    if x < -1.0 or x > 1.0:
        raise NgcRuntimeError("Argument to asin out of range")
    return math.degrees(math.asin(x))


def _ln(x: float) -> float:
    if x <= 0.0:
        raise NgcRuntimeError("Zero or negative argument to ln")
    return math.log(x)


def _sqrt(x: float) -> float:
    if x < 0.0:
        raise NgcRuntimeError("Negative argument to sqrt")
    return math.sqrt(x)


def _exp(x: float) -> float:
    try:
        return math.exp(x)
    except OverflowError:
        return math.inf


def _signed(r: float, x: float) -> float:
    """C's rounding functions keep the sign of a zero result (FUP[-0.5] is -0)."""
    return math.copysign(r, x) if r == 0.0 else r


def _fix(x: float) -> float:
    if x - x != 0.0:
        return x  # floor of an infinity or NaN is itself
    return _signed(float(math.floor(x)), x)


def _fup(x: float) -> float:
    if x - x != 0.0:
        return x
    return _signed(float(math.ceil(x)), x)


def _round(x: float) -> float:
    """Halves away from zero; a result of zero is +0 (rs274: ROUND[-0.11] is 0, not -0).

    rs274 goes through a C int: a result of 2**31 or more in size, or NaN, is INT_MIN.
    """
    a = abs(x) + 0.5
    if not a < 2147483648.0:
        return float(INT_MIN)
    return float(math.floor(a)) * (1.0 if x >= 0 else -1.0) + 0.0


# rs274 computes SIN, COS and TAN in x87 long double (see ngc/degrees.py); a zero angle keeps its
# sign (SIN[-0] and TAN[-0] are -0), a NaN or infinite one gives NaN.
def _trig(sin_: Callable[[float], float], cos_: Callable[[float], float],
          tan_: Callable[[float], float]) -> dict[str, Callable[[float], float]]:
    """SIN, COS and TAN from functions of degrees that are finite and not zero."""

    def sin(x: float) -> float:
        if x - x != 0.0:
            return math.nan
        return x if x == 0.0 else sin_(x)

    def cos(x: float) -> float:
        if x - x != 0.0:
            return math.nan
        return cos_(x) if x else 1.0

    def tan(x: float) -> float:
        if x - x != 0.0:
            return math.nan
        return x if x == 0.0 else tan_(x)

    return {"sin": sin, "cos": cos, "tan": tan}


_DEGREE_TRIG = _trig(degrees.sin_degrees, degrees.cos_degrees, degrees.tan_degrees)


def trig_functions() -> dict[str, Callable[[float], float]]:
    """SIN, COS and TAN as :data:`UNARY` has them, keeping the last angle's reduction
    (:class:`ngc.numeric.degrees.Trig`): the parser gives the functions of one line one such set, so that
    ``X[R * COS[A]] Y[R * SIN[A]]`` reduces A once."""
    trig = degrees.Trig()
    return _trig(trig.sin, trig.cos, trig.tan)


UNARY: dict[str, Callable[[float], float]] = {
    "abs": lambda x: -x if x < 0 else x,  # as rs274: ABS[-0] is -0
    "acos": _acos,
    "asin": _asin,
    "cos": _DEGREE_TRIG["cos"],
    "exp": _exp,
    "fix": _fix,
    "fup": _fup,
    "round": _round,
    "ln": _ln,
    "sin": _DEGREE_TRIG["sin"],
    "sqrt": _sqrt,
    "tan": _DEGREE_TRIG["tan"],
}


def atan2_degrees(y: float, x: float) -> float:
    """ATAN[y]/[x]: four-quadrant inverse tangent in degrees."""
    return finite(math.degrees(math.atan2(y, x)))




def as_expr(value: Value) -> Expr:
    """Wrap a constant as a closure (operands of a non-constant expression)."""
    if isinstance(value, float):
        v = value
        return lambda _p: v
    return value


def fold_binary(op: str, left: Value, right: Value, check: bool = False) -> Value:
    """Combine two operands; constant operands are folded now unless folding raises.  ``check``:
    the result is a value rs274 checks (a bracket's), see :func:`finite`."""
    return fold_binary_fn(BINARY[op], left, right, check)


def fold_binary_fn(fn: Callable[[float, float], float], left: Value, right: Value,
                   check: bool = False) -> Value:
    """Combine two operands with ``fn``, folding constants unless that raises."""
    if isinstance(left, float) and isinstance(right, float):
        try:
            v = fn(left, right)
            return finite(v) if check else v
        except NgcRuntimeError:
            x, y = left, right
            return (lambda p: finite(fn(x, y))) if check else (lambda p: fn(x, y))
    if not check:
        if isinstance(right, float):
            a, r = left, right
            return lambda p: fn(a(p), r)  # type: ignore[operator]
        if isinstance(left, float):
            lv, b = left, right
            return lambda p: fn(lv, b(p))
        a = left
        b = right
        return lambda p: fn(a(p), b(p))
    # The same, with the check inline (one call less per evaluation than a wrapper).
    if isinstance(right, float):
        ca, cr = left, right

        def right_constant(p: ParamContext) -> float:
            v = fn(ca(p), cr)  # type: ignore[operator]
            if v - v == 0.0:
                return v
            raise nonfinite(v)

        return right_constant
    if isinstance(left, float):
        cl, cb = left, right

        def left_constant(p: ParamContext) -> float:
            v = fn(cl, cb(p))
            if v - v == 0.0:
                return v
            raise nonfinite(v)

        return left_constant
    fa, fb = left, right

    def both(p: ParamContext) -> float:
        v = fn(fa(p), fb(p))
        if v - v == 0.0:
            return v
        raise nonfinite(v)

    return both


def fold_unary(fn: Callable[[float], float], arg: Value, check: bool = False) -> Value:
    """Apply a function; a constant argument is folded now unless folding raises.  ``check``:
    the result is a value rs274 checks (a function's), see :func:`finite`."""
    if isinstance(arg, float):
        try:
            v = fn(arg)
            return finite(v) if check else v
        except NgcRuntimeError:
            pass
    a = as_expr(arg)
    if not check:
        return lambda p: fn(a(p))

    def run(p: ParamContext) -> float:
        v = fn(a(p))
        if v - v == 0.0:
            return v
        raise nonfinite(v)

    return run


def evaluate(value: Value, params: ParamContext) -> float:
    """The number a value stands for now."""
    if isinstance(value, float):
        return value
    return value(params)
