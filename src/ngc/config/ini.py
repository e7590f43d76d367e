"""LinuxCNC INI files, read the way ``rs274`` 2.9.0~pre1 reads them.

The syntax (ini-config.adoc, "The INI File Components"), with the details the binary was observed
to follow where the document is silent or describes a newer reader:

* ``[SECTION]`` starts a section.  Leading blanks are allowed and anything after the ``]`` is
  ignored (``[S] # note`` is section ``S``); the name is the text between the first ``[`` and the
  first ``]``, compared case-sensitively (``[ S ]`` is not ``S``).  Only the *first* section of a
  name is searched: a second ``[VARS]`` block further down is never read.
* ``NAME = value``: the name is the first word of the line (up to a blank or ``=``) and is compared
  case-sensitively; whatever follows the name up to the first ``=`` is ignored (``NAME junk = v``
  reads ``v``).  The value is the rest of the line without leading and trailing blanks.  A line
  whose name matches but that has no ``=`` ends the search (not found).  The first occurrence of
  a name wins; an empty value is a value (``""``), and it wins too.
* A line whose first non-blank character is ``#`` or ``;`` is a comment.  ``#`` and ``;`` inside a
  value are part of the value (``A = 1 # one`` is ``"1 # one"``).
* A line ending in ``\\`` right before its newline continues on the next line, which is appended
  as it is (its leading blanks stay, and a ``[...]`` or comment line is swallowed).  A blank after
  the backslash, or a CR (``\\`` CR LF), stops the continuation: the backslash is then part of the
  value.  A continuation with no line after it makes the lookup fail.
* Any line whose first non-blank character is ``[`` ends the section (even ``[U`` without ``]``).
* No escapes are decoded (``\\x41`` stays four characters) and quotes are plain characters.
* CR LF line endings work (rs274 prints :data:`DOS_LINE_ENDINGS_WARNING` once when it opens such a
  file); a CR anywhere else is "ambiguous": a lookup that has to read across that line fails and
  rs274 prints :data:`AMBIGUOUS_CR_ERROR` once per such lookup.

Only a regular file (or a directory, read as empty) is an INI file: :meth:`Ini.read` refuses a
FIFO, device or socket without waiting for it, with the message of a file it cannot open (rs274
would wait forever on a FIFO).

``#<_ini[section]name>`` parameters are resolved by :func:`ini_parameter`; the ``[RS274NGC]``
settings the interpreter uses are collected by :meth:`Rs274ngcSettings.from_ini`.
"""

from __future__ import annotations

import contextlib
import math
import os
import re
import stat
from typing import NamedTuple

from ..errors import NgcConfigError

__all__ = [
    "AMBIGUOUS_CR_ERROR",
    "DOS_LINE_ENDINGS_WARNING",
    "FEATURE_HAL_PIN_VARS",
    "FEATURE_INI_VARS",
    "FEATURE_NO_DOWNCASE_OWORD",
    "FEATURE_OWORD_NARGS",
    "FEATURE_OWORD_WARNONLY",
    "FEATURE_RETAIN_G43",
    "Ini",
    "Rs274ngcSettings",
    "ini_parameter",
    "parse_int",
    "parse_real",
]

DOS_LINE_ENDINGS_WARNING = "inifile: warning: File contains DOS-style line endings."
AMBIGUOUS_CR_ERROR = "inifile: error: File contains ambiguous carriage returns"

# C isspace() in the C locale: what the reader trims around names and values.
BLANKS = " \t\n\v\f\r"
_NAME = re.compile(r"[^ \t\n\v\f\r=]*")

# A real number as rs274 accepts it in an INI value: decimal only (``0x10`` is refused), the
# whole value must be the number (``2.5abc``, ``1e`` are refused), ``inf``/``infinity``/``nan``
# in any case with an optional sign, and a number too big for a double is refused (``1e400``)
# while one too small reads as 0 (``1e-400``).
_REAL = re.compile(
    r"(?P<sign>[+-]?)(?:(?P<finite>(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?)"
    r"|(?P<inf>inf(?:inity)?)|nan(?:\(.*\))?)",
    re.IGNORECASE | re.DOTALL,
)
# An integer value: decimal digits with an optional sign, within a C int.
_INT = re.compile(r"[+-]?[0-9]+")
INT_MIN, INT_MAX = -(2**31), 2**31 - 1

