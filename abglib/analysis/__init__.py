"""Exact analysis of fixed-gain alpha-beta(-gamma) trackers, each closed form with a numeric twin.

Modules (one concept each; every public name is re-exported here):

``_transfer``
    transfer functions (seed 000 eqs 36-40), frequency response
``_stability``
    poles, pole radius, Jury conditions (seed 000 eqs 41-49),
    seed 001 eqs 12-14 as printed, :func:`is_stable`
``_features``
    frequency-domain features: minimum at wT = pi (eq 50), exact wT at a gain
    level (-3 dB, -6 dB, unity), exact peak and overshoot, and the printed
    approximations of seed 000 eqs 51-59
``_variance``
    variance reduction factors: closed forms (seed 000 eqs 11-14, 25-27,
    31-32) and the discrete Lyapunov solution (:func:`vrf`)
``_transient``
    transient measures D^2, A^2 (seed 000 eqs 15-20) and direct summation;
    steady-state lag errors (seed 002)
``_enbw``
    equivalent noise bandwidth (seed 002 eq 8, one-sided) and a direct numeric route
``_statespace``
    the state-space form of a gain set (:func:`state_space`), where every numeric route
    starts
``_kalman``
    the steady-state Kalman filter of a polynomial target model: process noise and the
    discrete algebraic Riccati equation (the route of
    :func:`abglib.design.steady_state_kalman`)

Seed 002's printed forms (eqs 3, 5-7, 8-14, the steady-state lag formulas) live with
their document in ``abglib.replications.huang.printed``.
"""

from ._enbw import *  # noqa: F403
from ._features import *  # noqa: F403
from ._kalman import *  # noqa: F403
from ._stability import *  # noqa: F403
from ._statespace import *  # noqa: F403
from ._transfer import *  # noqa: F403
from ._transient import *  # noqa: F403
from ._variance import *  # noqa: F403
