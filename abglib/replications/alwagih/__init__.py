"""Seed 001: Al-Wagih and Abdulla, *A Study of αβ Tracker with Some New Algorithms for
Selecting α and β Parameters*.

``study``      the simulation study on the reconstructed experiments: RMSE tables 1-6,
               the paired t-test, :class:`~.study.AlwagihStudy`
``printed``    the printed Tables 1-6, and Tables 3-6 recomputed from Tables 1-2
``stability``  section 4 as printed: eqs 11, 12-14, 20, 21-22; section 5.1's compromise
``claims``     one declaration per published claim (``CLAIMS``, ``STUDY``)
``figures``    the report's figures (imports matplotlib; not loaded here)

The methods M1-M5 themselves are in :mod:`abglib.methods` (core library).
"""

from .study import *  # noqa: F403
