"""Tracking antenna (seed 004): every table the report shows.

Writes, under ``results/antenna/``: the reconstructed parameters (``parameters.csv``),
the numeric checks of the control and estimation algebra (``checks.csv``), Fig. I.4
(``taylor.csv``), Figs I.5-I.7 (``tracking.csv``), Figs I.8-I.9 (``omega_sweep.csv``),
the V_w search (``vw_search.csv``), Figs I.10-I.13 and I.17-I.19 (``kalman_runs.csv``),
Figs I.14-I.16 (``kalman_sweep.csv``), app. H (``robustness.csv``, ``stability.csv``),
the alpha-beta-gamma object estimator (``abg.csv``), and ``reproduced.csv`` /
``alternatives.csv`` for the comparison rule.
"""

import numpy as np
import pandas as pd

from abglib import design as gdesign
from abglib.analysis import enbw
from abglib.replications.antenna import (
    AntennaParams,
    design_controller,
    extended_model,
    kalman_gains,
    kalman_object_enbw,
    preview_gain,
    preview_series,
    simulate,
    sine_state,
    spectral_radius,
    stable_interval,
    steady_state_amplitudes,
    stein_solve,
    taylor_model,
    taylor_predict,
)
from abglib.reporting.compare import read_published, write_csv
from abglib.reporting.pipeline import log_to

# preview lengths for the convergence check of the finite-preview gain (eq 2.37)
PREVIEW_STEPS = (50, 100, 200, 400, 800, 1600)

PARAMETER_BASIS = {
    "p_a": (
        "app. H: 'the small range of 0.5 % in p_a allows variations in J_a and J_d of about "
        "5 %'; with p_a = J_a/(J_a+J_d), d ln p_a = (1 - p_a) d ln J_a, so 1 - p_a = 0.1",
        "app. H, p. 38",
    ),
    "p_d": ("app. H: p_d = 1 - p_a (derived, not free)", "app. H, p. 37"),
    "p_f": (
        "not in the text (the value list is lost); neutral choice equal to the antenna + "
        "rotor inertia; app. H says any value gives a stable loop (checked in section 7)",
        "ch. 5 p. 12; app. H p. 37",
    ),
    "beta_a": (
        "not in the text; a typical structural damping ratio of an antenna structure (5 %). "
        "The dampings below are tied to it by the text's ratios",
        "ch. 5, p. 12",
    ),
    "beta_d": (
        "'the damping of the driver is about one tenth of the antenna damping'",
        "ch. 5, p. 12",
    ),
    "beta_f": (
        "'the damping of the foundation is about twice as big as the damping of the antenna'",
        "ch. 5, p. 12",
    ),
    "kappa": ("'the stiffness of the carriage and the antenna are the same'", "ch. 5, p. 12"),
    "dt": (
        "'The sample frequency ... is 10 times the eigenfrequency of the antenna'; time is "
        "scaled by the antenna eigenfrequency (1 rad per unit), so dt = 2 pi / 10",
        "ch. 6 p. 13, sec. 8.1",
    ),
    "Q, R": ("'Q = 100, R = 1'; Q/R = 10^4 for Figs I.9, I.15", "ch. 6 p. 13, sec. 6.2"),
    "V_v": (
        "OCR fragment '10-3 O 1' after 'The chosen V_v ... is given by'; read as 10^-3 I "
        "(the variance of a rounding to 0.1 is 0.1^2/12 = 8.3e-4)",
        "sec. 8.2, p. 20",
    ),
    "V_w input": (
        "'the force is assumed to be white noise with intensity V_w': read as a variance "
        "of the highest derivative's rate held over one step (ZOH input of the Taylor model)",
        "sec. 7.3, p. 19",
    ),
}


def log_grid(g):
    return np.geomspace(float(g["start"]), float(g["stop"]), int(g["n"]))


def n_steps_for(omega, dt, sim):
    span = max(float(sim["min_duration"]), float(sim["periods"]) * 2 * np.pi / omega)
    return int(np.ceil((float(sim["transient"]) + span) / dt))


def after(run, transient):
    return run["t"] >= transient


def run_max(run, transient, key):
    return float(np.max(np.abs(run[key][after(run, transient)])))


class Study:
    """The reconstructed setting and the runs every table shares."""

    def __init__(self, cfg):
        self.cfg = cfg
        self.params = AntennaParams.from_mapping(cfg["parameters"])
        self.dt = 2 * np.pi / float(cfg["samples_per_period"])
        w = cfg["weights"]
        self.q, self.r, self.q_high = float(w["q"]), float(w["r"]), float(w["q_high"])
        self.ctrl = design_controller(self.params, self.dt, self.q, self.r)
        self.ctrl_high = design_controller(self.params, self.dt, self.q_high, self.r)
        k = cfg["kalman"]
        self.vv = float(k["v_v"]) * np.eye(2)
        self.res = float(k["resolution"])
        self.sim = cfg["simulation"]
        self.transient = float(self.sim["transient"])
        nt = cfg["normal_track"]
        self.amp, self.omega = float(nt["amplitude"]), float(nt["omega"])

    def kalman_run(self, order, v_w, ctrl=None, amplitude=None, omega=None, n_steps=None):
        omega = self.omega if omega is None else omega
        return simulate(
            self.params,
            self.ctrl if ctrl is None else ctrl,
            amplitude=self.amp if amplitude is None else amplitude,
            omega=omega,
            n_steps=n_steps_for(omega, self.dt, self.sim) if n_steps is None else n_steps,
            mode="kalman",
            order=order,
            v_w=v_w,
            v_v=self.vv,
            resolution=self.res,
        )


