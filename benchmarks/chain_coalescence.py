"""Could one α-β series beat its dependency chain and stay bit-identical? Measured here.

Usage::

    python benchmarks/chain_coalescence.py [--trials 20] [--samples 100000]

The idea it tests (docs/engine-speed.md, "Splitting one series"): cut one long series
into four parts and run them as four lanes of the batched kernel, each later part
started from a guessed state a little before its first sample, then verify. A fixed-gain
tracker forgets its initial state (the error decays as the spectral radius to the power
of the samples), so the guessed trajectory would meet the exact one; once the two states
``(x, v)`` are the same bits, every later sample is the same bits too (the recursion is
deterministic), and the part needs no recomputation. Where they never meet, the part
must be recomputed one sample after another from the exact state: slower than not
splitting at all.

Measured with the public API only, on the same measurements:

* **when two runs meet**: ``abglib.track`` over a whole series of ``2 * --samples``, and a
  second run started at its middle sample ``c`` from the guess ``(z_c, 0)``, as a split
  part would be; the first sample from which ``x_smooth`` and ``v_smooth`` of the two are
  bit for bit the same (they stay so: checked), per signal and gains, over ``--trials``
  seeded series;
* **what the split would buy**: one series of 10^6 samples against the same samples as
  four series of 2.5·10^5 in one call (the batched kernel's four lanes), median of 9
  calls each.

Signals: the engine benchmark's random walk (``cumsum`` of unit normals), and a radar
track at constant velocity (10 km, 250 m/s, 30 m noise, T = 0.1 s). Gains: critically
damped α-β for θ = 0.5, 0.8 (the engine benchmark's) and 0.95 (seed 000).
Seeded (``SEED``): every run prints the same meeting samples; the timings are this
machine's.
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


def signal(kind: str, n: int, rng: np.random.Generator) -> np.ndarray:
    """One seeded series of ``n`` samples of the named kind."""
    if kind == "random walk":
        return rng.normal(size=n).cumsum()
    t = np.arange(n) * DT
    return 1e4 + 250.0 * t + 30.0 * rng.normal(size=n)


def meeting_sample(z: np.ndarray, gains: Gains, start: int):
    """Samples after ``start`` until a run started there from the guess ``(z_start, 0)``
    is the same bits as the run of the whole series, or ``None`` if it never is; then, for
    runs that never met, how far apart they end (:func:`_apart_by`)."""
    exact = track(z, gains, dt=DT)
    guess = track(z[start:], gains, dt=DT, init=np.array([z[start], 0.0, 0.0]))
    same = np.ones(z.size - start, bool)
    for name in ("x_smooth", "v_smooth"):
        a, b = getattr(exact, name)[start:], getattr(guess, name)
        same &= a.view(np.int64) == b.view(np.int64)
    if not same.any():
        return None, _apart_by(exact, guess, start)
    k = int(np.argmax(same))
    assert same[k:].all(), "met, then parted: the recursion is not deterministic"
    return k, None


def _apart_by(exact, guess, start: int) -> tuple[float, float]:
    """At the last sample of two runs that never met: how far apart are x and v, in
    units in the last place (ulps) of each?"""
    dx, dv = (
        abs(getattr(exact, k)[-1] - getattr(guess, k)[-1]) / np.spacing(abs(getattr(exact, k)[-1]))
        for k in ("x_smooth", "v_smooth")
    )
    return float(dx), float(dv)


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
        f"{'signal':<18} {'theta':>5} {'met <= 4096':>12} {'met at all':>11} "
        f"{'median':>8}  meeting samples"
    )
    for kind in ("random walk", "radar track"):
        for theta in THETAS:
            gains = Gains(1 - theta**2, (1 - theta) ** 2)
            met = [
                meeting_sample(signal(kind, 2 * args.samples, rng), gains, args.samples)
                for _ in range(args.trials)
            ]
            found = sorted(k for k, _ in met if k is not None)
            apart = [d for _, d in met if d is not None]
            early = sum(k <= 4096 for k in found)
            med = f"{np.median(found):.0f}" if found else "-"
            shown = " ".join(str(k) for k in found[:8]) + (" ..." if len(found) > 8 else "")
            print(
                f"{kind:<18} {theta:>5} {early:>6}/{args.trials:<5} "
                f"{len(found):>5}/{args.trials:<5} {med:>8}  {shown}"
            )
            if apart:
                dx, dv = np.array(apart).T
                print(
                    f"{'':<25} never met: at the end x apart by {dx.min():.0f}-"
                    f"{dx.max():.0f} ulp, v by {dv.min():.0f}-{dv.max():.0f} ulp"
                )
    gains = Gains(1 - 0.8**2, (1 - 0.8) ** 2)
    z = signal("random walk", 10**6, rng)
    one = track(z, gains, dt=DT)
    four = track(z.reshape(4, -1), gains, dt=DT)
    t_one = median_ms(lambda: track(z, gains, dt=DT, out=one))
    t_four = median_ms(lambda: track(z.reshape(4, -1), gains, dt=DT, out=four))
    print(
        f"10^6 samples, 4 outputs, out= buffers: one series {t_one:.2f} ms, "
        f"four lanes of 2.5e5 {t_four:.2f} ms ({t_one / t_four:.2f}x)"
    )


if __name__ == "__main__":
    main()
