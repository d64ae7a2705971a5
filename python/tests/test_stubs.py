"""The type stubs name every public function with its parameters as the package defines them."""
import ast
import inspect
from pathlib import Path

import impact3d


def test_stubs_match_the_package():
    stub = ast.parse((Path(impact3d.__file__).parent / "__init__.pyi").read_text())
    declared = {f.name: [a.arg for a in f.args.args + f.args.kwonlyargs] + ([f.args.kwarg.arg] if f.args.kwarg else [])
                for f in stub.body if isinstance(f, ast.FunctionDef)}
    checked = 0
    for name in impact3d.__all__:
        obj = getattr(impact3d, name)
        if inspect.isfunction(obj):
            assert list(inspect.signature(obj).parameters) == declared[name], name
            assert obj.__doc__ and len(obj.__doc__) > 100, name
            checked += 1
    assert checked == 6
