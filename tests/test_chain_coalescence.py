"""benchmarks/chain_coalescence.py: the measurement behind docs/engine-speed.md's
"Splitting one series" (why a speculative split of one series was not adopted)."""

import importlib.util
from pathlib import Path

import numpy as np

from abglib import Gains, track

SCRIPT = Path(__file__).resolve().parents[1] / "benchmarks" / "chain_coalescence.py"
_spec = importlib.util.spec_from_file_location("chain_coalescence", SCRIPT)
cc = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(cc)

GAINS = Gains(1 - 0.8**2, (1 - 0.8) ** 2)


def test_a_radar_track_started_from_a_guess_keeps_a_velocity_below_the_positions_ulp():
    """The documented mechanism, on one seeded radar track: the guessed run never meets the
    exact one; it ends with the same position bits and a velocity some ulp apart, a
    difference that ``T * dv`` cannot show in ``x`` (under half an ulp of ``x``)."""
    z = cc.signal("radar track", 40_000, np.random.default_rng(3))
    met, apart = cc.meeting_sample(z, GAINS, 20_000)
    assert met is None
    dx, dv = apart
    assert dx == 0.0 and dv >= 1.0
    exact = track(z, GAINS, dt=cc.DT)
    guess = track(z[20_000:], GAINS, dt=cc.DT, init=np.array([z[20_000], 0.0, 0.0]))
    x, v = exact.x_smooth[-1], exact.v_smooth[-1]
    assert guess.x_smooth[-1] == x
    assert 0 < cc.DT * abs(guess.v_smooth[-1] - v) < 0.5 * np.spacing(x)


def test_a_random_walk_started_from_a_guess_meets_and_stays_the_same_bits():
    """Near the origin the runs meet; from the meeting sample on, every output of the two
    runs is the same bits (x_pred included, which the meeting test does not compare)."""
    rng = np.random.default_rng(4)
    met = None
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
    before = 10_000 + met - 1  # the sample before the meeting: still apart
    assert (exact.x_smooth[before], exact.v_smooth[before]) != (
        guess.x_smooth[met - 1],
        guess.v_smooth[met - 1],
    )
