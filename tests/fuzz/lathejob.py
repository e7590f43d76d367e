"""The ``lathejob`` kind: whole lathe jobs as a CAM post or a machinist writes them.

A job has a tool table of lathe tools (orientations 1-9, nose radii, frontangle and backangle),
one or two part profiles in subroutines and a run of operations on a stock: facing, turning
passes, grooving with a dwell, parting, drilling on the centre, G33 threading passes and G76
cycles, G33.1 tapping, G71/G72 roughing (and their .1/.2 forms) on the profiles, G70 finishing
under cutter compensation (G41/G42 with the tool's orientation from the table, or G41.1/G42.1
with D and L) and plain finishing contours under compensation.  Spindle in G96 with and without
D or G97, feed in G95 or G94, G7/G8, in G21 or G20, with tool changes between operations.

Profiles are drawn as a part is: from the face (or the far end, for facing profiles) through
chamfers, diameters, shoulders with fillets (A) or chamfers (C) on the line, tapers, tangent arcs
whose centres are rounded to the program's places (so corners are a hair off tangent), convex and
concave arcs, and grooves the profile dips into and climbs out of (pockets).
"""

from __future__ import annotations

import math
import random

TABLE_MARK = ";tooltable:"  # as gen.TABLE_MARK

# orientation -> (frontangle, backangle) typical of the insert
_ANGLES = {1: (95, 5), 2: (95, 5), 3: (-95, -5), 4: (-95, -5), 5: (45, 135), 6: (-30, 30),
           7: (135, 225), 8: (30, -30), 9: (0, 0)}


class _Job:
    def __init__(self, seed: int) -> None:
        self.rng = random.Random(f"lathejob:{seed}")
        rng = self.rng
        self.metric = rng.random() < 0.7
        self.u = 1.0 if self.metric else 1 / 25.4  # program units per mm
        self.places = 3 if self.metric else 4
        self.diameter = rng.random() < 0.35  # G7
        self.lines: list[str] = []
        self.subs: list[str] = []
        self.table: dict[int, tuple[int, float]] = {}  # tool -> (orientation, diameter in inch)
        self.tool = 0
        self.comp = False
        self.stock_r = round(rng.uniform(10, 40), 0)  # mm
        self.length = round(rng.uniform(30, 90), 0)
        self.label = rng.choice((100, 200, 1000, 10))
        self.lower = rng.random() < 0.1

    # -- numbers ----------------------------------------------------------------------------
    def n(self, mm: float) -> str:
        """A length in mm, written in program units."""
        return self._fmt(mm * self.u)

    def _fmt(self, v: float) -> str:
        v = round(v, self.places)
        text = f"{v:.{self.places}f}"
        if self.rng.random() < 0.6:
            text = text.rstrip("0").rstrip(".")
        if text in ("", "-0", "-"):
            text = "0"
        return text

    def x(self, r_mm: float) -> str:
        """An X word's value: a radius, or a diameter in G7."""
        return self.n(2 * r_mm if self.diameter else r_mm)

    def emit(self, text: str) -> None:
        if self.lower and "(" not in text:
            text = text.lower()
        self.lines.append(text)


# -- the tool table -----------------------------------------------------------------------------
def _table(j: _Job) -> list[str]:
    rng = j.rng
    rows = []
    numbers = rng.sample(range(1, 13), rng.randint(3, 6))
    for i, t in enumerate(numbers):
        q = rng.choice((2, 2, 3, 6, 1, 4, 5, 7, 8, 9)) if i else rng.choice((2, 3))
        radius_in = rng.choice((0.0, 0.008, 0.0156, 0.0313, 0.0472, 0.016, 0.0315))
        d = round(2 * radius_in, 4)
        fa, ba = _ANGLES[q]
        fields = [f"D{d}", f"Z{rng.choice(('+0.0', '+0.25', '-0.1'))}"]
        if rng.random() < 0.6:
            fields.append(f"X{rng.choice(('+0.0', '+0.125', '-0.1'))}")
        fields += [f"I{fa}", f"J{ba}", f"Q{q}"]
        rows.append(f"T{t} P{t} " + " ".join(fields) + " ;" + rng.choice(
            ("turning", "finishing", "boring bar", "grooving", "threading", "drill")))
        j.table[t] = (q, d)
    return rows


