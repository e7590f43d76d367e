"""Numeric helpers that reproduce the C library's results to the last bit: SIN, COS and TAN of
degrees in long double (:mod:`.degrees`, :mod:`.longdouble`) and ``hypot`` (:mod:`.glibc_hypot`)."""
