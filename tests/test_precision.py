"""Perturbed arithmetic (abglib._perturb) and the precision derived from it
(abglib.reporting.precision; the lookup, abglib.common.tables): every spec checked against
values made by hand."""

import warnings

import numpy as np
import pandas as pd
import pytest

import abglib
from abglib._checks import AbglibValueError
from abglib._perturb import ENV, RELATIVE, perturb, perturb_scalar, perturbation_seed
from abglib.common import tables
from abglib.common.tables import csv_text, format_cell
from abglib.reporting import precision as prec
from abglib.reporting.verify import cell_agrees


# --------------------------------------------------------------------------- perturbation
def test_perturbation_is_small_idempotent_and_keeps_special_values():
    x = np.array([0.5, 0.1, -3.3, 1e300, 0.0, -0.0, 5e-324, np.inf, -np.inf, np.nan])
    for k in (1, 2, 7):
        y = perturb(x, k)
        rel = np.abs(y[:4] / x[:4] - 1)
        assert (rel <= RELATIVE).all() and (rel > 0).any()
        assert np.array_equal(np.sign(y[:4]), np.sign(x[:4]))
        np.testing.assert_array_equal(y[4:], x[4:])  # zeros, a subnormal, infinities, NaN
        np.testing.assert_array_equal(perturb(y, k), y)  # idempotent
    assert not np.array_equal(perturb(x, 1)[:4], perturb(x, 2)[:4])  # seeds differ


def test_scalar_route_gives_the_array_routes_bits():
    """A Gains' scalars take a route on Python's integers (perturb of a 0-d array, and
    perturb_scalar): bit for bit the numpy route's, for random doubles of every exponent
    and sign, and the special values it keeps (zeros, subnormals, infinities, NaN)."""
    from abglib._perturb import _perturbed

    rng = np.random.default_rng(20261202)
    bits = rng.integers(0, 2**64 - 1, size=4000, dtype=np.uint64, endpoint=True)
    x = bits.view(np.float64)
    x = np.concatenate([x, [0.0, -0.0, 5e-324, -2.2e-308, np.inf, -np.inf, np.nan, 1.0, 0.3]])
    for k in (1, 2, 7, 2**31 - 1):
        ref = _perturbed(x, k).view(np.uint64)
        one = np.array([perturb(np.array(v), k) for v in x]).view(np.uint64)
        scalar = np.array([perturb_scalar(float(v), k) for v in x]).view(np.uint64)
        np.testing.assert_array_equal(one, ref)
        np.testing.assert_array_equal(scalar, ref)
    frozen = np.array(0.4)
    frozen.setflags(write=False)
    assert perturb(np.array(0.4), 1).flags.writeable and not perturb(frozen, 1).flags.writeable


def test_plain_arithmetic_is_untouched(monkeypatch):
    monkeypatch.delenv(ENV, raising=False)
    x = np.linspace(0.1, 1.0, 7)
    assert perturb(x) is x and perturb(0.3) == 0.3
    monkeypatch.setenv(ENV, "0")
    assert perturb(x) is x


def test_perturbed_array_keeps_read_only_and_broadcast_views_raise_no_warning(monkeypatch):
    """A read-only input gives a read-only result, a writeable one a writeable result, and a
    view from np.broadcast_arrays (numpy warns on reading its ``flags.writeable``: seen in
    a perturbed build's Al-Wagih claims, through ``Gains`` of ``analysis.vrf``) is perturbed
    without a warning, read-only as numpy is making such views."""
    x = np.linspace(0.1, 1.0, 5)
    assert perturb(x, 1).flags.writeable
    frozen = x.copy()
    frozen.setflags(write=False)
    assert not perturb(frozen, 1).flags.writeable
    _, wide = np.broadcast_arrays(x, 0.3)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        y = perturb(wide, 1)
        np.testing.assert_array_equal(y, perturb(np.full(5, 0.3), 1))
        assert not y.flags.writeable
        # the route of the build's warning: a Gains of broadcast arrays under ABGLIB_PERTURB
        monkeypatch.setenv(ENV, "1")
        abglib.Gains(*np.broadcast_arrays(x, 0.2))


@pytest.mark.parametrize("bad", ["-1", "x", "1.5", "2147483648"])
def test_bad_seed_is_refused_naming_the_value(monkeypatch, bad):
    monkeypatch.setenv(ENV, bad)
    with pytest.raises(AbglibValueError, match=rf"{ENV} must be a whole number.*{bad!r}"):
        perturbation_seed()


