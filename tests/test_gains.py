"""abglib.Gains: canonical container, immutability, broadcasting, errors."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from abglib import AbglibValueError, Gains


def test_scalars_are_floats_and_order():
    g = Gains(0.3, 0.0356, 0.0014)  # Steelman Table 1, standard alpha-beta-gamma column
    assert isinstance(g.alpha, float) and g.order == 3 and g.shape == ()
    assert Gains(0.3, 0.0267).order == 2  # Table 1, standard alpha-beta column


def test_immutable():
    g = Gains(np.array([0.1, 0.2]), 0.01)
    with pytest.raises(dataclasses.FrozenInstanceError):
        g.alpha = 0.5
    with pytest.raises(ValueError, match="read-only"):
        g.alpha[0] = 0.5


def test_array_input_is_copied():
    a = np.array([0.1, 0.2])
    g = Gains(a, 0.01)
    a[0] = 9.0
    assert g.alpha[0] == 0.1


def test_bank_indexing_and_equality():
    bank = Gains(np.array([0.1, 0.2, 0.3]), np.array([0.01, 0.02, 0.03]))
    assert bank.shape == (3,)
    assert bank[1] == Gains(0.2, 0.02, 0.0)
    assert bank[1] != Gains(0.2, 0.02, 0.001)
    assert bank[1].isclose(Gains(0.2 + 1e-13, 0.02))
    assert "array(shape=(3,))" in repr(bank)


@pytest.mark.parametrize(
    ("args", "match"),
    [
        ((np.nan, 0.1), r"alpha must be finite, got nan"),
        ((0.1, np.array([0.1, np.inf])), r"beta must be finite, got inf at index 1"),
        ((0.1, 0.1, "x"), r"gamma must be a real number"),
        ((np.ones(2), np.ones(3)), r"alpha, beta and gamma must broadcast together"),
    ],
)
def test_bad_gains(args, match):
    with pytest.raises(ValueError, match=match):
        Gains(*args)


@pytest.mark.parametrize(
    "args, match",
    [
        (("0.3", 0.1), r"alpha must be a real number or array of them, got '0.3'"),
        ((None, 0.1), r"alpha must be a real number or array of them, got None"),
        ((0.3, 0.1 + 0.0j), r"beta must be real, got complex .*pass beta\.real or abs\(beta\)"),
        ((True, 0.1), r"alpha must be a real number or array of them, got booleans \(True\)"),
        ((0.3, np.array([False, True])), r"beta .* got booleans \(\[False,  True\]\)"),
        ((np.array(["0.3"]), 0.1), r"alpha must be a real number or array of them, got strings"),
        ((np.array([0.3, None], dtype=object), 0.1), r"alpha .* got an element None"),
    ],
)
def test_gains_refuse_strings_none_booleans_and_complex(args, match):
    # numbers are never parsed from text nor cast from booleans or complex: the caller converts
    with pytest.raises(AbglibValueError, match=match):
        Gains(*args)


def test_gains_accept_numpy_and_fraction_scalars():
    from fractions import Fraction

    g = Gains(np.float32(0.25), Fraction(1, 8), np.int64(0))
    assert (g.alpha, g.beta, g.gamma) == (0.25, 0.125, 0.0)
