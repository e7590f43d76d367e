"""``ngc flatten`` on the command line: the program written plain for a target, verified, to
OUT (or stdout); nothing is written for a program that is refused or does not verify."""

from __future__ import annotations

import argparse
import os
import stat
import sys
import tempfile

from .. import dialects
from ..dialects import ENGINE
from ..errors import NgcConfigError, NgcError
from ..options import new_interpreter
from .common import (
    EXIT_OK,
    EXIT_PROGRAM_ERROR,
    EXIT_USAGE,
    cannot_open,
    display_name,
    inputs_conflict,
    load_inputs,
    open_marked,
)


def run(options: argparse.Namespace) -> int:
    """Exit 2 for a bad command line, machine input, or a file that cannot be read or written;
    1 for a program error, a refusal (the line and the reason) or a written program whose path
    differs from the original's by more than the tolerance; 0 otherwise."""
    from ..flatten import Refused, flatten

    program = open_marked(options.file, options.dialect)
    try:
        conflict = inputs_conflict(options, program.dialect)
        if conflict is not None:
            sys.stderr.write(f"ngc flatten: {conflict}\n")
            return EXIT_USAGE
        if program.dialect == ENGINE:
            sys.stderr.write(f"ngc flatten: {program.name} is in the engine dialect: engine "
                             "programs are not flattened yet\n")
            return EXIT_USAGE
        try:
            inputs, setup = load_inputs("flatten", options, options.file)
        except NgcConfigError as exc:
            sys.stderr.write(f"ngc flatten: {exc.message}\n")
            return EXIT_USAGE
        if program.handle is None:
            return cannot_open("flatten", program)
        text = dialects.read_text(program.handle)
    finally:
        program.close()
    try:
        result = flatten(text, program.name,
                         lambda sink: new_interpreter(sink, inputs, setup, write_files=False),
                         target=options.target, inch=options.units == "inch",
                         decimals=options.decimals, source_lines=options.source_lines,
                         verify=not options.no_verify, tolerance=options.tolerance,
                         toolchange=options.toolchange)
    except ValueError as exc:
        sys.stderr.write(f"ngc flatten: {exc}\n")
        return EXIT_USAGE
    except Refused as exc:
        sys.stderr.write(f"{program.name}:{exc.line}: ngc flatten: refused: {exc.reason}\n")
        return EXIT_PROGRAM_ERROR
    except NgcError as exc:
        sys.stderr.write(exc.render() + "\n")
        return EXIT_PROGRAM_ERROR
    verified = result.verified
    tolerance = options.tolerance
    if verified is not None:
        if verified.difference is not None or verified.deviation > tolerance:
            what = verified.difference or (f"the path differs by {verified.deviation:.6f} mm, "
                                           f"more than --tolerance {tolerance:g}")
            sys.stderr.write(f"ngc flatten: {program.name}: not verified: {what}; nothing "
                             "written\n")
            return EXIT_PROGRAM_ERROR
        sys.stderr.write(f"ngc flatten: {program.name}: {result.lines} lines for "
                         f"{options.target}, verified: {verified.moves} moves, largest "
                         f"deviation {verified.deviation:.6f} mm\n")
    return _write(options.output, result.text)


def _write(output: str | None, text: str) -> int:
    """The program to ``output`` (None or ``-``: stdout), whole or not at all: a regular file
    (or a new one) through a temporary file renamed over it; anything else (``/dev/null``, a
    FIFO) written to as it is, never replaced."""
    if output is None or output == "-":
        sys.stdout.write(text)
        return EXIT_OK
    try:
        special = os.path.exists(output) and not stat.S_ISREG(os.stat(output).st_mode)
    except OSError:
        special = False
    if special:
        try:
            with open(output, "w", encoding="utf-8", newline="\n") as handle:
                handle.write(text)
        except OSError as exc:
            sys.stderr.write(f"ngc flatten: cannot write {display_name(output)}: {exc.strerror}\n")
            return EXIT_USAGE
        return EXIT_OK
    folder = os.path.dirname(os.path.abspath(output))
    try:
        fd, temporary = tempfile.mkstemp(dir=folder, prefix=".ngc-flatten-")
        with os.fdopen(fd, "w", encoding="utf-8", newline="\n") as handle:
            handle.write(text)
        os.replace(temporary, output)
    except OSError as exc:
        sys.stderr.write(f"ngc flatten: cannot write {display_name(output)}: {exc.strerror}\n")
        return EXIT_USAGE
    return EXIT_OK