# The ``FEATURES`` bitmask of LinuxCNC before 2.8 (ini-config.adoc, note after [RS274NGC]).  rs274
# 2.9.0~pre1 ignores FEATURES (observed: FEATURES = 0 leaves #<_ini[...]> working, FEATURES = 2 does
# not define #<n_args>); the six options are separate INI names now.
FEATURE_RETAIN_G43 = 0x1
FEATURE_OWORD_NARGS = 0x2
FEATURE_INI_VARS = 0x4
FEATURE_HAL_PIN_VARS = 0x8
FEATURE_NO_DOWNCASE_OWORD = 0x10
FEATURE_OWORD_WARNONLY = 0x20

# Center-format arc radius tolerances.  ini-config.adoc gives 0.00005 inch and 0.00127 mm as the
# defaults; rs274 2.9.0~pre1 was observed to use 0.002*sqrt(2) inch and 0.02*sqrt(2) mm when the INI
# does not set them (an arc whose end radius differs by 0.0283 mm passes, 0.0284 mm fails), and to
# refuse INI values outside [0.00004, default] inch and [0.001, default] mm.
CENTER_ARC_RADIUS_TOLERANCE_INCH = 0.002 * math.sqrt(2.0)
CENTER_ARC_RADIUS_TOLERANCE_MM = 0.02 * math.sqrt(2.0)
MIN_CENTER_ARC_RADIUS_TOLERANCE_INCH = 0.00004
MIN_CENTER_ARC_RADIUS_TOLERANCE_MM = 0.001

# Directory lists: at most this many existing directories are kept (ini-config.adoc, [RS274NGC]).
SUBROUTINE_PATH_MAX_DIRS = 10
USER_M_PATH_MAX_DIRS = 5


# An INI file is read whole; one larger than this is refused (LinuxCNC's run to tens of kilobytes).
MAX_INI_BYTES = 4 << 20
_HEADER = re.compile(r"^[ \t\v\f\r]*\[", re.MULTILINE)  # a line whose first non-blank is [
_AMBIGUOUS_CR = re.compile(r"\r(?!\n|\Z)")  # a CR neither before a newline nor at the very end


def _read_regular(name: str) -> bytes:
    """The bytes of the regular file ``name``, ``b""`` for a directory; OSError otherwise.

    A FIFO, device or socket is refused: on what ``stat`` sees before opening (a device is never
    opened), then on the open descriptor (a FIFO put there since is opened without blocking).
    A file over :data:`MAX_INI_BYTES` is :class:`IniTooLarge`.
    """
    with contextlib.suppress(FileNotFoundError):
        _check_regular(name, os.stat(name).st_mode)
    try:
        with open(name, "rb", opener=_open_nonblocking) as handle:
            info = os.fstat(handle.fileno())
            _check_regular(name, info.st_mode)
            if info.st_size > MAX_INI_BYTES:
                raise IniTooLarge(name)
            data = handle.read(info.st_size + 1)
            if len(data) > info.st_size:  # it grows (or stat does not know its size): read on
                data += handle.read(MAX_INI_BYTES + 1 - len(data))
    except IsADirectoryError:
        return b""
    if len(data) > MAX_INI_BYTES:  # (it grew since)
        raise IniTooLarge(name)
    return data


def _check_regular(name: str, mode: int) -> None:
    if not (stat.S_ISREG(mode) or stat.S_ISDIR(mode)):
        raise OSError(f"'{name}' is not a regular file")


def _open_nonblocking(name: str, flags: int) -> int:
    return os.open(name, flags | os.O_NONBLOCK | os.O_NOCTTY)


class IniTooLarge(NgcConfigError):
    """An INI file over :data:`MAX_INI_BYTES`."""

    def __init__(self, name: str) -> None:
        super().__init__(f"INI file {name} is larger than {MAX_INI_BYTES} bytes: not read",
                         file=name)


