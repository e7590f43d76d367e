"""Reading a drawing back: the toolpath group of an ``ngc plot`` SVG as its path commands (in
the view's coordinates, machine units), and a PNG's pixels (8-bit RGB or RGBA, not interlaced)."""

from __future__ import annotations

import re
import struct
import xml.etree.ElementTree as ET
import zlib
from typing import NamedTuple

SVG = "{http://www.w3.org/2000/svg}"
_TOKEN = re.compile(r"[MLACQ]|-?\d+(?:\.\d+)?(?:e-?\d+)?")
_ARGS = {"M": 2, "L": 2, "A": 7, "C": 6, "Q": 4}


class Segment(NamedTuple):
    """One path command with the pen's point before it: ``kind`` M L A C Q, ``start``, its
    numbers, ``stroke`` and whether the path is dashed."""

    kind: str
    start: tuple[float, float]
    args: tuple[float, ...]
    stroke: str
    dashed: bool

    @property
    def end(self) -> tuple[float, float]:
        return (self.args[-2], self.args[-1])


def read_svg(text: str) -> tuple[ET.Element, list[Segment], tuple[float, ...]]:
    """The document, the segments of its toolpath group, and the group's matrix (a b c d e f)."""
    root = ET.fromstring(text)
    group = root.find(f"{SVG}g[@id='toolpath']")
    assert group is not None
    m = re.fullmatch(r"matrix\(([^)]*)\)", group.attrib["transform"])
    assert m is not None
    matrix = tuple(float(v) for v in m.group(1).split())
    segments: list[Segment] = []
    for path in group.iter(f"{SVG}path"):
        tokens = _TOKEN.findall(path.attrib["d"])
        pen = (0.0, 0.0)
        i = 0
        while i < len(tokens):
            cmd = tokens[i]
            n = _ARGS[cmd]
            args = tuple(float(v) for v in tokens[i + 1:i + 1 + n])
            i += 1 + n
            segments.append(Segment(cmd, pen, args, path.attrib["stroke"],
                                    " r" in " " + path.attrib["class"]))
            pen = (args[-2], args[-1])
    return root, segments, matrix


def read_png(data: bytes) -> tuple[int, int, list[bytes]]:
    """Width, height and the rows of RGB(A) pixels of a PNG."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat = 8, b""
    width = height = channels = 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, color, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and interlace == 0 and color in (2, 6)
            channels = 3 if color == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    rows: list[bytes] = []
    prev = bytearray(stride)
    for y in range(height):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b = prev[x]
            c = prev[x - channels] if x >= channels else 0
            if f == 1:
                line[x] = (line[x] + a) & 255
            elif f == 2:
                line[x] = (line[x] + b) & 255
            elif f == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[x] = (line[x] + pred) & 255
        rows.append(bytes(line))
        prev = line
    return width, height, [bytes(r) for r in rows]
