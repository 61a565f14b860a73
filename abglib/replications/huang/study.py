r"""Huang, Yang and Ma, "Research on fixed-gain range tracking loop" (seed 002).

The science specific to this paper; everything general (gains, ENBW routes, stability,
lags) is in :mod:`abglib.design`, :mod:`abglib.analysis` and :mod:`abglib.conventions`.
Huang et al. write the acceleration gain as ``gamma_H = gamma / 2`` (their eqs 1, 3-4);
every function taking ``*_h`` gains takes them in that convention and converts through
:func:`abglib.conventions.from_huang`.

``C_LIGHT``                   speed of light (m/s)
``thermal_sigma``             the paper's thermal-noise range error (printed, or Barton's form)
``bandwidth_for_sigma``       its inverse: the ENBW at which the error reaches a given sigma
``measurement_sigma``         the per-pulse range noise that makes the printed formula exact
``enbw_huang_eq13_as_printed``  eq 13 read literally (no reconstruction), in Hz
``enbw_eq8_two_sided``        the first form of eq 8 as printed (whole band), by quadrature
``run_eqs_1_2``               the loop of eqs 1-2, transcribed literally (with the T^2/2 choice)
``bandwidth_curves``          ``B_n T`` against ``xi`` (Figures 2-3), exact and closed forms
``enbw_monte_carlo``          ENBW estimated from a noise-driven loop (seeded), with its SE
``table_row``                 one cell of Tables 1-2: what the printed gains really are
``simulate_range_track``      the range-track simulation of Figures 5-7 (seeded)
``error_metrics``             lag, initial error, peak, settling and overshoot of a run
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ..._checks import AbglibValueError, check_finite, check_positive, scalar_or_array
from ...analysis import (
    enbw,
    enbw_huang_eq8_13,
    enbw_huang_eq14,
    is_stable,
    pole_radius,
    stable_huang_eq5,
    stable_jury_steelman,
)
from ...analysis._enbw import _huang_k
from ...conventions import from_huang, to_huang
from ...design import huang_for_enbw, huang_type1, huang_type2
from ...engine import track
from ...gains import Gains
from ...simulate import polynomial_track, sample_times, white_noise

__all__ = [
    "C_LIGHT",
    "RULES",
    "bandwidth_curves",
    "bandwidth_for_sigma",
    "enbw_eq8_two_sided",
    "enbw_huang_eq13_as_printed",
    "enbw_monte_carlo",
    "error_metrics",
    "measurement_sigma",
    "run_eqs_1_2",
    "simulate_range_track",
    "table_row",
    "thermal_sigma",
]

#: Speed of light in vacuum, m/s (the paper's "c is light velocity").
C_LIGHT = 299_792_458.0
#: The paper's two gain-selection rules (seed 002, "Loop parameters selecting").
RULES = {"type1": huang_type1, "type2": huang_type2}
_FORMS = ("printed", "barton")


def _snr(snr_db):
    return 10.0 ** (check_finite("snr_db", snr_db) / 10.0)


def thermal_sigma(bn_hz, fr_hz, tau_s, snr_db, k=1.4, form="printed"):
    r"""Thermal-noise range tracking error in metres (seed 002, "Tracking errors").

    Parameters
    ----------
    bn_hz : float or array (...)
        Equivalent noise bandwidth ``B_n`` of the range loop, Hz, > 0.
    fr_hz : float
        Pulse repetition (sampling) frequency ``F_r = 1/T``, Hz.
    tau_s : float
        Pulse width ``tau``, s.
    snr_db : float
        Single-pulse signal-to-noise ratio ``(S/N)_0`` in dB (power ratio).
    k : float, default 1.4
        Normalised slope of the range discriminator.
    form : {"printed", "barton"}, default "printed"
        ``"printed"``: the paper's formula; ``"barton"``: the same with the
        ``2E/N_0`` of Barton's range-error formula (a factor ``sqrt 2`` smaller).

    Returns
    -------
    float or array (...)
        ``sigma`` in m.

    Notes
    -----
    Seed 002 (unnumbered, section "Tracking errors"):

    .. math:: \sigma = \frac{\tau c}{2k\sqrt{(S/N)_0\,(F_r/B_n)}},

    the range extent of the pulse ``tau c / 2`` over the discriminator slope and the
    square root of the signal-to-noise ratio integrated over ``F_r / B_n`` pulses.
    Barton's form writes ``2 E/N_0 = 2 (S/N)_0 F_r / B_n`` under the root; it is the
    printed formula with ``B_n`` replaced by ``B_n / 2``, i.e. the printed formula
    evaluated at the *two-sided* bandwidth of eq 8.
    """
    if form not in _FORMS:
        raise AbglibValueError(f"form must be one of {', '.join(map(repr, _FORMS))}, got {form!r}")
    bn = check_positive("bn_hz", bn_hz)
    fr = check_positive("fr_hz", fr_hz)
    tau = check_positive("tau_s", tau_s)
    kk = check_positive("k", k)
    factor = 1.0 if form == "printed" else 2.0
    return scalar_or_array(tau * C_LIGHT / (2.0 * kk * np.sqrt(factor * _snr(snr_db) * fr / bn)))


def bandwidth_for_sigma(sigma_m, fr_hz, tau_s, snr_db, k=1.4, form="printed"):
    r"""The ENBW (Hz) at which :func:`thermal_sigma` equals ``sigma_m``.

    Notes
    -----
    Inverting the formula of :func:`thermal_sigma`:
    :math:`B_n = f\,(S/N)_0 F_r\,(2k\sigma/(\tau c))^2`, ``f = 1`` (printed) or 2 (Barton).
    The error grows with ``B_n``, so ``sigma <= sigma_m`` needs ``B_n <=`` this value
    (seed 002, "Assuming the sigma <= 7m, the ENBW should be under 40Hz").
    """
    if form not in _FORMS:
        raise AbglibValueError(f"form must be one of {', '.join(map(repr, _FORMS))}, got {form!r}")
    s = check_positive("sigma_m", sigma_m)
    fr = check_positive("fr_hz", fr_hz)
    tau = check_positive("tau_s", tau_s)
    kk = check_positive("k", k)
    factor = 1.0 if form == "printed" else 2.0
    return scalar_or_array(factor * _snr(snr_db) * fr * (2.0 * kk * s / (tau * C_LIGHT)) ** 2)


def measurement_sigma(tau_s, snr_db, k=1.4):
    r"""Per-pulse range noise (m) for which the printed thermal error is exact.

    Returns
    -------
    float
        :math:`\sigma_m = \tau c / (2k\sqrt{2 (S/N)_0})` (Barton's single-pulse error).

    Notes
    -----
    White measurement noise of standard deviation ``sigma_m`` leaves a predicted-position
    error of variance :math:`\sigma_m^2\,\mathrm{VRF}_{x_p} = \sigma_m^2\, 2 B_n T`
    (:func:`abglib.analysis.enbw`, one-sided). With this ``sigma_m`` that is exactly
    :func:`thermal_sigma` ``(B_n, 1/T, ...)`` as printed: the printed formula is the
    single-pulse error of Barton's ``2E/N_0`` form smoothed by a loop of one-sided
    bandwidth ``B_n``.
    """
    return thermal_sigma(0.5, 1.0, tau_s, snr_db, k, form="printed")


# --------------------------------------------------------------------------- eq 13
def enbw_huang_eq13_as_printed(alpha_h, beta_h, gamma_h, dt):
    r"""Seed 002, eq 13 read literally, in Hz (no reconstruction).

    Parameters
    ----------
    alpha_h, beta_h, gamma_h : float
        Gains in Huang's convention (``gamma_h > 0``).
    dt : float
        Sample interval ``T`` > 0.

    Returns
    -------
    float
        :math:`B_n = \frac{1}{2TK_5}\,\frac{K_0\sqrt{K_2}\,b + K_1\sqrt{K_2} + K_2 a}{c}`
        with :math:`b^2 = K_4 + 2\alpha\sqrt{K_2}`, :math:`a^2 = K_3 + 2b`,
        :math:`ab = \sqrt{K_2} + c` exactly as printed (``alpha`` the gain, ``K_2``
        the denominator constant of eqs 11-12) and ``K0..K5`` of eq 11.

    Notes
    -----
    The correct result is :func:`abglib.analysis.enbw_huang_eq8_13` (three corrections:
    the constant ``K2/K5``, the Hurwitz coefficient ``a`` in place of the gain ``alpha``
    under ``b^2``, and ``c`` multiplied by ``sqrt K2``). Read literally, the printed
    formula gives values of the order of the paper's nominal bandwidths for the printed
    type II alpha-beta-gamma gains, where the exact ENBW is 100-340 Hz.
    """
    a, b, g = (
        float(check_finite(n, v))
        for n, v in (("alpha_h", alpha_h), ("beta_h", beta_h), ("gamma_h", gamma_h))
    )
    T = float(check_positive("dt", dt))
    if g <= 0.0:
        raise AbglibValueError(f"gamma_h must be > 0 (eq 13 is for alpha-beta-gamma), got {g!r}")
    K0, K1, K2, K3, K4, K5 = _huang_k(a, b, g)
    s = np.sqrt(K2)
    b2 = K4 + 2.0 * a * s
    if b2 <= 0.0:
        raise AbglibValueError(f"eq 13 as printed has no real b for gains ({a}, {b}, {g})")
    bb = np.sqrt(b2)
    a2 = K3 + 2.0 * bb
    if a2 <= 0.0:
        raise AbglibValueError(f"eq 13 as printed has no real a for gains ({a}, {b}, {g})")
    aa = np.sqrt(a2)
    c = aa * bb - s
    return float((K0 * s * bb + K1 * s + K2 * aa) / c / (2.0 * T * K5))


def enbw_eq8_two_sided(gains: Gains, dt=1.0) -> float:
    r"""The first form of seed 002, eq 8 as printed, in Hz: the whole-band integral.

    Parameters
    ----------
    gains : Gains
        Canonical gains (scalar), stable.
    dt : float, default 1.0
        Sample interval ``T`` > 0.

    Returns
    -------
    float
        :math:`\frac{1}{2\pi}\int_{-\pi/T}^{\pi/T}|H(e^{j\omega T})|^2\,d\omega`
        (``H = X_p/X``; the printed infinite limits are the Nyquist band of a sampled
        loop), by adaptive quadrature of :func:`abglib.analysis.frequency_response`.

    Notes
    -----
    ``|H|^2`` is even in ``omega``, so this is twice the one-sided
    :func:`abglib.analysis.enbw` of eqs 9-14: eq 8 as printed is the two-sided
    bandwidth.
    """
    import scipy.integrate

    from ...analysis import frequency_response, require_stable

    require_stable(gains, "noise bandwidth is unbounded")
    T = float(check_positive("dt", dt))

    def f(x):
        return float(np.abs(frequency_response(gains, "x_pred", np.asarray(x))) ** 2)

    edges = np.concatenate([-np.geomspace(np.pi, 1e-5, 30), [0.0], np.geomspace(1e-5, np.pi, 30)])
    total = sum(
        scipy.integrate.quad(f, lo, hi, limit=200, epsrel=1e-11, epsabs=0.0)[0]
        for lo, hi in zip(edges[:-1], edges[1:], strict=True)
    )
    return total / (2.0 * np.pi * T)


def run_eqs_1_2(z, alpha_h, beta_h, gamma_h, dt, half=True) -> np.ndarray:
    r"""The loop of seed 002, eqs 1-2, transcribed literally; returns ``R_p`` (array (n,)).

    Parameters
    ----------
    z : array (n,)
        Measured ranges ``R_m(kT)``.
    alpha_h, beta_h, gamma_h : float
        Gains in Huang's convention.
    dt : float
        ``T``.
    half : bool, default True
        True: predict with ``T^2 R''_s / 2`` (what eqs 3-4 assume); False: with
        ``T^2 R''_s`` exactly as eq 2 prints it.

    Notes
    -----
    Eq 1: ``R_s = R_p + alpha r``, ``R'_s = R'_p + (beta/T) r``,
    ``R''_s = R''_p + (2 gamma_H / T^2) r``, ``r = R_m - R_p``. Eq 2:
    ``R_p = R_s + T R'_s + c T^2 R''_s`` (``c = 1/2`` or 1), ``R'_p = R'_s + T R''_s``
    (eq 2 prints ``T R'_s``, a dimensional slip), ``R''_p = R''_s``. State zero before
    the first sample.
    """
    z = check_finite("z", z)
    T = float(check_positive("dt", dt))
    c = 0.5 if half else 1.0
    rs = vs = as_ = 0.0
    out = np.empty(z.shape)
    for k, zk in enumerate(z):
        rp = rs + T * vs + c * T * T * as_
        vp = vs + T * as_
        ap = as_
        out[k] = rp
        r = zk - rp
        rs = rp + alpha_h * r
        vs = vp + beta_h / T * r
        as_ = ap + 2.0 * gamma_h / (T * T) * r
    return out


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
    from ...analysis import require_stable

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
        out["stable_eq5"] = bool((alpha_h > -beta_h) & (beta_h > 0))  # eq 7
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


# --------------------------------------------------------------------------- simulation
def simulate_range_track(
    trackers: dict, dt, n, accel, jerk, sigma_m, seed, r0=0.0, v0=0.0
) -> pd.DataFrame:
    r"""Range track of seed 002's simulation: constant jerk, Gaussian noise, several loops.

    Parameters
    ----------
    trackers : dict
        ``{name: Gains}`` (canonical gains).
    dt : float
        ``T = 1/F_r`` (s).
    n : int
        Number of samples.
    accel, jerk : float
        Initial target acceleration ``A`` (m/s^2) and its rate ``B`` (m/s^3).
    sigma_m : float
        Standard deviation of the white Gaussian range noise per pulse (m).
    seed : int
        Seed of the noise (the same noise for every tracker).
    r0, v0 : float
        Initial range (m) and range rate (m/s).

    Returns
    -------
    DataFrame
        Columns ``t`` (s), ``truth`` (m), ``z`` (m) and, per tracker ``name``,
        ``err_<name>`` = truth - predicted position with noise and ``lag_<name>`` the
        same without noise (m).

    Notes
    -----
    Truth :math:`R(t) = r_0 + v_0 t + A t^2/2 + B t^3/6` (seed 002: "the target's
    acceleration is A, and the acceleration changing rate is B"). Each loop starts from
    the true range and range rate and zero acceleration (an explicit initial state of
    :func:`abglib.track`), so its transient is the response to the unknown acceleration.
    The error is that of the predicted position, the output of the paper's ``H(z)``.
    """
    T = float(check_positive("dt", dt))
    t = sample_times(int(n), T)
    truth = polynomial_track(t, r0, v0, accel, jerk)
    z = truth + white_noise(t.shape, sigma_m, seed)
    # ``track``'s explicit init is the state one sample before t = 0, so that its first
    # prediction is the true range r0 with the true rate v0
    init = np.array([r0 - v0 * T, v0, 0.0])
    out = {"t": t, "truth": truth, "z": z}
    for name, g in trackers.items():
        noisy = track(z, g, dt=T, init=init, outputs=("x_pred",)).x_pred
        clean = track(truth, g, dt=T, init=init, outputs=("x_pred",)).x_pred
        out[f"err_{name}"] = truth - noisy
        out[f"lag_{name}"] = truth - clean
    return pd.DataFrame(out)


def error_metrics(t, lag, err, gate_m, settle_fraction=0.05) -> dict:
    r"""Summary of one simulated run (see :func:`simulate_range_track`).

    Parameters
    ----------
    t, lag, err : array (n,)
        Time (s), noise-free error and noisy error (m) of one loop.
    gate_m : float
        Half-width of the range discriminator's linear region (m): a loop whose error
        leaves it has lost the track.
    settle_fraction : float, default 0.05
        Settling band, a fraction of the peak noise-free error.

    Returns
    -------
    dict
        ``peak_lag`` (max ``|lag|``), ``overshoot`` (``max(0, -min(lag) / max(lag))``, how far
        the error swings past zero relative to its peak), ``settle_s`` (last time the
        noise-free error is outside the band around its final drift line),
        ``lag_intercept`` (the settled noise-free error extrapolated linearly to
        ``t = 0``: the lag the loop would have if it had followed the initial
        acceleration from the start), ``lag_end`` (noise-free error at the end),
        ``rms_settled`` (RMS of the noisy error over the second half), ``peak_err``
        (max ``|err|``) and ``lost`` (``peak_err > gate_m``).
    """
    t = np.asarray(t, float)
    lag = np.asarray(lag, float)
    err = np.asarray(err, float)
    half = len(t) // 2
    slope, icpt = np.polyfit(t[half:], lag[half:], 1)
    drift = icpt + slope * t
    peak = float(np.max(np.abs(lag)))
    outside = np.nonzero(np.abs(lag - drift) > settle_fraction * max(peak, 1e-300))[0]
    top = float(np.max(lag))
    return {
        "peak_lag": peak,
        "overshoot": max(0.0, float(-np.min(lag) / top)) if top > 0 else np.nan,
        "settle_s": float(t[outside[-1]]) if outside.size else 0.0,
        "lag_intercept": float(icpt),
        "lag_slope": float(slope),
        "lag_end": float(lag[-1]),
        "rms_settled": float(np.sqrt(np.mean(err[half:] ** 2))),
        "peak_err": float(np.max(np.abs(err))),
        "lost": bool(np.max(np.abs(err)) > gate_m),
    }
