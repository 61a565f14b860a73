"""Appendix H of seed 004: controller and filter designed with one parameter off by a factor.

Stability from the spectral radius of the linear closed loop (:mod:`.robustness`); the
maximum tracking error of a long run (Figs I.20-I.22) as the median over a few object
phases (the loop is quantised, :mod:`.ensemble`).
"""

from __future__ import annotations

import numpy as np

from .closedloop import design_controller
from .ensemble import phase_grid
from .robustness import stable_interval
from .study_estimation import run_stats
from .study_exact import log_grid

__all__ = [
    "APPH_PARAMETERS",
    "design_error_rows",
    "edge_grid",
    "factor_grid",
    "radius_rows",
    "stability_row",
]

#: The parameters app. H varies, in the order of its text.
APPH_PARAMETERS = ("beta_d", "beta_a", "p_a", "p_f", "beta_f", "kappa")


def factor_grid(rb, params, name) -> np.ndarray:
    """Design factors: a coarse and a fine log grid and 1 (p_a kept below 1)."""
    grid = np.unique(np.concatenate([log_grid(rb["factors"]), log_grid(rb["fine"]), [1.0]]))
    return grid[grid * getattr(params, name) < 1.0] if name == "p_a" else grid


#: Points the stability edge search adds to p_a's grid between its last factor and the
#: admissible limit 1 / p_a (a design p_a >= 1 leaves the driver no inertia, p_d = 1 - p_a).
EDGE_POINTS_P_A = 10


def edge_grid(rb, params, name) -> np.ndarray:
    """The design factors searched for the stability edges: :func:`factor_grid`, and for
    p_a also :data:`EDGE_POINTS_P_A` evenly spaced factors up to (not at) the admissible
    limit 1 / p_a. factor_grid stops p_a at the fine grid's 1.05, where the loop of some
    plausible models is still stable (its edge there is near 1.07, default config): without
    them the edge was only a bound at those models (v0.4.5 had "explained" the printed 1.005
    there as a misprint of the bound 1.05; docs/releases.md)."""
    grid = factor_grid(rb, params, name)
    if name != "p_a":
        return grid
    limit = 1.0 / float(params.p_a)
    extra = np.linspace(grid.max(), limit, EDGE_POINTS_P_A + 2)[1:-1]
    return np.unique(np.concatenate([grid, extra]))


def radius_rows(s, name) -> list[dict]:
    """Closed-loop spectral radius of every design factor of one parameter (``s``: the study)."""
    tol = float(s.cfg["robustness"]["radius_tolerance"])
    return [
        {
            "parameter": name,
            "factor": float(f),
            "spectral_radius": (r := s.radius(name, f)),
            "stable": bool(r <= 1.0 + tol),
        }
        for f in factor_grid(s.cfg["robustness"], s.params, name)
    ]


def design_error_rows(s, name) -> list[dict]:
    """:func:`radius_rows` and the median long-run max |e| of every factor (Figs I.20-I.22)."""
    rb = s.cfg["robustness"]
    n = int(np.ceil(float(rb["duration"]) / s.dt))
    rows = []
    for row in radius_rows(s, name):
        ctrl = design_controller(s.params.scaled(name, row["factor"]), s.dt, s.q, s.r)
        st = run_stats(
            s.params,
            ctrl,
            transient=s.transient,
            amplitude=s.amp,
            omega=s.omega,
            n_steps=n,
            phases=phase_grid(int(rb["phases"])),
            mode="kalman",
            order=5,
            v_w=s.vw_filter(s.vw_opt5),
            v_v=s.vv,
            resolution=s.res,
        )
        rows.append({**row, "e_max": st.e_med})
    return rows


def stability_row(s, name) -> dict:
    """Edges of the stable factor interval around 1 (nan: stable to the end of the grid,
    :func:`edge_grid`)."""
    rb = s.cfg["robustness"]
    g = edge_grid(rb, s.params, name)
    lo, hi = stable_interval(
        s.params, name, s.dt, s.q, s.r, 5, s.vw_filter(s.vw_opt5), s.vv, g,
        float(rb["radius_tolerance"]), radius=lambda f: s.radius(name, f),
    )  # fmt: skip
    return {
        "parameter": name,
        "lower": lo,
        "upper": hi,
        "grid_min": float(g.min()),
        "grid_max": float(g.max()),
    }
