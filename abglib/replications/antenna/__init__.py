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
"""

from .closedloop import *  # noqa: F403
from .discretize import *  # noqa: F403
from .kalman import *  # noqa: F403
from .lq import *  # noqa: F403
from .model import *  # noqa: F403
from .objectmodel import *  # noqa: F403
from .preview import *  # noqa: F403
from .robustness import *  # noqa: F403
