"""Exact analysis of fixed-gain alpha-beta(-gamma) trackers, each closed form with a numeric twin.

By topic (each topic is one private module, ``_transfer`` ... ``_kalman``; every public
name is re-exported here):

Transfer functions and frequency response (seed 000 eqs 36-40)
    :func:`transfer_function`, :func:`frequency_response`; the outputs :data:`OUTPUTS`
Stability (seed 000 eqs 41-49; seed 001 eqs 12-14 as printed)
    :func:`poles`, :func:`pole_radius`, :func:`characteristic_polynomial`,
    :func:`is_stable`, :func:`require_stable`, :func:`stable_jury_steelman`,
    :func:`stable_sufficient_eq49`
Frequency-domain features (seed 000 eqs 50-59)
    the minimum at ωT = π (:func:`min_gain_at_pi`, :func:`min_gain_steelman_eq50`), the
    exact ωT at a gain level (:func:`omega_at_gain`), the exact :func:`peak` and
    overshoot, :func:`first_undesired_max`, and the printed approximations
    (:func:`omega_unity_eq51`, :func:`omega_unity_eq52`, :func:`omega_3db_eq53`,
    :func:`omega_max_eq54`, :func:`overshoot_eq55`, :func:`overshoot_eq55_terms`)
Variance reduction (seed 000 eqs 11-14, 25-27, 31-32)
    the discrete Lyapunov solution :func:`vrf` (keys :data:`VRF_KEYS`) and the closed
    forms :func:`vrf_simpson`, :func:`vrf_standard_abg`, :func:`vrf_standard_ab`,
    :func:`vrf_benedict_ab`
Transients and lag (seed 000 eqs 15-20; seed 002)
    :func:`transient_d2`, :func:`transient_a2` (direct summation) and Simpson's
    :func:`transient_d2_simpson`, :func:`transient_a2_simpson`; :func:`steady_state_lag`
Noise bandwidth (seed 002 eq 8, one-sided)
    :func:`enbw` and its direct numeric route :func:`enbw_numeric`
State space
    :func:`state_space` (a :class:`StateSpace`), where every numeric route starts
Steady-state Kalman filter of a polynomial target model
    :func:`process_noise` (models :data:`KALMAN_MODELS`) and :func:`kalman_gains`, the
    discrete algebraic Riccati route of :func:`abglib.design.steady_state_kalman`

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
