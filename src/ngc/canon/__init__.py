"""Canonical machine operations (the canon seam) and the sinks that consume them."""

from .ops import Op, Sink

__all__ = ["Op", "Sink"]
