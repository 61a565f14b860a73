"""Numerical hygiene shared by the studies: results that do not move with the machine."""

from __future__ import annotations

import numpy as np

__all__ = ["snap"]


def snap(x, bits: int = 36) -> np.ndarray:
    """``x`` rounded to ``bits`` mantissa bits (relative error at most 2^-bits).

    Designed gains and matrices differ in their last bits between BLAS kernels (FMA or
    not, the order of a sum). Rounding them to a coarser binary grid before they drive a
    simulation makes the simulation identical on every machine, unless a value lies within
    those last bits of a grid boundary, and changes the design far below any tolerance
    that matters (36 bits: 1.5e-11 relative).
    """
    m, e = np.frexp(np.asarray(x, dtype=float))
    return np.ldexp(np.round(m * 2.0**bits) / 2.0**bits, e)
