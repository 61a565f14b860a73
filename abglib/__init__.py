"""abglib: exact, fast fixed-gain alpha-beta and alpha-beta-gamma trackers.

Public names
------------
Gains
    Gain set ``(alpha, beta, gamma)`` in the canonical convention (seed 000, eqs 1-6).
track
    Run the tracker recursion over measurements ``z`` of shape ``(..., n)``.
TrackResult
    What :func:`track` returns: ``x_pred``, ``x_smooth``, ``v_smooth``, ``a_smooth``.

Submodules (imported on first use)
----------------------------------
design
    Every gain-design rule of the sources (standard/critically damped, QD,
    Benedict-Bordner, Simpson, growing memory, Huang type I/II, Bendix, Kalata).
conventions
    Explicit converters to and from Huang et al.'s and FilterPy's gain conventions.
analysis
    Transfer functions, frequency response, stability, variance reduction, transient
    measures, ENBW and frequency-domain features, each with a numeric twin.
compare
    Published-versus-reproduced tables (``comparison.csv``) and the scorecard.
datasets
    Simulated radar datasets (seeded kinematics and noise; Parquet + manifest).
methods
    The gain-selection methods M1-M5 of seed 001 (and a causal M5), batched.
alwagih
    The seed 001 simulation study: RMSE tables 1-6, the paired t-test, printed-table checks.
bendix, huang
    Seed 003 and seed 002 specifics (the Bendix program; thermal-noise error, printed ENBW forms).
antenna
    Seed 004: reconstructed antenna model, LQ preview control, Kalman estimation.
variants, metrics, benchmark, peers
    The benchmark matrix: named tracker variants, Monte Carlo cell metrics, league tables,
    agreement with peer libraries.
plotting, provenance, report
    Figures, provenance records and report rendering for the pipeline.
"""

from __future__ import annotations

import importlib

from ._checks import AbglibValueError
from .engine import TrackResult, track
from .gains import Gains

__version__ = "0.2.0"

__all__ = ["AbglibValueError", "Gains", "TrackResult", "__version__", "track"]

_SUBMODULES = {
    "alwagih",
    "analysis",
    "antenna",
    "benchmark",
    "bendix",
    "compare",
    "conventions",
    "datasets",
    "design",
    "huang",
    "methods",
    "metrics",
    "peers",
    "plotting",
    "provenance",
    "report",
    "simulate",
    "variants",
}


def __getattr__(name: str):
    if name in _SUBMODULES:
        return importlib.import_module(f".{name}", __name__)
    raise AttributeError(f"module 'abglib' has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | _SUBMODULES)
