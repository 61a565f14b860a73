"""The reconstructed nominal antenna (config.yaml `antenna.parameters`) shared by the
antenna tests: parameters and sample interval (2π/10: ten samples per eigenperiod)."""

import numpy as np
import pytest

NOMINAL_VALUES = dict(p_a=0.9, p_f=1.0, beta_a=0.05, beta_d=0.005, beta_f=0.1, kappa=1.0)
DT = 2 * np.pi / 10

#: The xdist group of the antenna test modules that call compiled loops with signatures of
#: their own (a transposed matrix, a writeable covariance, the phase-by-phase Kalman loop),
#: which numba's warm cache (tests/_numba_warm.py) does not hold: one worker compiles them
#: for all those modules (pytest-xdist --dist loadgroup), instead of each worker.
OWN_KERNEL_SIGNATURES = pytest.mark.xdist_group("antenna_test_kernels")
