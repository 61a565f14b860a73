"""abglib.replications._numerics.snap: machine-independent inputs to simulations."""

from __future__ import annotations

import numpy as np
import pytest

from abglib.replications._numerics import snap

from .conftest import small_config, study_for


def test_snap_is_within_its_bound_idempotent_and_absorbs_last_bits():
    rng = np.random.default_rng(5)
    x = rng.normal(size=1000) * 10.0 ** rng.integers(-8, 8, size=1000)
    s = snap(x, 36)
    assert np.all(np.abs(s - x) <= np.abs(x) * 2.0**-36)  # half a unit of 36 mantissa bits
    assert np.array_equal(snap(s, 36), s)
    # a 1-ulp difference (an FMA kernel against an SSE one) lands on the same grid point
    # unless the value sits within an ulp of a grid boundary (probability ~2^-16 here)
    same = snap(np.nextafter(x, np.inf), 36) == s
    assert same.mean() > 0.99


def test_huang_designed_gains_are_snapped():
    study = study_for("huang", small_config())
    for name, g in study.trackers.items():
        if not name.endswith("_printed"):
            assert all(snap(v) == v for v in g), name


@pytest.mark.parametrize("bits", [20, 36, 52])
def test_snap_keeps_exact_binary_values(bits):
    assert snap(0.5, bits) == 0.5 and snap(-3.0, bits) == -3.0 and snap(0.0, bits) == 0.0