def parameters_table(st: Study) -> pd.DataFrame:
    p = st.params
    values = {
        "p_a": p.p_a,
        "p_d": p.p_d,
        "p_f": p.p_f,
        "beta_a": p.beta_a,
        "beta_d": p.beta_d,
        "beta_f": p.beta_f,
        "kappa": p.kappa,
        "dt": st.dt,
        "Q, R": f"{st.q:g}, {st.r:g}",
        "V_v": f"{st.vv[0, 0]:g} I",
        "V_w input": "G_t (taylor_model)",
    }
    rows = [
        {
            "parameter": k,
            "value": v if isinstance(v, str) else float(v),
            "textual_basis": PARAMETER_BASIS[k][0],
            "where": PARAMETER_BASIS[k][1],
        }
        for k, v in values.items()
    ]
    return pd.DataFrame(rows)


def checks_table(st: Study) -> pd.DataFrame:
    """Independent routes for the algebra (the tests repeat them with peer libraries)."""
    import scipy.linalg

    tm, c = st.ctrl.tm, st.ctrl
    rows = []
    p_are = scipy.linalg.solve_discrete_are(c.A, c.B, c.C.T @ [[st.q]] @ c.C, [[st.r]])
    rows.append(
        {
            "check": "Riccati eq 2.12: iteration vs scipy solve_discrete_are",
            "value": float(np.max(np.abs(tm.P - p_are)) / np.max(np.abs(p_are))),
        }
    )
    rows.append(
        {
            "check": "spectral radius of A_g (eq 2.16)",
            "value": float(np.max(np.abs(np.linalg.eigvals(tm.Ag)))),
        }
    )
    rows.append(
        {"check": "||A_g||_2 (eq 2.32 assumes < 1)", "value": float(np.linalg.norm(tm.Ag, 2))}
    )
    at, ct, _ = taylor_model(5, st.dt)
    rhs = tm.Cg @ ct @ at
    x1 = stein_solve(tm.Ag, at, rhs, "kron")
    x2 = stein_solve(tm.Ag, at, rhs, "sylvester")
    rows.append(
        {
            "check": "Stein eq E.4 (order 5): Kronecker vs Bartels-Stewart, rel. diff",
            "value": float(np.max(np.abs(x1 - x2)) / np.max(np.abs(x1))),
        }
    )
    kt = preview_gain(tm, at, ct)
    for n in PREVIEW_STEPS:
        rows.append(
            {
                "check": f"preview gain: |Kv X_n - Kv X| / |Kv X|, n = {n} steps (eq 2.37)",
                "value": float(
                    np.max(np.abs(preview_series(tm, at, ct, n) - kt)) / np.max(np.abs(kt))
                ),
            }
        )
    em = extended_model(c.A, c.B, c.C, at, ct, _)
    kg = kalman_gains(em, 5e-10, st.vv)
    n = em.n_antenna
    dual = scipy.linalg.solve_discrete_are(at.T, em.M[1:2, n:].T, 5e-10 * _ @ _.T, st.vv[1:2, 1:2])
    rows.append(
        {
            "check": "Kalman eq 7.15 (order 5): object block vs dual DARE, rel. diff",
            "value": float(np.max(np.abs(kg.Q[n:, n:] - dual)) / np.max(np.abs(dual))),
        }
    )
    rows.append(
        {
            "check": "Kalman eq 7.15: largest |entry| of the antenna block (w = 0)",
            "value": float(np.max(np.abs(kg.Q[:n, :n]))),
        }
    )
    return pd.DataFrame(rows)


def taylor_table(cfg) -> pd.DataFrame:
    """Fig. I.4: z_i = sin(i/100) predicted from i = start with the Taylor model."""
    t = cfg["taylor"]
    dt, i0 = float(t["dt"]), int(t["start"])
    i = np.arange(i0, int(t["stop"]) + 1)
    k = i - i0
    x0 = sine_state(1.0, 1.0, i0 * dt, max(t["orders"]))
    out = {"i": i, "z": np.sin(i * dt)}
    for q in t["orders"]:
        at, ct, _ = taylor_model(q, dt)
        pred = taylor_predict(x0, q, dt, k)
        # the model route: C_t A_t^k x_t0 (eq 3.6)
        xs, model = x0[: q + 1].copy(), []
        for _k in k:
            model.append((ct @ xs)[0])
            xs = at @ xs
        if not np.allclose(pred, model, rtol=1e-12, atol=1e-12):
            raise RuntimeError(f"Taylor model and closed form differ, order {q}")
        out[f"order{q}"] = pred
    return pd.DataFrame(out)


