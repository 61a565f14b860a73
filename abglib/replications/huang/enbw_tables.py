r"""Seed 002, Figures 2-3 and Tables 1-2: the ENBW of the two gain rules, cell by cell.

``RULES``             the paper's two gain-selection rules (type I, type II)
``bandwidth_curves``  ``B_n T`` against ``xi`` (Figures 2-3), exact and closed forms
``enbw_monte_carlo``  ENBW estimated from a noise-driven loop (seeded), with its SE
``table_row``         one cell of Tables 1-2: what the printed gains really are
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ..._checks import AbglibValueError, check_finite, check_positive
from ...analysis import enbw, is_stable, pole_radius, require_stable, stable_jury_steelman
from ...conventions import from_huang, to_huang
from ...design import huang_for_enbw, huang_type1, huang_type2
from ...engine import track
from ...gains import Gains
from ...simulate import white_noise
from .printed import (
    enbw_huang_eq8_13,
    enbw_huang_eq13_as_printed,
    enbw_huang_eq14,
    stable_huang_eq5,
    stable_huang_eq7,
)

__all__ = ["RULES", "bandwidth_curves", "enbw_monte_carlo", "table_row"]

#: The paper's two gain-selection rules (seed 002, "Loop parameters selecting").
RULES = {"type1": huang_type1, "type2": huang_type2}


# --------------------------------------------------------------------------- Figs 2-3
def bandwidth_curves(xi, dt=1.0) -> pd.DataFrame:
    r"""``B_n T`` against ``xi`` for both rules and both trackers (seed 002, Figs 2-3).

    Parameters
    ----------
    xi : array (m,)
        Grid of the smoothing factor, inside ``0 < xi < 1``.
    dt : float, default 1.0
        Sample interval (``B_n T`` does not depend on it).

    Returns
    -------
    DataFrame
        Long table, columns ``rule, order, xi, alpha, beta, gamma_h, bnT_exact``
        (:func:`abglib.analysis.enbw`, Lyapunov), ``bnT_closed`` (eq 14 for alpha-beta;
        the reconstructed eqs 8-13 for alpha-beta-gamma) and ``bnT_eq13_printed``
        (alpha-beta-gamma only, :func:`enbw_huang_eq13_as_printed`).
    """
    x = check_finite("xi", xi).ravel()
    T = float(check_positive("dt", dt))
    rows = []
    for rule, fn in RULES.items():
        for order in (2, 3):
            g = fn(x, order)
            ah, bh, gh = (np.broadcast_to(v, x.shape) for v in to_huang(g))
            exact = np.asarray(enbw(g, T)) * T
            if order == 2:
                closed = np.asarray(enbw_huang_eq14(ah, bh, T)) * T
                literal = np.full(x.shape, np.nan)
            else:
                closed = np.asarray(enbw_huang_eq8_13(ah, bh, gh, T)) * T
                literal = np.array(
                    [enbw_huang_eq13_as_printed(*v, T) * T for v in zip(ah, bh, gh, strict=True)]
                )
            rows.append(
                pd.DataFrame(
                    {
                        "rule": rule,
                        "order": order,
                        "xi": x,
                        "alpha": ah,
                        "beta": bh,
                        "gamma_h": gh,
                        "bnT_exact": exact,
                        "bnT_closed": closed,
                        "bnT_eq13_printed": literal,
                    }
                )
            )
    return pd.concat(rows, ignore_index=True)


def enbw_monte_carlo(gains: Gains, dt, runs, samples, burn_in, seed) -> tuple:
    r"""One-sided ENBW (Hz) estimated by driving the loop with unit white noise.

    Parameters
    ----------
    gains : Gains
        Canonical gains (scalar), stable.
    dt : float
        ``T`` > 0.
    runs, samples, burn_in : int
        Independent runs, samples kept per run, and leading samples dropped (the
        zero-state transient).
    seed : int

    Returns
    -------
    (float, float)
        The estimate :math:`\widehat{\mathrm{VRF}}_{x_p}/(2T)` and its standard error
        (from the spread of the per-run variances).
    """
    require_stable(gains, "noise bandwidth is unbounded")
    T = float(check_positive("dt", dt))
    z = white_noise((int(runs), int(burn_in) + int(samples)), 1.0, seed)
    xp = track(z, gains, dt=T, outputs=("x_pred",)).x_pred[:, int(burn_in) :]
    per_run = np.mean(xp**2, axis=1)
    est = float(np.mean(per_run)) / (2.0 * T)
    se = float(np.std(per_run, ddof=1) / np.sqrt(len(per_run))) / (2.0 * T)
    return est, se


# --------------------------------------------------------------------------- Tables 1-2
def _xi_of(gains: Gains, rule: str, order: int) -> float:
    """The ``xi`` of a gain set on one of the rules' curves (its alpha)."""
    a = float(gains.alpha)
    if rule == "type1":
        return a
    return (1.0 - a) ** 0.5 if order == 2 else (1.0 - a) ** (1.0 / 3.0)


