"""A user's own tracker in the benchmark matrix (config ``callable:``, abglib.bench.variants)."""

import numpy as np
import pytest

from abglib import AbglibValueError, Gains, track
from abglib.bench.variants import (
    callable_file,
    check_variant,
    describe_variant,
    resolve_callable,
    variant_build,
)

USER_CODE = """
import numpy as np
from abglib import Gains, track


def fixed(dt, n_samples, alpha=0.5, beta=0.2):
    return Gains(alpha, beta)


def as_tuple(dt, n_samples, alpha):
    return (alpha, alpha ** 2 / (2 - alpha))


def moving_average(dt, n_samples, window=3):
    def run(z):
        kernel = np.ones(window) / window
        x = np.array([np.convolve(r, kernel)[: r.size] for r in z])
        pred = np.concatenate([z[:, :1], x[:, :-1]], axis=1)
        return {"x_pred": pred, "x_smooth": x}
    return run


def wrong(dt, n_samples):
    return "gains"


def bad_shape(dt, n_samples):
    return lambda z: {"x_pred": z[:, :-1]}


def broken(dt, n_samples):
    raise RuntimeError("boom")
"""


@pytest.fixture
def user_file(tmp_path):
    f = tmp_path / "my_trackers.py"
    f.write_text(USER_CODE, encoding="utf-8")
    return f


def test_a_file_callable_returns_gains_or_a_tracker(user_file):
    g = variant_build({"callable": f"{user_file}:fixed", "alpha": 0.4}, 1.0, 50)
    assert isinstance(g, Gains) and float(g.alpha) == 0.4 and float(g.beta) == 0.2
    g = variant_build({"callable": f"{user_file}:as_tuple", "alpha": 0.5}, 1.0, 50)
    assert float(g.beta) == pytest.approx(0.25 / 1.5, rel=1e-15)
    run = variant_build({"callable": f"{user_file}:moving_average", "window": 2}, 1.0, 5)
    z = np.arange(10.0).reshape(2, 5)
    res = run(z)
    np.testing.assert_allclose(res.x_smooth[0], [0.0, 0.5, 1.5, 2.5, 3.5])
    assert res.x_pred.shape == z.shape


def test_a_module_callable_and_relative_files(tmp_path, user_file, monkeypatch):
    monkeypatch.syspath_prepend(str(tmp_path))
    spec = {"callable": "my_trackers:fixed"}
    g = variant_build(spec, 1.0, 10)
    np.testing.assert_array_equal(
        track(np.ones((1, 10)), g).x_smooth, track(np.ones((1, 10)), Gains(0.5, 0.2)).x_smooth
    )
    assert callable_file(spec) == user_file
    rel = resolve_callable({"callable": "my_trackers.py:fixed", "alpha": 0.3}, base=tmp_path)
    assert rel == {"callable": f"{user_file}:fixed", "alpha": 0.3}
    assert callable_file(rel) == user_file
    assert resolve_callable({"rule": "gains", "alpha": 0.3, "beta": 0.1}) == {
        "rule": "gains",
        "alpha": 0.3,
        "beta": 0.1,
    }


@pytest.mark.parametrize(
    ("target", "message"),
    [
        ("no_such_module_xyz:f", "module 'no_such_module_xyz' not found"),
        ("{file}:nope", "has no function 'nope'; it defines: .*fixed"),
        ("{file}:wrong", "must return abglib.Gains, a tuple .* got str"),
        ("{file}:bad_shape", r"returned x_pred of shape \(2, 9\), expected .* \(2, 10\)"),
        ("{file}:broken", "raised RuntimeError: boom"),
        ("{dir}/missing.py:f", "no such file"),
        ("nocolon", "must be '<module>:<function>'"),
    ],
)
def test_bad_callables_fail_the_check_naming_the_variant(user_file, target, message):
    spec = {"callable": target.format(file=user_file, dir=user_file.parent)}
    with pytest.raises(AbglibValueError, match="variant 'mine'") as err:
        check_variant(spec, 1.0, 10, "mine")
    assert err.match(message)


def test_the_variants_table_describes_a_user_variant_without_loading_it():
    row = describe_variant({"callable": "somewhere.py:mine", "q": 1, "family": "mine"}, "v")
    assert row == {
        "variant": "v",
        "rule": "callable",
        "family": "mine",
        "fixed_gain": None,
        "source": "somewhere.py:mine",
        "parameters": "q=1",
    }
    assert describe_variant({"callable": "m:f"}, "v")["family"] == "user: f"