def _change_tool(j: _Job, want: tuple[int, ...] = ()) -> None:
    rng = j.rng
    choices = [t for t, (q, _) in j.table.items() if not want or q in want] or list(j.table)
    t = rng.choice(choices)
    if t == j.tool and rng.random() < 0.5:
        return
    j.tool = t
    j.emit(rng.choice((f"T{t} M6 G43", f"T{t} M6", f"T{t}M6G43", f"M6 T{t}\nG43 H{t}")))


# -- spindle, feed, moves ------------------------------------------------------------------------
def _spindle(j: _Job) -> None:
    rng = j.rng
    direction = rng.choice(("M3", "M3", "M4"))
    if rng.random() < 0.6:
        css = rng.choice((150, 180, 200, 250))
        limit = rng.choice((" D2500", " D3000", " D1500", "", " D800"))
        j.emit(f"G96{limit} S{css if j.metric else css * 3} {direction}")
    else:
        j.emit(f"G97 S{rng.choice((500, 800, 1200, 2000))} {direction}")


def _feed(j: _Job, roughing: bool = True) -> None:
    rng = j.rng
    if rng.random() < 0.6:
        mm = rng.choice((0.25, 0.3, 0.2)) if roughing else rng.choice((0.08, 0.1, 0.12))
        j.emit(f"G95 F{j.n(mm)}")
    else:
        j.emit(f"G94 F{j.n(rng.choice((100, 150, 200, 300)))}")


def _safe(j: _Job) -> None:
    j.emit(f"G0 X{j.x(j.stock_r + 5)} Z{j.n(j.rng.choice((2, 3, 5)))}")


# -- operations -------------------------------------------------------------------------------------
def op_face(j: _Job) -> None:
    rng = j.rng
    _change_tool(j, (2, 3, 6, 1))
    _feed(j)
    z = 0.0
    for _ in range(rng.randint(1, 3)):
        z -= rng.choice((0.5, 1.0, 0.25))
        j.emit(f"G0 X{j.x(j.stock_r + 2)} Z{j.n(z)}")
        end = rng.choice((0.0, 0.0, -0.4, 0.5))
        j.emit(f"G1 X{j.x(end)}")
        j.emit(f"G0 Z{j.n(z + 1)}")
    j.face = z  # type: ignore[attr-defined]


def op_turn(j: _Job) -> None:
    rng = j.rng
    _change_tool(j, (2, 3, 1))
    _feed(j)
    r = j.stock_r
    length = round(rng.uniform(5, j.length * 0.7), 1)
    for _ in range(rng.randint(1, 4)):
        r -= rng.choice((1.0, 1.5, 2.0, 0.5))
        j.emit(f"G0 X{j.x(r)} Z{j.n(2)}")
        j.emit(f"G1 Z{j.n(-length)}")
        if rng.random() < 0.5:
            j.emit(f"G1 X{j.x(r + 1)} Z{j.n(-length - 1)}")
        j.emit(f"G0 X{j.x(r + 2)}")
        j.emit(f"G0 Z{j.n(2)}")


def op_groove(j: _Job) -> None:
    rng = j.rng
    _change_tool(j, (6, 8, 2))
    j.emit(f"G95 F{j.n(0.05)}" if rng.random() < 0.5 else f"G94 F{j.n(40)}")
    z = -round(rng.uniform(3, j.length * 0.8), 1)
    depth = round(rng.uniform(1, 4), 1)
    j.emit(f"G0 X{j.x(j.stock_r + 2)} Z{j.n(z)}")
    for _ in range(rng.randint(1, 2)):
        j.emit(f"G1 X{j.x(j.stock_r - depth)}")
        if rng.random() < 0.6:
            j.emit(f"G4 P{rng.choice(('0.5', '1', '0.2'))}")
        j.emit(f"G0 X{j.x(j.stock_r + 2)}")
        z -= rng.choice((2.0, 3.0))
        j.emit(f"G0 Z{j.n(z)}")