class Ini:
    """An INI file's text, looked up the way rs274's reader searches it.

    rs274 searches the file from its start on each lookup; the same answers come here from an
    index made as the file is read (where each section's first header is) and, on a section's
    first lookup, a table of its names (the first occurrence of each), so that reading a file
    takes time in proportion to its length and a lookup none.

    >>> ini = Ini.parse("[VARS]\\nX = 10\\nX = 11\\n")
    >>> ini.get("VARS", "X"), ini.get("VARS", "x"), ini.get("vars", "X")
    ('10', None, None)
    """

    __slots__ = ("_ambiguous_at", "_headers", "_names", "path", "text")

    def __init__(self, text: str, path: str | None = None) -> None:
        self.text = text
        self.path = path
        # where the line of the first ambiguous CR starts: no lookup reads past it
        found = _AMBIGUOUS_CR.search(text)
        self._ambiguous_at = len(text) + 1 if found is None else text.rfind("\n", 0,
                                                                           found.start()) + 1
        self._headers: dict[str, int] = {}  # section -> where its first header line starts
        for match in _HEADER.finditer(text):
            bracket = match.end() - 1
            close = text.find("]", bracket, _line_end(text, bracket))
            if close > 0:
                self._headers.setdefault(text[bracket + 1 : close], match.start())
        self._names: dict[str, dict[str, str | None]] = {}  # section -> name -> value

    @classmethod
    def read(cls, path: str | os.PathLike[str]) -> Ini:
        """Read an INI file.

        A file that cannot be opened raises :class:`NgcConfigError` with rs274's text,
        ``Unable to open inifile:<path>:``; rs274 prints it (after ``executing``), exits 0 if the
        program is fine and otherwise runs exactly as without ``-i``.  A directory reads as an
        empty INI file, as it does for rs274 (no message, but it counts as an INI file).

        Only a regular file (or a directory) is read: a FIFO, a device or a socket, also behind a
        symbolic link, is a file that cannot be opened, refused without waiting (a device is not
        opened, a FIFO is opened with ``O_NONBLOCK``), where rs274 waits forever on a FIFO.  A
        file of more than :data:`MAX_INI_BYTES` is refused (:class:`IniTooLarge`).
        """
        name = os.fspath(path)
        try:
            data = _read_regular(name)
        except IniTooLarge:
            raise
        except OSError as exc:
            raise NgcConfigError(f"Unable to open inifile:{name}:", file=name) from exc
        return cls.parse(data.decode("utf-8", "surrogateescape"), path=name)

    @classmethod
    def parse(cls, text: str, path: str | None = None) -> Ini:
        """An INI file from its text."""
        return cls(text, path)

    @property
    def lines(self) -> tuple[str, ...]:
        """The physical lines, each with its newline when it has one."""
        parts = self.text.split("\n")
        lines = [part + "\n" for part in parts[:-1]]
        if parts[-1]:
            lines.append(parts[-1])
        return tuple(lines)

    @property
    def dos_line_endings(self) -> bool:
        """The file has CR LF line endings (rs274 prints :data:`DOS_LINE_ENDINGS_WARNING`)."""
        return "\r\n" in self.text or self.text.endswith("\r")

    @property
    def ambiguous_carriage_returns(self) -> bool:
        """The file has a CR inside a line (see :data:`AMBIGUOUS_CR_ERROR`)."""
        return self._ambiguous_at <= len(self.text)

    def has_section(self, section: str) -> bool:
        """A ``[section]`` header is in the file (searched or not: see :meth:`get`)."""
        return section in self._headers

    def get(self, section: str, name: str) -> str | None:
        """The value of ``[section]name`` (case-sensitive), or ``None`` when it is not there."""
        names = self._names.get(section)
        if names is None:
            names = self._names[section] = self._section_names(section)
        return names.get(name)

    def _section_names(self, section: str) -> dict[str, str | None]:
        """The names of ``section`` up to the line that ends its search, each with the value of
        its first occurrence (``None``: a line of that name without ``=``, which ends a lookup)."""
        header = self._headers.get(section)
        names: dict[str, str | None] = {}
        if header is None or header >= self._ambiguous_at:
            return names  # no header before the first ambiguous line: never found
        text = self.text
        position = _line_end(text, header) + 1
        while position < len(text):
            logical = self._logical_line(position)
            if logical is None:
                break
            line, position = logical
            stripped = line.lstrip(BLANKS)
            if stripped.startswith("["):
                break
            if stripped.startswith(("#", ";")):
                continue
            match = _NAME.match(stripped)
            key = match.group() if match is not None else ""
            if key not in names:
                equals = stripped.find("=", len(key))
                names[key] = None if equals < 0 else stripped[equals + 1 :].strip(BLANKS)
        return names

    def _logical_line(self, position: int) -> tuple[str, int] | None:
        """The line at ``position`` joined with its continuations, and where the next one
        starts; None where a line of an ambiguous CR or a continuation at the end comes first."""
        text = self.text
        joined = ""
        while position < len(text):
            if position >= self._ambiguous_at:
                return None
            end = _line_end(text, position)
            line = text[position:end]
            position = end + 1
            if end < len(text) and line.endswith("\\"):
                joined += line[:-1]
                continue
            return joined + line, position
        return None

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Ini) and (self.text, self.path) == (other.text, other.path)

    def __hash__(self) -> int:
        return hash((self.text, self.path))

    def __repr__(self) -> str:
        return f"Ini(path={self.path!r}, {len(self.text)} characters)"


