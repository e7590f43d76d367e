"""Hostile input for ngc: random bytes, token soup and mutated golden programs, and the harness
that runs one through the API.  Shared by the property test (tests/test_hostile.py) and the soak
script (tests/fuzz/soak.py).

Every generator takes a ``random.Random`` (or hypothesis's ``st.randoms()``, whose draws it can
shrink) and returns the bytes of one program file:

``random_bytes``   bytes, from any byte to a G-code-like alphabet, with a few long lines
``token_soup``     lines of G-code tokens in random order and lines built from the grammar with
                   hostile values: huge, tiny and non-finite numbers, every operator and function,
                   parameters of all kinds, o-word control flow, M98/M99, comments of every kind
                   (DEBUG, PRINT, LOG...), ``%``, odd line ends; and a few known-hard constructs
                   (subroutine fan-out, nested loops, overflow in every place)
``mutate_golden``  a golden program (tests/golden/cases/*.ngc) with line and byte mutations

``run_api(text)`` runs a program the way a library user does (a fresh ``Interpreter`` on a
``ListSink``, ``write_files=False``, a small ``max_iterations``); the property is that it returns
or raises :class:`ngc.errors.NgcError` (whose ``render()`` works), and does so quickly
(``time_limit``).
"""

from __future__ import annotations

import contextlib
import io
import random
import re
import signal
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import Any

import ngc
from ngc.canon.jsonl import ListSink
from ngc.errors import NgcError
from ngc.interp.interpreter import Interpreter

NGC_DIR = str(Path(ngc.__file__).parent) + "/"
GOLDEN_CASES = Path(__file__).resolve().parent.parent / "golden" / "cases"
MAX_ITERATIONS = 2_000
DECODINGS = ("latin-1", "utf-8")  # how rs274 reads a file; how ngc canon / check read one
FEEDS = ("file", "lines")  # a file object (rs274's way) or text.splitlines() (ngc.interpret's way)

# ---- vocabulary ---------------------------------------------------------------------------------

LETTERS = "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
WORD_LETTERS = "ABCDFGHIJKLMPQRSTUVWXYZ"  # letters a block may hold
G_CODES = ("0", "1", "2", "3", "4", "5.1", "5.2", "7", "8", "10", "17", "18", "19", "20", "21", "28",
           "28.1", "30", "33", "38.2", "40", "41", "42", "43", "43.1", "49", "52", "53", "54", "59.3",
           "61", "64", "73", "76", "80", "81", "83", "90", "91", "91.1", "92", "92.1", "92.3", "93",
           "94", "95", "96", "97", "98", "99", "9999", "-1", "0.5")
M_CODES = ("0", "1", "2", "3", "4", "5", "6", "7", "8", "9", "30", "48", "49", "50", "52", "53",
           "60", "61", "62", "66", "67", "68", "70", "71", "72", "73", "98", "99", "100", "199",
           "-1", "1000")
AXIS_LETTERS = "XYZABCUVWIJKRPQLFSTHD"
NUMBERS = ("0", "1", "-1", "2", "3", ".5", "-0.", "+1", "1.", "0.0001", "7", "9", "10", "31",
           "54", "98", "99", "100", "360", "-360", "1000", "5220", "5400", "5399", "32767",
           "2147483647", "2147483648", "-2147483649", "4294967296", "18446744073709551616",
           "1e999", "1e-999", "1.5e3", "nan", "inf", "-inf", "9" * 40, "1" + "0" * 200,
           "0." + "0" * 200 + "1", "-" + "9" * 60, "1.7976931348623157", "0x10", "1..2", "--1",
           "+-1", ".", "-", "1 2 3")
# Values no float holds, or that lead there: every one must stop the program with a message.
EXTREMES = ("[EXP[710]]", "[-EXP[710]]", "[EXP[710]-EXP[710]]", "[EXP[710]*0]", "[10**400]",
            "[10**-400]", "[-10**309]", "[2**1024]", "[[-8]**[1/3]]", "[0**-1]", "[1/0]",
            "[0/0]", "[SQRT[-1]]", "[LN[0]]", "[LN[-1]]", "[ASIN[2]]", "[ACOS[-2]]",
            "[TAN[90]]", "[EXP[709.78]]", "[EXP[-800]]", "[1e308*10]", "[FIX[EXP[710]]]",
            "[FUP[-EXP[710]]]", "[ROUND[EXP[710]]]", "[ABS[-EXP[710]]]", "[EXP[710] MOD 3]",
            "[3 MOD 0]", "[EXP[710] MOD EXP[710]]", "[ATAN[EXP[710]]/[EXP[710]]]",
            "[ATAN[0]/[0]]", "[SIN[EXP[710]]]", "[COS[EXP[710]-EXP[710]]]")