def op_part(j: _Job) -> None:
    rng = j.rng
    _change_tool(j, (6, 8))
    j.emit(f"G97 S{rng.choice((400, 600))} M3")
    j.emit(f"G0 X{j.x(j.stock_r + 2)} Z{j.n(-j.length)}")
    j.emit(f"G1 X{j.x(rng.choice((0.0, -0.5, 1.0)))} F{j.n(rng.choice((40, 30)))}")
    j.emit(f"G0 X{j.x(j.stock_r + 5)}")


def op_drill(j: _Job) -> None:
    rng = j.rng
    _change_tool(j, (9, 5, 7))
    j.emit(f"G97 S{rng.choice((600, 900))} M3")
    j.emit(f"G0 X0 Z{j.n(3)}")
    depth = round(rng.uniform(5, 25), 1)
    z = 0.0
    while z > -depth:
        z = max(z - rng.choice((3.0, 5.0)), -depth)
        j.emit(f"G1 Z{j.n(z)} F{j.n(rng.choice((60, 80)))}")
        j.emit(f"G0 Z{j.n(2)}")
        if z > -depth:
            j.emit(f"G0 Z{j.n(z + 0.5)}")
    if rng.random() < 0.5:
        pitch = rng.choice((1.0, 1.25, 1.5))
        j.emit(f"G0 X0 Z{j.n(5)}")
        j.emit(f"G33.1 Z{j.n(-depth + 3)} K{j.n(pitch)}")


def op_thread_g33(j: _Job) -> None:
    rng = j.rng
    _change_tool(j, (6, 8, 2))
    j.emit(f"G97 S{rng.choice((300, 500))} M3")
    pitch = rng.choice((1.0, 1.5, 2.0))
    r = j.stock_r - 2
    length = round(rng.uniform(8, 25), 0)
    depth = 0.0
    for _ in range(rng.randint(2, 4)):
        depth += rng.choice((0.2, 0.3, 0.15))
        j.emit(f"G0 X{j.x(r - depth)} Z{j.n(4)}")
        if rng.random() < 0.3:
            j.emit(f"G33 X{j.x(r - depth - 0.5)} Z{j.n(-length)} K{j.n(pitch)}")
        else:
            j.emit(f"G33 Z{j.n(-length)} K{j.n(pitch)}")
        j.emit(f"G0 X{j.x(r + 2)}")
    j.emit(f"G0 Z{j.n(4)}")


def op_thread_g76(j: _Job) -> None:
    rng = j.rng
    _change_tool(j, (6, 8, 2))
    j.emit(f"G97 S{rng.choice((300, 500))} M3")
    pitch = rng.choice((1.0, 1.5, 2.0, 1.25))
    r = j.stock_r - 2
    j.emit(f"G0 X{j.x(r + 1)} Z{j.n(rng.choice((3, 4, 5)))}")
    depth = round(0.61 * pitch, 3)
    words = [f"P{j.n(pitch)}", f"Z{j.n(-round(rng.uniform(8, 25), 0))}",
             f"I{j.n(-rng.choice((0.5, 1.0)))}", f"J{j.n(rng.choice((0.05, 0.1, 0.2)))}",
             f"K{j.n(depth)}"]
    if rng.random() < 0.7:
        words.append(f"Q{rng.choice((29.5, 29, 30))}")
    if rng.random() < 0.6:
        words.append(f"R{rng.choice((1.5, 2, 1))}")
    if rng.random() < 0.5:
        words.append(f"H{rng.choice((1, 2))}")
    if rng.random() < 0.4:
        words += [f"E{j.n(rng.choice((1.0, 2.0)))}", f"L{rng.choice((0, 1, 2, 3))}"]
    j.emit("G76 " + " ".join(words))
    j.emit(f"G0 X{j.x(j.stock_r + 5)}")


