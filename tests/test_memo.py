"""abglib.common.memo: the byte-bounded LRU cache of Al-Wagih's datasets and RMSE arrays,
checked against a plain dictionary model of least-recently-used eviction."""

from __future__ import annotations

from collections import OrderedDict

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from abglib import AbglibValueError
from abglib.bench import datasets
from abglib.common.memo import lru_cache_bytes


@given(
    budget=st.integers(0, 40),
    calls=st.lists(st.integers(0, 12), max_size=60),
)
def test_eviction_is_least_recently_used_within_the_byte_budget(budget, calls):
    """Every call's value, which calls compute, and what is held match a model: an ordered
    dict evicting its oldest entries while the held sizes exceed the budget."""
    computed = []

    @lru_cache_bytes(budget, len)
    def word(n):
        computed.append(n)
        return "x" * n

    model: OrderedDict[int, int] = OrderedDict()
    want = []
    for n in calls:
        assert word(n) == "x" * n
        if n in model:
            model.move_to_end(n)
            continue
        want.append(n)
        if n <= budget:
            model[n] = n
            while sum(model.values()) > budget:
                model.popitem(last=False)
    assert computed == want
    info = word.cache_info()
    assert (info.hits, info.misses) == (len(calls) - len(want), len(want))
    assert (info.entries, info.nbytes, info.max_bytes) == (len(model), sum(model.values()), budget)
    word.cache_clear()
    assert word.cache_info()[:4] == (0, 0, 0, 0)


def test_a_value_larger_than_the_budget_is_returned_and_not_kept():
    @lru_cache_bytes(4, len)
    def word(n):
        return "x" * n

    assert word(9) == "x" * 9
    assert word(9) == "x" * 9
    assert word.cache_info()[:4] == (0, 2, 0, 0)


@pytest.mark.parametrize("bad", [-1, 1.5, True, "10"])
def test_the_budget_must_be_whole_bytes(bad):
    with pytest.raises(AbglibValueError, match=r"max_bytes must be a whole number of bytes >= 0"):
        lru_cache_bytes(bad, len)


def test_a_datasets_bytes_are_its_arrays():
    spec = {
        "dt": 0.5,
        "n_samples": 7,
        "runs": 3,
        "seed": 1,
        "noise": {"sigma": 1.0, "colour": "white"},
        "tracks": {
            "x": {"kind": "constant_velocity", "p0": 0.0, "v0": 1.0},
            "y": {"kind": "constant_acceleration", "p0": 0.0, "v0": 1.0, "a0": 2.0},
        },
    }
    ds = datasets.generate("tiny", spec)
    series = (ds.truth_pos, ds.truth_vel, ds.truth_acc, ds.z)
    arrays = [ds.t, *(d[c] for d in series for c in ds.coords)]
    assert all(isinstance(a, np.ndarray) and a.dtype == np.float64 for a in arrays)
    # 7 times, and 4 series of 3 runs x 7 samples for each of the 2 coordinates
    assert ds.nbytes == 8 * (7 + 2 * 4 * 3 * 7)