def _line_end(text: str, position: int) -> int:
    """Where the line at ``position`` ends: its newline, or the end of the text."""
    end = text.find("\n", position)
    return len(text) if end < 0 else end


def parse_real(text: str | None) -> float | None:
    """An INI value as a real number, or ``None`` when rs274 does not accept it as one.

    >>> parse_real(" 1e3"), parse_real("0x10"), parse_real("2.5abc"), parse_real("1e400")
    (1000.0, None, None, None)
    """
    if text is None:
        return None
    text = text.strip(BLANKS)
    match = _REAL.fullmatch(text)
    if match is None:
        return None
    if match.group("finite") is None:
        magnitude = math.inf if match.group("inf") else math.nan
        return math.copysign(magnitude, -1.0 if match.group("sign") == "-" else 1.0)
    value = float(text)
    return None if math.isinf(value) else value


def parse_int(text: str | None) -> int | None:
    """An INI value as a C ``int`` (decimal, optional sign), or ``None`` when it is not one.

    >>> parse_int("+01"), parse_int("0x1"), parse_int("1.0"), parse_int("4294967296")
    (1, None, None, None)
    """
    if text is None or _INT.fullmatch(text.strip(BLANKS)) is None:
        return None
    value = int(text)
    return value if INT_MIN <= value <= INT_MAX else None


def _ascii_upper(text: str) -> str:
    """Upper case for ASCII letters only, as C ``toupper`` in the C locale."""
    return "".join(chr(ord(c) - 32) if "a" <= c <= "z" else c for c in text)


def ini_parameter(ini: Ini | None, name: str) -> float | None:
    """The value of the named parameter ``#<_ini[section]name>``, or ``None`` if it is not defined.

    ``name`` is the parameter name as the reader has it, lower-cased and without ``#<>``:
    ``"_ini[vars]toolchange_x"``.  rs274 upper-cases section and name before the case-sensitive
    INI lookup (overview.adoc, "HAL pins and INI values"), so ``[VARS]TOOLCHANGE_X`` is found while
    ``[Vars]``, ``[vars]`` or ``ToolChange_X`` in the file never are.  A value that is not a real
    number (:func:`parse_real`) is "not defined" as well: reading it fails with ``Named parameter
    #<_ini[vars]x> not defined``, ``EXISTS[...]`` gives 0 and ``(debug,...)`` shows ``######``.
    The caller also answers ``None`` when ``[RS274NGC]INI_VARS`` is off (:class:`Rs274ngcSettings`).
    The parameters are read-only: assigning one fails with ``Cannot assign to read-only parameter
    #<_ini[vars]x>``.

    >>> ini = Ini.parse("[VARS]\\nTOOLCHANGE_X = 10\\nMixed = 2\\n")
    >>> ini_parameter(ini, "_ini[vars]toolchange_x"), ini_parameter(ini, "_ini[vars]mixed")
    (10.0, None)
    """
    if ini is None or not name.startswith("_ini["):
        return None
    close = name.find("]")
    section = _ascii_upper(name[5:close]) if close > 0 else ""
    if not section:
        return None
    return parse_real(ini.get(section, _ascii_upper(name[close + 1 :])))