def table_row(rule, order, bn_hz, alpha_h, beta_h, gamma_h, xi, dt) -> dict:
    r"""One cell of seed 002, Tables 1-2: the printed gains against the rule and the ENBW.

    Parameters
    ----------
    rule : {"type1", "type2"}
        Table 1 (type I) or Table 2 (type II).
    order : {2, 3}
        Alpha-beta or alpha-beta-gamma column.
    bn_hz : float
        The row's nominal ENBW (2, 10 or 20 Hz).
    alpha_h, beta_h, gamma_h, xi : float
        The printed gains (Huang's convention; ``gamma_h = 0`` for alpha-beta) and ``xi``.
    dt : float
        ``T = 1/F_r``.

    Returns
    -------
    dict
        ``enbw_exact`` (Hz, ``inf`` when unstable), ``enbw_closed`` (eq 14 or the
        reconstructed eqs 8-13; NaN when unstable), ``enbw_eq13_printed`` (literal eq 13),
        ``stable_jury`` (exact), ``stable_eq5`` / ``stable_eq7`` (printed criteria),
        ``jury_eq47`` (seed 000, eq 47 value), ``pole_radius``; the rule at the printed
        ``xi`` (``rule_alpha``, ``rule_beta``, ``rule_gamma_h``, ``rule_enbw``) and the
        rule at the nominal ENBW (``xi_nominal`` and ``nominal_alpha``, ``_beta``,
        ``_gamma_h``).
    """
    if rule not in RULES:
        raise AbglibValueError(f"rule must be one of {list(RULES)}, got {rule!r}")
    g = from_huang(alpha_h, beta_h, gamma_h if order == 3 else 0.0)
    stable = bool(is_stable(g))
    out = {
        "rule": rule,
        "order": order,
        "bn_nominal_hz": float(bn_hz),
        "alpha_printed": float(alpha_h),
        "beta_printed": float(beta_h),
        "gamma_h_printed": float(gamma_h) if order == 3 else 0.0,
        "xi_printed": float(xi),
        "stable_jury": stable,
        "stable_jury_steelman": bool(stable_jury_steelman(g)),
        "jury_eq47": float(g.alpha * g.beta + g.alpha * g.gamma / 2 - g.gamma),
        "pole_radius": float(pole_radius(g)),
        "enbw_exact": float(enbw(g, dt)) if stable else np.inf,
        "enbw_closed": np.nan,
        "enbw_eq13_printed": np.nan,
    }
    if order == 3:
        out["stable_eq5"] = bool(stable_huang_eq5(alpha_h, beta_h, gamma_h))
        out["enbw_eq13_printed"] = enbw_huang_eq13_as_printed(alpha_h, beta_h, gamma_h, dt)
        if stable:
            out["enbw_closed"] = float(enbw_huang_eq8_13(alpha_h, beta_h, gamma_h, dt))
    else:
        out["stable_eq5"] = bool(stable_huang_eq7(alpha_h, beta_h))  # eq 7 for alpha-beta
        if stable:
            out["enbw_closed"] = float(enbw_huang_eq14(alpha_h, beta_h, dt))
    r = RULES[rule](xi, order)
    ra, rb, rg = to_huang(r)
    out.update(rule_alpha=ra, rule_beta=rb, rule_gamma_h=rg, rule_enbw=float(enbw(r, dt)))
    n = huang_for_enbw(bn_hz, dt, rule, order)
    na, nb, ng = to_huang(n)
    out.update(
        xi_nominal=_xi_of(n, rule, order),
        nominal_alpha=na,
        nominal_beta=nb,
        nominal_gamma_h=ng,
        nominal_enbw=float(enbw(n, dt)),
    )
    return out
