"""The rounding screen of the FAA Bendix memo gives exactly what the exact box gives."""

import numpy as np
import pytest

from abglib.analysis import vrf, vrf_benedict_ab
from abglib.gains import Gains
from abglib.replications.faa_bendix import program as bendix


def test_closed_form_is_within_the_screen_band_of_the_exact_vrf():
    box = bendix.rounding_box(0.5, 0.2, 2.0, half_unit=5e-4, n=21)
    cf = vrf_benedict_ab(Gains(box["alpha"].to_numpy(), box["beta"].to_numpy()), dt=2.0)
    for key, col in (("x_smooth", "position"), ("v_smooth", "velocity")):
        rel = np.abs(np.sqrt(cf[key]) / box[col].to_numpy() - 1.0)
        assert rel.max() < bendix.SCREEN_BAND * 1e-3


@pytest.mark.parametrize(
    "alpha, beta, T, printed", [(0.5, 0.2, 2.0, (0.83, 0.16)), (0.3, 0.05, 4.0, (0.5, 0.02))]
)
def test_rounding_extremes_equal_the_exact_box_bit_for_bit(alpha, beta, T, printed):
    tol = (0.005, 0.005)
    box = bendix.rounding_box(alpha, beta, T, half_unit=5e-4, n=31)
    worst = np.maximum(
        np.abs(box["position"] - printed[0]) / tol[0],
        np.abs(box["velocity"] - printed[1]) / tol[1],
    ).to_numpy()
    best = box.iloc[int(np.argmin(worst))]
    r = bendix.rounding_extremes(alpha, beta, T, printed, tol, half_unit=5e-4, n=31)
    assert r["position_min"] == box["position"].min()
    assert r["position_max"] == box["position"].max()
    assert r["velocity_min"] == box["velocity"].min()
    assert r["velocity_max"] == box["velocity"].max()
    assert (r["best_alpha"], r["best_beta"]) == (best["alpha"], best["beta"])
    assert (r["best_position"], r["best_velocity"]) == (best["position"], best["velocity"])
    assert r["best_worst"] == worst.min()


def test_rounding_extremes_solve_few_points_exactly(monkeypatch):
    sizes = []

    def counting_vrf(gains, dt=1.0):
        sizes.append(np.size(gains.alpha))
        return vrf(gains, dt=dt)

    monkeypatch.setattr(bendix, "vrf", counting_vrf)
    bendix.rounding_extremes(0.5, 0.2, 2.0, (0.83, 0.16), (0.005, 0.005), n=101)
    assert sizes and sizes[0] < 50
