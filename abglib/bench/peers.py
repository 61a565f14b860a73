r"""abglib against peer libraries on the same gains: every agreement and disagreement.

Peers: FilterPy's g-h and g-h-k filters (``filterpy.gh.GHFilter``, ``GHKFilter``; gains
converted only through :func:`abglib.conventions.to_filterpy`, ``k = gamma / 2``) and
its analytic helpers (``VRF``, ``VRF_prediction``, ``bias_error``,
``critical_damping_parameters``, ``benedict_bornder_constants``,
``least_squares_parameters``); :func:`scipy.signal.freqz` and python-control
(``TransferFunction`` evaluated on the unit circle, ``dlyap``) for frequency responses
and variances.

:func:`agreement_table` returns one row per compared quantity. Where abglib and the peer
disagree (relative difference above ``rtol``), the row is settled by independent routes
that share no code with either side: direct summation of the impulse response
(``sum h_k^2``, :func:`direct_vrf`), a seeded Monte Carlo with a confidence interval from
the across-run spread (:func:`monte_carlo_vrf`), python-control's ``dlyap``, or a
simulated track; ``supports`` says which side they confirm, and ``explanation`` what the
peer computes instead (demonstrated by a reparenthesised or rescaled formula evaluated
in the row's ``alternative`` column).
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import scipy.signal
import scipy.stats

from .. import design
from ..analysis import frequency_response, steady_state_lag, transfer_function, vrf
from ..analysis._statespace import state_space
from ..common.tables import roundoff, with_precision
from ..conventions import from_filterpy, to_filterpy
from ..engine import track
from ..gains import Gains

__all__ = ["GAIN_SETS", "agreement_table", "direct_vrf", "monte_carlo_vrf"]

#: Gain sets compared (label -> (gains, dt)): critically damped, Benedict-Bordner,
#: an underdamped Bendix set, and alpha-beta-gamma sets; two sample intervals so that
#: every dt scaling is exercised.
GAIN_SETS = {
    "standard α-β θ=0.8": (design.standard_ab(0.8), 1.0),
    "Benedict-Bordner α=0.5, T=0.5 s": (design.benedict_bordner(0.5), 0.5),
    "Bendix T=3 s (memo)": (design.bendix(3), 3.0),
    "standard α-β-γ θ=0.5": (design.standard_abg(0.5), 1.0),
    "standard α-β-γ θ=0.8, T=0.5 s": (design.standard_abg(0.8), 0.5),
    "Kalata α-β-γ Λ=0.5, T=2 s": (design.kalata_abg(0.5), 2.0),
}

_PRED = {"x_pred": "x_pred"}


def direct_vrf(gains: Gains, output: str, dt: float = 1.0, n: int = 200_000) -> float:
    """VRF by direct summation of the impulse response: ``sum_k h_k^2`` (white noise).

    The impulse response is the tracker run by :func:`scipy.signal.lfilter` on the
    transfer function of seed 000, eqs 36-39 (:func:`abglib.analysis.transfer_function`),
    truncated at ``n`` samples (stable gains: the tail is below machine precision).
    """
    num, den = transfer_function(gains, output, dt)
    imp = np.zeros(n)
    imp[0] = 1.0
    h = scipy.signal.lfilter(num, den, imp)
    return float(np.sum(h**2))


def monte_carlo_vrf(
    gains: Gains, dt: float = 1.0, runs: int = 200, samples: int = 4000, seed: int = 0
) -> dict:
    """Seeded Monte Carlo VRF of ``x_smooth``, ``v_smooth``, ``a_smooth``, ``x_pred``.

    Unit white noise tracked by :func:`abglib.track` from a zero state; the first
    ``samples // 4`` samples are dropped. Returns ``{output: (mean, lo, hi)}`` with a
    99.9 % Student-t interval from the ``runs`` per-run mean squares.
    """
    z = np.random.default_rng(seed).standard_normal((runs, samples))
    r = track(z, gains, dt=dt)
    q = scipy.stats.t.ppf(0.9995, runs - 1)
    out = {}
    for o in ("x_smooth", "v_smooth", "a_smooth", "x_pred"):
        per_run = np.mean(getattr(r, o)[:, samples // 4 :] ** 2, axis=1)
        m, se = per_run.mean(), per_run.std(ddof=1) / math.sqrt(runs)
        out[o] = (float(m), float(m - q * se), float(m + q * se))
    return out


def _rel(a, b) -> float:
    """Largest |a - b| over the largest |b| (norm-wise: arrays may pass through 0)."""
    a, b = np.asarray(a), np.asarray(b)
    return float(np.max(np.abs(a - b)) / max(float(np.max(np.abs(b))), 1e-300))


def _row(peer, function, label, quantity, ours, theirs, rtol, **extra) -> dict:
    rel = _rel(theirs, ours)
    return {
        "peer": peer,
        "function": function,
        "gains": label,
        "quantity": quantity,
        "abglib": float(np.asarray(ours).ravel()[0]) if np.size(ours) == 1 else None,
        "peer_value": float(np.asarray(theirs).ravel()[0]) if np.size(theirs) == 1 else None,
        "rel_diff": rel,
        "agree": bool(rel <= rtol),
        "independent_route": extra.get("route", ""),
        "independent_value": extra.get("independent"),
        "supports": extra.get("supports", ""),
        "alternative": extra.get("alternative"),
        "alternative_rel_diff": (
            None if extra.get("alternative") is None else _rel(extra["alternative"], ours)
        ),
        "explanation": extra.get("explanation", ""),
    }


def _settle(ours, theirs, independent, rtol, mc=None) -> str:
    """Which side the independent value (and the Monte Carlo interval) confirm."""
    ok_ours = abs(independent - ours) <= rtol * max(abs(ours), 1e-300) * 1e3
    ok_theirs = abs(independent - theirs) <= rtol * max(abs(theirs), 1e-300) * 1e3
    if mc is not None:
        _, lo, hi = mc
        ok_ours &= lo <= ours <= hi
        ok_theirs &= lo <= theirs <= hi
    if ok_ours and ok_theirs:
        return "both"
    return "abglib" if ok_ours else ("peer" if ok_theirs else "neither")


def _filterpy_rows(label, g: Gains, dt: float, rtol: float, seed: int) -> list[dict]:
    from filterpy.gh import (
        GHFilter,
        GHKFilter,
        benedict_bornder_constants,
    )

    rows = []
    fg, fh, fk = to_filterpy(g)
    ours = vrf(g, dt)
    mc = monte_carlo_vrf(g, dt, seed=seed)
    z = np.cumsum(np.random.default_rng(seed).normal(size=500))
    ref = track(z, g, dt=dt)

    def vrf_row(function, quantity, key, theirs, alternative=None, explanation=""):
        ind = direct_vrf(g, key if key != "x_pred" else "x_pred", dt)
        agree = _rel(theirs, ours[key]) <= rtol
        row = _row(
            "FilterPy",
            function,
            label,
            quantity,
            ours[key],
            theirs,
            rtol,
            route="direct summation Σh² and Monte Carlo (99.9 % CI)",
            independent=ind,
            supports=_settle(ours[key], theirs, ind, rtol, mc[key]),
            alternative=alternative,
            explanation="" if agree else explanation,
        )
        return row

    if g.order == 2:
        f = GHFilter(x=0.0, dx=0.0, dt=dt, g=fg, h=fh)
        res = f.batch_filter(z)[1:]
        rows.append(
            _row(
                "FilterPy",
                "GHFilter.batch_filter",
                label,
                "x_smooth, v_smooth track",
                np.r_[ref.x_smooth, ref.v_smooth],
                np.r_[res[:, 0], res[:, 1]],
                rtol,
            )
        )
        vx, vdx = f.VRF()
        rows.append(vrf_row("GHFilter.VRF()[0]", "VRF x_smooth", "x_smooth", vx))
        rows.append(vrf_row("GHFilter.VRF()[1]", "VRF v_smooth (1/s²)", "v_smooth", vdx))
        rows.append(
            vrf_row("GHFilter.VRF_prediction()", "VRF x_pred", "x_pred", f.VRF_prediction())
        )
        bb = benedict_bornder_constants(fg)
        ref_bb = design.benedict_bordner(fg) if fg <= 1 else None
        if ref_bb is not None:
            rows.append(
                _row(
                    "FilterPy",
                    "benedict_bornder_constants(g)",
                    label,
                    "β of Benedict-Bordner",
                    ref_bb.beta,
                    bb[1],
                    rtol,
                )
            )
        return rows

    f = GHKFilter(x=0.0, dx=0.0, ddx=0.0, dt=dt, g=fg, h=fh, k=fk)
    xs = np.array([f.update(zi)[0] for zi in z])
    rows.append(
        _row(
            "FilterPy",
            "GHKFilter.update (per sample)",
            label,
            "x_smooth track",
            ref.x_smooth,
            xs,
            rtol,
        )
    )
    fb = GHKFilter(x=0.0, dx=0.0, ddx=0.0, dt=dt, g=fg, h=fh, k=fk).batch_filter(z)[1:, 0]
    ab = track(z, Gains(g.alpha, g.beta, 0.0), dt=dt).x_smooth
    rows.append(
        _row(
            "FilterPy",
            "GHKFilter.batch_filter",
            label,
            "x_smooth track",
            ref.x_smooth,
            fb,
            rtol,
            route="abglib.track with the same α, β and γ = 0",
            independent=_rel(fb, ab),
            # the disagreement is FilterPy's only if its output is the alpha-beta tracker
            supports="abglib" if _rel(fb, ab) <= rtol else "neither",
            explanation=(
                "batch_filter ignores k: its output equals the α-β tracker with the "
                f"same g, h to {roundoff(_rel(fb, ab), 2)} relative (independent_value)"
            ),
        )
    )
    vx, vdx, vddx = f.VRF()
    h4, ghk = 4 - 2 * fg - fh, fg * fh + fg * fk - 2 * fk
    num_x = 2 * fh * (2 * fg**2 + 2 * fh - 3 * fg * fh) - 2 * fg * fk * h4
    rows.append(
        vrf_row(
            "GHKFilter.VRF()[0]",
            "VRF x_smooth",
            "x_smooth",
            vx,
            alternative=num_x / (2 * h4 * ghk),
            explanation=(
                "FilterPy divides by 2k − g(h+k)·(4−2g−h) (precedence) and drops a factor "
                "2: the same numerator over 2(4−2g−h)(gh+gk−2k) (alternative) equals abglib; "
                "FilterPy's value can be negative, impossible for a variance"
            ),
        )
    )
    num_dx = 2 * fh**3 - 4 * fh**2 * fk + 4 * fk**2 * (2 - fg)
    rows.append(
        vrf_row(
            "GHKFilter.VRF()[1]",
            "VRF v_smooth (1/s²)",
            "v_smooth",
            vdx,
            alternative=num_dx / (h4 * ghk) / dt**2,
            explanation=(
                "FilterPy's denominator has a spurious factor 2 and no dt²: "
                "(2h³−4h²k+4k²(2−g)) / ((4−2g−h)(gh+gk−2k)) / dt² (alternative) equals "
                "abglib"
            ),
        )
    )
    rows.append(vrf_row("GHKFilter.VRF()[2]", "VRF a_smooth (1/s⁴)", "a_smooth", vddx))
    gh2 = 2 * fg + fh
    rows.append(
        vrf_row(
            "GHKFilter.VRF_prediction()",
            "VRF x_pred",
            "x_pred",
            f.VRF_prediction(),
            alternative=(fg * fk * (gh2 - 4) + fh * (fg * gh2 + 2 * fh))
            / ((2 * fk - fg * (fh + fk)) * (gh2 - 4)),
            explanation=(
                "operator precedence: FilterPy computes 2k − (g(h+k)(2g+h−4)); the "
                "denominator (2k − g(h+k))·(2g+h−4) (alternative) equals abglib"
            ),
        )
    )
    # bias error for a constant jerk J: FilterPy's is estimate - truth of the prediction
    J = 1.0
    lag = steady_state_lag(g, dt, kind="jerk", magnitude=J, output="x_pred")
    # the cubic centred on the track (t from -600 dt to +599 dt): its lower-order terms add
    # no steady-state bias (the alpha-beta-gamma tracker follows a quadratic exactly), and
    # the measurements stay ~1e7 rather than ~1e10, so the subtraction of the truth
    # cancels ~1e3 times fewer digits (1200 samples: the transient has long died out)
    t = (np.arange(1200) - 600) * dt
    sim = track(J * t**3 / 6.0, g, dt=dt).x_pred
    sim_bias = float(sim[-1] - J * t[-1] ** 3 / 6.0)
    rows.append(
        _row(
            "FilterPy",
            "GHKFilter.bias_error(dddx=1)",
            label,
            "steady-state prediction bias for unit jerk (estimate − truth)",
            -lag,
            f.bias_error(J),
            rtol,
            route="simulated track of J t³/6 (last sample)",
            independent=sim_bias,
            supports=_settle(-lag, f.bias_error(J), sim_bias, 1e-9),
        )
    )
    return rows


def _helper_rows(rtol: float) -> list[dict]:
    from filterpy.gh import (
        benedict_bornder_constants,
        critical_damping_parameters,
        least_squares_parameters,
    )

    from ..analysis import poles

    rows = []
    for th in (0.3, 0.8):
        for order, ours in ((2, design.standard_ab(th)), (3, design.standard_abg(th))):
            theirs = from_filterpy(*critical_damping_parameters(th, order))
            rows.append(
                _row(
                    "FilterPy",
                    f"critical_damping_parameters({th}, order={order})",
                    f"θ={th}",
                    "(α, β, γ) with k → γ = 2k",
                    np.array(list(ours)),
                    np.array(list(theirs)),
                    rtol,
                )
            )
    n = np.arange(1, 50)
    gm = design.growing_memory(len(n))
    ls = np.array([least_squares_parameters(int(k) - 1) for k in n])
    rows.append(
        _row(
            "FilterPy",
            "least_squares_parameters(n), n = 0..48",
            "growing memory",
            "(g_n, h_n) vs growing_memory n+1 (seed 001, eqs 24a-b)",
            np.r_[gm.alpha, gm.beta],
            np.r_[ls[:, 0], ls[:, 1]],
            rtol,
        )
    )
    for g in (0.3, 0.8):
        _, h = benedict_bornder_constants(g, critical=True)
        p = poles(Gains(g, h))
        crit = design.standard_from_alpha(g, 2).beta
        rows.append(
            _row(
                "FilterPy",
                f"benedict_bornder_constants({g}, critical=True)",
                f"g={g}",
                "β 'nearly critically damped' vs critically damped β at the same α",
                crit,
                h,
                rtol,
                route="poles of the tracker (abglib.analysis.poles)",
                independent=float(np.max(np.abs(np.imag(p)))),
                supports="not comparable",
                explanation=(
                    "a different rule (Brookner 0.8·(2−g²−2√(1−g²))/g²), not "
                    "critical damping: independent_value is the largest |Im| of "
                    "its poles (0 would be critically or over-damped)"
                ),
            )
        )
    return rows


def _frequency_rows(label, g: Gains, dt: float, rtol: float) -> list[dict]:
    import control

    rows = []
    wT = np.linspace(0.0, np.pi, 257)
    for o in ("x_smooth", "v_smooth", "x_pred"):
        ours = frequency_response(g, o, wT, dt)
        num, den = transfer_function(g, o, dt)
        _, h_sp = scipy.signal.freqz(num, den, worN=wT)
        rows.append(
            _row(
                "scipy.signal",
                "freqz",
                label,
                f"H(e^jωT) of {o}, 257 ωT in [0, π]",
                ours,
                h_sp,
                rtol,
            )
        )
        sys = control.TransferFunction(num, den, dt)
        h_ct = np.asarray(sys(np.exp(1j * wT)))
        rows.append(
            _row(
                "python-control",
                "TransferFunction(num, den, dt)(e^jωT)",
                label,
                f"H(e^jωT) of {o}",
                ours,
                h_ct,
                rtol,
            )
        )
    ss = state_space(g, dt)
    P = np.asarray(control.dlyap(ss.F, np.outer(ss.K, ss.K)))
    v = vrf(g, dt)
    rows.append(
        _row(
            "python-control",
            "dlyap(F, K Kᵀ)",
            label,
            "VRF x_smooth, v_smooth",
            np.array([v["x_smooth"], v["v_smooth"]]),
            np.diag(P)[:2],
            rtol,
        )
    )
    return rows


def agreement_table(rtol: float = 1e-9, seed: int = 0) -> pd.DataFrame:
    """Every compared quantity: abglib, the peer, their relative difference, the verdict.

    Parameters
    ----------
    rtol : float
        Relative difference counted as agreement.
    seed : int
        Seed of the Monte Carlo routes and test signals (row ``i`` of :data:`GAIN_SETS`
        uses ``seed + i``).
    """
    rows = []
    for i, (label, (g, dt)) in enumerate(GAIN_SETS.items()):
        rows += _filterpy_rows(label, g, dt, rtol, seed + i)
        rows += _frequency_rows(label, g, dt, rtol)
    rows += _helper_rows(rtol)
    df = pd.DataFrame(rows)
    df.loc[df["agree"] & (df["supports"] == ""), "supports"] = "both"
    # agreements are round-off: relative differences below 1e-12 are written as the bound
    return with_precision(df, rel_diff="<1e-12", alternative_rel_diff="<1e-12")
