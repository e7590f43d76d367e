"""INI files: syntax, ``#<_ini[section]name>`` lookups and the interpreter settings.

Expected values are what LinuxCNC's ``rs274`` 2.9.0~pre1 was observed to do (values read through
``#<_ini[...]>`` in ``(debug,...)`` comments, string values through the file ``LOG_FILE`` creates,
settings through their effect on the canon output); each table says so once.
"""

from __future__ import annotations

import io
import math
import os
import re
import subprocess
from pathlib import Path

import pytest

from ngc.commands import rs274
from ngc.config import ini as ini_module
from ngc.config.ini import (
    AMBIGUOUS_CR_ERROR,
    CENTER_ARC_RADIUS_TOLERANCE_INCH,
    CENTER_ARC_RADIUS_TOLERANCE_MM,
    DOS_LINE_ENDINGS_WARNING,
    Ini,
    Rs274ngcSettings,
    ini_parameter,
    parse_int,
    parse_real,
)
from ngc.errors import NgcConfigError

RS274 = "/usr/bin/rs274"

# -- INI syntax ----------------------------------------------------------------------------------

# (file text, section, name, value); rs274 was observed to read each of these values.
SYNTAX = [
    ("[S]\nA = 1\n", "S", "A", "1"),
    ("[S]\n  C   =   5   \n", "S", "C", "5"),
    ("[S]\nTAB\t=\t11\t\n", "S", "TAB", "11"),
    ("[S]\nB=4\n", "S", "B", "4"),
    ("[S]\nF = 8\nF = 9\n", "S", "F", "8"),  # the first occurrence wins
    ("[S]\nF =\nF = 9\n", "S", "F", ""),  # ... even when it is empty
    ("[S]\nD = 6 # trailing\n", "S", "D", "6 # trailing"),  # no comments inside values
    ("[S]\nE = 7 ; trailing\n", "S", "E", "7 ; trailing"),
    ('[S]\nQ = "1"\n', "S", "Q", '"1"'),  # quotes are plain characters
    ("[S]\nESC = \\x31\n", "S", "ESC", "\\x31"),  # escapes are not decoded
    ("[S]\nE2 == 12\n", "S", "E2", "= 12"),
    ("[S]\nE3 = 1 = 2\n", "S", "E3", "1 = 2"),
    ("[S]\nSP ACE = 9\n", "S", "SP", "9"),  # the name is the first word
    ("[S]\nLOG_FILE x y = z\n", "S", "LOG_FILE", "z"),
    ("[S]\n1DIG = 13\n", "S", "1DIG", "13"),
    ("[S]\nCONT = 1\\\n5\n", "S", "CONT", "15"),  # continuation
    ("[S]\nA = a\\\n   b\n", "S", "A", "a   b"),
    ("[S]\nA = a \\\nb\n", "S", "A", "a b"),
    ("[S]\nA = a\\\nb\\\nc\n", "S", "A", "abc"),
    ("[S]\nA = a\\\n#b\n", "S", "A", "a#b"),
    ("[S]\nA = a\\\n[X]\n", "S", "A", "a[X]"),
    ("[S]\nA = \\\nb\n", "S", "A", "b"),
    ("[S]\nA = a\\\n\nb\n", "S", "A", "a"),
    ("[S]\nA = a\\  \nb\n", "S", "A", "a\\"),  # blanks after the backslash: no continuation
    ("[S]\nA = a\\\r\nb\r\n", "S", "A", "a\\"),  # nor a CR
    ("[S]\nA = a\\", "S", "A", "a\\"),  # nor the end of the file
    ("[S]\nA = a\\\\\nb\n", "S", "A", "a\\b"),
    ("[S]\n# c \\\nA = 1\nA = 2\n", "S", "A", "2"),  # a comment continues too
    ("[S]\nO = a\\\nA = 1\nA = 2\n", "S", "A", "2"),
    ("[S]\nX = 1\\\n[T]\nA = 3\n", "S", "A", "3"),
    ("[S]\\\nA = 5\n", "S", "A", "5"),
    ("[S]\nCR = 7\r\n", "S", "CR", "7"),
    ("[S]\n\tA = u\n", "S", "A", "u"),
    ("[S]\nA = a\tb\n", "S", "A", "a\tb"),
    ("[S] \nZ = 3\n", "S", "Z", "3"),
    (" [S]\nZ = 4\n", "S", "Z", "4"),
    ("[S] # c\nZ = 6\n", "S", "Z", "6"),
    ("[S]x\nZ = 1\n", "S", "Z", "1"),
    ("[S]]\nZ = 1\n", "S", "Z", "1"),
    ("[X]\nA = a\\\n[S]\nZ = 1\n", "S", "Z", "1"),  # headers are found in the raw lines
    ("[S]\nA = \u00e9\n", "S", "A", "\u00e9"),
]

