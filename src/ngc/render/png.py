"""SVG to PNG through resvg (the ``resvg-py`` wheel: a Rust renderer with no system libraries
and no browser), the optional ``ngc[png]`` extra."""

from __future__ import annotations

from ..errors import NgcConfigError

MISSING = ("PNG output needs the resvg renderer: pip install 'ngc[png]' "
           "(or write SVG: -o FILE.svg)")


def svg_to_png(svg_path: str, *, width: int | None = None, height: int | None = None,
               dpi: float = 0.0) -> bytes:
    """The SVG file ``svg_path`` rendered as PNG bytes, ``width`` x ``height`` pixels (None:
    the SVG's own size), at ``dpi`` (0: the SVG's 96)."""
    try:
        import resvg_py  # type: ignore[import-not-found,unused-ignore]
    except ImportError:
        raise NgcConfigError(MISSING) from None
    data: bytes = resvg_py.svg_to_bytes(svg_path=svg_path, width=width, height=height, dpi=dpi,
                                        background="white")
    return data