# -- profiles ------------------------------------------------------------------------------------
class _Profile:
    """A profile in (r, z) mm, drawn from the face toward -z, r growing: moves as
    (kind, r1, z1, cr, cz, extra words)."""

    def __init__(self, j: _Job, r0: float) -> None:
        self.j = j
        self.r = r0
        self.z = 0.0
        self.start = (r0, 0.0)
        self.moves: list[tuple[str, float, float, float, float, str]] = []
        self.dir = (0.0, -1.0)  # the tangent at the end (dr, dz)

    def line(self, r: float, z: float, extra: str = "") -> None:
        dr, dz = r - self.r, z - self.z
        n = math.hypot(dr, dz)
        if n < 1e-6:
            return
        last = self.moves[-1] if self.moves else None
        if (last is not None and last[0] == "line" and not last[5]
                and abs(dr / n - self.dir[0]) < 1e-9 and abs(dz / n - self.dir[1]) < 1e-9):
            self.moves.pop()  # (G70 refuses two lines in line: one line instead)
        self.moves.append(("line", r, z, 0.0, 0.0, extra))
        self.dir = (dr / n, dz / n)
        self.r, self.z = r, z

    def arc(self, kind: str, r: float, z: float, cr: float, cz: float) -> None:
        self.moves.append((kind, r, z, cr, cz, ""))
        # the tangent at the end: the radius turned a quarter the arc's way (G2 in (z, x): CW)
        vr, vz = r - cr, z - cz
        n = math.hypot(vr, vz)
        if kind == "G3":
            self.dir = (vz / n, -vr / n)
        else:
            self.dir = (-vz / n, vr / n)
        self.r, self.z = r, z


def _round(j: _Job, v: float) -> float:
    """A value as it is written in program units, back in mm."""
    return round(v * j.u, j.places) / j.u


def _draw_profile(j: _Job, pockets: bool) -> _Profile:
    rng = j.rng
    top = j.stock_r - rng.choice((0.5, 1.0, 2.0))
    r = round(rng.uniform(0, top * 0.4), 1) if rng.random() < 0.6 else 0.0
    p = _Profile(j, r)
    z_end = -round(rng.uniform(0.4, 0.9) * j.length, 0)
    features = rng.randint(3, 8)
    for _ in range(features):
        if p.z <= z_end + 2 or p.r >= top - 0.5:
            break
        room_r = top - p.r
        f = rng.random()
        if f < 0.15 and not p.moves:  # a chamfer at the face
            c = round(rng.uniform(0.3, 1.5), 1)
            p.line(min(p.r + c, top), p.z - c)
        elif f < 0.35:  # a diameter
            p.line(p.r, max(p.z - round(rng.uniform(2, 12), 1), z_end))
        elif f < 0.5:  # a shoulder, with a fillet or chamfer at its top now and then
            step = round(rng.uniform(0.5, min(room_r, 8)), 1)
            extra = ""
            if rng.random() < 0.45 and p.z - 1.5 > z_end:
                extra = f" {rng.choice('AC')}{j.n(rng.choice((0.3, 0.5, 0.8, 1.0)))}"
            p.line(p.r + step, p.z, extra)
            p.line(p.r, max(p.z - round(rng.uniform(1.5, 8), 1), z_end))
        elif f < 0.6:  # a taper
            p.line(min(p.r + round(rng.uniform(0.5, 4), 1), top),
                   max(p.z - round(rng.uniform(2, 8), 1), z_end))
        elif f < 0.75:  # a tangent arc from the current direction, its centre rounded
            _tangent_arc(j, p, top, z_end)
        elif f < 0.85:  # a quarter arc: convex shoulder or concave fillet
            rad = round(rng.uniform(0.5, min(room_r, 6)), 1)
            if rad <= 0.3:
                continue
            if rng.random() < 0.5:  # convex: from a face up to a diameter
                p.line(p.r + 0.0, p.z)
                p.arc("G3", p.r + rad, p.z - rad, p.r, p.z - rad)
            else:  # concave: from a diameter up a shoulder
                p.arc("G2", p.r + rad, p.z - rad, p.r + rad, p.z)
        elif pockets and p.r > 2:  # a groove: down, along, up
            depth = round(rng.uniform(0.5, min(3.0, p.r - 1)), 1)
            w = round(rng.uniform(1, 4), 1)
            if rng.random() < 0.5:
                p.line(p.r - depth, p.z - rng.choice((0.0, 0.5, 1.0)) - 0.01)
                p.line(p.r, p.z - w)
                p.line(p.r + depth + rng.choice((0.0, 0.5)), p.z - rng.choice((0.0, 0.5)) - 0.01)
            else:  # a round groove
                rad = round(w / 2, 2)
                p.arc("G3", p.r, p.z - 2 * rad, p.r, p.z - rad)
        else:
            p.line(p.r, max(p.z - round(rng.uniform(2, 6), 1), z_end))
    if not p.moves or rng.random() < 0.5:
        p.line(p.r, max(min(p.z - 2, z_end), p.z - 10))
    return p