PARAMS = ("#1", "#2", "#30", "#31", "#0", "#-1", "#5220", "#5221", "#5161", "#5400", "#5399",
          "#5599", "#5600", "#99999", "#100000", "#1.5", "#<x>", "#<y>", "#<X>", "#<_g>", "#<_h>",
          "#<_value>", "#<_value_returned>", "#<_line>", "#<_call_level>", "#<_task>",
          "#<_ini[a]b>", "#<_ini[RS274NGC]FEATURES>", "#<_hal[x]>", "#<>", "#<a b>", "#<_>",
          "##1", "##2", "#[1]", "#[#1]", "#[EXP[710]]", "#[-EXP[710]]", "#[1/3]", "#<_x]",
          "#<x", "#< x >")
OPERATORS = ("+", "-", "*", "/", "**", "MOD", "AND", "OR", "XOR", "EQ", "NE", "GT", "GE", "LT",
             "LE", "mod", "and", "=", "<", ">", "^")
FUNCTIONS = ("SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SQRT", "EXP", "LN", "ABS", "FIX", "FUP",
             "ROUND", "EXISTS", "sin", "Exp", "BOGUS")
OWORD_KEYWORDS = ("sub", "endsub", "call", "while", "endwhile", "do", "repeat", "endrepeat", "if",
                  "elseif", "else", "endif", "break", "continue", "return", "SUB", "Call", "x")
OWORD_LABELS = ("o100", "o101", "o102", "O100", "o1", "o0", "o-1", "o99999", "o100.5", "o<s>",
                "o<t>", "o<S>", "o<_s>", "o< s >", "o<>", "o<../s>", "o</nonexistent/s>",
                "o<s/t>", "o[100]", "o[#1]", "o[EXP[710]]", "o[0/0]", "o#1", "o")
COMMENTS = ("(hello)", "()", "(", ")", "((nested))", "(a(b)", ";semicolon comment", "(DEBUG,#1)",
            "(DEBUG,#<x> and #5220 and #[1+1])", "(DEBUG,#<_value>)", "(DEBUG,#[EXP[710]])",
            "(DEBUG,)", "(debug,x)", "(PRINT,#1)", "(PRINT,#<_line>)", "(PRINT,%d %f %%)",
            "(PRINT,#<undefined>)", "(MSG,message)", "(MSG,)", "(LOGOPEN,hostile.log)",
            "(LOGAPPEND,hostile.log)", "(LOGOPEN,../hostile.log)", "(LOGOPEN,)", "(LOG,#1 #<x>)",
            "(LOG,)", "(LOGCLOSE)", "(PROBEOPEN hostile.probe)", "(PROBECLOSE)",
            "(ABORT,stop #1)", "(ABORT,)", "(é ü €)", "(\x00)", "(\x7f\x01)",
            "(" + "x" * 300 + ")", "(DEBUG," + "#1" * 100 + ")")
ODD_TOKENS = ("%", "/", "/1", "N10", "N", "n99999", "=", "[", "]", "[[", "]]", "#", "#<", "<", ">",
              ",", "\t", " ", "  ", "\x00", "\x0c", "\x0b", "\x1c", "\x85", "\u2028", "\ufeff",
              "é", "€", "\ud800", "\\", "'", '"', "$", "@", "!", "?", "{", "}", "M98", "M99",
              "M98 P100 L3", "M98 P100 L99999", "M98 P1000", "O100", "O1000", "o100 sub",
              "o100 endsub", "o100 call", "o100 while [1]", "o100 endwhile", "o100 do",
              "o100 repeat [3]", "o100 endrepeat", "o100 if [1]", "o100 else", "o100 endif",
              "o100 return [EXP[710]]", "G10 L2 P2", "G10 L20 P1", "G92", "G43 H1", "T1 M6")