def tracking_table(st: Study) -> pd.DataFrame:
    """Figs I.5-I.7: tracking error, known vs predicted output, normal track."""
    ts = st.cfg["time_series"]
    n = int(np.ceil(float(ts["duration"]) / st.dt))
    frames = []
    cases = [("known", None)] + [("predicted", q) for q in ts["orders"]]
    for mode, q in cases:
        r = simulate(
            st.params, st.ctrl, amplitude=st.amp, omega=st.omega, n_steps=n, mode=mode, order=q
        )
        frames.append(
            pd.DataFrame(
                {
                    "case": mode if q is None else f"order {q}",
                    "t": r["t"],
                    "z": r["z"],
                    "y": r["y"],
                    "e": r["e"],
                    "u": r["u"],
                }
            )
        )
    return pd.concat(frames, ignore_index=True)


def omega_sweep_table(st: Study) -> pd.DataFrame:
    """Figs I.8-I.9: steady-state max |e| and |u| against omega, amplitude 1."""
    sw = st.cfg["omega_sweep"]
    rows = []
    for qr, ctrl in ((st.q / st.r, st.ctrl), (st.q_high / st.r, st.ctrl_high)):
        for w in log_grid(sw):
            for mode, q in [("known", None)] + [("predicted", q) for q in sw["orders"]]:
                a = steady_state_amplitudes(ctrl, w, 1.0, mode, q)
                rows.append(
                    {
                        "q_over_r": qr,
                        "omega": w,
                        "case": "known" if q is None else f"order {q}",
                        "e_max": a["e"],
                        "u_max": a["u"],
                        "phase_e": a["phase_e"],
                    }
                )
    return pd.DataFrame(rows)


def vw_search_table(st: Study) -> pd.DataFrame:
    """Normal track: max estimation and tracking errors against V_w = 5 x 10^k per order."""
    k0, k1 = st.cfg["kalman"]["vw_exponents"]
    rows = []
    for order in st.cfg["kalman"]["orders"]:
        for k in range(int(k0), int(k1) + 1):
            vw = 5.0 * 10.0**k
            r = st.kalman_run(order, vw)
            sel = after(r, st.transient)
            row = {
                "order": order,
                "v_w": vw,
                "e_max": run_max(r, st.transient, "e"),
                "u_max": run_max(r, st.transient, "u"),
            }
            for j in range(order + 1):
                row[f"est_err_d{j}"] = float(np.max(np.abs(r["xt_err"][j, sel])))
            rows.append(row)
    return pd.DataFrame(rows)


def optimum(vw: pd.DataFrame, order, key="e_max") -> float:
    d = vw[vw["order"] == order]
    return float(d.loc[d[key].idxmin(), "v_w"])


def settings(st: Study, vw: pd.DataFrame) -> dict:
    """The three V_w settings per figure (model emphasis, optimum, measurement emphasis)."""
    k = st.cfg["kalman"]
    o5, o3 = optimum(vw, 5), optimum(vw, 3)
    s5, s3 = float(k["spread_fifth"]), float(k["spread_third"])
    return {5: [o5 / s5, o5, o5 * s5], 3: [o3 / s3, o3, o3 * s3]}


def kalman_runs_table(st: Study, sets: dict) -> pd.DataFrame:
    """Figs I.10-I.13 (fifth order, three V_w) and I.17-I.19 (optimum, three amplitudes)."""
    frames = []
    labels = ("model emphasis", "optimal", "measurement emphasis")
    for label, vw in zip(labels, sets[5], strict=True):
        r = st.kalman_run(5, vw)
        d = {
            "figure": "I.10-I.13",
            "case": f"{label}, V_w = {vw:.0e}",
            "t": r["t"],
            "e": r["e"],
            "u": r["u"],
        }
        for j in range(6):
            d[f"est_err_d{j}"] = r["xt_err"][j]
        frames.append(pd.DataFrame(d))
    for amp in st.cfg["kalman"]["amplitudes"]:
        r = st.kalman_run(5, sets[5][1], amplitude=float(amp))
        frames.append(
            pd.DataFrame(
                {
                    "figure": "I.17-I.19",
                    "case": f"amplitude {amp:g}",
                    "t": r["t"],
                    "e": r["e"],
                    "u": r["u"],
                }
            )
        )
    return pd.concat(frames, ignore_index=True)


def kalman_sweep_table(st: Study, sets: dict) -> pd.DataFrame:
    """Figs I.14-I.16: max |e| and |u| against omega with estimation (amplitude 10)."""
    rows = []
    figs = (
        ("I.14", 5, st.ctrl, st.q),
        ("I.15", 5, st.ctrl_high, st.q_high),
        ("I.16", 3, st.ctrl, st.q),
    )
    for fig, order, ctrl, q in figs:
        for vw in sets[order]:
            for w in log_grid(st.cfg["kalman"]["omega_sweep"]):
                r = st.kalman_run(order, vw, ctrl=ctrl, omega=w)
                rows.append(
                    {
                        "figure": fig,
                        "order": order,
                        "q_over_r": q / st.r,
                        "v_w": vw,
                        "omega": w,
                        "e_max": run_max(r, st.transient, "e"),
                        "u_max": run_max(r, st.transient, "u"),
                    }
                )
    return pd.DataFrame(rows)


