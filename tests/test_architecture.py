"""The shape of the package, checked: no import cycles among the interpreter's modules (type-only
imports included), handlers that see the machine and not the interpreter, parsed objects without
interpreter caches, and a code table that is a value with a handler for each row it runs."""

from __future__ import annotations

import ast
from pathlib import Path

from ngc.interp.dispatch import HANDLERS, Dispatcher
from ngc.language.codes import LINUXCNC, WORD_STEPS
from ngc.language.parser import Block

SRC = Path(__file__).resolve().parent.parent / "src" / "ngc"


def _module(path: Path) -> str:
    parts = list(path.relative_to(SRC.parent).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


MODULES = frozenset(_module(p) for p in SRC.rglob("*.py"))


def _imports(path: Path) -> set[str]:
    """Every module ``path`` imports, at run time or for type checking only."""
    package = _module(path).split(".")
    if path.name != "__init__.py":
        package = package[:-1]
    found: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = package[: len(package) - node.level + 1] if node.level else []
            name = ".".join([*base, node.module] if node.module else base)
            names = {f"{name}.{alias.name}" for alias in node.names}
            found.update(names)
            if not names <= MODULES:  # (``from . import module`` runs the package first, but
                found.add(name)       # only modules: the package's own code is not needed)
    return found


def _graph(prefix: str) -> dict[str, set[str]]:
    modules = {_module(p): p for p in SRC.rglob("*.py")}
    inside = {name for name in modules if name.startswith(prefix)}
    return {name: {m for m in _imports(modules[name]) if m in inside and m != name} for name in inside}


def _cycle(graph: dict[str, set[str]]) -> list[str] | None:
    state: dict[str, int] = {}
    path: list[str] = []

    def visit(node: str) -> list[str] | None:
        state[node] = 1
        path.append(node)
        for nxt in sorted(graph[node]):
            if state.get(nxt) == 1:
                return [*path[path.index(nxt):], nxt]
            if nxt not in state and (found := visit(nxt)):
                return found
        path.pop()
        state[node] = 2
        return None

    for node in sorted(graph):
        if node not in state and (found := visit(node)):
            return found
    return None


def test_no_import_cycles_in_interp() -> None:
    graph = _graph("ngc.interp")
    assert len(graph) > 10
    assert _cycle(graph) is None


def test_no_import_cycles_in_the_package() -> None:
    assert _cycle(_graph("ngc")) is None


def test_no_import_cycles_in_language() -> None:
    assert _cycle(_graph("ngc.language")) is None


def test_the_cycle_finder_finds_cycles() -> None:
    assert _cycle({"a": {"b"}, "b": {"c"}, "c": {"a"}}) == ["a", "b", "c", "a"]
    assert _cycle({"a": {"b"}, "b": set()}) is None


def test_handlers_see_the_machine_not_the_interpreter() -> None:
    for path in (SRC / "interp" / "handlers").glob("*.py"):
        assert "ngc.interp.interpreter" not in _imports(path), path.name
        assert "ngc.interp.flow" not in _imports(path), path.name


def test_language_does_not_import_the_interpreter() -> None:
    for path in (SRC / "language").glob("*.py"):
        assert not any(m.startswith("ngc.interp") for m in _imports(path)), path.name


def test_parsed_blocks_carry_no_interpreter_caches() -> None:
    assert set(Block.__slots__) == {
        "delete", "items", "label", "line", "n_number", "oword", "resolved", "source"
    }


def test_every_row_that_runs_names_a_handler() -> None:
    for table in (LINUXCNC.g, LINUXCNC.m):
        for code, row in table.items():
            assert row.handler is None or row.handler == "" or row.handler in HANDLERS, code
    for _step, name in WORD_STEPS.values():
        assert name is None or name in HANDLERS
    Dispatcher(LINUXCNC)  # binds every name


def test_steps_follow_the_modal_groups() -> None:
    """Codes of one modal group run at one step (group 0 aside: each of its codes has its own)."""
    for table in (LINUXCNC.g, LINUXCNC.m):
        steps: dict[int, set[int]] = {}
        for row in table.values():
            steps.setdefault(row.group, set()).add(row.step)
        for group, found in steps.items():
            assert group == 0 or len(found) == 1, (group, found)