LINE_ENDS = ("\n", "\n", "\n", "\r\n", "\r", "\n\n", "\x00\n")
# Bytes that G-code is made of, so random bytes now and then get past the first character.
GCODE_BYTES = b"GMXYZIJKFRPQSTLO0123456789.-+#[]<>()= \n\t%/;abcdefghijklmnopqrstuvwxyz,*"

# ---- known-hard constructs ----------------------------------------------------------------------


def fanout(calls: int, depth: int) -> str:
    """A subroutine that calls itself ``calls`` times per level, ``depth`` levels deep."""
    body = "".join("o100 call [#1+1]\n" for _ in range(calls))
    return (f"o100 sub\no101 if [#1 LT {depth}]\n{body}o101 endif\no100 endsub\n"
            f"o100 call [0]\nM2\n")


def nested_while(depth: int, count: int) -> str:
    """``depth`` nested while loops of ``count`` iterations each."""
    opens = "".join(f"#{i + 1}=0\no{100 + i} while [#{i + 1} LT {count}]\n" for i in range(depth))
    closes = "".join(f"#{i + 1}=[#{i + 1}+1]\no{100 + i} endwhile\n" for i in reversed(range(depth)))
    return opens + "G0 X#1\n" + closes + "M2\n"


SNIPPETS: tuple[Callable[[random.Random], str], ...] = (
    lambda r: fanout(r.randint(1, 10), r.randint(1, 12)),
    lambda r: nested_while(r.randint(1, 6), r.randint(1, 30)),
    lambda r: f"o1 repeat {r.choice(EXTREMES)}\nG0 X1\no1 endrepeat\nM2\n",
    lambda r: "o1 while [1]\n#1=[#1+1]\no1 endwhile\nM2\n",
    lambda r: "o1 do\n#1=[#1+1]\no1 while [#1 GT -1]\nM2\n",
    lambda r: f"o1 repeat [{r.choice(NUMBERS)}]\no2 repeat [{r.choice(NUMBERS)}]\no2 endrepeat\n"
              f"o1 endrepeat\nM2\n",
    lambda r: f"G10 L2 P2 R{r.choice(EXTREMES)}\nG55 G0 X1 Y1\nM2\n",
    lambda r: f"G10 L2 P1 X{r.choice(EXTREMES)}\nG0 X1\nM2\n",
    lambda r: f"G92 X{r.choice(EXTREMES)}\nG1 X1 F1\nM2\n",
    lambda r: f"#1={r.choice(EXTREMES)}\nG0 X#1\nG2 X1 Y1 R#1 F1\nM2\n",
    lambda r: f"#1=EXISTS[#{r.choice(EXTREMES)}]\nM2\n",
    lambda r: f"G{r.choice(EXTREMES)}\nM2\n",
    lambda r: f"M{r.choice(EXTREMES)}\nM2\n",
    lambda r: f"o{r.choice(EXTREMES)} call\nM2\n",
    lambda r: f"o100 sub\no100 return {r.choice(EXTREMES)}\no100 endsub\no100 call\n"
              f"#1=#<_value>\nM2\n",
    lambda r: f"G1 F{r.choice(EXTREMES)} X1\nS{r.choice(EXTREMES)} M3\nM2\n",
    lambda r: f"G0 X{r.choice(EXTREMES)} Y{r.choice(EXTREMES)}\nG1 Z1 F100\nM2\n",
    lambda r: f"T{r.choice(EXTREMES)} M6\nG43 H{r.choice(EXTREMES)}\nM2\n",
    lambda r: f"G4 P{r.choice(EXTREMES)}\nG64 P{r.choice(EXTREMES)}\nM2\n",
    lambda r: f"G81 X1 Y1 Z-1 R1 L{r.choice(EXTREMES)} F10\nG80\nM2\n",
    lambda r: "O1000\nG0 X1\nM99\nM98 P1000 L" + r.choice(NUMBERS) + "\nM2\n",
    lambda r: "G1 X1 F1 " + "Y1 " * 100 + "\nM2\n",
    lambda r: "#1=" + "[" * 60 + "1" + "]" * 60 + "\nM2\n",
    lambda r: "#1=" + "-" * 200 + "1\nM2\n",
    lambda r: "".join(f"#{n}={r.choice(NUMBERS)}\n" for n in range(1, 40)) + "M2\n",
    lambda r: "%\nG0 X1\n%\nG0 X2\n",
    lambda r: "\ufeffG0 X1\nM2\n",
)

