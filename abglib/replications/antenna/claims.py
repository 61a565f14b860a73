"""Seed 004's claims (``CLAIMS``) and study (``STUDY``) for the replication driver.

One declaration per published key of ``data/published/antenna/claims.csv``, by chapter:
:mod:`.claims_exact` (ch. 2-6, exact states), :mod:`.claims_estimation` (ch. 8-9, Kalman
estimation with quantised measurements, judged on medians over object phases) and
:mod:`.claims_apph` (app. H). The inputs each claim depends on are in :mod:`._claimset`.
"""

from __future__ import annotations

from . import claims_apph, claims_estimation, claims_exact  # noqa: F401  (register)
from ._claimset import CLAIMS
from .study import AntennaStudy as STUDY

__all__ = ["CLAIMS", "STUDY"]
