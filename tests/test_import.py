"""Light import (PEP 562): the packages load their heavy dependencies only when a name that
needs them is used, every public name still resolves, and ``dir()`` lists them (the names
that moved in 0.3.0: tests/test_moved.py)."""

import ast
import importlib
import inspect
import json
import subprocess
import sys
from pathlib import Path

import pytest

import skcable

ROOT = Path(skcable.__file__).resolve().parents[1]
HEAVY = ("pandas", "scipy.optimize", "meshio", "pyvista", "matplotlib", "dask", "skfem")
PACKAGES = (
    "skcable",
    "skcable.cable",
    "skcable.bvp",
    "skcable.mooring",
    "skcable.conductors",
    "skcable.strand",
    "skcable.io",
)


def loaded_after(statement: str) -> dict:
    """Which of HEAVY a fresh interpreter holds in sys.modules after ``statement``."""
    code = f"import json, sys\n{statement}\nprint(json.dumps({{m: m in sys.modules for m in {HEAVY!r}}}))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True)
    return json.loads(out.stdout)


@pytest.mark.parametrize(
    "statement",
    [
        "import skcable",
        "from skcable import cable",
        "from skcable import strand",
        "import skcable.io",
        "from skcable import bvp, mooring, conductors",
        "from skcable import cable, strand, io; cable.__all__, dir(cable), dir(strand), dir(io)",
        "from skcable import bvp, mooring, conductors as c; dir(bvp), dir(mooring), dir(c)",
    ],
)
def test_import_loads_no_heavy_module(statement):
    loaded = loaded_after(statement)
    assert not any(loaded.values()), {name for name, yes in loaded.items() if yes}


def test_the_probe_sees_a_heavy_module():  # the subprocess check can fail
    assert loaded_after("from skcable import mooring; mooring.MooringSystem")["pandas"] is False
    assert loaded_after("import skcable.io; skcable.io.write")["meshio"] is False  # imported in write()
    assert loaded_after("from skcable import conductors; conductors.natural_frequencies")["skfem"] is True
    assert loaded_after("from skcable import strand; strand.StrandModel")["skfem"] is True


def test_closed_forms_and_mooring_lines_run_without_scikit_fem():
    """A seabed line's closed form solves with skcable.fe's Newton: that loads no FE machinery."""
    scene = "cable.elastic_catenary(800.0, 150.0, 1000.0, 5e8, length=850.0, seabed=0.0, friction=0.5)"
    line = "mooring.Line([mooring.Segment(300.0, 1000.0, 5e8)], seabed=0.0).solve(280.0, 150.0)"
    loaded = loaded_after(f"from skcable import cable, mooring; {scene}; {line}")
    assert not loaded["skfem"] and not loaded["pandas"]


@pytest.mark.parametrize("package", PACKAGES)
def test_every_public_name_resolves_and_is_listed(package):
    module = importlib.import_module(package)
    assert module.__all__ and len(set(module.__all__)) == len(module.__all__)
    for name in module.__all__:
        value = getattr(module, name)
        assert value is not None, name
        if inspect.isclass(value) or inspect.isfunction(value):  # defined inside the package
            assert value.__module__.startswith(package), (name, value.__module__)
    assert set(module.__all__) <= set(dir(module))


@pytest.mark.parametrize("package", PACKAGES)
def test_type_checking_imports_match_the_public_names(package):
    """The ``if TYPE_CHECKING:`` imports (what mypy and IDEs see) are the public names the
    lazy table serves at run time."""
    module = importlib.import_module(package)
    tree = ast.parse(Path(module.__file__).read_text())
    block = next(
        n for n in tree.body if isinstance(n, ast.If) and getattr(n.test, "id", "") == "TYPE_CHECKING"
    )
    static = {alias.name for node in block.body for alias in node.names}
    eager = {"ConvergenceError", "InputError"} if package == "skcable" else set()
    extra = {"io", "plot", "study"} if package == "skcable" else set()  # submodules, not in __all__
    assert static | eager == set(module.__all__) | extra
    assert static <= set(dir(module))


def test_same_object_as_the_defining_module():
    from skcable import cable
    from skcable.cable._catenary import catenary

    assert cable.catenary is catenary and skcable.cable is cable


def test_unknown_name_is_an_attribute_error():
    from skcable import cable

    with pytest.raises(AttributeError, match="no attribute 'catenery'"):
        cable.catenery  # noqa: B018
    assert not hasattr(skcable, "nothing_here")


def test_version_is_the_package_metadata():
    from importlib.metadata import version

    assert skcable.__version__ == version("skcable")