# ---- generators ---------------------------------------------------------------------------------


def random_bytes(rng: random.Random) -> bytes:
    """Up to a few hundred bytes: any byte, G-code-ish bytes, or a mix; now and then a long line."""
    n = rng.choice((0, 1, 2, 8, 40, 120, 300))
    style = rng.random()
    if style < 0.3:
        data = rng.randbytes(n)
    else:
        noise = 0.02 if style < 0.8 else 0.3
        data = bytes(rng.randrange(256) if rng.random() < noise else rng.choice(GCODE_BYTES)
                     for _ in range(n))
    if rng.random() < 0.1:
        data += bytes([rng.choice(GCODE_BYTES[:20])]) * rng.choice((253, 300, 2000))
    return data


def expression(rng: random.Random, depth: int = 0) -> str:
    """A bracketed expression, or an atom, from the whole grammar and its hostile values."""
    r = rng.random()
    if depth >= 3 or r < 0.35:
        return atom(rng)
    if r < 0.55:
        return f"[{expression(rng, depth + 1)} {rng.choice(OPERATORS)} {expression(rng, depth + 1)}]"
    if r < 0.75:
        fn = rng.choice(FUNCTIONS)
        if fn == "ATAN":
            return f"ATAN[{expression(rng, depth + 1)}]/[{expression(rng, depth + 1)}]"
        if fn == "EXISTS":
            return f"EXISTS[{rng.choice(PARAMS)}]"
        return f"{fn}[{expression(rng, depth + 1)}]"
    if r < 0.85:
        return f"{rng.choice(('-', '+', '', '--'))}[{expression(rng, depth + 1)}]"
    return f"#[{expression(rng, depth + 1)}]"


def atom(rng: random.Random) -> str:
    r = rng.random()
    if r < 0.4:
        return rng.choice(NUMBERS[:25])
    if r < 0.5:
        return rng.choice(NUMBERS)
    if r < 0.8:
        return rng.choice(PARAMS)
    return rng.choice(EXTREMES)


def value(rng: random.Random) -> str:
    """What follows a word letter: a number, a parameter or an expression."""
    r = rng.random()
    if r < 0.5:
        return rng.choice(NUMBERS[:25])
    if r < 0.7:
        return rng.choice(PARAMS)
    return expression(rng, 1)


def soup_tokens(rng: random.Random) -> str:
    """A line of tokens in no order at all."""
    parts = []
    for _ in range(rng.randint(1, 8)):
        r = rng.random()
        if r < 0.25:
            parts.append(rng.choice(LETTERS) + rng.choice(NUMBERS))
        elif r < 0.4:
            parts.append(rng.choice(OPERATORS + FUNCTIONS))
        elif r < 0.55:
            parts.append(rng.choice(PARAMS))
        elif r < 0.7:
            parts.append(rng.choice(ODD_TOKENS))
        elif r < 0.8:
            parts.append(rng.choice(COMMENTS))
        elif r < 0.9:
            parts.append(expression(rng))
        else:
            parts.append(f"{rng.choice(OWORD_LABELS)} {rng.choice(OWORD_KEYWORDS)}")
    return rng.choice(("", " ", "\t")).join(parts)


def word_line(rng: random.Random) -> str:
    words = []
    for _ in range(rng.randint(1, 5)):
        r = rng.random()
        if r < 0.3:
            words.append("G" + rng.choice(G_CODES))
        elif r < 0.45:
            words.append("M" + rng.choice(M_CODES))
        else:
            words.append(rng.choice(AXIS_LETTERS) + value(rng))
    if rng.random() < 0.1:
        words.append(rng.choice(COMMENTS))
    if rng.random() < 0.1:
        words.insert(0, f"N{rng.randint(0, 99999)}")
    line = rng.choice((" ", "", "  ")).join(words)
    return line.lower() if rng.random() < 0.1 else line


