"""Reading one line of RS274/NGC into a :class:`Block`, once.

A block keeps its items in source order — words, parameter settings, comments — with values that are
constants or compiled expressions (see :mod:`.expressions`).  Nothing here depends on the
interpreter's state, so a parsed block can be executed any number of times.  The grammar and the
messages are rs274's: overview.adoc "Format of a line", "Numbers", "Parameters", "Expressions".
"""

from __future__ import annotations

import re
from collections.abc import Callable
from types import MappingProxyType

from ..errors import NgcError, NgcRuntimeError, NgcSyntaxError
from . import expressions as ex
from .codes import LINUXCNC, POLAR_LETTERS, CodeTable
from .lexer import C_SPACE, normalize
from .oword import (
    CONDITION,
    KEYWORDS,
    NOTHING,
    OPTIONAL_VALUE,
    PROGRAM,
    OWord,
    number_label,
)
from .words import Words, add_word, check_signs, integer_value

WORD = 0
PARAM = 1
COMMENT = 2

Item = tuple[int, object, object]

_LETTERS = "abcdefghijklmpqrstxyz$"
_PROFILE_LETTERS = _LETTERS + "uw"  # a lathe cycle's profile: U, W are incremental X, Z
# How rs274 names a repeated word that is not named by its letter.
_WORD_NAMES = MappingProxyType({"$": "spindle choice ($)"})
_LOWER = "abcdefghijklmnopqrstuvwxyz"
# Letters the fast path takes: plain real-valued words (no M, no integer words, no N/O).
_FAST_LETTERS = frozenset("abcdefgijkpqrsxyz")  # not H L T: integers, checked as read
# split_plain's tables (translations without deleted bytes: bytes.translate sets up a table of
# its own for those, which costs more than the rest of the reading): the bytes that end a number,
# as NUL (a letter, or a byte that has no place in a plain line: float() takes a form feed or \v
# as white space, rs274 does not), and the letters the fast path takes (and N) lowered, every
# other byte a space.
_SKIPPED = "\t\n\r"
_CUTS = bytes(0 if chr(c).lower() in _LOWER or chr(c) == "_" or c == 127
              or (c < 32 and chr(c) not in _SKIPPED) else c for c in range(256))
_LETTERS_ONLY = bytes(ord(chr(c).lower()) if chr(c).lower() in _FAST_LETTERS | {"n"} and c < 128
                      else 32 for c in range(256))
_N_WORD = re.compile(r"n(\d+)(?:\.\d*)?")
_LINE_NUMBER = re.compile(rb"(\d+)(?:\.\d*)?")
_NUMBER_TOKEN = re.compile(r"[-+]?[0-9.]*")
_STRTOD = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)")
_NAME_END = re.compile(r"[^a-z]")
_OPERATOR_INITIALS = frozenset("aeglmnox")
_NUMBER_START = frozenset("0123456789.")
_OPERATORS = ("**", "*", "/", "+", "-", "mod", "eq", "ne", "gt", "ge", "lt", "le", "and", "or", "xor")

# The largest numbered parameter (overview.adoc, "Numbered Parameters").
MAX_PARAMETER = 5601
# Written by the machine only: a program that sets them gets "Parameter is readonly" (rs274
# says so as it reads the setting, before the rest of the line).
READ_ONLY_PARAMETERS = frozenset(range(5400, 5414)) | frozenset(range(5420, 5429))


def check_number_writable(index: int) -> None:
    """System parameters the machine maintains are read-only."""
    if index in READ_ONLY_PARAMETERS:
        raise NgcRuntimeError("Parameter is readonly")


def n_label(digits: str | None) -> str:
    """The N column rs274 prints before each canonical call of a block (digits as written)."""
    if digits is None:
        return "N..... "
    return "N" + f"{digits:<6s}"


