"""Reading a block as Grbl's parser does (``gc_execute_line``, step 2): each word in turn, a
letter then a number, with the errors found while reading — a character that is not a letter
(1), a number that is not one (2), a code Grbl does not have (20) or not whole (23), two
commands that use the axis words (24), two of one modal group (21), a repeated word (25), a
negative F N P S T (4), a T past the largest tool (38).

The first error stops the reading: a block is all or nothing.
"""

from __future__ import annotations

import re
from collections.abc import Mapping

from .codes import (
    AXIS_COMMAND_CONFLICT,
    AXIS_NONE,
    BAD_NUMBER_FORMAT,
    COMMAND_VALUE_NOT_INTEGER,
    EXPECTED_COMMAND_LETTER,
    MAX_VALUE_EXCEEDED,
    MODAL_GROUP_VIOLATION,
    NEGATIVE_VALUE,
    NO_ACTION,
    OFFSETS,
    UNSUPPORTED_COMMAND,
    WORD_REPEATED,
    Code,
    CodeTable,
    code_table,
    word_bits,
)
from .numbers import arm_unsigned, read_value, whole_and_hundredths
from .rules import Rules

# a word: a letter and read_float's number (sign, digits, one point, digits); else a character
_WORD = re.compile(r"([A-Z])(([-+]?)([0-9]*)\.?([0-9]*))|.", re.S)
# grblHAL's: "$" is a letter too ("if((letter < 'A' && letter != '$') || letter > 'Z')")
_HAL_WORD = re.compile(r"([A-Z$])(([-+]?)([0-9]*)\.?([0-9]*))|.", re.S)


class Rejected(Exception):
    """A line Grbl rejects, with its status code (the ``N`` of ``error:N``)."""

    def __init__(self, code: int) -> None:
        super().__init__(code)
        self.code = code


class NotChecked(Exception):
    """A block this row reads but does not check: it has ``what`` (a code or a word whose
    checks no row models yet)."""

    def __init__(self, what: str) -> None:
        super().__init__(what)
        self.what = what


class Block:
    """One block as read: its copy of the modes with the codes' changes (``modes``, indexed by
    the slots of :mod:`ngc.grbl.codes`, the block's non-modal command last), the command words
    (a bit per modal group), the value words (a bit per letter) and their values, the axis
    words and arc offsets given (a bit per axis), and its axis command.

    ``unchecked``: what the block has that no check of this row models (a code or a word), or
    "".  A block with one is read, each error of the reading exact, but not checked.
    """

    __slots__ = ("axis_command", "axis_words", "command_words", "modes", "offset_words",
                 "unchecked", "value_words", "values")

    def __init__(self, modes: list[int]) -> None:
        self.unchecked = ""
        self.modes = modes
        self.command_words = 0
        self.value_words = 0
        self.values: dict[str, float] = {}
        self.axis_words = 0
        self.offset_words = 0
        self.axis_command = AXIS_NONE


