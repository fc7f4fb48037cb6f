"""Every public callable of the package says what it takes and what it gives (numpydoc).

Public: a module-level function or class of a module whose name does not start with "_", or a
method or property of such a class, whose own name does not start with "_". Each has a
docstring (a method may inherit its base class's); one that takes arguments (besides self and
cls) has a Parameters section; one that returns or yields a value has a Returns (or Yields)
section. A class made with arguments (its __init__'s, or a dataclass's fields) has Parameters in
its docstring or its __init__'s. HTTP handlers (`request` → a response) are functions like any.
"""

from __future__ import annotations

import ast
import dataclasses
import importlib
import inspect
import pkgutil
import textwrap

import eigendance

SKIPPED_MODULES = ("__main__",)  # running them runs the command line


def public_modules():
    for info in pkgutil.walk_packages(eigendance.__path__, "eigendance."):
        last = info.name.rsplit(".", 1)[-1]
        if last.startswith("_") or last in SKIPPED_MODULES:
            continue
        yield importlib.import_module(info.name)
    yield eigendance


def returns_a_value(function) -> bool:
    """Whether the function's own body returns a value or yields (nested functions aside)."""
    try:
        source = textwrap.dedent(inspect.getsource(function))
    except (OSError, TypeError):
        return False
    tree = ast.parse(source).body[0]
    stack = list(ast.iter_child_nodes(tree))
    while stack:
        node = stack.pop()
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda | ast.ClassDef):
            continue
        if isinstance(node, ast.Yield | ast.YieldFrom):
            return True
        if isinstance(node, ast.Return) and node.value is not None and not (
                isinstance(node.value, ast.Constant) and node.value.value is None):
            return True
        stack.extend(ast.iter_child_nodes(node))
    return False


def takes_arguments(function) -> bool:
    try:
        parameters = list(inspect.signature(function).parameters)
    except (TypeError, ValueError):
        return False
    return bool([name for name in parameters if name not in ("self", "cls")])


def problems_of_function(function, documented: str) -> list[str]:
    problems = []
    if not documented:
        return ["no docstring"]
    if takes_arguments(function) and "Parameters" not in documented:
        problems.append("no Parameters section")
    if returns_a_value(function) and "Returns" not in documented and "Yields" not in documented:
        problems.append("no Returns section")
    return problems


def problems_of_class(cls) -> list[str]:
    documented = inspect.getdoc(cls) or ""
    if not documented or documented == inspect.getdoc(object):
        return ["no docstring"]
    init = cls.__dict__.get("__init__")
    made_with = bool(dataclasses.is_dataclass(cls) and dataclasses.fields(cls)) or (
        init is not None and takes_arguments(init))
    if made_with and "Parameters" not in documented + (inspect.getdoc(init) or "" if init
                                                       else ""):
        return ["no Parameters section (what it is made with)"]
    return []


def members(cls):
    for name, value in vars(cls).items():
        if name.startswith("_"):
            continue
        if isinstance(value, property):
            yield name, value.fget, True
        elif isinstance(value, staticmethod | classmethod):
            yield name, value.__func__, False
        elif inspect.isfunction(value):
            yield name, value, False


def undocumented() -> dict[str, list[str]]:
    found = {}
    for module in public_modules():
        for name, value in vars(module).items():
            if name.startswith("_") or getattr(value, "__module__", None) != module.__name__:
                continue
            where = f"{module.__name__}.{name}"
            if inspect.isclass(value):
                if problems := problems_of_class(value):
                    found[where] = problems
                for member, function, is_property in members(value):
                    documented = inspect.getdoc(getattr(value, member)) if not is_property \
                        else inspect.getdoc(function)
                    if is_property:
                        problems = [] if documented else ["no docstring"]
                    else:
                        problems = problems_of_function(function, documented or "")
                    if problems:
                        found[f"{where}.{member}"] = problems
            elif inspect.isfunction(value) and value.__name__ == name:  # not an alias
                if problems := problems_of_function(value, inspect.getdoc(value) or ""):
                    found[where] = problems
    return found


def test_every_public_callable_states_its_parameters_and_what_it_returns():
    found = undocumented()
    listed = "\n".join(f"{where}: {', '.join(problems)}" for where, problems in
                       sorted(found.items()))
    assert not found, f"{len(found)} public callables lack numpydoc sections:\n{listed}"