# (file text, section, name); rs274 was observed not to find these.
NOT_FOUND = [
    ("A = 100\n[S]\n", "S", "A"),  # before any section
    ("[S]\nA\n", "S", "A"),
    ("[S]\nA x\nA = 2\n", "S", "A"),  # the name without "=" ends the search
    ("[S]\nAx = 1\n", "S", "A"),
    ("[S]\na = 1\n", "S", "A"),  # names are case-sensitive
    ("[s]\nA = 1\n", "S", "A"),  # so are sections
    ("[ S ]\nA = 1\n", "S", "A"),
    ("[[S]\nA = 1\n", "S", "A"),
    ("[S\nA = 1\n", "S", "A"),
    ("[S]\nX = 1\n[U\nA = 1\n", "S", "A"),  # any "[" line ends the section
    ("[S]\nX = 1\n  [U]\nA = 1\n", "S", "A"),
    ("[S]\nX = 1\n[S]\nA = 1\n", "S", "A"),  # only the first [S] is searched
    ("[S]\n#A = 1\n", "S", "A"),
    ("[S]\n;A = 1\n", "S", "A"),
    ("[S]\nA = a\\\n", "S", "A"),  # a continuation with nothing after it
    ("[S]\nB = 1\rX\nA = 2\n", "S", "A"),  # reading across an ambiguous CR fails
    ("[T]\nB = 1\rX\n[S]\nA = 2\n", "S", "A"),
]


@pytest.mark.parametrize(("text", "section", "name", "value"), SYNTAX)
def test_values_rs274_reads(text: str, section: str, name: str, value: str) -> None:
    assert Ini.parse(text).get(section, name) == value


@pytest.mark.parametrize(("text", "section", "name"), NOT_FOUND)
def test_values_rs274_does_not_find(text: str, section: str, name: str) -> None:
    assert Ini.parse(text).get(section, name) is None


def test_lookups_before_an_ambiguous_cr_work() -> None:
    ini = Ini.parse("[RS274NGC]\nINI_VARS = 0\n[S]\nA = 1\rB\nC = 2\n")
    assert ini.get("RS274NGC", "INI_VARS") == "0"
    assert ini.get("S", "A") is None and ini.get("S", "C") is None
    assert ini.ambiguous_carriage_returns and not ini.dos_line_endings


def test_carriage_return_diagnostics() -> None:
    # Printed by rs274 on stderr after "executing" (the error once per failing lookup).
    assert DOS_LINE_ENDINGS_WARNING == "inifile: warning: File contains DOS-style line endings."
    assert AMBIGUOUS_CR_ERROR == "inifile: error: File contains ambiguous carriage returns"
    for text in ("[S]\r\n", "[S]\nC = 2\r", "# c\r\n[S]\nC = 2\n"):
        assert Ini.parse(text).dos_line_endings
        assert not Ini.parse(text).ambiguous_carriage_returns
    assert not Ini.parse("[S]\nA = 1\n").dos_line_endings


def test_read_missing_unreadable_and_directory(tmp_path: Path) -> None:
    # rs274 -i missing.ini: stderr "Unable to open inifile:missing.ini:", rc 0, run as without -i.
    with pytest.raises(NgcConfigError) as caught:
        Ini.read("missing.ini")
    assert caught.value.message == "Unable to open inifile:missing.ini:"
    # A directory: no message, an empty INI file.
    assert Ini.read(tmp_path).lines == ()
    path = tmp_path / "a.ini"
    path.write_bytes(b"[S]\r\nA = 1\r\n")
    ini = Ini.read(path)
    assert ini.get("S", "A") == "1" and ini.path == str(path) and ini.dos_line_endings


@pytest.fixture
def fifo(tmp_path: Path) -> Path:
    path = tmp_path / "f.ini"
    os.mkfifo(path)
    return path


