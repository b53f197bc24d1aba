"""Regimes of the command line's ``--json``: the same scenes as the library regimes, through
`skcable.cli.main`, the JSON parsed and its numbers checked against the library's.

An exit status of 0 must print one JSON object of finite numbers, those of the library call
the command stands for (whose own regime checks it against the oracles); 2 (usage) and 3 (no
convergence) one line on stderr where the library refuses too (else a spurious refusal); 4
(an internal error) is untyped.
"""

from __future__ import annotations

import json
import math
import shlex
import warnings

import numpy as np

from skcable.errors import ConvergenceError, InputError, PlausibilityWarning
from tests.fuzz import conductors, lines, multi, spectra
from tests.fuzz.harness import Case, RefusedByCli
from tests.fuzz.scenes import pick

__all__ = ["REGIMES"]


def _number(value) -> str:
    return repr(float(value))


def _case(regime, argv, api: str, pairs) -> Case:
    """The command line ``argv``; ``api`` the library call it stands for; ``pairs(data,
    result)`` the (name, JSON value, library value) to agree to round-off."""
    shell = "skcable " + " ".join(shlex.quote(a) for a in argv)
    expr = f"cli.main({argv!r})"

    def library():
        from tests.fuzz.harness import namespace

        return eval(api, namespace())  # noqa: S307 - the harness's own expression

    def check(result, caught):
        status, out, err = result
        if "Traceback" in err:
            return [f"a traceback on stderr: {err[-300:]}"]
        if status in (0, 5):  # 5: solved, with plausibility warnings (issue 31)
            try:
                data = json.loads(out)
            except ValueError as exc:
                return [f"status 0 but no JSON object on stdout ({exc}): {out[:200]!r}"]
            bad = [k for k, v in _leaves(data) if isinstance(v, float) and not math.isfinite(v)]
            if bad:
                return [f"non-finite numbers in the JSON: {bad[:4]}"]
            try:
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore", PlausibilityWarning)
                    reference = library()
            except (InputError, ConvergenceError) as exc:
                return [f"status 0 where the library refuses {api}: {type(exc).__name__}: {exc}"]
            problems = []
            for name, got, want in pairs(data, reference):
                if not (got == want or abs(got - want) <= 1e-15 * abs(want)):
                    problems.append(f"{name}: JSON {got!r}, library {want!r}")
            return problems
        if status in (2, 3):
            text = err.strip().splitlines()
            if len(text) != 1:
                return [f"status {status} with {len(text)} lines on stderr: {err[:300]!r}"]
            try:
                library()
            except (InputError, ConvergenceError):
                return []  # the library refuses too (its refusal is judged by its own regime)
            raise RefusedByCli(f"status {status} ({text[0]}) where the library solves {api}")
        return [f"status {status} (an internal error): {err.strip()[:300]}"]

    return Case(regime, expr, frozenset(), check, None, shell=shell)


def _leaves(data, prefix=""):
    if isinstance(data, dict):
        for key, value in data.items():
            yield from _leaves(value, f"{prefix}{key}.")
    elif isinstance(data, list):
        for i, value in enumerate(data):
            yield from _leaves(value, f"{prefix}{i}.")
    else:
        yield prefix.rstrip("."), data


def _list(values) -> str:
    return "[" + ", ".join(_number(v) for v in values) + "]"


def _cli_values(values) -> str:
    """What the command passes for a flag of several values: one as a float, more as an array."""
    return _number(values[0]) if len(values) == 1 else f"np.array({_list(values)})"


def _same(names):
    """Pairs of the JSON value and the library attribute of the same name."""

    def pairs(data, ref):
        return [(name, data[name], float(getattr(ref, name))) for name in names]

    return pairs


def elastic(rng) -> Case:
    """``skcable elastic-catenary --json`` against `cable.elastic_catenary`."""
    span, dh, w, EA, L = lines._free_data(rng)
    argv = [
        "elastic-catenary",
        "--span",
        _number(span),
        "--dh",
        _number(dh),
        "--w",
        _number(w),
        "--EA",
        _number(EA),
        "--length",
        _number(L),
        "--json",
    ]
    api = lines._free_call(span, dh, w, EA, L)
    return _case("cli/elastic-catenary", argv, api, _same(("H", "V_A", "V_B", "T_A", "T_B", "sag")))


