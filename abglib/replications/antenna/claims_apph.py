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
            f"{EDGE_NOTE}; stable to the end of the grid searched: reproduced is the grid's "
            "end, and abs_err is a lower bound on the error",
            bound="<" if side == "lower" else ">",
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


#: The claim "not very robust, especially for variations in beta_a and p_a" compares these
#: two with beta_d, whose window the text prints as wide (Fig. I.20: stable up to 4 times).
SENSITIVE = ("beta_a", "p_a")
REFERENCE = "beta_d"


def _sides(s, name):
    """How far the stable design-factor interval of ``name`` reaches below and above the
    real value (factor 1), each as ``(low, high)`` bounds of ln(factor ratio) and the edge as
    written: a located edge gives low = high; an edge past the grid's end (stable to the
    end) gives only the bound, high = inf, written '< 0.1' or '> 10'."""
    r = s.stability_of(name)
    out = []
    for side, end, sign, cmp in (("lower", "grid_min", -1.0, "<"), ("upper", "grid_max", 1.0, ">")):
        v = float(r[side])
        if np.isnan(v):
            g = float(r[end])
            out.append(((sign * np.log(g), np.inf), f"{cmp} {g:.3g}"))
        else:
            out.append(((sign * np.log(v), sign * np.log(v)), f"{v:.3g}"))
    return out


def _below(a, b):
    """Whether interval ``a = (low, high)`` lies below ``b``: True, False, or None when the
    bounds leave it open (not decidable)."""
    if a[1] < b[0]:
        return True
    if a[0] >= b[1]:
        return False
    return None


def _written(x) -> str:
    """An interval as written: its value when located, '>= low' when only bounded below,
    'low to high' when bounded on both sides."""
    if x[1] == x[0]:
        return f"{x[0]:.3g}"
    return f">= {x[0]:.3g}" if np.isinf(x[1]) else f"{x[0]:.3g} to {x[1]:.3g}"


@CLAIMS.claim("appH.beta_a_p_a_most_sensitive", depends_on=EST)
def _most(s):
    # "Not robust for variations in x" is read as a small stability margin: the smallest
    # change of the design factor that makes the loop unstable, ln of the factor at the
    # nearer edge. It is located whenever that edge lies inside the grid. The width of the
    # interval, ln(hi / lo), also counts the far edge, which is often past the grid's end
    # (only a lower bound there); it is written beside the margin but does not decide.
    margin, width, edges = {}, {}, {}
    for n in (REFERENCE, *SENSITIVE):
        ((d0, d1), lt), ((u0, u1), ht) = _sides(s, n)
        margin[n] = (min(d0, u0), min(d1, u1))
        width[n] = (d0 + u0, d1 + u1)
        edges[n] = f"{lt} to {ht}"
    ok = [_below(margin[n], margin[REFERENCE]) for n in SENSITIVE]
    value = False if False in ok else (None if None in ok else True)
    words = {True: "is", False: "is not", None: "cannot be told to be"}
    by_width = [_below(width[n], width[REFERENCE]) for n in SENSITIVE]
    printed = _printed_margins(s)
    holds = all(printed[n] < printed[REFERENCE] for n in SENSITIVE)
    return Result(
        value,
        "sensitivity read as the stability margin, |ln| of the design factor at the nearer "
        "edge of the stable interval (the edge a variation meets first; '>=': that edge lies "
        "past the end of the grid searched): "
        + ", ".join(f"{n} {_written(margin[n])} (edges {edges[n]})" for n in margin)
        + "; "
        + ", ".join(
            f"{n} {words[o]} more sensitive than {REFERENCE}"
            for n, o in zip(SENSITIVE, ok, strict=True)
        )
        + ". On the printed edges (Figs I.20-I.22) the margins are "
        + ", ".join(f"{n} {printed[n]:.3g}" for n in printed)
        + f" and the claim {'holds' if holds else 'does not hold'} there"
        + (
            ": the disagreement is in the reconstructed windows (the Fig. I.20-I.22 rows)"
            if holds and value is False
            else ""
        )
        + ". The widths ln(hi / lo) "
        + ("decide the same" if by_width == ok else "do not decide it")
        + " ("
        + ", ".join(f"{n} {_written(width[n])}" for n in width)
        + ")",
    )


def _printed_margins(s) -> dict[str, float]:
    """The stability margins of the printed edges (Figs I.20-I.22; beta_d's window is
    printed from 0 up to 4, so only its upper edge counts)."""
    out = {}
    for n in (REFERENCE, *SENSITIVE):
        edges = [float(s.printed(key)) for key, (name, _) in EDGES.items() if name == n]
        out[n] = min(abs(float(np.log(e))) for e in edges)
    return out
