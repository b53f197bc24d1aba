"""The moves of 0.3.0 (one package per domain): every module path and every public name of 0.2.0
still resolves for one release, to the very object of its new home, with a DeprecationWarning
naming that home; the new paths do not warn.

``SKCABLE_CABLE_0_2_0`` is the ``__all__`` of ``skcable.cable`` at the 0.2.0 release (commit
aa34991), typed from that file: the names the table must keep serving.
"""

import importlib
import subprocess
import sys
import warnings

import pytest

import skcable
from skcable import _moved

SKCABLE_CABLE_0_2_0 = """
ClampStress ComponentCurve CreepLaw ResidualStrength StressStrainModel ThermalRating WohlerCurve
clamp_stress clearance_ampacity fatigue_life level_span_states miner_damage poffenberger_swart
residual_strength sag_at_current Buoyancy CableForce CableState CableTerm CurrentDrag WindDrag
ArcSolution BVPSegment LineBVP LineBVPSolution SlopedSeabedCatenary sloped_seabed_catenary
solve_line_bvp BVPSolution DeckLoad DistributedLoad PointLoad SelfWeight solve_bvp CableSolution
ChangeOfState ThermalCatenary change_of_state sag_tension_table thermal_catenary Catenary
ElasticCatenary SeabedCatenary Funicular NaturalFrequencies irvine_frequencies natural_frequencies
FunicularVertical Parabola SlidingLoad anchor_block_weight capstan catenary elastic_catenary
fairlead_stiffness funicular funicular_vertical geometric_stiffness geometric_stiffness_series
membrane_tension parabola ring_on_rod sliding_load solve smooth_surface_reaction sphere_parallel
Conductor TensionSection ruling_span tension_section Buoy ClumpWeight Line LineSolution Segment
Line3D MooringEquilibrium MooringSystem PointBody RigidBody line_3d rotation_matrix LineBetween
MooringLine MooringPoint line_between line_in_plane PlaneLine Component component components
register_component design_line design_pattern read_moordyn write_moordyn MoorDynModel LineInSea
ModelChoice LawLineSolution
""".split()

#: the 0.2.0 names of the old subpackages that did not follow their package's move
SUBPACKAGE_NAMES = {
    "skcable.cable.bvp": ("solve_line_bvp", "LineBVP", "LineBVP3D", "solve_line_bvp_3d", "solve_bvp"),
    "skcable.cable.lines": ("elastic_catenary", "SeabedCatenary", "MooringSystem", "Line"),
    "skcable.cable.conductors": ("poffenberger_swart", "ThermalRating"),
}


def _quietly(get):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        return get()


@pytest.mark.parametrize("name", SKCABLE_CABLE_0_2_0)
def test_every_0_2_0_name_of_cable_resolves(name):
    from skcable import cable

    if name in cable.__all__:  # still at home: no warning
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            assert getattr(cable, name) is not None
        return
    new = _moved.names_moved_from("skcable.cable")[name]
    with pytest.warns(DeprecationWarning, match=rf"skcable\.cable\.{name} is deprecated: use {new}\b"):
        old = getattr(cable, name)
    path, _, attribute = new.rpartition(".")
    assert old is getattr(importlib.import_module(path), attribute)
    assert name not in dir(cable)  # dir() lists the package's own names only


@pytest.mark.parametrize("old", sorted(_moved.MODULES))
def test_every_old_module_path_imports_with_a_warning(old):
    new = _moved.MODULES[old]
    code = (
        "import warnings, importlib\n"
        "with warnings.catch_warnings(record=True) as caught:\n"
        "    warnings.simplefilter('always')\n"
        f"    old = importlib.import_module({old!r})\n"
        f"new = importlib.import_module({new!r})\n"
        "assert old is not new and old.__name__ == " + repr(old) + "\n"
        "assert all(getattr(old, n) is getattr(new, n) for n in dir(new) if not n.startswith('__'))\n"
        "print([str(w.message) for w in caught if w.category is DeprecationWarning])\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert f"{old} is deprecated: use {new} " in out.stdout


@pytest.mark.parametrize("package", sorted(SUBPACKAGE_NAMES))
def test_names_below_an_old_subpackage_resolve(package):
    module = _quietly(lambda: importlib.import_module(package))
    for name in SUBPACKAGE_NAMES[package]:
        value = _quietly(lambda name=name: getattr(module, name))
        home = _moved.names_moved_from(package).get(name)
        if home is None:  # followed its package
            home = f"{_moved.MODULES[package]}.{name}"
        path, _, attribute = home.rpartition(".")
        assert value is getattr(importlib.import_module(path), attribute), (package, name)


def test_an_old_module_below_a_moved_package_is_the_new_modules_stand_in():
    segments = _quietly(lambda: importlib.import_module("skcable.cable.lines.segments.line"))
    from skcable.mooring.segments.line import Line

    assert segments.Line is Line and segments.__name__ == "skcable.cable.lines.segments.line"


def test_a_stand_in_does_not_write_into_the_new_package():
    """Importing ``skcable.cable.bvp.solve`` (a module in 0.2.0) leaves ``skcable.bvp.solve``
    the model-choice function."""
    _quietly(lambda: importlib.import_module("skcable.cable.bvp.solve"))
    from skcable import bvp

    assert callable(bvp.solve) and bvp.solve.__module__ == "skcable.bvp.choice"


def test_the_new_paths_do_not_warn():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        from skcable.bvp.forms import graph_residual  # noqa: F401
        from skcable.conductors import change_of_state  # noqa: F401
        from skcable.mooring import MooringSystem, read_moordyn  # noqa: F401


def test_every_moved_name_lives_where_the_table_says():
    for package, homes in _moved.NAMES.items():
        for home, names in homes.items():
            module = importlib.import_module(home)
            for name in names:
                assert name in module.__all__, (package, home, name)


def test_an_unknown_old_name_is_an_attribute_error():
    with pytest.raises(AttributeError, match="no attribute 'catenery'"):
        skcable.cable.catenery  # noqa: B018