def line(rng) -> Case:
    """``skcable line --json`` (segments, clumps, buoys, seabed, friction) against `mooring.Line`."""
    segments, attachments, bed, friction, span, dh = multi.random_line(rng)
    argv = [
        "line",
        "--span",
        _number(span),
        "--dh",
        _number(dh),
        "--length",
        *[_number(s[0]) for s in segments],
        "--w",
        *[_number(s[1]) for s in segments],
        "--EA",
        *[_number(s[2]) for s in segments],
    ]
    for kind, joint, size in attachments:
        argv += ["--clump" if kind == "ClumpWeight" else "--buoy", str(joint), _number(size)]
    if bed is not None:
        argv += ["--seabed", _number(bed), "--friction", _number(friction)]
    argv.append("--json")
    api = f"{multi.line_expr(segments, attachments, bed, friction)}.solve({_number(span)}, {_number(dh)})"
    return _case("cli/line", argv, api, _same(("H", "V_B", "V_A", "H_A", "T_B", "length_on_seabed")))


def change_of_state(rng) -> Case:
    """``skcable change-of-state --json`` against `conductors.change_of_state`."""
    span, dh, EA, alpha, w0, t0, ref = conductors._conductor(rng)
    m = int(rng.integers(1, 4))
    w, t, wind = conductors._states(rng, w0, m)
    argv = [
        "change-of-state",
        "--span",
        _number(span),
        "--dh",
        _number(dh),
        "--EA",
        _number(EA),
        "--alpha",
        _number(alpha),
        "--w0",
        _number(w0),
        "--t0",
        _number(t0),
        f"--{ref[0]}",
        _number(ref[1]),
        "--w",
        *map(_number, w),
        "--t",
        *map(_number, t),
        "--wind",
        *map(_number, wind),
        "--json",
    ]
    api = (
        f"conductors.change_of_state({_number(span)}, {_number(dh)}, EA={_number(EA)}, "
        f"alpha={_number(alpha)}, w0={_number(w0)}, t0={_number(t0)}, {ref[0]}={_number(ref[1])}, "
        f"w={_cli_values(w)}, t={_cli_values(t)}, wind={_cli_values(wind)})"
    )

    def pairs(data, ref_):
        out = []
        for name in ("H", "sag", "T_max", "length"):
            values = data[name] if isinstance(data[name], list) else [data[name]]
            library = np.ravel(getattr(ref_, name))
            out += [
                (f"{name}[{i}]", v, float(r)) for i, (v, r) in enumerate(zip(values, library, strict=True))
            ]
        return out + [("L0", data["L0"], float(ref_.L0))]

    return _case("cli/change-of-state", argv, api, pairs)


def frequencies(rng) -> Case:
    """``skcable frequencies --json`` against `conductors.natural_frequencies`."""
    span, dh, w, EA, given, n = spectra._cable(rng)
    argv = [
        "frequencies",
        "--span",
        _number(span),
        "--dh",
        _number(dh),
        "--EA",
        _number(EA),
        "--w",
        _number(w),
        f"--{given[0]}",
        _number(given[1]),
        "--n-modes",
        str(n),
        "--json",
    ]
    api = spectra._freq_call(span, dh, w, EA, given, n)

    def pairs(data, ref):
        return [
            (f"{name}[{i}]", v, float(r))
            for name in ("f_in_plane", "f_out_of_plane")
            for i, (v, r) in enumerate(zip(data[name], getattr(ref, name), strict=True))
        ]

    return _case("cli/frequencies", argv, api, pairs)


def strand_section(rng) -> Case:
    """``skcable strand section --json`` against the library's section (checked by its regime)."""
    name = pick(rng, spectra.PRESETS[:4])
    damage = int(rng.integers(0, 7))
    argv = ["strand", "section", "--preset", name, "--damage", str(damage), "--json"]
    api = f"strand.preset({name!r}).damaged({damage}).section()"

    def pairs(data, sec):
        return [
            ("area_m2", data["area_m2"], sec.area),
            ("EA_N", data["EA_N"], sec.EA),
            ("EI_stick_1_Nm2", data["EI_stick_1_Nm2"], float(sec.EI_stick[0])),
            ("EI_stick_2_Nm2", data["EI_stick_2_Nm2"], float(sec.EI_stick[1])),
            ("EI_slip_1_Nm2", data["EI_slip_1_Nm2"], float(sec.EI_slip[0])),
        ]

    return _case("cli/strand-section", argv, api, pairs)


REGIMES = {
    "cli/elastic-catenary": elastic,
    "cli/line": line,
    "cli/change-of-state": change_of_state,
    "cli/frequencies": frequencies,
    "cli/strand-section": strand_section,
}
