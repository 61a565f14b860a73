"""Seed 002: Huang, Yang and Ma, *Research on Fixed-gain Range Tracking Loop*.

``printed``      the paper's printed forms (eqs 1-14, the tracking-error formulas), as
                 printed and reconstructed
``enbw_tables``  Figures 2-3 and Tables 1-2: the ENBW of the gain rules, cell by cell
``simulation``   Figures 5-7: the simulated range track and its summary
``study``        :class:`HuangStudy`, every table the claims and the report read
``claims``       one declaration per published number or claim (loaded by
                 :func:`abglib.replications.reproduce`)
``figures``      the report's figures (imports matplotlib; not loaded here)
"""

from .enbw_tables import *  # noqa: F403
from .printed import *  # noqa: F403
from .simulation import *  # noqa: F403
from .study import *  # noqa: F403
