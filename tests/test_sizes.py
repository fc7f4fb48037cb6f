"""Sizes a reader can hold: modules under about 400 lines and functions under about 60, so that
each is read whole (docs/design.md#flow). Docstrings aside: every public callable carries a
numpydoc docstring (tests/test_docstrings.py), and documenting must not push code apart."""

import ast
import os

ROOT = os.path.join(os.path.dirname(__file__), "..", "src", "eigendance")
MODULE_LINES, FUNCTION_LINES = 420, 60


def sources():
    for folder, _, files in os.walk(ROOT):
        for name in sorted(files):
            if name.endswith(".py"):
                path = os.path.join(folder, name)
                relative = os.path.relpath(path, ROOT).replace(os.sep, "/")
                with open(path, encoding="utf-8") as file:
                    yield relative, file.read()


def docstring_lines(node: ast.AST) -> int:
    """Lines of the docstring of a module, class or function (0 without one)."""
    body = getattr(node, "body", [])
    if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant) \
            and isinstance(body[0].value.value, str):
        return body[0].end_lineno - body[0].lineno + 1
    return 0


def code_lines(function: ast.AST) -> int:
    """Lines of a function without its docstring."""
    return function.end_lineno - function.lineno + 1 - docstring_lines(function)


def module_code_lines(text: str) -> int:
    """Lines of a module without the docstrings of the module and of its classes and
    functions."""
    tree = ast.parse(text)
    documented = [node for node in ast.walk(tree) if isinstance(
        node, ast.Module | ast.ClassDef | ast.FunctionDef | ast.AsyncFunctionDef)]
    return text.count("\n") - sum(docstring_lines(node) for node in documented)


def test_modules_are_under_about_400_lines():
    long = {path: module_code_lines(text) for path, text in sources()
            if module_code_lines(text) > MODULE_LINES}
    assert not long, f"modules over {MODULE_LINES} lines (docstrings aside): {long}"


def test_functions_are_under_about_60_lines():
    long = {}
    for path, text in sources():
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef) and \
                    code_lines(node) > FUNCTION_LINES:
                long[f"{path}:{node.name}"] = code_lines(node)
    assert not long, f"functions over {FUNCTION_LINES} lines (docstrings aside): {long}"

