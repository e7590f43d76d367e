"""A machine's linear units, from its INI file's ``[TRAJ]LINEAR_UNITS`` (ini-config.adoc, [TRAJ]
Section: "mm or inch").  Besides the names, a number is read as machine units per millimetre, the
form of older configurations: 1.0 is mm, 0.03937 (1/25.4, written with as many digits as one
likes) is inch.

A LinuxCNC machine reads its tool table and the offsets of its parameter file in these units
(rs274ngc.adoc, "Tool table lengths/diameters are in INI file units"; "Offset parameters are INI
file units"); the planner's limits are in them too.
"""

from __future__ import annotations

import math
from types import MappingProxyType

from ..errors import NgcConfigError
from .ini import BLANKS, Ini, parse_real

UNIT_NAMES = MappingProxyType(
    {"mm": "mm", "metric": "mm", "inch": "inch", "in": "inch", "imperial": "inch"})
UNITS_PER_MM = MappingProxyType({"mm": 1.0, "inch": 1.0 / 25.4})
UNITS_PER_MM_TOLERANCE = 1e-4  # relative: 0.03937 and 0.0393700787 are both inch
UNITS_EXPECTED = ("mm, inch (or in, metric, imperial) or the machine units per mm "
                  "(1.0 for mm, 0.03937 for inch)")


def read_linear_units(text: str) -> str | None:
    """``mm`` or ``inch`` for a LINEAR_UNITS value, None for one that is neither."""
    name = UNIT_NAMES.get(text.strip(BLANKS).lower())
    if name is not None:
        return name
    per_mm = parse_real(text)
    for unit, expected in UNITS_PER_MM.items():
        if per_mm is not None and math.isclose(per_mm, expected, rel_tol=UNITS_PER_MM_TOLERANCE):
            return unit
    return None


def linear_units(ini: Ini) -> str:
    """The machine's linear units, ``mm`` or ``inch`` (mm without [TRAJ]LINEAR_UNITS, the
    planner's default machine); raises :class:`NgcConfigError` for a value that is neither."""
    return stated_linear_units(ini) or "mm"


def stated_linear_units(ini: Ini) -> str | None:
    """The linear units [TRAJ]LINEAR_UNITS states, ``mm`` or ``inch``, or None when it is not
    set; raises :class:`NgcConfigError` for a value that is neither."""
    text = ini.get("TRAJ", "LINEAR_UNITS")
    if text is None:
        return None
    value = read_linear_units(text)
    if value is None:
        where = f"INI file {ini.path}" if ini.path else "INI file"
        raise NgcConfigError(f"{where}: [TRAJ]LINEAR_UNITS is '{text}', not {UNITS_EXPECTED}",
                             file=ini.path)
    return value
