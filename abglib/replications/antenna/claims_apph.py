"""Claims of appendix H of seed 004 (design-parameter errors, Figs I.20-I.22)."""

from __future__ import annotations

import numpy as np

from .._claims import Result
from ._claimset import CLAIMS, EST

__all__: list[str] = []

EDGE_NOTE = "linear closed loop (quantisation left out), spectral radius > 1 + tol"


@CLAIMS.claim("appH.nominal_err", depends_on=EST)
def _nominal(s):
    e = s.long_run.e_med
    return Result(
        e,
        f"long run ({s.cfg['robustness']['duration']:g} time units) at the optimal "
        "settings, median over the object phases of the run's max |e|",
    )


EDGES = {
    "appH.beta_d_upper": ("beta_d", "upper"),
    "appH.beta_a_lower": ("beta_a", "lower"),
    "appH.beta_a_upper": ("beta_a", "upper"),
    "appH.p_a_lower": ("p_a", "lower"),
    "appH.p_a_upper": ("p_a", "upper"),
}


#: Significant digits a stability edge holds (located to 1e-6 relative).
EDGE_DIGITS = 5


@CLAIMS.family(
    r"appH\.(beta_d_upper|beta_a_lower|beta_a_upper|p_a_lower|p_a_upper)", depends_on=EST
)
def _edge(s, key):
    name, side = EDGES[key]
    row = s.stability_of(name)
    v = float(row[side])
    if np.isnan(v):
        lim = row["grid_min" if side == "lower" else "grid_max"]
        return Result(
            float(lim),
            f"{EDGE_NOTE}; stable to the end of the grid: the limit is "
            f"beyond {lim:g} (a bound, not a limit)",
        )
    # the edge is located by brentq to 1e-6 relative (robustness.stable_interval): its digits
    # beyond that move with the BLAS kernel (6.5e-8 relative measured), so 5 are kept
    return Result(float(f"{v:.{EDGE_DIGITS}g}"), EDGE_NOTE)


@CLAIMS.claim("appH.beta_d_stable_below", depends_on=EST)
def _bd_below(s):
    d = s.radii_of("beta_d")
    d = d[d["factor"] < 4.0]
    un = d[~d["stable"]]["factor"]
    return Result(
        bool(d["stable"].all()),
        "unstable design factors below 4 on the grid: "
        + (f"{un.min():.3g} ... {un.max():.3g}" if len(un) else "none")
        + " (the long-run errors are in design_errors.csv)",
    )


@CLAIMS.claim("appH.p_a_inertia")
def _inertia(s):
    dp = 0.005
    return Result(
        None,
        f"p_a was reconstructed from this remark (100 x {dp:g} / (1 - p_a) = "
        f"{100 * dp / (1 - s.params.p_a):.3g} % by construction), so it cannot also "
        "test it",
    )


@CLAIMS.claim("appH.others_never", depends_on=EST)
def _others(s):
    rows = [s.radii_of(n) for n in ("p_f", "beta_f", "kappa")]
    ok = all(bool(d["stable"].all()) for d in rows)
    f = np.concatenate([d["factor"].to_numpy() for d in rows])
    return Result(ok, f"every factor {f.min():.3g} ... {f.max():.3g} stable for p_f, beta_f, kappa")


@CLAIMS.claim("appH.beta_a_p_a_most_sensitive", depends_on=EST)
def _most(s):
    width = {}
    for n in ("beta_d", "beta_a", "p_a"):
        r = s.stability_of(n)
        lo = r["grid_min"] if np.isnan(r["lower"]) else r["lower"]
        hi = r["grid_max"] if np.isnan(r["upper"]) else r["upper"]
        width[n] = float(np.log(hi / lo))
    ok = width["p_a"] < width["beta_d"] and width["beta_a"] < width["beta_d"]
    return Result(
        bool(ok),
        "log-width of the stable design-factor interval: "
        + ", ".join(f"{k} {v:.3g}" for k, v in width.items()),
    )