def _tangent_arc(j: _Job, p: _Profile, top: float, z_end: float) -> None:
    """An arc leaving the current direction along its tangent, its centre rounded as written."""
    rng = j.rng
    dr, dz = p.dir
    rad = round(rng.uniform(2, 12), 1)
    turn_left = rng.random() < 0.5  # in (z, r): left is toward +r when going -z
    # the centre: the direction turned a quarter (left in (z, r): (dz, dr) -> (-dr, dz))
    nz, nr = (-dr, dz) if turn_left else (dr, -dz)
    cz, cr = _round(j, p.z + nz * rad), _round(j, p.r + nr * rad)
    start = math.atan2(p.r - cr, p.z - cz)
    sweep = rng.uniform(0.2, 1.2) * (1 if turn_left else -1)
    radius = math.hypot(p.r - cr, p.z - cz)
    end = start + sweep
    ez, er = _round(j, cz + radius * math.cos(end)), _round(j, cr + radius * math.sin(end))
    if not (ez < p.z - 0.2 and z_end < ez and -0.5 < er < top):
        return
    # along Z one way only: no point of the arc beyond its ends in Z
    for k in range(1, 20):
        a = start + sweep * k / 20
        z = cz + radius * math.cos(a)
        if not ez < z < p.z:
            return
    # G3 is counterclockwise in (z, x)
    p.arc("G3" if turn_left else "G2", er, ez, cr, cz)


def _write_profile(j: _Job, p: _Profile, label: int, frame: str, approach: tuple[float, float]
                   ) -> list[str]:
    """The profile subroutine, turned into the XZ plane: ``frame`` 'turn' (as drawn), 'bore'
    (r measured down from the stock's bore), 'face' (r and z swapped)."""
    rng = j.rng

    def xz(r: float, z: float) -> tuple[float, float]:
        if frame == "bore":
            return j.stock_r - r, z
        if frame == "face":
            return j.stock_r + z * 0.5 + 5, -r * 0.5
        return r, z

    out = [f"O{label} SUB"]
    x0, z0 = xz(*p.start)
    out.append(f"{rng.choice(('G0', 'G1', 'G0'))} X{j.x(x0)} Z{j.n(z0)}")
    px, pz = x0, z0
    absolute_ij = False
    for kind, r1, z1, cr, cz, extra in p.moves:
        x1, z1_ = xz(r1, z1)
        if kind == "line":
            words = []
            if abs(x1 - px) > 1e-9 or rng.random() < 0.2:
                if rng.random() < 0.1:
                    words.append(f"U{j.x(x1 - px)}")
                else:
                    words.append(f"X{j.x(x1)}")
            if abs(z1_ - pz) > 1e-9 or not words:
                if rng.random() < 0.1:
                    words.append(f"W{j.n(z1_ - pz)}")
                else:
                    words.append(f"Z{j.n(z1_)}")
            modal = out[-1][:2] == "G1" or out[-1][0] in "XZUW"
            out.append(rng.choice(("G1 ", "G1 ", "" if modal else "G1 ")) + " ".join(words) + extra)
        else:
            ccx, ccz = xz(cr, cz)
            code = kind
            if frame == "bore":  # a mirror image turns the arc round (facing turns it a quarter)
                code = "G2" if kind == "G3" else "G3"
            if rng.random() < 0.8 or absolute_ij:
                out.append(f"{code} X{j.x(x1)} Z{j.n(z1_)} I{j.n(ccx - px)} K{j.n(ccz - pz)}")
            else:
                rad = math.hypot(px - ccx, pz - ccz)
                out.append(f"{code} X{j.x(x1)} Z{j.n(z1_)} R{j.n(rad)}")
        px, pz = x1, z1_
    if rng.random() < 0.85:  # out to the start's diameter (or face) again, as most programs end
        ax, az = approach
        out.append(f"G{rng.choice((0, 1))} X{j.x(ax if frame != 'face' else px)} "
                   f"Z{j.n(pz if frame != 'face' else az)}")
    out.append(f"O{label} ENDSUB")
    return out


