"""The type stubs (python/ringvib.pyi, installed beside the module) against the module itself:
every public name of the module is in the stubs and the other way round, every class's public
attributes likewise, and every function's parameters, in order, are the ones pybind11 reports
in its signature line. A function or attribute added to python/module.cpp without its stub
fails here."""
import ast
import os
import pathlib
import re

import ringvib

STUB = pathlib.Path(os.environ["RINGVIB_SOURCE_DIR"]) / "python" / "ringvib.pyi"
# What Python's exceptions carry whatever the module adds.
INHERITED = set(dir(Exception))


def stub_tree():
    return ast.parse(STUB.read_text())


def public(names):
    return {n for n in names if not n.startswith("_")}


def stub_names(tree):
    out = {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            out[node.name] = node
        elif isinstance(node, ast.AnnAssign):
            out[node.target.id] = node
    return out


def test_the_stubs_name_exactly_the_modules_public_names():
    names = stub_names(stub_tree())
    assert public(names) == public(dir(ringvib))


def test_each_class_has_exactly_the_modules_attributes():
    for name, node in stub_names(stub_tree()).items():
        if not isinstance(node, ast.ClassDef):
            continue
        stubbed = {n.name for n in node.body if isinstance(n, ast.FunctionDef)}
        stubbed |= {n.target.id for n in node.body if isinstance(n, ast.AnnAssign)}
        actual = public(dir(getattr(ringvib, name))) - INHERITED
        assert public(stubbed) == actual, name


def signature_parameters(doc):
    """The parameter names of pybind11's first docstring line 'f(a: T, *, b: U = 1) -> R'."""
    inside = re.match(r"\w+\((.*)\) ->", doc.splitlines()[0]).group(1)
    names = []
    depth, current = 0, ""
    for ch in inside + ",":
        if ch in "([":
            depth += 1
        elif ch in ")]":
            depth -= 1
        if ch == "," and depth == 0:
            part = current.strip()
            if part and part != "*":
                names.append(part.split(":")[0].split("=")[0].strip().lstrip("*"))
            current = ""
        else:
            current += ch
    return names


def test_each_functions_parameters_are_the_modules():
    for name, node in stub_names(stub_tree()).items():
        if not isinstance(node, ast.FunctionDef):
            continue
        args = node.args
        stubbed = [a.arg for a in args.posonlyargs + args.args + args.kwonlyargs]
        assert stubbed == signature_parameters(getattr(ringvib, name).__doc__), name