def oword_line(rng: random.Random) -> str:
    label, keyword = rng.choice(OWORD_LABELS[:8]), rng.choice(OWORD_KEYWORDS)
    if keyword in ("while", "if", "elseif", "repeat", "return") or rng.random() < 0.1:
        return f"{label} {keyword} {expression(rng)}"
    if keyword == "call":
        args = " ".join(f"[{expression(rng, 1)}]" for _ in range(rng.randint(0, 3)))
        return f"{label} call {args}".rstrip()
    return f"{label} {keyword}"


def statement(rng: random.Random) -> str:
    """One line: token soup, an assignment, words, an o-word, a comment or an odd token."""
    r = rng.random()
    if r < 0.2:
        return soup_tokens(rng)
    if r < 0.4:
        return f"{rng.choice(PARAMS)}{rng.choice(('=', ' = ', '='))}{expression(rng)}"
    if r < 0.65:
        return word_line(rng)
    if r < 0.82:
        return oword_line(rng)
    if r < 0.92:
        return rng.choice(COMMENTS)
    return rng.choice(ODD_TOKENS)


def tame_expression(rng: random.Random, depth: int = 0) -> str:
    """An expression that evaluates to a modest number (given modest parameters)."""
    r = rng.random()
    if depth >= 2 or r < 0.4:
        return rng.choice(("0", "1", "2", "0.5", "-1", "10", "#1", "#2", "#3", "90"))
    if r < 0.75:
        op = rng.choice(("+", "-", "*", "/", "MOD", "LT", "GT", "EQ", "AND", "OR"))
        return f"[{tame_expression(rng, depth + 1)} {op} {rng.choice(('1', '2', '3', '#1'))}]"
    fn = rng.choice(("SIN", "COS", "ABS", "FIX", "FUP", "ROUND", "SQRT", "EXP"))
    return f"{fn}[ABS[{tame_expression(rng, depth + 1)}] MOD 5]"


def tame_statement(rng: random.Random) -> str:
    """A line that usually runs: assignments, moves, a message."""
    r = rng.random()
    if r < 0.35:
        name = rng.choice(("#1", "#2", "#<x>", "#<_g>", "#3"))
        return f"{name}={tame_expression(rng)}"
    if r < 0.7:
        return (f"G{rng.choice(('0', '1'))} X{tame_expression(rng)} Y{tame_expression(rng)}"
                f"{rng.choice(('', ' F100', ' Z-1 F50'))}")
    if r < 0.8:
        return rng.choice(("G17", "G20", "G21", "G90", "G91", "G54", "G55", "M3 S1000", "M5", "M8",
                           "G2 X1 Y0 I0.5 J0 F100", "T1 M6", "G43 H1", "G4 P0.01"))
    return rng.choice(("(DEBUG,x=#1)", "(PRINT,#<x>)", "(MSG,hi)", "(LOG,#2)", "(comment)"))


def structure(rng: random.Random, depth: int, labels: Iterator[int], wild: float) -> list[str]:
    """A properly nested block of o-word control flow around statements (tame or not)."""
    def body() -> list[str]:
        out: list[str] = []
        for _ in range(rng.randint(1, 3)):
            if depth < 3 and rng.random() < 0.3:
                out += structure(rng, depth + 1, labels, wild)
            else:
                out.append(statement(rng) if rng.random() < wild else tame_statement(rng))
        return out

    o = f"o{next(labels)}"
    r = rng.random()
    if r < 0.3:
        return [f"{o} if [{tame_expression(rng)}]", *body(), f"{o} elseif [#1 GT 1]", *body(),
                f"{o} else", *body(), f"{o} endif"]
    if r < 0.5:
        count, i = rng.choice(("3", "10", "#2", "[#1*2]")), f"#<_i{depth}>"
        return [f"{i}=0", f"{o} while [{i} LT {count}]", f"{i}=[{i}+1]", *body(),
                rng.choice((f"{o} break", f"{o} continue", "(no exit)")), f"{o} endwhile"]
    if r < 0.65:
        return [f"{o} repeat [{rng.choice(('0', '2', '5', '#2'))}]", *body(), f"{o} endrepeat"]
    if r < 0.75:
        return [f"#<_n{depth}>=0", f"{o} do", *body(), f"#<_n{depth}>=[#<_n{depth}>+1]",
                f"{o} while [#<_n{depth}> LT 3]"]
    args = " ".join(f"[{tame_expression(rng)}]" for _ in range(rng.randint(0, 3)))
    ret = rng.choice(("", f"{o} return [#1]", f"{o} return"))
    return [f"{o} sub", *body(), ret, f"{o} endsub", f"{o} call {args}".rstrip(),
            rng.choice(("", "#3=#<_value>", f"{o} call"))]