class Reader:
    """Reads the blocks of one build (:class:`Rules`); keeps the values of the numbers it has
    read (a program repeats many), up to a bound."""

    CACHE = 1 << 16

    def __init__(self, rules: Rules) -> None:
        self.rules = rules
        self.codes = code_table(rules.parser, rules.mist_coolant)
        self.words = _value_words(rules.axes, rules.extra_words)
        self.pattern = _HAL_WORD if "$" in rules.extra_words else _WORD
        self.not_negative = frozenset(rules.not_negative)
        self.extra = frozenset(rules.extra_words)
        self.whole = frozenset(rules.whole_words)
        self._numbers: dict[str, float] = {}
        self._codes: dict[float, tuple[int, int]] = {}

    def read(self, text: str, modes: list[int]) -> Block:
        """The block of a line as Grbl keeps it (:func:`ngc.grbl.lines.kept`), read against the
        parser's modes; raises :class:`Rejected`.  (The loop is the hot path of a check: its
        lookups are local.)"""
        block = Block([*modes, NO_ACTION])
        numbers, codes, words, values = self._numbers, self._codes, self.words, block.values
        max_tool, not_negative, table = self.rules.max_tool, self.not_negative, self.codes
        value_words = axis_words = offset_words = 0
        for letter, number, sign, whole, fraction in self.pattern.findall(text):
            if not letter:
                raise Rejected(EXPECTED_COMMAND_LETTER)
            value = numbers.get(number)
            if value is None:
                value = self._value(number, sign, whole, fraction)
            if letter == "G" or letter == "M":
                split = codes.get(value) or self._code(value)
                if letter == "G":
                    _g_word(block, split, table)
                else:
                    _m_word(block, split, table.m_codes)
                continue
            word = words.get(letter)
            if word is None:
                raise Rejected(UNSUPPORTED_COMMAND)
            if letter in self.whole or letter in self.extra:
                self._other_word(block, letter, value)
            if letter == "T" and self._tool(value) > max_tool:
                raise Rejected(MAX_VALUE_EXCEEDED)
            if letter in values:
                raise Rejected(WORD_REPEATED)
            if value < 0.0 and letter in not_negative:
                raise Rejected(NEGATIVE_VALUE)
            values[letter] = value
            value_words |= word[0]
            axis_words |= word[1]
            offset_words |= word[2]
        block.value_words, block.axis_words, block.offset_words = value_words, axis_words, offset_words
        return block

    def _other_word(self, block: Block, letter: str, value: float) -> None:
        """A word that must be whole (error 23, grblHAL's "if (mantissa > 0)"), or one read only
        for codes no row checks (the block is not checked)."""
        if letter in self.whole and whole_and_hundredths(value, self.rules.code_bits)[1]:
            raise Rejected(COMMAND_VALUE_NOT_INTEGER)
        if letter in self.extra and not block.unchecked:
            block.unchecked = f"the {letter} word (used only by codes this row does not check)"

    def _tool(self, value: float) -> float:
        """T as the limit is held against it: the value (Grbl), or its 32-bit whole number
        (grblHAL's ``int_value``)."""
        return float(arm_unsigned(value)) if self.rules.code_bits == 32 else value

    def _value(self, number: str, sign: str, whole: str, fraction: str) -> float:
        """A number read (error 2 if it has no digit), and kept."""
        if not whole and not fraction:
            raise Rejected(BAD_NUMBER_FORMAT)
        if len(self._numbers) >= self.CACHE:
            self._numbers.clear()
        rules = self.rules
        value = self._numbers[number] = read_value(sign, whole, fraction, rules.digits,
                                                   rules.leading_zeros)
        return value

    def _code(self, value: float) -> tuple[int, int]:
        """A G or M word's whole number and hundredths, kept."""
        if len(self._codes) >= self.CACHE:
            self._codes.clear()
        code = self._codes[value] = whole_and_hundredths(value, self.rules.code_bits)
        return code


def _value_words(axes: str, extra: str) -> dict[str, tuple[int, int, int]]:
    """Each value word's bit among the value words, its bit among the axis words (an axis) and
    among the arc offsets (I J K)."""
    words = {}
    for letter, bit in word_bits(axes, extra).items():
        axis = 1 << axes.index(letter) if letter in axes else 0
        offset = 1 << OFFSETS.index(letter) if letter in OFFSETS else 0
        words[letter] = (bit, axis, offset)
    return words


def _g_word(block: Block, split: tuple[int, int], table: CodeTable) -> None:
    code = table.g_codes.get(split)
    if code is None:
        whole = split[0]
        fraction = table.g_fractions.get(whole)
        if fraction is None:
            raise Rejected(UNSUPPORTED_COMMAND)
        _take_axis_command(block, fraction.axis)
        if fraction.error:
            raise Rejected(fraction.error)
        code = table.g_codes[(whole, 0)]  # (a fraction the parser drops)
    else:
        _take_axis_command(block, code.axis)
    _set(block, code)


def _m_word(block: Block, split: tuple[int, int], codes: Mapping[int, Code]) -> None:
    whole, hundredths = split
    if hundredths:
        raise Rejected(COMMAND_VALUE_NOT_INTEGER)
    code = codes.get(whole)
    if code is None:
        raise Rejected(UNSUPPORTED_COMMAND)
    _set(block, code)


def _take_axis_command(block: Block, axis: int) -> None:
    """A code that uses the axis words: error 24 if the block has one already."""
    if axis != AXIS_NONE:
        if block.axis_command != AXIS_NONE:
            raise Rejected(AXIS_COMMAND_CONFLICT)
        block.axis_command = axis


def _set(block: Block, code: Code) -> None:
    """A code's modal group taken (error 21 if taken already) and its mode set."""
    bit = 1 << code.group
    if block.command_words & bit:
        raise Rejected(MODAL_GROUP_VIOLATION)
    block.command_words |= bit
    if code.unchecked and not block.unchecked:
        block.unchecked = code.unchecked
    if code.slot is not None:
        if code.adds:
            block.modes[code.slot] |= code.value
        else:
            block.modes[code.slot] = code.value
