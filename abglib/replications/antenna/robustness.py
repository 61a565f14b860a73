"""Robustness of the controlled antenna to design-parameter errors (seed 004, app. H).

The real plant keeps the nominal parameters; controller and Kalman filter are designed
with one parameter multiplied by a factor. Stability is judged on the linear closed loop
(:func:`.closedloop.closed_loop_matrix`, quantisation left out): its spectral radius.
The nominal loop has radius exactly 1: the filter's estimate of the antenna's rigid-body
mode (an eigenvalue 1 of the antenna model) gets no correction (w = 0 for the antenna,
sec. 7.3), so that mode of the estimation error is marginal; it is never excited when the
model is exact. A factor is *stable* when the radius is at most ``1 + tol``.
"""

from __future__ import annotations

import numpy as np
import scipy.optimize

from .closedloop import closed_loop_matrix, design_controller
from .model import AntennaParams

__all__ = ["RADIUS_DIGITS", "spectral_radius", "stable_interval"]


#: Significant digits of a written closed-loop spectral radius: a stable design's radius
#: is a double eigenvalue 1 (the marginal mode above), which round-off of ~1e-16 in the
#: designs moves by ~sqrt(1e-16) = 1e-8, so digits beyond the 7th are noise (the BLAS and
#: the compiled Riccati routes differ by up to 1.6e-8 there).
RADIUS_DIGITS = 7


def spectral_radius(nominal: AntennaParams, name, factor, dt, q, r, order, v_w, v_v) -> float:
    """Spectral radius of the closed loop with design parameter ``name`` scaled by ``factor``.

    The designs use the compiled Riccati solvers (:func:`.lq.riccati_solve`,
    :func:`.kalman.kalman_riccati` ``fast=True``; faster than the exact routes). A
    stable design's radius is the marginal mode's 1 computed to ~1e-8 by either route, so
    it holds :data:`RADIUS_DIGITS` digits.
    """
    design = nominal.scaled(name, factor)
    ctrl = design_controller(design, dt, q, r, fast=True)
    big = closed_loop_matrix(nominal, ctrl, order, v_w, v_v, fast=True)
    return float(np.max(np.abs(np.linalg.eigvals(big))))


def stable_interval(nominal, name, dt, q, r, order, v_w, v_v, grid, tol=1e-9, radius=None):
    """Largest interval of factors around 1 with radius <= 1 + tol, refined by bisection.

    Parameters
    ----------
    grid : array
        Increasing factors containing values on both sides of 1; the edges are located
        between grid points and refined with :func:`scipy.optimize.brentq`.

    radius : callable, optional
        ``radius(factor)``, a (memoised) :func:`spectral_radius` of the same setting.

    Returns
    -------
    (lower, upper) : floats; ``nan`` where the loop stays stable to the end of the grid.
    """
    grid = np.asarray(grid, dtype=float)

    if radius is None:

        def radius(f):
            return spectral_radius(nominal, name, f, dt, q, r, order, v_w, v_v)

    def excess(f):
        return radius(f) - 1.0 - tol

    # evaluated on demand: the walk from 1 outwards reads the grid only up to each edge
    # (a radius costs an LQ design and a Kalman design)
    seen: dict[int, float] = {}

    def ex(j: int) -> float:
        if j not in seen:
            seen[j] = excess(grid[j])
        return seen[j]

    i1 = int(np.argmin(np.abs(grid - 1.0)))
    out = []
    for step, stop in ((-1, -1), (1, len(grid))):
        j, edge = i1, np.nan
        while j + step != stop:
            if ex(j) <= 0.0 < ex(j + step):
                a, b = sorted((grid[j], grid[j + step]))
                edge = scipy.optimize.brentq(excess, a, b, xtol=1e-6 * a)
                break
            if ex(j + step) > 0.0:
                break
            j += step
        out.append(edge)
    return out[0], out[1]
