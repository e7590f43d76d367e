"""Reading the TOML files of ngc's own machine inputs (the machine file, probe surfaces, the
engine's setup sheet).

Whatever a file holds, reading it ends in the value ``parse`` makes of it or in an
:class:`NgcConfigError` naming the file and the problem: bytes that are not UTF-8, TOML syntax,
arrays or tables nested too deeply for the reader, an integer outside TOML's 64 bits.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, TypeVar

from ..errors import NgcConfigError

T = TypeVar("T")

# TOML 1.0, Integer: "Arbitrary 64-bit signed integers (from -2^63 to 2^63-1) should be accepted
# and handled losslessly. If an integer cannot be represented losslessly, an error must be thrown."
INT64_MIN, INT64_MAX = -(2**63), 2**63 - 1


def read_toml(path: str, what: str, parse: Callable[[dict[str, Any]], T],
              errors: tuple[type[Exception], ...] = (ValueError,)) -> T:
    """``parse`` of the TOML file at ``path``; a file that cannot be read or parsed, or that
    ``parse`` rejects with one of ``errors``, is an :class:`NgcConfigError` naming ``what`` it is
    ("probe file") and why."""
    try:
        with open(path, "rb") as handle:
            raw = handle.read()
    except OSError as exc:
        raise NgcConfigError(f"cannot open {what} {path}: {exc.strerror}", file=path) from None
    data = _load(raw, path, what)
    try:
        return parse(data)
    except errors as exc:
        raise NgcConfigError(f"{what} {path}: {exc}", file=path) from None


def _load(raw: bytes, path: str, what: str) -> dict[str, Any]:
    """The TOML document in ``raw``, its integers checked."""
    import tomllib  # here, not at start-up: only a run with such a file needs it

    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise NgcConfigError(f"{what} {path}: not UTF-8 text: byte 0x{raw[exc.start]:02x} at "
                             f"offset {exc.start}", file=path) from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise NgcConfigError(f"{what} {path}: {exc}", file=path) from None
    except RecursionError:
        raise NgcConfigError(f"{what} {path}: arrays or tables nested too deeply",
                             file=path) from None
    except ValueError:  # an integer of more digits than Python converts (4300)
        raise NgcConfigError(f"{what} {path}: an integer of thousands of digits, outside TOML's "
                             f"64-bit range ({INT64_MIN} to {INT64_MAX})", file=path) from None
    _check_integers(data, path, what)
    return data


def _check_integers(data: dict[str, Any], path: str, what: str) -> None:
    """Every integer of ``data`` within 64 bits (walked without recursion: the document may be
    as deep as the TOML reader goes)."""
    stack: list[Any] = [data]
    while stack:
        item = stack.pop()
        if isinstance(item, dict):
            stack.extend(item.values())
        elif isinstance(item, list):
            stack.extend(item)
        elif isinstance(item, int) and not INT64_MIN <= item <= INT64_MAX:
            raise NgcConfigError(f"{what} {path}: an integer outside TOML's 64-bit range "
                                 f"({INT64_MIN} to {INT64_MAX})", file=path)
