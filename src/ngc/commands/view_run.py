"""``ngc view`` on the command line: the page written (and opened), or served with ``--watch``.

``--watch`` serves the page on 127.0.0.1 with the standard library's ``http.server`` (one user,
one page, on the loopback: nothing a server library would add is needed, and the core keeps no
dependency): ``/`` is the page, built again when the program file changes, ``/version`` a number
the page polls to reload itself.
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
import threading
import time
import webbrowser
from typing import TYPE_CHECKING

from .. import dialects
from ..dialects import ENGINE
from ..errors import NgcConfigError
from ..options import new_interpreter
from .common import (
    EXIT_OK,
    EXIT_PROGRAM_ERROR,
    EXIT_USAGE,
    display_name,
    engine_setup,
    inputs_conflict,
    load_inputs,
    open_marked,
)

if TYPE_CHECKING:
    from ..view.page import Page

POLL_SECONDS = 0.3  # how often --watch looks at the program file


def run(options: argparse.Namespace) -> int:
    """``ngc view FILE``: exit 2 for a bad command line, machine input or a file that cannot be
    read or written; 1 when the program stopped on an error (the page shows what ran and the
    error); 0 otherwise."""
    try:
        page = _page(options)
    except _Refused as exc:
        sys.stderr.write(f"ngc view: {exc}\n")
        return EXIT_USAGE
    if options.watch:
        return _serve(options, page)
    output = options.output
    if output is None:
        folder = tempfile.mkdtemp(prefix="ngc-view-")
        output = os.path.join(folder, os.path.splitext(os.path.basename(
            options.file if options.file != "-" else "stdin"))[0] + ".html")
    try:
        with open(output, "wb") as handle:
            handle.write(page.html)
    except OSError as exc:
        sys.stderr.write(f"ngc view: cannot write {display_name(output)}: {exc.strerror}\n")
        return EXIT_USAGE
    _report(options, page, output)
    if not options.no_open and options.output is None:
        webbrowser.open("file://" + os.path.abspath(output))
    return EXIT_PROGRAM_ERROR if page.error is not None or page.warnings else EXIT_OK


class _Refused(Exception):
    """What makes the command refuse to go on (exit 2), said in its message."""


def _page(options: argparse.Namespace) -> Page:
    """The page of the program, or :class:`_Refused`."""
    from ..view.page import build_page

    program = open_marked(options.file, options.dialect)
    try:
        conflict = inputs_conflict(options, program.dialect)
        if conflict is not None:
            raise _Refused(conflict)
        if program.handle is None:
            reason = program.error.strerror if program.error is not None else None
            raise _Refused(f"cannot open {program.name}: {reason}")
        try:
            if program.dialect == ENGINE:
                setup = engine_setup(options)
                text = dialects.read_text(program.handle)
                return build_page(text, program.name, new_interpreter=None,
                                  engine=setup, engine_dialect=True,
                                  max_iterations=options.max_iterations)
            inputs, loaded = load_inputs("view", options, options.file)
            from ..planner.config import load_machine

            machine = None
            try:
                machine = load_machine(loaded.ini, options.machine_file)
            except NgcConfigError as exc:
                if options.machine_file is not None:
                    raise
                sys.stderr.write(f"ngc view: warning: not timed: {exc.message}\n")
            text = dialects.read_text(program.handle)
            from .plot import auto_view

            view = "lathe" if auto_view(text.encode("utf-8", "surrogateescape")) == "lathe" \
                else "iso"
            return build_page(text, program.name,
                              lambda sink: new_interpreter(sink, inputs, loaded,
                                                           write_files=False),
                              machine=machine, view=view)
        except NgcConfigError as exc:
            raise _Refused(exc.message) from None
    finally:
        program.close()


def _report(options: argparse.Namespace, page: Page, where: str) -> None:
    if page.error is not None:
        sys.stderr.write(page.error.render() + "\n")
    for warning in page.warnings:
        sys.stderr.write(f"ngc view: {display_name(options.file)}: {warning}\n")
    timed = "" if page.total_s is None else f", {page.total_s:.3f} s on the machine"
    sys.stderr.write(f"ngc view: {display_name(where)}: {page.segments} segments{timed}\n")


def _serve(options: argparse.Namespace, first: Page) -> int:
    """Serve the page until Ctrl-C, building it again when the program file changes."""
    import http.server

    state = {"page": first, "version": 1}
    lock = threading.Lock()
    path = options.file

    class Handler(http.server.BaseHTTPRequestHandler):
        def do_GET(self) -> None:
            with lock:
                page, version = state["page"], state["version"]
            if self.path.split("?")[0] in ("/", "/index.html"):
                body, kind = page.html, "text/html; charset=utf-8"  # type: ignore[attr-defined]
            elif self.path.split("?")[0] == "/version":
                body, kind = str(version).encode(), "text/plain"
            else:
                self.send_error(404)
                return
            self.send_response(200)
            self.send_header("Content-Type", kind)
            self.send_header("Content-Length", str(len(body)))
            self.send_header("Cache-Control", "no-store")
            self.end_headers()
            self.wfile.write(body)

        def log_message(self, format: str, *args: object) -> None:
            """Quiet: the command says what matters."""

    try:
        server = http.server.ThreadingHTTPServer(("127.0.0.1", options.port), Handler)
    except OSError as exc:
        sys.stderr.write(f"ngc view: cannot serve on 127.0.0.1:{options.port}: {exc.strerror}\n")
        return EXIT_USAGE
    address = f"http://127.0.0.1:{server.server_address[1]}/"
    _report(options, first, address)
    print(f"ngc view: serving {address} (Ctrl-C stops)", flush=True)
    if not options.no_open:
        webbrowser.open(address)

    def watch() -> None:
        seen = _stamp(path)
        while True:
            time.sleep(POLL_SECONDS)
            now = _stamp(path)
            if now == seen:
                continue
            seen = now
            try:
                page = _page(options)
            except _Refused as exc:
                sys.stderr.write(f"ngc view: {exc}\n")
                continue
            with lock:
                state["page"] = page
                state["version"] = int(state["version"]) + 1  # type: ignore[call-overload]
            _report(options, page, address)

    threading.Thread(target=watch, daemon=True).start()
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        pass
    finally:
        server.server_close()
    return EXIT_OK


def _stamp(path: str) -> tuple[int, int] | None:
    try:
        st = os.stat(path)
    except OSError:
        return None
    return (st.st_mtime_ns, st.st_size)