def robustness_tables(st: Study, vw_opt: float):
    """App. H: spectral radius and simulated max |e| against the design factor."""
    rb = st.cfg["robustness"]
    tol = float(rb["radius_tolerance"])
    n = int(np.ceil(float(rb["duration"]) / st.dt))
    grid = np.unique(np.concatenate([log_grid(rb["factors"]), log_grid(rb["fine"]), [1.0]]))
    rows, stab = [], []
    for name in ("beta_d", "beta_a", "p_a", "p_f", "beta_f", "kappa"):
        g = grid[grid * getattr(st.params, name) < 1.0] if name == "p_a" else grid
        for f in g:
            rad = spectral_radius(st.params, name, f, st.dt, st.q, st.r, 5, vw_opt, st.vv)
            ctrl = design_controller(st.params.scaled(name, f), st.dt, st.q, st.r)
            with np.errstate(over="ignore", invalid="ignore"):
                r = simulate(
                    st.params,
                    ctrl,
                    amplitude=st.amp,
                    omega=st.omega,
                    n_steps=n,
                    mode="kalman",
                    order=5,
                    v_w=vw_opt,
                    v_v=st.vv,
                    resolution=st.res,
                )
                e = np.abs(r["e"][after(r, st.transient)])
            rows.append(
                {
                    "parameter": name,
                    "factor": f,
                    "spectral_radius": rad,
                    "stable": bool(rad <= 1.0 + tol),
                    "e_max": float(np.max(e)) if np.all(np.isfinite(e)) else np.inf,
                }
            )
        lo, hi = stable_interval(st.params, name, st.dt, st.q, st.r, 5, vw_opt, st.vv, g, tol)
        stab.append(
            {
                "parameter": name,
                "lower": lo,
                "upper": hi,
                "grid_min": float(g.min()),
                "grid_max": float(g.max()),
            }
        )
    return pd.DataFrame(rows), pd.DataFrame(stab)


def abg_table(st: Study, vw: pd.DataFrame) -> pd.DataFrame:
    """Beyond the source: alpha-beta-gamma object estimators with a Kalman filter's ENBW.

    Two matches: the ENBW of the fifth-order Kalman object predictor at its optimal V_w
    (the filter of the source's optimal settings) and that of a second-order one (the
    same model order as the alpha-beta-gamma, at its own optimal V_w); both rows of gains
    are critically damped (Steelman's standard / Huang type II). The omega grid of Figs
    I.14-I.16 plus the normal track.
    """
    rows = []
    kal = {}
    for order in (5, 2):
        at, ct, gt = taylor_model(order, st.dt)
        em = extended_model(st.ctrl.A, st.ctrl.B, st.ctrl.C, at, ct, gt)
        v = optimum(vw, order)
        bn = kalman_object_enbw(kalman_gains(em, v, st.vv), em, st.dt)
        kal[order] = (v, bn, gdesign.huang_for_enbw(bn, st.dt, rule="type2", order=3))
    grid = np.union1d(log_grid(st.cfg["kalman"]["omega_sweep"]), [st.omega])
    for w in grid:
        n = n_steps_for(w, st.dt, st.sim)
        row = {"omega": w}
        for order, (v, bn, g) in kal.items():
            r_abg = simulate(
                st.params,
                st.ctrl,
                mode="abg",
                abg=g,
                resolution=st.res,
                amplitude=st.amp,
                omega=w,
                n_steps=n,
            )
            r_k = st.kalman_run(order, v, omega=w, n_steps=n)
            row.update(
                {
                    f"v_w_{order}": v,
                    f"enbw_{order}": bn,
                    f"abg{order}_enbw": float(enbw(g, st.dt)),
                    f"alpha_{order}": float(g.alpha),
                    f"beta_{order}": float(g.beta),
                    f"gamma_{order}": float(g.gamma),
                    f"e_max_kalman{order}": run_max(r_k, st.transient, "e"),
                    f"e_max_abg{order}": run_max(r_abg, st.transient, "e"),
                    f"u_max_kalman{order}": run_max(r_k, st.transient, "u"),
                    f"u_max_abg{order}": run_max(r_abg, st.transient, "u"),
                }
            )
        rows.append(row)
    return pd.DataFrame(rows)


