"""M codes and S in the engine dialect: program stops and end, spindle and coolant.

The seed lists only G-codes, but the programs it runs end with M2 or M30 and turn spindles and
coolant on; the dialect takes the M codes LinuxCNC's m-code.adoc gives for that, by number only
(the seed names no M code), as operations of their own (``docs/engine-dialect.md``, "M codes").
A line of M codes holds any of them with at most one S, one code of each group, and runs them in
LinuxCNC's order (overview.adoc, Order of Execution): the speed, the spindle, the coolant, then a
stop or the end.
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from .reading import value
from .state import Engine, EngineError, ModeChange, Op, ProgramStop

# code -> (group, what it is, for messages)
M_CODES: dict[int, tuple[str, str]] = {
    0: ("stop", "M0 (program stop)"),
    1: ("stop", "M1 (optional program stop)"),
    2: ("stop", "M2 (program end)"),
    30: ("stop", "M30 (program end)"),
    3: ("spindle", "M3 (spindle clockwise)"),
    4: ("spindle", "M4 (spindle counterclockwise)"),
    5: ("spindle", "M5 (spindle stop)"),
    7: ("coolant", "M7 (mist)"),
    8: ("coolant", "M8 (flood)"),
    9: ("coolant", "M9 (coolant off)"),
}
_SPINDLE = {3: "clockwise", 4: "counterclockwise", 5: "off"}
_STOPS = {0: "PROGRAM_STOP", 1: "OPTIONAL_PROGRAM_STOP", 2: "PROGRAM_END", 30: "PROGRAM_END"}
_WORD = re.compile(r"([ms])(.*)", re.IGNORECASE | re.DOTALL)
_M_NUMBER = re.compile(r"\d+")
_VALUE_START = tuple("0123456789.+-#[")


def starts_m_line(words: list[str]) -> bool:
    """Whether ``words`` begin with an M code (``M3``, ``M 3``) or an S word (``S1000``,
    ``S [#1]``); names such as ``set vector`` do not."""
    if not words or words[0][:1] not in "mMsS":
        return False
    rest = words[0][1:] or (words[1] if len(words) > 1 else "")
    if words[0][0] in "sS":
        return rest[:1] in _VALUE_START
    return rest[:1].isdigit()


def _read(eng: Engine, words: list[str]) -> tuple[dict[str, int], float | None]:
    """The line's M codes by group, and its S value (None without one)."""
    codes: dict[str, int] = {}
    speed: float | None = None
    i = 0
    while i < len(words):
        m = _WORD.fullmatch(words[i])
        if m is None:
            raise EngineError(f"'{words[i]}' on a line of M codes: only M codes and S may be there")
        letter, rest = m.group(1).upper(), m.group(2)
        if not rest:
            i += 1
            if i == len(words):
                raise EngineError(f"{letter} without a value")
            rest = words[i]
        i += 1
        if letter == "S":
            if speed is not None:
                raise EngineError("S given twice on one line")
            speed = value(rest, eng.params)
            continue
        if _M_NUMBER.fullmatch(rest) is None or int(rest) not in M_CODES:
            raise EngineError(f"Unknown code M{rest.upper()}")
        code = int(rest)
        group, _ = M_CODES[code]
        if group in codes:
            raise EngineError(f"{M_CODES[codes[group]][1]} and {M_CODES[code][1]} on one line")
        codes[group] = code
    return codes, speed


def run_m_line(eng: Engine, line: int, words: list[str]) -> Iterator[Op]:
    """The line's speed, spindle, coolant and stop, in that order; M2 and M30 end the run."""
    codes, speed = _read(eng, words)
    if speed is not None:
        if speed < 0.0:
            raise EngineError(f"S {speed:g}: a spindle speed must not be negative")
        eng.spindle_speed = speed
        yield ModeChange(line, "SPINDLE_SPEED", speed)
    if "spindle" in codes:
        yield from _spindle(eng, line, _SPINDLE[codes["spindle"]])
    if "coolant" in codes:
        code = codes["coolant"]
        yield from _coolant(eng, line, mist=code == 7 or (code == 8 and eng.mist),
                            flood=code == 8 or (code == 7 and eng.flood))
    if "stop" in codes:
        code = codes["stop"]
        if code in (2, 30):
            # m-code.adoc, M2 M30: "The spindle is stopped (like 'M5')", "Coolant is turned off
            # (like 'M9')"; "Lines of code after M2/M30 will not be executed."
            yield from _spindle(eng, line, "off")
            yield from _coolant(eng, line, mist=False, flood=False)
            eng.ended = True
        yield ProgramStop(line, _STOPS[code])


def _spindle(eng: Engine, line: int, state: str) -> Iterator[Op]:
    if state != eng.spindle:
        eng.spindle = state
        yield ModeChange(line, "SPINDLE", state)


def _coolant(eng: Engine, line: int, *, mist: bool, flood: bool) -> Iterator[Op]:
    if (mist, flood) != (eng.mist, eng.flood):
        eng.mist, eng.flood = mist, flood
        yield ModeChange(line, "COOLANT", {"mist": mist, "flood": flood})
