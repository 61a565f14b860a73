"""Could one α-β series beat its dependency chain and stay bit-identical? Measured here.

Usage::

    python benchmarks/chain_coalescence.py [--trials 20] [--samples 100000]

The idea it tests (docs/engine-speed.md, "Splitting one series"): cut one long series
into four parts and run them as four lanes of the batched kernel, each later part
started from a guessed state some samples before its first one, then verify. A stable
fixed-gain tracker forgets its initial state (for critically damped gains the error
decays as ``k θ^k``), so the guessed run should meet the exact one; once the two states
``(x, v)`` are the same bits, every later sample is the same bits too (the recursion is
deterministic), and the part needs no recomputation. A part whose run has not met the
exact one must be recomputed one sample after another from the exact state, until the
two meet or the part ends: where they never meet, that is slower than not splitting.

Measured with the public API only, on the same measurements:

* **when two runs meet**: ``abglib.track`` over a whole series of ``2 * --samples``, and a
  second run started at its middle sample ``c`` from the guess ``(z_c, 0)``, as a split
  part would be; the first sample from which ``x_smooth`` and ``v_smooth`` of the two are
  bit for bit the same (they stay so: checked), per signal and gains, over ``--trials``
  seeded series. "Within 4096" is what an overlap of 4096 samples, run at the four
  lanes' speed before a part's first own sample, would absorb;
* **how runs that never meet differ** (:func:`apart`): at the last sample, ``x`` and ``v``
  apart in ulps of each; the share of samples whose prediction ``x_p`` differs, how the
  velocity difference moves there, and how little it moves where ``x_p`` is the same;
* **what the split would buy**: one series of 10^6 samples against the same samples as
  four series of 2.5·10^5 in one call (the batched kernel's four lanes), median of 9
  calls each.

Signals (``dt = 0.1`` s, 30 m noise on the radar ones, at ranges a radar tracks): the
engine benchmark's random walk (``cumsum`` of unit normals); a target inbound from 100 km
to 20 km at 200 m/s, a new pass every 400 s; a target circling, its range 50 ± 20 km over a period
of 600 s; a stationary target at 10 km. Gains: critically damped α-β for θ = 0.5, 0.8
(the engine benchmark's) and 0.95 (seed 000). Seeded (``SEED``): every run prints the
same meeting samples; the timings are this machine's.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # this checkout's abglib
from abglib import Gains, track  # noqa: E402

SEED = 20261204
DT = 0.1
THETAS = (0.5, 0.8, 0.95)
SIGNALS = ("random walk", "inbound", "circling", "stationary")
OVERLAP = 4096


def signal(kind: str, n: int, rng: np.random.Generator) -> np.ndarray:
    """One seeded series of ``n`` samples of the named kind (see the module docstring)."""
    if kind == "random walk":
        return rng.normal(size=n).cumsum()
    t = np.arange(n) * DT
    noise = 30.0 * rng.normal(size=n)
    if kind == "inbound":
        return 100e3 - 200.0 * (t % 400.0) + noise
    if kind == "circling":
        return 50e3 + 20e3 * np.sin(2 * np.pi * t / 600.0) + noise
    if kind == "stationary":
        return 10e3 + noise
    raise ValueError(f"signal must be one of {SIGNALS}, got {kind!r}")


def runs(z: np.ndarray, gains: Gains, start: int):
    """The run of the whole series from sample ``start`` on, and a run started there from
    the guess ``(z_start, 0)``: ``(x_pred, x_smooth, v_smooth)`` of each."""
    exact = track(z, gains, dt=DT)
    guess = track(z[start:], gains, dt=DT, init=np.array([z[start], 0.0, 0.0]))
    names = ("x_pred", "x_smooth", "v_smooth")
    return (
        tuple(getattr(exact, k)[start:] for k in names),
        tuple(getattr(guess, k) for k in names),
    )


def meeting_sample(z: np.ndarray, gains: Gains, start: int):
    """Samples after ``start`` until the guessed run (:func:`runs`) is the same bits as the
    exact one, or ``None`` if it never is; and, for runs that never met, :func:`apart`."""
    exact, guess = runs(z, gains, start)
    (_, xe, ve), (_, xg, vg) = exact, guess
    same = (xe.view(np.int64) == xg.view(np.int64)) & (ve.view(np.int64) == vg.view(np.int64))
    if not same.any():
        return None, apart(exact, guess)
    k = int(np.argmax(same))
    if not same[k:].all():
        raise RuntimeError("the runs met, then parted: the recursion is not deterministic")
    return k, None


def apart(exact, guess) -> tuple[float, float, float, int, float, float]:
    """How two runs that never met differ (the ``(x_pred, x_smooth, v_smooth)`` of each).

    At the last sample, ``x`` and ``v`` apart in ulps (units in the last place) of each.
    Over the run: the share of samples whose prediction ``x_p`` differs; how many times the
    velocity difference changed at such samples, and its median step there in ulps of
    ``v``; and its largest step, in ulps of ``v``, at samples whose ``x_p`` is the same
    bits (the residual ``r`` is then the same too).
    """
    (pe, xe, ve), (pg, xg, vg) = exact, guess
    dx = abs(xe[-1] - xg[-1]) / np.spacing(abs(xe[-1]))
    dv = abs(ve[-1] - vg[-1]) / np.spacing(abs(ve[-1]))
    p_differs = pe != pg
    step = np.abs(np.diff(ve - vg)) / np.spacing(np.abs(ve[1:]))
    moved = step > 0
    loud = step[moved & p_differs[1:]]
    quiet = step[moved & ~p_differs[1:]]
    return (
        float(dx),
        float(dv),
        float(np.mean(p_differs)),
        int(loud.size),
        float(np.median(loud)) if loud.size else 0.0,
        float(quiet.max()) if quiet.size else 0.0,
    )


def median_ms(call, calls: int = 9) -> float:
    times = []
    for _ in range(calls):
        t0 = time.perf_counter()
        call()
        times.append(time.perf_counter() - t0)
    return 1e3 * float(np.median(times))


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--trials", type=int, default=20)
    ap.add_argument("--samples", type=int, default=100_000)
    args = ap.parse_args(argv)
    rng = np.random.default_rng(SEED)
    print(
        f"a run of the whole series against one started at its middle sample c from "
        f"(z_c, 0); {args.trials} series of 2 x {args.samples} samples; dt = {DT}"
    )
    print(
        f"{'signal':<12} {'theta':>5} {f'met <= {OVERLAP}':>12} {'met at all':>11} "
        f"{'median':>8}  meeting samples"
    )
    for kind in SIGNALS:
        for theta in THETAS:
            gains = Gains(1 - theta**2, (1 - theta) ** 2)
            met = [
                meeting_sample(signal(kind, 2 * args.samples, rng), gains, args.samples)
                for _ in range(args.trials)
            ]
            found = sorted(k for k, _ in met if k is not None)
            never = np.array([d for _, d in met if d is not None])
            early = sum(k <= OVERLAP for k in found)
            med = f"{np.median(found):.0f}" if found else "-"
            shown = " ".join(str(k) for k in found[:8]) + (" ..." if len(found) > 8 else "")
            print(
                f"{kind:<12} {theta:>5} {early:>6}/{args.trials:<5} "
                f"{len(found):>5}/{args.trials:<5} {med:>8}  {shown}"
            )
            if never.size:
                dx, dv, share, loud, step, quiet = never.T
                print(
                    f"{'':<19} never met: at the end x apart by {dx.min():.0f}-{dx.max():.0f} "
                    f"ulp, v by {dv.min():.0f}-{dv.max():.0f} ulp; x_p differs in "
                    f"{100 * share.min():.1f}-{100 * share.max():.1f} % of samples, where the "
                    f"v difference moved {loud.min():.0f}-{loud.max():.0f} times (median step "
                    f"{np.median(step):.3g} ulp of v); elsewhere by <= {quiet.max():.0f} ulp"
                )
    gains = Gains(1 - 0.8**2, (1 - 0.8) ** 2)
    z = signal("random walk", 10**6, rng)
    one = track(z, gains, dt=DT)
    four = track(z.reshape(4, -1), gains, dt=DT)
    t_one = median_ms(lambda: track(z, gains, dt=DT, out=one))
    t_four = median_ms(lambda: track(z.reshape(4, -1), gains, dt=DT, out=four))
    print(
        f"10^6 samples, 4 outputs, out= buffers: one series {t_one:.2f} ms, four lanes of "
        f"2.5e5 {t_four:.2f} ms ({t_one / t_four:.2f}x); if no part meets: the lanes plus "
        f"three quarters of one series, {t_four + 0.75 * t_one:.2f} ms "
        f"({t_one / (t_four + 0.75 * t_one):.2f}x)"
    )


if __name__ == "__main__":
    main()
