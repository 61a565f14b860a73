"""The study of seed 000 (Steelman 1978): everything its claims and report tables need.

Steelman's general closed forms (eqs 50-55, the Jury conditions, eq 49) are analysis of
the canonical tracker and live in :mod:`abglib.analysis`; the table of agreement of every
numbered equation is :mod:`.equations`. This module holds what is specific to the
document: the gains of Tables 1-2, the design example of p. 8 (twice: from the exact
-3 dB frequency and from the printed graph readings), Tables 3-5, and the numbers behind
its statements about the figures (Figs. 3-4 text, the straight-line and midpoint remarks
before eqs 53-54), each computed once (:func:`functools.cached_property`).

Printed numbers come from ``data/published/steelman1978`` (:meth:`SteelmanStudy.value`),
every other input from the ``steelman1978`` config section. Two words of the text are
given a number there: how many dB apart two curves may be and still be "very similar"
(``judging.similar_db``) and how far an approximation may be off and still be "good" or
"near" (``judging.approx_rtol``); both have a plausible range.
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import cached_property

import numpy as np
import pandas as pd

from ... import analysis as A
from ... import design
from ..._checks import AbglibValueError
from ...common.tables import ROUNDOFF, with_precision
from ...engine import track
from ...gains import Gains
from ...verdicts import parse_printed
from .._claims import Study
from .equations import equation_table, stability_table

__all__ = ["SteelmanStudy", "fading_memory_weights"]


def wt_grid(grid: Mapping, kind: str) -> np.ndarray:
    """omega*T grid from a config grid ``{start, stop_over_pi, n}``.

    ``kind='linear'``: evenly spaced; ``'log'``: log-spaced (``start`` must be > 0).
    """
    start, stop, n = float(grid["start"]), float(grid["stop_over_pi"]) * np.pi, int(grid["n"])
    if kind == "linear":
        return np.linspace(start, stop, n)
    if kind == "log":
        if start <= 0:
            raise AbglibValueError(f"a log grid needs start > 0, got {start!r}")
        return np.geomspace(start, stop, n)
    raise AbglibValueError(f"kind must be one of ['linear', 'log'], got {kind!r}")


def fading_memory_weights(theta: float, degree: int, n: int) -> np.ndarray:
    """Weights of the exponentially weighted least-squares polynomial fit (seed 000, p. 4).

    The fit of degree ``degree`` to the data ``z[n-k]``, k = 0, 1, ..., weighted by
    ``theta**k``: with the fit written ``p(t) = sum_j c_j t^j`` (t = 0 at the newest
    sample, t = -k at ``z[n-k]``), row ``j`` holds the weights of ``c_j`` on ``z[n-k]``
    for k < ``n`` (``theta**n`` must be negligible). ``c_0`` is the smoothed position,
    ``c_1`` the velocity, ``2 c_2`` the acceleration.

    Returns
    -------
    array (degree + 1, n)
    """
    k = np.arange(n, dtype=float)
    w = theta**k
    V = np.vander(-k, degree + 1, increasing=True)
    M = V.T @ (w[:, None] * V)
    return np.linalg.solve(M, (V * w[:, None]).T)


class SteelmanStudy(Study):
    """Seed 000 at one configuration (``config['steelman1978']``)."""

    doc = "steelman1978"

    # ----------------------------------------------------------------- inputs
    def value(self, key: str) -> float:
        """The printed number of one published key, as a float."""
        return float(parse_printed(self.printed(key)))

    def std(self, alpha: float, order: int = 3) -> Gains:
        """Standard (critically damped) gains: eqs 22-24 (order 3), p. 5 (order 2)."""
        return design.standard_from_alpha(float(alpha), order)

    @cached_property
    def table_alphas(self) -> list[float]:
        """The alphas of Tables 3-5 (and Fig. 2)."""
        return [float(a) for a in self.cfg["table345_alphas"]]

    @cached_property
    def check_alphas(self) -> list[float]:
        """The alphas where the equation checks and the trend claims are evaluated."""
        return sorted(float(a) for a in self.cfg["equation_checks"]["alphas"])

    @property
    def judging(self):
        return self.cfg["judging"]

    @cached_property
    def wt_log(self) -> np.ndarray:
        return wt_grid(self.cfg["grids"]["log"], "log")

    @cached_property
    def wt_linear(self) -> np.ndarray:
        return wt_grid(self.cfg["grids"]["linear"], "linear")

    # ----------------------------------------------------------------- Tables 1-2
    @cached_property
    def t1_alpha(self) -> float:
        return float(self.cfg["table1"]["alpha"])

    @cached_property
    def t2_alpha(self) -> float:
        return float(self.cfg["table2"]["alpha"])

    @cached_property
    def qd_m_t1(self) -> float:
        """The m of eq 28 that gives Table 1's α exactly."""
        return float(design.qd_m_from_alpha(self.t1_alpha))

    @cached_property
    def qd_t1(self) -> Gains:
        return design.qd(self.qd_m_t1)

    @cached_property
    def qd_printed_m(self) -> Gains:
        """QD gains with the m printed after Table 1."""
        return design.qd(self.value("text.qd_m_alpha_0.3"))

    @cached_property
    def qd_t2(self) -> Gains:
        return design.qd(float(self.cfg["table2"]["qd_m"]))

    @cached_property
    def gains(self) -> pd.DataFrame:
        """The gain sets of Tables 1-2 / Figs. 5-6 as reproduced (exact, unrounded)."""
        t1, t2 = self.t1_alpha, self.t2_alpha
        m_printed = self.printed("text.qd_m_alpha_0.3")
        sets = [
            ("Table 1", "standard α-β-γ", f"α = {t1:g}", self.std(t1)),
            ("Table 1", "standard α-β", f"α = {t1:g}", self.std(t1, 2)),
            ("Table 1", "QD", f"m = {self.qd_m_t1:.4f} (gives α = {t1:g})", self.qd_t1),
            ("Table 1", "QD", f"m = {m_printed} (as printed)", self.qd_printed_m),
            ("Table 2", "standard α-β-γ", f"α = {t2:g}", self.std(t2)),
            (
                "Table 2",
                "standard α-β-γ",
                f"α = α_QD({self.cfg['table2']['qd_m']:g}) = {self.qd_t2.alpha:.5f}",
                self.std(self.qd_t2.alpha),
            ),
            ("Table 2", "standard α-β", f"α = {t2:g}", self.std(t2, 2)),
            ("Table 2", "QD", f"m = {self.cfg['table2']['qd_m']:g}", self.qd_t2),
        ]
        return pd.DataFrame(
            [
                {
                    "table": t,
                    "tracker": k,
                    "defined_by": d,
                    "alpha": g.alpha,
                    "beta": g.beta,
                    "gamma": g.gamma,
                }
                for t, k, d, g in sets
            ]
        )

    # ----------------------------------------------------------------- design example
    @cached_property
    def g_de(self) -> Gains:
        return self.std(self.cfg["design_example"]["alpha"])

    @cached_property
    def wt_edge(self) -> float:
        """Exact ωT where |X̄/X| of the design example's tracker is at the pass-band level."""
        return float(A.omega_at_gain(self.g_de, self.cfg["design_example"]["passband_level_db"]))

    def T_from(self, wt_edge: float) -> float:
        """Sample interval that puts ``wt_edge`` at the pass-band frequency (step 1)."""
        return wt_edge / (2.0 * np.pi * self.cfg["design_example"]["passband_hz"])

    @property
    def ratio(self) -> float:
        de = self.cfg["design_example"]
        return de["interference_hz"] / de["passband_hz"]

    def atten_db(self, wt) -> float:
        """dB down of |X̄/X| of the design example's tracker at ``wt``."""
        return float(-20.0 * np.log10(abs(A.frequency_response(self.g_de, "x_smooth", wt))))

    @cached_property
    def wt_max_de(self) -> float:
        """ωT of the pass-band peak, the offset d of the first undesired maximum."""
        return float(A.peak(self.g_de)[0])

    @staticmethod
    def omega_first_max(offset: float, T: float) -> float:
        """(2π - d)/T, step 3."""
        return (2.0 * np.pi - offset) / T

    @cached_property
    def design_routes(self) -> dict[str, dict[str, float]]:
        """The design example computed twice: the exact chain and the printed arithmetic
        (the paper continues from its graph readings ωT = .135 and d = .04 and from T
        rounded to .0043)."""
        out = {}
        for name in ("exact chain (abglib)", "printed arithmetic"):
            if name.startswith("exact"):
                wt, d = self.wt_edge, self.wt_max_de
                T = T_used = self.T_from(wt)
            else:
                wt, d = self.value("design.wT_3db"), self.value("design.first_max_offset")
                T, T_used = self.T_from(wt), self.value("design.T")
            om = self.omega_first_max(d, T_used)
            out[name] = {
                "wT_3dB": wt,
                "T_s": T,
                "rate_per_s": 1.0 / T,
                "wT_60Hz": self.ratio * wt,
                "atten_60Hz_dB": self.atten_db(self.ratio * wt),
                "d": d,
                "omega_first_max": om,
                "f_first_max_Hz": om / (2 * np.pi),
            }
        return out

    @property
    def design_exact(self) -> dict[str, float]:
        return self.design_routes["exact chain (abglib)"]

    @property
    def design_printed(self) -> dict[str, float]:
        return self.design_routes["printed arithmetic"]

    @cached_property
    def design_example(self) -> pd.DataFrame:
        return pd.DataFrame([{"route": k, **v} for k, v in self.design_routes.items()])

    # ----------------------------------------------------------------- Tables 3-5
    def table345_row(self, alpha: float) -> dict[str, float]:
        """Printed-formula and exact values of Tables 3-5 at one α (standard α-β-γ)."""
        e6 = self.cfg["eq53_exponent_6db"]
        g = self.std(alpha)
        wmax, over = A.peak(g)
        key = f"table3.exact.{alpha:g}"
        printed = self.value(key) if key in set(self.published["key"]) else np.nan
        at_printed = -self.magnitude_db(g, "x_smooth", printed) if np.isfinite(printed) else np.nan
        return {
            "alpha": float(alpha),
            "beta": g.beta,
            "gamma": g.gamma,
            "wT_6dB_eq53": float(A.omega_3db_eq53(g, e6)),
            "wT_6dB_exact": float(A.omega_at_gain(g, 20 * e6)),
            "wT_half_exact": float(A.omega_at_gain(g, 20 * np.log10(0.5))),
            "wT_6dB_printed_exact": printed,
            "dB_down_at_printed_exact": float(at_printed),
            "overshoot_eq55": float(A.overshoot_eq55(g)),
            "overshoot_exact": float(over),
            "wTmax_eq54": float(A.omega_max_eq54(g)),
            "wTmax_exact": float(wmax),
        }

    @cached_property
    def tables345(self) -> pd.DataFrame:
        """Tables 3-5 side by side: printed-formula and exact values per α."""
        return pd.DataFrame([self.table345_row(a) for a in self.table_alphas])

    # ----------------------------------------------------------------- equations
    @cached_property
    def equations(self) -> pd.DataFrame:
        exps = [self.cfg["eq53_exponent_3db"], self.cfg["eq53_exponent_6db"]]
        return equation_table(self.cfg["equation_checks"], exps)

    @cached_property
    def stability(self) -> pd.DataFrame:
        return stability_table(self.cfg["equation_checks"])

    # ----------------------------------------------------------------- figure statements
    def magnitude_db(self, gains: Gains, output: str, wt, scale: float = 1.0) -> np.ndarray:
        h = np.asarray(A.frequency_response(gains, output, wt))
        return 20.0 * np.log10(scale * np.abs(h))

    @cached_property
    def fig3_gap(self) -> tuple[float, float]:
        """max |20 log |X_p/X| - 20 log |X̄/X|| over the log grid (Fig. 3, α of Table 1),
        and the ωT where it occurs."""
        g = self.std(self.t1_alpha)
        d = np.abs(
            self.magnitude_db(g, "x_pred", self.wt_log)
            - self.magnitude_db(g, "x_smooth", self.wt_log)
        )
        i = int(np.argmax(d))
        return float(d[i]), float(self.wt_log[i])

    @cached_property
    def fig4_scale(self) -> float:
        """The factor of T²Ā/X in Fig. 4 (200, from the figure's config)."""
        curves = self.cfg["figures"]["fig4"]["curves"]
        return float(next(c.get("scale", 1.0) for c in curves if c["output"] == "a_smooth"))

    @cached_property
    def fig4_alpha(self) -> float:
        curves = self.cfg["figures"]["fig4"]["curves"]
        return float(next(c["alpha"] for c in curves if c["output"] == "a_smooth"))

    @cached_property
    def fig4_gap(self) -> tuple[float, float, np.ndarray, np.ndarray]:
        """|dB difference| of |X̄/X| and |scale·T²Ā/X| (Fig. 4) on the log grid: the max over
        ωT above the printed bound and where, and the whole curve ``(wt, diff)``."""
        g = self.std(self.fig4_alpha)
        wt = self.wt_log
        d = np.abs(
            self.magnitude_db(g, "a_smooth", wt, self.fig4_scale)
            - self.magnitude_db(g, "x_smooth", wt)
        )
        above = wt > float(self.judging["fig4_above_wT"])
        i = int(np.argmax(np.where(above, d, -np.inf)))
        return float(d[i]), float(wt[i]), wt, d

    def similar_from(self, threshold_db: float) -> float:
        """The ωT above which Fig. 4's two magnitudes stay within ``threshold_db``."""
        _, _, wt, d = self.fig4_gap
        bad = np.nonzero(d > threshold_db)[0]
        return float(wt[0]) if bad.size == 0 else float(wt[min(bad[-1] + 1, wt.size - 1)])

    @cached_property
    def straight_line(self) -> dict[float, float]:
        """Per table α: max dB deviation of 20 log|X̄/X| from the straight line (in log ωT)
        between the ωT where |X̄/X| = 1 (eq 51) and ωT = π (the minimum, eq 50)."""
        out = {}
        n = int(self.cfg["grids"]["log"]["n"])
        for a in self.table_alphas:
            g = self.std(a)
            w1 = float(A.omega_at_gain(g, 0.0))
            wt = np.geomspace(w1, np.pi, n)
            m = self.magnitude_db(g, "x_smooth", wt)
            chord = np.interp(np.log(wt), [np.log(w1), np.log(np.pi)], [m[0], m[-1]])
            out[a] = float(np.max(np.abs(m - chord)))
        return out

    @cached_property
    def approximations(self) -> pd.DataFrame:
        """Per table α: eq 52 against the exact unity-gain ωT, eq 53 (-3 dB as printed)
        against the exact -3 dB ωT, the peak's ωT over the unity-gain ωT (the "midpoint"
        remark before eq 54), eq 55 against the exact overshoot."""
        rows = []
        e3 = self.cfg["eq53_exponent_3db"]
        for a in self.table_alphas:
            g = self.std(a)
            w1 = float(A.omega_at_gain(g, 0.0))
            w3 = float(A.omega_at_gain(g, 20 * e3))
            wmax, over = (float(v) for v in A.peak(g))
            rows.append(
                {
                    "alpha": a,
                    "wT_unity": w1,
                    "wT_unity_eq52": float(A.omega_unity_eq52(g)),
                    "wT_3dB": w3,
                    "wT_3dB_eq53": float(A.omega_3db_eq53(g, e3)),
                    "wTmax_over_wT_unity": wmax / w1,
                    "overshoot": over,
                    "overshoot_eq55": float(A.overshoot_eq55(g)),
                }
            )
        t = pd.DataFrame(rows)
        t["eq52_rel_err"] = (t["wT_unity_eq52"] / t["wT_unity"] - 1).abs()
        t["eq53_rel_err"] = (t["wT_3dB_eq53"] / t["wT_3dB"] - 1).abs()
        t["midpoint_rel_err"] = (2 * t["wTmax_over_wT_unity"] - 1).abs()
        t["eq55_rel_err"] = (t["overshoot_eq55"] / t["overshoot"] - 1).abs()
        return t

    @cached_property
    def attenuation_trend(self) -> list[tuple[float, float]]:
        """(α, dB down of |X̄/X| at the design example's 60 Hz ωT) for the checked alphas."""
        wt60 = self.design_exact["wT_60Hz"]
        return [
            (a, float(-self.magnitude_db(self.std(a), "x_smooth", wt60))) for a in self.check_alphas
        ]

    @cached_property
    def cubic(self) -> dict[float, tuple[int, float, float]]:
        """Per table α: the degree in q = |z - 1|² = 2 - 2cos ωT of |N|² - |Δ|²/2 (the
        condition |X̄/X| = 0.707 of eqs 36, 40), found by sampling and fitting; its root
        in (0, 4) as ωT; and the exact 1/√2 crossing for comparison."""
        out = {}
        q = np.linspace(0.05, 3.95, 13)
        wt = 2.0 * np.arcsin(np.sqrt(q) / 2.0)
        z = np.exp(1j * wt)
        for a in self.table_alphas:
            al, be, ga = (float(v) for v in self.std(a))
            num = np.abs(z * (al * (z - 1) ** 2 + (be + ga / 2) * (z - 1) + ga)) ** 2
            den = (
                np.abs((z - 1) ** 3 + al * (z - 1) ** 2 + (be + ga / 2) * z * (z - 1) + ga * z) ** 2
            )
            coef = np.polynomial.polynomial.polyfit(q, num - 0.5 * den, 6)
            scale = np.max(np.abs(coef))
            degree = int(np.max(np.nonzero(np.abs(coef) > 1e-9 * scale)[0]))
            roots = np.polynomial.polynomial.polyroots(coef[: degree + 1])
            real = roots[(np.abs(roots.imag) < 1e-9) & (roots.real > 0) & (roots.real < 4)].real
            root_wt = float(2.0 * np.arcsin(np.sqrt(real.min()) / 2.0)) if real.size else np.nan
            exact = float(A.omega_at_gain(self.std(a), 20 * np.log10(np.sqrt(0.5))))
            out[a] = (degree, root_wt, exact)
        return out

    # ----------------------------------------------------------------- definitions
    @cached_property
    def fading_memory(self) -> dict[tuple[int, float], float]:
        """(order, α) -> max |impulse response of the standard tracker - weights of the
        exponentially weighted least-squares fit| over position, velocity (and
        acceleration), for the table alphas (seed 000, p. 4 and p. 5)."""
        out = {}
        for order in (3, 2):
            for a in self.table_alphas:
                g = self.std(a, order)
                theta = float(design.standard_theta_from_alpha(a, order))
                n = int(np.ceil(np.log(1e-17) / np.log(theta)))
                C = fading_memory_weights(theta, order - 1, n)
                z = np.zeros(n)
                z[0] = 1.0
                r = track(z, g)
                err = [np.abs(r.x_smooth - C[0]), np.abs(r.v_smooth - C[1])]
                if order == 3:
                    err.append(np.abs(r.a_smooth - 2.0 * C[2]))
                out[(order, a)] = float(max(e.max() for e in err))
        return out

    @cached_property
    def simpson_limit(self) -> dict[float, float]:
        """Per table α: worst relative difference between Simpson's eqs 11-12 and 15-16 at
        γ = 1e-9 β (the standard α-β gains) and the α-β results (Lyapunov VRF, summed D²)."""
        out = {}
        for a in self.table_alphas:
            ab = self.std(a, 2)
            near = Gains(ab.alpha, ab.beta, 1e-9 * ab.beta)
            s, d = A.vrf_simpson(near), A.transient_d2_simpson(near)
            v, e = A.vrf(ab), A.transient_d2(ab)
            pairs = [
                (s["x"], v["x_smooth"]),
                (s["v"], v["v_smooth"]),
                (d["x"], e["x"]),
                (d["v"], e["v"]),
            ]
            out[a] = float(max(abs(p / x - 1) for p, x in pairs))
        return out

    # ----------------------------------------------------------------- abstract
    @cached_property
    def abstract_0707(self) -> pd.DataFrame:
        """Per table α: the ωT where |X̄/X| = 0.707 (the abstract's level, as printed),
        found by Brent's method on the frequency response between the passband peak and
        ωT = π, against eq 53 as printed (exponent -.15), the only equation the report
        gives for that frequency (seed 000, abstract and eq 53; the text before eq 51 says
        the exact solution needs a cubic)."""
        from scipy.optimize import brentq

        level = 0.707
        e3 = self.cfg["eq53_exponent_3db"]
        rows = []
        for a in self.table_alphas:
            g = self.std(a)
            lo = float(A.peak(g)[0])

            def gap(w, g=g):
                return float(abs(A.frequency_response(g, "x_smooth", w))) - level

            w = float(brentq(gap, lo, np.pi, xtol=1e-15, rtol=4 * np.finfo(float).eps))
            w53 = float(A.omega_3db_eq53(g, e3))
            rows.append({"alpha": a, "wT_0707": w, "wT_eq53": w53, "rel_err": abs(w53 / w - 1)})
        return pd.DataFrame(rows)

    # ----------------------------------------------------------------- report tables
    def tables(self) -> dict[str, pd.DataFrame]:
        return {
            "gains": self.gains,
            "design_example": self.design_example,
            "tables345": self.tables345,
            "approximations": self.approximations,
            # rel_diff of an exact equation is round-off: written as the bound
            "equations": with_precision(self.equations, rel_diff=f"<{ROUNDOFF:g}"),
            "stability": self.stability,
        }