@pytest.mark.parametrize("kind", ["fifo", "link-to-fifo", "/dev/null", "/dev/zero"])
def test_read_refuses_fifos_and_devices_without_blocking(fifo: Path, kind: str) -> None:
    name = {"fifo": str(fifo), "link-to-fifo": str(fifo.parent / "l.ini")}.get(kind, kind)
    if kind == "link-to-fifo":
        os.symlink(fifo, name)
    with pytest.raises(NgcConfigError) as caught:
        Ini.read(name)
    assert caught.value.message == f"Unable to open inifile:{name}:"
    assert caught.value.file == name


def test_read_checks_what_it_opened(fifo: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # A FIFO put in place after the first look is opened without blocking, then refused.
    def missing(path: object) -> os.stat_result:
        raise FileNotFoundError(2, "No such file or directory")

    monkeypatch.setattr(ini_module.os, "stat", missing)
    with pytest.raises(NgcConfigError) as caught:
        Ini.read(fifo)
    assert caught.value.message == f"Unable to open inifile:{fifo}:"


def test_rs274_reports_a_fifo_ini_file_and_runs_without_it(
    fifo: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # As for an INI file rs274 cannot open: the message after "executing", then the run, rc 0.
    monkeypatch.chdir(fifo.parent)
    Path("p.ngc").write_text("G0 X1\nM2\n")
    out, err = io.StringIO(), io.StringIO()
    assert rs274.run(["-i", "f.ini", "-g", "p.ngc"], stdout=out, stderr=err) == 0
    assert err.getvalue() == "executing\nUnable to open inifile:f.ini:\n"
    plain = io.StringIO()
    assert rs274.run(["-g", "p.ngc"], stdout=plain, stderr=io.StringIO()) == 0
    assert out.getvalue() == plain.getvalue()


# -- numbers -------------------------------------------------------------------------------------

# rs274 was observed to accept these as real numbers (ORIENT_OFFSET and #<_ini[...]> alike) ...
REALS = [
    ("42", 42.0),
    ("42.5", 42.5),
    ("1e1", 10.0),
    ("1E+1", 10.0),
    ("1.e5", 1e5),
    (".5", 0.5),
    ("5.", 5.0),
    ("-3", -3.0),
    ("+2", 2.0),
    ("00012", 12.0),
    ("1e-400", 0.0),
    ("1e308", 1e308),
    ("inf", math.inf),
    ("INF", math.inf),
    ("+inf", math.inf),
    ("-inf", -math.inf),
    ("Infinity", math.inf),
]
# ... and to refuse these (ORIENT_OFFSET stays 0, the parameter is not defined).
NOT_REALS = [
    "abc",
    "42 # c",
    "0x10",
    "0x1p3",
    "",
    "1,5",
    "1e",
    "1e+",
    "42abc",
    "1e400",
    "1_0",
    "- 1",
    "infinit",
    "2.5abc",
]


@pytest.mark.parametrize(("text", "value"), REALS)
def test_parse_real(text: str, value: float) -> None:
    assert parse_real(text) == value


@pytest.mark.parametrize("text", NOT_REALS)
def test_parse_real_refuses(text: str) -> None:
    assert parse_real(text) is None


def test_parse_real_nan() -> None:
    for text in ("nan", "NAN", "+nan", "nan(12)", "nan()", "nan(a b)"):
        value = parse_real(text)
        assert value is not None and math.isnan(value) and math.copysign(1.0, value) == 1.0
    value = parse_real("-nan")
    assert value is not None and math.isnan(value) and math.copysign(1.0, value) == -1.0


def test_parse_int() -> None:
    # Observed through DISABLE_FANUC_STYLE_SUB and OWORD_NARGS.
    assert [parse_int(t) for t in ("1", "+1", "01", "-0", "2147483647", "-2147483648")] == [
        1,
        1,
        1,
        0,
        2147483647,
        -2147483648,
    ]
    for text in ("0x1", "1.0", "true", "yes", "1e0", "1x", "2147483648", "-2147483649", "", None):
        assert parse_int(text) is None


# -- #<_ini[section]name> ------------------------------------------------------------------------

VARS = Ini.parse(
    "[RS274NGC]\nINI_VARS = 1\n\n[VARS]\nTOOLCHANGE_X = 10\nTOOLCHANGE_Y = 20\nTOOLCHANGE_Z = 30\n"
    "MixedName = 2\nlower = 3\nI = abc\nG = 0x10\nJ =\nT = inf\nU = nan\n= 5\n"
    "[Mixed]\nX = 11\n[MIXED]\nX = 12\n[]\nB = 7\n"
)


@pytest.mark.parametrize(
    ("name", "value"),
    [
        # corpus case interp-iniparam: #<_ini[vars]toolchange_x> and friends
        ("_ini[vars]toolchange_x", 10.0),
        ("_ini[vars]toolchange_y", 20.0),
        ("_ini[vars]toolchange_z", 30.0),
        ("_ini[nosuchsection]nosuchname", None),
        # probed: names are upper-cased, so mixed- or lower-case INI entries are unreachable
        ("_ini[vars]mixedname", None),
        ("_ini[vars]lower", None),
        ("_ini[mixed]x", 12.0),
        # probed: values that are not real numbers are not defined
        ("_ini[vars]i", None),
        ("_ini[vars]g", None),
        ("_ini[vars]j", None),
        ("_ini[vars]t", math.inf),
        ("_ini[vars]", 5.0),
        ("_ini[]b", None),
        ("_hal[vars]toolchange_x", None),
    ],
)
def test_ini_parameter(name: str, value: float | None) -> None:
    assert ini_parameter(VARS, name) == value


def test_ini_parameter_without_ini() -> None:
    # rs274 without -i: #<_ini[vars]a> is not defined.
    assert ini_parameter(None, "_ini[vars]a") is None
    nan = ini_parameter(VARS, "_ini[vars]u")
    assert nan is not None and math.isnan(nan)


# -- settings ------------------------------------------------------------------------------------


def settings(text: str, cwd: str = ".") -> Rs274ngcSettings:
    return Rs274ngcSettings.from_ini(Ini.parse(text), cwd)


def test_defaults_are_rs274s() -> None:
    default = Rs274ngcSettings()
    assert Rs274ngcSettings.from_ini(None, ".") == default
    assert settings("") == default
    assert settings("[RS274NGC]\n") == default
    assert default.ini_vars and default.hal_pin_vars
    assert not (default.oword_nargs or default.disable_g92_persistence or default.disable_fanuc_style_sub)
    assert default.orient_offset == 0.0 and default.subroutine_path == ()
    # Observed thresholds of the radius check without an INI: 0.0028284 inch, 0.0282843 mm.
    assert CENTER_ARC_RADIUS_TOLERANCE_INCH == 0.0028284271247461905
    assert CENTER_ARC_RADIUS_TOLERANCE_MM == 0.028284271247461905
    assert default.messages == ()


@pytest.mark.parametrize(
    ("value", "on"),
    # Observed with DISABLE_G92_PERSISTENCE, DISABLE_FANUC_STYLE_SUB and [EMCIO]TOOL_CHANGE_*.
    [
        ("1", True),
        ("2", True),
        ("-1", True),
        ("01", True),
        ("0", False),
        ("-0", False),
        ("0x1", False),
        ("1.0", False),
        ("true", False),
        ("yes", False),
        ("4294967296", False),
    ],
)
def test_integer_switches(value: str, on: bool) -> None:
    s = settings(
        f"[RS274NGC]\nDISABLE_G92_PERSISTENCE = {value}\nDISABLE_FANUC_STYLE_SUB = {value}\n"
        f"[EMCIO]\nTOOL_CHANGE_QUILL_UP = {value}\nTOOL_CHANGE_AT_G30 = {value}\n"
        f"TOOL_CHANGE_WITH_SPINDLE_ON = {value}\n"
    )
    assert s.disable_g92_persistence is on and s.disable_fanuc_style_sub is on
    assert s.tool_change_quill_up is on and s.tool_change_at_g30 is on
    assert s.tool_change_with_spindle_on is on


@pytest.mark.parametrize(
    ("value", "nargs", "ini_vars"),
    # Observed: OWORD_NARGS defines #<n_args> only for 1; INI_VARS turns off only for 0.
    [
        ("1", True, True),
        ("+1", True, True),
        ("0000001", True, True),
        ("0", False, False),
        ("00", False, False),
        ("+0", False, False),
        ("-0", False, False),
        ("2", False, True),
        ("-1", False, True),
        ("0x1", False, True),
        ("1.0", False, True),
        ("yes", False, True),
        ("1 #c", False, True),
        ("4294967296", False, True),
    ],
)
def test_former_feature_flags(value: str, nargs: bool, ini_vars: bool) -> None:
    s = settings(f"[RS274NGC]\nOWORD_NARGS = {value}\nINI_VARS = {value}\n")
    assert s.oword_nargs is nargs and s.ini_vars is ini_vars


def test_features_is_parsed_but_changes_nothing() -> None:
    # Observed: FEATURES = 0 keeps #<_ini[...]>, FEATURES = 2 gives no #<n_args>.
    assert settings("[RS274NGC]\nFEATURES = 0\n").ini_vars
    s = settings("[RS274NGC]\nFEATURES = 2\n")
    assert s.features == 2 and not s.oword_nargs
    assert settings("[RS274NGC]\nFEATURES = abc\n").features is None


@pytest.mark.parametrize(
    ("value", "offset"),
    # Observed as ORIENT_SPINDLE(0, <offset>, 0) for M19 R0.
    [
        ("42.0", 42.0),
        ("42.5", 42.5),
        ("abc", 0.0),
        ("42 # c", 0.0),
        ("0x10", 0.0),
        ("1e1", 10.0),
        ("", 0.0),
        ("1e400", 0.0),
        ("-3", -3.0),
    ],
)
def test_orient_offset(value: str, offset: float) -> None:
    assert settings(f"[RS274NGC]\nORIENT_OFFSET = {value}\n").orient_offset == offset


@pytest.mark.parametrize(
    ("inch", "mm", "messages"),
    [
        ("0.001", "0.01", ()),
        ("0.00004", "0.001", ()),
        ("0.0028284271247461905", "0.028284271247461905", ()),
        ("nan", "nan", ()),
        ("", "", ()),
        ("0.00003", "0.02", ("invalid [RS274NGC]CENTER_ARC_RADIUS_TOLERANCE_INCH in INI file",)),
        (
            "0.002828427124746191",
            "0.0009999999999999998",
            (
                "invalid [RS274NGC]CENTER_ARC_RADIUS_TOLERANCE_INCH in INI file",
                "invalid [RS274NGC]CENTER_ARC_RADIUS_TOLERANCE_MM in INI file",
            ),
        ),
        ("0.001", "abc", ("invalid [RS274NGC]CENTER_ARC_RADIUS_TOLERANCE_MM in INI file",)),
        ("0.001", "0x1", ("invalid [RS274NGC]CENTER_ARC_RADIUS_TOLERANCE_MM in INI file",)),
        ("0.001", "-1", ("invalid [RS274NGC]CENTER_ARC_RADIUS_TOLERANCE_MM in INI file",)),
        (
            "inf",
            "0",
            (
                "invalid [RS274NGC]CENTER_ARC_RADIUS_TOLERANCE_INCH in INI file",
                "invalid [RS274NGC]CENTER_ARC_RADIUS_TOLERANCE_MM in INI file",
            ),
        ),
    ],
)
def test_arc_tolerances(inch: str, mm: str, messages: tuple[str, ...]) -> None:
    # Observed: the messages (each followed by an empty line on stderr), rc 0, defaults kept.
    s = settings(
        f"[RS274NGC]\nCENTER_ARC_RADIUS_TOLERANCE_INCH = {inch}\nCENTER_ARC_RADIUS_TOLERANCE_MM = {mm}\n"
    )
    assert s.messages == messages
    refused = " ".join(messages)
    if "INCH" in refused or not inch:
        assert s.center_arc_radius_tolerance_inch == CENTER_ARC_RADIUS_TOLERANCE_INCH
    if inch == "0.001":
        assert s.center_arc_radius_tolerance_inch == 0.001
    if "_MM" in refused or not mm:
        assert s.center_arc_radius_tolerance_mm == CENTER_ARC_RADIUS_TOLERANCE_MM


def test_subroutine_path(tmp_path: Path) -> None:
    # Observed: ":"-separated, relative to the current directory (not the INI file's), empty and
    # missing entries skipped, at most 10 existing directories searched.
    names = [f"d{i}" for i in range(12)]
    for name in names:
        (tmp_path / name).mkdir()
    s = settings(f"[RS274NGC]\nSUBROUTINE_PATH = nope::{':'.join(names)}\n", str(tmp_path))
    assert s.subroutine_path == tuple(str(tmp_path / name) for name in names[:10])
    assert settings("[RS274NGC]\nSUBROUTINE_PATH = d0;d1\n", str(tmp_path)).subroutine_path == ()
    assert settings("[RS274NGC]\nSUBROUTINE_PATH = d0: d1\n", str(tmp_path)).subroutine_path == (
        str(tmp_path / "d0"),
    )
    absolute = settings(f"[RS274NGC]\nSUBROUTINE_PATH = {tmp_path / 'd3'}\n", "/")
    assert absolute.subroutine_path == (str(tmp_path / "d3"),)
    with_nul = settings("[RS274NGC]\nSUBROUTINE_PATH = d\0:d1\n", str(tmp_path))
    assert with_nul.subroutine_path == (str(tmp_path / "d1"),)  # a NUL byte: no such folder


def test_corpus_ini_files() -> None:
    # The [RS274NGC] lines of the conformance corpus INI files.
    assert settings("[RS274NGC]\nORIENT_OFFSET = 42.0\n").orient_offset == 42.0
    assert settings("[RS274NGC]\nDISABLE_G92_PERSISTENCE = 1\n").disable_g92_persistence
    assert not settings("[RS274NGC]\nDISABLE_G92_PERSISTENCE = 0\n").disable_g92_persistence
    no_fanuc = settings(
        "[RS274NGC]\nDISABLE_FANUC_STYLE_SUB = 1\n[EMC]\nDEBUG = 2147483647\nRCS_DEBUG = 0x05400f01\n"
    )
    assert no_fanuc.disable_fanuc_style_sub
    abort = settings(
        "[RS274NGC]\n# enable #<_ini[section]name> expansion\nINI_VARS = 1\n\n[A]\nVALUE= 3.14\n"
    )
    assert abort.ini_vars
    assert ini_parameter(Ini.parse("[A]\nVALUE= 3.14\n"), "_ini[a]value") == 3.14


def test_strings_and_ignored_options() -> None:
    s = settings(
        "[RS274NGC]\nLOG_FILE = my log.txt \nLOG_LEVEL = 3\nPARAMETER_FILE = pf.var\n"
        "RS274NGC_STARTUP_CODE = G17 G20\nON_ABORT_COMMAND=O <on_abort> call\n"
        "G73_PECK_CLEARANCE = .02\nDISABLE_AUTO_G54 = 1\n[DISPLAY]\nPROGRAM_PREFIX = ~/nc\n"
    )
    assert s.log_file == "my log.txt" and s.log_level == 3
    assert s.parameter_file == "pf.var" and s.startup_code == "G17 G20"
    assert s.on_abort_command == "O <on_abort> call" and s.program_prefix == "~/nc"
    assert s.g73_peck_clearance == 0.02 and s.g83_peck_clearance is None and s.disable_auto_g54
    assert settings("[RS274NGC]\nLOG_FILE =\n").log_file is None


# -- against the reference -----------------------------------------------------------------------

LIVE_INI = (
    "[RS274NGC]\nINI_VARS = 1\n[VARS]\nA = 1\nMixedName = 2\nB=4\n  C   =   5   \nD = 6 # x\n"
    "F = 8\nF = 9\nG = 0x10\nH = 1e3\nI = abc\nK = 2.5abc\nM = -4.5\nO = 7\\\n8\n"
    "[Mixed]\nX = 11\n[VARS]\nV = 14\n"
)
LIVE_NAMES = ["a", "mixedname", "b", "c", "d", "f", "g", "h", "i", "k", "m", "o", "v", "zz"]


@pytest.mark.skipif(not os.path.exists(RS274), reason="needs LinuxCNC's rs274")
def test_ini_parameters_against_rs274(tmp_path: Path) -> None:
    (tmp_path / "t.ini").write_text(LIVE_INI)
    program = (
        "".join(f"(debug,{n}=#<_ini[vars]{n}>)\n" for n in LIVE_NAMES) + "(debug,x=#<_ini[mixed]x>)\nM2\n"
    )
    (tmp_path / "t.ngc").write_text(program)
    home = tmp_path / "home"
    home.mkdir()
    done = subprocess.run(
        [RS274, "-i", "t.ini", "-g", "t.ngc"],
        cwd=tmp_path,
        env={"HOME": str(home), "LC_ALL": "C", "PATH": os.environ.get("PATH", "")},
        stdin=subprocess.DEVNULL,
        capture_output=True,
        text=True,
        timeout=20,
        check=False,
    )
    ini = Ini.parse(LIVE_INI)
    expected = []
    for name, section in [(n, "vars") for n in LIVE_NAMES] + [("x", "mixed")]:
        value = ini_parameter(ini, f"_ini[{section}]{name}")
        expected.append(f"{name}=" + ("######" if value is None else f"{value:f}"))
    assert re.findall(r'MESSAGE\("([^"]*)"\)', done.stdout) == expected
