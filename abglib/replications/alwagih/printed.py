"""Seed 001 as printed: Tables 1-6 from ``data/published/alwagih``, and Tables 3-6
recomputed from the printed Tables 1-2 (a check of the paper against itself).

Keys: ``t1``/``t2`` (Tables 1-2, RMSE of eq 26), ``t3``/``t4`` (averages over the five
experiments of ``RMSE(base) - RMSE(Mi)``), ``t5``/``t6`` (``PC_{i,1}`` of eq 27).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ... import methods
from ..._checks import AbglibValueError
from ...verdicts import parse_printed

__all__ = [
    "BASES",
    "COMPARED",
    "NOISE_OF_TABLE",
    "PAPER_METHODS",
    "printed_consistency",
    "printed_t12",
    "printed_values",
]

#: The paper's five methods.
PAPER_METHODS = ("M1", "M2", "M3", "M4", "M5")
#: Methods the paper compares against (Tables 3-4, rows) and the compared ones (columns).
BASES = ("M1", "M2")
COMPARED = ("M3", "M4", "M5")
#: Noise of each printed table (Tables 1, 3, 5: white; 2, 4, 6: coloured).
NOISE_OF_TABLE = {1: "white", 2: "coloured", 3: "white", 4: "coloured", 5: "white", 6: "coloured"}


def printed_t12(published: pd.DataFrame) -> pd.DataFrame:
    """Printed Tables 1-2: noise, experiment, coord, method, value and half a unit of its
    last printed digit."""
    rows = []
    for key, text in zip(published["key"], published["published"], strict=True):
        parts = key.split(".")
        if parts[0] not in ("t1", "t2") or len(parts) != 4:
            continue
        d = parse_printed(text)
        rows.append(
            {
                "noise": NOISE_OF_TABLE[int(parts[0][1])],
                "experiment": int(parts[1][1:]),
                "coord": parts[2],
                "method": parts[3],
                "value": float(d),
                "half_unit": float(5 * 10.0 ** (d.as_tuple().exponent - 1)),
            }
        )
    return pd.DataFrame(rows)


def printed_values(published: pd.DataFrame, table: int) -> dict[str, float]:
    """``{key: value}`` of the numeric cells of printed Table ``table`` (3-6)."""
    out = {}
    for key, text in zip(published["key"], published["published"], strict=True):
        if key.startswith(f"t{table}.") and text != "":
            out[key] = float(parse_printed(text))
    return out


def _interval(f, values, half_units):
    """Range of ``f`` over the box ``values +- half_units`` (f monotone in each input).

    ``f`` maps corner points, one per row of a ``(corners, inputs)`` array, to their
    values (row by row the numbers a call per corner gives: a reduction along a row of
    a few elements adds them in the same order).
    """
    values = np.asarray(values, float)
    h = np.asarray(half_units, float)
    corners = np.array(np.meshgrid(*[[-1.0, 1.0]] * values.size)).reshape(values.size, -1).T
    vals = f(values + corners * h)
    return float(np.min(vals)), float(np.max(vals))


def printed_consistency(t12: pd.DataFrame) -> pd.DataFrame:
    """Tables 3-6 recomputed from the printed Tables 1-2.

    Parameters
    ----------
    t12 : DataFrame
        Columns noise (``white`` = Table 1, ``coloured`` = Table 2), experiment, coord,
        method, value (float as printed), half_unit (half a unit in its last digit).

    Returns
    -------
    DataFrame
        One row per cell of Tables 3-6: table, noise, row (base or experiment), coord,
        method, ``central`` (from the printed values) and ``low``, ``high``: the range the
        printed rounding of the inputs allows.
    """
    need = {"noise", "experiment", "coord", "method", "value", "half_unit"}
    if not need <= set(t12.columns):
        raise AbglibValueError(f"t12 needs columns {sorted(need)}, got {list(t12.columns)}")
    rows = []
    tables = {"white": (3, 5), "coloured": (4, 6)}
    for noise, (tdiff, tpc) in tables.items():
        sub = t12[t12["noise"] == noise]
        for coord in ("X", "Y"):
            s = sub[sub["coord"] == coord]
            val = s.pivot(index="experiment", columns="method", values="value")
            hu = s.pivot(index="experiment", columns="method", values="half_unit")
            exps = list(val.index)
            for base in BASES:
                for m in COMPARED:
                    v = np.concatenate([val[base].to_numpy(), val[m].to_numpy()])
                    h = np.concatenate([hu[base].to_numpy(), hu[m].to_numpy()])
                    k = len(exps)

                    def f(x, k=k):
                        return float(np.mean(x[:k] - x[k:]))

                    def fs(x, k=k):
                        return np.mean(x[:, :k] - x[:, k:], axis=1)

                    lo, hi = _interval(fs, v, h)
                    rows.append(
                        {
                            "table": tdiff,
                            "noise": noise,
                            "row": base,
                            "coord": coord,
                            "method": m,
                            "central": f(v),
                            "low": lo,
                            "high": hi,
                        }
                    )
            for e in exps:
                for m in COMPARED:
                    v = np.array([val.loc[e, "M1"], val.loc[e, m]])
                    h = np.array([hu.loc[e, "M1"], hu.loc[e, m]])

                    def pc(x):
                        return float(methods.percentage_change(x[0], x[1]))

                    def pcs(x):
                        return methods.percentage_change(x[:, 0], x[:, 1])

                    lo, hi = _interval(pcs, v, h)
                    rows.append(
                        {
                            "table": tpc,
                            "noise": noise,
                            "row": f"experiment {e}",
                            "coord": coord,
                            "method": m,
                            "central": pc(v),
                            "low": lo,
                            "high": hi,
                        }
                    )
    return pd.DataFrame(rows)