def _cycle_start(j: _Job, frame: str) -> tuple[float, float]:
    rng = j.rng
    if frame == "bore":
        return j.stock_r - rng.choice((1.0, 2.0)) - j.stock_r * 0.9, rng.choice((1.0, 2.0, 3.0))
    if frame == "face":
        return j.stock_r + rng.choice((2.0, 3.0)) + 5, rng.choice((1.0, 2.0))
    return j.stock_r + rng.choice((1.0, 2.0, 3.0)), rng.choice((1.0, 2.0, 3.0))


def _comp_on(j: _Job, frame: str = "turn") -> None:
    """Compensation on the side the tool cuts from (G42 outside going toward the chuck, G41 in a
    bore), now and then the other."""
    rng = j.rng
    usual, other = ("41", "42") if frame == "bore" else ("42", "41")
    side = usual if rng.random() < 0.9 else other
    q, _d = j.table.get(j.tool, (0, 0.0))
    if rng.random() < 0.5 and j.tool:
        j.emit(f"G{side}" + (f" D{j.tool}" if rng.random() < 0.5 else ""))
    else:
        dia = rng.choice((0.4, 0.8, 1.2, 0.2, 0.0)) * j.u
        words = f"G{side}.1 D{j._fmt(dia)}"
        if rng.random() < 0.7:
            words += f" L{rng.choice((2, 3, 1, 4, 6, 8, 5, 7, 9, q or 2))}"
        j.emit(words)
    j.comp = True


def op_profile(j: _Job) -> None:
    """Rough a profile with G71/G72 and finish it with G70, under compensation now and then."""
    rng = j.rng
    frame = rng.choice(("turn", "turn", "turn", "bore", "face"))
    pockets = rng.random() < 0.5
    p = _draw_profile(j, pockets)
    label = j.label
    j.label += rng.choice((1, 10, 100))
    sx, sz = _cycle_start(j, frame)
    j.subs += _write_profile(j, p, label, frame, (sx, sz))
    _change_tool(j, (2, 3, 1, 4))
    _spindle(j)
    _feed(j)
    if rng.random() < 0.3:
        j.emit(f"G0 X{j.x(sx)} Z{j.n(sz)}")
    code = ("G72" if frame == "face" else "G71") + rng.choice(("", "", ".1", ".2"))
    words = [f"Q{label}", f"X{j.x(sx)}", f"Z{j.n(sz)}"]
    d = rng.choice((0.0, 0.2, 0.3, 0.5))
    if d or rng.random() < 0.3:
        words.append(f"D{j.n(d)}")
    words.append(f"I{j.n(rng.choice((0.5, 1.0, 1.5, 2.0, 0.75)))}")
    if rng.random() < 0.7:
        words.append(f"R{j.n(rng.choice((0.2, 0.3, 0.5)))}")
    if rng.random() < 0.85:
        j.emit(f"{code} " + " ".join(words))
        if rng.random() < 0.4 and code[3:] != ".2":  # the pockets after .1
            j.emit(f"{code[:3]}.2 " + " ".join(words))
    if rng.random() < 0.8:
        if rng.random() < 0.5:
            _change_tool(j, (2, 3, 1, 4))
        _feed(j, False)
        comp = rng.random() < 0.5
        if rng.random() < 0.15 and not comp:
            j.emit(f"G0 X{j.x(sx)} Z{j.n(sz)}")
        if comp:
            _comp_on(j, frame)
        words = [f"Q{label}", f"X{j.x(sx)}", f"Z{j.n(sz)}"]
        passes = rng.choice((1, 1, 2, 3))
        if passes > 1 or rng.random() < 0.3:
            words += [f"D{j.n(rng.choice((0.5, 0.3, 1.0)))}", f"P{passes}"]
        if rng.random() < 0.4:
            words.append(f"E{j.n(rng.choice((0.0, 0.1, 0.05)))}")
        j.emit("G70 " + " ".join(words))
        if comp:
            j.emit(rng.choice(("G40", f"G40 G0 X{j.x(sx + 2)}")))
            j.comp = False
    j.emit(f"G0 X{j.x(sx + 2)}" if frame != "face" else f"G0 Z{j.n(sz + 2)}")


