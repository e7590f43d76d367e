"""The controllers ``ngc flatten`` writes for, each a table of what it accepts: a new controller
is a row, not a branch.

Each row says where its facts come from.
"""

from __future__ import annotations

from types import MappingProxyType
from typing import NamedTuple

# Grbl's modes at the start: no G80, under which Grbl rejects any axis word, G43.1's Z too
# (gcode.c: "Even non-modal commands or TLO that use axis words will throw this strict error")
GRBL_HEADER = "G90 G91.1 G94 G40 G49 G17"


class Target(NamedTuple):
    """What a controller takes."""

    name: str
    arc_planes: frozenset[str]  # G17 G18 G19 where it cuts arcs
    helix: bool  # an arc may move along its axis
    turns: bool  # an arc may turn more than once (P)
    tool_length: str  # "G43 H": the table's length by number; "none": folded into coordinates
    tool_change: bool  # M6 T
    feed_per_rev: bool  # G95
    blending: bool  # G64 P Q, G61, G61.1
    decimals_mm: int
    decimals_inch: int
    max_line: int  # significant characters of a line, spaces and comments left out (0: no limit)
    systems: int = 9  # work offsets G54 .. (6: to G59; G59.1-G59.3 refused)
    css: bool = True  # G96 / G97
    header: str = "G90 G91.1 G94 G40 G49 G80 G17 G97"  # the modes set at the start
    percent: bool = True  # a program ended by % is written between % lines (else: M2 at the end)
    io: bool = True  # M62-M65 digital outputs, M67/M68 analog outputs
    mist: bool = True  # M7
    sync: bool = True  # G33 and G33.1, spindle-synchronised motion (G76 is written as G33)
    orient: bool = True  # M19
    digits: int = 0  # significant digits a number may have (Grbl's reader keeps 8; 0: any)
    rotary: bool = True  # A B C axes (Grbl's default build has X Y Z only)
    spiral: bool = True  # an arc whose end is off its start's circle (LinuxCNC runs a spiral)
    raw_line: int = 0  # characters of a line, all counted (rs274: "Command too long" past 255)
    min_radius: float = 0.002  # mm: a smaller arc is refused (rs274: "Zero-radius arc" below
    # 0.00127 mm, 0.00005 in, in either units), so it is written as lines


TARGETS = MappingProxyType({
    "linuxcnc": Target("linuxcnc", frozenset({"G17", "G18", "G19"}), True, True, "G43 H", True,
                       True, True, 4, 5, 0, raw_line=255),
    # Grbl 1.1 (commands.md): no M6 (a tool change is a pause), G43.1 for a tool length (Z
    # only), no G61/G64, no G95, G54-G59 only, no G96/G97, 79 characters (error:11)
    "grbl": Target("grbl", frozenset({"G17", "G18", "G19"}), True, False, "G43.1", False, False,
                   False, 3, 4, 79, systems=6, css=False,
                   header=GRBL_HEADER, percent=False, io=False,
                   mist=False, sync=False, orient=False, digits=8,
                   rotary=False, spiral=False),
    # grblHAL (its core README's list of G-codes, leaving out what it marks as depending on the
    # driver or configuration: M6, G43, G95-G97, G33, G76, the outputs): Grbl's, with G59.1-G59.3,
    # M7, and arcs of several turns (P) from build 20220718
    "grblhal": Target("grblhal", frozenset({"G17", "G18", "G19"}), True, True, "G43.1", False,
                      False, False, 3, 4, 79, systems=9, css=False,
                      header=GRBL_HEADER, percent=False, io=False,
                      mist=True, sync=False, orient=False, digits=8,
                   rotary=False, spiral=False),
    # FluidNC: written to Grbl 1.1's documented commands, which it takes as Grbl does (what it
    # adds depends on the machine's configuration)
    "fluidnc": Target("fluidnc", frozenset({"G17", "G18", "G19"}), True, False, "G43.1", False,
                      False, False, 3, 4, 79, systems=6, css=False,
                      header=GRBL_HEADER, percent=False, io=False,
                      mist=False, sync=False, orient=False, digits=8,
                   rotary=False, spiral=False),
})
