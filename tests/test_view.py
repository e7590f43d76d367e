"""``ngc view``: the page in a real browser (Debian's chromium driven by Playwright, WebGL through
SwiftShader), and the page's bytes.

Each program of the golden drawings (lines, arcs in the three planes, a helix, cycles, mill and
lathe compensation, lathe cycles, NURBS, rotation with offsets, inch, tool changes, an error stop)
and two engine-dialect programs: the page loads with no console error and no page error, draws
the toolpath where its projection says, a click on a segment selects its line, ``select(line)``
lights its segments, the slider puts the tool where ``ngc time --trajectory`` says, measure gives
the distance between two points of the path, and ``--watch`` reloads the page after an edit.
"""

from __future__ import annotations

import csv
import itertools
import math
import os
import shutil
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parent.parent
GOLDEN = ROOT / "tests" / "golden" / "plot"
PROGRAMS = [*sorted(GOLDEN.glob("*.ngc")), ROOT / "docs" / "engine" / "oval.ngc",
            ROOT / "docs" / "engine" / "trim.ngc"]
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
ARGS = ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader"]
BACKGROUND = (0xFB, 0xFB, 0xFD)


def _ngc(*argv: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "ngc", *argv], capture_output=True, text=True,
                          timeout=300, cwd=cwd)


def _page(program: Path, out: Path) -> Path:
    done = _ngc("view", str(program), "-o", str(out))
    assert done.returncode in (0, 1), done.stderr
    return out


# -- the page's bytes (no browser) --------------------------------------------------------------
def test_the_page_is_the_same_bytes_each_time(tmp_path: Path) -> None:
    a = _page(ROOT / "examples" / "pocket.ngc", tmp_path / "a.html").read_bytes()
    b = _page(ROOT / "examples" / "pocket.ngc", tmp_path / "b.html").read_bytes()
    assert a == b
    text = a.decode()
    assert "http://" not in text.split('id="ngc-meta"')[0].replace("http://www.w3.org", "")
    assert "<script src=" not in text and "The MIT License" in text  # inlined, with the licence


def test_a_file_that_cannot_be_read_is_refused_as_check_refuses_it(tmp_path: Path) -> None:
    view = _ngc("view", "nope.ngc", "-o", str(tmp_path / "x.html"), cwd=tmp_path)
    check = _ngc("check", "nope.ngc", cwd=tmp_path)
    assert (view.returncode, check.returncode) == (2, 2)
    assert view.stderr.replace("ngc view:", "ngc check:") == check.stderr
    assert not (tmp_path / "x.html").exists()


def test_a_program_with_an_error_still_makes_its_page(tmp_path: Path) -> None:
    done = _ngc("view", str(GOLDEN / "error-stop.ngc"), "-o", str(tmp_path / "e.html"))
    assert done.returncode == 1
    assert "error-stop.ngc:" in done.stderr and (tmp_path / "e.html").stat().st_size > 0


# -- in the browser ------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def browser() -> Iterator[Any]:
    required = os.environ.get("NGC_REQUIRE_BROWSER") == "1"  # (.ci/run sets it)
    if CHROMIUM is None:
        reason = "no chromium here (apt-get install chromium): the page is not tested in a browser"
        if required:
            pytest.fail(reason)
        pytest.skip(reason)
    try:
        import playwright.sync_api as playwright
    except ImportError:
        reason = "Playwright for Python is not installed (pip install -e '.[test]')"
        if required:
            pytest.fail(reason)
        pytest.skip(reason)
    with playwright.sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=ARGS)
        yield b
        b.close()


class Opened:
    def __init__(self, page: Any, errors: list[str]) -> None:
        self.page = page
        self.errors = errors

    def js(self, expression: str, arg: object = None) -> Any:
        return self.page.evaluate(expression, arg)


def _open(browser: Any, url: str) -> Opened:
    page = browser.new_page(viewport={"width": 1280, "height": 800})
    errors: list[str] = []
    page.on("console", lambda m: errors.append(f"console {m.type}: {m.text}")
            if m.type in ("error", "warning") else None)
    page.on("pageerror", lambda e: errors.append(f"page error: {e}"))
    page.goto(url)
    page.evaluate("window.ngcView.ready.then(() => true)")
    return Opened(page, errors)