def test_perturbed_build_moves_gains_and_tracks_by_round_off(monkeypatch):
    """Gains and track() take the perturbation (the chokepoints of every table), and a
    Gains rebuilt from another's arrays keeps its (perturbed) values."""
    z = np.cumsum(np.random.default_rng(1).normal(size=500))
    plain = abglib.track(z, abglib.Gains(0.5, 0.2), dt=0.1).x_smooth
    monkeypatch.setenv(ENV, "3")
    g = abglib.Gains(np.array([0.5, 0.4]), np.array([0.2, 0.1]))
    assert 0 < abs(g.alpha[0] - 0.5) <= 0.5 * RELATIVE
    assert g[0] == abglib.Gains(g.alpha[0], g.beta[0])
    moved = abglib.track(z, abglib.Gains(0.5, 0.2), dt=0.1).x_smooth
    dev = np.max(np.abs(moved - plain) / np.maximum(np.abs(plain), 1.0))
    assert 0 < dev < 1e-11


def test_m4s_own_recursion_takes_the_perturbation(monkeypatch):
    """M4 (seed 001, Algorithm 2) runs a recursion of its own and never reaches track(): its
    measurements and dt are perturbed where the methods read them (abglib.methods._z,
    _dt), as track() perturbs them. Under perturbation M4 equals M4 given the perturbed
    measurements by hand (idempotent), and moves from the plain M4."""
    from abglib import methods

    z = np.cumsum(np.random.default_rng(2).normal(size=(3, 80)), axis=-1)
    grid = np.linspace(0.05, 1.0, 20)
    plain = methods.m4(z, 0.1, 10, grid, 0.5).x_pred
    monkeypatch.setenv(ENV, "5")
    moved = methods.m4(z, 0.1, 10, grid, 0.5).x_pred
    assert not np.array_equal(moved, plain)
    assert np.max(np.abs(moved - plain) / np.maximum(np.abs(plain), 1.0)) < 1e-11
    by_hand = methods.m4(perturb(z), 0.1, 10, grid, perturb_scalar(0.5)).x_pred
    np.testing.assert_array_equal(moved, by_hand)
    # the methods that call track() are perturbed once, not twice: M1 under perturbation
    # equals track() on the same inputs under perturbation
    m1 = methods.m1(z, 0.3, 0.5).x_pred
    ref = abglib.track(z, methods.benedict_bordner(0.3), dt=0.5, init="two_point").x_pred
    np.testing.assert_array_equal(m1, ref)


# --------------------------------------------------------------------------- specs
def _runs(x, *deltas):
    x = np.asarray(x, float)
    return np.array([x, *(x + np.asarray(d, float) for d in deltas)])


def test_column_that_keeps_every_digit_gets_no_spec():
    assert prec.column_spec(_runs([1.0, 2.5], [0, 0])) is None
    assert prec.column_spec(_runs([1.0, 2.5], [1e-15, 0])) is None  # keeps 14 > 10 digits


def test_digits_follow_the_deviation():
    # deviation 1e-9 on 1.0, times the safety 10: one unit of the last digit must be
    # >= 2e-8; 8 digits have a unit of 1e-7, 9 digits 1e-8 < 2e-8
    assert prec.column_spec(_runs([1.0, 3.0], [1e-9, 0])) == 8
    # no more digits than the config writes anyway: no spec needed
    assert prec.column_spec(_runs([1.0, 3.0], [1e-9, 0]), cap=5) is None


def test_round_off_cells_get_a_bound_above_them():
    # a residual that is zero in exact arithmetic next to values with full digits
    spec = prec.column_spec(_runs([1.19e-12, 0.25, 3.0], [4e-14, 0, 0]))
    assert spec == "<1e-11:10"
    # every cell round-off: the bound alone
    assert prec.column_spec(_runs([1e-15, -3e-16], [2e-15, 1e-16])) == "<1e-13"


def test_bound_moves_up_until_no_cell_sits_within_its_deviation_of_it():
    # a noise cell puts the bound at 1e-11; a value at 1.0000001e-11 that moves by 1e-15
    # (x10 safety) is within its deviation of it, so the bound goes to 1e-10
    spec = prec.column_spec(_runs([1e-12, 1.0000001e-11, 1.0], [5e-13, 1e-15, 0]))
    assert spec.startswith("<1e-10:")


def test_a_cell_empty_in_some_runs_only_cannot_be_reproduced():
    with pytest.raises(AbglibValueError, match="empty in some runs only"):
        prec.column_spec(np.array([[1.0, np.nan], [1.0, 2.0]]))


def test_written_numbers_verify_against_the_perturbed_ones():
    """The property the spec exists for: write the plain and the perturbed values at the
    derived spec, and every pair agrees as `abglib verify` judges it."""
    rng = np.random.default_rng(5)
    for _ in range(200):
        x = rng.normal(size=20) * 10.0 ** rng.integers(-14, 6, size=20)
        noise = 10.0 ** rng.uniform(-16, -8) * rng.normal(size=(4, 20)) * np.abs(x)
        noise[:, :3] = 10.0 ** rng.uniform(-16, -12) * rng.normal(size=(4, 3))
        x[:3] = 10.0 ** rng.uniform(-16, -13, size=3)  # round-off cells
        runs = np.vstack([x, x + noise[:3]])
        spec = prec.column_spec(runs[:3])  # derived from two perturbed runs
        if spec is None:
            spec = 10
        other = runs[3]  # a run the spec was not derived from
        for a, b in zip(runs[0], other, strict=True):
            assert cell_agrees(format_cell(a, spec), format_cell(b, spec))[0], (a, b, spec)


