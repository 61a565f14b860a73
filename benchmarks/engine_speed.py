"""Speed of abglib.track against FilterPy and a plain Python loop, side by side in one run.

Usage::

    python benchmarks/engine_speed.py [--out benchmarks/results/engine_speed.csv]
                                      [--rounds 3] [--calls 5] [--quick]

Cases (issue: abglib core, item 5; issue 14, part 4; issue 24, item 3):

* ``single``: one series of 10^6 samples;
* ``batch``: 10^4 Monte Carlo runs x 10^3 samples (abglib does them in one call).

abglib rows, each a call of ``abglib.track`` over the whole case (the target rows):

* ``4 outputs, out= buffers``: all of x_pred, x_smooth, v_smooth, a_smooth written into
  caller-owned arrays reused from call to call (``track(..., out=previous_result)``), the
  way a Monte Carlo loop would call it;
* ``4 outputs, fresh arrays``: the same without ``out=``, each call returning new arrays
  while the previous call's result is still held (the timing loop's variable), as a
  Monte Carlo loop ``r = track(...)`` does. From the third call on, abglib recycles the
  memory of results that are gone (:mod:`abglib._buffers`), so these calls too skip the
  operating system's fresh pages; the two calls before the timed ones are warm-up;
* ``x_smooth only``: ``outputs=("x_smooth",)``, fresh.

Reference rows (no target; they show what bounds the target rows on this machine):

* ``abglib.track, new arrays, recycling off``: the pool switched off
  (``ABGLIB_POOL_BYTES=0``): every call faults and zeroes its outputs' fresh pages;
* ``numpy, 4 fresh arrays: np.empty + fill``: numpy alone allocating four new arrays of
  the case's shape and filling each once: no tracking, only the fresh pages' cost;
* ``dependency chain, minimal numba loop`` (single series only): seed 000, eqs 1-6 in
  the fewest operations numba compiles it to, no outputs stored, no checks: the speed
  of the recursion's dependency chain itself (each sample waits for the previous
  estimate). A bit-identical kernel could beat it only by speculating, on inputs where
  guessed runs meet the exact one early; the split measured in
  benchmarks/chain_coalescence.py loses on inputs where they do not. Printed with the
  CPU-time latencies of a dependent add and a dependent multiply measured in the same
  round, and the chain's length in those (docs/engine-speed.md explains it).

Peers, on the same data and converted gains (:mod:`abglib.conventions`):

* alpha-beta: ``filterpy.gh.GHFilter.batch_filter`` (FilterPy's fastest alpha-beta path);
* alpha-beta-gamma: ``filterpy.gh.GHKFilter.update`` per sample (its ``batch_filter``
  ignores ``k``, so it cannot run an alpha-beta-gamma tracker);
* a plain Python loop of seed 000, eqs 1-6.

Every row is timed in every one of ``--rounds`` rounds, the rows of a round one after the
other, so each ratio compares timings taken minutes apart at most, under the same load.
The pure-Python peers are linear in the number of samples, so they are timed once a
round on a subset (``peer_samples`` in the CSV) and reported as samples per second;
abglib's rows are timed on the whole case, ``--calls`` calls a round (after warm-up
calls, the first of which also pays numba's one-off compilation or cache load). Every
call is reported (the CSV has one line per call; the table lists every call's rate), and
its ratio is samples-per-second over FilterPy's of the same round. A row meets the target
when the median call of EVERY round is >= 100x FilterPy; the lowest single call is
printed too. Every peer's output is checked against abglib's on the subset (maximum
relative difference in the CSV; <= 1e-9 asserted).

Timings are wall clock (the target's ratios); each call's CPU time (the process's, all
threads) is recorded too and its ratio printed beside: on a machine shared with other jobs
a call waits for a core at random, which wall clock counts and CPU time does not, so the
CPU-time ratios show what the calls cost when they run. abglib's batched kernel uses
numba's threads (all cores unless ``NUMBA_NUM_THREADS`` says otherwise; its CPU time sums
them), the single series runs on one core. The header
prints the machine, its load (``/proc/loadavg``) before and after, numba's threads and
the BLAS thread pools (threadpoolctl). The script imports the ``abglib`` of the checkout
it sits in, not an installed one.
"""

from __future__ import annotations

import argparse
import os
import platform
import sys
import time
from pathlib import Path

