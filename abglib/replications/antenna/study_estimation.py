"""Chapter 8 of seed 004: control with Kalman estimation and quantised measurements.

Every maximum under quantisation is taken as the median over an ensemble of object phases
(:mod:`.ensemble`): one run's maximum is chaotic, the median is not. Printed V_w values
(``5 * 10^k``) are handed to the filter times ``kalman.vw_scale`` (the convention by which
the report's V_w enters its filter is not in the scan).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from .ensemble import phase_grid, simulate_phases

__all__ = [
    "RunStats",
    "kalman_runs_table",
    "kalman_sweep_table",
    "n_steps_for",
    "optimum",
    "run_stats",
    "vw_search_table",
]


def n_steps_for(omega: float, dt: float, sim) -> int:
    """Steps of a run: the transient plus ``periods`` periods, at least ``min_duration``."""
    span = max(float(sim["min_duration"]), float(sim["periods"]) * 2 * np.pi / omega)
    return int(np.ceil((float(sim["transient"]) + span) / dt))


@dataclass(frozen=True)
class RunStats:
    """Per-phase maxima after the transient of one ensemble of closed-loop runs."""

    e: np.ndarray  # (n_phases,) max |e|
    u: np.ndarray  # (n_phases,) max |u|
    est: np.ndarray  # (n_phases, p) max |estimated - true| per derivative
    run: dict | None = None  # the raw runs (kept when asked for traces)

    @property
    def e_med(self) -> float:
        return float(np.median(self.e))

    @property
    def u_med(self) -> float:
        return float(np.median(self.u))

    def est_med(self, j: int) -> float:
        return float(np.median(self.est[:, j]))


def run_stats(params, ctrl, *, transient, keep=False, **kw) -> RunStats:
    """:func:`.ensemble.simulate_phases` reduced to the per-phase maxima after ``transient``."""
    with np.errstate(over="ignore", invalid="ignore"):
        r = simulate_phases(params, ctrl, **kw)
        # t is increasing: the steps t >= transient are a tail (a view, not a copy)
        sel = slice(int(np.searchsorted(r["t"], transient, side="left")), None)
        e = np.max(np.abs(r["e"][:, sel]), axis=1)
        u = np.max(np.abs(r["u"][:, sel]), axis=1)
        est = np.max(np.abs(r["xt_err"][:, :, sel]), axis=2)
    bad = ~np.isfinite(e)
    e[bad], u[bad] = np.inf, np.inf
    return RunStats(e, u, est, r if keep else None)


def vw_search_table(stats, orders, exponents) -> pd.DataFrame:
    """Normal track: median max errors against printed V_w = 5 x 10^k, per model order.

    ``stats(order, v_w)`` gives the :class:`RunStats` of the normal track.
    """
    rows = []
    for order in orders:
        for k in range(int(exponents[0]), int(exponents[1]) + 1):
            vw = 5.0 * 10.0**k
            s = stats(order, vw)
            row = {
                "order": order,
                "v_w": vw,
                "e_max": s.e_med,
                "u_max": s.u_med,
                "e_max_phase0": float(s.e[0]),
            }
            for j in range(order + 1):
                row[f"est_err_d{j}"] = s.est_med(j)
            rows.append(row)
    return pd.DataFrame(rows)


def optimum(vw: pd.DataFrame, order, key="e_max") -> float:
    """Printed V_w with the smallest (median) ``key`` for one order."""
    d = vw[vw["order"] == order]
    return float(d.loc[d[key].idxmin(), "v_w"])


def kalman_runs_table(run, settings5, amplitudes) -> pd.DataFrame:
    """Figs I.10-I.13 (fifth order, three V_w) and I.17-I.19 (optimum, three amplitudes):
    the traces of the printed track (phase 0). ``run(v_w, amplitude)`` gives the raw runs."""
    frames = []
    labels = ("model emphasis", "optimal", "measurement emphasis")
    for label, vw in zip(labels, settings5, strict=True):
        r = run(vw, None)
        d = {
            "figure": "I.10-I.13",
            "case": f"{label}, V_w = {vw:.0e}",
            "t": r["t"],
            "e": r["e"][0],
            "u": r["u"][0],
        }
        for j in range(r["xt_err"].shape[1]):
            d[f"est_err_d{j}"] = r["xt_err"][0, j]
        frames.append(pd.DataFrame(d))
    for amp in amplitudes:
        r = run(settings5[1], float(amp))
        frames.append(
            pd.DataFrame(
                {
                    "figure": "I.17-I.19",
                    "case": f"amplitude {amp:g}",
                    "t": r["t"],
                    "e": r["e"][0],
                    "u": r["u"][0],
                }
            )
        )
    return pd.concat(frames, ignore_index=True)


def kalman_sweep_table(stats, figs, grid) -> pd.DataFrame:
    """Figs I.14-I.16: median max |e| and |u| against omega (amplitude 10).

    ``figs`` lists ``(figure, order, weight_key, q_over_r, [v_w, ...])``;
    ``stats(order, v_w, weight_key, omega)`` gives the :class:`RunStats`.
    """
    rows = []
    for fig, order, wkey, qr, vws in figs:
        for vw in vws:
            for w in grid:
                s = stats(order, vw, wkey, float(w))
                rows.append(
                    {
                        "figure": fig,
                        "order": order,
                        "q_over_r": qr,
                        "v_w": vw,
                        "omega": float(w),
                        "e_max": s.e_med,
                        "u_max": s.u_med,
                        "e_q25": float(np.quantile(s.e, 0.25)),
                        "e_q75": float(np.quantile(s.e, 0.75)),
                    }
                )
    return pd.DataFrame(rows)


def phases_of(n: int) -> np.ndarray:
    """The phase ensemble of ``n`` members (:func:`.ensemble.phase_grid`)."""
    return phase_grid(n)
