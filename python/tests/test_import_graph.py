"""No import cycle in the scantrace package, not even one hidden inside a function: every import
statement of every module (at the top or in a function body) is an edge of the package's import
graph, read from the sources with `ast`, and the graph must have no cycle. A cycle makes a
module's behaviour depend on which of the two was imported first."""

import ast
import pathlib

PACKAGE = pathlib.Path(__file__).resolve().parents[1] / "scantrace"
# The compiled modules (python/src/): they import nothing of the package.
EXTENSIONS = {"scantrace._scantrace", "scantrace._scantrace_cv"}


def _module_name(path):
    parts = ("scantrace",) + path.relative_to(PACKAGE).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _modules():
    return {_module_name(p): p for p in PACKAGE.rglob("*.py")}


def _imports(name, path, modules):
    """The package's modules that `name` imports anywhere in its source."""
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if isinstance(node, ast.Import):
            found.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = package
            for _ in range(node.level - 1):
                base = base.rpartition(".")[0]
            target = ".".join(filter(None, [base if node.level else "", node.module or ""]))
            # `from . import x` imports the module x when there is one (a compiled module is
            # none of the graph's), else the name from the module `target`.
            for a in node.names:
                sub = f"{target}.{a.name}"
                found.add(sub if sub in modules or sub in EXTENSIONS else target)
    return {m for m in found if m in modules and m != name}


def _cycle(graph):
    """One cycle of `graph` as a list of modules, or None (a depth-first search)."""
    state, stack = {}, []

    def visit(node):
        state[node] = "open"
        stack.append(node)
        for nxt in sorted(graph[node]):
            if state.get(nxt) == "open":
                return stack[stack.index(nxt):] + [nxt]
            if nxt not in state and (found := visit(nxt)):
                return found
        state[node] = "done"
        stack.pop()
        return None

    for node in sorted(graph):
        if node not in state and (found := visit(node)):
            return found
    return None


def test_the_cycle_finder_finds_a_cycle_and_accepts_a_tree():
    assert _cycle({"a": {"b"}, "b": {"c"}, "c": {"a"}}) == ["a", "b", "c", "a"]
    assert _cycle({"a": {"b", "c"}, "b": {"c"}, "c": set()}) is None


def test_the_graph_sees_imports_inside_functions(tmp_path):
    # A module importing its sibling only inside a function is still an edge.
    pkg = tmp_path / "scantrace"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("")
    (pkg / "a.py").write_text("def f():\n    from .b import g\n    return g\n")
    (pkg / "b.py").write_text("from . import a\n")
    global PACKAGE
    saved, PACKAGE = PACKAGE, pkg
    try:
        modules = _modules()
        graph = {m: _imports(m, p, modules) for m, p in modules.items()}
    finally:
        PACKAGE = saved
    assert graph["scantrace.a"] == {"scantrace.b"}
    assert _cycle(graph) == ["scantrace.a", "scantrace.b", "scantrace.a"]


def test_the_package_has_no_import_cycle():
    modules = _modules()
    assert {"scantrace._api", "scantrace._grade", "scantrace.grade.battery"} <= set(modules)
    graph = {m: _imports(m, p, modules) for m, p in modules.items()}
    assert "scantrace._common" in graph["scantrace._api"]
    assert _cycle(graph) is None, "import cycle: " + " -> ".join(_cycle(graph))
