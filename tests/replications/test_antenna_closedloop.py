"""Seed 004, ch. 6, 8 and app. H: closed-loop simulations and their linear twins."""

import numpy as np
import pytest

from abglib import Gains, track
from abglib._checks import AbglibValueError
from abglib.analysis._statespace import state_space
from abglib.replications.antenna import (
    AntennaParams,
    closed_loop_matrix,
    design_controller,
    simulate,
    spectral_radius,
    steady_state_amplitudes,
)

from .antenna_common import DT, NOMINAL_VALUES, OWN_KERNEL_SIGNATURES

pytestmark = OWN_KERNEL_SIGNATURES

NOMINAL = AntennaParams(**NOMINAL_VALUES)
VV = 1e-3 * np.eye(2)


@pytest.fixture(scope="module")
def ctrl():
    return design_controller(NOMINAL, DT, 100.0, 1.0)


@pytest.mark.parametrize(
    ("mode", "order", "omega"), [("known", None, 0.5), ("predicted", 2, 0.3), ("predicted", 5, 0.8)]
)
def test_steady_state_amplitude_equals_simulation(ctrl, mode, order, omega):
    """Frequency-response amplitudes (Figs I.8-I.9) against a long time simulation: the
    simulated maximum after the transient approaches the amplitude from below."""
    n = 4000
    r = simulate(NOMINAL, ctrl, amplitude=1.0, omega=omega, n_steps=n, mode=mode, order=order)
    a = steady_state_amplitudes(ctrl, omega, 1.0, mode, order)
    tail = slice(n // 2, None)
    # sampled sinusoid: the maximum over many periods reaches the amplitude to O(dt^2)
    assert np.abs(r["e"][tail]).max() == pytest.approx(a["e"], rel=2e-2)
    assert np.abs(r["u"][tail]).max() == pytest.approx(a["u"], rel=2e-2)
    assert np.abs(r["e"][tail]).max() <= a["e"] * (1 + 1e-9)


def test_kalman_run_exact_model_keeps_antenna_estimate(ctrl):
    """With the exact antenna model and w = 0, the object estimate is all the filter does:
    the run is bounded and the estimation error of the position stays small."""
    r = simulate(
        NOMINAL,
        ctrl,
        amplitude=10.0,
        omega=0.1,
        n_steps=600,
        mode="kalman",
        order=5,
        v_w=5e-10,
        v_v=VV,
    )
    assert np.abs(r["e"][200:]).max() < 1.0
    assert np.abs(r["xt_err"][0, 200:]).max() < 0.5


def test_abg_mode_is_the_canonical_tracker(ctrl):
    """The alpha-beta-gamma object estimator inside the loop is abglib.track on the same
    measurements (CONTRACTS section 1): its predictions equal track's x_pred."""
    g = Gains(0.5, 0.2, 0.02)
    r = simulate(NOMINAL, ctrl, amplitude=10.0, omega=0.1, n_steps=300, mode="abg", abg=g)
    zm = r["y"] - np.round((r["y"] - r["z"]) / 0.1) * 0.1
    x0 = np.array([0.0, 1.0, 0.0])  # true [z, z', z''] at t = 0
    init = np.linalg.solve(state_space(g, DT, reduced=False).Phi, x0)
    out = track(zm, g, dt=DT, init=init)
    np.testing.assert_allclose(r["xt_err"][0] + r["z"], out.x_pred, atol=1e-10)


def test_robustness_radius_and_simulation_agree(ctrl):
    """App. H: nominal radius 1 (marginal, unexcited); a p_a design error of -10 % gives a
    radius > 1 and a diverging simulation."""
    assert spectral_radius(NOMINAL, "p_a", 1.0, DT, 100.0, 1.0, 5, 5e-10, VV) == pytest.approx(
        1.0, abs=1e-7
    )
    rad = spectral_radius(NOMINAL, "p_a", 0.9, DT, 100.0, 1.0, 5, 5e-10, VV)
    assert rad > 1.1
    bad = design_controller(NOMINAL.scaled("p_a", 0.9), DT, 100.0, 1.0)
    r = simulate(
        NOMINAL,
        bad,
        amplitude=10.0,
        omega=0.1,
        n_steps=300,
        mode="kalman",
        order=5,
        v_w=5e-10,
        v_v=VV,
    )
    assert np.abs(r["e"][-20:]).max() > 100.0
    big = closed_loop_matrix(NOMINAL, ctrl, 5, 5e-10, VV)
    assert big.shape == (6 + 6 + 6, 6 + 6 + 6)


def test_simulate_errors(ctrl):
    common = dict(amplitude=1.0, omega=0.1, n_steps=10)
    with pytest.raises(AbglibValueError, match="mode must be one of"):
        simulate(NOMINAL, ctrl, mode="x", **common)
    with pytest.raises(AbglibValueError, match="needs an order of prediction"):
        simulate(NOMINAL, ctrl, mode="predicted", **common)
    with pytest.raises(AbglibValueError, match="needs v_w and v_v"):
        simulate(NOMINAL, ctrl, mode="kalman", order=3, **common)
    with pytest.raises(AbglibValueError, match="needs alpha-beta-gamma gains"):
        simulate(NOMINAL, ctrl, mode="abg", **common)
    with pytest.raises(AbglibValueError, match="n_steps must be >= 1"):
        simulate(NOMINAL, ctrl, mode="known", amplitude=1.0, omega=0.1, n_steps=0)
    with pytest.raises(AbglibValueError, match="mode must be 'known' or 'predicted'"):
        steady_state_amplitudes(ctrl, 0.1, mode="kalman")


def test_stable_interval_edges_are_where_the_radius_crosses():
    """App. H's stability window of p_a: the located edges have radius 1 + tol, and the
    factors just inside/outside are stable/unstable."""
    from abglib.replications.antenna import stable_interval

    tol = 1e-6
    args = (DT, 100.0, 1.0, 5, 5e-10, VV)
    lo, hi = stable_interval(NOMINAL, "p_a", *args, grid=[0.95, 1.0, 1.06], tol=tol)
    assert 0.95 < lo < 1.0 < hi < 1.06
    for edge in (lo, hi):
        assert spectral_radius(NOMINAL, "p_a", edge, *args) == pytest.approx(1 + tol, abs=1e-5)
    assert spectral_radius(NOMINAL, "p_a", lo * 0.995, *args) > 1 + tol
    assert spectral_radius(NOMINAL, "p_a", hi * 1.005, *args) > 1 + tol


# ----------------------------------------------------------------------------- written precision
def test_wrap_phase_writes_both_sides_of_the_cut_alike():
    """A phase at the branch cut (pi - 1e-9 on one BLAS kernel, -pi + 1e-9 on another, as
    measured for the known-output case at Q/R = 10^4) is written the same."""
    from abglib.common.tables import format_cell
    from abglib.replications.antenna.study_exact import PHASE_DIGITS, wrap_phase

    for eps in (0.0, 1e-12, 1e-9, 4e-5):
        a = format_cell(wrap_phase(np.pi - eps), PHASE_DIGITS)
        b = format_cell(wrap_phase(-np.pi + eps), PHASE_DIGITS)
        assert a == b == "3.142"
    # away from the cut the phase is unchanged
    for ph in (-3.0, -1.479, 0.0, 0.6556, 3.0):
        assert wrap_phase(ph) == ph


def test_omega_sweep_precision_and_roundoff_phase():
    """e_max is declared to hold 4 digits above its absolute round-off; below it e_max is
    written as the bound and its phase (undefined) is left empty."""
    from abglib.common.tables import format_table
    from abglib.replications.antenna.study_exact import E_ROUNDOFF, omega_sweep_table

    ctrl = design_controller(NOMINAL, DT, 1e4, 1.0)
    d = omega_sweep_table({1e4: ctrl}, 1.0, {"start": 0.003, "stop": 1.0, "n": 3, "orders": [5]})
    assert d.attrs["precision"] == {"e_max": f"<{E_ROUNDOFF:g}:4", "phase_e": 4, "u_max": 6}
    small = d["e_max"] < E_ROUNDOFF
    assert small.any() and not small.all()
    assert d.loc[small, "phase_e"].isna().all() and d.loc[~small, "phase_e"].notna().all()
    assert np.all(d["phase_e"].dropna() <= np.pi + 1e-3)
    out = format_table(d)
    assert (out.loc[small, "e_max"] == f"<{E_ROUNDOFF:g}").all()
    assert (out.loc[small, "phase_e"] == "").all()


def test_checks_roundoff_written_as_bound():
    from abglib.common.tables import format_table
    from abglib.replications.antenna.study_exact import checks_table

    ctrl = design_controller(NOMINAL, DT, 100.0, 1.0)
    d = checks_table(ctrl, 100.0, 1.0, 1e-3 * np.eye(2))
    out = format_table(d).set_index("check")["value"]
    assert out["Riccati eq 2.12: iteration vs scipy solve_discrete_are"] == "<1e-10"
    assert out["Stein eq E.4 (order 5): Kronecker vs Bartels-Stewart, rel. diff"] == "<1e-10"
    assert out["spectral radius of A_g (eq 2.16)"] == "0.944999"


def test_roundoff_notes_print_a_bound():
    from abglib.replications.antenna.claims_exact import roundoff

    assert roundoff(5.4e-14) == "< 1e-12"
    assert roundoff(9.58e-5) == "9.6e-05"


def test_tracking_table_precision():
    """y and e of the time series hold 5 digits above an absolute round-off of 1e-10."""
    from abglib.common.tables import format_table
    from abglib.replications.antenna.study_exact import TRACK_PRECISION, tracking_table

    ctrl = design_controller(NOMINAL, DT, 100.0, 1.0)
    d = tracking_table(NOMINAL, ctrl, 10.0, 0.1, {"duration": 20.0, "orders": [2]})
    assert d.attrs["precision"] == {
        "y": TRACK_PRECISION,
        "e": TRACK_PRECISION,
        "u": TRACK_PRECISION,
    }
    out = format_table(d)
    assert out.loc[0, "y"] == "<1e-10"  # the antenna at rest: below the round-off bound
    assert out.loc[1, "y"] == f"{d.loc[1, 'y']:.5g}" and out.loc[1, "e"] == f"{d.loc[1, 'e']:.5g}"


@pytest.mark.parametrize(("order", "v_w", "res"), [(5, 5e-3, 0.1), (3, 5e-2, 0.1), (5, 5e3, 1e-6)])
def test_time_major_kalman_loop_equals_the_phase_loop_bit_for_bit(ctrl, order, v_w, res):
    """ensemble._kalman_loop (all phases one step at a time, vectorised) against
    _kalman_loop_by_phase (one phase after the other): the same operations per phase, so the
    same bits, the quantiser's decisions included."""
    from abglib.replications.antenna import ensemble

    calls = []
    real = ensemble._kalman_loop

    def spy(*args):
        calls.append(args)
        return real(*args)

    ensemble._kalman_loop = spy
    try:
        ensemble.simulate_phases(
            NOMINAL, ctrl, amplitude=1.0, omega=0.3, n_steps=300, mode="kalman",
            phases=ensemble.phase_grid(7), order=order, v_w=v_w, v_v=VV, resolution=res,
        )  # fmt: skip
    finally:
        ensemble._kalman_loop = real
    (args,) = calls
    assert args[-1] is True  # the zeros of A - Kf M are skipped
    outs = []
    for skip in (True, False, None):
        y, u, err = (np.full_like(a, 7.0) for a in args[-4:-1])
        if skip is None:
            ensemble._kalman_loop_by_phase(*args[:-4], y, u, err)
        else:
            assert ensemble._kalman_loop(*args[:-4], y, u, err, skip)
        outs.append((y, u, err))
    for o in outs[1:]:
        for a, b in zip(outs[0], o, strict=True):
            assert a.tobytes() == b.tobytes()
    assert np.unique(np.round(outs[0][0] / 0.1)).size > 10  # the run moved


def test_kalman_loop_skipping_zeros_falls_back_where_a_run_diverges(ctrl):
    """A design with p_a halved diverges (app. H, spectral radius 10): the state overflows,
    and the loop that skips the zeros of A - Kf M reports it (0 * inf = nan would have
    entered); the ensemble then equals the dense reference loop bit for bit, nan and inf
    included."""
    from abglib.replications.antenna import ensemble

    bad = design_controller(NOMINAL.scaled("p_a", 0.5), DT, 100.0, 1.0)
    kw = dict(amplitude=10.0, omega=0.1, n_steps=1600, mode="kalman", order=5, v_w=5e-8,
              v_v=VV, resolution=0.1, phases=ensemble.phase_grid(3))  # fmt: skip
    calls = []
    real = ensemble._kalman_loop

    def spy(*args):
        calls.append(args)
        return real(*args)

    ensemble._kalman_loop = spy
    try:
        r = ensemble.simulate_phases(NOMINAL, bad, **kw)
    finally:
        ensemble._kalman_loop = real
    assert [c[-1] for c in calls] == [True, False]  # skipped, diverged, rerun dense
    assert not np.isfinite(r["y"][:, -1]).any()
    y, u, err = (np.full_like(a, 7.0) for a in calls[0][-4:-1])
    ensemble._kalman_loop_by_phase(*calls[0][:-4], y, u, err)
    for a, b in zip((y, u, err), (r["y"], r["u"], r["xt_err"]), strict=True):
        assert a.tobytes() == b.tobytes()
