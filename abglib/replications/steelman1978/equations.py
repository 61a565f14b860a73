"""Table of agreement: every numbered equation of seed 000 that makes a checkable claim.

Each printed closed form (eqs 11-41, 50-59) is evaluated *as printed* (the ``*_simpson``,
``*_standard_*``, ``*_eq5x`` functions of :mod:`abglib.analysis`, or the printed
polynomial written out here) and compared with an exact route: the Lyapunov variance,
direct summation of the transient, the eigenvalues of the closed-loop matrix
(:func:`abglib.analysis.state_space`), exact frequency-domain features, the DFT of the
impulse response of :func:`abglib.track`. Where a printed form disagrees with the quantity
the text names but equals another exact quantity, the row says which (``matches``).

The stability criteria (eqs 42-49) are checked on random gain sets (seeded) against the
poles (:func:`abglib.analysis.is_stable`).

``equation_table``   one row per (equation, gain set)
``stability_table``  one row per criterion or implication of eqs 42-49
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
import pandas as pd

from ... import analysis as A
from ... import design
from ...analysis._statespace import state_space
from ...engine import track
from ...gains import Gains

__all__ = [
    "EQUATION_COLUMNS",
    "STABILITY_COLUMNS",
    "equation_table",
    "impulse_length",
    "stability_table",
]

EQUATION_COLUMNS = [
    "equation",
    "quantity",
    "case",
    "printed_form",
    "exact_route",
    "rel_diff",
    "claimed",
    "holds",
    "matches",
    "comment",
]
STABILITY_COLUMNS = [
    "equations",
    "check",
    "samples",
    "stable_by_poles",
    "criterion_true",
    "agree",
    "criterion_true_but_unstable",
    "criterion_false_but_stable",
]

# the quantity each printed variance form names (smoothed: seed 000 defines k_x(0) as the
# "steady-state variance in position output" beside Simpson's eqs 11-13), and the exact
# outputs it may equal instead (Morrison's fading-memory forms may be one-step predictions)
_VRF_EXACT = {"x": ("x_smooth", "x_pred"), "v": ("v_smooth", "v_pred"), "a": ("a_smooth", "a_pred")}


def _cases(alphas: Sequence[float]):
    """Gain sets where every closed form is evaluated: standard α-β-γ / α-β, QD."""
    cases = []
    for a in alphas:
        cases.append((f"standard α-β-γ, α={a:g}", "abg", design.standard_from_alpha(a, 3)))
    for a in alphas:
        cases.append((f"standard α-β, α={a:g}", "ab", design.standard_from_alpha(a, 2)))
    for a in alphas:
        cases.append((f"QD, α={a:g}", "qd", design.qd(design.qd_m_from_alpha(a))))
    return cases


def _row(eq, quantity, case, printed, exact, claimed, rtol, matches="", comment=""):
    rel = abs(printed - exact) / abs(exact) if exact != 0 else abs(printed - exact)
    holds = bool(rel <= rtol) if claimed == "exact" else None
    return {
        "equation": eq,
        "quantity": quantity,
        "case": case,
        "printed_form": printed,
        "exact_route": exact,
        "rel_diff": rel,
        "claimed": claimed,
        "holds": holds,
        "matches": matches,
        "comment": comment,
    }


def _match(value, candidates: Mapping, rtol) -> str:
    """Names of the exact quantities that ``value`` equals within ``rtol``."""
    return ", ".join(
        k for k, v in candidates.items() if np.isfinite(v) and abs(value - v) <= rtol * abs(v)
    )


def _morrison_rows(printed, eqs, exact_vrf, case, rtol):
    """Rows for Morrison's k_x, k_v(, k_a) (eqs 25-27 or 31-32) against every exact VRF."""
    rows = []
    for eq, key in zip(eqs, ("x", "v", "a"), strict=False):
        cands = {k: exact_vrf[k] for k in _VRF_EXACT[key] if k in exact_vrf}
        rows.append(
            _row(
                eq,
                f"k_{key}(0), Morrison",
                case,
                printed[key],
                exact_vrf[_VRF_EXACT[key][0]],
                "exact",
                rtol,
                _match(printed[key], cands, rtol),
            )
        )
    return rows


