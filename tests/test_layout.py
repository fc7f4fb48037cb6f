"""The package's import graph: no cycles, and no imports hidden inside functions.

`eigendance.cli` is the top of the graph (nothing else imports it): its `__init__` imports its
own `main`, so that the `eigendance = eigendance.cli:main` entry point finds it.

Only heavy optional libraries are imported where they are used, each with a comment saying so.
"""

import ast
import os

ROOT = os.path.join(os.path.dirname(__file__), "..", "src")
LAZY = {"trimesh", "igl", "robust_laplacian", "av", "matplotlib.figure", "DracoPy", "PIL", "bpy",
        "ray", "librosa", "aalink"}
TOP = "eigendance.cli"  # the command line: imports everything, imported by nothing


def modules() -> dict[str, ast.Module]:
    found = {}
    for folder, _, files in os.walk(os.path.join(ROOT, "eigendance")):
        for name in files:
            if name.endswith(".py"):
                path = os.path.join(folder, name)
                dotted = os.path.relpath(path, ROOT)[:-3].replace(os.sep, ".")
                dotted = dotted.removesuffix(".__init__")
                with open(path, encoding="utf-8") as file:
                    found[dotted] = (ast.parse(file.read()), path)
    return found


def imported(node) -> list[str]:
    if isinstance(node, ast.Import):
        return [alias.name for alias in node.names]
    if isinstance(node, ast.ImportFrom) and node.module:
        return [node.module]
    return []


def test_module_level_imports_form_no_cycle():
    graph = {}
    for name, (tree, _) in modules().items():
        graph[name] = {target for node in tree.body for target in imported(node)
                       if target.startswith("eigendance.")}
        package = name.rsplit(".", 1)[0]
        if package.count(".") and package in modules() and package != TOP:
            graph[name].add(package)  # importing a module runs its subpackage first
    state = {}

    def visit(node, path):
        if state.get(node) == "done":
            return
        assert state.get(node) != "open", f"import cycle: {' → '.join([*path, node])}"
        state[node] = "open"
        for target in sorted(graph.get(node, ())):
            visit(target, [*path, node])
        state[node] = "done"

    for name in sorted(graph):
        visit(name, [])


def test_subpackages_import_nothing_in_their_init():
    for name, (tree, _) in modules().items():
        if name.count(".") == 1 and os.path.isdir(os.path.join(ROOT, *name.split("."))):
            targets = [target for node in tree.body for target in imported(node)]
            if name == TOP:
                assert all(target.startswith(TOP + ".") for target in targets), targets
            else:
                assert not targets, name


def test_nothing_but_the_entry_points_imports_the_command_line():
    for name, (tree, _) in modules().items():
        if name in ("eigendance.__main__", TOP) or name.startswith(TOP + "."):
            continue
        targets = [target for node in ast.walk(tree) for target in imported(node)]
        assert not [t for t in targets if t == TOP or t.startswith(TOP + ".")], name


def test_only_heavy_optional_libraries_are_imported_inside_functions():
    for name, (tree, path) in modules().items():
        with open(path, encoding="utf-8") as file:
            lines = file.read().splitlines()
        for function in ast.walk(tree):
            if not isinstance(function, ast.FunctionDef | ast.AsyncFunctionDef):
                continue
            for node in ast.walk(function):
                for target in imported(node):
                    assert target in LAZY, f"{name}: import of {target} inside a function"
                    assert "#" in lines[node.lineno - 1], \
                        f"{name}:{node.lineno}: say why {target} is imported on use"
