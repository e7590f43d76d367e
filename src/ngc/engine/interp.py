"""Running an engine-dialect program: lines to engine segments and the other operations.

Positions are program positions in program units (no fixture offsets yet); a motion's clauses each
give a displacement over the move's normalised time t in [0, 1] and the displacements add.  See
``docs/engine-dialect.md`` for every decision the seed leaves open.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import NamedTuple

from ..errors import NgcRuntimeError, NgcSemanticError, NgcSyntaxError
from ..language import expressions as ex
from ..language.parser import read_value
from . import bezier
from .bezier import Cubic
from .names import MOVE, NAMES, split_name
from .setup import Setup

EngineError = NgcSemanticError

AXES = "XYZABCUVW"
_AXIS = {a: i for i, a in enumerate(AXES)}
VECTORS = tuple("V" + a for a in AXES)
POLARS = ("PX", "PY", "PZ")
# polar transform -> (normal, zero) by default (the defaults)
_POLAR_DEFAULTS = {"PZ": ("VZ", "VX"), "PX": ("VX", "VY"), "PY": ("VY", "VZ")}
# rapid rates: program units per second for the linear axes at G21 (mm/s), degrees per second for
# the rotary ones
RAPID_LINEAR_MM_S = 25.0
RAPID_ROTARY_DEG_S = 360.0
_ROTARY = {3, 4, 5}
# the codes the seed lists that ngc does not run yet in this dialect
_NOT_YET = {2, 3, 15, 16, 31, 43, 49, 53, 54, 55, 56, 57, 58, 59, 73, 80, 81, 82, 83, 85, 86, 89,
            100}
_REFERENCE = re.compile(r"(V[XYZABCUVW]|P[XYZ]|[XYZABCUVWFP])(?![A-Z])", re.IGNORECASE)


class EngineSegment(NamedTuple):
    """Per axis, the four control points of a cubic Bézier of its position over the segment's
    normalised time; ``duration`` in seconds; ``motion`` the kind of move it belongs to: "rapid"
    (G0), "feed" (G1), "arc" (G2/G3), "probe" (G31) or "run" (axes at constant speed, G100)."""

    line: int
    duration: float
    axes: dict[str, Cubic]
    motion: str = "feed"


class Dwell(NamedTuple):
    line: int
    seconds: float


class ModeChange(NamedTuple):
    """A setting that moves nothing: ``name`` (UNITS, PLANE, DISTANCE, EXACT_STOP, FEED_RATE,
    SET_POSITION, DRILL_VECTOR) and its new value."""

    line: int
    name: str
    value: object


Op = EngineSegment | Dwell | ModeChange


@dataclass
class Polar:
    normal: str
    zero: str
    centre: list[float] | None = None
    radius: float = 0.0


class _Params:
    """Parameters by number or name, for expressions."""

    def __init__(self) -> None:
        self.numbered: dict[int, float] = {}
        self.names: dict[str, float] = {}

    def num(self, index: int) -> float:
        return self.numbered.get(index, 0.0)

    def named(self, name: str) -> float:
        if name not in self.names:
            raise NgcRuntimeError(f"Named parameter #<{name}> not defined")
        return self.names[name]

    def local(self, name: str) -> float:
        return self.named(name)

    def exists(self, name: str) -> bool:
        return name in self.names

    def index(self, value: float) -> int:
        return round(value)


def _unit(k: int) -> list[float]:
    v = [0.0] * 9
    v[k] = 1.0
    return v


@dataclass
class Engine:
    """The dialect's machine state."""

    pos: list[float] = field(default_factory=lambda: [0.0] * 9)
    metric: bool = True
    absolute: bool = True
    motion: int = 0
    feed: float | None = None
    plane: str = "XY"
    vectors: dict[str, list[float]] = field(default_factory=dict)
    along: dict[str, float] = field(default_factory=dict)
    polars: dict[str, Polar] = field(default_factory=dict)
    drill: str = "VZ"
    params: _Params = field(default_factory=_Params)
    setup: Setup = field(default_factory=Setup)

    def __post_init__(self) -> None:
        self.reset_transforms()

    def reset_transforms(self) -> None:
        """G69: every vector and polar transform back to its default."""
        self.vectors = {name: _unit(k) for k, name in enumerate(VECTORS)}
        self.along = dict.fromkeys(VECTORS, 0.0)
        self.polars = {p: Polar(*_POLAR_DEFAULTS[p]) for p in POLARS}

    # -- polar geometry -----------------------------------------------------------------------
    def frame(self, polar: str) -> tuple[list[float], list[float], list[float]]:
        """(normal, zero, quarter): the polar transform's axis, its zero-degree direction and the
        direction at 90 degrees (normal x zero, on X Y Z)."""
        p = self.polars[polar]
        n, z = self.vectors[p.normal], self.vectors[p.zero]
        q = [0.0] * 9
        q[0] = n[1] * z[2] - n[2] * z[1]
        q[1] = n[2] * z[0] - n[0] * z[2]
        q[2] = n[0] * z[1] - n[1] * z[0]
        return n, z, q