class Block:
    """One parsed line.  ``items`` are ``(kind, key, value)`` tuples in source order."""

    __slots__ = ("delete", "items", "label", "line", "n_number", "oword", "resolved", "source")

    def __init__(self, line: int, source: str) -> None:
        self.line = line
        self.source = source
        self.delete = False
        self.n_number: int | None = None
        self.label = "N..... "
        self.items: list[Item] = []
        self.oword: OWord | None = None
        # The block's words when every value on the line is a constant (read once, reused).
        self.resolved: Words | None = None


def parse_line(raw: str, line: int = 0, table: CodeTable = LINUXCNC, fast: bool = True,
               eager: ex.ParamContext | None = None, profile: bool = False) -> Block:
    """Parse one source line (without its newline) into a :class:`Block`.

    ``table`` is the dialect's code table (unknown codes and modal clashes are read errors);
    ``fast`` lets a line of plain words with literal numbers take :func:`split_plain`.

    ``eager`` reads the line as rs274 does, evaluating each value against those parameters as it
    is read: an error in a value (``X[1/0]``) comes before a read error further on (``G0 G1``).
    The interpreter reads a line so only when the line has a read error, to know which comes
    first; the block it returns is of no other use.

    ``profile`` reads a line of a lathe cycle's profile subroutine, where U and W are words too
    (elsewhere rs274 says "Bad character 'u' used").

    >>> b = parse_line("N10 G1 X1.5 Y[2*3] (cut)")
    >>> b.label, [(k, key) for k, key, _ in b.items]
    ('N10    ', [(0, 'g'), (0, 'x'), (0, 'y'), (2, '(cut)')])
    """
    source = raw.rstrip(C_SPACE)
    block = Block(line, source)
    try:
        text = normalize(source)  # rs274 drops the white space that ends a line
        if text.startswith("/"):
            block.delete = True
            text = text[1:]
        if not (fast and _fast(block, text, table)):
            reader = _Reader(text, block, table) if eager is None else _EagerReader(
                text, block, table, eager)
            if profile:
                reader.letters = _PROFILE_LETTERS
            reader.read_line()
            _resolve_constant(block, reader.read)
    except NgcError as err:
        if err.column is not None:
            err.column = raw_column(raw, err.column - 1)
        raise err.locate(file=None, line=line, source=source) from None
    return block


def skim_oword(raw: str, line: int = 0) -> OWord | None:
    """The o-word of a line being skipped, read as rs274 reads it then; None if it has none.

    Comments are still checked (an unclosed one is an error); other lines are not read.
    """
    try:
        text = normalize(raw).lstrip("/")
        if text.startswith("n"):
            m = _N_WORD.match(text)
            if m is None:
                raise NgcSyntaxError("Bad format unsigned integer", column=1)
            text = text[m.end() :]
        if not text.startswith("o"):
            return None
        block = Block(line, raw.rstrip(C_SPACE))
        _Reader(text, block).read_oword(skim=True)
    except NgcError as err:
        if err.column is not None:
            err.column = raw_column(raw, err.column - 1)
        raise err.locate(file=None, line=line, source=raw.rstrip(C_SPACE)) from None
    return block.oword


def _fast(block: Block, text: str, table: CodeTable) -> bool:
    """Plain words with literal numbers: resolved here, once (see :func:`split_plain`)."""
    found = split_plain(text)
    if found is None:
        return False
    w, g, digits = found
    if digits is not None:
        _set_number(block, digits)
    block.resolved = words_of(w, g, table)
    return True