def impulse_length(gains: Gains, n_min: int) -> int:
    """Samples after which the impulse response has decayed below 1e-17 of its start (the
    slowest pole), and at least ``n_min``: a power of two, so that the DFT of the truncated
    response is the transfer function to rounding."""
    radius = float(A.pole_radius(gains))
    need = int(np.ceil(np.log(1e-17) / np.log(radius))) if 0 < radius < 1 else n_min
    return int(2 ** np.ceil(np.log2(max(need, n_min))))


def _impulse_dft_error(gains: Gains, output: str, n: int) -> float:
    """max |H(e^{jωT}) - DFT(impulse response of track())| over the DFT bins (eqs 36-39)."""
    z = np.zeros(n)
    z[0] = 1.0
    res = track(z, gains)
    h = {
        "x_smooth": res.x_smooth,
        "x_pred": res.x_pred,
        "v_smooth": res.v_smooth,
        "a_smooth": res.a_smooth,
    }[output]
    wt = 2.0 * np.pi * np.arange(n // 2 + 1) / n
    tf = np.asarray(A.frequency_response(gains, output, wt))
    return float(np.max(np.abs(np.fft.rfft(h) - tf)))


def _eq33_35_residual(gains: Gains, n: int = 64) -> float:
    """max residual of the Z-transformed eqs 33-35 (T = 1) with X̄, V̄, Ā of eqs 36-38,
    on ``n`` points of the unit circle (the responses come from the state-space route)."""
    a, b, g = (float(v) for v in gains)
    wt = np.linspace(0.05, np.pi, n)
    z = np.exp(1j * wt)
    x, v, acc = (
        np.asarray(A.frequency_response(gains, o, wt)) for o in ("x_smooth", "v_smooth", "a_smooth")
    )
    r33 = (z + a - 1) * x + (a - 1) * v + (a - 1) / 2 * acc - a * z
    r34 = b * x + (z + b - 1) * v + (b / 2 - 1) * acc - b * z
    r35 = g * x + g * v + (z + g / 2 - 1) * acc - g * z
    return float(np.max(np.abs(np.concatenate([r33, r34, r35]))))


def _printed_delta(gains: Gains) -> np.ndarray:
    """Eq 40 as printed, expanded: (Z-1)^3 + α(Z-1)^2 + (β+γ/2)Z(Z-1) + γZ (descending)."""
    a, b, g = (float(v) for v in gains)
    w = np.poly1d([1.0, -1.0])
    z = np.poly1d([1.0, 0.0])
    return (w**3 + a * w**2 + (b + g / 2) * z * w + g * z).coeffs


def _poles_poly(gains: Gains, reduced: bool) -> np.ndarray:
    """Characteristic polynomial from the eigenvalues of the closed-loop matrix F."""
    return np.real(np.poly(np.linalg.eigvals(state_space(gains, reduced=reduced).F)))


def equation_table(cfg: Mapping, eq53_exponents: Sequence[float]) -> pd.DataFrame:
    """Rows of the table of agreement for the gain sets of ``cfg['alphas']``.

    Parameters
    ----------
    cfg : mapping
        ``steelman1978.equation_checks`` (``alphas``, ``exact_rtol``, ``impulse_samples``).
    eq53_exponents : sequence of float
        Exponents of eq 53 to check (-.15 printed for -3 dB, -.3 for Table 3's -6 dB).
    """
    rtol = float(cfg["exact_rtol"])
    n_impulse = int(cfg["impulse_samples"])
    rows = []
    for case, kind, g in _cases(cfg["alphas"]):
        exact_vrf = A.vrf(g)
        if kind in ("abg", "qd"):
            printed = A.vrf_simpson(g)
            for eq, key in (("11", "x"), ("12", "v"), ("13", "a")):
                cands = {k: exact_vrf[k] for k in _VRF_EXACT[key]}
                rows.append(
                    _row(
                        eq,
                        f"k_{key}(0), Simpson (with eq 14)",
                        case,
                        printed[key],
                        exact_vrf[_VRF_EXACT[key][0]],
                        "exact",
                        rtol,
                        _match(printed[key], cands, rtol),
                    )
                )
            for first, fn_p, fn_e, name in (
                (15, A.transient_d2_simpson, A.transient_d2, "D²"),
                (18, A.transient_a2_simpson, A.transient_a2, "A²"),
            ):
                p, e = fn_p(g), fn_e(g)
                for i, key in enumerate(("x", "v", "a")):
                    rows.append(
                        _row(
                            str(first + i),
                            f"{name}_{key}, Simpson",
                            case,
                            p[key],
                            e[key],
                            "exact",
                            rtol,
                            _match(p[key], e, rtol),
                        )
                    )
        if kind == "abg":
            theta = design.standard_theta_from_alpha(g.alpha, 3)
            cp = _poles_poly(g, reduced=False)
            rows.append(
                _row(
                    "22-24",
                    "max |char. poly - (z-θ)³| (critically damped)",
                    case,
                    float(np.max(np.abs(cp - np.poly([theta] * 3)))),
                    0.0,
                    "exact",
                    rtol,
                    comment="all three poles at z = θ",
                )
            )
            rows += _morrison_rows(
                A.vrf_standard_abg(theta), ("25", "26", "27"), exact_vrf, case, rtol
            )
        if kind == "ab":
            theta = design.standard_theta_from_alpha(g.alpha, 2)
            rows += _morrison_rows(A.vrf_standard_ab(theta), ("31", "32"), exact_vrf, case, rtol)
            a, b = g.alpha, g.beta
            printed41 = np.array([1.0, a + b - 2.0, 1.0 - a])
            rows.append(
                _row(
                    "41",
                    "max |eigenvalue char. poly - printed Δ| (α-β)",
                    case,
                    float(np.max(np.abs(_poles_poly(g, reduced=True) - printed41))),
                    0.0,
                    "exact",
                    rtol,
                )
            )
        else:
            rows.append(
                _row(
                    "33-35",
                    "max residual of eqs 33-35 with the exact X̄, TV̄, T²Ā",
                    case,
                    _eq33_35_residual(g),
                    0.0,
                    "exact",
                    rtol,
                    comment="64 points of the unit circle",
                )
            )
            rows.append(
                _row(
                    "40",
                    "max |eigenvalue char. poly - printed Δ|",
                    case,
                    float(np.max(np.abs(_poles_poly(g, reduced=False) - _printed_delta(g)))),
                    0.0,
                    "exact",
                    rtol,
                )
            )
        # transfer functions (eqs 36-39) against the simulated impulse response
        for eq, out in (
            ("36", "x_smooth"),
            ("37", "v_smooth"),
            ("38", "a_smooth"),
            ("39", "x_pred"),
        ):
            if kind == "ab" and out == "a_smooth":
                continue
            n = impulse_length(g, n_impulse)
            rows.append(
                _row(
                    eq,
                    f"max |H - DFT(track impulse)|, {out}",
                    case,
                    _impulse_dft_error(g, out, n),
                    0.0,
                    "exact",
                    rtol,
                    comment=f"{n}-point DFT",
                )
            )
        # frequency-domain features (eqs 50-59)
        wmax, over = A.peak(g)
        unity = A.omega_at_gain(g, 0.0)
        rows.append(
            _row(
                "50",
                "min |X̄/X| (at ωT = π)",
                case,
                A.min_gain_steelman_eq50(g),
                A.min_gain_at_pi(g),
                "exact",
                rtol,
            )
        )
        rows.append(
            _row("51", "ωT where |X̄/X| = 1", case, A.omega_unity_eq51(g), unity, "exact", rtol)
        )
        rows.append(
            _row(
                "52",
                "ωT where |X̄/X| = 1",
                case,
                A.omega_unity_eq52(g),
                unity,
                "approximation",
                rtol,
            )
        )
        for exponent in eq53_exponents:
            level = 20.0 * exponent
            rows.append(
                _row(
                    "53",
                    f"ωT where |X̄/X| = {level:g} dB (exponent {exponent:g})",
                    case,
                    A.omega_3db_eq53(g, exponent),
                    A.omega_at_gain(g, level),
                    "approximation",
                    rtol,
                )
            )
        rows.append(_row("54", "ωT_max", case, A.omega_max_eq54(g), wmax, "approximation", rtol))
        rows.append(
            _row("55-59", "overshoot", case, A.overshoot_eq55(g), over, "approximation", rtol)
        )
    return pd.DataFrame(rows, columns=EQUATION_COLUMNS)


def stability_table(cfg: Mapping) -> pd.DataFrame:
    """Agreement of the printed stability criteria (eqs 42-49) with the poles.

    Gains are drawn uniformly from ``cfg['stability_box']`` with ``cfg['stability_seed']``;
    α-β sets (γ = 0) for eqs 42-44, α-β-γ sets for the rest. Besides the criteria, the
    statements after eq 48: the implications, and that γ = 0 reduces the α-β-γ
    conditions (45-47) to the α-β ones (42-44).
    """
    rng = np.random.default_rng(int(cfg["stability_seed"]))
    n = int(cfg["stability_samples"])
    box = cfg["stability_box"]
    a = rng.uniform(*box["alpha"], n)
    b = rng.uniform(*box["beta"], n)
    c = rng.uniform(*box["gamma"], n)
    g3, g2 = Gains(a, b, c), Gains(a, b)
    s3, s2 = np.asarray(A.is_stable(g3)), np.asarray(A.is_stable(g2))
    eq45 = (a > 0) & (a < 2)
    checks = [
        ("42-44", "α-β: printed criterion vs poles", np.asarray(A.stable_jury_steelman(g2)), s2),
        ("45-48", "α-β-γ: printed criterion vs poles", np.asarray(A.stable_jury_steelman(g3)), s3),
        (
            "45,46,48,49",
            "α-β-γ: sufficient condition vs poles",
            np.asarray(A.stable_sufficient_eq49(g3)),
            s3,
        ),
    ]
    rows = []
    for eq, what, crit, truth in checks:
        rows.append(
            {
                "equations": eq,
                "check": what,
                "samples": n,
                "stable_by_poles": int(truth.sum()),
                "criterion_true": int(crit.sum()),
                "agree": int((crit == truth).sum()),
                "criterion_true_but_unstable": int((crit & ~truth).sum()),
                "criterion_false_but_stable": int((~crit & truth).sum()),
            }
        )
    ab = (a > 0) & (b > 0) & (2 * a + b < 4)
    imp = [
        ("42-44 ⇒ 45", "α>0, β>0, 2α+β<4 imply 0<α<2", ab, eq45),
        (
            "45,47,48 ⇒ 43",
            "0<α<2, αβ+αγ/2-γ>0, γ>0 imply β>0",
            eq45 & (a * b + a * c / 2 - c > 0) & (c > 0),
            b > 0,
        ),
    ]
    for eq, what, premise, conclusion in imp:
        rows.append(
            {
                "equations": eq,
                "check": what,
                "samples": n,
                "stable_by_poles": None,
                "criterion_true": int(premise.sum()),
                "agree": int((~premise | conclusion).sum()),
                "criterion_true_but_unstable": int((premise & ~conclusion).sum()),
                "criterion_false_but_stable": 0,
            }
        )
    # γ = 0 in eqs 45-47 (eq 48, γ > 0, cannot hold at γ = 0 and is left out)
    reduced = eq45 & (2 * a + b < 4) & (a * b > 0)
    rows.append(
        {
            "equations": "45-47 at γ=0 ⇔ 42-44",
            "check": "γ = 0 in eqs 45-47 gives eqs 42-44 (eq 48 left out)",
            "samples": n,
            "stable_by_poles": None,
            "criterion_true": int(reduced.sum()),
            "agree": int((reduced == ab).sum()),
            "criterion_true_but_unstable": int((reduced & ~ab).sum()),
            "criterion_false_but_stable": int((~reduced & ab).sum()),
        }
    )
    return pd.DataFrame(rows, columns=STABILITY_COLUMNS)