def _direction(z: list[float], q: list[float], degrees: float) -> list[float]:
    a = math.radians(degrees)
    c, s = math.cos(a), math.sin(a)
    return [c * zi + s * qi for zi, qi in zip(z, q, strict=True)]


# ---- reading ------------------------------------------------------------------------------------


def _strip(raw: str) -> str:
    """The line without its comments (``( ... )`` and from ``;`` on)."""
    text = re.sub(r"\([^)]*\)", " ", raw)
    return text.split(";", 1)[0].strip()


def _tokens(text: str) -> list[str]:
    """Words separated by white space or commas; a bracket keeps its inside together, and a
    reference written against its first expression (``X2``, ``PZ-1``) is split from it."""
    out: list[str] = []
    cur = ""
    depth = 0
    for c in text:
        if depth == 0 and (c.isspace() or c == ","):
            if cur:
                out.append(cur)
            cur = ""
            continue
        depth += (c == "[") - (c == "]")
        cur += c
    if cur:
        out.append(cur)
    split: list[str] = []
    for tok in out:
        m = _REFERENCE.match(tok)
        if m is not None and m.end() < len(tok) and tok[m.end()] in "0123456789.+-#[":
            split += [tok[: m.end()], tok[m.end():]]
        else:
            split.append(tok)
    return split


def _value(token: str, params: _Params) -> float:
    try:
        value = read_value(re.sub(r"\s+", "", token.lower()))
    except NgcSyntaxError:
        raise
    except Exception as exc:  # (a token the reader cannot take)
        raise NgcSyntaxError(f"Bad expression '{token}'") from exc
    return ex.evaluate(value, params)


def _reference(token: str) -> str | None:
    up = token.upper()
    if up in _AXIS or up in VECTORS or up in POLARS or up in ("F", "P"):
        return up
    return None


def _clauses(tokens: list[str], params: _Params) -> list[tuple[str, list[float]]]:
    """``[(reference, values), ...]`` in order."""
    out: list[tuple[str, list[float]]] = []
    for tok in tokens:
        ref = _reference(tok)
        if ref is not None:
            out.append((ref, []))
        elif not out:
            raise NgcSyntaxError(f"Expression '{tok}' before any reference")
        else:
            out[-1][1].append(_value(tok, params))
    return out


# ---- motion -------------------------------------------------------------------------------------

# a clause as the pieces it gives over [t0, t1]: axis index -> cubic of displacement
Piece = dict[int, Cubic]


class _Clause(NamedTuple):
    segments: int  # how many it needs
    piece: Callable[[float, float], Piece]


def _axis_clause(eng: Engine, axes: dict[int, float], values: list[float],
                 start_along: float | None) -> _Clause:
    """An axis (``axes`` = {k: 1}) or a vector's axes (their scales): 1 value, constant speed;
    3 values, the Bézier's inner control points and its end."""
    cps: dict[int, Cubic] = {}
    for k, scale in axes.items():
        origin = (start_along if start_along is not None else eng.pos[k]) if eng.absolute else 0.0
        if len(values) == 1:
            d = (values[0] - origin) * scale
            cps[k] = (0.0, d / 3.0, 2.0 * d / 3.0, d)
        else:
            e1, e2, e3 = ((v - origin) * scale for v in values)
            cps[k] = (0.0, e1, e2, e3)

    def piece(t0: float, t1: float) -> Piece:
        return {k: bezier.part(c, t0, t1) for k, c in cps.items()}

    return _Clause(1, piece)


