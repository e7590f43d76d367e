"""Running an engine-dialect program: lines to engine segments and the other operations.

A line holds one code, by number or by name, and its clauses; ``docs/engine-dialect.md`` gives
every decision the seed leaves open.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterator

from ..errors import NgcRuntimeError, NgcSemanticError, NgcSyntaxError
from . import cycles, motion
from .mcodes import run_m_line, starts_m_line
from .names import MOVE, NAMES, split_name
from .reading import clauses, reference, single, strip, tokens, value
from .state import (
    AXES,
    AXIS,
    PLANES,
    POLARS,
    VECTORS,
    Cycle,
    Dwell,
    Engine,
    EngineError,
    EngineSegment,
    ModeChange,
    Op,
    PolarMode,
    ProgramStop,
    Stop,
    direction,
)

__all__ = ["Dwell", "Engine", "EngineError", "EngineSegment", "ModeChange", "Op", "ProgramStop",
           "Stop", "run"]

_WHAT = {1: "G1 (feed)", 4: "G4 (dwell)", 15: "G15 (cancel polar coordinates)",
         16: "G16 (set polar origin)", 31: "G31 (probe)", 43: "G43 (apply tool length offset)",
         49: "G49 (cancel tool length offset)", 80: "G80 (cancel fixed cycles)",
         92: "G92 (preset)", 100: "G100 (run)"}
_MOTION = {0: "rapid", 1: "feed", 31: "probe"}


def _vector_name(tok: str) -> str:
    up = tok.upper()
    if up not in VECTORS:
        raise EngineError(f"'{tok}' is not a vector (VX ... VW)")
    return up


def _polar_name(tok: str) -> str:
    up = tok.upper()
    if up not in POLARS:
        raise EngineError(f"'{tok}' is not a polar transform (PX, PY, PZ)")
    return up


def _args(words: list[str], n: int, what: str) -> None:
    if len(words) < n:
        raise EngineError(f"{what} needs {n} arguments, not {len(words)}")


def _axes_only(eng: Engine, words: list[str], what: str) -> dict[int, float]:
    """Axis letters each with one value (program values), as ``{axis: value}``."""
    out: dict[int, float] = {}
    for ref, values in clauses(words, eng.params):
        if ref not in AXIS:
            raise EngineError(f"{what} takes axes each with one value, not {ref}")
        out[AXIS[ref]] = single(ref, values, what)
    return out


def _no_arguments(code: int, words: list[str]) -> None:
    if words:
        what = _WHAT.get(code, f"G{code}")
        raise EngineError(f"{what} takes no arguments, not '{' '.join(words)}'")


def _moving(eng: Engine, line: int, code: int, words: list[str]) -> Iterator[Op]:
    """G0, G1, G31: a move made of the line's clauses."""
    kind = _MOTION[code]
    made, ends, ops = motion.clauses_of(eng, line, clauses(words, eng.params), f"G{code}")
    yield from ops
    if made and code != 0:
        motion.need_feed(eng, _WHAT[code])
    yield from motion.segments(eng, line, made, kind)
    eng.along.update(ends)
    if code == 31:
        # no probe input in a simulation: the move runs to its end
        eng.params.names["__probe_stop"] = 0.0


def _dwell(eng: Engine, line: int, words: list[str]) -> Iterator[Op]:
    """G4: P seconds (or the number alone); running axes (G100) run on through it."""
    p = eng.params
    found = clauses(words, p) if words and reference(words[0]) else [
        ("P", [value(t, p) for t in words])]
    values = [v for ref, vs in found if ref == "P" for v in vs]
    if len(values) > 1 or any(ref != "P" for ref, _ in found):
        raise EngineError("G4 (dwell) takes one time in seconds (P)")
    seconds = values[0] if values else 0.0
    if seconds < 0.0:
        raise EngineError("G4 (dwell): the time must not be negative")
    motion.check_seconds(seconds, "G4 (dwell)")
    if eng.running and seconds > 0.0:
        yield from motion.timed(eng, line, {}, seconds, "run")
    else:
        yield Dwell(line, seconds)


def _polar_on(eng: Engine, line: int, words: list[str]) -> Iterator[Op]:
    """G16: polar coordinates from an origin fixed in machine position; X Y Z name it (the
    current position for the others), through the polar translation if G16 is already on."""
    what = _WHAT[16]
    found = clauses(words, eng.params)
    prog = eng.program()
    origin = list(eng.pos)
    offsets = eng.offsets()
    first, second, _ = PLANES[eng.plane]
    if eng.polar_mode is not None:
        found, made = motion.polar_coordinates(eng, found)
        for k, t in (made[0].ends if made else {}).items():
            origin[k] = t
    for ref, values in found:
        if ref not in ("X", "Y", "Z"):
            raise EngineError(f"{what} takes X Y Z each with one value, not {ref}")
        k = AXIS[ref]
        origin[k] = single(ref, values, what) * eng.unit(k) + (
            offsets[k] if eng.absolute else prog[k] + offsets[k])
    dx, dy = eng.pos[first] - origin[first], eng.pos[second] - origin[second]
    eng.polar_mode = PolarMode(origin, math.hypot(dx, dy), math.degrees(math.atan2(dy, dx)))
    yield ModeChange(line, "POLAR_COORDINATES",
                     {AXES[k]: eng.shown(k, origin[k]) for k in range(3)})