def split_plain(text: str) -> tuple[dict[str, float], float | None, str | None] | None:
    """Read a line of plain words with literal numbers (the common CAM line), as it is read
    from the file: spaces are dropped and letters lowered here.

    Cutting at the letters and letting ``float`` judge each number is the cheapest way to read
    such a line; anything unusual (expressions, parameters, comments, bad numbers, repeated or
    unknown letters, M or integer words) returns None and takes the general reader.  Returns the
    non-G words, the G word's value and the N word's digits.
    """
    if not text.isascii():
        return None
    # The text between the letters, spaces dropped, and the letters: two byte translations
    # (cheaper than a regular expression).  A byte that has no place in a plain line ("_", a
    # control character but the white space rs274 skips) cuts the line once more, a letter the
    # fast path does not take is left out of the letters, and two letters with nothing between
    # them read as one, so that such a line has not one number per letter.
    data = text.encode()
    parts = data.translate(_CUTS).replace(b" ", b"").split(b"\0")
    letters = data.translate(_LETTERS_ONLY).decode().split()
    if parts[0] or len(parts) != len(letters) + 1:
        return None
    digits = None
    i = 1  # (parts[0] is empty)
    if letters and letters[0] == "n":
        m = _LINE_NUMBER.fullmatch(parts[1])
        if m is None:
            return None
        digits = m.group(1).decode()
        del letters[0]
        i = 2
    w = {}
    try:
        for letter in letters:  # one number per letter (cheaper than dict(zip(...)))
            w[letter] = float(parts[i])
            i += 1
    except ValueError:
        return None
    if len(w) != len(letters) or "n" in w:
        return None
    return w, w.pop("g", None), digits


def words_of(w: dict[str, float], g: float | None, table: CodeTable) -> Words:
    """The :class:`Words` of a line read by :func:`split_plain`."""
    words = Words()
    if g is not None:
        add_word(words, "g", g, table)
    check_signs(w)
    words.w = w
    return words.finish()


def _resolve_constant(block: Block, words: Words) -> None:
    """Resolve a block now if nothing on it can change between executions: ``words`` are its
    constant words, added as the reader read them."""
    for kind, key, value in block.items:
        if kind == PARAM or not isinstance(value, float | None):
            return
        if kind == COMMENT:
            words.comment = key  # type: ignore[assignment]
    block.resolved = words.finish()


def _set_number(block: Block, digits: str) -> None:
    block.n_number = int(digits)
    block.label = n_label(digits)


def _show_char(c: str) -> str:
    """A character as rs274 shows it: control characters and bytes past ``z`` as three octal digits
    (rs274 reads the program as bytes: a character past ASCII is its first byte in UTF-8, a byte
    that is not UTF-8 (read as a lone surrogate) the byte itself)."""
    code = ord(c)
    if 0xDC80 <= code <= 0xDCFF:
        code -= 0xDC00
    elif code > 0xFF:
        code = c.encode("utf-8", "surrogatepass")[0]
    return f"\\{code:03o}" if code < 32 or code > 122 else c


def raw_column(raw: str, index: int) -> int:
    """1-based column in ``raw`` of character ``index`` of its normalized form."""
    seen = 0
    in_comment = False
    for col, c in enumerate(raw):
        if in_comment or c not in " \t":
            if seen == index:
                return col + 1
            seen += 1
        if c == "(":
            in_comment = True
        elif c == ")":
            in_comment = False
    return len(raw) + 1


