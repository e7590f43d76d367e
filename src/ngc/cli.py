"""The ``ngc`` command line: parses arguments, calls the library, maps errors to exit codes."""

from __future__ import annotations

import sys

from . import rs274

COMMANDS = ("rs274", "canon", "check")


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``ngc`` console script and ``python -m ngc``."""
    args = sys.argv[1:] if argv is None else argv
    if not args or args[0] in ("-h", "--help"):
        sys.stdout.write(
            "usage: ngc {rs274,canon,check} ...\n\n"
            "  rs274 [-t TBL] [-v VAR] [-i INI] [-n 0|1|2] [-b] [-s] [-g] FILE\n"
            "        drop-in for LinuxCNC's standalone rs274 (batch mode)\n"
            "  canon FILE [--format text|json]   canonical machine operations\n"
            "  check FILE...                     validate programs\n"
        )
        return 0 if args else 2
    command, rest = args[0], args[1:]
    if command == "rs274":
        code = rs274.run(rest)
    else:
        sys.stderr.write(f"ngc: unknown command '{command}' (expected one of {', '.join(COMMANDS)})\n")
        return 2
    sys.stdout.flush()
    return code
