r"""Zero-order-hold discretisation (seed 004, app. D, eqs D.9-D.12).

.. math::
    \exp\!\left(\begin{bmatrix} A^c & B^c \\ 0 & 0\end{bmatrix}\Delta t\right)
    = \begin{bmatrix} A & B \\ 0 & I\end{bmatrix},\qquad
    A = e^{A^c\Delta t},\ B = \int_0^{\Delta t} e^{A^c\tau}\,d\tau\, B^c.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg

from ..._checks import AbglibValueError, check_positive
from ..._perturb import perturb

__all__ = ["zoh"]


def zoh(ac, bc, dt):
    """Discrete ``(A, B)`` of ``dx/dt = Ac x + Bc u`` with ``u`` held over ``dt`` (eqs D.9-D.10).

    Parameters
    ----------
    ac : array (n, n)
    bc : array (n, m)
    dt : float
        Sampling period > 0.

    Returns
    -------
    A : array (n, n)
    B : array (n, m)
    """
    ac = np.atleast_2d(np.asarray(ac, dtype=float))
    bc = np.asarray(bc, dtype=float)
    if bc.ndim == 1:
        bc = bc[:, None]
    n = ac.shape[0]
    if ac.shape != (n, n) or bc.shape[0] != n:
        raise AbglibValueError(
            f"ac must be square (n, n) and bc (n, m), got shapes {ac.shape} and {bc.shape}"
        )
    dt = float(check_positive("dt", dt))
    # perturbed arithmetic (ABGLIB_PERTURB, abglib._perturb): a no-op in a plain build
    ac, bc, dt = perturb(ac), perturb(bc), perturb(dt)
    m = bc.shape[1]
    big = np.zeros((n + m, n + m))
    big[:n, :n] = ac
    big[:n, n:] = bc
    e = scipy.linalg.expm(big * dt)
    return e[:n, :n], e[:n, n:]
