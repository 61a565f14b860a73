"""State-space form of the tracker: the shared starting point of the numeric routes.

With state ``s = [x, v, a]`` (smoothed), transition ``Phi`` and gain ``K`` (seed 000,
eqs 1-6, canonical convention)::

    Phi = [[1, T, T^2/2], [0, 1, T], [0, 0, 1]],   H = [1, 0, 0],
    K = [alpha, beta/T, gamma/T^2]^T
    s(n) = F s(n-1) + K z(n),   F = (I - K H) Phi
    x_p(n) = H Phi s(n-1)

The closed-loop matrix ``F`` has the poles of the tracker (the roots of seed 000, eq 40).
"""

from __future__ import annotations

import numpy as np

from .._checks import AbglibValueError, check_positive
from ..gains import Gains

__all__ = ["StateSpace", "state_space"]


class StateSpace:
    """Matrices of one (scalar) gain set: ``Phi``, ``H``, ``K``, ``F``.

    With the smoothed state ``s = [x, v, a]``, the transition ``Phi``, the measurement row
    ``H`` and the gain ``K`` (seed 000, eqs 1-6, canonical convention)::

        Phi = [[1, T, T^2/2], [0, 1, T], [0, 0, 1]],   H = [1, 0, 0],
        K = [alpha, beta/T, gamma/T^2]^T
        s(n) = F s(n-1) + K z(n),   F = (I - K H) Phi
        x_p(n) = H Phi s(n-1)

    The closed-loop matrix ``F`` has the poles of the tracker. ``n`` is 3 for every gain
    set (an alpha-beta tracker has ``gamma = 0``, which leaves the acceleration state at
    zero and adds a pole at z = 1 that is uncontrollable from the measurements;
    :func:`state_space` with ``reduced=True`` drops it).

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 1-6: the tracker's recursion, whose
    matrices these are; eq 40: the poles, the eigenvalues of ``F``.
    """

    def __init__(self, Phi, H, K, F, dt):
        self.Phi, self.H, self.K, self.F, self.dt = Phi, H, K, F, dt

    @property
    def n(self) -> int:
        return self.F.shape[0]


def state_space(gains: Gains, dt: float = 1.0, reduced: bool | None = None) -> StateSpace:
    """State-space matrices of a scalar gain set (seed 000, eqs 1-6).

    Parameters
    ----------
    gains : Gains
        Scalar gains (a bank must be looped over by the caller).
    dt : float
        Sample interval ``T`` > 0.
    reduced : bool, optional
        Use the 2-state ``[x, v]`` model. Default: True when ``gamma == 0``.

    Returns
    -------
    StateSpace
        ``Phi``, ``H``, ``K`` and the closed-loop ``F = (I - K H) Phi``.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 1-6: the recursion in matrix form;
    eq 40: the characteristic polynomial, ``det(zI - F)``.
    """
    if gains.shape != ():
        raise AbglibValueError(f"state_space needs scalar gains, got a bank of shape {gains.shape}")
    T = float(check_positive("dt", dt))
    alpha, beta, gamma = (float(v) for v in gains)
    if reduced is None:
        reduced = gamma == 0.0
    if reduced:
        if gamma != 0.0:
            raise AbglibValueError(f"reduced=True needs gamma == 0, got {gamma!r}")
        Phi = np.array([[1.0, T], [0.0, 1.0]])
        K = np.array([alpha, beta / T])
    else:
        Phi = np.array([[1.0, T, 0.5 * T * T], [0.0, 1.0, T], [0.0, 0.0, 1.0]])
        K = np.array([alpha, beta / T, gamma / (T * T)])
    H = np.zeros(Phi.shape[0])
    H[0] = 1.0
    F = (np.eye(Phi.shape[0]) - np.outer(K, H)) @ Phi
    return StateSpace(Phi, H, K, F, T)
