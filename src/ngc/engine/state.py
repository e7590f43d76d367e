"""The engine dialect's operations and machine state.

Positions are kept as machine positions in millimetres (degrees for A B C), whatever the program's
units: a program value is scaled on the way in and the operations give positions back in the
program's units.  Fixture and tool offsets are in millimetres (the setup sheet's units).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import NamedTuple

from ..budget import DEFAULT_MAX_ITERATIONS
from ..errors import NgcRuntimeError, NgcSemanticError
from .bezier import Cubic
from .setup import Setup

EngineError = NgcSemanticError

AXES = "XYZABCUVW"
AXIS = {a: i for i, a in enumerate(AXES)}
ROTARY = frozenset({3, 4, 5})
VECTORS = tuple("V" + a for a in AXES)
POLARS = ("PX", "PY", "PZ")
INCH = 25.4
# polar transform -> (normal, zero) by default
POLAR_DEFAULTS = {"PZ": ("VZ", "VX"), "PX": ("VX", "VY"), "PY": ("VY", "VZ")}
# contour plane -> (first, second, normal) axis indices; G16's radius is on the first, its angle
# on the second (the seed's table)
PLANES = {"XY": (0, 1, 2), "ZX": (2, 0, 1), "YZ": (1, 2, 0)}


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


class Stop(NamedTuple):
    """G61: the engine waits for every axis to stop before the next command."""

    line: int


class ProgramStop(NamedTuple):
    """M0, M1, M2 and M30, by LinuxCNC's canon names: ``PROGRAM_STOP`` (M0), ``OPTIONAL_PROGRAM_STOP``
    (M1) or ``PROGRAM_END`` (M2, M30: nothing after it runs)."""

    line: int
    name: str


class ModeChange(NamedTuple):
    """A setting that moves nothing: ``name`` (UNITS, PLANE, FEED_RATE, FIXTURE, ...) and its
    new value."""

    line: int
    name: str
    value: object


Op = EngineSegment | Dwell | Stop | ProgramStop | ModeChange


@dataclass
class Polar:
    """A polar transform: its normal and zero vectors' names; centre (machine, mm) and radius
    (mm)."""

    normal: str
    zero: str
    centre: list[float] | None = None
    radius: float = 0.0


@dataclass
class PolarMode:
    """G16: the polar origin (machine, mm) and the last radius (mm) and angle (degrees)."""

    origin: list[float]
    radius: float
    angle: float


@dataclass
class Cycle:
    """What drilling cycles keep until G80: levels along the drill vector (mm), peck (mm) and
    dwell (s)."""

    retract: float | None = None
    bottom: float | None = None
    peck: float | None = None
    dwell: float | None = None


class Params:
    """Parameters by number or name, for expressions."""

    def __init__(self) -> None:
        self.numbered: dict[int, float] = {}
        self.names: dict[str, float] = {"__probe_stop": 0.0}

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


def unit_vector(k: int) -> list[float]:
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
    feed: float | None = None  # mm/s
    feed_rotary: float | None = None  # degrees/s, on moves of A B C alone
    plane: str = "XY"
    exact: bool = False
    vectors: dict[str, list[float]] = field(default_factory=dict)
    along: dict[str, float] = field(default_factory=dict)
    polars: dict[str, Polar] = field(default_factory=dict)
    drill: str = "VZ"
    fixture: int = 0
    tool_offset: bool = False
    polar_mode: PolarMode | None = None
    cycle: Cycle = field(default_factory=Cycle)
    running: dict[int, float] = field(default_factory=dict)  # axis -> speed (mm/s, degrees/s)
    spindle: str = "off"  # M3 "clockwise", M4 "counterclockwise", M5 "off"
    spindle_speed: float = 0.0  # S, revolutions per minute
    mist: bool = False  # M7 (M9 off)
    flood: bool = False  # M8 (M9 off)
    ended: bool = False  # M2, M30
    params: Params = field(default_factory=Params)
    setup: Setup = field(default_factory=Setup)
    # The work budget of a run (``--max-iterations``): each engine segment and each drilling peck
    # counts one, so a program whose numbers ask for billions of them ends with an error.
    max_iterations: int = DEFAULT_MAX_ITERATIONS
    iterations: int = 0

    def __post_init__(self) -> None:
        self.reset_transforms()

    def reset_transforms(self) -> None:
        """G69: every vector and polar transform back to its default."""
        self.vectors = {name: unit_vector(k) for k, name in enumerate(VECTORS)}
        self.along = dict.fromkeys(VECTORS, 0.0)
        self.polars = {p: Polar(*POLAR_DEFAULTS[p]) for p in POLARS}

    def work(self, count: int = 1) -> None:
        """``count`` more segments or pecks against the work budget; past it, an error."""
        self.iterations += count
        if self.iterations > self.max_iterations:
            raise NgcRuntimeError(
                f"Work limit reached: {self.max_iterations} segments and drilling pecks; the "
                "program asks for more than that (raise the limit with --max-iterations)")

    # -- units and offsets ----------------------------------------------------------------------
    @property
    def length_unit(self) -> float:
        """Millimetres per program unit of length."""
        return 1.0 if self.metric else INCH

    def unit(self, k: int) -> float:
        """Millimetres (or degrees) per program unit on axis ``k``."""
        return 1.0 if k in ROTARY else self.length_unit

    def offsets(self) -> list[float]:
        """Machine position minus program position (mm): the fixture's offsets and, with G43,
        the selected tool's length along the fixture's tool axis."""
        fixture = self.setup.fixtures[self.fixture]
        out = list(fixture.offsets)
        if self.tool_offset:
            k, sign = fixture.tool_axis
            out[k] += sign * self.tool_length()
        return out

    def tool_length(self) -> float:
        tool = self.setup.tool
        if tool is None:
            raise EngineError("G43 (apply tool length offset): the machine setup selects no tool")
        if tool not in self.setup.lengths:
            raise EngineError(f"G43 (apply tool length offset): the machine setup gives tool "
                              f"{tool} no length")
        return self.setup.lengths[tool]

    def program(self) -> list[float]:
        """The current position in program coordinates (mm)."""
        return [p - o for p, o in zip(self.pos, self.offsets(), strict=True)]

    def shown(self, k: int, value: float) -> float:
        """A machine value (mm) on axis ``k`` in program units."""
        return value / self.unit(k)

    # -- polar geometry -------------------------------------------------------------------------
    def frame(self, polar: str) -> tuple[list[float], list[float], list[float]]:
        """(normal, zero, quarter): the polar transform's axis, its zero-degree direction and the
        direction at 90 degrees (normal x zero, on X Y Z)."""
        p = self.polars[polar]
        n, z = self.vectors[p.normal], self.vectors[p.zero]
        return n, z, cross(n, z)


def cross(n: list[float], z: list[float]) -> list[float]:
    """``n x z`` on X Y Z (the other axes 0)."""
    q = [0.0] * 9
    q[0] = n[1] * z[2] - n[2] * z[1]
    q[1] = n[2] * z[0] - n[0] * z[2]
    q[2] = n[0] * z[1] - n[1] * z[0]
    return q


def direction(z: list[float], q: list[float], degrees: float) -> list[float]:
    """The direction at ``degrees`` from ``z`` toward ``q``."""
    a = math.radians(degrees)
    c, s = math.cos(a), math.sin(a)
    return [c * zi + s * qi for zi, qi in zip(z, q, strict=True)]
