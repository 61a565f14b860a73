"""Beyond seed 004: alpha-beta-gamma object estimators with a Kalman object predictor's ENBW.

Two matches: the ENBW of the fifth-order Kalman object predictor at its optimal V_w (the
filter of the source's optimal settings) and that of a second-order one (the model order of
the alpha-beta-gamma, at its own optimal V_w); both critically damped (Steelman's standard,
Huang type II). Maxima are medians over the phase ensemble (:mod:`.ensemble`).
"""

from __future__ import annotations

import pandas as pd

from ... import design as gdesign
from ...analysis import enbw
from .closedloop import kalman_object_enbw
from .kalman import extended_model, kalman_gains
from .objectmodel import taylor_model
from .study_estimation import n_steps_for, run_stats

__all__ = ["abg_table"]


def abg_table(s, grid) -> pd.DataFrame:
    """One row per omega of ``grid``: Kalman (orders 5, 2) vs the matched alpha-beta-gamma."""
    kal = {}
    for order in (5, 2):
        at, ct, gt = taylor_model(order, s.dt)
        em = extended_model(s.ctrl.A, s.ctrl.B, s.ctrl.C, at, ct, gt)
        v = s.vw_optimum(order)
        bn = kalman_object_enbw(kalman_gains(em, s.vw_filter(v), s.vv), em, s.dt)
        kal[order] = (v, bn, gdesign.huang_for_enbw(bn, s.dt, rule="type2", order=3))
    rows = []
    for w in grid:
        n = n_steps_for(w, s.dt, s.sim)
        row = {"omega": float(w)}
        common = dict(
            transient=s.transient,
            amplitude=s.amp,
            omega=float(w),
            n_steps=n,
            phases=s.phases,
            resolution=s.res,
        )
        for order, (v, bn, g) in kal.items():
            ra = run_stats(s.params, s.ctrl, mode="abg", abg=g, **common)
            rk = run_stats(
                s.params, s.ctrl, mode="kalman", order=order, v_w=s.vw_filter(v), v_v=s.vv, **common
            )
            row.update(
                {
                    f"v_w_{order}": v,
                    f"enbw_{order}": bn,
                    f"abg{order}_enbw": float(enbw(g, s.dt)),
                    f"alpha_{order}": float(g.alpha),
                    f"beta_{order}": float(g.beta),
                    f"gamma_{order}": float(g.gamma),
                    f"e_max_kalman{order}": rk.e_med,
                    f"e_max_abg{order}": ra.e_med,
                    f"u_max_kalman{order}": rk.u_med,
                    f"u_max_abg{order}": ra.u_med,
                }
            )
        rows.append(row)
    return pd.DataFrame(rows)