def reproduced_tables(
    st, published, checks, taylor, tracking, sweep, vw, sets, runs, ksweep, rob, stab
):
    """One reproduced value (or check outcome) per published key."""
    cfg = st.cfg
    rep, alts = {}, []

    def put(key, value, note=""):
        rep[key] = {"key": key, "reproduced": value, "note": note}

    ck = checks.set_index("check")["value"]
    # --- chapter 2 and 4 (model-independent algebra, checked on the reconstructed model)
    c = st.ctrl
    a_inv_t = np.linalg.inv(c.A).T
    brb = c.B @ c.B.T / st.r
    qx = c.C.T @ c.C * st.q
    ham = np.block([[c.A + brb @ a_inv_t @ qx, -brb @ a_inv_t], [-a_inv_t @ qx, a_inv_t]])
    ev = np.linalg.eigvals(ham)
    paired = all(np.min(np.abs(ev - 1.0 / e)) < 1e-6 * max(1.0, abs(1.0 / e)) for e in ev)
    put(
        "ch2.hamiltonian_pairs",
        paired,
        "eigenvalues of the symplectic matrix of eqs 2.8-2.9 "
        "(reconstructed model) paired mu, 1/mu to 1e-6; holds for any model (theorem)",
    )
    norm = float(ck["||A_g||_2 (eq 2.32 assumes < 1)"])
    put(
        "ch2.norm_ag_lt_1",
        norm < 1.0,
        f"||A_g||_2 = {norm:.3g} with spectral radius "
        f"{ck['spectral radius of A_g (eq 2.16)']:.3g}: "
        "stability of A_g bounds the spectral radius, not the 2-norm; the preview-step count "
        "is therefore taken from the powers ||A_g^n||_2 "
        "(abglib.replications.antenna.preview_steps)",
    )
    conv = [ck[k] for k in ck.index if k.startswith("preview gain")]
    put(
        "ch4.preview_converges",
        bool(np.all(np.diff(conv[-3:]) < 0) and conv[-1] < 1e-8),
        "relative difference of the n-step and infinite-preview gains (fifth-order "
        "prediction): "
        + ", ".join(f"{v:.1e}" for v in conv)
        + f" for n = {', '.join(map(str, PREVIEW_STEPS))}: converges, slowly, because the "
        "Taylor model grows like n^5 against the decay of A_g^n; section 2",
    )
    # --- Fig. I.4 (model-independent)
    tcfg = cfg["taylor"]
    errs = {q: np.abs(taylor[f"order{q}"] - taylor["z"]).to_numpy() for q in tcfg["orders"]}
    grows = all(
        np.all(np.diff(np.maximum.accumulate(e)) >= 0) and e[-1] > e[1] for e in errs.values()
    )
    put(
        "fig4.deviation_grows",
        grows,
        "running maximum of the error never decreases and the "
        "error at the end exceeds that at the first step, for every order; section 3",
    )
    tol = float(tcfg["tolerance"])
    horizon = [int(np.argmax(e > tol)) if np.any(e > tol) else len(e) for e in errs.values()]
    put(
        "fig4.longer_with_order",
        bool(np.all(np.diff(horizon) > 0)),
        f"steps until the error exceeds {tol:g}: "
        + ", ".join(map(str, horizon))
        + f" for orders {tcfg['orders']}; section 3",
    )
    # --- chapter 6 (reconstructed model)
    thr = cfg["thresholds"]
    kn = sweep[(sweep["case"] == "known")]
    a_k = steady_state_amplitudes(st.ctrl, st.omega, 1.0, "known")
    # y = z + e: amplitude and phase of y relative to z
    e_c = a_k["e"] * np.exp(1j * a_k["phase_e"])
    y_c = 1.0 + e_c
    ph = float(np.degrees(np.angle(y_c)))
    put(
        "fig5.smaller_no_phase",
        bool(abs(y_c) < 1.0 and abs(ph) < float(thr["phase_deg"])),
        f"steady state: |y|/|z| = {abs(y_c):.8f}, phase of y {ph:.2e} deg; section 4",
    )
    n01 = sweep[(sweep["q_over_r"] == st.q / st.r)]
    w01 = n01["omega"].unique()[np.argmin(np.abs(n01["omega"].unique() - st.omega))]
    at01 = {row.case: row for row in n01[n01["omega"] == w01].itertuples()}
    orders = cfg["omega_sweep"]["orders"]
    ek = at01["known"].e_max
    eo = [at01[f"order {q}"].e_max for q in orders]
    ek_c = ek * np.exp(1j * at01["known"].phase_e)
    dist = [
        abs(at01[f"order {q}"].e_max * np.exp(1j * at01[f"order {q}"].phase_e) - ek_c)
        for q in orders
    ]
    put(
        "fig7.toward_known",
        bool(np.all(np.diff(dist) < 0)),
        f"omega = {w01:.3g}: |E_q - E_known| (steady-state complex amplitudes) per order "
        + ", ".join(f"{v:.2e}" for v in dist)
        + f"; max errors {[f'{v:.2e}' for v in eo]}, "
        f"known {ek:.2e}",
    )
    ph_o = [abs(at01[f"order {q}"].phase_e - at01["known"].phase_e) for q in orders]
    ph_o = [min(p, 2 * np.pi - p) for p in ph_o]
    put(
        "fig7.phase_decreases",
        bool(np.all(np.diff(ph_o) <= 1e-9)),
        "steady-state phase of the error relative to the known-output error (deg): "
        + ", ".join(f"{np.degrees(p):.3g}" for p in ph_o)
        + f" for orders {orders}",
    )
    e3 = [at01[f"order {q}"].e_max for q in orders if q >= 3]
    put(
        "fig8.third_near_known",
        bool(max(e3) / ek < float(thr["near_ratio"])),
        f"omega = {w01:.3g}, Q/R = 100: order >= 3 max error / known = "
        f"{max(e3) / ek:.3g} (counted 'nearly equal' below {thr['near_ratio']:g})",
    )
    put(
        "fig8.max_err_lt_002pct",
        bool(100 * max(e3) < 0.02),
        f"largest of orders >= 3: {100 * max(e3):.2e} % of the amplitude",
    )
    k100 = kn[kn["q_over_r"] == st.q / st.r]
    put(
        "fig8.known_lt_10pct",
        bool(k100["e_max"].max() < 0.1),
        f"largest known-output error over omega: {100 * k100['e_max'].max():.3g} %",
    )
    p100 = n01[n01["case"] != "known"]
    put(
        "fig8.pred_exceeds_amplitude",
        bool(p100["e_max"].max() > 1.0),
        f"largest predicted-output error over omega and orders: {p100['e_max'].max():.3g} "
        "of the amplitude; hinges on beta_a and the lost parameters",
    )
    piv = p100.pivot(index="omega", columns="case", values="e_max")[[f"order {q}" for q in orders]]
    notmono = bool(np.any(np.diff(piv.to_numpy(), axis=1) > 0))
    put(
        "fig8.higher_order_not_always",
        notmono,
        "some omega where a higher order gives a larger error: "
        + (
            f"{piv.index[np.any(np.diff(piv.to_numpy(), axis=1) > 0, axis=1)].min():.3g} and up"
            if notmono
            else "none"
        ),
    )
    nh = sweep[(sweep["q_over_r"] == st.q_high / st.r)]
    pivh = nh[nh["case"] != "known"].pivot(index="omega", columns="case", values="e_max")[
        [f"order {q}" for q in orders]
    ]
    bad = np.any(np.diff(pivh.to_numpy(), axis=1) > 0, axis=1)
    put(
        "fig9.higher_order_better",
        bool(not np.any(bad)),
        "omega where a higher order is worse: "
        + (", ".join(f"{w:.3g}" for w in pivh.index[bad]) if np.any(bad) else "none"),
    )
    w1 = {row.case: row for row in nh[np.isclose(nh["omega"], nh["omega"].max())].itertuples()}
    put(
        "fig9.known_w1_lt_01pct",
        bool(100 * w1["known"].e_max < 0.1),
        f"known output at omega = 1: {100 * w1['known'].e_max:.3g} %",
    )
    put("fig9.fifth_w1", 100 * w1["order 5"].e_max, "hinges on beta_a, p_f and dt (lost)")
    put("fig9.second_w1", 100 * w1["order 2"].e_max, "hinges on beta_a, p_f and dt (lost)")
    put("fig9.third_w1", 100 * w1["order 3"].e_max, "hinges on beta_a, p_f and dt (lost)")
    uk = kn.pivot(index="omega", columns="q_over_r", values="u_max")
    rel = float(np.max(np.abs(uk.iloc[:, 1] - uk.iloc[:, 0]) / uk.iloc[:, 0]))
    put(
        "fig89.u_known_same",
        rel < float(thr["same_rel"]),
        f"largest relative difference of the known-output control: {rel:.3g}",
    )
    dev = []
    for qr in (st.q / st.r, st.q_high / st.r):
        d = sweep[sweep["q_over_r"] == qr]
        uu = d.pivot(index="omega", columns="case", values="u_max")
        dev.append(
            float(
                np.median(
                    np.abs(uu[[f"order {q}" for q in orders]].sub(uu["known"], axis=0))
                    .div(uu["known"], axis=0)
                    .to_numpy()
                )
            )
        )
    put(
        "fig89.u_pred_closer",
        dev[1] < dev[0],
        f"median relative deviation from the known-output control: {dev[0]:.3g} (Q/R = 100), "
        f"{dev[1]:.3g} (Q/R = 10^4)",
    )
    # --- chapter 8 (reconstructed model; V_w scale hinges on the lost noise convention)
    o5 = optimum(vw, 5)
    put(
        "sec82.vw_opt_fifth",
        None,
        f"the exponent is lost in the scan; in the reconstructed model the optimum on "
        f"5 x 10^k is V_w = {o5:.0e} (hinges on the V_w convention, dt and beta_a)",
    )
    best = vw[(vw["order"] == 5) & (vw["v_w"] == o5)].iloc[0]
    w = st.omega
    put(
        "sec82.pos_err_lt_1pct",
        bool(best["est_err_d0"] < 0.01 * st.amp),
        f"max position-estimation error {best['est_err_d0']:.3g} = "
        f"{100 * best['est_err_d0'] / st.amp:.3g} % of the amplitude",
    )
    put("sec82.vel_err", 100 * best["est_err_d1"] / (st.amp * w), "hinges on beta_a, dt, V_w")
    put("sec82.acc_err", 100 * best["est_err_d2"] / (st.amp * w**2), "hinges on beta_a, dt, V_w")
    put(
        "sec82.fifth_deriv_err",
        100 * best["est_err_d5"] / (st.amp * w**5),
        "hinges on beta_a, dt, V_w",
    )
    est_opt = optimum(vw, 5, "est_err_d0")
    put(
        "sec82.opt_smallest_tracking",
        bool(est_opt == o5),
        f"V_w minimising the position-estimation error {est_opt:.0e}, the tracking error {o5:.0e}",
    )
    orders_8 = [q for q in cfg["kalman"]["orders"] if q >= 3]  # the orders the text compares
    opts = [optimum(vw, q) for q in orders_8]
    put(
        "sec82.lower_order_larger_vw",
        bool(np.all(np.diff(opts) < 0)),
        "optimal V_w for orders "
        + ", ".join(f"{q}: {v:.0e}" for q, v in zip(orders_8, opts, strict=True)),
    )
    third = {v: st.kalman_run(3, v) for v in (0.01, 0.1, 1.0)}
    e3s = {v: run_max(r, st.transient, "e") for v, r in third.items()}
    put(
        "sec82.vw_opt_third",
        min(e3s, key=e3s.get),
        "max tracking error for V_w = 0.01, 0.1, 1: "
        + ", ".join(f"{v:.3g}" for v in e3s.values())
        + f"; on the fine grid the third-order optimum is {optimum(vw, 3):.0e}: the V_w scale "
        "hinges on the lost noise convention and parameters",
    )
    k14 = ksweep[ksweep["figure"] == "I.14"]
    hi = k14[k14["omega"] > 0.2]
    put(
        "sec83.w_gt_02_gt_10pct",
        bool(np.all(hi["e_max"] > 0.1 * st.amp)),
        f"smallest max error for omega > 0.2: {hi['e_max'].min() / st.amp:.3g} of the amplitude",
    )
    k15 = ksweep[ksweep["figure"] == "I.15"]
    ratio_k = float(
        np.median(k14.groupby("omega")["e_max"].min() / k15.groupby("omega")["e_max"].min())
    )
    pp = sweep[sweep["case"] == "order 5"].pivot(index="omega", columns="q_over_r", values="e_max")
    ratio_p = float(np.median(pp.iloc[:, 0] / pp.iloc[:, 1]))
    put(
        "sec83.qr_small_decrease",
        ratio_k < ratio_p,
        f"median error ratio Q/R 100 : 10^4, with estimation {ratio_k:.3g}, exact states "
        f"(order 5) {ratio_p:.3g}",
    )
    uinc = [
        float(
            np.median(
                k15[k15["v_w"] == v]["u_max"].to_numpy() / k14[k14["v_w"] == v]["u_max"].to_numpy()
            )
        )
        for v in sets[5]
    ]
    put(
        "sec83.qr_more_control",
        bool(uinc[2] > float(thr["considerable_ratio"]) and uinc[2] == max(uinc)),
        "median control ratio Q/R 10^4 : 100 for the three V_w: "
        + ", ".join(f"{v:.3g}" for v in uinc),
    )
    k16 = ksweep[ksweep["figure"] == "I.16"]
    wmin = ksweep["omega"].min()
    spread5 = k14[k14["omega"] == wmin]["e_max"]
    spread3 = k16[k16["omega"] == wmin]["e_max"]
    # the answer is set by how far apart the fifth-order V_w settings are, which the scan
    # lost (config spread_fifth): with the third order's printed decade spacing the fifth
    # order's ratio is the smaller one, with two decades the larger; so no verdict
    put(
        "sec83.third_less_critical",
        None,
        f"hinges on the lost spacing of the fifth-order V_w settings (Figs I.10-I.15): the "
        f"max/min error over the three V_w at omega = {wmin:.3g} is "
        f"{spread3.max() / spread3.min():.3g} for the third order (decade spacing, as printed) "
        f"and {spread5.max() / spread5.min():.3g} "
        f"for the fifth with the configured spread {st.cfg['kalman']['spread_fifth']:g}; a "
        "decade spread for the fifth order reverses the comparison",
    )
    u3 = float(k16[k16["v_w"] == sets[3][1]]["u_max"].median())
    u5 = float(k14[k14["v_w"] == sets[5][1]]["u_max"].median())
    put(
        "sec83.third_more_control",
        u3 > float(thr["considerable_ratio"]) * u5,
        f"median max control at the optimal V_w: third order {u3:.3g}, fifth {u5:.3g}, ratio "
        f"{u3 / u5:.3g}; 'considerably larger' read as a ratio above "
        f"{float(thr['considerable_ratio']):g} (config), so the verdict is marginal",
    )
    r17 = runs[(runs["figure"] == "I.17-I.19")]
    mx = {}
    for amp in cfg["kalman"]["amplitudes"]:
        d = r17[(r17["case"] == f"amplitude {amp:g}") & (r17["t"] >= st.transient)]
        mx[float(amp)] = (float(d["e"].abs().max()), float(d["u"].abs().max()))
    e10 = mx[st.amp][0]
    put("fig17.err_lt_3pct", e10 < 0.03 * st.amp, f"{100 * e10 / st.amp:.3g} % of the amplitude")
    put("fig17.u_max", mx[st.amp][1], "hinges on beta_a, p_f, dt and V_w")
    put("fig18.err_a100", 100 * mx[100.0][0] / 100.0, "hinges on beta_a, dt and V_w")
    larger = [
        run_max(st.kalman_run(5, sets[5][1] * f, amplitude=100.0), st.transient, "e")
        for f in cfg["kalman"]["larger_vw_factors"]
    ]
    put(
        "fig18.err_a100_larger_vw",
        100 * min(larger) / 100.0,
        "best over V_w x " + ", ".join(f"{f:g}" for f in cfg["kalman"]["larger_vw_factors"]),
    )
    put("fig19.err_a1", 100 * mx[1.0][0] / 1.0, "hinges on beta_a, dt and V_w")
    put("ch8.normal_3pct", 100 * e10 / st.amp, "hinges on beta_a, p_f, dt and V_w")
    low = [
        min(run_max(st.kalman_run(5, v, omega=float(w)), st.transient, "e") for v in sets[5])
        for w in cfg["kalman"]["low_omegas"]
    ]
    put(
        "ch8.low_w_005",
        min(low),
        "best over the three V_w settings at omega = "
        + ", ".join(f"{w:g}" for w in cfg["kalman"]["low_omegas"]),
    )
    all_hi = ksweep[(ksweep["omega"] > 0.3) & (ksweep["figure"] != "I.15")]
    put(
        "ch8.w_gt_03",
        bool(np.all(all_hi["e_max"] > 0.1 * st.amp)),
        f"smallest max error for omega > 0.3: {all_hi['e_max'].min() / st.amp:.3g} of amplitude",
    )
    put("summary.three_resolutions", e10 / st.res, "hinges on beta_a, p_f, dt and V_w")
    opt14 = k14[k14["v_w"] == sets[5][1]]
    put(
        "ch9.unacceptable_above_015",
        bool(np.all(opt14[opt14["omega"] > 0.15]["e_max"] > 0.1 * st.amp)),
        f"smallest max error at the optimal V_w for omega > 0.15: "
        f"{opt14[opt14['omega'] > 0.15]['e_max'].min() / st.amp:.3g} of the amplitude",
    )
    # --- appendix H
    nom = rob[(rob["parameter"] == "beta_d") & np.isclose(rob["factor"], 1.0)].iloc[0]
    put("appH.nominal_err", float(nom["e_max"]), "long run at the optimal settings")
    sb = stab.set_index("parameter")
    note_edge = "linear closed loop (quantisation left out), spectral radius > 1 + tol; "

    def edge(name, side):
        v = float(sb.loc[name, side])
        if np.isnan(v):
            lim = sb.loc[name, "grid_min" if side == "lower" else "grid_max"]
            return float(lim), (
                f"{note_edge}stable to the end of the grid: the limit is beyond "
                f"{lim:g} (a bound, not a limit)"
            )
        return v, note_edge + "hinges on the lost beta_a, p_f and on V_w"

    for key, name, side in (
        ("appH.beta_d_upper", "beta_d", "upper"),
        ("appH.beta_a_lower", "beta_a", "lower"),
        ("appH.beta_a_upper", "beta_a", "upper"),
        ("appH.p_a_lower", "p_a", "lower"),
        ("appH.p_a_upper", "p_a", "upper"),
    ):
        put(key, *edge(name, side))
    bd = rob[(rob["parameter"] == "beta_d") & (rob["factor"] < 4.0)]
    put(
        "appH.beta_d_stable_below",
        bool(bd["stable"].all()),
        f"stable for every factor below 4 on the grid: {bool(bd['stable'].all())}; largest "
        f"max error {bd['e_max'].max():.3g}",
    )
    dp = 0.005
    put(
        "appH.p_a_inertia",
        None,
        f"p_a was reconstructed from this remark (100 x {dp:g} / (1 - p_a) = "
        f"{100 * dp / (1 - st.params.p_a):.3g} % by construction), so it cannot also test it; "
        "it hinges on the lost value of p_a",
    )
    oth = rob[rob["parameter"].isin(["p_f", "beta_f", "kappa"])]
    put(
        "appH.others_never",
        bool(oth["stable"].all()),
        f"factors {oth['factor'].min():.3g} ... {oth['factor'].max():.3g}",
    )
    keys = list(published["key"])
    missing = [k for k in keys if k not in rep]
    if missing:
        raise RuntimeError(f"no reproduced value for {missing}")
    out = pd.DataFrame([rep[k] for k in keys])
    return out, pd.DataFrame(alts, columns=["key", "alternative", "value", "section"])


