"""The linerate adapter against linerate called directly, the heat balance at its answers, and
sag and ampacity at a clearance."""

import numpy as np
import pytest

from skcable import conductors, strand
from skcable.conductors import ThermalRating, clearance_ampacity, sag_at_current
from skcable.errors import InputError

linerate = pytest.importorskip("linerate")

TIME = np.datetime64("2016-10-03T14:00")


def _span(heat_capacity=False):
    """ACSR Drake (795 kcmil 26/7): the conductor of the IEEE 738 examples, as linerate takes it."""
    data = dict(
        core_diameter=10.4e-3, conductor_diameter=28.1e-3, outer_layer_strand_diameter=4.44e-3,
        emissivity=0.8, solar_absorptivity=0.8, temperature1=25.0, temperature2=75.0,
        resistance_at_temperature1=7.283e-5, resistance_at_temperature2=8.688e-5,
        aluminium_cross_section_area=float("nan"), constant_magnetic_effect=1.0,
        current_density_proportional_magnetic_effect=0.0, max_magnetic_core_relative_resistance_increase=1.0,
    )  # fmt: skip
    if heat_capacity:
        conductor = linerate.ConductorWithHeatCapacity(
            **data, steel_mass_per_unit_length=0.5119, steel_specific_heat_capacity_at_20_celsius=481.0,
            steel_specific_heat_capacity_temperature_coefficient=1.00e-4,
            aluminium_mass_per_unit_length=1.116,
            aluminium_specific_heat_capacity_at_20_celsius=897.0,
            aluminium_specific_heat_capacity_temperature_coefficient=3.8e-4,
        )  # fmt: skip
    else:
        conductor = linerate.Conductor(**data)
    a = linerate.Tower(latitude=50 - 0.0045, longitude=0, altitude=500 - 88)
    b = linerate.Tower(latitude=50 + 0.0045, longitude=0, altitude=500 + 88)
    return linerate.Span(conductor=conductor, start_tower=a, end_tower=b, num_conductors=1)


WEATHER = linerate.Weather(
    air_temperature=20.0,
    wind_direction=np.radians(80),
    wind_speed=1.66,
    ground_albedo=0.1,
    clearness_ratio=0.5,
)


@pytest.mark.parametrize("standard, cls", [("ieee738", "IEEE738"), ("cigre601", "Cigre601")])
def test_steady_state_against_linerate(standard, cls):
    rating = ThermalRating(_span(), WEATHER, TIME, standard=standard)
    direct = getattr(linerate, cls)(_span(), WEATHER, TIME)
    currents = np.array([0.0, 400.0, 800.0, 1200.0])
    T = rating.temperature(currents)
    np.testing.assert_array_equal(T, direct.compute_conductor_temperature(currents, 20.0, 300, 1e-4))
    # the heat balance vanishes there, to its slope times the tolerance
    balance = direct.compute_heat_balance(T, currents)
    slope = np.abs(
        direct.compute_heat_balance(T + 0.5, currents) - direct.compute_heat_balance(T - 0.5, currents)
    )
    assert np.all(np.abs(balance) <= slope * 1e-4)
    assert np.all(np.diff(T) > 0) and T[0] > WEATHER.air_temperature  # the sun heats it
    I = rating.ampacity(np.array([75.0, 100.0]))
    np.testing.assert_array_equal(
        I, direct.compute_steady_state_ampacity(np.array([75.0, 100.0]), 0, 10000, 1e-4)
    )
    np.testing.assert_allclose(rating.temperature(I), [75.0, 100.0], atol=1e-3)


def test_transient_against_linerate():
    rating = ThermalRating(_span(heat_capacity=True), WEATHER, TIME, standard="cigre601")
    direct = linerate.Cigre601(_span(heat_capacity=True), WEATHER, TIME)
    ten = np.timedelta64(10, "m")
    T = rating.temperature_after(1200.0, ten, initial_temperature=40.0)
    assert T == direct.compute_temperature_after_heating(40.0, ten, 1200.0, np.timedelta64(1, "s"))
    # it heats towards the steady state and reaches it after hours
    steady = rating.temperature(1200.0)
    assert 40.0 < T < steady
    late = rating.temperature_after(
        1200.0, np.timedelta64(6, "h"), initial_temperature=40.0, time_step=np.timedelta64(20, "s")
    )
    assert late == pytest.approx(steady, abs=0.05)
    with pytest.raises(InputError) as info:
        ThermalRating(_span(), WEATHER, TIME).temperature_after(1200.0, ten, initial_temperature=40.0)
    assert info.value.argument == "span"


def test_sag_at_current_and_the_ampacity_of_a_clearance():
    drake = conductors.Conductor.from_strand(strand.preset("acsr-drake"))
    rating = ThermalRating(_span(), WEATHER, TIME, standard="ieee738")
    kw = dict(t0=15.0, H0=28e3)
    hot = sag_at_current(drake, 400.0, rating=rating, current=[600.0, 1000.0], **kw)
    T = linerate.IEEE738(_span(), WEATHER, TIME).compute_conductor_temperature(
        np.array([600.0, 1000.0]), 20.0, 300, 1e-4
    )
    np.testing.assert_array_equal(hot.temperature, T)
    np.testing.assert_allclose(hot.sag, drake.change_of_state(400.0, t=T, **kw).sag, rtol=1e-14)
    max_sag = float(hot.sag[1])  # the clearance kept at 1000 A
    I, T_max = clearance_ampacity(drake, 400.0, rating=rating, max_sag=max_sag, **kw)
    assert drake.change_of_state(400.0, t=T_max, **kw).sag == pytest.approx(max_sag, rel=1e-12)
    assert T_max == pytest.approx(T[1], abs=2e-4)
    assert I == pytest.approx(1000.0, abs=0.05)  # the current that heated it there


def test_an_ampacity_without_weather_is_refused():
    drake = conductors.Conductor.from_strand(strand.preset("acsr-drake"))
    with pytest.raises(InputError) as info:
        ThermalRating(_span(), None, TIME)
    assert info.value.argument == "weather"
    with pytest.raises(InputError) as info:
        clearance_ampacity(drake, 400.0, rating=None, max_sag=12.0, t0=15.0, H0=28e3)
    assert info.value.argument == "rating" and "weather" in str(info.value)
    rating = ThermalRating(_span(), WEATHER, TIME)
    for bad, name in ((dict(max_sag=0.5), "max_sag"), (dict(max_sag=-1.0), "max_sag")):
        with pytest.raises(InputError) as info:
            clearance_ampacity(drake, 400.0, rating=rating, t0=15.0, H0=28e3, **bad)
        assert info.value.argument == name
    with pytest.raises(InputError) as info:
        ThermalRating(_span(), WEATHER, TIME, standard="cigre207")
    assert info.value.argument == "standard"
    with pytest.raises(InputError) as info:
        rating.temperature(-5.0)
    assert info.value.argument == "current"
