"""The lathe cycles G70, G71/G71.1/G71.2 and G72/G72.1/G72.2 (g-code.adoc, "G70 Lathe finishing
cycle", "G71 G72 Lathe roughing cycles"), as rs274 2.9.0~pre1 runs them.

``profile`` holds the contour a cycle's subroutine describes, ``path`` the moves a cycle makes
(``Out``); the cycles are in ``roughing`` and ``finishing``; ``handlers/lathe.py`` records the
subroutine and runs them.
"""
