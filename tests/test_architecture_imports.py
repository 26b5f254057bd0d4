"""Every module imports alone: no import cycle among the package's modules.

A module that imports a second one at module level, which imports the first back (a split-out module
re-exported by the module it came from, with the shared helpers left behind), works in the order the
suite happens to import them and fails when the second is imported first in a fresh interpreter
(``python -m pytest --doctest-modules graphmethods/sheets/work_diagrams.py``). The graph of module-level
imports is read from the source (no module is run), so the check costs a parse of every file; a cycle is
reported with the lines that close it. The remedy is to move the shared piece down into a module both
import, never to import the upper module lazily from the lower.
"""

import ast
import functools
import pathlib
import subprocess
import sys

PKG = pathlib.Path(__file__).resolve().parents[1] / "graphmethods"


def _module_name(path: pathlib.Path) -> str:
    parts = path.relative_to(PKG.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


MODULES = {_module_name(p): p for p in PKG.rglob("*.py")}


def _is_type_checking(test: ast.expr) -> bool:
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING")


def _module_level_imports(body: list[ast.stmt]):
    """The import statements run when the module is imported: its top level, inside ``if``/``try`` blocks
    (not ``if TYPE_CHECKING:``), never inside a function or class body (those run when called)."""
    for node in body:
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            yield node
        elif isinstance(node, ast.If):
            if not _is_type_checking(node.test):
                yield from _module_level_imports(node.body)
            yield from _module_level_imports(node.orelse)
        elif isinstance(node, ast.Try):
            for block in (node.body, *(h.body for h in node.handlers), node.orelse, node.finalbody):
                yield from _module_level_imports(block)


def _imports(name: str, path: pathlib.Path) -> dict[str, int]:
    """The package's modules that ``name`` imports at module level, each with the line of its import;
    ``from package import name`` counts as an import of the submodule when ``name`` is one."""
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    out: dict[str, int] = {}
    for node in _module_level_imports(ast.parse(path.read_text(encoding="utf-8")).body):
        if isinstance(node, ast.Import):
            targets = [a.name for a in node.names if a.name in MODULES]
        else:
            if node.level:
                base = package.split(".")[: len(package.split(".")) - node.level + 1]
                source = ".".join(base + ([node.module] if node.module else []))
            else:
                source = node.module or ""
            targets = [f"{source}.{a.name}" if f"{source}.{a.name}" in MODULES else source for a in node.names]
        for target in targets:
            if target in MODULES and target != name:
                out.setdefault(target, node.lineno)
    return out


@functools.cache
def package_graph() -> dict[str, dict[str, int]]:
    """Each module of the package with the modules it imports at module level (parsed once per session)."""
    return {name: _imports(name, path) for name, path in MODULES.items()}


def import_cycles(graph: dict[str, dict[str, int]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan's algorithm, iterative)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    cycles: list[list[str]] = []
    for root in sorted(graph):
        if root in index:
            continue
        work = [(root, iter(sorted(graph[root])))]
        index[root] = low[root] = len(index)
        stack.append(root)
        on_stack.add(root)
        while work:
            v, children = work[-1]
            w = next(children, None)
            if w is not None:
                if w not in index:
                    index[w] = low[w] = len(index)
                    stack.append(w)
                    on_stack.add(w)
                    work.append((w, iter(sorted(graph[w]))))
                elif w in on_stack:
                    low[v] = min(low[v], index[w])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[v])
            if low[v] == index[v]:
                component = []
                while True:
                    w = stack.pop()
                    on_stack.discard(w)
                    component.append(w)
                    if w == v:
                        break
                if len(component) > 1:
                    cycles.append(sorted(component))
    return cycles


def test_the_cycle_finder_finds_a_cycle_and_only_cycles():
    graph = {"a": {"b": 1}, "b": {"c": 1}, "c": {"a": 1}, "d": {"a": 1}, "e": {}}
    assert import_cycles(graph) == [["a", "b", "c"]]
    assert import_cycles({"a": {"b": 1}, "b": {}}) == []


def test_the_import_graph_sees_a_re_export_at_the_bottom_of_a_module():
    """The pattern that broke: ``calculus`` re-exported ``work_diagrams`` at its bottom while
    ``work_diagrams`` imported ``calculus``'s helpers; the reader finds both edges."""
    source = ("from graphmethods.sheets.layout import Box\n"
              "if TYPE_CHECKING:\n    from graphmethods.sheets.energy import energy_graph\n"
              "def f():\n    from graphmethods.sheets import steps\n"
              "from graphmethods.sheets import forces as SF  # noqa: E402\n")
    tree = ast.parse(source)
    names = [n.module if isinstance(n, ast.ImportFrom) else None for n in _module_level_imports(tree.body)]
    assert names == ["graphmethods.sheets.layout", "graphmethods.sheets"]
    assert "graphmethods.sheets.layout" in package_graph()["graphmethods.sheets.energy"]


def test_no_module_level_import_cycle():
    graph = package_graph()
    found = []
    for cycle in import_cycles(graph):
        members = set(cycle)
        edges = [f"    {m}:{line} imports {t}" for m in cycle for t, line in sorted(graph[m].items()) if t in members]
        found.append("\n".join([" <-> ".join(cycle), *edges]))
    assert not found, ("import cycles (the module imported first fails; move the shared piece down):\n"
                       + "\n".join(found))


def test_the_modules_once_in_a_cycle_import_first_in_a_fresh_interpreter():
    """The modules that failed when imported first (and their partners), each imported first with every
    module of the package forgotten before it: one interpreter, so numpy and the rest load once."""
    names = ["graphmethods.sheets." + n for n in (
        "energy_graph", "work_diagrams", "speed_graphs", "zhukovsky_lever", "force_panels", "force_working",
        "construction_steps", "cam_steps")]
    code = (
        "import importlib, sys\n"
        f"for name in {names!r}:\n"
        "    for m in [m for m in sys.modules if m == 'graphmethods' or m.startswith('graphmethods.')]:\n"
        "        del sys.modules[m]\n"
        "    try:\n"
        "        importlib.import_module(name)\n"
        "    except ImportError as e:\n"
        "        print(name, e)\n"
    )
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True,
                          cwd=PKG.parent)
    assert proc.stdout == "", proc.stdout