def token_soup(rng: random.Random) -> bytes:
    """A short program of token soup and grammar-built lines, tame or hostile in a proportion
    drawn per program, some in o-word structures; sometimes a known-hard construct, a closing
    M2, ``%`` delimiters."""
    wild = rng.choice((0.0, 0.05, 0.2, 0.5, 1.0, 1.0))
    labels = iter(range(100, 1000))
    lines: list[str] = []
    for _ in range(rng.choice((0, 1, 2, 3, 5, 8, 13))):
        if rng.random() < 0.15:
            lines += structure(rng, 0, labels, wild)
        else:
            lines.append(statement(rng) if rng.random() < wild else tame_statement(rng))
    if rng.random() < 0.15:
        lines.insert(rng.randint(0, len(lines)), rng.choice(SNIPPETS)(rng).rstrip("\n"))
    if rng.random() < 0.75:
        lines.append(rng.choice(("M2", "M2", "M30", "m2", "%")))
    if rng.random() < 0.1:
        lines.insert(0, "%")
    end = rng.choice(LINE_ENDS)
    text = end.join(lines) + (end if rng.random() < 0.8 else "")
    return text.encode(rng.choice(("utf-8", "utf-8", "utf-16-le")), "surrogatepass")


def golden_corpus(folder: Path = GOLDEN_CASES) -> list[bytes]:
    """The golden programs, in a fixed order."""
    return [p.read_bytes() for p in sorted(folder.glob("*.ngc"))]


_NUMBER = re.compile(rb"[-+]?(?:\d+\.?\d*|\.\d+)")


def _lines(data: bytes) -> list[bytes]:
    return data.split(b"\n")


def _delete_line(rng: random.Random, data: bytes) -> bytes:
    lines = _lines(data)
    del lines[rng.randrange(len(lines))]
    return b"\n".join(lines)


def _duplicate_line(rng: random.Random, data: bytes) -> bytes:
    lines = _lines(data)
    i = rng.randrange(len(lines))
    lines[i:i] = [lines[i]] * rng.choice((1, 1, 2, 10))
    return b"\n".join(lines)


def _swap_lines(rng: random.Random, data: bytes) -> bytes:
    lines = _lines(data)
    i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
    lines[i], lines[j] = lines[j], lines[i]
    return b"\n".join(lines)


def _insert_line(rng: random.Random, data: bytes) -> bytes:
    lines = _lines(data)
    new = statement(rng) if rng.random() < 0.9 else rng.choice(SNIPPETS)(rng).rstrip("\n")
    lines.insert(rng.randint(0, len(lines)), new.encode("utf-8", "surrogatepass"))
    return b"\n".join(lines)


def _insert_token(rng: random.Random, data: bytes) -> bytes:
    token = rng.choice((rng.choice(ODD_TOKENS), rng.choice(PARAMS), rng.choice(EXTREMES),
                        rng.choice(OPERATORS), rng.choice(COMMENTS), expression(rng)))
    i = rng.randint(0, len(data))
    return data[:i] + token.encode("utf-8", "surrogatepass") + data[i:]


def _delete_bytes(rng: random.Random, data: bytes) -> bytes:
    i = rng.randint(0, len(data))
    return data[:i] + data[i + rng.choice((1, 1, 2, 5, 20)):]


def _flip_byte(rng: random.Random, data: bytes) -> bytes:
    if not data:
        return data
    i = rng.randrange(len(data))
    return data[:i] + bytes([rng.randrange(256)]) + data[i + 1:]