def _polar_point(eng: Engine, name: str, values: list[float]) -> _Clause:
    p = eng.polars[name]
    if p.centre is None:
        raise EngineError(f"{name} has no centre: set one with G103 (set polar center)")
    n, z, q = eng.frame(name)
    angle = values[0]
    radius = values[1] if len(values) > 1 else p.radius
    offset = values[2] if len(values) > 2 else 0.0
    p.radius = radius
    u = _direction(z, q, angle)
    target = [c + radius * ui + offset * ni for c, ui, ni in zip(p.centre, u, n, strict=True)]
    disp = {k: target[k] - eng.pos[k] for k in range(9) if target[k] != eng.pos[k]}

    def piece(t0: float, t1: float) -> Piece:
        return {k: bezier.line(d, t0, t1) for k, d in disp.items()}

    return _Clause(1, piece)


def _arc_count(sweep: float, radius: float) -> int:
    """Segments for an arc: at most 90 degrees each; over a radius of 1 the radius times the
    angle decides (the seed)."""
    size = abs(sweep) * max(1.0, abs(radius))
    return max(1, math.ceil(size / 90.0 - 1e-9))


def _polar_arc(eng: Engine, name: str, values: list[float]) -> _Clause:
    a0, a1, radius, offset = values
    eng.polars[name].radius = radius
    n, z, q = eng.frame(name)
    sweep = a1 - a0
    u0 = _direction(z, q, a0)
    moving = [k for k in range(9) if z[k] or q[k] or (offset and n[k])]

    def piece(t0: float, t1: float) -> Piece:
        b0, b1 = a0 + sweep * t0, a0 + sweep * t1
        ua, ub = _direction(z, q, b0), _direction(z, q, b1)
        k_ = bezier.quarter_factor(math.radians(b1 - b0)) * radius
        ra, rb = math.radians(b0), math.radians(b1)
        ta = [-math.sin(ra) * zi + math.cos(ra) * qi for zi, qi in zip(z, q, strict=True)]
        tb = [-math.sin(rb) * zi + math.cos(rb) * qi for zi, qi in zip(z, q, strict=True)]
        out: Piece = {}
        for k in moving:
            p0 = radius * (ua[k] - u0[k])
            p3 = radius * (ub[k] - u0[k])
            c = (p0, p0 + k_ * ta[k], p3 - k_ * tb[k], p3)
            h = bezier.line(offset * n[k], t0, t1)
            out[k] = (c[0] + h[0], c[1] + h[1], c[2] + h[2], c[3] + h[3])
        return out

    return _Clause(_arc_count(sweep, radius), piece)


def _motion(eng: Engine, line: int, code: int, clauses: list[tuple[str, list[float]]]
            ) -> Iterator[Op]:
    made: list[_Clause] = []
    ends: dict[str, float] = {}
    for ref, values in clauses:
        if ref == "F":
            if len(values) != 1:
                raise EngineError(f"F takes 1 expression, not {len(values)}")
            eng.feed = values[0]
            yield ModeChange(line, "FEED_RATE", values[0])
        elif ref in _AXIS or ref in VECTORS:
            if len(values) not in (1, 3):
                raise EngineError(f"{ref} takes 1 or 3 expressions, not {len(values)}")
            if ref in _AXIS:
                made.append(_axis_clause(eng, {_AXIS[ref]: 1.0}, values, None))
            else:
                vec = eng.vectors[ref]
                scales = {k: s for k, s in enumerate(vec) if s}
                made.append(_axis_clause(eng, scales, values, eng.along[ref]))
                last = values[-1]
                ends[ref] = last if eng.absolute else ends.get(ref, eng.along[ref]) + last
        elif ref in POLARS:
            if not 1 <= len(values) <= 4:
                raise EngineError(f"{ref} takes 1 to 4 expressions, not {len(values)}")
            made.append(_polar_arc(eng, ref, values) if len(values) == 4
                        else _polar_point(eng, ref, values))
        else:
            raise EngineError(f"{ref} is not a reference of a motion")
    if not made:
        return
    if code == 1 and not eng.feed:
        raise EngineError("G1 (feed) with no feed rate: set one with F")
    count = max(c.segments for c in made)
    # the pieces are displacements from the move's start: positions from where it began
    start = list(eng.pos)
    total: dict[int, list[float]] = {}
    for j in range(count):
        t0, t1 = j / count, (j + 1) / count
        total = {}
        for c in made:
            for k, cub in c.piece(t0, t1).items():
                acc = total.setdefault(k, [0.0, 0.0, 0.0, 0.0])
                for i in range(4):
                    acc[i] += cub[i]
        axes: dict[str, Cubic] = {
            AXES[k]: (start[k] + acc[0], start[k] + acc[1], start[k] + acc[2], start[k] + acc[3])
            for k, acc in sorted(total.items())}
        yield EngineSegment(line, _duration(eng, code, axes), axes, "rapid" if code == 0 else "feed")
    for k, acc in total.items():
        eng.pos[k] = start[k] + acc[3]
    eng.along.update(ends)


