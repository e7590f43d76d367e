"""``ngc check --dialect grbl`` (or ``grblhal``): each file's lines held against Grbl 1.1 (or
grblHAL: a row of :data:`ngc.grbl.DIALECTS`), its rejected lines on stderr, a summary line (or
a JSON object) on stdout; its exit code.

``prog.ngc:12: error:33 Motion command target is invalid. (G2 X10 Y0 I3 J0)`` per rejected
line, as they are found (``prog.ngc:14: not checked: ... (G81 ...)`` for a line with a code
the row does not check); then ``prog.ngc: 54 lines, Grbl 1.1 accepts all`` or ``prog.ngc: 54
lines, Grbl 1.1 rejects 3``.  Exit 2 if a file cannot be read or a machine input is given (Grbl
checks the program alone), else 1 if a line is rejected or not checked, else 0.
"""

from __future__ import annotations

import argparse
import io
import sys
from collections.abc import Iterator

from ..canon.jsonl import dumps
from ..grbl import DIALECTS, Checker, GrblError
from ..grbl.lines import EndlessLine, read_lines
from .common import (
    EXIT_OK,
    EXIT_PROGRAM_ERROR,
    EXIT_USAGE,
    LINUXCNC_INPUTS,
    display_name,
    each_file,
    open_binary,
    progress_of,
)

# the machine inputs of the other dialects, as options: (attribute, flag)
MACHINE_INPUTS = (*LINUXCNC_INPUTS, ("setup_file", "--setup"), ("machine_file", "--machine"))


def run(options: argparse.Namespace) -> int:
    """``ngc check --dialect grbl FILE...`` (``-j N``: N files at once, output in their order)."""
    given = [flag for attribute, flag in MACHINE_INPUTS
             if getattr(options, attribute, None) is not None]
    if getattr(options, "any_tool", False):
        given.append("--any-tool")
    if given:
        what = "is a machine input" if len(given) == 1 else "are machine inputs"
        sys.stderr.write(f"ngc check: {', '.join(given)} {what} of the other dialects: "
                         f"--dialect {options.dialect} checks each line as the controller does, "
                         "with no machine\n")
        return EXIT_USAGE
    return each_file(options, _check_file, "")


def _check_file(options: argparse.Namespace, path: str) -> int:
    """One file: its rejected lines on stderr as found, its summary on stdout; its exit code."""
    name = display_name(path)
    json_lines = options.format == "json"
    row = options.dialect
    checker = Checker(DIALECTS[row])
    kept: list[GrblError] = []
    try:
        handle = open_binary(path)
    except OSError as exc:
        return _cannot(name, "open", exc.strerror, json_lines, row)
    try:
        for error in _errors(name, handle, checker):
            status = "" if error.code is None else f"error:{error.code} "
            sys.stderr.write(f"{name}:{error.line}: {status}{error.message} "
                             f"({error.text.strip()})\n")
            if json_lines:
                kept.append(error)
    except (OSError, EndlessLine) as exc:
        return _cannot(name, "read", exc.strerror if isinstance(exc, OSError) else str(exc),
                       json_lines, row)
    sys.stdout.write((dumps(_record(name, checker, kept, row)) if json_lines
                      else _summary(name, checker)) + "\n")
    return EXIT_PROGRAM_ERROR if checker.rejected or checker.unchecked_lines else EXIT_OK


def _errors(name: str, handle: io.BufferedReader, checker: Checker) -> Iterator[GrblError]:
    """The rejected lines of a program file (UTF-8, bytes that are not kept as they are: Grbl
    drops them all the same), read a line at a time; the progress line on a terminal."""
    line_chars = checker.grbl.rules.line_chars
    with (io.TextIOWrapper(handle, encoding="utf-8", errors="surrogateescape",
                           newline="") as stream,
          progress_of(name, handle, output_to_terminal=False) as progress):
        for error in checker.errors(progress.lines(read_lines(stream, line_chars))):
            progress.close()  # (it is shown again at its next paint)
            yield error


def _summary(name: str, checker: Checker) -> str:
    """``prog.ngc: 54 lines, Grbl 1.1 accepts all`` (or ``rejects 3``), and the lines of ``$``
    system commands, which are not checked."""
    rules = checker.grbl.rules
    verdict = f"rejects {checker.rejected}" if checker.rejected else "accepts all"
    text = f"{name}: {checker.lines} lines, {rules.name} {verdict}"
    system = len(checker.system_lines)
    if system:
        text += f"; {system} {'line' if system == 1 else 'lines'} of $ system commands not checked"
    unchecked = len(checker.unchecked_lines)
    if unchecked:
        text += (f"; {unchecked} {'line' if unchecked == 1 else 'lines'} with codes "
                 f"{rules.name} takes but this check does not model, not checked")
    return text


def _record(name: str, checker: Checker, errors: list[GrblError],
            row: str) -> dict[str, object]:
    """``--format json``'s object for one file (``unchecked_lines`` only when a row has
    codes it does not check)."""
    record: dict[str, object] = {
        "file": name, "dialect": row, "controller": checker.grbl.rules.name,
        "ok": not checker.rejected and not checker.unchecked_lines, "lines": checker.lines,
        "rejected": checker.rejected, "errors": [error._asdict() for error in errors],
        "system_lines": checker.system_lines,
    }  # fmt: skip
    if checker.unchecked_lines:
        record["unchecked_lines"] = checker.unchecked_lines
    return record


def _cannot(name: str, what: str, reason: str | None, json_lines: bool, row: str) -> int:
    """A file that cannot be opened or read: said on stderr (and in its JSON object, shaped as
    ``ngc check`` shapes it); exit 2."""
    sys.stderr.write(f"ngc check: cannot {what} {name}: {reason}\n")
    if json_lines:
        error = {"message": f"cannot {what}: {reason}", "about": None, "file": name,
                 "line": None, "column": None, "source": None}
        sys.stdout.write(dumps({"file": name, "dialect": row, "ok": False, "lines": None,
                                "error": error, "rejected": None, "errors": None,
                                "system_lines": None}) + "\n")
    return EXIT_USAGE