PIXELS = """([x, y]) => { const c = window.ngcView.viewer.renderer.domElement;
    window.ngcView.viewer.drawNow();
    const r = c.getBoundingClientRect(), k = c.width / r.width;
    const s = document.createElement("canvas"); s.width = c.width; s.height = c.height;
    const g = s.getContext("2d"); g.drawImage(c, 0, 0);
    const d = g.getImageData(Math.round((x - r.left) * k) - 2, Math.round((y - r.top) * k) - 2, 5, 5).data;
    const out = []; for (let i = 0; i < d.length; i += 4) out.push([d[i], d[i + 1], d[i + 2]]);
    return out; }"""


def _pixels(o: Opened, x: float, y: float) -> list[tuple[int, int, int]]:
    """The canvas's pixels within 2 px of the page point (x, y), as drawn now."""
    return [tuple(p) for p in o.js(PIXELS, [x, y])]


def _longest_cut(o: Opened) -> int:
    return int(o.js("""() => { const v = window.ngcView.viewer; let best = -1, len = -1;
        for (let i = 0; i < v.count; i++) { if (v.segKind[i] === 0) continue;
          const p = v.positions, k = i * 6;
          const d = Math.hypot(p[k+3]-p[k], p[k+4]-p[k+1], p[k+5]-p[k+2]);
          if (d > len) { len = d; best = i; } } return best; }"""))


