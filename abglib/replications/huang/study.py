r"""The study of Huang, Yang and Ma (seed 002): every table its claims and report read.

:class:`HuangStudy` builds, lazily and from the ``huang`` config section and the printed
Tables 1-2 (``data/published/huang``): the ``B_n T`` curves of Figures 2-3, the thermal
error of Figure 4, Tables 1-2 cell by cell with every ENBW route, and the simulated range
track of Figures 5-7 with its summary. Each piece is a
:func:`functools.cached_property`, so a claim re-judged at another value of an assumed
input (the range gate, how the loop is started and its initial range error, the noise
level, the settling band)
recomputes only what it reads.
"""

from __future__ import annotations

from functools import cached_property

import numpy as np
import pandas as pd

from ..._checks import AbglibValueError
from ...analysis import enbw, enbw_numeric, is_stable, pole_radius
from ...common.tables import with_precision
from ...conventions import from_huang, to_huang
from ...design import huang_for_enbw
from ...gains import Gains
from ...simulate import white_noise
from .._claims import Study
from .._numerics import snap
from .enbw_tables import bandwidth_curves, enbw_monte_carlo, table_row
from .printed import (
    C_LIGHT,
    enbw_eq8_two_sided,
    enbw_huang_eq8_13,
    enbw_huang_eq13_as_printed,
    enbw_huang_eq14,
    thermal_sigma,
)
from .simulation import error_metrics, simulate_range_track

__all__ = ["NOISE", "TABLE_CELLS", "HuangStudy"]

#: Tables 1-2: (table, rule) and (column, order) of every cell; rows 2, 10, 20 Hz.
TABLE_CELLS = {
    "tables": {"t1": "type1", "t2": "type2"},
    "columns": {"ab": 2, "abg": 3},
}
#: Measurement-noise levels of the simulation (the paper: "the Gauss noise is added"):
#: ``barton``, the per-pulse error for which the printed thermal formula is exactly the
#: loop's output error (:func:`.printed.measurement_sigma`); ``printed_single_pulse``, the
#: printed formula for one pulse (``F_r / B_n = 1``), sqrt 2 larger.
NOISE = ("barton", "printed_single_pulse")

#: Results that depend on the radar and the printed tables only, shared by every study of
#: the process: the claims re-judge the study at many values of the assumed simulation
#: inputs (gate, start, initial error, v0, noise, duration), none of which they read.
_SHARED: dict = {}


def _shared(key, compute):
    """``compute()``, memoised under ``key`` for the process (the caller copies what it
    could mutate)."""
    if key not in _SHARED:
        _SHARED[key] = compute()
    return _SHARED[key]


