"""The build of a Grbl-family controller, as a row: what its parser is compiled with.

Grbl 1.1h's default build (``config.h``, ``gcode.c``, ``protocol.h``) is :data:`GRBL`.  The
checker reads only these fields, so a controller that follows Grbl's parser with other limits
is another row of :data:`DIALECTS`.
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType
from typing import NamedTuple


class Rules(NamedTuple):
    """What a build of Grbl accepts.

    ``line_chars``: the most characters a line may keep once spaces and comments are dropped
    (``LINE_BUFFER_SIZE`` - 1; one more is error 11).  ``axes``: the axis letters, in Grbl's
    order (``N_AXIS``).  ``mist_coolant``: M7 is accepted (``ENABLE_M7``).  ``max_tool``: the
    largest T (``MAX_TOOL_NUMBER``; more is error 38).  ``max_line_number``: the largest N
    (``MAX_LINE_NUMBER``; more is error 27).  ``coordinate_systems``: G54 onwards, the number of
    them (``N_COORDINATE_SYSTEM``; a G10 P past it is error 29).  ``tool_length_axis``: the axis
    G43.1 takes its offset on (``TOOL_LENGTH_OFFSET_AXIS``).  ``probe_to_start``: in check mode
    a probe move leaves the position where it was (``SET_CHECK_MODE_PROBE_TO_START``) rather
    than at its target.
    """

    name: str
    line_chars: int = 79
    axes: str = "XYZ"
    mist_coolant: bool = False
    max_tool: int = 255
    max_line_number: int = 10_000_000
    coordinate_systems: int = 6
    tool_length_axis: str = "Z"
    probe_to_start: bool = False


GRBL = Rules("Grbl 1.1")

# the rules by the name ``ngc check --dialect`` takes
DIALECTS: Mapping[str, Rules] = MappingProxyType({"grbl": GRBL})
