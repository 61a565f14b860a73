"""The reconstructed nominal antenna (config.yaml `antenna.parameters`) shared by the
antenna tests: parameters and sample interval (2π/10: ten samples per eigenperiod)."""

import numpy as np

NOMINAL_VALUES = dict(p_a=0.9, p_f=1.0, beta_a=0.05, beta_d=0.005, beta_f=0.1, kappa=1.0)
DT = 2 * np.pi / 10
