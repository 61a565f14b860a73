r"""Three-degree-of-freedom dimensionless tracking antenna (seed 004, ch. 5, Fig. I.3, app. H).

The antenna (inertia :math:`J_a`, angle :math:`\varphi_a`) is connected to the driver's
rotor (:math:`J_d`, :math:`\varphi_d`) by a spring :math:`k_a` and a damper :math:`b_a`;
the driver's stator sits on the carriage (:math:`J_f`, :math:`\varphi_f`), connected to
the environment by a spring :math:`k_f` and a damper :math:`b_f`. The driver has damping
:math:`b_d` between rotor and stator, and the control torque :math:`T` acts between rotor
(+T) and stator (-T).

Dimensionless form (reconstruction; the scan lost the formulas and the values). Time is
scaled by the antenna eigenfrequency :math:`\omega_0 = \sqrt{k_a/J_a}` (antenna on a held
rotor), so the frequency ratio :math:`\omega` of ch. 6 is the object's angular frequency in
this time; inertias are fractions of :math:`J_a + J_d` (app. H: :math:`p_d = 1 - p_a`);
dampings are :math:`\beta_i = b_i / (2\sqrt{k_a J_a})` (one reference for all, so that the
text's ratios of dampings are ratios of the :math:`\beta_i`); :math:`\kappa = k_f/k_a`;
torque :math:`u = T/k_a`:

.. math::
    \ddot\varphi_a &= -(\varphi_a-\varphi_d) - 2\beta_a(\dot\varphi_a-\dot\varphi_d)\\
    \tfrac{p_d}{p_a}\ddot\varphi_d &= (\varphi_a-\varphi_d) + 2\beta_a(\dot\varphi_a-
        \dot\varphi_d) - 2\beta_d(\dot\varphi_d-\dot\varphi_f) + u\\
    \tfrac{p_f}{p_a}\ddot\varphi_f &= -\kappa\varphi_f - 2\beta_f\dot\varphi_f
        + 2\beta_d(\dot\varphi_d-\dot\varphi_f) - u

State ``x = [phi_a, phi_d, phi_f, dphi_a, dphi_d, dphi_f]``, output ``y = phi_a``.
"""

from __future__ import annotations

from dataclasses import dataclass, fields, replace

import numpy as np

from ..._checks import AbglibValueError

__all__ = ["PARAMETER_NAMES", "AntennaParams", "continuous_model"]

#: The independent dimensionless parameters (app. H; p_d = 1 - p_a is derived).
PARAMETER_NAMES = ("p_a", "p_f", "beta_a", "beta_d", "beta_f", "kappa")


@dataclass(frozen=True)
class AntennaParams:
    """Dimensionless antenna parameters (seed 004, ch. 5 and app. H).

    Parameters
    ----------
    p_a : float
        Antenna inertia as a fraction of antenna + rotor, 0 < p_a < 1 (p_d = 1 - p_a).
    p_f : float
        Carriage inertia over antenna + rotor inertia, > 0.
    beta_a, beta_d, beta_f : float
        Antenna, driver and carriage-foundation damping, >= 0 (one common reference).
    kappa : float
        Carriage stiffness over antenna stiffness, > 0.
    """

    p_a: float
    p_f: float
    beta_a: float
    beta_d: float
    beta_f: float
    kappa: float

    def __post_init__(self):
        for f in fields(self):
            v = getattr(self, f.name)
            try:
                v = float(v)
            except (TypeError, ValueError):
                raise AbglibValueError(f"{f.name} must be a real number, got {v!r}") from None
            if not np.isfinite(v):
                raise AbglibValueError(f"{f.name} must be finite, got {v!r}")
            object.__setattr__(self, f.name, v)
        if not 0.0 < self.p_a < 1.0:
            raise AbglibValueError(
                f"p_a must satisfy 0 < p_a < 1 (p_d = 1 - p_a), got {self.p_a!r}"
            )
        for name in ("p_f", "kappa"):
            if getattr(self, name) <= 0.0:
                raise AbglibValueError(f"{name} must be > 0, got {getattr(self, name)!r}")
        for name in ("beta_a", "beta_d", "beta_f"):
            if getattr(self, name) < 0.0:
                raise AbglibValueError(f"{name} must be >= 0, got {getattr(self, name)!r}")

    @property
    def p_d(self) -> float:
        """Rotor inertia fraction, ``1 - p_a`` (app. H)."""
        return 1.0 - self.p_a

    @classmethod
    def from_mapping(cls, m) -> AntennaParams:
        """Build from a mapping holding (at least) :data:`PARAMETER_NAMES`."""
        missing = [k for k in PARAMETER_NAMES if k not in m]
        if missing:
            raise AbglibValueError(f"antenna parameters missing {missing}")
        return cls(**{k: m[k] for k in PARAMETER_NAMES})

    def scaled(self, name: str, factor: float) -> AntennaParams:
        """Copy with parameter ``name`` multiplied by ``factor`` (app. H robustness tests)."""
        if name not in PARAMETER_NAMES:
            raise AbglibValueError(f"name must be one of {PARAMETER_NAMES}, got {name!r}")
        return replace(self, **{name: getattr(self, name) * float(factor)})


def continuous_model(params: AntennaParams):
    """Continuous state-space matrices ``(Ac, Bc, Cc)`` of the antenna (module docstring).

    Returns
    -------
    Ac : array (6, 6)
    Bc : array (6, 1)
    Cc : array (1, 6)
        Output: antenna position ``phi_a``.
    """
    p = params
    m = np.array([1.0, p.p_d / p.p_a, p.p_f / p.p_a])
    k = np.array([[1.0, -1.0, 0.0], [-1.0, 1.0, 0.0], [0.0, 0.0, p.kappa]])
    d = 2.0 * np.array(
        [
            [p.beta_a, -p.beta_a, 0.0],
            [-p.beta_a, p.beta_a + p.beta_d, -p.beta_d],
            [0.0, -p.beta_d, p.beta_d + p.beta_f],
        ]
    )
    f = np.array([0.0, 1.0, -1.0])
    ac = np.zeros((6, 6))
    ac[:3, 3:] = np.eye(3)
    ac[3:, :3] = -k / m[:, None]
    ac[3:, 3:] = -d / m[:, None]
    bc = np.zeros((6, 1))
    bc[3:, 0] = f / m
    cc = np.zeros((1, 6))
    cc[0, 0] = 1.0
    return ac, bc, cc