def _run_axes(eng: Engine, line: int, words: list[str]) -> Iterator[Op]:
    """G100: axes at constant speed, as percentages of their maximum speeds (0 stops)."""
    for k, percent in _axes_only(eng, words, _WHAT[100]).items():
        if abs(percent) > 100.0:
            raise EngineError(f"G100 (run): {AXES[k]} at {percent:g}% is over its maximum speed")
        if percent:
            eng.running[k] = percent / 100.0 * eng.setup.max_speed[k]
        else:
            eng.running.pop(k, None)
    yield motion.run_change(eng, line)


def _setting(eng: Engine, line: int, code: int, words: list[str]) -> Iterator[Op]:
    p = eng.params
    if code in (17, 18, 19):
        eng.plane = {17: "XY", 18: "ZX", 19: "YZ"}[code]
        yield ModeChange(line, "PLANE", eng.plane)
    elif code in (20, 21):
        eng.metric = code == 21
        yield ModeChange(line, "UNITS", "mm" if eng.metric else "inch")
    elif code == 15:
        eng.polar_mode = None
        yield ModeChange(line, "POLAR_COORDINATES", None)
    elif code == 43:
        eng.tool_length()  # the setup must give one
        eng.tool_offset = True
        yield _tool_change(eng, line)
    elif code == 49:
        eng.tool_offset = False
        yield _tool_change(eng, line)
    elif 53 <= code <= 59:
        eng.fixture = code - 53
        yield ModeChange(line, "FIXTURE", eng.fixture)
        if eng.tool_offset:  # along this fixture's tool axis now
            yield _tool_change(eng, line)
    elif code in (61, 64):
        eng.exact = code == 61
        yield ModeChange(line, "EXACT_STOP", eng.exact)
    elif code == 69:
        eng.reset_transforms()
        yield ModeChange(line, "TRANSFORMS", "default")
    elif code == 80:
        eng.cycle = Cycle()
        yield ModeChange(line, "CYCLE", None)
    elif code in (90, 91):
        eng.absolute = code == 90
        yield ModeChange(line, "DISTANCE", "absolute" if eng.absolute else "incremental")
    elif code == 92:
        offsets = eng.offsets()
        for k, v in _axes_only(eng, words, _WHAT[92]).items():
            eng.pos[k] = v * eng.unit(k) + offsets[k]
        yield ModeChange(line, "SET_POSITION",
                         {a: eng.shown(k, eng.pos[k]) for k, a in enumerate(AXES)})
    elif code == 101:
        _args(words, 3, "G101 (rotate vectors)")
        normal = list(eng.vectors[_vector_name(words[0])])
        angle = math.radians(value(words[1], p))
        for tok in words[2:]:
            name = _vector_name(tok)
            eng.vectors[name] = _rotated(eng.vectors[name], normal, angle)
        yield ModeChange(line, "VECTORS", {v: list(eng.vectors[v]) for v in VECTORS})
    elif code == 102:
        _args(words, 3, "G102 (set vector)")
        name = _vector_name(words[0])
        vec = [0.0] * 9
        for k, scale in _axes_only(eng, words[1:], "G102 (set vector)").items():
            vec[k] = scale
        eng.vectors[name] = vec
        yield ModeChange(line, "VECTORS", {name: vec})
    elif code == 103:
        _args(words, 3, "G103 (set polar center)")
        name = _polar_name(words[0])
        angle = value(words[1], p)
        radius = value(words[2], p) * eng.length_unit
        offset = value(words[3], p) * eng.length_unit if len(words) > 3 else 0.0
        n, z, q = eng.frame(name)
        u = direction(z, q, angle)
        centre = [x - radius * ui - offset * ni for x, ui, ni in zip(eng.pos, u, n, strict=True)]
        eng.polars[name].centre = centre
        eng.polars[name].radius = radius
        yield ModeChange(line, "POLAR_CENTRE",
                         {name: [eng.shown(k, c) for k, c in enumerate(centre)]})
    elif code in (104, 105):
        what = "G104 (set polar axis)" if code == 104 else "G105 (set polar zero)"
        _args(words, 2, what)
        name, ref = _polar_name(words[0]), _vector_name(words[1])
        if code == 104:
            eng.polars[name].normal = ref
        else:
            eng.polars[name].zero = ref
        yield ModeChange(line, "POLAR_AXIS" if code == 104 else "POLAR_ZERO", {name: ref})
    elif code == 107:
        _args(words, 1, "G107 (set drill vector)")
        eng.drill = _vector_name(words[0])
        yield ModeChange(line, "DRILL_VECTOR", eng.drill)
    elif code == 108:
        _args(words, 2, "G108 (set vector position)")
        name = _vector_name(words[0])
        eng.along[name] = value(words[1], p) * eng.length_unit
        yield ModeChange(line, "VECTOR_POSITION", {name: value(words[1], p)})
    else:  # pragma: no cover (every code of NAMES is dispatched)
        raise EngineError(f"G{code} is not supported in the engine dialect")