class _Reader:
    """Reads the items of a normalized line, rs274's way (the general path)."""

    __slots__ = ("block", "i", "letters", "read", "s", "table", "trig")

    def __init__(self, text: str, block: Block, table: CodeTable = LINUXCNC) -> None:
        self.s = text
        self.i = 0
        self.letters = _LETTERS
        self.block = block
        self.table = table
        # The constant words read so far: rs274 raises a word's errors (a repeated letter, two
        # codes of one group) when it reads the word, before it reads what follows.
        self.read = Words()
        # SIN, COS and TAN of this line (see expressions.trig_functions), made at the first.
        self.trig: dict[str, Callable[[float], float]] | None = None

    def error(self, message: str, at: int | None = None) -> NgcSyntaxError:
        return NgcSyntaxError(message, column=(self.i if at is None else at) + 1)

    # -- line ---------------------------------------------------------------------------------
    def read_line(self) -> None:
        s = self.s
        if s.startswith("n"):
            self.read_line_number()
        items = self.block.items
        seen: set[str] = set()
        letters = self.letters
        n = len(s)
        while self.i < n:
            c = s[self.i]
            if c == "(":
                end = s.index(")", self.i)
                items.append((COMMENT, s[self.i : end + 1], None))
                self.i = end + 1
            elif c == "#":
                items.append(self.read_parameter_setting())
            elif c in letters or c in POLAR_LETTERS:
                if c in seen:
                    raise self.error(f"Multiple {_WORD_NAMES.get(c, c)} words on one line")
                if c not in "gm":
                    seen.add(c)
                self.i += 1
                value = self.read_value()
                items.append((WORD, c, value))
                if type(value) is float:
                    add_word(self.read, c, value, self.table)
            elif c == "o" and not items:
                self.read_oword()
            elif c == ";":
                break
            else:
                err = self.error(f"Bad character '{_show_char(c)}' used")
                err.char = c
                raise err

    def read_oword(self, skim: bool = False) -> None:
        """An o-word line: label, keyword, its bracketed values, then comments only.

        ``skim`` reads a line being skipped the way rs274 does: label and keyword, the bracketed
        values that are there; a missing bracket or anything after them goes unnoticed.
        """
        s = self.s
        self.i += 1  # 'o'
        label: str | None = None
        label_expr: ex.Value | None = None
        if s.startswith("<", self.i):
            if s.find(">", self.i) < 0:
                self.block.oword = OWord(NOTHING, None, None)
                self.i = len(s)
                return
            label = self.read_name()
        else:
            value = self.read_value()
            if isinstance(value, float):
                label = number_label(value)
            else:
                label_expr = value
        keyword = next((k for k in KEYWORDS if s.startswith(k, self.i)), None)
        if keyword is None:
            if self.i < len(s) and s[self.i] not in "(;":
                raise self.error("Unknown control command in o word")
            keyword = PROGRAM
        self.i += len(keyword)
        oword = OWord(keyword, label, label_expr)
        self.block.oword = oword
        if skim:
            # Only what a skip may evaluate: a condition, a value at the end of a definition.
            valued = keyword in CONDITION or keyword in OPTIONAL_VALUE
            if valued and s.startswith("[", self.i):
                oword.args.append(self.read_expression())
            self.i = len(s)
            return
        if keyword in CONDITION:
            if not s.startswith("[", self.i):
                raise self.error(f"Left bracket missing after '{keyword}'")
            oword.args.append(self.now(self.read_expression()))
        elif keyword == "call" or keyword in OPTIONAL_VALUE:
            while True:
                self.skip_comments()
                if not s.startswith("[", self.i) or (keyword != "call" and oword.args):
                    break
                oword.args.append(self.now(self.read_expression()))
        self.skip_comments()
        if self.i < len(s) and s[self.i] != ";":
            raise self.error("Unexpected character after O-word")

    def skip_comments(self) -> None:
        """Comments on an o-word line are read and dropped."""
        s = self.s
        while s.startswith("(", self.i):
            self.i = s.index(")", self.i) + 1

    def read_line_number(self) -> None:
        m = _N_WORD.match(self.s)
        if m is None:
            raise self.error("Bad format unsigned integer")
        _set_number(self.block, m.group(1))
        self.i = m.end()

    def read_parameter_setting(self) -> Item:
        self.i += 1  # '#'
        target: object
        if self.s.startswith("<", self.i):
            target = self.read_name()
            self.declare(target)
        else:
            target = self.read_index()
            if isinstance(target, int):
                check_number_writable(target)
        if not self.s.startswith("=", self.i):
            raise self.error("Equal sign missing in parameter setting")
        self.i += 1
        return (PARAM, target, self.read_value())

    # -- values -------------------------------------------------------------------------------
    def now(self, value: ex.Value) -> ex.Value:
        """A value rs274 has computed at this point of the line (see :class:`_EagerReader`)."""
        return value

    def declare(self, name: str) -> None:
        """A named parameter's setting has been read (see :class:`_EagerReader`)."""

    def read_value(self) -> ex.Value:
        """A real value: number, ``[expression]``, ``#parameter``, function call, signed value."""
        s = self.s
        if self.i >= len(s):
            raise self.error("No characters found in reading real value")
        c = s[self.i]
        if c == "[":
            return self.read_expression(check=True)
        if c == "#":
            self.i += 1
            return self.read_parameter_value()
        if "a" <= c <= "z":
            return self.read_function()
        # A sign before anything but a digit or a point is an operator on the value after it
        # (rs274: "X-{" fails on '' after the sign, "X-" at the end of the line on '-').
        if c in "+-" and self.i + 1 < len(s) and s[self.i + 1] not in _NUMBER_START:
            self.i += 1
            inner = self.read_value()
            if c == "+":
                return inner
            return ex.fold_unary(lambda v: -v, inner)
        return self.read_number()

    def read_number(self) -> float:
        m = _NUMBER_TOKEN.match(self.s, self.i)
        assert m is not None
        token = m.group()
        num = _STRTOD.match(token)
        if num is None:
            raise self.error(f"bad number format (conversion failed) parsing '{token}'")
        if num.end() != len(token):
            raise self.error(f"bad number format (trailing characters) parsing '{token}'")
        self.i = m.end()
        return float(token)

    def read_expression(self, check: bool = False) -> ex.Value:
        """``[v0 op1 v1 ...]``; ``check``: rs274 checks the value (a bracket read as a value, not
        a function's argument nor an o-word's bracket), see :func:`.expressions.finite`.

        rs274 applies each operator as soon as the next operator, of the same or a lower
        precedence, is read (``[1/0 + SQRT[-1]]`` divides by zero before it reads SQRT): the
        values are combined here in that order, so their closure evaluates in it too.
        """
        start = self.i
        self.i += 1  # '['
        values = [self.read_value()]
        pending: list[str] = []
        s = self.s
        precedence = ex.PRECEDENCE
        while True:
            if self.i >= len(s):
                raise self.error("Unclosed expression", start)
            if s[self.i] == "]":
                self.i += 1
                break
            op = next((o for o in _OPERATORS if s.startswith(o, self.i)), None)
            if op is None:
                c = s[self.i]
                if c in _OPERATOR_INITIALS:
                    raise self.error(f"Unknown operation name starting with {c}")
                raise self.error("Unknown operation")
            self.i += len(op)
            level = precedence[op]
            while pending and precedence[pending[-1]] >= level:
                right = values.pop()
                values[-1] = self.now(ex.fold_binary(pending.pop(), values[-1], right))
            pending.append(op)
            values.append(self.read_value())
        while pending:
            right = values.pop()
            values[-1] = ex.fold_binary(pending.pop(), values[-1], right, check and not pending)
        return values[0]

    def read_function(self) -> ex.Value:
        s = self.s
        m = _NAME_END.search(s, self.i)
        end = m.start() if m else len(s)
        word = s[self.i : end]
        name = next((f for f in _FUNCTIONS if word.startswith(f)), None)
        if name is None:
            if not any(f.startswith(s[self.i]) for f in _FUNCTIONS):
                raise self.error("Unknown word where unary operation could be")
            raise self.error(f"Unknown word starting with {s[self.i]}")
        self.i += len(name)
        if not s.startswith("[", self.i):
            raise self.error("Left bracket missing after unary operation name")
        if name == "exists":
            return self.read_exists()
        arg = self.read_expression()
        if name == "atan":
            if not s.startswith("/", self.i):
                raise self.error("Slash missing after first atan argument")
            self.i += 1
            if not s.startswith("[", self.i):
                raise self.error("Left bracket missing after slash with atan")
            return ex.fold_binary_fn(ex.atan2_degrees, arg, self.read_expression())
        if name in _TRIG:
            if self.trig is None:
                self.trig = ex.trig_functions()
            return ex.fold_unary(self.trig[name], arg, check=True)
        return ex.fold_unary(ex.UNARY[name], arg, check=True)

    def read_exists(self) -> ex.Value:
        """EXISTS[#<name>]: 1 if the named parameter exists; EXISTS[#n]: 1 if n is in range."""
        s = self.s
        self.i += 1  # '['
        if not s.startswith("#", self.i):
            raise self.error("Expected # reading parameter")
        self.i += 1
        result: ex.Value
        if s.startswith("<", self.i):
            name = self.read_name()
            result = lambda p: 1.0 if p.exists(name) else 0.0  # noqa: E731
        else:
            index = self.read_value()
            result = ex.fold_unary(lambda v: 1.0 if 1 <= round(v) <= MAX_PARAMETER else 0.0, index)
        if not s.startswith("]", self.i):
            raise self.error("Expected ] reading bracketed parameter")
        self.i += 1
        return result

    # -- parameters ---------------------------------------------------------------------------
    def read_name(self) -> str:
        end = self.s.find(">", self.i)
        if end < 0:
            raise self.error("Named parameter not terminated")
        name = self.s[self.i + 1 : end]
        self.i = end + 1
        return name

    def read_index(self) -> int | ex.Expr:
        value = self.read_value()
        if isinstance(value, float):
            return check_index(value)
        return lambda p: float(check_index(value(p)))

    def read_parameter_value(self) -> ex.Value:
        """A parameter's value; one that is infinite or NaN (from a parameter file, or passed to
        a subroutine) stops the program where it is read.  The check is written out in each
        closure, as in ``expressions.fold_*``: a shared helper would cost a call per read."""
        if self.s.startswith("<", self.i):
            name = self.read_name()
            if not name.startswith("_"):

                def local(p: ex.ParamContext) -> float:
                    v = p.local(name)
                    if v - v == 0.0:
                        return v
                    raise ex.nonfinite(v)

                return local

            def named(p: ex.ParamContext) -> float:
                v = p.named(name)
                if v - v == 0.0:
                    return v
                raise ex.nonfinite(v)

            return named
        index = self.read_index()
        if isinstance(index, int):
            k = index

            def number(p: ex.ParamContext) -> float:
                v = p.num(k)
                if v - v == 0.0:
                    return v
                raise ex.nonfinite(v)

            return number
        fn = index

        def computed(p: ex.ParamContext) -> float:
            v = p.num(int(fn(p)))
            if v - v == 0.0:
                return v
            raise ex.nonfinite(v)

        return computed


