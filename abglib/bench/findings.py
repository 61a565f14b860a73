"""The benchmark report's findings, computed from its tables (the notebook only formats them).

- :func:`leaders`: per scenario, the leading variant and family, the best other family
  and the margin between them;
- :func:`tradeoff_extremes`: per scenario, the least noisy and the least lagging variant
  of the noise-versus-lag table, each with the other axis;
- :func:`peer_disagreements`: per peer, how many comparisons disagree with abglib and
  which side the independent routes support.
"""

from __future__ import annotations

from collections.abc import Iterable

import pandas as pd

__all__ = ["leaders", "peer_disagreements", "tradeoff_extremes"]


def _ranked(league: pd.DataFrame) -> pd.DataFrame:
    diverged = league["diverged"].astype(str).str.lower() == "true"
    return league[~diverged]


def leaders(league: pd.DataFrame, metric: str, exclude: Iterable[str] = ()) -> pd.DataFrame:
    """Per scenario: the leader, the best variant of another family, and the margin.

    Parameters
    ----------
    league : DataFrame
        ``league.csv`` (columns ``scenario, rank, variant, family, diverged`` and metrics).
    metric : str
        Metric to compare: the league's ``benchmark.rank_by`` (the report gets it from
        the config; it is not inferred from the ranks).
    exclude : iterable of str
        Variants left out (e.g. one that is not a realisable predictor).

    Returns
    -------
    DataFrame
        One row per scenario: ``scenario, noise_colour, leader, family, value, runner_up,
        runner_up_family, runner_up_value, margin`` where ``margin`` is
        ``runner_up_value / value - 1`` (0.25 = the next family is 25 % worse).
    """
    if metric not in league.columns:
        raise ValueError(f"metric must be a column of the league, got {metric!r}")
    live = _ranked(league)
    live = live[~live["variant"].isin(list(exclude)) & live[metric].notna()]
    rows = []
    for sc, d in live.groupby("scenario", sort=False):
        d = d.sort_values(metric, kind="stable")
        best = d.iloc[0]
        other = d[d["family"] != best["family"]]
        second = other.iloc[0] if len(other) else None
        rows.append(
            {
                "scenario": sc,
                "noise_colour": best.get("noise_colour", ""),
                "leader": best["variant"],
                "family": best["family"],
                "value": float(best[metric]),
                "runner_up": None if second is None else second["variant"],
                "runner_up_family": None if second is None else second["family"],
                "runner_up_value": None if second is None else float(second[metric]),
                "margin": None
                if second is None
                else float(second[metric]) / float(best[metric]) - 1,
            }
        )
    return pd.DataFrame(rows)


def tradeoff_extremes(tradeoff: pd.DataFrame, output: str = "x_smooth") -> pd.DataFrame:
    """Per scenario, the least noisy and the least lagging variant of ``tradeoff.csv``.

    Returns one row per scenario: ``scenario, quiet, quiet_noise, quiet_lag, fast,
    fast_noise, fast_lag, best_rmse, best_rmse_variant, lag_free`` (``quiet``: smallest
    noise RMS; ``fast``: smallest lag RMS; ``best_rmse``: the smallest total RMSE;
    ``lag_free``: every variant's lag is below 1e-6 of its noise, e.g. a constant-velocity
    track, where there is no trade-off).
    """
    d = tradeoff[tradeoff["output"] == output]
    if d.empty:
        raise ValueError(f"tradeoff table has no rows for output {output!r}")
    rows = []
    for sc, g in d.groupby("scenario", sort=False):
        quiet = g.loc[g["noise_rms"].idxmin()]
        fast = g.loc[g["lag_rms"].idxmin()]
        best = g.loc[g["rmse"].idxmin()]
        rows.append(
            {
                "scenario": sc,
                "quiet": quiet["variant"],
                "quiet_noise": float(quiet["noise_rms"]),
                "quiet_lag": float(quiet["lag_rms"]),
                "fast": fast["variant"],
                "fast_noise": float(fast["noise_rms"]),
                "fast_lag": float(fast["lag_rms"]),
                "best_rmse": float(best["rmse"]),
                "best_rmse_variant": best["variant"],
                "lag_free": bool((g["lag_rms"] <= 1e-6 * g["noise_rms"]).all()),
            }
        )
    return pd.DataFrame(rows)


def peer_disagreements(peers: pd.DataFrame) -> pd.DataFrame:
    """Per peer: comparisons, disagreements, how many of those the independent routes
    settle for abglib (``supports == "abglib"``) and how many compare different rules
    (``"not comparable"``), with the functions concerned: ``functions`` names those of every
    disagreement, ``not_comparable_functions`` only those of the ``"not comparable"`` rows."""
    agree = peers["agree"].astype(str).str.lower() == "true"
    rows = []
    for peer, g in peers.groupby("peer", sort=False):
        bad = g[~agree.loc[g.index]]
        rows.append(
            {
                "peer": peer,
                "comparisons": len(g),
                "disagreements": len(bad),
                "settled_for_abglib": int((bad["supports"] == "abglib").sum()),
                "not_comparable": int((bad["supports"] == "not comparable").sum()),
                "functions": ", ".join(dict.fromkeys(bad["function"].astype(str))),
                "not_comparable_functions": ", ".join(
                    dict.fromkeys(bad["function"][bad["supports"] == "not comparable"].astype(str))
                ),
            }
        )
    return pd.DataFrame(rows)