def main(input, output, params) -> None:
    cfg = params.cfg
    st = Study(cfg)
    published = read_published(input.published)
    d = params.digits
    checks = checks_table(st)
    taylor = taylor_table(cfg)
    tracking = tracking_table(st)
    sweep = omega_sweep_table(st)
    vw = vw_search_table(st)
    sets = settings(st, vw)
    runs = kalman_runs_table(st, sets)
    ksweep = kalman_sweep_table(st, sets)
    rob, stab = robustness_tables(st, sets[5][1])
    abg = abg_table(st, vw)
    rep, alts = reproduced_tables(
        st, published, checks, taylor, tracking, sweep, vw, sets, runs, ksweep, rob, stab
    )
    for name, df in (
        ("parameters", parameters_table(st)),
        ("checks", checks),
        ("taylor", taylor),
        ("tracking", tracking),
        ("omega_sweep", sweep),
        ("vw_search", vw),
        ("kalman_runs", runs),
        ("kalman_sweep", ksweep),
        ("robustness", rob),
        ("stability", stab),
        ("abg", abg),
        ("reproduced", rep),
        ("alternatives", alts),
    ):
        write_csv(df, getattr(output, name), d)


if "snakemake" in globals():
    log_to(snakemake.log[0])  # noqa: F821
    main(snakemake.input, snakemake.output, snakemake.params)  # noqa: F821
