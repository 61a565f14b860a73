"""The claim set of seed 004 and the assumed inputs its claims depend on.

Declared here so that the claims of each chapter (:mod:`.claims_exact`,
:mod:`.claims_estimation`, :mod:`.claims_apph`) register on one :class:`ClaimSet`;
:mod:`.claims` is the entry point the replication driver imports.
"""

from __future__ import annotations

from .._claims import ClaimSet

__all__ = ["CLAIMS", "EST", "MODEL", "SPREAD"]

CLAIMS = ClaimSet("antenna")

#: Reconstructed model inputs (ch. 5 lost its value list; ch. 6's "10 times" has two
#: readings of the sample interval): every claim computed on the model depends on them.
MODEL = (
    "antenna.parameters.beta_a",
    "antenna.parameters.p_f",
    "antenna.parameters.p_a",
    "antenna.samples_per_period",
)
#: ... and, with Kalman estimation (ch. 8), the measurement covariance and the V_w scale.
EST = (*MODEL, "antenna.kalman.v_v", "antenna.kalman.vw_scale")
#: The lost spacing of the three fifth-order V_w settings of Figs I.10-I.15.
SPREAD = "antenna.kalman.spread_fifth"
