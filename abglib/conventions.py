"""Converters between the canonical gain convention and the others met in the sources.

This module is the only place where a gain convention is converted. The canonical
convention is Steelman's (seed 000, eqs 1-6; ``shared/CONTRACTS.md`` section 1): the
acceleration is corrected by ``(gamma / T^2) r``. Two other conventions occur:

``Huang et al.`` (seed 002)
    The acceleration gain is half the canonical one, ``gamma_H = gamma / 2``: their
    characteristic polynomial (seed 002, eq 4) is Steelman's (seed 000, eq 40) with
    ``gamma / 2`` replaced by ``gamma_H``, and their corrector (eq 1) multiplies the
    residual by ``2 gamma_H / T^2``. (Their predictor, eq 2, prints ``T^2 R''`` where
    ``T^2 R'' / 2`` is meant; the transfer function, eq 3, follows from the latter.)
``FilterPy`` (``filterpy.gh.GHKFilter``)
    ``g = alpha``, ``h = beta`` and ``k = gamma / 2``: ``GHKFilter.update`` corrects the
    acceleration by ``2 k y / dt^2``.

Alpha and beta mean the same thing in all three conventions.
"""

from __future__ import annotations

from ._checks import check_finite, scalar_or_array
from .gains import Gains, require_gains

__all__ = ["from_filterpy", "from_huang", "to_filterpy", "to_huang"]


def _half(value):
    return scalar_or_array(check_finite("gamma", value) / 2.0)


def to_huang(gains: Gains) -> tuple:
    r"""Canonical gains to Huang et al.'s convention ``(alpha_h, beta_h, gamma_h)``.

    Parameters
    ----------
    gains : Gains
        Canonical gains (seed 000, eqs 1-3); scalars or arrays ``(...)``.

    Returns
    -------
    alpha_h, beta_h, gamma_h : float or array (...)
        Gains as seed 002 uses them (eqs 1, 3-4): ``alpha_h = alpha``,
        ``beta_h = beta``, ``gamma_h = gamma / 2``.

    Notes
    -----
    Seed 002, eq 4 expands to Steelman's seed 000, eq 40 exactly when

    .. math:: \gamma_H = \gamma / 2 .

    References
    ----------
    Huang, Yang & Ma, seed 002 (``huang``), eqs 1, 3-4 (gamma_H = gamma / 2);
    Steelman (1978), seed 000 (``steelman1978``), eq 40.

    Examples
    --------
    >>> to_huang(Gains(0.5, 0.2, 0.04))
    (0.5, 0.2, 0.02)
    """
    g = require_gains(gains)
    return g.alpha, g.beta, _half(g.gamma)


def from_huang(alpha_h, beta_h, gamma_h=0.0) -> Gains:
    r"""Gains given in Huang et al.'s convention (seed 002) to canonical :class:`~abglib.Gains`.

    Parameters
    ----------
    alpha_h, beta_h : float or array (...)
        Position and velocity gains of seed 002 (the same as canonical).
    gamma_h : float or array (...), default 0.0
        Seed 002's acceleration gain (eq 1: the residual is scaled by ``2 gamma_h / T^2``).

    Returns
    -------
    Gains
        ``Gains(alpha_h, beta_h, 2 * gamma_h)``.

    Notes
    -----
    .. math:: \gamma = 2\gamma_H \quad\text{(seed 002, eq 4 vs seed 000, eq 40)}

    References
    ----------
    Huang, Yang & Ma, seed 002 (``huang``), eqs 1, 3-4 (gamma_H = gamma / 2);
    Steelman (1978), seed 000 (``steelman1978``), eq 40.

    Examples
    --------
    >>> from_huang(0.71, 0.29, 0.020)
    Gains(alpha=0.71, beta=0.29, gamma=0.04)
    """
    gamma = scalar_or_array(check_finite("gamma_h", gamma_h) * 2.0)
    return Gains(alpha_h, beta_h, gamma)


def to_filterpy(gains: Gains) -> tuple:
    r"""Canonical gains to FilterPy's ``(g, h, k)`` (``filterpy.gh.GHKFilter``).

    Parameters
    ----------
    gains : Gains
        Canonical gains; scalars or arrays ``(...)``.

    Returns
    -------
    g, h, k : float or array (...)
        ``g = alpha``, ``h = beta``, ``k = gamma / 2`` (FilterPy corrects the
        acceleration by ``2 k y / dt^2``, ``filterpy/gh/gh_filter.py``,
        ``GHKFilter.update``). For an alpha-beta tracker (``GHFilter``) use ``g, h``.

    Notes
    -----
    .. math:: g = \alpha,\quad h = \beta,\quad k = \gamma / 2

    References
    ----------
    FilterPy's ``filterpy.gh.GHKFilter`` (not a seed document);
    Steelman (1978), seed 000 (``steelman1978``), eqs 1-3.

    Examples
    --------
    >>> to_filterpy(Gains(0.5, 0.2, 0.04))
    (0.5, 0.2, 0.02)
    """
    g = require_gains(gains)
    return g.alpha, g.beta, _half(g.gamma)


def from_filterpy(g, h, k=0.0) -> Gains:
    r"""FilterPy's ``(g, h, k)`` to canonical :class:`~abglib.Gains`.

    Parameters
    ----------
    g, h : float or array (...)
        FilterPy's position and velocity gains (``alpha``, ``beta``).
    k : float or array (...), default 0.0
        FilterPy's acceleration gain (``GHKFilter``); 0 for a ``GHFilter``.

    Returns
    -------
    Gains
        ``Gains(g, h, 2 * k)``.

    Notes
    -----
    .. math:: \alpha = g,\quad \beta = h,\quad \gamma = 2k

    References
    ----------
    FilterPy's ``filterpy.gh.GHKFilter`` (not a seed document;
    ``k = gamma / 2``); Steelman (1978), seed 000 (``steelman1978``), eqs 1-3.

    Examples
    --------
    >>> from_filterpy(0.5, 0.2, 0.02)
    Gains(alpha=0.5, beta=0.2, gamma=0.04)
    """
    gamma = scalar_or_array(check_finite("k", k) * 2.0)
    return Gains(g, h, gamma)
