"""Speed of abglib.track against FilterPy and a plain Python loop, side by side in one run.

Usage::

    python benchmarks/engine_speed.py [--out benchmarks/results/engine_speed.csv] [--quick]

Cases (issue: abglib core, item 5; issue 14, part 4):

* ``single``: one series of 10^6 samples;
* ``batch``: 10^4 Monte Carlo runs x 10^3 samples (abglib does them in one call).

abglib rows, each a call of ``abglib.track`` over the whole case:

* ``4 outputs, out= buffers``: all of x_pred, x_smooth, v_smooth, a_smooth written into
  caller-owned arrays reused from call to call (``track(..., out=previous_result)``), the
  way a Monte Carlo loop would call it;
* ``4 outputs, fresh arrays``: the same without ``out=``, each call returning new arrays
  while the previous call's result is still held (the timing loop's variable), as a
  Monte Carlo loop ``r = track(...)`` does. From the third call on, abglib recycles the
  memory of results that are gone (:mod:`abglib._buffers`), so these calls too skip the
  operating system's fresh pages (320 MB a call in the batch case);
* ``x_smooth only``: ``outputs=("x_smooth",)``, fresh.

Two reference rows show what fresh pages cost without recycling (neither is a target
row): ``abglib.track, new arrays, recycling off`` (the pool switched off,
``ABGLIB_POOL_BYTES=0``: every call faults and zeroes its outputs' pages), and ``numpy,
4 fresh arrays: np.empty + fill``, numpy alone allocating four new arrays of the case's
shape and filling each (``np.empty(shape).fill(0.0)``, one thread): no tracking at all,
only what the operating system charges for fresh pages.

Peers, on the same data and converted gains (:mod:`abglib.conventions`):

* alpha-beta: ``filterpy.gh.GHFilter.batch_filter`` (FilterPy's fastest alpha-beta path);
* alpha-beta-gamma: ``filterpy.gh.GHKFilter.update`` per sample (its ``batch_filter``
  ignores ``k``, so it cannot run an alpha-beta-gamma tracker);
* a plain Python loop of seed 000, eqs 1-6.

The pure-Python peers are linear in the number of samples, so they are timed on a
subset (``peer_samples`` in the CSV) and reported as samples per second; abglib is
timed on the whole case (median of ``--repeats`` calls after a warm-up call, which
also pays numba's one-off compilation). Every peer's output is checked against abglib's
on the subset (maximum relative difference in the CSV; the issue asks for <= 1e-9).
Ratios are samples-per-second over FilterPy's. Timings are wall clock; abglib's batched
kernel uses numba's threads (all cores unless ``NUMBA_NUM_THREADS`` says otherwise; the
core count is in the CSV), the single series runs on one core. Noisy machines give noisy
numbers, so run it several times before quoting a figure.

The script imports the ``abglib`` of the checkout it sits in, not an installed one.
The last lines check issue 14's target: every batched all-four-outputs row
>= 2e8 sample-updates/s and >= 100x FilterPy.
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import sys
import time
from pathlib import Path

import numpy as np
import pandas as pd
from filterpy.gh import GHFilter, GHKFilter

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # this checkout's abglib
from abglib import Gains, _buffers, track  # noqa: E402
from abglib.conventions import to_filterpy  # noqa: E402

TARGET_RATE = 2e8  # sample-updates/s, batched, all four outputs (issue 14)
TARGET_RATIO = 100.0  # x FilterPy, same rows
ALL = ("x_pred", "x_smooth", "v_smooth", "a_smooth")

SEED = 20261121  # fixed so every run times the same data
DT = 0.1
GAINS = {
    # standard (critically damped) gains for theta = 0.8 (seed 000, eqs 22-24 and the
    # alpha-beta pair): typical moderate smoothing
    "alpha-beta": Gains(1 - 0.8**2, (1 - 0.8) ** 2),
    "alpha-beta-gamma": Gains(1 - 0.8**3, 1.5 * (1 - 0.8) ** 2 * (1 + 0.8), (1 - 0.8) ** 3),
}


def python_loop(z, gains: Gains, dt: float):
    """Seed 000, eqs 1-6, one sample at a time in plain Python. Returns x_smooth."""
    alpha, beta, gamma = float(gains.alpha), float(gains.beta), float(gains.gamma)
    b, c, h = beta / dt, gamma / dt**2, 0.5 * dt**2
    x = v = a = 0.0
    out = [0.0] * len(z)
    for i, zi in enumerate(z.tolist()):
        xp = x + dt * v + h * a
        r = zi - xp
        x = xp + alpha * r
        v = v + dt * a + b * r
        a = a + c * r
        out[i] = x
    return np.array(out)


def filterpy_run(z, gains: Gains, dt: float):
    """FilterPy's fastest path for the tracker order. Returns x_smooth."""
    g, h, k = to_filterpy(gains)
    if gains.order == 2:
        return GHFilter(x=0.0, dx=0.0, dt=dt, g=g, h=h).batch_filter(z)[1:, 0]
    f = GHKFilter(x=0.0, dx=0.0, ddx=0.0, dt=dt, g=g, h=h, k=k)
    return np.array([f.update(zi)[0] for zi in z])


FRESH_FLOOR = "numpy, 4 fresh arrays: np.empty + fill"
NO_RECYCLING = "abglib.track, new arrays, recycling off"


def _fresh_fill(shape):
    """Four new arrays of ``shape``, each filled once by numpy: the fresh pages' cost."""
    out = []
    for _ in ALL:
        a = np.empty(shape)
        a.fill(0.0)
        out.append(a)
    return out


