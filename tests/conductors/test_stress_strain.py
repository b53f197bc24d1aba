"""Polynomial stress–strain conductors: a level span's initial, final-after-load and
final-after-creep states against an independent brentq solution of the same strain summation,
the knee point, creep, and the refusals."""

import numpy as np
import pytest
from scipy.optimize import brentq

from skcable.conductors import (
    ComponentCurve,
    CreepLaw,
    StressStrainModel,
    aa_coefficients,
    level_span_states,
)
from skcable.errors import InputError

PSI = 6894.757293168361
AREA = 468.6e-6  # m², a Drake-sized ACSR
# Illustrative curves of the form the Aluminum Association prints (psi, strain in %): increasing
# over 0-0.45 %; not published coefficients.
AL_PSI = [-1213.0, 44308.1, -14004.4, -37618.0, 30676.0]
ST_PSI = [-69.3, 38629.0, -3998.1, -45713.0, 27892.0]
E_AL, E_ST = 64000.0 * PSI * 100, 37000.0 * PSI * 100  # final moduli over the whole area (Pa)
ALPHA_AL, ALPHA_ST, T_REF = 23e-6, 11.5e-6, 20.0
CASES = {"cold": (15.97, -20.0), "every day": (15.97, 15.0), "ice": (35.97, 0.0), "hot": (15.97, 100.0),
         "very hot": (15.97, 180.0)}  # fmt: skip
CREEP = (4e-4, 0.0)


def _model():
    al = ComponentCurve("aluminium", aa_coefficients(AL_PSI), 0.0045, E_AL, ALPHA_AL, compression_limit=0.0)
    st = ComponentCurve("steel", aa_coefficients(ST_PSI), 0.0045, E_ST, ALPHA_ST)
    return StressStrainModel((al, st), AREA, t_ref=T_REF)


# --- the same strain summation, written afresh: np.polyval in psi and %, brentq ----------------


def _initial(coeffs_psi, eps):
    x = min(max(eps, 0.0), 0.0045) * 100  # %
    value = np.polyval(coeffs_psi[::-1], x) * PSI
    slope = np.polyval(np.polyder(coeffs_psi[::-1]), x) * PSI * 100
    return value + slope * (eps - x / 100)


def _component(coeffs, E, eps, permanent, peak, slack):
    load = _initial(coeffs, eps) if permanent is None or eps >= peak else E * (eps - permanent)
    return max(load, 0.0) if slack else load


def _stress(eps, t, state):
    e_al, e_st = (
        eps - ALPHA_AL * (t - T_REF) - state["creep"][0],
        eps - ALPHA_ST * (t - T_REF) - state["creep"][1],
    )
    return _component(AL_PSI, E_AL, e_al, state["p"][0], state["k"][0], True) + _component(
        ST_PSI, E_ST, e_st, state["p"][1], state["k"][1], False
    )


def _strain(sigma, t, state):
    return brentq(lambda e: _stress(e, t, state) - sigma, -0.05, 0.05, xtol=1e-17, rtol=1e-15, maxiter=500)


def _catenary(H, w, S):
    c = H / w
    L = 2 * c * np.sinh(S / (2 * c))
    return L, H * (S + c * np.sinh(S / c)) / (2 * L)


def _tension(w, t, L0, S, state):
    def g(H):
        L, T = _catenary(H, w, S)
        return L / L0 - 1 - _strain(T / AREA, t, state)

    return brentq(g, 2e3, 5e5, xtol=1e-12, rtol=1e-15, maxiter=500)


def _independent(span, w0, t0, H0):
    initial = dict(p=(None, None), k=(None, None), creep=(0.0, 0.0))
    L, T = _catenary(H0, w0, span)
    L0 = L / (1 + _strain(T / AREA, t0, initial))
    w, t = CASES["ice"]
    H = _tension(w, t, L0, span, initial)
    eps = _strain(_catenary(H, w, span)[1] / AREA, t, initial)
    peaks = (eps - ALPHA_AL * (t - T_REF), eps - ALPHA_ST * (t - T_REF))
    sets = tuple(
        k - _initial(c, k) / E for k, c, E in zip(peaks, (AL_PSI, ST_PSI), (E_AL, E_ST), strict=True)
    )
    final = dict(p=sets, k=peaks, creep=(0.0, 0.0))
    crept = dict(final, creep=CREEP)
    out = {}
    for name, (w, t) in CASES.items():
        for label, state in (("initial", initial), ("final after load", final), ("final after creep", crept)):
            out[(name, label)] = _tension(w, t, L0, span, state)
    return out


def test_level_span_against_an_independent_strain_summation():
    table = level_span_states(
        _model(), 300.0, w0=15.97, t0=15.0, H0=28e3, cases=CASES, max_load="ice", creep=CREEP
    )
    expected = _independent(300.0, 15.97, 15.0, 28e3)
    assert len(table) == len(expected) == 15
    for key, H in expected.items():
        assert table.loc[key, "H"] == pytest.approx(H, rel=1e-9), key
    # the stringing state is the initial curve at 15 °C: its H is the given one
    assert table.loc[("every day", "initial"), "H"] == pytest.approx(28e3, rel=1e-12)
    # after the ice load the conductor is longer: less tension, more sag, at every other state
    for case in ("cold", "every day", "hot"):
        assert table.loc[(case, "final after load"), "H"] < table.loc[(case, "initial"), "H"]
        assert table.loc[(case, "final after creep"), "sag"] >= table.loc[(case, "final after load"), "sag"]


def test_the_knee_leaves_the_steel_alone():
    model = _model()
    table = level_span_states(
        model, 300.0, w0=15.97, t0=15.0, H0=28e3, cases=CASES, max_load="ice", creep=CREEP
    )
    hot = table.loc[("very hot", "final after load")]
    assert hot["slack"] and not table.loc[("every day", "final after load"), "slack"]
    # beyond the knee only the steel carries the load: its curve alone gives the strain, and
    # creep of the (slack) aluminium changes nothing
    assert table.loc[("very hot", "final after creep"), "H"] == pytest.approx(hot["H"], rel=1e-12)
    final = model.after_load(0.004, 0.0)  # a history (its peaks and sets)
    loads = model.loads(hot["strain"], 180.0, final)
    assert loads[0] == 0.0 and loads[1] > 0


def test_creep_law_and_refusals():
    law = CreepLaw(K=1.2e-4, phi=0.01, alpha=1.3, mu=0.16)
    assert law.strain(40e6, 87600.0, 15.0) == pytest.approx(
        1.2e-4 * np.exp(0.15) * 40**1.3 * 87600**0.16, rel=1e-14
    )
    assert law.strain(40e6, 0.0, 15.0) == 0.0
    with pytest.raises(InputError) as info:
        law.strain(40e6, -1.0, 15.0)
    assert info.value.argument == "time"
    with pytest.raises(InputError) as info:  # decreasing beyond 0.3 %: refused
        ComponentCurve("aluminium", aa_coefficients([0.0, 40000.0, -80000.0]), 0.0045, E_AL, ALPHA_AL)
    assert info.value.argument == "coefficients"
    with pytest.raises(InputError) as info:
        ComponentCurve("steel", (0.0, -1e9), 0.004, E_ST, ALPHA_ST)
    assert info.value.argument == "coefficients"
    with pytest.raises(InputError) as info:
        _model().with_creep(_model().initial_history, [-1e-4, 0.0])
    assert info.value.argument == "creep"
    with pytest.raises(InputError) as info:
        level_span_states(_model(), 300.0, w0=15.97, t0=15.0, H0=28e3, cases=CASES, max_load="storm")
    assert info.value.argument == "max_load"
