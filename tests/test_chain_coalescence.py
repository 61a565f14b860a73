"""benchmarks/chain_coalescence.py: the measurement behind docs/engine-speed.md's
"Splitting one series" (why a speculative split of one series was not adopted)."""

import importlib.util
from pathlib import Path

import numpy as np
import pytest

from abglib import Gains

SCRIPT = Path(__file__).resolve().parents[1] / "benchmarks" / "chain_coalescence.py"
_spec = importlib.util.spec_from_file_location("chain_coalescence", SCRIPT)
cc = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(cc)

GAINS = Gains(1 - 0.8**2, (1 - 0.8) ** 2)


def test_a_guessed_run_that_never_meets_moves_its_velocity_difference_in_coarse_steps():
    """The documented mechanism, on one seeded circling target: the guessed run never meets
    the exact one. Where the two predictions ``x_p`` are the same bits, the velocity
    difference moves by at most one ulp of ``v`` and is too small for ``x_p`` to show
    (``T * dv`` under an ulp of ``x``); where they differ, it moves by many ulps."""
    z = cc.signal("circling", 40_000, np.random.default_rng(1))
    met, (dx, dv, share, loud, step, quiet) = cc.meeting_sample(z, GAINS, 20_000)
    assert met is None
    assert dx == 0.0 and dv >= 1.0
    assert 0.0 < share < 0.2 and loud > 0 and step > 10.0 and quiet <= 1.0
    (pe, xe, ve), (pg, xg, vg) = cc.runs(z, GAINS, 20_000)
    same_p = pe == pg
    assert np.all(ve != vg)  # never met: the velocities differ at every sample
    tv = cc.DT * np.abs(ve - vg)
    assert np.all(tv[:-1][same_p[1:]] < np.spacing(np.abs(xe[:-1][same_p[1:]])))
    moves = np.abs(np.diff(ve - vg)) / np.spacing(np.abs(ve[1:]))
    assert moves[same_p[1:]].max() <= 1.0


def test_a_guessed_run_that_meets_stays_the_same_bits():
    """From the meeting sample on, every output of the two runs is the same bits (x_pred
    included, which the meeting test does not compare); the sample before, they differ."""
    from abglib import track

    rng = np.random.default_rng(4)
    for _ in range(10):
        z = cc.signal("random walk", 20_000, rng)
        met, _ = cc.meeting_sample(z, GAINS, 10_000)
        if met is not None:
            break
    assert met is not None and 0 < met < 10_000
    exact = track(z, GAINS, dt=cc.DT)
    guess = track(z[10_000:], GAINS, dt=cc.DT, init=np.array([z[10_000], 0.0, 0.0]))
    for name in ("x_pred", "x_smooth", "v_smooth"):
        a = getattr(exact, name)[10_000 + met + 1 :]
        b = getattr(guess, name)[met + 1 :]
        assert np.array_equal(a.view(np.int64), b.view(np.int64)), name
    before = 10_000 + met - 1
    assert (exact.x_smooth[before], exact.v_smooth[before]) != (
        guess.x_smooth[met - 1],
        guess.v_smooth[met - 1],
    )


def test_an_unknown_signal_is_refused_by_name():
    with pytest.raises(ValueError, match=r"signal must be one of .*got 'sine'"):
        cc.signal("sine", 10, np.random.default_rng(0))