def _time(fn, repeats=1):
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), out


def _rel_diff(a, b):
    return float(np.max(np.abs(a - b)) / np.max(np.abs(b)))


def _whole_case_row(case, filt, label, samples, secs) -> dict:
    """A row timed on the whole case (abglib's rows and the numpy floor; nothing to diff)."""
    return dict(
        case=case,
        filter=filt,
        implementation=label,
        samples=samples,
        peer_samples=samples,
        seconds=secs,
        max_rel_diff=0.0,
    )


def run(quick: bool = False, repeats: int = 5) -> pd.DataFrame:
    rng = np.random.default_rng(SEED)
    runs, n_batch = (10**3, 10**3) if quick else (10**4, 10**3)
    cases = {
        "single": rng.normal(size=10**5 if quick else 10**6).cumsum(),
        "batch": rng.normal(size=(runs, n_batch)).cumsum(axis=-1),
    }
    peer_samples = 2 * 10**4 if quick else 2 * 10**5
    rows = []
    for case, z in cases.items():
        for filt, gains in GAINS.items():
            track(z[..., :16], gains, dt=DT)  # warm-up (numba compilation / cache load)
            variants = (
                ("abglib.track, 4 outputs, out= buffers", ALL, True),
                ("abglib.track, 4 outputs, fresh arrays", ALL, False),
                ("abglib.track, x_smooth only", ("x_smooth",), False),
            )
            for label, outputs, reuse in variants:
                res = track(z, gains, dt=DT, outputs=outputs)  # touch the memory once
                kw = {"out": res} if reuse else {}
                secs, out = _time(lambda: track(z, gains, dt=DT, outputs=outputs, **kw), repeats)  # noqa: B023
                rows.append(_whole_case_row(case, filt, label, z.size, secs))
            limit = _buffers.pool_limit()
            _buffers.set_pool_limit(0)
            try:
                track(z, gains, dt=DT)
                secs, _ = _time(lambda: track(z, gains, dt=DT), repeats)  # noqa: B023
            finally:
                _buffers.set_pool_limit(limit)
            rows.append(_whole_case_row(case, filt, NO_RECYCLING, z.size, secs))
            secs, _ = _time(lambda: _fresh_fill(z.shape), repeats)  # noqa: B023
            rows.append(_whole_case_row(case, filt, FRESH_FLOOR, z.size, secs))
            # peers on a subset: the first series (or rows) summing to peer_samples
            flat = z.reshape(-1, z.shape[-1])
            per_row = flat.shape[1]
            nrows = max(1, min(flat.shape[0], peer_samples // per_row))
            sub = flat[:nrows, : min(per_row, peer_samples)]
            ref = track(sub, gains, dt=DT).x_smooth
            for label, fn in (("filterpy", filterpy_run), ("python loop", python_loop)):
                secs, out = _time(lambda: np.stack([fn(row, gains, DT) for row in sub]))  # noqa: B023
                rows.append(
                    dict(
                        case=case,
                        filter=filt,
                        implementation=label,
                        samples=z.size,
                        peer_samples=sub.size,
                        seconds=secs,
                        max_rel_diff=_rel_diff(out, ref),
                    )
                )
    df = pd.DataFrame(rows)
    df["samples_per_s"] = df["peer_samples"] / df["seconds"]
    fp = df[df.implementation == "filterpy"].set_index(["case", "filter"])["samples_per_s"]
    df["ratio_vs_filterpy"] = [r.samples_per_s / fp[(r.case, r.filter)] for r in df.itertuples()]
    df["machine"] = f"{platform.machine()} python {platform.python_version()}"
    df["cores"] = os.cpu_count()
    return df


def target_rows(df: pd.DataFrame) -> pd.DataFrame:
    """The rows issue 14's engine target is about: batched, all four outputs."""
    rows = df[(df.case == "batch") & df.implementation.str.contains("4 outputs")].copy()
    rows["meets_target"] = (rows.samples_per_s >= TARGET_RATE) & (
        rows.ratio_vs_filterpy >= TARGET_RATIO
    )
    return rows


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", type=Path, default=Path("benchmarks/results/engine_speed.csv"))
    parser.add_argument("--quick", action="store_true", help="smaller sizes (a smoke test)")
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args(argv)
    df = run(quick=args.quick, repeats=args.repeats)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    df.to_csv(args.out, index=False, float_format="%.6g")
    with pd.option_context("display.width", 160, "display.max_columns", 20):
        print(
            df[
                [
                    "case",
                    "filter",
                    "implementation",
                    "samples_per_s",
                    "ratio_vs_filterpy",
                    "max_rel_diff",
                ]
            ].to_string(index=False, float_format=lambda v: f"{v:.3g}")
        )
    print(f"\nwritten {args.out}")
    print(f"\ntarget (batched, all four outputs): >= {TARGET_RATE:.0e} /s and >= 100x FilterPy")
    for r in target_rows(df).itertuples():
        verdict = "meets" if r.meets_target else "MISSES"
        print(
            f"  {verdict:6s} {r.filter:16s} {r.implementation:38s} "
            f"{r.samples_per_s:.3g} /s, {r.ratio_vs_filterpy:.0f}x FilterPy"
        )
    worst = df.loc[df.implementation == "filterpy", "max_rel_diff"].max()
    if worst > 1e-9:
        print(f"FilterPy disagrees with abglib by {worst:.3g} relative (> 1e-9)", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
