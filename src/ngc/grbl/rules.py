"""The build of a Grbl-family controller, as a row: what its parser is compiled with.

Grbl 1.1h's default build (``config.h``, ``gcode.c``, ``protocol.h``) is :data:`GRBL`;
grblHAL's default build (grblHAL/core ``config.h``, ``gcode.c``, ``protocol.c``,
``nuts_bolts.c`` at commit 04ce2c5c) is :data:`GRBLHAL`.  The checker reads only these fields,
so a controller that follows Grbl's parser with other limits is another row of
:data:`DIALECTS`.

FluidNC has no row: its parser (bdring/FluidNC ``GCode.cpp``, ``gc_execute_line``) reads a
line differently from Grbl's (no axis-command conflict on G0-G3: ``G0 G1`` is error 21, not
24; ``#`` parameter assignments and O-word flow control), and what it accepts of M4, M7, M8
and G38 follows the machine's YAML configuration (a reversible spindle, coolant pins, a probe
pin), of which there is no default to check against.
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType
from typing import NamedTuple


class Rules(NamedTuple):
    """What a build of Grbl accepts.

    ``line_chars``: the most characters a line may keep (``LINE_BUFFER_SIZE`` - 1; one more is
    error 11), counted as ``reader`` keeps them.  ``axes``: the axis letters, in Grbl's order
    (``N_AXIS``).  ``mist_coolant``: M7 is accepted (``ENABLE_M7``).  ``max_tool``: the largest
    T (``MAX_TOOL_NUMBER``; more is error 38).  ``max_line_number``: the largest N
    (``MAX_LINE_NUMBER``; more is error 27).  ``coordinate_systems``: G54 onwards, the number of
    them (``N_COORDINATE_SYSTEM``; a G10 P past it is error 29).  ``tool_length_axis``: the axis
    G43.1 takes its offset on (``TOOL_LENGTH_OFFSET_AXIS``; "" for any axis, each its own
    offset).  ``probe_to_start``: in check mode a probe move leaves the position where it was
    (``SET_CHECK_MODE_PROBE_TO_START``) rather than at its target.

    The parser's own ways (Grbl 1.1h's unless said): ``parser``, its table of codes
    (:func:`ngc.grbl.codes.code_table`); ``reader``, how the line is read before the parser
    (:mod:`ngc.grbl.lines`); ``digits``, the digits ``read_float`` keeps (``MAX_INT_DIGITS``)
    and ``leading_zeros``, whether leading zeros count among them; ``code_bits``, the width of
    the whole number of a G or M word (8: ``uint8_t``; 32: ``uint32_t``, converted as an ARM
    does, saturating); ``not_negative``, the value words a negative value is error 4 for;
    ``whole_words``, those a fraction is error 23 for; ``extra_words``, value words read beyond
    Grbl's (used only by codes no row checks: a block with one is not checked);
    ``arc_turns``, P on G2/G3 is the number of turns; ``g80_non_modal_axes``, G10 G28 G30 G92
    take axis words under G80; ``g10_hal_order``, G10 is checked as grblHAL checks it (26 only
    without axis words and without R, unless L20; a negative P 4; the L before the P: 20
    before 29); ``error_latch``, after an error each G-code line is answered with it, unrun,
    until an empty line (grblHAL's ``COMPATIBILITY_LEVEL`` 0).
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
    parser: str = "grbl"
    reader: str = "grbl"
    digits: int = 8
    leading_zeros: bool = True
    code_bits: int = 8
    not_negative: str = "FNPST"
    whole_words: str = ""
    extra_words: str = ""
    arc_turns: bool = False
    g80_non_modal_axes: bool = False
    g10_hal_order: bool = False
    error_latch: bool = False


GRBL = Rules("Grbl 1.1")

# grblHAL's default build, facts from grblHAL/core (gcode.c, protocol.c and nuts_bolts.c at
# commit 04ce2c5c, config.h, nuts_bolts.h, errors.h):
GRBLHAL = Rules(
    "grblHAL",
    # protocol.h: LINE_BUFFER_SIZE 257, "256 characters plus terminator"; protocol.c counts a
    # line's characters with its comments and spaces (only control characters and leading
    # blanks are dropped before the count)
    line_chars=256, reader="grblhal",
    # M7 is refused only by a driver without mist control (hal.driver_cap.mist_control)
    mist_coolant=True,
    # gcode.c: MAX_TOOL_NUMBER 4294967294 when N_TOOLS is 0 (config.h's default)
    max_tool=4_294_967_294,
    # config.h: N_WorkCoordinateSystems 9 (G59.1-G59.3, G10 P1-P9)
    coordinate_systems=9,
    # config.h: "TOOL_LENGTH_OFFSET_AXIS -1 // Default is all axes."
    tool_length_axis="",
    parser="grblhal",
    # nuts_bolts.h: MAX_INT_DIGITS 9; read_float counts a digit "if(c != 0 || intval)"
    digits=9, leading_zeros=False,
    # gcode.c: "int_value = (uint32_t)truncf(value)"
    code_bits=32,
    # gcode.c positive_only_words: D F H N O T S (not P); H L O T $ "if (mantissa > 0)" 23
    not_negative="DFHNOST", whole_words="HLOT$", extra_words="DEHOQ$",
    # gcode.c, G2/G3: "if (gc_block.words.p) { // Number of turns"
    arc_turns=True,
    # gcode.c, [20. Motion modes]: "if (axis_words.mask && axis_command != AxisCommand_NonModal)"
    g80_non_modal_axes=True,
    # gcode.c, G10: "if (!(axis_words.mask || (gc_block.values.l != 20 && gc_block.words.r)))",
    # then P or L (28), "if(gc_block.values.p < 0.0f)" (4), then "switch(gc_block.values.l)":
    # an L but 2 and 20 is 20 (the default case), R with L2 is 20, then P past 9 is 29
    g10_hal_order=True,
    # protocol.c: "else if(gc_state.last_error == Status_OK || ...) gc_execute_block(line)"
    # under "#if COMPATIBILITY_LEVEL == 0" (config.h's default); an empty line sets it OK
    error_latch=True,
)

# the rules by the name ``ngc check --dialect`` takes
DIALECTS: Mapping[str, Rules] = MappingProxyType({"grbl": GRBL, "grblhal": GRBLHAL})
