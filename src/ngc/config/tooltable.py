"""Tool table files in LinuxCNC's format (tool-compensation.adoc, "Tool Table Format").

One tool a line, words in any order: ``T`` tool number, ``P`` pocket, ``X Y Z A B C U V W``
offsets, ``D`` diameter, ``I`` front angle, ``J`` back angle, ``Q`` orientation, then an optional
``;comment``.  Letters may be lower case.  Values are in inches (the standalone machine's units)
and are kept as written: a program sees them converted to its units.

:func:`parse_tool_table` gives a :class:`ToolTable`, a value: its entries in file order (the
1-based *index* rs274 prints in ``CHANGE_TOOL``) and the lines it skipped, as rs274 skips them
(a word with another letter, a value that is no number): rs274 reports each on stdout and goes on.
:data:`DEFAULT_TABLE` is the table rs274 reads when it is given none.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from typing import NamedTuple

from ..errors import NgcConfigError

OFFSET_LETTERS = "xyzabcuvw"
_NUMBER = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?")


# Tool lengths reach a program through millimetres: rs274 divides a table value (inches) by this
# inch-per-mm factor, a little off 1/25.4, then by 25.4 for a program in inches; a length a
# program sets (G10 L1/L10/L11) goes back the other way.  #5400-#5413 read the table's value.
INCH_PER_MM = 0.03937007874016
MM_PER_INCH = 25.4


def length_to_program(value: float, metric: bool) -> float:
    """A tool table length (inches) in program units, as G43 and G41/G42 D use it."""
    mm = value / INCH_PER_MM
    return mm if metric else mm / MM_PER_INCH


def length_from_program(value: float, metric: bool) -> float:
    """A length in program units (G10 L1 R, Z...) as the tool table keeps it (inches)."""
    mm = value if metric else value * MM_PER_INCH
    return mm * INCH_PER_MM


class ToolEntry(NamedTuple):
    """One tool: offsets X Y Z A B C U V W, diameter and lengths in inches, angles in degrees."""

    number: int
    pocket: int
    offsets: tuple[float, ...] = (0.0,) * 9
    diameter: float = 0.0
    frontangle: float = 0.0
    backangle: float = 0.0
    orientation: int = 0
    comment: str = ""


_ROTARY = frozenset((3, 4, 5))  # A B C in the offsets X Y Z A B C U V W: degrees


def scaled_entry(entry: ToolEntry, factor: float) -> ToolEntry:
    """A tool with its lengths and diameter times ``factor`` (inches to mm: 25.4); angles and
    rotary offsets (A B C) are kept."""
    offsets = tuple(v if i in _ROTARY else v * factor for i, v in enumerate(entry.offsets))
    return entry._replace(offsets=offsets, diameter=entry.diameter * factor)

# The slot of a line that starts with a tool number and is skipped: no tool is found there.
UNREAD = ToolEntry(-1, -1)
# The spindle's entry when no tool was ever loaded.
EMPTY_SPINDLE = ToolEntry(0, -1)


class ToolTable(NamedTuple):
    """A tool table as read: entries in file order, the lines skipped, and the entry of a line
    without a P word (the tool in the spindle)."""

    entries: tuple[ToolEntry, ...] = ()
    skipped: tuple[str, ...] = ()
    spindle: ToolEntry | None = None

    def find(self, number: int) -> ToolEntry | None:
        """The first entry of tool ``number`` (the spindle's last), or None."""
        spindle: tuple[ToolEntry, ...] = () if self.spindle is None else (self.spindle,)
        for entry in (*self.entries, *spindle):
            if entry.number == number and number >= 0:
                return entry
        return None

    def scaled(self, factor: float) -> ToolTable:
        """The table with its lengths and diameters times ``factor`` (a table in mm read into
        the interpreter's inches: ``1 / 25.4``); angles and rotary offsets (A B C) are kept."""
        if factor == 1.0:
            return self
        spindle = None if self.spindle is None else scaled_entry(self.spindle, factor)
        return self._replace(entries=tuple(scaled_entry(e, factor) if e is not UNREAD else e
                                           for e in self.entries), spindle=spindle)

    def skipped_report(self, name: str) -> str:
        """What rs274 prints on stdout for the skipped lines of file ``name``."""
        return "".join(f"File: {name} Unrecognized line skipped:\n    {line}\n" for line in self.skipped)


def _number(text: str) -> float | None:
    """The number a word's value starts with (C's strtod reads a prefix), or None."""
    match = _NUMBER.match(text)
    return float(match.group(0)) if match else None


def parse_line(line: str) -> ToolEntry | str | None:
    """One line: an entry, None (blank or comment only), or the line itself if it is skipped."""
    found = _parse(line)
    if found is None or isinstance(found, str):
        return found
    entry, _ = found
    return entry


def _parse(line: str) -> tuple[ToolEntry, bool] | str | None:
    """:func:`parse_line`, and whether the entry's line has a P word."""
    body, _, comment = line.partition(";")
    words = body.split()
    if not words:
        return None
    fields: dict[str, float] = {}
    for word in words:
        letter = word[0].lower()
        value = _number(word[1:])
        if letter not in "tp" + OFFSET_LETTERS + "dijq" or value is None:
            return line
        fields[letter] = value
    if "t" not in fields:
        return None
    if not all(math.isfinite(fields.get(letter, 0.0)) for letter in "tpq"):
        return line  # a number past a float (400 digits) is no tool, pocket or orientation
    offsets = tuple(fields.get(letter, 0.0) for letter in OFFSET_LETTERS)
    entry = ToolEntry(int(fields["t"]), int(fields.get("p", 0)), offsets, fields.get("d", 0.0),
                      fields.get("i", 0.0), fields.get("j", 0.0), int(fields.get("q", 0)),
                      comment.strip())
    return entry, "p" in fields


def parse_tool_table(text: str) -> ToolTable:
    """A tool table file's text.  A line without a P word is the tool in the spindle (rs274 puts
    it in slot 0, the last such line wins); the others take slots 1..n in file order."""
    entries: list[ToolEntry] = []
    skipped: list[str] = []
    spindle: ToolEntry | None = None
    for raw in text.splitlines():
        line = raw.rstrip("\r\n")
        found = _parse(line)
        if isinstance(found, str):
            skipped.append(found)
            first = found.split()[0]
            if first[0] in "tT" and _number(first[1:]) is not None:
                entries.append(UNREAD)  # rs274 gave the line its slot before it gave up
        elif found is not None:
            entry, has_pocket = found
            if has_pocket:
                entries.append(entry)
            else:
                spindle = entry
    return ToolTable(tuple(entries), tuple(skipped), spindle)


def read_tool_table(path: str, *, strict: bool = False) -> ToolTable:
    """The tool table in file ``path``.  rs274 takes a file it cannot read as an empty table;
    ``strict`` (``ngc canon``/``check``) refuses it, and a line that would be skipped."""
    try:
        with open(path, encoding="latin-1") as handle:
            text = handle.read()
    except OSError as exc:
        if strict:
            raise NgcConfigError(f"cannot read tool table {path}: {exc.strerror}", file=path) from None
        return ToolTable()
    table = parse_tool_table(text)
    if strict and table.skipped:
        bad = table.skipped[0]
        number = next(i for i, raw in enumerate(text.splitlines(), 1) if raw.rstrip("\r\n") == bad)
        raise NgcConfigError(f"tool table {path}, line {number}: unrecognized line: {bad.strip()}",
                             file=path)
    return table


DEFAULT_TABLE = parse_tool_table(
    "T1 P1 D0.125000 Z+0.511000 ;1/8 end mill\n"
    "T2 P2 D0.062500 Z+0.100000 ;1/16 end mill\n"
    "T3 P3 D0.201000 Z+1.273000 ;#7 tap drill\n"
    "T99999 P123     Z+0.100000 ;big tool number\n"
)


class Tools:
    """The machine's tool data while a program runs: slot 0 is the spindle (first the table's
    line without a P word, if any), slots 1..n the table's entries in file order (G10
    L1/L10/L11 replace them)."""

    __slots__ = ("slots", "spindle_pocket", "unknown")

    def __init__(self, table: ToolTable = DEFAULT_TABLE,
                 unknown: Callable[[int], None] | None = None) -> None:
        spindle = EMPTY_SPINDLE if table.spindle is None else table.spindle
        self.slots: list[ToolEntry] = [spindle, *table.entries]
        # Given (--any-tool): a tool the table lacks is added as one with no offsets, in the
        # pocket of its number, and told to ``unknown``; else it is not found (LinuxCNC's error).
        self.unknown = unknown
        # The pocket of slot 0 in the canon's copy of the table: G10 L1 gives the spindle's
        # entry a tool's data and pocket, the canon's copy only the data; M6 copies a slot
        # whole.  rs274 reads the canon's copy back after M6 and M61 (:meth:`reload`).
        self.spindle_pocket = spindle.pocket

    def load(self, index: int) -> None:
        """M6: the spindle takes slot ``index`` (the slot itself for 0)."""
        if index > 0:
            self.slots[0] = self.slots[index]
            self.spindle_pocket = self.slots[index].pocket

    def reload(self) -> None:
        """The spindle's entry as the canon has it (after M6 or M61)."""
        self.slots[0] = self.slots[0]._replace(pocket=self.spindle_pocket)

    def find(self, number: int) -> ToolEntry | None:
        """The first entry of tool ``number`` in the table (not the spindle), or None."""
        index = self.index(number)
        return None if index is None else self.slots[index]

    def index(self, number: int) -> int | None:
        """The slot of tool ``number`` (1-based, file order; the spindle's slot 0 last), or None."""
        if number < 0:
            return None
        for i in range(1, len(self.slots)):
            if self.slots[i].number == number:
                return i
        if self.slots[0].number == number:
            return 0
        if self.unknown is None or number == 0:
            return None
        self.slots.append(ToolEntry(number, number))
        self.unknown(number)
        return len(self.slots) - 1

    def pocket(self, index: int) -> int:
        """The pocket of the entry in slot ``index`` (-1 for no such slot), as rs274 reads it."""
        return self.slots[index].pocket if 0 <= index < len(self.slots) else -1

    @property
    def spindle(self) -> ToolEntry:
        """The entry of the tool in the spindle (#5400-#5413 read it)."""
        return self.slots[0]