def _search_dirs(value: str | None, cwd: str, limit: int) -> tuple[str, ...]:
    """A colon-separated directory list: relative entries are taken from ``cwd`` (not from the
    INI file's directory), empty and non-existent entries are dropped, ``limit`` are kept."""
    dirs: list[str] = []
    for entry in (value or "").split(":"):
        if not entry:
            continue
        try:
            dirs.append(os.path.realpath(os.path.join(cwd, entry), strict=True))
        except (OSError, ValueError):  # no such folder; a NUL byte in the entry
            continue
        if len(dirs) == limit:
            break
    return tuple(dirs)


def _folder(value: str | None, cwd: str) -> str | None:
    """A folder named in the INI file (``~`` expanded, relative to ``cwd``), if it is one."""
    if not value:
        return None
    try:
        path = os.path.realpath(os.path.join(cwd, os.path.expanduser(value)), strict=True)
    except (OSError, ValueError):
        return None
    return path if os.path.isdir(path) else None


def _switch(ini: Ini, section: str, name: str) -> bool:
    """An integer option that is on when non-zero; not an integer (``yes``, ``0x1``, ``1.0``): off."""
    return bool(parse_int(ini.get(section, name)))


def _flag(ini: Ini, name: str, default: bool) -> bool:
    """One of the six former FEATURES options: ``0`` or ``1``; anything else keeps the default
    (``OWORD_NARGS = 2`` is off, ``INI_VARS = 2`` stays on)."""
    value = parse_int(ini.get("RS274NGC", name))
    return default if value not in (0, 1) else value == 1


def _string(ini: Ini, section: str, name: str) -> str | None:
    """A text value; an empty value counts as not set."""
    return ini.get(section, name) or None


def _real(ini: Ini, name: str, default: float) -> float:
    value = parse_real(ini.get("RS274NGC", name))
    return default if value is None else value


def _tolerance(ini: Ini, name: str, low: float, default: float, messages: list[str]) -> float:
    """A radius tolerance: rs274 reports a value it refuses and keeps the default."""
    text = ini.get("RS274NGC", name)
    if not text:
        return default
    value = parse_real(text)
    if value is None or value < low or value > default:
        messages.append(f"invalid [RS274NGC]{name} in INI file")
        return default
    return value


