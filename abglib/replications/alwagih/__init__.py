"""Seed 001: Al-Wagih and Abdulla, *A Study of αβ Tracker with Some New Algorithms for
Selecting α and β Parameters*.

``study``    the simulation study: RMSE tables 1-6, the paired t-test, printed-table checks
``figures``  the report's figures (imports matplotlib; not loaded here)
"""

from .study import *  # noqa: F403