def _duration(eng: Engine, code: int, axes: dict[str, Cubic]) -> float:
    if code == 1:
        dist = 0.0
        for group in ("XYZ", "UVW", "ABC"):  # the first group that moves
            dist = bezier.length([axes[a] for a in group if a in axes])
            if dist:
                break
        assert eng.feed is not None
        per_second = eng.feed if eng.metric else eng.feed / 60.0
        return dist / per_second
    # rapid: the slowest axis at its own rate decides
    worst = 0.0
    for a, c in axes.items():
        k = _AXIS[a]
        rate = RAPID_ROTARY_DEG_S if k in _ROTARY else (
            RAPID_LINEAR_MM_S if eng.metric else RAPID_LINEAR_MM_S / 25.4)
        worst = max(worst, bezier.length([c]) / rate)
    return worst


# ---- the other codes ----------------------------------------------------------------------------


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


def _args(tokens: list[str], n: int, what: str) -> None:
    if len(tokens) < n:
        raise EngineError(f"{what} needs {n} arguments, not {len(tokens)}")


def _setting(eng: Engine, line: int, code: int, tokens: list[str]) -> Iterator[Op]:
    p = eng.params
    if code == 4:
        clauses = _clauses(tokens, p) if tokens and _reference(tokens[0]) else [
            ("P", [_value(t, p) for t in tokens])]
        values = [v for ref, vs in clauses if ref == "P" for v in vs]
        if len(values) > 1 or any(ref != "P" for ref, _ in clauses):
            raise EngineError("G4 (dwell) takes one time in seconds (P)")
        yield Dwell(line, values[0] if values else 0.0)
    elif code in (17, 18, 19):
        eng.plane = {17: "XY", 18: "ZX", 19: "YZ"}[code]
        yield ModeChange(line, "PLANE", eng.plane)
    elif code in (20, 21):
        eng.metric = code == 21
        yield ModeChange(line, "UNITS", "mm" if eng.metric else "inch")
    elif code in (61, 64):
        yield ModeChange(line, "EXACT_STOP", code == 61)
    elif code == 69:
        eng.reset_transforms()
        yield ModeChange(line, "TRANSFORMS", "default")
    elif code in (90, 91):
        eng.absolute = code == 90
        yield ModeChange(line, "DISTANCE", "absolute" if eng.absolute else "incremental")
    elif code == 92:
        for ref, values in _clauses(tokens, p):
            if ref not in _AXIS or len(values) != 1:
                raise EngineError("G92 (preset) takes axes each with one value")
            eng.pos[_AXIS[ref]] = values[0]
        yield ModeChange(line, "SET_POSITION", dict(zip(AXES, eng.pos, strict=True)))
    elif code == 101:
        _args(tokens, 3, "G101 (rotate vectors)")
        normal = list(eng.vectors[_vector_name(tokens[0])])
        angle = math.radians(_value(tokens[1], p))
        for tok in tokens[2:]:
            name = _vector_name(tok)
            eng.vectors[name] = _rotated(eng.vectors[name], normal, angle)
        yield ModeChange(line, "VECTORS", {v: list(eng.vectors[v]) for v in VECTORS})
    elif code == 102:
        _args(tokens, 3, "G102 (set vector)")
        name = _vector_name(tokens[0])
        vec = [0.0] * 9
        for ref, values in _clauses(tokens[1:], p):
            if ref not in _AXIS or len(values) != 1:
                raise EngineError("G102 (set vector) takes axis names each with one scale")
            vec[_AXIS[ref]] = values[0]
        eng.vectors[name] = vec
        yield ModeChange(line, "VECTORS", {name: vec})
    elif code == 103:
        _args(tokens, 3, "G103 (set polar center)")
        name = _polar_name(tokens[0])
        angle, radius = _value(tokens[1], p), _value(tokens[2], p)
        offset = _value(tokens[3], p) if len(tokens) > 3 else 0.0
        n, z, q = eng.frame(name)
        u = _direction(z, q, angle)
        centre = [x - radius * ui - offset * ni for x, ui, ni in zip(eng.pos, u, n, strict=True)]
        eng.polars[name].centre = centre
        eng.polars[name].radius = radius
        yield ModeChange(line, "POLAR_CENTRE", {name: centre})
    elif code in (104, 105):
        what = "G104 (set polar axis)" if code == 104 else "G105 (set polar zero)"
        _args(tokens, 2, what)
        name, ref = _polar_name(tokens[0]), _vector_name(tokens[1])
        if code == 104:
            eng.polars[name].normal = ref
        else:
            eng.polars[name].zero = ref
        yield ModeChange(line, "POLAR_AXIS" if code == 104 else "POLAR_ZERO", {name: ref})
    elif code == 107:
        _args(tokens, 1, "G107 (set drill vector)")
        eng.drill = _vector_name(tokens[0])
        yield ModeChange(line, "DRILL_VECTOR", eng.drill)
    elif code == 108:
        _args(tokens, 2, "G108 (set vector position)")
        name = _vector_name(tokens[0])
        eng.along[name] = _value(tokens[1], p)
        yield ModeChange(line, "VECTOR_POSITION", {name: eng.along[name]})
    else:
        raise EngineError(f"G{code} is not supported yet in the engine dialect")


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

