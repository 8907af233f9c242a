"""The type stubs and docstrings cover the whole compiled module."""

import ast
import os

import boolean_isosurfacing as bi

STUB = os.path.join(os.path.dirname(__file__), "..", "boolean_isosurfacing", "_core.pyi")


def test_stub_names_match_the_module():
    tree = ast.parse(open(STUB).read())
    names = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    names |= {n.target.id for n in tree.body if isinstance(n, ast.AnnAssign)}
    public = {n for n in dir(bi._core) if not n.startswith("_")}
    assert public - names == set(), "in the module, not in the stub"
    assert names - public == set(), "in the stub, not in the module"


def test_every_function_has_a_docstring_beyond_its_signature():
    for name in dir(bi._core):
        f = getattr(bi._core, name)
        if callable(f) and not isinstance(f, type) and not name.startswith("_"):
            lines = [l for l in (f.__doc__ or "").splitlines() if l.strip()]
            assert len(lines) >= 2, name  # pybind11's signature line, then ours


def test_exceptions_are_value_errors():
    for name in ("EmptyInputError", "NonTriangleFaceError", "OpenMeshError", "NonFiniteValueError",
                 "InwardOrientedMeshError", "SelfIntersectingMeshError", "LatticeTooLargeError", "ParseError"):
        assert issubclass(getattr(bi, name), bi.InvalidInputError)
    assert issubclass(bi.InvalidInputError, ValueError)