class Rs274ngcSettings(NamedTuple):
    """The INI settings that change what the interpreter does, with rs274's defaults.

    ``Rs274ngcSettings()`` is what rs274 uses without ``-i`` (or with an INI it cannot open).
    Fields marked *not read by rs274* are documented LinuxCNC options that rs274 2.9.0~pre1 does
    not consult (observed); they are parsed so that a user's INI file is not silently lost.
    """

    subroutine_path: tuple[str, ...] = ()
    """[RS274NGC]SUBROUTINE_PATH: ``:``-separated; relative to the current directory; entries that
    do not exist are dropped and at most 10 existing directories are searched."""
    program_prefix: str | None = None
    """[DISPLAY]PROGRAM_PREFIX, as written."""
    program_prefix_dir: str | None = None
    """The folder PROGRAM_PREFIX names (``~`` expanded, relative to the current directory), if
    it is one: searched for subroutine files after the current directory and before
    SUBROUTINE_PATH, as rs274 does."""
    orient_offset: float = 0.0
    """[RS274NGC]ORIENT_OFFSET, added to M19 R; a value that is not a real number reads as 0."""
    center_arc_radius_tolerance_inch: float = CENTER_ARC_RADIUS_TOLERANCE_INCH
    """[RS274NGC]CENTER_ARC_RADIUS_TOLERANCE_INCH; a refused value is reported in ``messages``."""
    center_arc_radius_tolerance_mm: float = CENTER_ARC_RADIUS_TOLERANCE_MM
    """[RS274NGC]CENTER_ARC_RADIUS_TOLERANCE_MM; a refused value is reported in ``messages``."""
    disable_g92_persistence: bool = False
    """[RS274NGC]DISABLE_G92_PERSISTENCE: non-zero integer = on; #5210-#5219 are zeroed after the
    parameter file is read (and so are written back as zeros)."""
    disable_fanuc_style_sub: bool = False
    """[RS274NGC]DISABLE_FANUC_STYLE_SUB: non-zero integer = on; M98 then fails with
    ``DISABLE_FANUC_STYLE_SUB set in INI file, but found m98``."""
    retain_g43: bool = False
    """[RS274NGC]RETAIN_G43 (0/1, anything else keeps the default)."""
    oword_nargs: bool = False
    """[RS274NGC]OWORD_NARGS (0/1): a called subroutine gets ``#<n_args>``."""
    ini_vars: bool = True
    """[RS274NGC]INI_VARS (0/1): ``#<_ini[section]name>`` parameters are defined."""
    hal_pin_vars: bool = True
    """[RS274NGC]HAL_PIN_VARS (0/1)."""
    no_downcase_oword: bool = False
    """[RS274NGC]NO_DOWNCASE_OWORD (0/1)."""
    oword_warnonly: bool = False
    """[RS274NGC]OWORD_WARNONLY (0/1; rs274 2.9.0~pre1 crashes on some O-word errors when it is 1)."""
    tool_change_quill_up: bool = False
    """[EMCIO]TOOL_CHANGE_QUILL_UP (non-zero = on): M6 first rapids Z to machine 0."""
    tool_change_at_g30: bool = False
    """[EMCIO]TOOL_CHANGE_AT_G30 (non-zero = on): M6 first rapids to the G30 position."""
    tool_change_with_spindle_on: bool = False
    """[EMCIO]TOOL_CHANGE_WITH_SPINDLE_ON (non-zero = on): M6 does not stop the spindle."""
    random_toolchanger: bool = False
    """[EMCIO]RANDOM_TOOLCHANGER (non-zero = on)."""
    log_level: int = 0
    """[RS274NGC]LOG_LEVEL."""
    log_file: str | None = None
    """[RS274NGC]LOG_FILE: rs274 creates (truncates) this file, relative to the current directory."""
    on_abort_command: str | None = None
    """[RS274NGC]ON_ABORT_COMMAND, as written."""
    features: int | None = None
    """[RS274NGC]FEATURES (``FEATURE_*`` bits); not read by rs274 2.9.0~pre1."""
    user_m_path: tuple[str, ...] = ()
    """[RS274NGC]USER_M_PATH, resolved like SUBROUTINE_PATH (5 directories); not read by rs274,
    which reports M100-M199 as ``Unknown m code used``."""
    parameter_file: str | None = None
    """[RS274NGC]PARAMETER_FILE; not read by rs274 (only ``-v`` names a parameter file)."""
    startup_code: str | None = None
    """[RS274NGC]RS274NGC_STARTUP_CODE; not read by rs274."""
    g64_default_tolerance: float = 0.0
    """[RS274NGC]G64_DEFAULT_TOLERANCE; not read by rs274."""
    g64_default_naivetolerance: float = 0.0
    """[RS274NGC]G64_DEFAULT_NAIVETOLERANCE; not read by rs274."""
    disable_auto_g54: bool = False
    """[RS274NGC]DISABLE_AUTO_G54; not read by rs274 (M2/M30 always return to G54)."""
    g73_peck_clearance: float | None = None
    """[RS274NGC]G73_PECK_CLEARANCE in machine units; not read by rs274."""
    g83_peck_clearance: float | None = None
    """[RS274NGC]G83_PECK_CLEARANCE in machine units; not read by rs274."""
    messages: tuple[str, ...] = ()
    """What rs274 reports about the settings while it starts, in order.  rs274 prints each one as
    an error report with an empty source line (``message`` newline, newline) and carries on."""

    @classmethod
    def from_ini(cls, ini: Ini | None, cwd: str) -> Rs274ngcSettings:
        """The settings of ``ini`` (``None``: rs274's defaults); ``cwd`` anchors relative paths.

        >>> s = Rs274ngcSettings.from_ini(Ini.parse("[RS274NGC]\\nORIENT_OFFSET = 42\\n"), ".")
        >>> s.orient_offset, s.ini_vars, s.oword_nargs
        (42.0, True, False)
        """
        if ini is None:
            return cls()
        messages: list[str] = []
        inch = _tolerance(
            ini,
            "CENTER_ARC_RADIUS_TOLERANCE_INCH",
            MIN_CENTER_ARC_RADIUS_TOLERANCE_INCH,
            CENTER_ARC_RADIUS_TOLERANCE_INCH,
            messages,
        )
        mm = _tolerance(
            ini,
            "CENTER_ARC_RADIUS_TOLERANCE_MM",
            MIN_CENTER_ARC_RADIUS_TOLERANCE_MM,
            CENTER_ARC_RADIUS_TOLERANCE_MM,
            messages,
        )
        return cls(
            subroutine_path=_search_dirs(
                ini.get("RS274NGC", "SUBROUTINE_PATH"), cwd, SUBROUTINE_PATH_MAX_DIRS
            ),
            program_prefix=_string(ini, "DISPLAY", "PROGRAM_PREFIX"),
            program_prefix_dir=_folder(_string(ini, "DISPLAY", "PROGRAM_PREFIX"), cwd),
            orient_offset=_real(ini, "ORIENT_OFFSET", 0.0),
            center_arc_radius_tolerance_inch=inch,
            center_arc_radius_tolerance_mm=mm,
            disable_g92_persistence=_switch(ini, "RS274NGC", "DISABLE_G92_PERSISTENCE"),
            disable_fanuc_style_sub=_switch(ini, "RS274NGC", "DISABLE_FANUC_STYLE_SUB"),
            retain_g43=_flag(ini, "RETAIN_G43", False),
            oword_nargs=_flag(ini, "OWORD_NARGS", False),
            ini_vars=_flag(ini, "INI_VARS", True),
            hal_pin_vars=_flag(ini, "HAL_PIN_VARS", True),
            no_downcase_oword=_flag(ini, "NO_DOWNCASE_OWORD", False),
            oword_warnonly=_flag(ini, "OWORD_WARNONLY", False),
            tool_change_quill_up=_switch(ini, "EMCIO", "TOOL_CHANGE_QUILL_UP"),
            tool_change_at_g30=_switch(ini, "EMCIO", "TOOL_CHANGE_AT_G30"),
            tool_change_with_spindle_on=_switch(ini, "EMCIO", "TOOL_CHANGE_WITH_SPINDLE_ON"),
            random_toolchanger=_switch(ini, "EMCIO", "RANDOM_TOOLCHANGER"),
            log_level=parse_int(ini.get("RS274NGC", "LOG_LEVEL")) or 0,
            log_file=_string(ini, "RS274NGC", "LOG_FILE"),
            on_abort_command=_string(ini, "RS274NGC", "ON_ABORT_COMMAND"),
            features=parse_int(ini.get("RS274NGC", "FEATURES")),
            user_m_path=_search_dirs(ini.get("RS274NGC", "USER_M_PATH"), cwd, USER_M_PATH_MAX_DIRS),
            parameter_file=_string(ini, "RS274NGC", "PARAMETER_FILE"),
            startup_code=_string(ini, "RS274NGC", "RS274NGC_STARTUP_CODE"),
            g64_default_tolerance=_real(ini, "G64_DEFAULT_TOLERANCE", 0.0),
            g64_default_naivetolerance=_real(ini, "G64_DEFAULT_NAIVETOLERANCE", 0.0),
            disable_auto_g54=_switch(ini, "RS274NGC", "DISABLE_AUTO_G54"),
            g73_peck_clearance=parse_real(ini.get("RS274NGC", "G73_PECK_CLEARANCE")),
            g83_peck_clearance=parse_real(ini.get("RS274NGC", "G83_PECK_CLEARANCE")),
            messages=tuple(messages),
        )