def op_contour(j: _Job) -> None:
    """A finishing pass of plain moves under compensation (a profile written out)."""
    rng = j.rng
    p = _draw_profile(j, False)
    _change_tool(j, (2, 3))
    _feed(j, False)
    x0, z0 = p.start
    j.emit(f"G0 X{j.x(x0)} Z{j.n(rng.choice((2.0, 3.0)))}")
    _comp_on(j)
    j.emit(f"G1 Z{j.n(z0)}" if rng.random() < 0.7 else f"G0 X{j.x(x0)} Z{j.n(z0)}")
    for kind, r1, z1, cr, cz, _extra in p.moves:
        if kind == "line":
            j.emit(f"G1 X{j.x(r1)} Z{j.n(z1)}")
        else:
            pr, pz = _last(j, p, r1, z1)
            j.emit(f"{kind} X{j.x(r1)} Z{j.n(z1)} I{j.n(cr - pr)} K{j.n(cz - pz)}")
    j.emit(f"G1 X{j.x(j.stock_r + 1)}")
    j.emit(rng.choice(("G40", f"G40 G0 X{j.x(j.stock_r + 4)}")))
    j.comp = False
    j.emit(f"G0 X{j.x(j.stock_r + 5)} Z{j.n(3)}")


def _last(j: _Job, p: _Profile, r1: float, z1: float) -> tuple[float, float]:
    """The point before the move of ``p`` that ends at (r1, z1)."""
    prev = p.start
    for _, r, z, _, _, _ in p.moves:
        if (r, z) == (r1, z1):
            return prev
        prev = (r, z)
    return prev


def op_mode(j: _Job) -> None:
    """A change of diameter mode, or of spindle or coolant, between operations."""
    rng = j.rng
    r = rng.random()
    if r < 0.4:
        j.diameter = not j.diameter
        j.emit("G7" if j.diameter else "G8")
    elif r < 0.7:
        _spindle(j)
    else:
        j.emit(rng.choice(("M8", "M9", "M7", "(check part)", "M1", "(MSG,turn part over)")))


OPS = [(3, op_face), (3, op_turn), (2, op_groove), (1, op_part), (1.5, op_drill),
       (2, op_thread_g33), (2, op_thread_g76), (8, op_profile), (3, op_contour), (2, op_mode)]


def gen_lathejob(seed: int) -> str:
    j = _Job(seed)
    rng = j.rng
    rows = _table(j)
    units = "G21" if j.metric else "G20"
    j.emit(f"G18 {units} G90 G40 G80 {'G7' if j.diameter else 'G8'}" + rng.choice(("", " G54", " G64 P0.01")))
    j.emit(f"(stock {j.stock_r * 2:g} x {j.length:g} mm)")
    _change_tool(j)
    _spindle(j)
    if rng.random() < 0.6:
        j.emit("M8")
    _safe(j)
    ops = [rng.choices([f for _, f in OPS], [w for w, _ in OPS])[0] for _ in range(rng.randint(2, 6))]
    if op_profile not in ops and rng.random() < 0.7:
        ops.insert(rng.randrange(len(ops) + 1), op_profile)
    for op in ops:
        op(j)
        if rng.random() < 0.5:
            _safe(j)
    j.emit("M9")
    j.emit("M5")
    j.emit(f"G0 X{j.x(j.stock_r + 20)} Z{j.n(20)}")
    j.emit(rng.choice(("M2", "M30")))
    head = [TABLE_MARK + " " + row for row in rows]
    where = 1 if rng.random() < 0.7 else 0  # the subroutines after the first line, or first
    body = j.lines[:where] + j.subs + j.lines[where:]
    return "".join(line + "\n" for line in head + body)


__all__ = ["gen_lathejob"]
