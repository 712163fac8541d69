"""The type stubs parse and declare what the compiled module holds: a
stub that Python cannot read (as one once could not) or that misses a
function leaves users' type checkers blind."""

import ast
from pathlib import Path

import placecat._placecat as native

STUB = Path(native.__file__).parent / "_placecat.pyi"


def declared():
    tree = ast.parse(STUB.read_text())
    top, classes = set(), {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            top.add(node.name)
        if isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            top.add(node.target.id)
        if isinstance(node, ast.ClassDef):
            classes[node.name] = {
                n.name if isinstance(n, ast.FunctionDef) else n.target.id
                for n in node.body
                if isinstance(n, ast.FunctionDef)
                or (isinstance(n, ast.AnnAssign) and isinstance(n.target, ast.Name))
            }
    return top, classes


def public(names):
    return {n for n in names if not n.startswith("_")}


def test_the_stub_declares_every_public_function_and_method():
    top, classes = declared()
    assert public(dir(native)) - top == set()
    for name in public(dir(native)):
        obj = getattr(native, name)
        if isinstance(obj, type) and not issubclass(obj, Exception):
            assert name in classes, name
            assert public(dir(obj)) - classes[name] == set(), name
