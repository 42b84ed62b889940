"""The type stubs (exactccd/__init__.pyi) describe the module as built: the same public
functions, and for each the same parameter names, order and defaults as the extension's own
signature (pybind11 writes it as the first line of every docstring). (mypy's stubtest checks
only that the names exist: pybind11 functions expose no signature to it.)"""

import ast
import os

import exactccd


def _stub_functions():
    path = os.path.join(os.path.dirname(exactccd.__file__), "__init__.pyi")
    with open(path, encoding="utf-8") as f:
        tree = ast.parse(f.read(), path)
    out = {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef) and not node.name.startswith("_"):
            args = node.args.posonlyargs + node.args.args
            defaults = [None] * (len(args) - len(node.args.defaults)) + [
                ast.literal_eval(d) for d in node.args.defaults
            ]
            has_default = [False] * (len(args) - len(node.args.defaults)) + [True] * len(node.args.defaults)
            out[node.name] = [(a.arg, h, d) for a, h, d in zip(args, has_default, defaults)]
    return out


def _split_top_level(text):
    """Splits 'a: x[y, z] = 1, b: w' at the commas outside brackets."""
    parts, depth, start = [], 0, 0
    for i, ch in enumerate(text):
        if ch in "[(":
            depth += 1
        elif ch in "])":
            depth -= 1
        elif ch == "," and depth == 0:
            parts.append(text[start:i].strip())
            start = i + 1
    if text[start:].strip():
        parts.append(text[start:].strip())
    return parts


def _runtime_signature(name, function):
    first = function.__doc__.splitlines()[0]
    assert first.startswith(name + "("), first
    inner = first[len(name) + 1 : first.rindex(") ->")]
    params = []
    for p in _split_top_level(inner):
        head, _, default = p.partition("=")
        params.append((head.split(":")[0].strip(), bool(default), ast.literal_eval(default.strip()) if default else None))
    return params


def _runtime_functions():
    return {
        n: getattr(exactccd, n)
        for n in dir(exactccd)
        if not n.startswith("_") and callable(getattr(exactccd, n)) and not isinstance(getattr(exactccd, n), type)
    }


def test_stub_declares_exactly_the_public_functions():
    assert sorted(_stub_functions()) == sorted(_runtime_functions())


def test_stub_parameters_and_defaults_match_the_extension():
    stubs = _stub_functions()
    for name, function in _runtime_functions().items():
        assert stubs[name] == _runtime_signature(name, function), name