@pytest.mark.parametrize("program", PROGRAMS, ids=[p.name for p in PROGRAMS])
def test_the_page_loads_draws_and_selects(browser: Any, tmp_path: Path, program: Path) -> None:
    page = _page(program, tmp_path / "p.html")
    o = _open(browser, page.as_uri())
    assert o.errors == []
    count = o.js("window.ngcView.segments")
    assert count > 0
    # the toolpath is drawn where its projection says (a few segments across the path)
    drawn = 0
    samples = sorted({0, count // 3, 2 * count // 3, count - 1})
    for i in samples:
        x, y = o.js("(i) => window.ngcView.screenOfSegment(i)", i)
        if any(p != BACKGROUND for p in _pixels(o, x, y)):
            drawn += 1
    assert drawn == len(samples)
    # a click on a segment selects its line, and the text marks it
    i = _longest_cut(o)
    if i >= 0:
        line = o.js("(i) => window.ngcView.lineOfSegment(i)", i)
        x, y = o.js("(i) => window.ngcView.screenOfSegment(i)", i)
        o.page.mouse.click(x, y)
        picked = o.js("window.ngcView.selected()")
        near = o.js("""([line, x, y]) => window.ngcView.segmentsOfLine(line).some((s) => {
            const [a, b] = window.ngcView.screenOfSegment(s); return Math.hypot(a - x, b - y) < 9; })""",
                    [picked, x, y])
        assert picked == line or near
        current = o.page.locator('[aria-current="true"]')
        assert current.get_attribute("data-line") == str(picked)
        # select(line) lights its segments
        lit = o.js("(line) => window.ngcView.select(line)", line)
        assert lit == len(o.js("(l) => window.ngcView.segmentsOfLine(l)", line)) > 0
        assert any(abs(r - 0xFF) < 40 and abs(g - 0x1F) < 60 and abs(b - 0x5A) < 60
                   for r, g, b in _pixels(o, x, y))
    o.page.close()


def _trajectory_at(path: Path, t: float) -> tuple[float, float, float]:
    rows = list(csv.DictReader(path.open()))
    for a, b in itertools.pairwise(rows):
        ta, tb = float(a["t"]), float(b["t"])
        if ta <= t <= tb:
            f = (t - ta) / (tb - ta) if tb > ta else 0.0
            return tuple(float(a[k]) + (float(b[k]) - float(a[k])) * f for k in "xyz")  # type: ignore[return-value]
    raise AssertionError(f"no row about {t}")


@pytest.mark.parametrize("name", ["helix.ngc", "cycles.ngc", "lines.ngc"])
def test_the_slider_puts_the_tool_where_the_trajectory_says(browser: Any, tmp_path: Path,
                                                            name: str) -> None:
    program = GOLDEN / name
    page = _page(program, tmp_path / "p.html")
    done = _ngc("time", str(program), "--trajectory", str(tmp_path / "t.csv"))
    assert done.returncode == 0, done.stderr
    o = _open(browser, page.as_uri())
    total = o.js("window.ngcView.viewer.meta.time.total")
    half = total / 2
    o.page.locator("#slider").fill("5000")  # the slider's middle: half the time
    at = o.js("window.ngcView.toolPosition()")
    expected = _trajectory_at(tmp_path / "t.csv", half)
    assert math.dist(at, expected) < 0.05, (at, expected)
    assert o.errors == []


def test_measure_gives_the_distance_between_two_points(browser: Any, tmp_path: Path) -> None:
    page = _page(GOLDEN / "lines.ngc", tmp_path / "p.html")
    o = _open(browser, page.as_uri())
    i = _longest_cut(o)
    a, b = o.js("""(i) => { const v = window.ngcView.viewer, p = v.positions, o = v.meta.origin, k = i * 6;
        return [[p[k]+o[0], p[k+1]+o[1], p[k+2]+o[2]], [p[k+3]+o[0], p[k+4]+o[1], p[k+5]+o[2]]]; }""", i)
    o.page.keyboard.press("m")
    for point in (a, b):
        x, y = o.js("(q) => window.ngcView.screenOfPoint(q[0], q[1], q[2])", point)
        o.page.mouse.click(x, y)
    measured = o.js("window.ngcView.measure()")
    assert measured["distance"] == pytest.approx(math.dist(a, b), abs=1e-3)
    assert measured["dx"] == pytest.approx(b[0] - a[0], abs=1e-3)
    assert "distance" in o.page.locator("#measure-out").inner_text()
    assert o.errors == []


def test_an_error_is_shown_in_the_page(browser: Any, tmp_path: Path) -> None:
    page = _page(GOLDEN / "error-stop.ngc", tmp_path / "p.html")
    o = _open(browser, page.as_uri())
    alert = o.page.locator('[role="alert"]').inner_text()
    assert "error-stop.ngc:" in alert
    line = o.js("window.ngcView.viewer.meta.error.line")
    assert o.page.locator('[aria-current="true"]').get_attribute("data-line") == str(line)
    assert o.errors == []


def test_watch_reloads_the_page_when_the_file_changes(browser: Any, tmp_path: Path) -> None:
    program = tmp_path / "w.ngc"
    program.write_text("G21\nG1 X10 F100\nM2\n")
    server = subprocess.Popen([sys.executable, "-m", "ngc", "view", "--watch", "--no-open",
                               str(program)], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              text=True, env={**os.environ, "PYTHONUNBUFFERED": "1"})
    try:
        assert server.stdout is not None
        line = server.stdout.readline()
        assert "serving http://127.0.0.1:" in line, line
        url = line.split("serving ")[1].split()[0]
        o = _open(browser, url)
        assert o.js("window.ngcView.segments") == 1
        time.sleep(0.5)
        program.write_text("G21\nG1 X10 F100\nG1 Y10\nG1 X0\nM2\n")
        deadline = time.time() + 20
        count = 1
        while time.time() < deadline and count != 3:
            time.sleep(0.3)
            try:
                count = o.js("window.ngcView.ready.then(() => window.ngcView.segments)")
            except Exception:  # (the page is reloading)
                continue
        assert count == 3
        assert o.errors == []
    finally:
        server.send_signal(__import__("signal").SIGINT)
        try:
            code = server.wait(timeout=10)
        except subprocess.TimeoutExpired:
            server.kill()
            raise
    assert code == 0


def test_the_controls(browser: Any, tmp_path: Path) -> None:
    """A line of the text lights its segments, the search finds a line, each colour mode has its
    legend, play moves the time, the help overlay opens with ?, and after the slider the path is
    faded."""
    page = _page(ROOT / "examples" / "pocket.ngc", tmp_path / "p.html")
    o = _open(browser, page.as_uri())
    # a click on a line of the text: its segments lit, the line marked
    o.page.locator('.row[data-line="26"]').click()
    assert o.js("window.ngcView.selected()") == 26
    assert o.page.locator('[aria-current="true"]').get_attribute("data-line") == "26"
    assert o.js("window.ngcView.viewer.highlight.geometry.attributes.position.count") == \
        2 * len(o.js("window.ngcView.segmentsOfLine(26)")) > 0
    # the search: the next line holding the text
    o.page.locator("#search").fill("finishing pass")
    o.page.locator("#search").press("Enter")
    assert o.page.locator('[aria-current="true"]').inner_text().find("finishing pass") > 0
    # the colour modes
    for mode, shown in (("tool", "no tool"), ("feed", "mm/min"), ("speed", "mm/s"), ("kind", "arc")):
        o.page.locator("#colour").select_option(mode)
        assert shown in o.page.locator("#legend").inner_text()
    # play at 10x moves the time on (not so fast that a slow machine sees it reach the end)
    o.page.locator("#slider").fill("0")
    o.page.locator("#rate").select_option("10")
    o.page.locator("#play").click()
    o.page.wait_for_function("window.ngcView.viewer.time > 0", timeout=10_000)
    o.page.locator("#play").click()
    assert 0 < o.js("window.ngcView.viewer.time") <= o.js("window.ngcView.viewer.meta.time.total")
    # the help overlay
    o.page.locator("body").press("?")
    assert o.page.locator("#help").is_visible()
    o.page.locator("body").press("Escape")
    assert not o.page.locator("#help").is_visible()
    # after the slider, the path is faded: the last cut's pixels lighter than at the end
    last = o.js("""() => { const v = window.ngcView.viewer; for (let i = v.count - 1; i >= 0; i--)
        if (v.segKind[i] !== 0) return i; return -1; }""")
    x, y = o.js("(i) => window.ngcView.screenOfSegment(i)", last)
    o.js("(t) => window.ngcView.setTime(t)", o.js("window.ngcView.viewer.meta.time.total"))
    full = min(sum(p) for p in _pixels(o, x, y))
    o.js("() => window.ngcView.setTime(0.1)")
    faded = min(sum(p) for p in _pixels(o, x, y))
    assert faded > full + 100
    assert o.errors == []


@pytest.mark.parametrize("size", [(1280, 720), (2560, 1440), (800, 900)])
def test_laptop_and_large_screens(browser: Any, tmp_path: Path, size: tuple[int, int]) -> None:
    page = _page(ROOT / "examples" / "pocket.ngc", tmp_path / "p.html")
    tab = browser.new_page(viewport={"width": size[0], "height": size[1]})
    errors: list[str] = []
    tab.on("pageerror", lambda e: errors.append(str(e)))
    tab.goto(page.as_uri())
    tab.evaluate("window.ngcView.ready.then(() => true)")
    box = tab.locator("#canvas canvas").bounding_box()
    assert box is not None and box["width"] > 200 and box["height"] > 200
    assert tab.locator("#text .row").count() > 5 and errors == []
    tab.close()


@pytest.mark.parametrize("name", ["oval.ngc", "trim.ngc"])
def test_an_engine_program_plays_on_the_engines_times(browser: Any, tmp_path: Path,
                                                      name: str) -> None:
    import json

    program = ROOT / "docs" / "engine" / name
    page = _page(program, tmp_path / "p.html")
    checked = json.loads(_ngc("check", "--format", "json", str(program)).stdout)
    o = _open(browser, page.as_uri())
    total = o.js("window.ngcView.viewer.meta.time.total")
    assert total == pytest.approx(checked["summary"]["time"], rel=1e-9)
    # half way, the tool is on the drawn path (within the chords' error)
    at = o.js("(t) => window.ngcView.setTime(t).position", total / 2)
    points = o.js("""() => { const v = window.ngcView.viewer, o = v.meta.origin, out = [];
        for (let i = 0; i < v.points.length; i += 3)
          out.push([v.points[i] + o[0], v.points[i+1] + o[1], v.points[i+2] + o[2]]);
        return out; }""")
    assert min(math.dist(at, p) for p in points) < 0.05
    assert o.errors == []
