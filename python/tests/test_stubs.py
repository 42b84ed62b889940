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



def _stub_classes():
    """{class name: {method or property name: parameters (None for a property)}} of the stubs."""
    path = os.path.join(os.path.dirname(exactccd.__file__), "__init__.pyi")
    with open(path, encoding="utf-8") as f:
        tree = ast.parse(f.read(), path)
    out = {}
    for node in tree.body:
        if not isinstance(node, ast.ClassDef) or node.name.startswith("_"):
            continue
        members = {}
        for item in node.body:
            if not isinstance(item, ast.FunctionDef) or (item.name.startswith("_") and item.name != "__init__"):
                continue
            if any(isinstance(d, ast.Name) and d.id == "property" for d in item.decorator_list):
                members[item.name] = None
                continue
            args = item.args.posonlyargs + item.args.args
            defaults = [None] * (len(args) - len(item.args.defaults)) + [ast.literal_eval(d) for d in item.args.defaults]
            has_default = [False] * (len(args) - len(item.args.defaults)) + [True] * len(item.args.defaults)
            members[item.name] = [(a.arg, h, d) for a, h, d in zip(args, has_default, defaults)]
        out[node.name] = members
    return out


def _runtime_classes():
    return {n: getattr(exactccd, n) for n in dir(exactccd) if not n.startswith("_") and isinstance(getattr(exactccd, n), type)}


def test_stub_declares_exactly_the_public_classes_and_their_members():
    stubs, runtime = _stub_classes(), _runtime_classes()
    assert sorted(stubs) == sorted(runtime)
    for name, cls in runtime.items():
        public = sorted(m for m in dir(cls) if not m.startswith("_")) + ["__init__"]
        assert sorted(stubs[name]) == sorted(public), name


def test_stub_methods_match_the_extension():
    for name, cls in _runtime_classes().items():
        for member, params in _stub_classes()[name].items():
            attribute = getattr(cls, member)
            if params is None:  # a property in the stub: a property at run time too
                assert isinstance(attribute, property), f"{name}.{member}"
                continue
            assert _runtime_signature(member, attribute) == params, f"{name}.{member}"