class _EagerReader(_Reader):
    """Reads a line computing each value as it is read, in rs274's order (see :func:`parse_line`)."""

    __slots__ = ("params",)

    def __init__(self, text: str, block: Block, table: CodeTable, params: ex.ParamContext) -> None:
        super().__init__(text, block, table)
        self.params = params

    def now(self, value: ex.Value) -> ex.Value:
        return value if type(value) is float else value(self.params)  # type: ignore[operator]

    def declare(self, name: str) -> None:
        declare = getattr(self.params, "declare", None)
        if declare is not None:
            declare(name)  # from here on the name reads 0 (rs274)

    def read_value(self) -> ex.Value:
        return self.now(super().read_value())


_TRIG = frozenset({"sin", "cos", "tan"})
_FUNCTIONS = (
    "abs",
    "acos",
    "asin",
    "atan",
    "cos",
    "exists",
    "exp",
    "fix",
    "fup",
    "ln",
    "round",
    "sin",
    "sqrt",
    "tan",
)


def read_value(text: str) -> ex.Value:
    """The real value that is the whole of ``text`` (lower case, no white space): a number,
    ``[expression]``, ``#parameter`` or function call."""
    reader = _Reader(text, Block(0, text))
    value = reader.read_value()
    if reader.i != len(text):
        raise NgcSyntaxError(f"Bad expression '{text}'", column=reader.i + 1)
    return value


def check_index(value: float) -> int:
    """A parameter number: close to an integer and in 1..MAX_PARAMETER (rs274's checks)."""
    k = integer_value(value)
    if k < 1 or k > MAX_PARAMETER:
        raise NgcSyntaxError("Parameter number out of range")
    return k
