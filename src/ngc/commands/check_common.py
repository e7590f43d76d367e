"""What ``ngc check``'s reports share between the dialects (:mod:`ngc.commands.check` for LinuxCNC
programs, :mod:`ngc.commands.check_engine` for engine ones): a file's headline, and an error as a
JSON-ready record."""

from __future__ import annotations

from ..errors import NgcError


def headline(path: str, error: NgcError | None) -> str:
    """The start of ``ngc check``'s paragraph on a file: ok, or where the error stopped it."""
    if error is None:
        return f"{path}: ok"
    if error.line is None:
        return f"{path}: error"
    if error.file is not None and error.file != path:
        # (in a subroutine file the program called: its line is that file's)
        return f"{path}: stopped by an error at line {error.line} of {error.file}"
    return f"{path}: stopped by an error at line {error.line}"


def error_record(error: NgcError) -> dict[str, object]:
    """An error as a JSON-ready mapping: rs274's message, what it is about (or None), file,
    line, column (None where only the line is known, as for an error found running it), source
    line."""
    return {"message": error.text_message(), "about": error.about_text(), "file": error.file,
            "line": error.line, "column": error.column, "source": error.source}
