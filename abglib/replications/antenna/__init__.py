"""Optimal preview control and Kalman estimation for a tracking antenna (seed 004).

A replication of a report on discrete-time LQ tracking with preview and Kalman state
estimation for a radar tracking antenna (a follow-up to Timmermans, 1990). The scan lost
the model's parameter values; :mod:`.model` reconstructs them (see its docstring and the
report). One module per concept:

``model``        3-DOF dimensionless antenna (ch. 5, app. H), parameter validation
``discretize``   zero-order-hold discretisation (app. D)
``lq``           Riccati eq 2.12, matrices 2.16-2.21, finite-preview law 2.22-2.28 and 2.37,
                 preview-step count 2.35
``objectmodel``  Taylor-series object model (ch. 3, eqs 3.3-3.8)
``preview``      infinite-preview law through the Stein (Lyapunov) equation (ch. 4, app. E)
``kalman``       predictor-form Kalman filter on the extended model (ch. 7, app. F-G)
``closedloop``   simulations of chapters 6 and 8, appendix H robustness, and the
                 fixed-gain alpha-beta-gamma object estimator (beyond the source)
``ensemble``     the quantised closed loop over an ensemble of object phases (compiled):
                 maxima under quantisation are judged on their median (the loop is chaotic)
``study``        :class:`AntennaStudy`, the reconstructed setting and every report table;
                 pieces per chapter in ``study_exact`` (ch. 2-6), ``study_estimation``
                 (ch. 8), ``study_apph`` (app. H), ``study_abg`` (beyond the source)
``claims``       ``CLAIMS``/``STUDY`` for :func:`abglib.replications.reproduce`; one
                 declaration per published key in ``claims_exact``, ``claims_estimation``,
                 ``claims_apph``; the assumed inputs they depend on in ``_claimset``
"""

from .closedloop import *  # noqa: F403
from .discretize import *  # noqa: F403
from .kalman import *  # noqa: F403
from .lq import *  # noqa: F403
from .model import *  # noqa: F403
from .objectmodel import *  # noqa: F403
from .preview import *  # noqa: F403
from .robustness import *  # noqa: F403