def _extreme_number(rng: random.Random, data: bytes) -> bytes:
    spans = [m.span() for m in _NUMBER.finditer(data)]
    if not spans:
        return data
    i, j = rng.choice(spans)
    new = rng.choice((rng.choice(EXTREMES), rng.choice(NUMBERS), rng.choice(PARAMS)))
    return data[:i] + new.encode() + data[j:]


def _truncate(rng: random.Random, data: bytes) -> bytes:
    return data[:rng.randint(0, len(data))]


def _line_ends(rng: random.Random, data: bytes) -> bytes:
    return data.replace(b"\n", rng.choice(LINE_ENDS).encode("latin-1"))


MUTATIONS: tuple[Callable[[random.Random, bytes], bytes], ...] = (
    _delete_line, _duplicate_line, _swap_lines, _insert_line, _insert_line, _insert_token,
    _insert_token, _delete_bytes, _flip_byte, _extreme_number, _extreme_number, _truncate,
    _line_ends)


def mutate(rng: random.Random, data: bytes) -> bytes:
    """A program with one to four mutations."""
    for _ in range(rng.choice((1, 1, 2, 3, 4))):
        data = rng.choice(MUTATIONS)(rng, data)
    return data


def mutate_golden(rng: random.Random, corpus: Sequence[bytes]) -> bytes:
    """A golden program with one to four mutations."""
    return mutate(rng, rng.choice(corpus))


KINDS = ("bytes", "soup", "golden")


def generate(kind: str, rng: random.Random, corpus: Sequence[bytes]) -> bytes:
    if kind == "bytes":
        return random_bytes(rng)
    if kind == "soup":
        return token_soup(rng)
    if kind == "golden":
        return mutate_golden(rng, corpus)
    raise ValueError(f"unknown kind {kind!r}; known: {', '.join(KINDS)}")


# ---- running ------------------------------------------------------------------------------------


def decode(data: bytes, how: str) -> str:
    """Program bytes as text: ``latin-1`` as rs274 reads them, ``utf-8`` (undecodable bytes kept as
    surrogates) as ``ngc canon`` and ``ngc check`` do."""
    return data.decode("latin-1") if how == "latin-1" else data.decode("utf-8", "surrogateescape")


def run_api(text: str, *, feed: str = "file", max_iterations: int = MAX_ITERATIONS) -> ListSink:
    """Run a program through the API; returns the sink, or raises what the interpreter raised.
    An ``NgcError`` is rendered too (what the command line shows), so a failure there shows."""
    sink = ListSink()
    interp = Interpreter(sink, write_files=False, max_iterations=max_iterations)
    interp.startup()
    lines = io.StringIO(text, newline="") if feed == "file" else text.splitlines()
    try:
        interp.run(lines, file="hostile.ngc")
    except NgcError as exc:
        exc.render()
        raise
    return sink


class Overtime(BaseException):
    """Raised by ``time_limit`` when the time is up (a BaseException: ``except Exception`` in the
    code under test does not swallow it)."""


def _alarm(signum: int, frame: Any) -> None:
    raise Overtime


@contextlib.contextmanager
def time_limit(seconds: float, cpu: bool = False) -> Iterator[None]:
    """Raise ``Overtime`` in the block after ``seconds`` of wall time, or with ``cpu`` of this
    process's CPU time (user and system: a busy machine does not make the block slow), main
    thread, Unix."""
    signum, timer = (signal.SIGPROF, signal.ITIMER_PROF) if cpu else (signal.SIGALRM,
                                                                       signal.ITIMER_REAL)
    old = signal.signal(signum, _alarm)
    signal.setitimer(timer, seconds)
    try:
        yield
    finally:
        signal.setitimer(timer, 0)
        signal.signal(signum, old)


def failure_class(exc: BaseException) -> str:
    """``OverflowError in fix (interp/expr.py)``: the exception class and the innermost frame
    inside ngc, which tells bugs apart better than the class alone."""
    where = ""
    tb = exc.__traceback__
    while tb is not None:
        path = tb.tb_frame.f_code.co_filename
        if path.startswith(NGC_DIR):
            where = f" in {tb.tb_frame.f_code.co_name} ({path[len(NGC_DIR):]})"
        tb = tb.tb_next
    return f"{type(exc).__name__}{where}"
