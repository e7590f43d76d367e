"""Reading the TOML files of ngc's own machine inputs (probe surfaces, the engine's setup sheet)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, TypeVar

from ..errors import NgcConfigError

T = TypeVar("T")


def read_toml(path: str, what: str, parse: Callable[[dict[str, Any]], T],
              errors: tuple[type[Exception], ...] = (ValueError,)) -> T:
    """``parse`` of the TOML file at ``path``; a file that cannot be read or parsed, or that
    ``parse`` rejects with one of ``errors``, is an :class:`NgcConfigError` naming ``what`` it is
    ("probe file") and why."""
    import tomllib  # here, not at start-up: only a run with such a file needs it

    try:
        with open(path, "rb") as handle:
            data = tomllib.load(handle)
    except OSError as exc:
        raise NgcConfigError(f"cannot open {what} {path}: {exc.strerror}", file=path) from None
    except tomllib.TOMLDecodeError as exc:
        raise NgcConfigError(f"{what} {path}: {exc}", file=path) from None
    try:
        return parse(data)
    except errors as exc:
        raise NgcConfigError(f"{what} {path}: {exc}", file=path) from None
