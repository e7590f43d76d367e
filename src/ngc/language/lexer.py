"""Line normalization: what LinuxCNC does to a line before reading its items.

Outside comments, spaces and tabs are dropped and letters are lower-cased; a ``;`` ends the line
(kept, so that a ``;`` where a value should be is a bad number, as in rs274).
A ``( ... )`` comment is kept verbatim (case and spaces) and may not contain another ``(``.
(overview.adoc, "Format of a line" and "Comments".)
"""

from __future__ import annotations

from ..errors import NgcSyntaxError

# C's isspace: what rs274 trims from the end of a line it shows.
C_SPACE = " \t\n\v\f\r"
# The white space a line may hold between its words (removed before reading).
WHITE_SPACE = str.maketrans("", "", " \t\r\n")
# rs274 lower-cases ASCII letters only (C tolower); other bytes pass through.
_ASCII_LOWER = str.maketrans("ABCDEFGHIJKLMNOPQRSTUVWXYZ", "abcdefghijklmnopqrstuvwxyz")


def _lower(text: str) -> str:
    return text.lower() if text.isascii() else text.translate(_ASCII_LOWER)


def normalize(raw: str) -> str:
    """Return ``raw`` with white space removed and letters lower-cased outside comments."""
    if "(" not in raw and ";" not in raw:
        if "\t" in raw or "\r" in raw:
            raw = raw.translate(WHITE_SPACE)
        return _lower(raw.replace(" ", ""))
    out: list[str] = []
    i = 0
    n = len(raw)
    while i < n:
        c = raw[i]
        if c == "(":
            close = raw.find(")", i + 1)
            if close < 0:
                raise NgcSyntaxError("Unclosed comment found", column=i + 1)
            nested = raw.find("(", i + 1, close)
            if nested >= 0:
                raise NgcSyntaxError("Nested comment found", column=nested + 1)
            out.append(raw[i : close + 1])
            i = close + 1
            continue
        if c == ";":
            out.append(c)  # the reader stops there, or fails on it inside a value, as rs274
            break
        if c not in " \t\r\n":
            out.append(_lower(c))
        i += 1
    return "".join(out)