def test_stricter_and_merge():
    assert tables.stricter(6, 4) == 4
    assert tables.stricter("<1e-12", 5) == "<1e-12:5"
    assert tables.stricter("<1e-12:8", "<1e-10:9") == "<1e-10:8"
    assert tables.stricter(None, "<1e-12") == "<1e-12"
    merged = tables.merge_specs({"a/t": {"x": 7}}, {"a/t": {"x": "<1e-13:9", "y": 4}})
    assert merged == {"a/t": {"x": "<1e-13:7", "y": 4}}
    with pytest.raises(AbglibValueError, match="must start with '<'"):
        tables.stricter("1e-12", 3)


def test_precision_for_merges_declared_and_derived(monkeypatch):
    monkeypatch.setattr(tables, "_derived", lambda: {"doc/t": {"x": 6, "y": "<1e-12:12"}})
    df = pd.DataFrame({"x": [1.0], "y": [2.0], "z": [3.0]})
    df.attrs["precision"] = {"z": 4, "x": 8}
    digits, spec = tables.precision_for(df, "results/doc/t.csv", 10)
    assert digits == 10 and spec == {"x": 6, "y": "<1e-12:10", "z": 4}
    monkeypatch.setenv(tables.RAW_ENV, "1")
    assert tables.precision_for(df, "results/doc/t.csv", 10) == (tables.RAW_DIGITS, {})
    monkeypatch.setenv(tables.RAW_ENV, "yes")
    with pytest.raises(AbglibValueError, match="must be 0 or 1"):
        tables.precision_for(df, "results/doc/t.csv", 10)


def test_raw_table_round_trips_every_float(monkeypatch):
    x = np.array([0.1 + 0.2, 1 / 3, 2.0**-40])
    text = csv_text(pd.DataFrame({"x": x}), tables.RAW_DIGITS)
    assert [float(v) for v in text.split()[1:]] == list(x)


def test_derive_folders_finds_specs_and_moved_text(tmp_path):
    rows = {
        0: "x,n,note\n1.0,3,same\n1.19e-12,4,largest 3e-14\n",
        1: "x,n,note\n1.0,3,same\n1.21e-12,4,largest 4e-14\n",
    }
    for k, text in rows.items():
        (tmp_path / f"r{k}" / "doc").mkdir(parents=True)
        (tmp_path / f"r{k}" / "doc" / "t.csv").write_text(text, encoding="utf-8")
    d = prec.derive_folders(tmp_path / "r0", [tmp_path / "r1"])
    # 1.0 keeps every digit, 1.19e-12 is round-off (moved by 2e-14)
    assert d.specs() == {"doc/t": {"x": "<1e-11:10"}}
    assert d.text_differences == [("doc/t.csv", 2, "note", "largest 3e-14", "largest 4e-14")]
    assert d.problems == []


def test_the_generated_table_names_real_columns():
    """Every spec of the committed table parses (a hand edit that breaks one fails here)."""
    from abglib.common._precision_table import PRECISION

    for key, cols in PRECISION.items():
        assert key.count("/") == 1, key
        for spec in cols.values():
            tables.stricter(spec, spec)  # raises on a malformed spec


def test_table_keys():
    assert tables.table_key("results/alwagih/table1.csv") == "alwagih/table1"
    assert tables.table_key("/x/results/benchmark/cells/std_ab/alwagih_w1.csv") == "benchmark/cells"
    assert tables.table_key("results/benchmark/cells.csv") == "benchmark/cells"


def test_derive_folders_mixed_columns_and_counts(tmp_path):
    """A comparison's ``reproduced`` mixes numbers and a qualitative claim's True/False:
    the numbers give the spec, the words must not move; whole numbers that stay whole in
    every run are counts (must be equal), a float that is whole in one run is a float."""
    rows = {
        0: "reproduced,n,bias\nTrue,3,-8\n0.5,4,-16\n1.19e-12,5,-2\n",
        1: "reproduced,n,bias\nFalse,3,-7.9999999999999591\n0.5,4,-16\n1.22e-12,6,-2\n",
    }
    for k, text in rows.items():
        (tmp_path / f"r{k}" / "doc").mkdir(parents=True)
        (tmp_path / f"r{k}" / "doc" / "t.csv").write_text(text, encoding="utf-8")
    d = prec.derive_folders(tmp_path / "r0", [tmp_path / "r1"])
    specs = d.specs()["doc/t"]
    # bias is a float column (no text difference), keeping 13 > 10 digits: no spec
    assert specs == {"reproduced": "<1e-11:10"}
    assert sorted(d.text_differences) == [
        ("doc/t.csv", 1, "reproduced", "True", "False"),
        ("doc/t.csv", 3, "n", "5", "6"),
    ]