import numba
import numpy as np
import pandas as pd
from filterpy.gh import GHFilter, GHKFilter
from numba import njit

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # this checkout's abglib
from abglib import Gains, _buffers, track  # noqa: E402
from abglib.conventions import to_filterpy  # noqa: E402

TARGET_RATE = 2e8  # sample-updates/s, batched, all four outputs (issue 14)
TARGET_RATIO = 100.0  # x FilterPy, every abglib row (issue 24)
SINGLE_RATE = 2e8  # sample-updates/s, one series (issue 24), or the chain's bound
ALL = ("x_pred", "x_smooth", "v_smooth", "a_smooth")

SEED = 20261121  # fixed so every run times the same data
DT = 0.1
GAINS = {
    # standard (critically damped) gains for theta = 0.8 (seed 000, eqs 22-24 and the
    # alpha-beta pair): typical moderate smoothing
    "alpha-beta": Gains(1 - 0.8**2, (1 - 0.8) ** 2),
    "alpha-beta-gamma": Gains(1 - 0.8**3, 1.5 * (1 - 0.8) ** 2 * (1 + 0.8), (1 - 0.8) ** 3),
}

OUT_BUFFERS = "abglib.track, 4 outputs, out= buffers"
FRESH = "abglib.track, 4 outputs, fresh arrays"
X_ONLY = "abglib.track, x_smooth only"
NO_RECYCLING = "abglib.track, new arrays, recycling off"
FRESH_FLOOR = "numpy, 4 fresh arrays: np.empty + fill"
CHAIN = "dependency chain, minimal numba loop"
TARGETS = (OUT_BUFFERS, FRESH, X_ONLY)
REFERENCES = (NO_RECYCLING, FRESH_FLOOR, CHAIN)


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


# --------------------------------------------------------------------------- the chain
@njit(cache=False)
def _chain2(z, T, alpha, b):
    """Seed 000, eqs 1-6 with gamma = 0: only the operations of the recursion (the
    engine's order, no fast-math), nothing stored. Returns the final state's sum."""
    x = v = 0.0
    for i in range(z.shape[0]):
        x_p = x + T * v
        r = z[i] - x_p
        x = x_p + alpha * r
        v = v + b * r
    return x + v


@njit(cache=False)
def _chain3(z, T, h, alpha, b, c):
    """:func:`_chain2` for the alpha-beta-gamma tracker."""
    x = v = a = 0.0
    for i in range(z.shape[0]):
        x_p = x + T * v + h * a
        v_p = v + T * a
        r = z[i] - x_p
        x = x_p + alpha * r
        v = v_p + b * r
        a = a + c * r
    return x + v + a


@njit(cache=False)
def _dependent_adds(n, y):
    x = 0.0
    for _ in range(n):
        x = x + y
    return x


@njit(cache=False)
def _dependent_muls(n, y):
    x = 1.0
    for _ in range(n):
        x = x * y
    return x


def _chain_call(z, gains: Gains, dt: float):
    alpha, beta, gamma = float(gains.alpha), float(gains.beta), float(gains.gamma)
    if gains.order == 2:
        return lambda: _chain2(z, dt, alpha, beta / dt)
    return lambda: _chain3(z, dt, 0.5 * dt * dt, alpha, beta / dt, gamma / (dt * dt))


def latencies(n: int = 10**7, calls: int = 5) -> tuple[float, float]:
    """CPU seconds of one dependent float64 add and of one dependent multiply (the
    fastest of ``calls`` loops of ``n``): the units the dependency chain is counted in."""
    _dependent_adds(10, 1e-300)
    _dependent_muls(10, 1.0000000001)
    add = min(_cpu_timed(lambda: _dependent_adds(n, 1e-300)) for _ in range(calls)) / n
    mul = min(_cpu_timed(lambda: _dependent_muls(n, 1.0000000001)) for _ in range(calls)) / n
    return add, mul


# --------------------------------------------------------------------------- timing
def _cpu_timed(fn) -> float:
    c0 = time.process_time()
    fn()
    return time.process_time() - c0


def _calls(fn, calls: int) -> list[tuple[float, float]]:
    """``(wall seconds, CPU seconds)`` of each of ``calls`` calls of ``fn``; each result
    is kept until the next call returns (as a loop ``r = fn()`` keeps it). CPU seconds
    are the process's (every thread's: numba's workers included) and leave out the time
    the call waited for a core, which wall clock on a shared machine does not."""
    times, keep = [], None
    for _ in range(calls):
        c0, t0 = time.process_time(), time.perf_counter()
        keep = fn()
        times.append((time.perf_counter() - t0, time.process_time() - c0))
    del keep
    return times


