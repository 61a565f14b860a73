"""Perturbed arithmetic: the build mode behind each table's declared precision.

A number is written with the digits it is reproducible to (``shared/CONTRACTS.md`` §3).
Which digits those are is found by perturbing the computation itself, not by comparing
two BLAS kernels on one machine: with ``ABGLIB_PERTURB=<k>`` (k = 1, 2, ...) in the
environment, every floating-point input of the numerical core has its lowest
:data:`BITS` bits of mantissa replaced by a pattern drawn from ``k`` and the remaining
bits, a relative change of up to ``2**(BITS - 52)`` (about 1.8e-15: a few ulps, what
another BLAS kernel, SIMD code path or summation order changes one operation's result by;
the derived precision multiplies the deviations it sees by a safety factor).
A build under several ``k`` then shows which written digits move: those are not
reproducible, and ``abglib precision`` (:mod:`abglib.reporting.precision`) writes each
column with the digits that survive, and pure round-off as a bound.

Where inputs are perturbed (the chokepoints every number of a table flows through):

- :class:`abglib.Gains` (``alpha``, ``beta``, ``gamma``): every tracker, closed form and
  numeric twin;
- :func:`abglib.track`: the measurements ``z`` and ``dt`` (every Monte Carlo result);
- :mod:`abglib.methods` (seed 001's M1-M5): the measurements ``z`` and ``dt``, where M4 runs a
  recursion of its own and never reaches :func:`abglib.track`;
- :func:`abglib.replications.antenna.discretize.zoh`: the continuous model matrices and
  the sampling period of seed 004 (every LQ, Lyapunov and Kalman result).

The replacement is idempotent (a perturbed value is perturbed to itself, so a
:class:`~abglib.Gains` rebuilt from another's arrays keeps its values), keeps zero, signs,
infinities and NaN, and is a pure function of the value and ``k``, so equal inputs stay
equal and a perturbed build is as deterministic as a plain one.

Unset (or ``0``), nothing changes: a plain build never pays for this module beyond one
environment look-up per call.
"""

from __future__ import annotations

import math
import os
import struct

import numpy as np

from ._checks import AbglibValueError

__all__ = ["BITS", "ENV", "RELATIVE", "perturb", "perturb_scalar", "perturbation_seed"]

#: the environment variable that switches perturbed arithmetic on (its value: the seed k)
ENV = "ABGLIB_PERTURB"
#: low mantissa bits replaced by the perturbation: up to 7 ulps, the size of what another
#: BLAS kernel, SIMD code path or summation order changes in one operation (a larger one,
#: 9 bits, moved only the route given a Gains of two routes compared to round-off far
#: more than any machine does, and flipped checks at 1e-9)
BITS = 3
#: the largest relative change of a perturbed value
RELATIVE = 2.0 ** (BITS - 52)

_LOW = np.uint64((1 << BITS) - 1)
_HIGH = ~_LOW
# constants of splitmix64's finaliser (a bijective mix of 64 bits)
_M1 = np.uint64(0xBF58476D1CE4E5B9)
_M2 = np.uint64(0x94D049BB133111EB)
_GOLDEN = 0x9E3779B97F4A7C15


def perturbation_seed() -> int:
    """The seed ``k`` of ``ABGLIB_PERTURB`` (0: plain arithmetic).

    Raises
    ------
    AbglibValueError
        When the variable is set to anything but a whole number from 0 to 2**31 - 1.
    """
    text = os.environ.get(ENV, "").strip()
    if not text:
        return 0
    try:
        k = int(text)
    except ValueError:
        k = -1
    if not 0 <= k < 2**31:
        raise AbglibValueError(
            f"{ENV} must be a whole number from 0 (plain) to 2147483647, got {text!r}"
        )
    return k


def _mix(bits: np.ndarray, k: int) -> np.ndarray:
    x = bits ^ np.uint64((k * _GOLDEN) & 0xFFFFFFFFFFFFFFFF)
    x = (x ^ (x >> np.uint64(30))) * _M1
    x = (x ^ (x >> np.uint64(27))) * _M2
    return x ^ (x >> np.uint64(31))


def _perturbed(a: np.ndarray, k: int) -> np.ndarray:
    bits = a.view(np.uint64)
    high = bits & _HIGH
    with np.errstate(over="ignore"):
        pattern = _mix(high, k) & _LOW
    out = (high | pattern).view(np.float64)
    # zero, subnormals, infinities and NaN stay as they are (no low bits to spare)
    keep = ~np.isfinite(a) | (np.abs(a) < np.finfo(np.float64).tiny)
    return np.where(keep, a, out)


def perturb(x, k: int | None = None):
    """``x`` with perturbed low mantissa bits under ``ABGLIB_PERTURB`` (else ``x`` itself).

    Parameters
    ----------
    x : float or array_like of float64
        Values; other dtypes (integers, booleans) are returned unchanged.
    k : int, optional
        The perturbation seed (default: from the environment, :func:`perturbation_seed`).

    Returns
    -------
    The same kind of object: a float for a Python float, an array (a new one, read-only
    when the input was) for an array.
    """
    k = perturbation_seed() if k is None else k
    if not k:
        return x
    if isinstance(x, float):
        return perturb_scalar(x, k)
    a = np.asarray(x)
    if a.dtype != np.float64:
        return x
    if a.ndim == 0:  # a gain: the scalar route, the same bits (tests/test_precision.py)
        out = np.array(_perturbed_float(float(a), k))
    else:
        out = _perturbed(np.ascontiguousarray(a), k).reshape(a.shape)
    if isinstance(x, np.ndarray) and _read_only(x):
        out.setflags(write=False)
    return out


def _read_only(x: np.ndarray) -> bool:
    # the array interface's read-only flag: ``x.flags.writeable`` warns (FutureWarning,
    # numpy >= 1.17) on a view from np.broadcast_arrays, which numpy is making read-only;
    # the interface already reports such a view read-only, without the warning
    return bool(x.__array_interface__["data"][1])


def perturb_scalar(x: float, k: int | None = None) -> float:
    """A Python float perturbed like :func:`perturb`."""
    k = perturbation_seed() if k is None else k
    if not k:
        return x
    return _perturbed_float(float(x), k)


_MASK64 = (1 << 64) - 1
_TINY = float(np.finfo(np.float64).tiny)


def _perturbed_float(x: float, k: int) -> float:
    # _perturbed for one value on Python's integers (every product reduced mod 2**64, as
    # numpy's uint64 arithmetic wraps): the same bits, without the ~10 numpy calls that
    # cost more than the rest of a Gains (a perturbed build makes some 10**5 of them)
    if not math.isfinite(x) or abs(x) < _TINY:
        return x
    high = struct.unpack("<Q", struct.pack("<d", x))[0] & ~int(_LOW) & _MASK64
    m = high ^ ((k * _GOLDEN) & _MASK64)
    m = ((m ^ (m >> 30)) * int(_M1)) & _MASK64
    m = ((m ^ (m >> 27)) * int(_M2)) & _MASK64
    m ^= m >> 31
    return struct.unpack("<d", struct.pack("<Q", high | (m & int(_LOW))))[0]
