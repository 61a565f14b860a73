"""Every published claim of seed 001 (Al-Wagih & Abdulla), one declaration each.

Three kinds of rows:

* Tables 1-2 (``t1.*``, ``t2.*``): absolute RMSEs of trajectories the paper does not
  give - not reproducible whatever the reconstruction (no value, no assumed input); the
  note says where the reconstruction's values are.
* Tables 3-6 (``t3.*`` .. ``t6.*``) and ``claim.printed.*``, ``text.*``: decided by the
  printed Tables 1-2 themselves (arithmetic, rankings, signs, paired t-tests) - no
  assumed input.
* ``claim.t*``, ``claim.conclusion.*``, ``claim.ttest.*``, ``claim.m5.*``: judged on the
  reconstructed experiments, so they declare what they depend on (the reconstruction's
  noise, manoeuvre and colour, alpha_0, the M4 window, the M5 bank, the realisation).
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np

from ... import methods
from ...analysis import is_stable
from ...common.tables import roundoff
from ...gains import Gains
from ...verdicts import format_number, judge, parse_printed
from .. import ClaimSet, Reading, Result
from . import stability
from .printed import BASES, COMPARED, NOISE_OF_TABLE, PAPER_METHODS, printed_values
from .study import AlwagihStudy, rank_methods

CLAIMS = ClaimSet("alwagih")
STUDY = AlwagihStudy

CONSISTENCY_SECTION = "Consistency of the printed tables"
_RECON = ("alwagih.reconstruction.noise_scale", "alwagih.reconstruction.manoeuvre_scale")
_RHO = "alwagih.reconstruction.coloured_rho"
_SETTING = {
    "M1": ("alwagih.m1_alpha",),
    "M2": (),
    "M3": (),
    "M4": ("alwagih.m4.alpha0", "alwagih.m4.window"),
    "M5": ("alwagih.m5.alphas.n",),
}


def _noise(token: str) -> str:
    """'t3' -> 'white', 'coloured' -> 'coloured'."""
    return NOISE_OF_TABLE[int(token[1])] if token.startswith("t") else token


def _deps(noise: str, methods=PAPER_METHODS, realisation: bool = False) -> tuple[str, ...]:
    out = [*_RECON, *([_RHO] if noise == "coloured" else [])]
    for m in methods:
        out.extend(_SETTING[m])
    if realisation:
        out.append("alwagih.realisation")
    return tuple(out)


#: The study's tables computed from the printed numbers alone (shared between studies).
_PRINTED_TABLES = frozenset({"printed_wide", "consistency", "printed_ttests"})


def _row(s, table: str, noise, coord):
    """Experiments x M1-M5 of one noise and coordinate of the study's ``table`` (``mc`` or
    ``printed_wide``), selected once per study (the claims ask for them ~900 times)."""
    wide = getattr(s, table)
    key = ("row", table, noise, coord)
    return s.memo(key, lambda: _select_row(wide, noise, coord), table in _PRINTED_TABLES)


def _select_row(wide, noise, coord):
    return wide.xs(noise, level="noise").xs(coord, level="coord")[list(PAPER_METHODS)]


def _lookup(s, table: str, keys: tuple, values: tuple) -> dict:
    """The row of the study's long ``table`` whose ``keys`` columns equal ``values`` (the
    first, as ``[mask].iloc[0]``), from an index built once per study."""

    def build():
        out = {}
        for r in getattr(s, table).to_dict("records"):
            out.setdefault(tuple(r[k] for k in keys), r)
        return out

    return s.memo(("lookup", table, keys), build, table in _PRINTED_TABLES)[values]


def _expected_positive(base: str, coord: str, method: str) -> bool:
    """Section 7: 'positive in all cases except when we compare M4 with M2 in the Y-coordinate'."""
    return not (base == "M2" and coord == "Y" and method == "M4")


# --------------------------------------------------------------------------- Tables 1-2
@CLAIMS.family(r"t[12]\.e\d\.[XY]\.M[1-5]")
def _t12(s, key):
    """An absolute RMSE of Table 1 or 2: not reproducible whatever the reconstruction.

    The row has no value anywhere, so ``evaluate`` leaves ``depends_on`` and ``robust``
    empty (``shared/CONTRACTS.md`` section 3). The note names where the reconstruction's
    values of the cell are (``table1.csv``/``table2.csv`` and ``mc_rmse.csv``) rather than
    quoting them: they move with the inputs and the draws, the row's verdict does not.
    """
    table = key.split(".")[0]
    return Result(
        None,
        "an absolute RMSE of a trajectory the paper does not give (nor its noise level, "
        "alpha_0, M4 window or M5 bank): no reconstruction can reproduce it; the "
        f"reconstruction's values of this cell are in table{table[1]}.csv and mc_rmse.csv",
    )


# --------------------------------------------------------------------------- Tables 3-6
@CLAIMS.family(r"t[3-6]\.(M[12]|e\d)\.[XY]\.M[345]")
def _t3456(s, key):
    table, row, coord, m = key.split(".")
    t = int(table[1])
    label = row if t in (3, 4) else f"experiment {row[1:]}"
    r = _lookup(s, "consistency", ("table", "row", "coord", "method"), (t, label, coord, m))
    printed = float(parse_printed(s.printed(key)))
    src = 1 if t in (3, 5) else 2
    return Result(
        float(r["central"]),
        f"recomputed from the printed Table {src} (rounding of its entries allows "
        f"{format_number(r['low'], 7)} .. {format_number(r['high'], 7)})",
        (
            Reading(
                f"the same formula on Table {src} entries anywhere inside their printed rounding",
                float(np.clip(printed, r["low"], r["high"])),
                CONSISTENCY_SECTION,
                family="typo:rounded intermediate (the source table's printed entries)",
            ),
        ),
    )


@CLAIMS.claim("text.pc_example")
def _pc_example(s):
    """Section 7: '10.9382 means that RMSE of M4 is 10.9382 % lower with respect to M1'
    (Table 5, experiment 1, X, M4), recomputed from the printed Table 1 by eq 27."""
    c = s.consistency
    r = c[
        (c["table"] == 5)
        & (c["row"] == "experiment 1")
        & (c["coord"] == "X")
        & (c["method"] == "M4")
    ]
    return Result(float(r["central"].iloc[0]), "eq 27 on Table 1, experiment 1, X: M1 and M4")


# --------------------------------------------------------------------------- on the printed tables
@CLAIMS.family(r"claim\.printed\.t[12]\.m5_lowest\.[XY]")
def _p_m5_lowest(s, key):
    table, coord = key.split(".")[2], key.split(".")[4]
    w = _row(s, "printed_wide", _noise(table), coord)
    ok = (w["M5"] < w.drop(columns="M5").min(axis=1)).all()
    margin = (w.drop(columns="M5").min(axis=1) / w["M5"]).min()
    return Result(
        bool(ok),
        f"printed Table {table[1]}: M5 lowest in every experiment: {bool(ok)}; the next best "
        f"is at least {margin:.2f} times M5's RMSE",
    )


@CLAIMS.family(r"claim\.printed\.conclusion\.(white|coloured)\.[XY]")
def _p_conclusion(s, key):
    noise, coord = key.split(".")[3], key.split(".")[4]
    m = _row(s, "printed_wide", noise, coord).mean()
    return Result(
        bool(m["M5"] < m["M4"] < m["M3"]),
        "printed mean RMSE over the five experiments (m): "
        + ", ".join(f"{k} {m[k]:.1f}" for k in PAPER_METHODS)
        + f"; ranking {rank_methods(m.to_dict())}",
    )


@CLAIMS.family(r"claim\.printed\.ttest\.t[34]\.M[12]\.[XY]\.M[345]")
def _p_ttest(s, key):
    _, _, _, table, base, coord, m = key.split(".")
    where = f"printed Table {int(table[1]) - 2}"
    return _ttest_result(s, "printed_ttests", _noise(table), base, coord, m, where)


@CLAIMS.family(r"claim\.printed\.t[34]\.sign\.M[12]\.[XY]\.M[345]")
def _p_sign(s, key):
    _, _, table, _, base, coord, m = key.split(".")
    w = _row(s, "printed_wide", _noise(table), coord)
    d = float((w[base] - w[m]).mean())
    want = _expected_positive(base, coord, m)
    return Result(
        (d > 0) == want,
        f"from the printed Table {int(table[1]) - 2}: average {base} - {m} = {d:.4f} m; section 7 "
        f"says {'positive' if want else 'negative'}",
    )


@CLAIMS.family(r"claim\.printed\.t[34]\.sign_pattern\.(as_printed|from_t[12])")
def _p_sign_pattern(s, key):
    table, how = key.split(".")[2], key.split(".")[4]
    t = int(table[1])
    signs = []
    for base in BASES:
        for coord in ("X", "Y"):
            for m in COMPARED:
                if how == "as_printed":
                    d = float(parse_printed(s.printed(f"{table}.{base}.{coord}.{m}")))
                else:
                    w = _row(s, "printed_wide", _noise(table), coord)
                    d = float((w[base] - w[m]).mean())
                signs.append(((base, coord, m), d))
    wrong = [
        _contrary(b, c, m, f"{d:+.4f}")
        for (b, c, m), d in signs
        if (d > 0) != _expected_positive(b, c, m)
    ]
    src = (
        f"printed Table {t}" if how == "as_printed" else f"Table {t} recomputed from Table {t - 2}"
    )
    return Result(
        not wrong,
        f"{src}: "
        + (
            "every sign as section 7 states"
            if not wrong
            else "sign contrary to section 7: " + ", ".join(wrong)
        ),
    )


def _contrary(base: str, coord: str, method: str, diff: str) -> str:
    """``'M2-M3 in Y (-3.4251 m; stated positive)'``: one average RMSE(base) - RMSE(Mi)
    whose sign is not the one section 7 states."""
    stated = "positive" if _expected_positive(base, coord, method) else "negative"
    return f"{base}-{method} in {coord} ({diff} m; stated {stated})"


@CLAIMS.family(r"claim\.printed\.t[56]\.m4_m5_positive")
def _p_m4_m5_positive(s, key):
    t = int(key.split(".")[2][1])
    vals = {
        k: v for k, v in printed_values(s.published, t).items() if k.split(".")[-1] in ("M4", "M5")
    }
    low = min(vals, key=vals.get)
    return Result(
        all(v > 0 for v in vals.values()),
        f"printed Table {t}: the {len(vals)} PC values of M4 and M5 range from {vals[low]:g} "
        f"({low}) to {max(vals.values()):g} %",
    )


@CLAIMS.family(r"claim\.printed\.t[12]\.suggested_significant")
def _p_suggested(s, key):
    noise = _noise(key.split(".")[2])
    t = s.printed_ttests[s.printed_ttests["noise"] == noise]
    ok = (t["mean_difference"] > 0) & (t["p_value"] < 0.001)
    return Result(
        bool(ok.all()),
        f"printed Table {key.split('.')[2][1]}: {int(ok.sum())} of {len(t)} comparisons "
        f"(M1/M2 vs M3/M4/M5, X and Y) positive with p < 0.001; largest p "
        f"{t['p_value'].max():.3g}",
    )


def _ttest_result(s, tests, noise, base, coord, m, where):
    t = _lookup(s, tests, ("noise", "base", "coord", "method"), (noise, base, coord, m))
    return Result(
        bool(t["p_value"] < 0.001),
        f"{where}: paired t over {int(t['pairs'])} experiments, t = {t['t']:.3g}, "
        f"p = {t['p_value']:.3g} (mean difference {t['mean_difference']:.3g} m)",
    )


# --------------------------------------------------------------------------- on the reconstruction
def _key_noise_coord(key):
    p = key.split(".")
    return _noise(p[1]), p[3]


@CLAIMS.family(
    r"claim\.t[12]\.m5_lowest\.[XY]", depends_on=lambda k: _deps(_noise(k.split(".")[1]))
)
def _m5_lowest(s, key):
    noise, coord = _key_noise_coord(key)
    m = _row(s, "mc", noise, coord)
    others = m.drop(columns="M5").min(axis=1)
    lost = [f"e{e}" for e, ok in (m["M5"] < others).items() if not ok]
    return Result(
        not lost,
        f"Monte Carlo means: M5 {m['M5'].min():.1f}-{m['M5'].max():.1f} m, best other "
        f"{others.min():.1f}-{others.max():.1f} m"
        + (f"; M5 not lowest in {', '.join(lost)}" if lost else ""),
    )


@CLAIMS.family(r"claim\.t[12]\.ranking\.[XY]", depends_on=lambda k: _deps(_noise(k.split(".")[1])))
def _ranking(s, key):
    noise, coord = _key_noise_coord(key)
    ours = rank_methods(_row(s, "mc", noise, coord).mean().to_dict())
    printed = rank_methods(_row(s, "printed_wide", noise, coord).mean().to_dict())
    return Result(
        ours == printed, f"printed (mean of the table): {printed}; reconstruction: {ours}"
    )


@CLAIMS.family(
    r"claim\.conclusion\.(white|coloured)\.[XY]",
    depends_on=lambda k: _deps(k.split(".")[2], ("M3", "M4", "M5")),
)
def _conclusion(s, key):
    noise, coord = key.split(".")[2], key.split(".")[3]
    m = _row(s, "mc", noise, coord).mean()
    return Result(
        bool(m["M5"] < m["M4"] < m["M3"]),
        "Monte Carlo mean RMSE over the experiments (m): "
        + ", ".join(f"{k} {m[k]:.1f}" for k in ("M3", "M4", "M5")),
    )


@CLAIMS.family(
    r"claim\.t[56]\.size\.[XY]\.M[345]",
    depends_on=lambda k: _deps(_noise(k.split(".")[1]), ("M1", k.split(".")[-1])),
)
def _size(s, key):
    """Whether the Monte Carlo mean PC of one method lies within the range of the paper's
    five PCs (Table 5 or 6, one coordinate).

    Tables 5-6 are eq 27 on Tables 1-2. A printed entry the printed Table 1/2 rejects
    (its own row, *Consistency of the printed tables*, is a ``mismatch``: neither the
    rounding of the Table 1/2 entries nor any reading gives it) is not the paper's PC
    but a misprint of it, so the range takes that entry as recomputed from Table 1/2 and
    the note says so, with the range as printed. Only Table 5, Y, M4 has such entries
    (experiments 4 and 5: printed 99.0708 and 9.4433, recomputed 7.0792 and 9.3365);
    the rule is the same for all twelve rows.
    """
    _, table, _, coord, m = key.split(".")
    t = int(table[1])
    w = _row(s, "mc", _noise(table), coord)
    pc = float(np.mean((w["M1"] - w[m]) / w["M1"] * 100))
    entries = _pc_entries(s, t, coord, m)
    vals = [v for _, v, _, _ in entries]
    low, high = min(vals), max(vals)
    shown = {v: text for _, v, text, _ in entries}
    bad = [(e, text, was) for e, _, text, was in entries if was is not None]
    if not bad:
        note = f"reconstruction {pc:.1f} %, printed range {shown[low]} .. {shown[high]} %"
    else:
        printed = [float(parse_printed(was or text)) for _, _, text, was in entries]
        plural = len(bad) > 1
        es = " and ".join(str(e) for e, _, _ in bad)
        note = (
            f"reconstruction {pc:.1f} %, range {shown[low]} .. {shown[high]} % of the five "
            f"PCs with experiment{'s' * plural} {es} as eq 27 gives "
            f"{'them' if plural else 'it'} on the printed Table {t - 4} "
            f"({' and '.join(text for _, text, _ in bad)}): "
            f"{'their' if plural else 'its'} printed {' and '.join(w for _, _, w in bad)} "
            f"{'are' if plural else 'is'} not what that table gives, within its rounding or "
            f"by any reading tried (row{'s' * plural} Table {t}, experiment {es}, {coord}, "
            f"{m}: "
            "mismatch); with "
            f"the printed entries the range is {min(printed):g} .. {max(printed):g} %"
        )
    return Result(low <= pc <= high, note)


def _pc_entries(s, t: int, coord: str, m: str) -> list[tuple]:
    """The paper's five PCs of Table ``t`` (5 or 6), one coordinate and method, as
    ``(experiment, value, text, printed text if replaced else None)``: each as printed,
    unless the entry's own row rejects it (verdict ``mismatch``: the printed Table
    ``t - 4`` does not give it, within its rounding or by any reading), then as
    recomputed from that table by eq 27."""
    out = []
    for e in range(1, 6):
        key = f"t{t}.e{e}.{coord}.{m}"
        text = s.printed(key)
        v, central = s.memo(("pc_entry", key), lambda key=key: _entry_verdict(s, key), True)
        if v == "mismatch":
            out.append((e, central, f"{central:.4f}", f"{float(parse_printed(text)):g}"))
        else:
            out.append((e, float(parse_printed(text)), f"{float(parse_printed(text)):g}", None))
    return out


def _entry_verdict(s, key: str) -> tuple[str, float]:
    """The verdict of one printed Table 3-6 entry, judged as its own row is (the verdict
    engine, with the entry's readings), and its value recomputed from Tables 1-2."""
    res = CLAIMS.compute(s, key)
    row = SimpleNamespace(key=key, item=key, quantity="", published=s.printed(key))
    return judge(CLAIMS.doc, row, res.value, res.note, res.readings)["verdict"], float(res.value)


@CLAIMS.family(
    r"claim\.t[34]\.sign\.M[12]\.[XY]\.M[345]",
    depends_on=lambda k: _deps(_noise(k.split(".")[1]), (k.split(".")[3], k.split(".")[5])),
)
def _sign(s, key):
    _, table, _, base, coord, m = key.split(".")
    w = _row(s, "mc", _noise(table), coord)
    ours = float((w[base] - w[m]).mean())
    printed = float(parse_printed(s.printed(f"{table}.{base}.{coord}.{m}")))
    return Result(
        (ours > 0) == (printed > 0), f"reconstruction {ours:.2f} m, printed {printed:g} m"
    )


@CLAIMS.family(r"claim\.t[34]\.sign_pattern", depends_on=lambda k: _deps(_noise(k.split(".")[1])))
def _sign_pattern(s, key):
    noise = _noise(key.split(".")[1])
    wrong = []
    for base in BASES:
        for coord in ("X", "Y"):
            w = _row(s, "mc", noise, coord)
            for m in COMPARED:
                d = float((w[base] - w[m]).mean())
                if (d > 0) != _expected_positive(base, coord, m):
                    wrong.append(_contrary(base, coord, m, f"{d:+.1f}"))
    return Result(
        not wrong,
        "reconstruction (Monte Carlo means): "
        + (
            "every sign as section 7 states"
            if not wrong
            else "sign contrary to section 7: " + ", ".join(wrong)
        ),
    )


@CLAIMS.family(
    r"claim\.ttest\.t[34]\.M[12]\.[XY]\.M[345]",
    depends_on=lambda k: _deps(
        _noise(k.split(".")[2]), (k.split(".")[3], k.split(".")[5]), realisation=True
    ),
)
def _ttest(s, key):
    _, _, table, base, coord, m = key.split(".")
    return _ttest_result(
        s, "ttests", _noise(table), base, coord, m, f"reconstruction, run {s.cfg['realisation']}"
    )


@CLAIMS.family(
    r"claim\.m5\.more_trackers\.(white|coloured)\.[XY]",
    depends_on=lambda k: _deps(k.split(".")[3], ()),
)
def _more_trackers(s, key):
    noise, coord = key.split(".")[3], key.split(".")[4]
    b = s.m5_bank
    b = b[(b["noise"] == noise) & (b["coord"] == coord)].sort_values("K")
    v = b["M5"].to_numpy()
    return Result(
        bool(np.all(np.diff(v) < 0)),
        "Monte Carlo mean M5 RMSE (m) by bank size K: "
        + ", ".join(f"K={k} {x:.2f}" for k, x in zip(b["K"], v, strict=True)),
    )


# --------------------------------------------------------------------------- sections 3-5
@CLAIMS.claim("claim.eq12_14")
def _eq12_14(s):
    a, b = stability.random_gains(s.cfg["stability_seed"], s.cfg["stability_samples"])
    exact = np.asarray(is_stable(Gains(a, b)))
    printed = np.asarray(stability.stable_alwagih_eq12_14(a, b))
    return Result(
        bool(np.array_equal(exact, printed)),
        f"{a.size} random gain pairs, {int(exact.sum())} stable; disagreements: "
        f"{int((exact != printed).sum())}",
    )


@CLAIMS.claim("claim.eq20")
def _eq20(s):
    gap = stability.eq20_double_pole_gap(np.linspace(0.01, 1.0, 100))
    # a double pole is found only to ~sqrt(eps): its separation is written as a bound
    return Result(
        gap < 1e-6,
        f"largest pole separation over 100 alphas in (0, 1]: {roundoff(gap, bound=1e-6)}",
    )


@CLAIMS.claim("claim.eq21_22")
def _eq21_22(s):
    a, b = stability.random_gains(s.cfg["stability_seed"], s.cfg["stability_samples"])
    r = stability.eq21_22_region(a, b)
    ex = (
        f" (e.g. alpha = {r['example_alpha']:.3f}, beta = {r['example_beta']:.3f})"
        if r["example_alpha"] is not None
        else ""
    )
    return Result(
        r["stable_outside"] == 0 and r["unstable_inside"] == 0,
        f"{r['samples']} random gain pairs: {r['stable_outside']} of {r['stable']} stable ones "
        f"have alpha > 1{ex}, outside eq 21",
    )


@CLAIMS.claim("claim.alpha_gt1_roots")
def _alpha_gt1(s):
    a, b = stability.random_gains(s.cfg["stability_seed"], s.cfg["stability_samples"])
    r = stability.alpha_above_one_has_negative_root(a, b)
    return Result(
        r["with_negative_root"] == 0,
        f"{r['with_negative_root']} of {r['samples']} random gain pairs with alpha > 1 have a "
        "negative real root of eq 15 (the product of the roots is 1 - alpha < 0)",
    )


@CLAIMS.claim("claim.init_eq9_10")
def _init(s):
    rng = np.random.default_rng(int(s.cfg["stability_seed"]))
    z = rng.normal(0.0, 100.0, (8, 12))
    first = np.stack([methods.m1(z, a).x_pred[:, :3] for a in (0.01, 0.1, 0.5, 1.0)])
    want = np.stack([z[:, 0], z[:, 1], 2 * z[:, 1] - z[:, 0]], axis=-1)
    err = float(np.max(np.abs(first - want)))
    return Result(
        err < 1e-9,
        f"first three predictions of M1 at alpha 0.01-1 on 8 random series: x_p(1..2) = x_m, "
        f"x_p(3) = 2 x_m(2) - x_m(1) (eqs 9-10) to {roundoff(err)}",
    )


@CLAIMS.claim("claim.eq24_least_squares")
def _eq24(s):
    rng = np.random.default_rng(int(s.cfg["stability_seed"]) + 1)
    z = rng.normal(0.0, 100.0, 30)
    pred = methods.m2(z[None, :]).x_pred[0]
    ls = [np.polyval(np.polyfit(np.arange(n), z[:n], 1), n) for n in range(2, z.size)]
    err = float(np.max(np.abs(pred[2:] - ls)))
    return Result(
        err < 1e-6,
        f"M2 (eq 24) vs the least-squares line through all earlier samples, 28 steps: "
        f"largest difference {roundoff(err)} m",
    )


@CLAIMS.claim("claim.eq20_plus")
def _eq20_plus(s):
    gap = stability.eq20_double_pole_gap(np.linspace(0.01, 1.0, 100), sign=1.0)
    return Result(
        gap < 1e-6,
        f"the + branch, beta = 2 - alpha + 2 sqrt(1 - alpha): largest pole separation over 100 "
        f"alphas in (0, 1]: {roundoff(gap, bound=1e-6)}",
    )


@CLAIMS.claim("claim.eq11")
def _eq11(s):
    from ...analysis import frequency_response

    a, b = stability.random_gains(s.cfg["stability_seed"], 50)
    keep = np.asarray(is_stable(Gains(a, b)))
    w = np.linspace(0.0, np.pi, 64)
    err = max(
        float(
            np.max(
                np.abs(
                    stability.eq11_response(x, y, w) - frequency_response(Gains(x, y), "x_pred", w)
                )
            )
        )
        for x, y in zip(a[keep], b[keep], strict=True)
    )
    return Result(
        err < 1e-9,
        f"eq 11 against abglib's X_p/X_m (the one-step prediction) on {int(keep.sum())} stable "
        f"random gain pairs, 64 frequencies: largest difference {roundoff(err, bound=1e-9)}",
    )


@CLAIMS.claim("claim.eq23_tradeoff")
def _eq23_tradeoff(s):
    r = stability.eq23_tradeoff(np.linspace(0.05, 1.0, 20))
    ok = bool(np.all(np.diff(r["vrf_pred"]) > 0) and np.all(np.diff(r["lag"]) < 0))
    return Result(
        ok,
        f"along eq 23b, alpha 0.05 -> 1: prediction noise gain {r['vrf_pred'][0]:.3g} -> "
        f"{r['vrf_pred'][-1]:.3g} (rising), lag behind a unit acceleration {r['lag'][0]:.4g} -> "
        f"{r['lag'][-1]:.3g} (falling)",
    )


@CLAIMS.family(r"claim\.printed\.t[12]\.suggested_better")
def _p_suggested_better(s, key):
    table = key.split(".")[2]
    lost = []
    for coord in ("X", "Y"):
        m = _row(s, "printed_wide", _noise(table), coord).mean()
        for new in COMPARED:
            for base in BASES:
                if not m[new] < m[base]:
                    lost.append(f"{new} vs {base} in {coord} ({m[new]:.1f} >= {m[base]:.1f} m)")
    return Result(
        not lost,
        f"printed Table {table[1]}, mean RMSE over the experiments: "
        + (
            "every suggested method below both classical ones"
            if not lost
            else "not better: " + "; ".join(lost)
        ),
    )


# --------------------------------------------------------------------------- added in v0.4.0
@CLAIMS.claim("claim.eq23b_benedict_bordner")
def _eq23b_bb(s):
    """Section 5.1: eq 23b is Benedict and Bordner's relation, i.e. the locus of the
    minimisers of their criterion (the study's ``benedict_bordner_optima``)."""
    t = s.benedict_bordner_optima
    worst = float(np.max(np.abs(t["rel_gap"])))
    return Result(
        bool(np.isfinite(worst) and worst < 1e-6),
        "minimisers of VRF_pred + lambda x (summed squared prediction errors after a unit "
        "velocity step), Nelder-Mead over (alpha, beta): "
        + ", ".join(
            f"lambda {w:g}: alpha {a:.4f}, beta {b:.5f} (eq 23b {b23:.5f})"
            for w, a, b, b23 in zip(
                t["weight"], t["alpha"], t["beta"], t["beta_eq23b"], strict=True
            )
        )
        + f"; largest relative gap to eq 23b {roundoff(worst, bound=1e-6)} (the optimiser's "
        "tolerance 1e-6)",
    )


#: How closely the zero-state and two-point starts of eq 24 must agree (m, measurements of
#: ~100 m): far above their round-off (~1e-12 m), far below any error of the recursion.
EQ24_AGREE = 1e-9


@CLAIMS.claim("claim.eq24_n2_is_eq9_10")
def _eq24_n2(s):
    """Eq 24 at n = 2 (the paper states it for n > 2) against the start of eqs 9-10."""
    from ...design import growing_memory
    from ...engine import track

    g2 = growing_memory(1, start=2)
    a2, b2 = float(g2.alpha[0]), float(g2.beta[0])
    rng = np.random.default_rng(int(s.cfg["stability_seed"]) + 2)
    z = rng.normal(0.0, 100.0, (8, 6))
    errs = []
    for dt in (1.0, 0.5):
        gm = growing_memory(z.shape[-1])
        # eq 24 from n = 1 (alpha = 1, beta = 3) on a zero state, and the two-point start
        # of eqs 9-10 followed by eq 24 from n = 3: the same predictions, states from n = 2
        zero = track(z, gm, dt=dt)
        two = track(z, gm, dt=dt, init="two_point")
        v2 = (z[:, 1] - z[:, 0]) / dt  # eq 9
        xp3 = z[:, 1] + dt * v2  # eq 10
        errs += [
            np.max(np.abs(zero.v_smooth[:, 1] - v2)),
            np.max(np.abs(zero.x_pred[:, 2] - xp3)),
            np.max(np.abs(zero.x_pred[:, 2:] - two.x_pred[:, 2:])),
        ]
    err = float(max(errs))
    # the two routes agree to round-off, ~1e-12 m on measurements of ~100 m: the note
    # writes it as the claim's own bound (1e-12 itself was crossed under abglib precision's
    # perturbation, 1.28e-12 m, and a note that moves makes the row rest on chance)
    return Result(
        bool(math.isclose(a2, 1.0, rel_tol=1e-12) and math.isclose(b2, 1.0, rel_tol=1e-12))
        and err < EQ24_AGREE,
        f"eq 24 at n = 2: alpha = {a2:g}, beta = {b2:g}; run from a zero state (T = 1 and 0.5 s, "
        f"8 random series) it leaves v_s(2) = (x_m(2) - x_m(1))/T and x_p(3) = x_m(2) + T v_s(2) "
        f"of eqs 9-10 and the same later predictions as the two-point start, to "
        f"{roundoff(err, bound=EQ24_AGREE)} m",
    )


@CLAIMS.claim("claim.eq16_17")
def _eq16_17(s):
    """Eqs 16-17, the roots of eq 15 as printed, against the poles of abglib's tracker."""
    from ...analysis import poles

    a, b = stability.random_gains(s.cfg["stability_seed"], 200)
    disc = np.sqrt((a + b - 2) ** 2 - 4 * (1 - a) + 0j)
    printed = np.sort_complex(np.stack([(-(a + b - 2) + disc) / 2, (-(a + b - 2) - disc) / 2], 1))
    exact = np.sort_complex(np.asarray(poles(Gains(a, b)), dtype=complex))
    err = float(np.max(np.abs(printed - exact)))
    return Result(
        err < 1e-9,
        f"{a.size} random gain pairs (real and complex roots): largest difference between eqs "
        f"16-17 and the tracker's poles {roundoff(err)}",
    )


@CLAIMS.claim("claim.intro_constant_velocity")
def _intro_cv(s):
    """Section 1: "a good performance for non-maneuvering, constant velocity targets", read
    as: the one-step prediction follows a constant-velocity target without lag."""
    from ...analysis import pole_radius
    from ...engine import track

    a, b = stability.random_gains(s.cfg["stability_seed"] + 3, 400)
    # stable with a transient that dies out within the run (radius^3000 < 1e-13)
    keep = np.asarray(pole_radius(Gains(a, b))) < 0.99
    a, b = a[keep], b[keep]
    T, v = 2.0, 150.0
    z = 1000.0 + v * T * np.arange(3000.0)
    # from a zero state, so that only the loop (not the two-point start) removes the lag
    lag = np.abs(z - track(z, Gains(a[:, None], b[:, None]), dt=T, init="zero").x_pred)
    worst = float(lag[:, -1].max())
    first = float(lag[:, 1].min())
    return Result(
        worst < 1e-6 * v * T,
        f"{a.size} random gain pairs with pole radius < 0.99, a {v:g} m/s target at T = {T:g} s "
        f"from a zero state: prediction error at least {first:.3g} m at the second sample, "
        f"below {1e-6 * v * T:g} m after 3000 samples (no steady-state lag: the loop is of "
        "type 2)",
    )