class HuangStudy(Study):
    """Seed 002 from the ``huang`` config section and the printed Tables 1-2."""

    doc = "huang"

    # ------------------------------------------------------------------ inputs
    @cached_property
    def radar(self) -> dict:
        return dict(self.cfg["radar"])

    @cached_property
    def dt(self) -> float:
        """``T = 1 / F_r`` (s)."""
        return 1.0 / float(self.radar["fr_hz"])

    @cached_property
    def gate_m(self) -> float:
        """Half-width of the range discriminator's linear region (m): ``c tau / 2`` times
        ``gate_fraction_of_pulse`` (assumed: the paper gives no gate)."""
        fraction = float(self.cfg["gate_fraction_of_pulse"])
        return C_LIGHT * float(self.radar["tau_s"]) / 2.0 * fraction

    def thermal(self, bn_hz, form="printed"):
        """:func:`.printed.thermal_sigma` at the configured radar (m)."""
        r = self.radar
        return thermal_sigma(bn_hz, r["fr_hz"], r["tau_s"], r["snr_db"], r["k"], form=form)

    @cached_property
    def sigma_m(self) -> float:
        """Standard deviation of the simulated per-pulse range noise (m)."""
        noise = self.cfg["simulation"]["noise"]
        if noise not in NOISE:
            raise AbglibValueError(f"huang.simulation.noise must be one of {NOISE}, got {noise!r}")
        fr = float(self.radar["fr_hz"])
        return float(self.thermal(fr, "barton" if noise == "barton" else "printed"))

    # ------------------------------------------------------------------ Tables 1-2
    def printed_value(self, key: str) -> float:
        """A printed number of the transcription, as a float."""
        return float(self.printed(key))

    def cell(self, base: str) -> dict:
        """One printed cell of Tables 1-2 (``'t2.abg.10hz'``): rule, order and the printed
        ENBW, gains (Huang's convention) and xi."""
        table, col, _ = base.split(".")
        order = TABLE_CELLS["columns"][col]
        return {
            "base": base,
            "rule": TABLE_CELLS["tables"][table],
            "order": order,
            "bn_hz": self.printed_value(f"{base}.enbw"),
            "alpha_h": self.printed_value(f"{base}.alpha"),
            "beta_h": self.printed_value(f"{base}.beta"),
            "gamma_h": self.printed_value(f"{base}.gamma") if order == 3 else 0.0,
            "xi": self.printed_value(f"{base}.xi"),
        }

    def printed_gains(self, base: str) -> Gains:
        """The printed gains of one cell, converted to the canonical convention."""
        c = self.cell(base)
        return from_huang(c["alpha_h"], c["beta_h"], c["gamma_h"])

    @cached_property
    def cells(self) -> list[dict]:
        """Every cell of Tables 1-2 that the transcription holds, in table order."""
        keys = set(self.published["key"])
        out = []
        for table in TABLE_CELLS["tables"]:
            for col in TABLE_CELLS["columns"]:
                bases = sorted(
                    {k.rsplit(".", 1)[0] for k in keys if k.startswith(f"{table}.{col}.")},
                    key=lambda b: float(b.split(".")[2].removesuffix("hz")),
                )
                out.extend(self.cell(b) for b in bases)
        return out

    @cached_property
    def _cells_key(self) -> tuple:
        """What :attr:`table_rows` and :attr:`routes` read: ``T`` and the printed cells."""
        return (self.dt, tuple(tuple(sorted(c.items())) for c in self.cells))

    @cached_property
    def table_rows(self) -> pd.DataFrame:
        """Tables 1-2 cell by cell (:func:`.enbw_tables.table_row`), indexed by cell,
        with the ENBW of an unstable set read with the canonical gamma (no factor 2)."""
        return _shared(("table_rows", self._cells_key), self._table_rows).copy()

    def _table_rows(self) -> pd.DataFrame:
        rows = []
        for c in self.cells:
            row = {"cell": c["base"]}
            row.update(
                table_row(
                    c["rule"], c["order"], c["bn_hz"], c["alpha_h"], c["beta_h"],
                    c["gamma_h"], c["xi"], self.dt,
                )
            )  # fmt: skip
            alt = Gains(c["alpha_h"], c["beta_h"], c["gamma_h"])
            row["enbw_if_gamma_canonical"] = (
                float(enbw(alt, self.dt)) if not row["stable_jury"] and is_stable(alt) else np.nan
            )
            rows.append(row)
        return pd.DataFrame(rows).set_index("cell", drop=False)

    @cached_property
    def tables12(self) -> pd.DataFrame:
        """:attr:`table_rows` plus a Monte Carlo ENBW of every stable printed set."""
        mc = self.cfg["monte_carlo"]
        out = self.table_rows.copy()
        est, se = [], []
        for i, c in enumerate(self.cells):
            if out.loc[c["base"], "stable_jury"]:
                e, s = enbw_monte_carlo(
                    self.printed_gains(c["base"]), self.dt, mc["runs"], mc["samples"],
                    mc["burn_in"], int(mc["seed"]) + i,
                )  # fmt: skip
            else:
                e = s = np.nan
            est.append(e)
            se.append(s)
        out["enbw_mc"] = est
        out["enbw_mc_se"] = se
        return out.reset_index(drop=True)

    @cached_property
    def routes(self) -> pd.DataFrame:
        """ENBW (Hz) of the printed (stable) and nominal gains of every cell, by every
        independent route (Lyapunov, quadrature, impulse sum, eq 8 as printed, the closed
        forms: eq 14, eq 13 reconstructed and as printed, eqs 11-12)."""
        return _shared(("routes", self._cells_key), self._routes).copy()

    def _routes(self) -> pd.DataFrame:
        rows = []
        for c in self.cells:
            sets = {"printed": (c["alpha_h"], c["beta_h"], c["gamma_h"])}
            sets["nominal"] = to_huang(huang_for_enbw(c["bn_hz"], self.dt, c["rule"], c["order"]))
            for which, (a, b, gh) in sets.items():
                g = from_huang(a, b, gh)
                if not is_stable(g):
                    continue
                row = {"cell": c["base"], "gains": which, "alpha": a, "beta": b, "gamma_h": gh}
                row["exact_lyapunov"] = float(enbw(g, self.dt))
                row["numeric_integral"] = float(enbw_numeric(g, self.dt, "integral"))
                row["impulse_sum"] = float(enbw_numeric(g, self.dt, "impulse"))
                row["eq8_two_sided"] = float(enbw_eq8_two_sided(g, self.dt))
                row["eq14"] = np.nan
                row["eq13_reconstructed"] = row["eq13_as_printed"] = np.nan
                row["eq11_12_reconstructed"] = np.nan
                if c["order"] == 2:
                    row["eq14"] = float(enbw_huang_eq14(a, b, self.dt))
                else:
                    row["eq13_reconstructed"] = float(enbw_huang_eq8_13(a, b, gh, self.dt))
                    row["eq13_as_printed"] = enbw_huang_eq13_as_printed(a, b, gh, self.dt)
                    try:
                        row["eq11_12_reconstructed"] = float(
                            enbw_huang_eq8_13(a, b, gh, self.dt, method="eq11_12")
                        )
                    except ValueError:
                        pass
                rows.append(row)
        return pd.DataFrame(rows)

    # ------------------------------------------------------------------ Figs 2-4
    @cached_property
    def curves(self) -> pd.DataFrame:
        """``B_n T`` against ``xi`` (Figures 2-3) on the configured grid."""
        g = self.cfg["xi_grid"]
        return bandwidth_curves(np.linspace(g["start"], g["stop"], g["n"]), self.dt)

    @cached_property
    def thermal_table(self) -> pd.DataFrame:
        """Thermal-noise error against ENBW (Figure 4), printed and Barton's form."""
        e = self.cfg["enbw_grid_hz"]
        bn = np.geomspace(e["start"], e["stop"], e["n"])
        return pd.DataFrame(
            {
                "enbw_hz": bn,
                "sigma_printed_m": self.thermal(bn),
                "sigma_barton_m": self.thermal(bn, "barton"),
            }
        )

    # ------------------------------------------------------------------ Figs 5-7
    @cached_property
    def trackers(self) -> dict:
        """The loops of Figures 5-7 (canonical gains), named as in ``track.csv``.

        Fig 5 (type II, ``fig5_enbw_hz``): the alpha-beta gains as printed, the
        alpha-beta-gamma ones as printed and at a true ``fig5_enbw_hz``; the 2 Hz sentence
        (``low_enbw_hz``): alpha-beta as printed, alpha-beta-gamma at a true 2 Hz; Figs 6-7:
        both rules at the true ``residual_enbw_hz``.
        """
        sim = self.cfg["simulation"]
        f5, lo = sim["fig5_enbw_hz"], sim["low_enbw_hz"]

        def designed(bn, rule):
            # designed gains carry the BLAS kernel's last bits (their ENBW is solved through
            # a Lyapunov equation): snapped, the simulated tracks are the same on any machine
            return _shared(
                ("designed", float(bn), self.dt, rule),
                lambda: Gains(*(float(snap(v)) for v in huang_for_enbw(bn, self.dt, rule, 3))),
            )

        out = {
            f"ab_t2_{f5:g}_printed": self.printed_gains(f"t2.ab.{f5:g}hz"),
            f"abg_t2_{f5:g}_printed": self.printed_gains(f"t2.abg.{f5:g}hz"),
            f"abg_t2_{f5:g}": designed(f5, "type2"),
            f"ab_t2_{lo:g}_printed": self.printed_gains(f"t2.ab.{lo:g}hz"),
            f"abg_t2_{lo:g}": designed(lo, "type2"),
        }
        for rule in ("type1", "type2"):
            for bn in sim["residual_enbw_hz"]:
                out[f"abg_t{rule[-1]}_{bn:g}"] = designed(bn, rule)
        return out

    @cached_property
    def track(self) -> pd.DataFrame:
        """The simulated range track of every loop of :attr:`trackers` (seeded)."""
        sim, tgt = self.cfg["simulation"], self.cfg["target"]
        n = int(round(sim["duration_s"] / self.dt))
        return simulate_range_track(
            self.trackers, self.dt, n, tgt["accel"], tgt["jerk"], self.sigma_m,
            int(sim["seed"]), tgt["r0"], tgt["v0"], start=sim["start"],
            initial_range_error=float(sim["initial_range_error_m"]),
        )  # fmt: skip

    @cached_property
    def metrics(self) -> pd.DataFrame:
        """Summary of every run (:func:`.simulation.error_metrics`), indexed by tracker,
        with ``lost`` against the assumed gate :attr:`gate_m`."""
        rows = []
        frac = self.cfg["simulation"]["settle_fraction"]
        for name, g in self.trackers.items():
            m = error_metrics(
                self.track["t"], self.track[f"lag_{name}"], self.track[f"err_{name}"],
                self.gate_m, frac,
            )  # fmt: skip
            a, b, gh = to_huang(g)
            rows.append(
                {
                    "tracker": name,
                    "sigma_measurement_m": self.sigma_m,
                    "gate_m": self.gate_m,
                    "alpha": a,
                    "beta": b,
                    "gamma_h": gh,
                    "enbw_hz": _shared(("enbw", g, self.dt), lambda g=g: float(enbw(g, self.dt))),
                    "pole_radius": _shared(("pole_radius", g), lambda g=g: float(pole_radius(g))),
                    **m,
                }
            )
        return pd.DataFrame(rows).set_index("tracker", drop=False)

    # ------------------------------------------------------------------ checks
    @cached_property
    def random_checks(self) -> tuple:
        """Seeded inputs of the eq 2-6 checks (``checks_seed``): a unit white-noise input
        (64 samples) and 50 random stable gain sets (Huang's convention)."""
        rng = np.random.default_rng(int(self.cfg["checks_seed"]))
        z = white_noise(64, 1.0, rng)
        sets = []
        for _ in range(50):
            a = rng.uniform(0.05, 0.95)
            b = rng.uniform(0.01, 0.5) * a
            gh = rng.uniform(0.0, 0.5) * a * b / 2  # inside Jury's alpha beta > gamma (2 - alpha)
            sets.append((float(a), float(b), float(gh)))
        return z, sets

    # ------------------------------------------------------------------ tables
    def tables(self) -> dict[str, pd.DataFrame]:
        return {
            "bandwidth_curves": self.curves,
            "thermal": self.thermal_table,
            "tables12": self.tables12,
            "enbw_routes": self.routes,
            "track": self.track,
            # the slope of an alpha-beta-gamma loop's noise-free error is round-off; the
            # radius of a triple pole (type II) is known to ~eps^(1/3) only; lag_end of a
            # converged loop to ~1e-9 relative
            "track_metrics": with_precision(
                self.metrics.reset_index(drop=True), lag_slope="<1e-8", lag_end=6, pole_radius=4
            ),
        }