def _fresh_fill(shape):
    """Four new arrays of ``shape``, each filled once by numpy: the fresh pages' cost."""
    out = []
    for _ in ALL:
        a = np.empty(shape)
        a.fill(0.0)
        out.append(a)
    return out


def _rel_diff(a, b):
    return float(np.max(np.abs(a - b)) / np.max(np.abs(b)))


def _abglib_rows(z, gains, calls):
    """``{label: [(wall, CPU) seconds of each call]}`` of abglib's rows and references."""
    rows = {}
    res = track(z, gains, dt=DT)  # touch the memory of one result once
    # out= buffers: every call writes into the same arrays
    track(z, gains, dt=DT, out=res)
    rows[OUT_BUFFERS] = _calls(lambda: track(z, gains, dt=DT, out=res), calls)
    res = None  # its memory back to the pool
    for label, outputs in ((FRESH, ALL), (X_ONLY, ("x_smooth",))):
        # two warm-up calls: the third call on is the steady state of a loop r = track()
        _calls(lambda: track(z, gains, dt=DT, outputs=outputs), 2)  # noqa: B023
        rows[label] = _calls(lambda: track(z, gains, dt=DT, outputs=outputs), calls)  # noqa: B023
    limit = _buffers.pool_limit()
    _buffers.set_pool_limit(0)
    try:
        track(z, gains, dt=DT)
        rows[NO_RECYCLING] = _calls(lambda: track(z, gains, dt=DT), calls)
    finally:
        _buffers.set_pool_limit(limit)
    rows[FRESH_FLOOR] = _calls(lambda: _fresh_fill(z.shape), calls)
    if z.ndim == 1:
        chain = _chain_call(z, gains, DT)
        chain()
        rows[CHAIN] = _calls(chain, calls)
    return rows