# settings without arguments, which may come before a line's main code
_MODAL = {17, 18, 19, 20, 21, 61, 64, 69, 90, 91}
_G_NUMBER = re.compile(r"g\s*(\d+)(?![\d.])", re.IGNORECASE)
_ASSIGN = re.compile(r"#\s*(<[^>]*>|\d+)\s*=(.*)")


def _line(eng: Engine, n: int, raw: str) -> Iterator[Op]:
    text = _strip(raw)
    if not text or text == "%":
        return
    m = _ASSIGN.fullmatch(text)
    if m is not None:
        value = _value(m.group(2).strip().replace(" ", ""), eng.params)
        key = m.group(1)
        if key.startswith("<"):
            eng.params.names[key[1:-1].replace(" ", "").lower()] = value
        else:
            eng.params.numbered[int(key)] = value
        return
    g = _G_NUMBER.match(text)
    if g is not None:
        code = int(g.group(1))
        rest = _tokens(text[g.end():])
        if code not in _KNOWN:
            raise EngineError(f"Unknown code G{code}")
    else:
        words = _tokens(text)
        if words and words[0].upper() == "F":
            yield from _motion(eng, n, eng.motion, _clauses(words, eng.params))
            return
        named = split_name(words)
        if named is None:
            raise EngineError(f"Unknown name '{words[0]}'")
        code, used = named
        rest = words[used:]
    if code in _MODAL and rest:  # a setting before the line's main code: "G90 G0 X1"
        yield from _setting(eng, n, code, [])
        yield from _line(eng, n, " ".join(rest))
        return
    if code == MOVE:
        code = eng.motion
    if code in (0, 1):
        eng.motion = code
        yield from _motion(eng, n, code, _clauses(rest, eng.params))
    elif code in _NOT_YET:
        raise EngineError(f"G{code} is not supported yet in the engine dialect")
    else:
        yield from _setting(eng, n, code, rest)


_KNOWN = set(NAMES)


def run(text: str, engine: Engine | None = None, file: str | None = None) -> Iterator[Op]:
    """The operations of an engine-dialect program, line by line; an error carries its line."""
    eng = engine if engine is not None else Engine()
    for n, raw in enumerate(text.splitlines(), 1):
        try:
            yield from _line(eng, n, raw)
        except (NgcSemanticError, NgcSyntaxError, NgcRuntimeError) as err:
            raise err.locate(file=file, line=n, source=raw) from None
