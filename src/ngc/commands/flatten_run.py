"""``ngc flatten`` on the command line: the program written plain for a target, verified, to
OUT (or stdout); nothing is written for a program that is refused or does not verify."""

from __future__ import annotations

import argparse
import contextlib
import os
import shutil
import stat
import sys
import tempfile
from typing import TextIO

from ..dialects import ENGINE
from ..errors import NgcConfigError, NgcError
from ..interp.source import ProgramReader, text_reader
from ..options import MachineOptions, Setup, new_interpreter
from ..progress import Progress, is_terminal
from .common import (
    EXIT_OK,
    EXIT_PROGRAM_ERROR,
    EXIT_USAGE,
    cannot_open,
    display_name,
    inputs_conflict,
    load_inputs,
    open_marked,
    progress_of,
)


def run(options: argparse.Namespace) -> int:
    """Exit 2 for a bad command line, machine input, or a file that cannot be read or written;
    1 for a program error, a refusal (the line and the reason) or a written program whose path
    differs from the original's by more than the tolerance; 0 otherwise.

    The program is read and written as a stream (to a temporary file beside OUT, or in the
    temporary folder for standard output), so memory stays flat in its length; the file takes
    OUT's place only once it is verified."""
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
        handle = text_reader(program.handle)
        output = options.output if options.output not in (None, "-") else None
        try:
            spool = _Spool(output)
        except OSError as exc:
            sys.stderr.write(f"ngc flatten: cannot write {display_name(output or '-')}: "
                             f"{exc.strerror}\n")
            return EXIT_USAGE
        with handle, spool, progress_of(program.name, handle,
                                        output_to_terminal=output is None
                                        and is_terminal(sys.stdout)) as progress:
            code = _flatten(options, program.name, handle, progress, spool, inputs, setup)
            progress.close()
            if code != EXIT_OK:
                return code
            return spool.keep()
    finally:
        program.close()


def _flatten(options: argparse.Namespace, name: str, handle: ProgramReader, progress: Progress,
             spool: _Spool, inputs: MachineOptions, setup: Setup) -> int:
    from ..flatten import Refused, flatten

    try:
        result = flatten(progress.lines(handle), name,
                         lambda sink: new_interpreter(sink, inputs, setup, write_files=False),
                         target=options.target, inch=options.units == "inch",
                         decimals=options.decimals, source_lines=options.source_lines,
                         verify=not options.no_verify, tolerance=options.tolerance,
                         toolchange=options.toolchange, fold_lengths=options.fold_tool_length,
                         out=spool.file, reader=handle)
    except ValueError as exc:
        progress.close()
        sys.stderr.write(f"ngc flatten: {exc}\n")
        return EXIT_USAGE
    except Refused as exc:
        progress.close()
        sys.stderr.write(f"{name}:{exc.line}: ngc flatten: refused: {exc.reason}\n")
        return EXIT_PROGRAM_ERROR
    except NgcError as exc:
        progress.close()
        sys.stderr.write(exc.render() + "\n")
        return EXIT_PROGRAM_ERROR
    verified = result.verified
    tolerance = options.tolerance
    progress.close()
    if verified is not None:
        if verified.difference is not None or verified.deviation > tolerance:
            what = verified.difference or (f"the path differs by {verified.deviation:.6f} mm, "
                                           f"more than --tolerance {tolerance:g}")
            sys.stderr.write(f"ngc flatten: {name}: not verified: {what}; nothing written\n")
            return EXIT_PROGRAM_ERROR
        sys.stderr.write(f"ngc flatten: {name}: {result.lines} lines for {options.target}, "
                         f"verified: {verified.moves} moves, largest deviation "
                         f"{verified.deviation:.6f} mm\n")
    return EXIT_OK


class _Spool:
    """The program as it is written: a temporary file beside ``output`` (renamed over it by
    :meth:`keep`), or in the temporary folder for standard output (copied to it by
    :meth:`keep`); a device or a FIFO is written to by :meth:`keep` as it is, never replaced.
    Left unkept, the temporary file is removed."""

    def __init__(self, output: str | None) -> None:
        self.output = output
        try:
            special = output is not None and os.path.exists(output) and not stat.S_ISREG(
                os.stat(output).st_mode)
        except OSError:
            special = False
        self.special = special
        folder = (os.path.dirname(os.path.abspath(output)) if output is not None and not special
                  else None)
        fd, self.temporary = tempfile.mkstemp(dir=folder, prefix=".ngc-flatten-")
        self.file: TextIO = os.fdopen(fd, "w+", encoding="utf-8", newline="\n")

    def __enter__(self) -> _Spool:
        return self

    def __exit__(self, *exc: object) -> None:
        self.file.close()
        with contextlib.suppress(OSError):
            os.unlink(self.temporary)

    def keep(self) -> int:
        output = self.output
        try:
            if output is None or self.special:
                self.file.seek(0)
                with contextlib.ExitStack() as stack:
                    target: TextIO = sys.stdout if output is None else stack.enter_context(
                        open(output, "w", encoding="utf-8", newline="\n"))
                    shutil.copyfileobj(self.file, target, 1 << 20)
                    target.flush()
                return EXIT_OK
            self.file.close()
            os.replace(self.temporary, output)
        except OSError as exc:
            sys.stderr.write(f"ngc flatten: cannot write {display_name(output or '-')}: "
                             f"{exc.strerror}\n")
            return EXIT_USAGE
        return EXIT_OK
