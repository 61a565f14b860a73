"""Chapters 2-6 of seed 004 on the reconstructed antenna: algebra checks, Fig. I.4
(Taylor prediction), Figs I.5-I.7 (time series) and Figs I.8-I.9 (frequency sweep), all
with exactly known states (no quantiser, so every number here is deterministic)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import scipy.linalg

from .closedloop import simulate, steady_state_amplitudes
from .kalman import extended_model, kalman_gains
from .objectmodel import sine_state, taylor_model, taylor_predict
from .preview import preview_gain, preview_series, stein_solve

__all__ = [
    "PREVIEW_STEPS",
    "checks_table",
    "hamiltonian_eigenvalues",
    "log_grid",
    "omega_sweep_table",
    "preview_steps",
    "taylor_table",
    "tracking_table",
    "wrap_phase",
]

#: Preview lengths for the convergence check of the finite-preview gain (eq 2.37), in steps
#: of the nominal dt = 2 pi / 10 (scaled with the sample rate: the same preview *time*).
PREVIEW_STEPS = (50, 100, 200, 400, 800, 1600)


def preview_steps(dt: float) -> list[int]:
    """:data:`PREVIEW_STEPS` at sample interval ``dt`` (the same preview horizons in time)."""
    return [int(round(n * (2 * np.pi / 10) / dt)) for n in PREVIEW_STEPS]


def log_grid(g) -> np.ndarray:
    """``{start, stop, n}`` of the config as a geometric grid."""
    return np.geomspace(float(g["start"]), float(g["stop"]), int(g["n"]))


def hamiltonian_eigenvalues(ctrl, q: float, r: float) -> np.ndarray:
    """Eigenvalues of the system matrix 2.10 of eqs 2.8-2.9 (symplectic form)."""
    a_inv_t = np.linalg.inv(ctrl.A).T
    brb = ctrl.B @ ctrl.B.T / r
    qx = ctrl.C.T @ ctrl.C * q
    ham = np.block([[ctrl.A + brb @ a_inv_t @ qx, -brb @ a_inv_t], [-a_inv_t @ qx, a_inv_t]])
    return np.linalg.eigvals(ham)


def checks_table(ctrl, q: float, r: float, v_v) -> pd.DataFrame:
    """Independent routes for the algebra of ch. 2, 4, 7 (Riccati 2.12, Stein E.4, 2.37, 7.15)."""
    tm, c = ctrl.tm, ctrl
    rows = []
    p_are = scipy.linalg.solve_discrete_are(c.A, c.B, c.C.T @ [[q]] @ c.C, [[r]])
    rows.append(
        (
            "Riccati eq 2.12: iteration vs scipy solve_discrete_are",
            np.max(np.abs(tm.P - p_are)) / np.max(np.abs(p_are)),
        )
    )
    rows.append(("spectral radius of A_g (eq 2.16)", np.max(np.abs(np.linalg.eigvals(tm.Ag)))))
    rows.append(("||A_g||_2 (eq 2.32 assumes < 1)", np.linalg.norm(tm.Ag, 2)))
    at, ct, gt = taylor_model(5, ctrl.dt)
    rhs = tm.Cg @ ct @ at
    x1 = stein_solve(tm.Ag, at, rhs, "kron")
    x2 = stein_solve(tm.Ag, at, rhs, "sylvester")
    rows.append(
        (
            "Stein eq E.4 (order 5): Kronecker vs Bartels-Stewart, rel. diff",
            np.max(np.abs(x1 - x2)) / np.max(np.abs(x1)),
        )
    )
    kt = preview_gain(tm, at, ct)
    for n in preview_steps(ctrl.dt):
        rows.append(
            (
                f"preview gain: |Kv X_n - Kv X| / |Kv X|, n = {n} steps (eq 2.37)",
                np.max(np.abs(preview_series(tm, at, ct, n) - kt)) / np.max(np.abs(kt)),
            )
        )
    em = extended_model(c.A, c.B, c.C, at, ct, gt)
    kg = kalman_gains(em, 5e-10, v_v)
    n = em.n_antenna
    dual = scipy.linalg.solve_discrete_are(
        at.T, em.M[1:2, n:].T, 5e-10 * gt @ gt.T, np.atleast_2d(v_v[1, 1])
    )
    rows.append(
        (
            "Kalman eq 7.15 (order 5): object block vs dual DARE, rel. diff",
            np.max(np.abs(kg.Q[n:, n:] - dual)) / np.max(np.abs(dual)),
        )
    )
    rows.append(
        (
            "Kalman eq 7.15: largest |entry| of the antenna block (w = 0)",
            np.max(np.abs(kg.Q[:n, :n])),
        )
    )
    df = pd.DataFrame([(k, float(v)) for k, v in rows], columns=["check", "value"])
    # the independent-route differences are round-off (the default OpenBLAS kernel and
    # OPENBLAS_CORETYPE=Prescott give 2e-15 vs 5e-15, 5.4e-14 vs 5.2e-14, ...; the Kalman
    # iteration's remainder 2.9e-12 moves by 0.6 %): written as the bound; the other values
    # (radii, norms, the preview differences of the short previews) hold 6 digits
    df.attrs["precision"] = {"value": "<1e-10:6"}
    return df


def taylor_table(t) -> pd.DataFrame:
    """Fig. I.4: ``z_i = sin(i dt)`` predicted from ``i = start`` by the Taylor model (eq 3.6)."""
    dt, i0 = float(t["dt"]), int(t["start"])
    i = np.arange(i0, int(t["stop"]) + 1)
    k = i - i0
    x0 = sine_state(1.0, 1.0, i0 * dt, max(t["orders"]))
    out = {"i": i, "z": np.sin(i * dt)}
    for q in t["orders"]:
        at, ct, _ = taylor_model(q, dt)
        pred = taylor_predict(x0, q, dt, k)
        xs, model = x0[: q + 1].copy(), []
        for _k in k:  # the model route: C_t A_t^k x_t0
            model.append((ct @ xs)[0])
            xs = at @ xs
        if not np.allclose(pred, model, rtol=1e-12, atol=1e-12):
            raise RuntimeError(f"Taylor model and closed form differ, order {q}")
        out[f"order{q}"] = pred
    return pd.DataFrame(out)


def tracking_table(params, ctrl, amp, omega, ts) -> pd.DataFrame:
    """Figs I.5-I.7: tracking error, known vs predicted output, normal track."""
    n = int(np.ceil(float(ts["duration"]) / ctrl.dt))
    frames = []
    for mode, q in [("known", None)] + [("predicted", q) for q in ts["orders"]]:
        r = simulate(params, ctrl, amplitude=amp, omega=omega, n_steps=n, mode=mode, order=q)
        case = mode if q is None else f"order {q}"
        frames.append(pd.DataFrame({"case": case, **{k: r[k] for k in "tzyeu"}}))
    df = pd.concat(frames, ignore_index=True)
    # y and e = y - z carry an absolute round-off of about 1e-15 (the BLAS kernel's
    # matrix-vector products; 1.1e-15 between the default kernel and Prescott), which is
    # most of the value where y or e is tiny (the start, the zero crossings of e): written
    # with 5 digits, and as the bound below 1e-10. u, a sum of feedback terms much larger
    # than itself (|u| ~ 1e-3 against |z| = 1), carries ~1e-13 the same way (the default
    # kernel and Prescott wrote 2 of its ~3000 values differently at 10 digits): so too
    df.attrs["precision"] = {"y": TRACK_PRECISION, "e": TRACK_PRECISION, "u": TRACK_PRECISION}
    return df


#: Written precision of the time series' y and e (see :func:`tracking_table`).
TRACK_PRECISION = "<1e-10:5"


def omega_sweep_table(controllers, r: float, sw) -> pd.DataFrame:
    """Figs I.8-I.9: exact steady-state amplitudes of e and u against omega, amplitude 1.

    ``controllers`` maps Q to the controller designed with it; the printed omega = 1 end
    of the range is always on the grid.
    """
    rows = []
    grid = np.union1d(log_grid(sw), [1.0])
    for q, ctrl in controllers.items():
        for w in grid:
            for mode, order in [("known", None)] + [("predicted", o) for o in sw["orders"]]:
                a = steady_state_amplitudes(ctrl, w, 1.0, mode, order)
                rows.append(
                    {
                        "q_over_r": q / r,
                        "omega": float(w),
                        "case": "known" if order is None else f"order {order}",
                        "e_max": a["e"],
                        "u_max": a["u"],
                        "phase_e": a["phase_e"],
                    }
                )
    df = pd.DataFrame(rows)
    # e is the small difference y - z (|z| = 1): its round-off is absolute, about 1e-14
    # (default OpenBLAS kernel vs OPENBLAS_CORETYPE=Prescott: 9e-15 at e = 1.2e-8), so e_max
    # holds 4 digits above 1e-10 and is round-off below; its phase is then undefined
    small = df["e_max"] < E_ROUNDOFF
    df["phase_e"] = [
        np.nan if sm else wrap_phase(p) for sm, p in zip(small, df["phase_e"], strict=True)
    ]
    # u_max ~ 1e-3 carries the ~1e-13 absolute round-off of u (tracking_table; 10 digits
    # differed between the two kernels in one row): U_DIGITS hold
    df.attrs["precision"] = {
        "e_max": f"<{E_ROUNDOFF:g}:4",
        "phase_e": PHASE_DIGITS,
        "u_max": U_DIGITS,
    }
    return df


#: Bound below which the steady-state error amplitude e is written as round-off
#: (``<1e-10``): above it e holds 4 digits (see :func:`omega_sweep_table`).
E_ROUNDOFF = 1e-10
#: Absolute error of e itself: about 1e-14 (the default OpenBLAS kernel vs
#: ``OPENBLAS_CORETYPE=Prescott``: 9e-15 at e = 1.2e-8).
E_ABS_ERROR = 1e-14
#: Significant digits the phase of e holds (its error is about 1e-14 / e_max rad, < 1e-4).
PHASE_DIGITS = 4
#: Significant digits the amplitude of u holds (absolute round-off ~1e-13 at ~1e-3).
U_DIGITS = 6


def wrap_phase(phase: float, digits: int = PHASE_DIGITS) -> float:
    """``phase`` (rad, in [-pi, pi]) with the branch cut handled at the written precision.

    A phase that rounds to -pi at ``digits - 1`` decimals is moved up by 2 pi, so that
    -pi + 1e-9 and pi - 1e-9 (the same angle, on either side of the cut by round-off) are
    written alike: the result lies in (-pi, pi] once rounded.
    """
    d = digits - 1
    if round(float(phase), d) <= -round(np.pi, d):
        return float(phase) + 2.0 * np.pi
    return float(phase)
