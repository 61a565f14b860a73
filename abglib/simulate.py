"""Test inputs, target trajectories and measurement noise.

Everything random takes a :class:`numpy.random.Generator` (or a seed), never global
state, so that every number of the pipeline comes from a seed in ``config.yaml``.
"""

from __future__ import annotations

import numpy as np

from ._checks import AbglibValueError, check_in_range, check_positive

__all__ = [
    "ar1_noise",
    "bendix_impulse",
    "bendix_ramp",
    "polynomial_kinematics",
    "polynomial_track",
    "rng_from",
    "sample_times",
    "white_noise",
]


def rng_from(seed) -> np.random.Generator:
    """A :class:`numpy.random.Generator` from an int seed (or pass one through).

    References
    ----------
    None: a seeded NumPy generator; seeds are recorded in every
    dataset's manifest.
    """
    if isinstance(seed, np.random.Generator):
        return seed
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise AbglibValueError(f"seed must be a non-negative integer, got {seed!r}")
    return np.random.default_rng(int(seed))


def _check_n(n) -> int:
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 1:
        raise AbglibValueError(f"n must be a positive integer, got {n!r}")
    return int(n)


def sample_times(n: int, dt: float = 1.0) -> np.ndarray:
    """Sample instants ``t_k = k * dt``, ``k = 0..n-1``.

    References
    ----------
    None: the sampling instants ``t_k = k T`` of every source
    (e.g. Steelman (1978), seed 000 (``steelman1978``), eqs 1-6).
    """
    return np.arange(_check_n(n)) * float(check_positive("dt", dt))


def bendix_impulse(n: int = 40, dt: float = 1.0) -> np.ndarray:
    """Impulse input of the FAA Bendix test program (seed 003).

    "A pulse of amplitude 1/T and width T is applied to the input at the first sampling":
    ``z[0] = 1/T``, zero afterwards (unit area).

    References
    ----------
    Elwell and Sinsky, FAA Bendix letter report, seed 003 (``faa_bendix``): the test program's
    impulse input (a pulse of amplitude 1/T and width T), graphs 1-3 of each gain set.
    """
    T = float(check_positive("dt", dt))
    z = np.zeros(_check_n(n))
    z[0] = 1.0 / T
    return z


def bendix_ramp(n: int = 40, dt: float = 1.0, rise_samples: int = 10) -> np.ndarray:
    """Ramp input of the FAA Bendix test program (seed 003).

    "An input of zero at the first sampling. The input level is then raised by the value
    of T each sampling for 10 periods. The input is then held at zero for the remaining
    samples": ``z[k] = k T`` for ``k = 0..rise_samples``, then ``0``.

    References
    ----------
    Elwell and Sinsky, FAA Bendix letter report, seed 003 (``faa_bendix``): the test program's ramp
    input (raised by T for 10 periods, then zero), graphs 4-6 of each gain set.
    """
    T = float(check_positive("dt", dt))
    n = _check_n(n)
    if isinstance(rise_samples, bool) or not isinstance(rise_samples, (int, np.integer)):
        raise AbglibValueError(f"rise_samples must be an integer, got {rise_samples!r}")
    if not 0 <= rise_samples < n:
        raise AbglibValueError(
            f"rise_samples must satisfy 0 <= rise_samples < n={n}, got {rise_samples}"
        )
    z = np.zeros(n)
    k = np.arange(rise_samples + 1)
    z[: rise_samples + 1] = k * T
    return z


def polynomial_kinematics(t, x0=0.0, v0=0.0, a0=0.0, jerk=0.0):
    """Exact position, velocity and acceleration of the cubic ``x0 + v0 t + a0 t^2/2 +
    jerk t^3/6`` at times ``t`` (array (..., n)): the one home of the polynomial track
    (the benchmark's ``polynomial`` scenarios, :mod:`abglib.bench.datasets`, take it).

    Returns
    -------
    (pos, vel, acc) : float arrays shaped like ``t``.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 4-6 (the polynomial motion the tracker
    models); Al-Wagih & Abdulla, seed 001 (``alwagih``), eq 1 (constant acceleration);
    the velocity, acceleration and jerk inputs of Huang, Yang & Ma, seed 002 (``huang``)
    (after eq 14).
    """
    t = np.asarray(t, dtype=float)
    pos = x0 + v0 * t + 0.5 * a0 * t**2 + jerk * t**3 / 6.0
    vel = v0 + a0 * t + 0.5 * jerk * t**2
    acc = np.broadcast_to(a0 + jerk * t, t.shape).astype(float)
    return pos, vel, acc


def polynomial_track(t, x0=0.0, v0=0.0, a0=0.0, jerk=0.0) -> np.ndarray:
    """Position ``x0 + v0 t + a0 t^2/2 + jerk t^3/6`` at times ``t`` (array (..., n)):
    the position of :func:`polynomial_kinematics`.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 4-6 (the polynomial motion the tracker
    models); the velocity, acceleration and jerk inputs of
    Huang, Yang & Ma, seed 002 (``huang``) (after eq 14).
    """
    return polynomial_kinematics(t, x0, v0, a0, jerk)[0]


def white_noise(shape, sigma: float, seed) -> np.ndarray:
    """Gaussian white noise of standard deviation ``sigma`` (seeded).

    References
    ----------
    Al-Wagih & Abdulla, seed 001 (``alwagih``), the simulations' "Gaussian white noise"
    (Tables 1 and 3).
    """
    sigma = float(check_positive("sigma", sigma))
    return rng_from(seed).normal(0.0, sigma, size=shape)


def ar1_noise(shape, sigma: float, rho: float, seed) -> np.ndarray:
    """Stationary first-order autoregressive (coloured) Gaussian noise along the last axis.

    ``w[k] = rho w[k-1] + sqrt(1 - rho^2) sigma e[k]``, ``w[0] ~ N(0, sigma^2)``, so every
    sample has standard deviation ``sigma`` and lag-1 correlation ``rho``.

    References
    ----------
    Al-Wagih & Abdulla, seed 001 (``alwagih``), the simulations' "Gaussian colored noise"
    (Tables 2 and 4).
    """
    sigma = float(check_positive("sigma", sigma))
    rho = float(check_in_range("rho", rho, -1.0, 1.0))
    e = rng_from(seed).normal(0.0, sigma, size=shape)
    e = np.atleast_1d(e)
    w = np.empty_like(e)
    w[..., 0] = e[..., 0]
    scale = np.sqrt(1.0 - rho * rho)
    for k in range(1, e.shape[-1]):
        w[..., k] = rho * w[..., k - 1] + scale * e[..., k]
    return w
