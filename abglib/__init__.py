"""abglib: exact, fast fixed-gain alpha-beta and alpha-beta-gamma trackers.

Public names
------------
:class:`Gains`
    Gain set ``(alpha, beta, gamma)`` in the canonical convention (seed 000, eqs 1-6).
:func:`track`
    Run the tracker recursion over measurements ``z`` of shape ``(..., n)``.
:class:`TrackResult`
    What :func:`track` returns: ``x_pred``, ``x_smooth``, ``v_smooth``, ``a_smooth``.

Submodules (imported on first use)
----------------------------------
:mod:`~abglib.design`
    Every gain-design rule of the sources (standard/critically damped, QD,
    Benedict-Bordner, Simpson, growing memory, Huang type I/II, Bendix, Kalata).
:mod:`~abglib.conventions`
    Explicit converters to and from Huang et al.'s and FilterPy's gain conventions.
:mod:`~abglib.analysis`
    Transfer functions, frequency response, stability, variance reduction, transient
    measures, ENBW and frequency-domain features, each with a numeric twin.
:mod:`~abglib.simulate`
    Trajectories and measurement noise.
:mod:`~abglib.methods`
    The gain-selection methods M1-M5 of seed 001 (and a causal M5), batched.
:mod:`~abglib.verdicts`
    Judging a printed number against a reproduced one: tolerance from the printed digits,
    the reading catalogue with each family's look-elsewhere chance, vague words, and
    robustness over plausible inputs and random seeds.

Layers installed with extras (``pip install ".[...]"``), lowest first
----------------------------------------------------------------------
common
    (any extra) what the layers above the core share: deterministic tables, atomic
    writes, a job's threads and log, the one figure style.
bench
    (``[bench]``) simulated radar datasets, tracker variants, Monte Carlo cell metrics,
    league tables, agreement with peer libraries.
replications
    (``[replications]``) one folder per source document: printed forms, study, claims;
    the published-versus-reproduced tables.
reporting
    (``[reporting]``) provenance, report rendering, releases, the workflow's glue.

The core (``pip install .`` from a clone) needs numpy, scipy and numba only. Each layer imports
only the ones below it (``docs/architecture.md``, ``tests/test_layers.py``).
"""

from __future__ import annotations

import importlib

from ._checks import AbglibValueError
from .engine import TrackResult, track
from .gains import Gains

__version__ = "0.4.8"

__all__ = ["AbglibValueError", "Gains", "TrackResult", "__version__", "track"]

_SUBMODULES = {
    "analysis",
    "bench",
    "common",
    "conventions",
    "design",
    "methods",
    "replications",
    "reporting",
    "simulate",
    "verdicts",
}


def __getattr__(name: str):
    if name in _SUBMODULES:
        return importlib.import_module(f".{name}", __name__)
    raise AttributeError(f"module 'abglib' has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | _SUBMODULES)
