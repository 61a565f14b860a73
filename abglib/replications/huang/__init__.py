"""Seed 002: Huang, Yang and Ma, *Research on Fixed-gain Range Tracking Loop*.

``study``    the printed forms and the study (thermal error, ENBW routes, range track)
``figures``  the report's figures (imports matplotlib; not loaded here)
"""

from .study import *  # noqa: F403
