r"""Taylor-series model of the object to be tracked (seed 004, ch. 3, eqs 3.1-3.8).

Assuming the (p-2)-th derivative of the force vanishes, :math:`z^{(p)}(t) = 0` (eq 3.3),
the state :math:`x_t = [z, \dot z, \dots, z^{(p-1)}]` obeys :math:`\dot x_t = A_t^c x_t` with
:math:`A_t^c` the shift matrix (eq 3.4); its discrete form :math:`A_t = e^{A_t^c\Delta t}`
(eq 3.5, app. D) is upper triangular with entries :math:`\Delta t^{j-i}/(j-i)!`, so that
:math:`C_t A_t^k x_{t,0}` is the Taylor polynomial of order :math:`q = p-1` (the *order of
prediction*) evaluated :math:`k` steps ahead (eqs 3.6-3.8).
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from ..._checks import AbglibValueError, check_positive
from .discretize import zoh

__all__ = ["sine_state", "taylor_model", "taylor_predict"]


def _check_order(order) -> int:
    if isinstance(order, bool) or int(order) != order or order < 0:
        raise AbglibValueError(f"order of prediction must be an integer >= 0, got {order!r}")
    return int(order)


def taylor_model(order: int, dt: float):
    """Discrete object model of prediction order ``order`` (eqs 3.4-3.5).

    Returns
    -------
    At : array (p, p)
        ``exp(Atc dt)``, p = order + 1.
    Ct : array (1, p)
        Selects the position ``z`` (eq 4.3).
    Gt : array (p, 1)
        Zero-order-hold input of the highest derivative's rate ``z^(p)`` held over a step:
        how the model error ("the force ... white noise with intensity V_w", sec. 7.3)
        enters the discrete model.
    """
    q = _check_order(order)
    dt = float(check_positive("dt", dt))
    return tuple(m.copy() for m in _taylor_model(q, dt))


@lru_cache(maxsize=64)
def _taylor_model(q: int, dt: float):
    p = q + 1
    atc = np.eye(p, k=1)
    bc = np.zeros((p, 1))
    bc[-1, 0] = 1.0
    at, gt = zoh(atc, bc, dt)
    ct = np.zeros((1, p))
    ct[0, 0] = 1.0
    return at, ct, gt


def taylor_predict(x0, order: int, dt: float, k):
    """Closed-form Taylor prediction ``sum_j z^(j)(0) (k dt)^j / j!`` (eq 3.8).

    Parameters
    ----------
    x0 : array (p,)
        ``[z, z', ..., z^(q)]`` at the present time, p >= order + 1 (extra entries ignored).
    k : array of int
        Steps ahead.
    """
    q = _check_order(order)
    x0 = np.asarray(x0, dtype=float)
    if x0.shape[0] < q + 1:
        raise AbglibValueError(f"x0 needs order + 1 = {q + 1} derivatives, got {x0.shape[0]}")
    h = np.asarray(k, dtype=float) * float(check_positive("dt", dt))
    return sum(x0[j] * h**j / math.factorial(j) for j in range(q + 1))


def sine_state(amplitude, omega, t, order: int):
    """Exact object state ``[z, z', ..., z^(order)]`` of ``z = amplitude sin(omega t)`` (ch. 6).

    Returns an array ``(order + 1, *shape(t))``.
    """
    q = _check_order(order)
    t = np.asarray(t, dtype=float)
    return np.stack(
        [amplitude * omega**j * np.sin(omega * t + j * np.pi / 2.0) for j in range(q + 1)]
    )