def run(quick: bool = False, rounds: int = 3, calls: int = 5) -> pd.DataFrame:
    """One line per timed call (abglib and references) or pass (peers), every round."""
    rng = np.random.default_rng(SEED)
    runs, n_batch = (10**3, 10**3) if quick else (10**4, 10**3)
    cases = {
        "single": rng.normal(size=10**5 if quick else 10**6).cumsum(),
        "batch": rng.normal(size=(runs, n_batch)).cumsum(axis=-1),
    }
    peer_samples = 2 * 10**4 if quick else 2 * 10**5
    for z in cases.values():
        for gains in GAINS.values():
            track(z[..., :16], gains, dt=DT)  # numba's compilation / cache load
    lines = []
    for rnd in range(1, rounds + 1):
        add, mul = latencies(10**6 if quick else 10**7)
        for case, z in cases.items():
            for filt, gains in GAINS.items():
                base = dict(round=rnd, case=case, filter=filt, samples=z.size, add_s=add, mul_s=mul)
                # peers on a subset: the first series (or rows) summing to peer_samples
                flat = z.reshape(-1, z.shape[-1])
                per_row = flat.shape[1]
                nrows = max(1, min(flat.shape[0], peer_samples // per_row))
                sub = flat[:nrows, : min(per_row, peer_samples)]
                ref = track(sub, gains, dt=DT).x_smooth
                for label, fn in (("filterpy", filterpy_run), ("python loop", python_loop)):
                    c0, t0 = time.process_time(), time.perf_counter()
                    out = np.stack([fn(row, gains, DT) for row in sub])
                    secs, cpu = time.perf_counter() - t0, time.process_time() - c0
                    lines.append(
                        dict(
                            base,
                            implementation=label,
                            call=1,
                            peer_samples=sub.size,
                            seconds=secs,
                            cpu_seconds=cpu,
                            max_rel_diff=_rel_diff(out, ref),
                        )
                    )
                for label, times in _abglib_rows(z, gains, calls).items():
                    for k, (secs, cpu) in enumerate(times, 1):
                        lines.append(
                            dict(
                                base,
                                implementation=label,
                                call=k,
                                peer_samples=z.size,
                                seconds=secs,
                                cpu_seconds=cpu,
                                max_rel_diff=0.0,
                            )
                        )
    df = pd.DataFrame(lines)
    df["samples_per_s"] = df["peer_samples"] / df["seconds"]
    df["samples_per_cpu_s"] = df["peer_samples"] / df["cpu_seconds"].clip(lower=1e-9)
    fp = df[df.implementation == "filterpy"].set_index(["round", "case", "filter"])
    key = [(r.round, r.case, r.filter) for r in df.itertuples()]
    df["ratio_vs_filterpy"] = df["samples_per_s"].to_numpy() / fp["samples_per_s"][key].to_numpy()
    df["cpu_ratio_vs_filterpy"] = (
        df["samples_per_cpu_s"].to_numpy() / fp["samples_per_cpu_s"][key].to_numpy()
    )
    df["machine"] = f"{platform.machine()} python {platform.python_version()}"
    df["cores"] = os.cpu_count()
    df["numba_threads"] = numba.get_num_threads()
    return df


# --------------------------------------------------------------------------- report
def _cpu_model() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def _load() -> str:
    try:
        return " ".join(Path("/proc/loadavg").read_text().split()[:3])
    except OSError:
        return "unknown"


def machine_header() -> list[str]:
    """The machine, numba's threads and the BLAS pools (threadpoolctl), as printed."""
    lines = [
        f"machine: {platform.machine()} {_cpu_model()}, {os.cpu_count()} cores, "
        f"python {platform.python_version()}, numpy {np.__version__}, numba {numba.__version__}",
        f"numba: {numba.get_num_threads()} threads, threading layer {numba.config.THREADING_LAYER}",
    ]
    try:
        from threadpoolctl import threadpool_info
    except ImportError:
        lines.append("BLAS: threadpoolctl not installed")
    else:
        pools = threadpool_info()
        for p in pools:
            lines.append(
                f"BLAS/threads: {p.get('internal_api')} {p.get('version')} "
                f"({p.get('threading_layer', '-')}, {p.get('architecture', '-')}): "
                f"{p.get('num_threads')} threads"
            )
        if not pools:
            lines.append("BLAS/threads: no thread pool loaded")
    return lines


def _fmt_rates(rates) -> str:
    return " ".join(f"{r / 1e8:.2f}" for r in rates)


def table(df: pd.DataFrame) -> str:
    """Every row of every round: each call's wall-clock rate (1e8 samples/s) and the
    range of its calls' ratios to FilterPy, by wall clock and by CPU time."""
    out = []
    header = (
        f"{'round':>5} {'case':6} {'filter':16} {'implementation':40} "
        f"{'each call, 1e8 samples/s':>30} {'x FilterPy':>9} {'(CPU time)':>10}"
    )
    out.append(header)
    out.append("-" * len(header))
    order = {name: i for i, name in enumerate((*TARGETS, *REFERENCES, "filterpy", "python loop"))}
    keys = ["round", "case", "filter", "implementation"]
    grouped = df.groupby(keys, sort=False)
    for (rnd, case, filt, impl), g in sorted(
        grouped, key=lambda kv: (kv[0][0], kv[0][1] != "single", kv[0][2], order[kv[0][3]])
    ):
        ratios, cpu = g.ratio_vs_filterpy, g.cpu_ratio_vs_filterpy
        if impl in ("filterpy", "python loop"):
            rates = f"{g.samples_per_s.iloc[0]:.3g} /s"
            rng, crng = f"{ratios.iloc[0]:.3g}", f"{cpu.iloc[0]:.3g}"
        else:
            rates = _fmt_rates(g.samples_per_s)
            rng = f"{ratios.min():.0f}-{ratios.max():.0f}"
            crng = f"{cpu.min():.0f}-{cpu.max():.0f}"
        out.append(f"{rnd:>5} {case:6} {filt:16} {impl:40} {rates:>30} {rng:>9} {crng:>10}")
    return "\n".join(out)


def verdicts(df: pd.DataFrame) -> tuple[list[str], bool]:
    """The target lines and whether every target row meets >= 100x in every round."""
    lines, ok = [], True
    per_round = df.groupby(["case", "filter", "implementation", "round"]).agg(
        median_ratio=("ratio_vs_filterpy", "median"),
        min_ratio=("ratio_vs_filterpy", "min"),
        median_rate=("samples_per_s", "median"),
        median_cpu_ratio=("cpu_ratio_vs_filterpy", "median"),
        median_cpu_rate=("samples_per_cpu_s", "median"),
    )
    lines.append(f"target: every abglib row >= {TARGET_RATIO:.0f}x FilterPy in every round")
    for case in ("single", "batch"):
        for filt in GAINS:
            for impl in TARGETS:
                rows = per_round.loc[(case, filt, impl)]
                meets = bool((rows.median_ratio >= TARGET_RATIO).all())
                ok &= meets
                lines.append(
                    f"  {'meets' if meets else 'MISSES':6s} {case:6} {filt:16} {impl:40} "
                    f"round medians {' '.join(f'{v:.0f}x' for v in rows.median_ratio)}; "
                    f"lowest call {rows.min_ratio.min():.0f}x; by CPU time "
                    f"{' '.join(f'{v:.0f}x' for v in rows.median_cpu_ratio)}"
                )
    lines.append(f"issue 14 (batched, all four outputs): >= {TARGET_RATE:.0e} /s")
    for filt in GAINS:
        for impl in (OUT_BUFFERS, FRESH):
            rows = per_round.loc[("batch", filt, impl)]
            meets = bool((rows.median_rate >= TARGET_RATE).all())
            lines.append(
                f"  {'meets' if meets else 'MISSES':6s} {filt:16} {impl:40} round medians "
                f"{' '.join(f'{v:.3g}' for v in rows.median_rate)} /s"
            )
    lines.append(
        f"one series: >= {SINGLE_RATE:.0e} /s, or the dependency chain's own speed on this "
        "machine (a kernel that keeps the bits beats it only by speculating: docs/engine-speed.md)"
    )
    for filt in GAINS:
        chain = per_round.loc[("single", filt, CHAIN)].median_rate
        adds = df[(df.case == "single") & (df["filter"] == filt)].groupby("round")
        add_s, mul_s = adds.add_s.first(), adds.mul_s.first()
        chain_cpu = per_round.loc[("single", filt, CHAIN)].median_cpu_rate
        chain_len = (1.0 / chain_cpu) / add_s  # CPU time over CPU time: waits left out
        for impl in (OUT_BUFFERS, FRESH, X_ONLY):
            rate = per_round.loc[("single", filt, impl)].median_rate
            frac = rate / chain
            frac_cpu = per_round.loc[("single", filt, impl)].median_cpu_rate / chain_cpu
            lines.append(
                f"  {filt:16} {impl:40} round medians "
                f"{' '.join(f'{v:.3g}' for v in rate)} /s = "
                f"{' '.join(f'{v:.0%}' for v in frac)} of the chain "
                f"(CPU time: {' '.join(f'{v:.0%}' for v in frac_cpu)})"
            )
        lines.append(
            f"  {filt:16} {CHAIN:40} round medians "
            f"{' '.join(f'{v:.3g}' for v in chain)} /s (CPU time "
            f"{' '.join(f'{v:.3g}' for v in chain_cpu)} /s): one sample = "
            f"{' '.join(f'{v:.1f}' for v in chain_len)} dependent adds of CPU time "
            f"(add {' '.join(f'{1e9 * v:.2f}' for v in add_s)} ns, "
            f"multiply {' '.join(f'{1e9 * v:.2f}' for v in mul_s)} ns)"
        )
    return lines, ok


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", type=Path, default=Path("benchmarks/results/engine_speed.csv"))
    parser.add_argument("--quick", action="store_true", help="smaller sizes (a smoke test)")
    parser.add_argument("--rounds", type=int, default=3, help="rounds of every row (3)")
    parser.add_argument("--calls", type=int, default=5, help="timed calls a round (5)")
    args = parser.parse_args(argv)
    if args.rounds < 1 or args.calls < 1:
        parser.error(f"--rounds and --calls must be >= 1, got {args.rounds}, {args.calls}")
    load_before = _load()
    df = run(quick=args.quick, rounds=args.rounds, calls=args.calls)
    load_after = _load()
    args.out.parent.mkdir(parents=True, exist_ok=True)
    df.to_csv(args.out, index=False, float_format="%.6g")
    print("\n".join(machine_header()))
    print(f"load average (1, 5, 15 min): {load_before} before, {load_after} after")
    print(
        f"{args.rounds} rounds x {args.calls} calls per abglib row; peers one pass a round; "
        f"ratios against the same round's FilterPy\n"
    )
    print(table(df))
    lines, _ = verdicts(df)
    print()
    print("\n".join(lines))
    print(f"\nwritten {args.out} (one line per call)")
    worst = df.loc[df.implementation == "filterpy", "max_rel_diff"].max()
    if worst > 1e-9:
        print(f"FilterPy disagrees with abglib by {worst:.3g} relative (> 1e-9)", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
