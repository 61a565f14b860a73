"""The gain set of a fixed-gain tracker, in the canonical (Steelman 1978) convention.

Canonical convention (seed 000, eqs 1-6; ``shared/CONTRACTS.md`` section 1), sample
interval ``T``::

    x_p = x(n-1) + T v(n-1) + T^2 a(n-1) / 2      v_p = v(n-1) + T a(n-1)      a_p = a(n-1)
    r   = z(n) - x_p
    x(n) = x_p + alpha r      v(n) = v_p + (beta / T) r      a(n) = a_p + (gamma / T^2) r

``gamma = 0`` is the alpha-beta tracker. Other conventions are converted in
:mod:`abglib.conventions`, nowhere else.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ._checks import AbglibValueError, check_finite
from ._perturb import perturb

__all__ = ["Gains", "require_gains"]


def _frozen(name: str, value):
    # perturbed arithmetic (ABGLIB_PERTURB, abglib._perturb): a no-op in a plain build
    arr = perturb(np.asarray(check_finite(name, value), dtype=np.float64))
    if arr.ndim == 0:
        return float(arr)
    arr = arr.copy()
    arr.setflags(write=False)
    return arr


@dataclass(frozen=True, eq=False)
class Gains:
    """Gains ``(alpha, beta, gamma)`` of an alpha-beta(-gamma) tracker (canonical convention).

    Parameters
    ----------
    alpha, beta : float or array (...)
        Position and velocity gains (seed 000, eqs 1-2).
    gamma : float or array (...), default 0.0
        Acceleration gain (seed 000, eq 3); ``0`` gives the alpha-beta tracker.

    Notes
    -----
    Values are stored as Python floats (scalars) or read-only float64 arrays. Arrays
    broadcast against each other and, in :func:`abglib.track`, against the measurements
    ``z`` of shape ``(..., n)``: an axis of length ``n`` last is a time-varying gain
    (e.g. the growing-memory gains of seed 001, eq 24); leading axes form a bank of gains
    (use ``alpha[:, None]`` to put a bank of ``k`` gains against series of length ``n``).

    Any finite values are accepted, unstable ones included, so that instability can be
    studied; :func:`abglib.analysis.is_stable` tells whether a set is stable.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 1-3: the gains alpha, beta, gamma of the
    recursion.

    Examples
    --------
    >>> g = Gains(0.5, 0.2)
    >>> g.order
    2
    >>> Gains(0.3, 0.0356, 0.0014).order
    3
    """

    alpha: float | np.ndarray
    beta: float | np.ndarray
    gamma: float | np.ndarray = 0.0

    def __post_init__(self):
        for name in ("alpha", "beta", "gamma"):
            object.__setattr__(self, name, _frozen(name, getattr(self, name)))
        try:
            np.broadcast_shapes(np.shape(self.alpha), np.shape(self.beta), np.shape(self.gamma))
        except ValueError:
            raise AbglibValueError(
                "alpha, beta and gamma must broadcast together, got shapes "
                f"{np.shape(self.alpha)}, {np.shape(self.beta)}, {np.shape(self.gamma)}"
            ) from None

    # ------------------------------------------------------------------ properties
    @property
    def shape(self) -> tuple[int, ...]:
        """Broadcast shape of the three gains (``()`` for a single scalar set)."""
        return np.broadcast_shapes(np.shape(self.alpha), np.shape(self.beta), np.shape(self.gamma))

    @property
    def order(self) -> int:
        """2 for an alpha-beta tracker (gamma identically zero), 3 otherwise."""
        return 2 if np.all(np.asarray(self.gamma) == 0.0) else 3

    def as_arrays(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The three gains broadcast to :attr:`shape`, as float64 arrays (read-only views)."""
        return tuple(np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in self)))

    def __iter__(self):
        yield self.alpha
        yield self.beta
        yield self.gamma

    def __getitem__(self, index) -> Gains:
        """Select gains from a bank, e.g. ``bank[2]`` (arrays are broadcast first)."""
        a, b, g = self.as_arrays()
        return Gains(a[index], b[index], g[index])

    def __eq__(self, other):
        if not isinstance(other, Gains):
            return NotImplemented
        return all(np.array_equal(x, y) for x, y in zip(self, other, strict=True))

    def __hash__(self):
        return hash(tuple(np.asarray(v).tobytes() for v in self))

    def __repr__(self) -> str:
        def fmt(v):
            return f"{v:.6g}" if np.ndim(v) == 0 else f"array(shape={np.shape(v)})"

        return f"Gains(alpha={fmt(self.alpha)}, beta={fmt(self.beta)}, gamma={fmt(self.gamma)})"

    def isclose(self, other: Gains, rtol: float = 1e-9, atol: float = 0.0) -> bool:
        """True where all three gains agree with ``other`` within tolerance."""
        return all(
            np.allclose(x, y, rtol=rtol, atol=atol) for x, y in zip(self, other, strict=True)
        )


def require_gains(gains, name: str = "gains") -> Gains:
    """Return ``gains`` if it is a :class:`~abglib.Gains`, else raise naming what was passed."""
    if not isinstance(gains, Gains):
        raise AbglibValueError(f"{name} must be an abglib.Gains, got {type(gains).__name__}")
    return gains