def _tool_change(eng: Engine, line: int) -> ModeChange:
    """TOOL_OFFSET: the tool length offset now applied, per axis, in program units."""
    if not eng.tool_offset:
        return ModeChange(line, "TOOL_OFFSET", {})
    k, sign = eng.setup.fixtures[eng.fixture].tool_axis
    return ModeChange(line, "TOOL_OFFSET", {AXES[k]: eng.shown(k, sign * eng.tool_length())})


def _rotated(v: list[float], axis: list[float], angle: float) -> list[float]:
    """``v`` turned ``angle`` radians about ``axis`` (Rodrigues, on X Y Z)."""
    n = math.sqrt(sum(a * a for a in axis[:3]))
    if n == 0.0:
        raise EngineError("G101 (rotate vectors): the axis vector has no X Y Z part")
    k = [a / n for a in axis[:3]]
    x = v[:3]
    c, s = math.cos(angle), math.sin(angle)
    cross = [k[1] * x[2] - k[2] * x[1], k[2] * x[0] - k[0] * x[2], k[0] * x[1] - k[1] * x[0]]
    dot = sum(ki * xi for ki, xi in zip(k, x, strict=True))
    out = [x[i] * c + cross[i] * s + k[i] * dot * (1.0 - c) for i in range(3)]
    return out + list(v[3:])


# ---- lines --------------------------------------------------------------------------------------

# codes without arguments, which may come before a line's main code ("G90 G0 X1")
_MODAL = {15, 17, 18, 19, 20, 21, 43, 49, 53, 54, 55, 56, 57, 58, 59, 61, 64, 69, 80, 90, 91}
_G_NUMBER = re.compile(r"g\s*(\d+)(?![\d.])", re.IGNORECASE)
_G_DECIMAL = re.compile(r"g\s*\d*\.\d*", re.IGNORECASE)
_ASSIGN = re.compile(r"#\s*(<[^>]*>|\d+)\s*=(.*)")
_KNOWN = set(NAMES)


def _code(eng: Engine, line: int, code: int, rest: list[str]) -> Iterator[Op]:
    if code == MOVE:
        code = eng.motion
    if code in (0, 1):
        eng.motion = code
        yield from _moving(eng, line, code, rest)
    elif code == 31:
        yield from _moving(eng, line, code, rest)
    elif code in (2, 3):
        yield from motion.circle(eng, line, code, clauses(rest, eng.params))
    elif code == 4:
        yield from _dwell(eng, line, rest)
    elif code == 16:
        yield from _polar_on(eng, line, rest)
    elif code in cycles.WHAT:
        yield from cycles.drill(eng, line, code, clauses(rest, eng.params))
    elif code == 100:
        yield from _run_axes(eng, line, rest)
    else:
        if code in _MODAL:
            _no_arguments(code, rest)
        yield from _setting(eng, line, code, rest)


def _line(eng: Engine, n: int, raw: str) -> Iterator[Op]:
    text = strip(raw)
    if not text or text == "%":
        return
    m = _ASSIGN.fullmatch(text)
    if m is not None:
        result = value(m.group(2).strip().replace(" ", ""), eng.params)
        key = m.group(1)
        if key.startswith("<"):
            eng.params.names[key[1:-1].replace(" ", "").lower()] = result
        else:
            eng.params.numbered[int(key)] = result
        return
    g = _G_NUMBER.match(text)
    decimal = _G_DECIMAL.match(text)
    if decimal is not None:
        raise EngineError(f"Unknown code {decimal.group(0).upper()}")
    if g is not None:
        code = int(g.group(1))
        rest = tokens(text[g.end():])
        if code not in _KNOWN:
            raise EngineError(f"Unknown code G{code}")
    else:
        words = tokens(text)
        if starts_m_line(words):
            yield from run_m_line(eng, n, words)
            return
        if words and words[0].upper() == "F":
            yield from _moving(eng, n, eng.motion, words)
            return
        named = split_name(words)
        if named is None:
            err = EngineError(f"Unknown name '{words[0]}'")
            err.token = words[0]
            raise err
        code, used = named
        rest = words[used:]
    if code in _MODAL and rest and (_G_NUMBER.match(rest[0]) or rest[0].upper() == "F"
                                    or starts_m_line(rest) or split_name(rest)):
        # a setting before the line's main code
        yield from _setting(eng, n, code, [])
        yield from _line(eng, n, " ".join(rest))
        return
    yield from _code(eng, n, code, rest)


def run(text: str, engine: Engine | None = None, file: str | None = None) -> Iterator[Op]:
    """The operations of an engine-dialect program, line by line; an error carries its line."""
    eng = engine if engine is not None else Engine()
    for n, raw in enumerate(text.splitlines(), 1):
        try:
            yield from _line(eng, n, raw)
        except (NgcSemanticError, NgcSyntaxError, NgcRuntimeError) as err:
            raise err.locate(file=file, line=n, source=raw) from None
        if eng.ended:  # M2, M30: "Lines of code after M2/M30 will not be executed."
            return
