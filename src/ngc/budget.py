"""The work budget of a run (``--max-iterations``): its default, for both dialects.

The LinuxCNC dialect counts loop iterations, subroutine calls and the loops inside codes against
it (:mod:`ngc.interp.flow`), the engine dialect its segments and drilling pecks
(:class:`ngc.engine.Engine`); past it a run ends with a "Work limit reached" error.
"""

DEFAULT_MAX_ITERATIONS = 10_000_000
