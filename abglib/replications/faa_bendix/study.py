"""The study of seed 003: every table the FAA Bendix report shows and the claims read.

Gains, periods and scale factors come from the transcription (:mod:`.printed`), every
other input from the ``faa_bendix`` config section. Each table is a cached property, so
that a claim recomputed at another value of an assumed input pays only for what it uses.
"""

from __future__ import annotations

from functools import cached_property

import numpy as np
import pandas as pd

from ...analysis import vrf
from ...gains import Gains
from ...verdicts import parse_printed, tolerance_from_printed
from .._claims import Study
from . import printed
from . import program as bendix

__all__ = ["TABLES", "FaaBendixStudy"]

#: Report tables of the study (``results/faa_bendix/<stem>.csv``).
TABLES = (
    "responses",
    "gains",
    "memo_table",
    "rounding",
    "row7",
    "damping_lags",
    "captions",
)
#: The two gain tables: the memo's (three decimals) and the captions' (two decimals).
GAIN_TABLES = ("memo", "captions")


class FaaBendixStudy(Study):
    """Seed 003: the test program's runs, the memo's table, the captions, damping and lags."""

    doc = "faa_bendix"

    # ------------------------------------------------------------------ printed inputs
    @cached_property
    def periods(self) -> list[int]:
        return [int(p) for p in self.cfg["periods"]]

    @cached_property
    def memo_gains(self) -> pd.DataFrame:
        return printed.memo_gains(self.published)

    @cached_property
    def caption_values(self) -> pd.DataFrame:
        return printed.captions(self.published)

    def caption(self, kind: str, period: int) -> pd.Series:
        c = self.caption_values
        return c[(c["input"] == kind) & (c["period_s"] == period)].iloc[0]

    def gains(self, period: int, table: str = "memo", kind: str = "impulse") -> Gains:
        """The memo's gain set of a period, or the one the ``kind`` captions print."""
        if table == "memo":
            r = self.memo_gains.loc[period]
        else:
            r = self.caption(kind, period)
        return Gains(float(r["alpha"]), float(r["beta"]))

    def input(self, kind: str, period: int) -> np.ndarray:
        """The program's test input for one period (config: samples, ramp rise)."""
        c = self.cfg
        return bendix.program_input(
            kind, int(c["samples"]), float(period), int(c["ramp_rise_samples"])
        )

    # ------------------------------------------------------------------ the program
    @cached_property
    def responses(self) -> pd.DataFrame:
        """Impulse and ramp responses of every gain set of both tables (long table)."""
        c = self.cfg
        frames = []
        for table in GAIN_TABLES:
            for p in self.periods:
                for kind in bendix.INPUTS:
                    g = self.gains(p, table, kind)
                    r = bendix.responses(
                        g, float(p), int(c["samples"]), int(c["ramp_rise_samples"]), (kind,)
                    )
                    r.insert(0, "beta", float(g.beta))
                    r.insert(0, "alpha", float(g.alpha))
                    r.insert(0, "period_s", p)
                    r.insert(0, "table", table)
                    frames.append(r)
        return pd.concat(frames, ignore_index=True)

    @cached_property
    def literal_difference(self) -> float:
        """Largest |literal transcription - abglib.track| over every run and graph."""
        worst = 0.0
        for (table, p, kind), d in self.responses.groupby(["table", "period_s", "input"]):
            g = self.gains(p, table, kind)
            lit = bendix.run_test_program(d["z"].to_numpy(), g.alpha, g.beta, float(p))
            for out in bendix.GRAPHS:
                worst = max(worst, float(np.max(np.abs(lit[out] - d[out].to_numpy()))))
        return worst

    @cached_property
    def gains_table(self) -> pd.DataFrame:
        """Memo vs caption gains, and the largest response difference they cause (also in
        the captions' SFY divisions)."""
        resp = self.responses
        rows = []
        for p in self.periods:
            m, c = self.gains(p, "memo"), self.gains(p, "captions")
            row = {
                "period_s": p,
                "alpha_memo": m.alpha,
                "beta_memo": m.beta,
                "alpha_captions": c.alpha,
                "beta_captions": c.beta,
            }
            for kind in bendix.INPUTS:
                sel = (resp["period_s"] == p) & (resp["input"] == kind)
                dm = resp[sel & (resp["table"] == "memo")]
                dc = resp[sel & (resp["table"] == "captions")]
                sfy = float(self.caption(kind, p)["sfy"])
                for out in bendix.GRAPHS:
                    diff = float(np.max(np.abs(dm[out].to_numpy() - dc[out].to_numpy())))
                    row[f"maxdiff_{kind}_{out}"] = diff
                    row[f"maxdiff_{kind}_{out}_sfy"] = diff / sfy
            rows.append(row)
        return pd.DataFrame(rows)

    # ------------------------------------------------------------------ the captions
    @cached_property
    def captions_table(self) -> pd.DataFrame:
        """Per caption group: the printed numbers, the memo's gains (printed, rounded and
        truncated to the caption's decimals, and how the two cuts meet:
        :func:`~abglib.replications.faa_bendix.printed.cut_kind`), the nearest memo period,
        the input's peak and the reconstructed SFY at ``plot_divisions``."""
        memo = self.memo_gains
        div = float(self.cfg["plot_divisions"])
        rows = []
        for c in self.caption_values.itertuples(index=False):
            m = memo.loc[c.period_s]
            dist = np.maximum(np.abs(memo["alpha"] - c.alpha), np.abs(memo["beta"] - c.beta))
            peak = float(np.max(np.abs(self.input(c.input, c.period_s))))
            row = {"input": c.input, "period_s": c.period_s, "T": c.T, "sfy": c.sfy}
            for name in ("alpha", "beta"):
                cap, pm = getattr(c, f"{name}_printed"), m[f"{name}_printed"]
                row[name] = getattr(c, name)
                row[f"{name}_memo"] = float(m[name])
                row[f"{name}_memo_rounded"] = printed.round_half_up(pm, cap)
                row[f"{name}_memo_truncated"] = printed.truncate(pm, cap)
                row[f"{name}_memo_cut"] = printed.cut_kind(pm, cap)
            row["nearest_memo_period"] = int(dist.idxmin())
            row["input_peak"] = peak
            row["input_peak_in_sfy"] = peak / c.sfy
            row["sfy_reconstructed"] = bendix.power_of_ten_scale(peak, div)
            rows.append(row)
        return pd.DataFrame(rows)

    # ------------------------------------------------------------------ the memo
    @cached_property
    def closed_form(self) -> pd.DataFrame:
        """The memo's two columns by closed form (both gain tables) and by Lyapunov."""
        rows = []
        for p in self.periods:
            row = {"period_s": p}
            for table in GAIN_TABLES:
                g = self.gains(p, table)
                cf = bendix.memo_ratios(g.alpha, g.beta, p)
                sfx = "" if table == "memo" else "_captions"
                row[f"alpha{sfx}"], row[f"beta{sfx}"] = g.alpha, g.beta
                row[f"position_closed{sfx}"] = cf["position"]
                row[f"velocity_closed{sfx}"] = cf["velocity"]
            ly = vrf(self.gains(p), dt=p)
            row["position_lyapunov"] = float(np.sqrt(ly["x_smooth"]))
            row["velocity_lyapunov"] = float(np.sqrt(ly["v_smooth"]))
            # the alternative reading of the second column: per sample (sqrt(k_v) T)
            row["velocity_per_sample"] = row["velocity_closed"] * p
            for k in ("position", "velocity"):
                row[f"{k}_published"] = float(parse_printed(self.printed(f"memo.T{p}.{k}")))
            rows.append(row)
        return pd.DataFrame(rows).set_index("period_s")

    @cached_property
    def monte_carlo(self) -> pd.DataFrame:
        """Seeded Monte Carlo of the memo's ratios (row i uses seed + i), 95 % CIs and the
        standard score of the variance against the exact (Lyapunov) one."""
        return pd.DataFrame([self.monte_carlo_row(p) for p in self.periods]).set_index("period_s")

    def monte_carlo_row(self, p) -> dict:
        """One period's row of :attr:`monte_carlo` (seed + its index among the periods),
        computed once: a claim that needs one period does not pay for the others."""
        done = self.__dict__.setdefault("_monte_carlo_rows", {})
        if p not in done:
            mc = self.cfg["monte_carlo"]
            g = self.gains(p)
            est = bendix.monte_carlo_ratios(
                g,
                p,
                runs=mc["runs"],
                samples=mc["samples"],
                burn_in=mc["burn_in"],
                seed=int(mc["seed"]) + list(self.periods).index(p),
            )
            ly = vrf(g, dt=p)
            row = {"period_s": p, "mc_samples": est["n"]}
            for k, out in (("position", "x_smooth"), ("velocity", "v_smooth")):
                row[f"{k}_mc"] = est[k]
                row[f"{k}_mc_lo"] = est[f"{k}_lo"]
                row[f"{k}_mc_hi"] = est[f"{k}_hi"]
                row[f"{k}_mc_z"] = (est[f"{k}_var"] - ly[out]) / est[f"{k}_var_se"]
            done[p] = row
        return done[p]

    @cached_property
    def memo_table(self) -> pd.DataFrame:
        """The memo's two columns: printed, closed form, Lyapunov, Monte Carlo (95 % CI)."""
        return self.closed_form.join(self.monte_carlo).reset_index()

    @cached_property
    def rounding(self) -> pd.DataFrame:
        """Per row: the ratio ranges inside the printed rounding of the gains, and the pair
        inside it that best reproduces both printed ratios together."""
        rows = []
        for p in self.periods:
            m = self.memo_gains.loc[p]
            half = max(
                tolerance_from_printed(m["alpha_printed"]),
                tolerance_from_printed(m["beta_printed"]),
            )
            px, pv = self.printed(f"memo.T{p}.position"), self.printed(f"memo.T{p}.velocity")
            r = bendix.rounding_extremes(
                m["alpha"],
                m["beta"],
                p,
                (px, pv),
                (tolerance_from_printed(px), tolerance_from_printed(pv)),
                half_unit=half,
                n=int(self.cfg["rounding_grid"]),
            )
            best_worst = r.pop("best_worst")
            rows.append(
                {"period_s": p, **r}
                | {
                    "best_worst_error_in_tolerances": best_worst,
                    "both_reproduced": bool(best_worst <= 1.0),
                }
            )
        return pd.DataFrame(rows)

    @cached_property
    def row7(self) -> pd.DataFrame:
        """The 7 s row against the trend of the other gain sets.

        Hypotheses for its out-of-trend ratios: (a) the ratios are those of the printed
        gains; (b) the gains are on trend and the ratios a slip (alpha and beta
        interpolated from the other periods by a cubic in T); (c) the velocity column
        belongs to another period T.
        """
        others = [p for p in self.periods if p != 7]
        a = np.array([self.gains(p).alpha for p in others])
        b = np.array([self.gains(p).beta for p in others])
        trend = Gains(
            float(np.polyval(np.polyfit(others, a, 3), 7.0)),
            float(np.polyval(np.polyfit(others, b, 3), 7.0)),
        )
        g = self.gains(7)
        rows = []
        for label, gg, T in (
            ("printed gains (memo), T = 7 s", g, 7.0),
            ("captions' gains, T = 7 s", self.gains(7, "captions"), 7.0),
            ("on-trend gains (cubic through the other periods), T = 7 s", trend, 7.0),
            ("printed gains, velocity per T = 6 s", g, 6.0),
            ("printed gains, velocity per T = 8 s", g, 8.0),
        ):
            r = bendix.memo_ratios(gg.alpha, gg.beta, T)
            rows.append(
                {
                    "hypothesis": label,
                    "alpha": gg.alpha,
                    "beta": gg.beta,
                    "T": T,
                    "position": r["position"],
                    "velocity": r["velocity"],
                    "zeta": bendix.damping(gg.alpha, gg.beta, T)["zeta"],
                }
            )
        return pd.DataFrame(rows)

    # ------------------------------------------------------------------ beyond the source
    @cached_property
    def damping_lags(self) -> pd.DataFrame:
        """Damping class, stability-triangle position and steady-state lags per gain set."""
        rows = []
        for p in self.periods:
            g = self.gains(p)
            d = bendix.damping(g.alpha, g.beta, p)
            lag = bendix.lags(g, p)
            sim = bendix.simulated_lags(g, p, n=int(self.cfg["lag_check_samples"]))
            rows.append(
                {
                    "period_s": p,
                    "alpha": g.alpha,
                    "beta": g.beta,
                    "stable": d["stable"],
                    "beta_upper_limit": 4.0 - 2.0 * g.alpha,
                    "damping": d["cls"],
                    "beta_critical": d["beta_critical"],
                    "beta_benedict": d["beta_benedict"],
                    "beta_over_benedict": g.beta / d["beta_benedict"],
                    "benedict_bordner": d["benedict_bordner"],
                    "pole_radius": d["pole_radius"],
                    "zeta": d["zeta"],
                    **{f"lag_{k}": v for k, v in lag.items()},
                    **{f"lag_{k}_simulated": v for k, v in sim.items()},
                }
            )
        return pd.DataFrame(rows)

    def tables(self) -> dict[str, pd.DataFrame]:
        return {
            "responses": self.responses,
            "gains": self.gains_table,
            "memo_table": self.memo_table,
            "rounding": self.rounding,
            "row7": self.row7,
            "damping_lags": self.damping_lags,
            "captions": self.captions_table,
        }
