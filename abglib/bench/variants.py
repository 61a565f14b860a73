r"""Registry of tracker variants: a config entry names a design rule and its parameters.

A *variant* is a named entry of ``config.yaml`` (``benchmark: variants:``)::

    std_ab_0.3:   {rule: standard_alpha, alpha: 0.3, order: 2}
    huang1_2hz:   {rule: huang_enbw, bn_hz: 2.0, type: type1, order: 2}

:func:`variant_gains` turns it into canonical :class:`~abglib.Gains` for a scenario's
sample interval ``dt`` (and length ``n_samples``, for time-varying gains); each rule is a
thin adapter around one function of :mod:`abglib.design`, which cites its source
equation. :data:`RULES` lists the rules; :func:`register` adds one (a new design function
in abglib plus one :class:`Rule` is all a new kind of variant needs). Rules of kind
``"method"`` run an estimator other than the fixed-gain recursion (e.g. the adaptive
methods M3-M5 of seed 001) through a ``run(z, dt, **params)`` callable returning
``x_pred, x_smooth, v_smooth`` (and optionally ``a_smooth``).

Rules
-----
==================  =====================================================  ===============
rule                parameters (``[]`` optional, default)                  abglib.design
==================  =====================================================  ===============
standard_theta      theta, [order=2]                                       standard_ab/abg
standard_alpha      alpha, [order=2]                                       standard_from_alpha
qd_m                m                                                      qd
qd_alpha            alpha                                                  qd(qd_m_from_alpha)
benedict_bordner    alpha                                                  benedict_bordner
simpson             alpha, beta or gamma                                   simpson
kalata_ab           tracking_index                                         kalata_ab
kalata_abg          tracking_index                                         kalata_abg
huang_enbw          bn_hz, [type="type1"], [order=2]                       huang_for_enbw
bendix              period_s, [table="memo"]                               bendix
growing_memory      [start=1]                                              growing_memory
steady_state_kalman q, r, [order=2], [model="piecewise_constant"]          steady_state_kalman
gains               alpha, beta, [gamma=0]                                 Gains (explicit)
==================  =====================================================  ===============

The methods of :mod:`abglib.methods` (seed 001, Al-Wagih & Abdulla) are
registered too, as rules of kind ``"method"`` scored on their one-step predictions:
``alwagih_m1`` (alpha0), ``alwagih_m2``, ``alwagih_m3`` ([w_start, w_stop, w_n]),
``alwagih_m4`` (alpha0, window, [grid_start, grid_stop, grid_n]), ``alwagih_m5``
([grid_start, grid_stop, grid_n], [causal=0], [memory=1]).
"""

from __future__ import annotations

import numbers
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import numpy as np

from .. import design
from .._checks import AbglibValueError
from ..gains import Gains

__all__ = [
    "RULES",
    "Rule",
    "register",
    "variant_family",
    "variant_gains",
    "variant_rule",
    "variant_runner",
]

#: Keys of a variant entry that are not rule parameters.
META_KEYS = ("rule", "label")


@dataclass(frozen=True)
class Rule:
    """One design rule a variant may name.

    Attributes
    ----------
    name : str
        The ``rule:`` value in config.
    build : callable
        ``build(params, dt, n_samples) -> Gains`` (kind ``"gains"``) or
        ``build(params, dt, n_samples) -> run`` with ``run(z) -> result`` (kind ``"method"``).
    required : tuple of str
        Parameters that must be given.
    optional : dict
        Optional parameters and their defaults.
    family : str or callable
        Design family for the trade-off plots; a callable gets the full parameters.
    fixed_gain : bool
        True when the gains are constant in time (the analytic VRF applies).
    kind : {"gains", "method"}
    source : str
        Where the rule comes from (seed and equation).
    one_of : tuple of tuple of str
        Groups of parameters of which exactly one must be given (e.g. Simpson's beta/gamma).
    """

    name: str
    build: Callable
    required: tuple = ()
    optional: dict = field(default_factory=dict)
    family: object = ""
    fixed_gain: bool = True
    kind: str = "gains"
    source: str = ""
    one_of: tuple = ()

    @property
    def allowed(self) -> tuple:
        groups = tuple(p for g in self.one_of for p in g)
        return self.required + groups + tuple(self.optional)

    def family_of(self, params: Mapping) -> str:
        return self.family(params) if callable(self.family) else self.family


def _order_suffix(params) -> str:
    return " α-β-γ" if int(params.get("order", 2)) == 3 else " α-β"


def _standard_theta(p, dt, n):
    order = design._check_order(p["order"])
    return design.standard_ab(p["theta"]) if order == 2 else design.standard_abg(p["theta"])


def _huang_family(p) -> str:
    kind = {"type1": "Huang type I", "type2": "Huang type II"}.get(p.get("type", "type1"), "Huang")
    return kind + _order_suffix(p)


RULES: dict[str, Rule] = {}


def register(rule: Rule) -> Rule:
    """Add ``rule`` to :data:`RULES` (a new name; replacing a rule is an error)."""
    if rule.name in RULES:
        raise AbglibValueError(f"rule {rule.name!r} is already registered")
    if rule.kind not in ("gains", "method"):
        raise AbglibValueError(f"rule kind must be 'gains' or 'method', got {rule.kind!r}")
    RULES[rule.name] = rule
    return rule


for _rule in (
    Rule(
        "standard_theta",
        _standard_theta,
        ("theta",),
        {"order": 2},
        lambda p: "standard (critically damped)" + _order_suffix(p),
        source="seed 000, eqs 22-24 and the alpha-beta pair after eq 30",
    ),
    Rule(
        "standard_alpha",
        lambda p, dt, n: design.standard_from_alpha(p["alpha"], p["order"]),
        ("alpha",),
        {"order": 2},
        lambda p: "standard (critically damped)" + _order_suffix(p),
        source="seed 000, eqs 22-24 inverted for theta",
    ),
    Rule(
        "qd_m",
        lambda p, dt, n: design.qd(p["m"]),
        ("m",),
        {},
        "QD α-β-γ",
        source="seed 000, eqs 28-30",
    ),
    Rule(
        "qd_alpha",
        lambda p, dt, n: design.qd(design.qd_m_from_alpha(p["alpha"])),
        ("alpha",),
        {},
        "QD α-β-γ",
        source="seed 000, eqs 28-30 (m solved for alpha)",
    ),
    Rule(
        "benedict_bordner",
        lambda p, dt, n: design.benedict_bordner(p["alpha"]),
        ("alpha",),
        {},
        "Benedict-Bordner α-β",
        source="seed 001, eq 23b (method M1)",
    ),
    Rule(
        "simpson",
        lambda p, dt, n: design.simpson(p["alpha"], beta=p.get("beta"), gamma=p.get("gamma")),
        ("alpha",),
        {},
        "Simpson α-β-γ",
        source="seed 000, eq 21",
        one_of=(("beta", "gamma"),),
    ),
    Rule(
        "kalata_ab",
        lambda p, dt, n: design.kalata_ab(p["tracking_index"]),
        ("tracking_index",),
        {},
        "Kalman (Kalata index) α-β",
        source="Kalata 1984",
    ),
    Rule(
        "kalata_abg",
        lambda p, dt, n: design.kalata_abg(p["tracking_index"]),
        ("tracking_index",),
        {},
        "Kalman (Kalata index) α-β-γ",
        source="Kalata 1984; Gray & Murray 1993",
    ),
    Rule(
        "huang_enbw",
        lambda p, dt, n: design.huang_for_enbw(p["bn_hz"], dt, rule=p["type"], order=p["order"]),
        ("bn_hz",),
        {"type": "type1", "order": 2},
        _huang_family,
        source="seed 002, type I / type II at an ENBW (eq 8)",
    ),
    Rule(
        "bendix",
        lambda p, dt, n: design.bendix(p["period_s"], table=p["table"]),
        ("period_s",),
        {"table": "memo"},
        "Bendix α-β",
        source="seed 003, Sinsky's memo table",
    ),
    Rule(
        "growing_memory",
        lambda p, dt, n: design.growing_memory(n, start=p["start"]),
        (),
        {"start": 1},
        "growing memory α-β",
        fixed_gain=False,
        source="seed 001, eqs 24a-b (method M2)",
    ),
    Rule(
        "steady_state_kalman",
        lambda p, dt, n: design.steady_state_kalman(
            p["q"], p["r"], dt=dt, order=p["order"], model=p["model"]
        ),
        ("q", "r"),
        {"order": 2, "model": "piecewise_constant"},
        lambda p: "Kalman (DARE)" + _order_suffix(p),
        source="steady-state discrete algebraic Riccati equation",
    ),
    Rule(
        "gains",
        lambda p, dt, n: Gains(p["alpha"], p["beta"], p["gamma"]),
        ("alpha", "beta"),
        {"gamma": 0.0},
        "explicit gains",
        source="given gains (canonical convention, seed 000 eqs 1-6)",
    ),
):
    register(_rule)


# --------------------------------------------------------------------------- checks
def variant_rule(spec: Mapping, name: str = "variant") -> tuple[Rule, dict]:
    """Check a variant entry; return its :class:`Rule` and the full parameters.

    Raises :class:`~abglib.AbglibValueError` naming the variant and, for an unknown rule,
    the known rules; for an unknown, missing or non-numeric parameter, the allowed ones.
    """
    if not isinstance(spec, Mapping):
        raise AbglibValueError(
            f"variant {name!r} must be a mapping {{rule: ..., <parameters>}}, got {spec!r}"
        )
    rule_name = spec.get("rule")
    if rule_name not in RULES:
        raise AbglibValueError(
            f"variant {name!r}: rule must be one of {', '.join(sorted(RULES))}, got {rule_name!r}"
        )
    rule = RULES[rule_name]
    params = {k: v for k, v in spec.items() if k not in META_KEYS}
    allowed = ", ".join(rule.allowed) or "(none)"
    unknown = sorted(set(params) - set(rule.allowed))
    if unknown:
        raise AbglibValueError(
            f"variant {name!r}: unknown parameter(s) {', '.join(unknown)} for rule "
            f"{rule_name!r}; allowed: {allowed}"
        )
    missing = [k for k in rule.required if k not in params]
    if missing:
        raise AbglibValueError(
            f"variant {name!r}: rule {rule_name!r} needs parameter(s) {', '.join(missing)}; "
            f"allowed: {allowed}"
        )
    for group in rule.one_of:
        given = [k for k in group if params.get(k) is not None]
        if len(given) != 1:
            raise AbglibValueError(
                f"variant {name!r}: rule {rule_name!r} needs exactly one of "
                f"{', '.join(group)}, got {given or 'none'}"
            )
    for k, v in params.items():
        if isinstance(rule.optional.get(k), str) and isinstance(v, str):
            continue
        if v is not None and (isinstance(v, bool) or not isinstance(v, numbers.Real)):
            raise AbglibValueError(
                f"variant {name!r}: parameter {k} of rule {rule_name!r} must be a number, got {v!r}"
            )
    full = dict(rule.optional)
    full.update(params)
    return rule, full


def variant_gains(spec: Mapping, dt: float, n_samples: int | None = None, name: str = "variant"):
    """Canonical gains of a variant for a scenario with sample interval ``dt``.

    Parameters
    ----------
    spec : mapping
        The config entry ``{rule: ..., <parameters>}``.
    dt : float
        Scenario sample interval ``T`` (s), > 0 (Huang's ENBW rule and the DARE need it).
    n_samples : int, optional
        Scenario length; needed by time-varying rules (``growing_memory``).
    name : str
        Variant name, for error messages.

    Returns
    -------
    Gains
        Scalars for fixed-gain rules, arrays ``(n_samples,)`` for time-varying ones.

    Raises
    ------
    AbglibValueError
        Unknown rule or parameter, missing parameter, a rule of kind ``"method"`` (use
        :func:`variant_runner`), or a parameter outside the design rule's domain (the
        message of the :mod:`abglib.design` function, prefixed with the variant's name).
    """
    rule, params = variant_rule(spec, name)
    if rule.kind != "gains":
        raise AbglibValueError(
            f"variant {name!r}: rule {rule.name!r} is an estimation method, not a gain design; "
            "use variant_runner"
        )
    if not rule.fixed_gain and n_samples is None:
        raise AbglibValueError(
            f"variant {name!r}: rule {rule.name!r} has time-varying gains and needs n_samples"
        )
    try:
        return rule.build(params, dt, n_samples)
    except AbglibValueError as exc:
        raise AbglibValueError(f"variant {name!r} (rule {rule.name!r}): {exc}") from None


def variant_runner(spec: Mapping, dt: float, n_samples: int, name: str = "variant"):
    """A callable ``run(z) -> result`` for a variant of kind ``"method"``."""
    rule, params = variant_rule(spec, name)
    if rule.kind != "method":
        raise AbglibValueError(f"variant {name!r}: rule {rule.name!r} is a gain design")
    try:
        return rule.build(params, dt, n_samples)
    except AbglibValueError as exc:
        raise AbglibValueError(f"variant {name!r} (rule {rule.name!r}): {exc}") from None


def variant_family(spec: Mapping, name: str = "variant") -> str:
    """Design family of a variant (e.g. ``'standard (critically damped) α-β'``)."""
    rule, params = variant_rule(spec, name)
    return rule.family_of(params)


# --------------------------------------------------------------------------- seed 001
def _linspace(p, prefix):
    return np.linspace(
        float(p[f"{prefix}_start"]), float(p[f"{prefix}_stop"]), int(p[f"{prefix}_n"])
    )


def _register_alwagih_methods() -> None:
    """Register methods M1-M5 of seed 001 (:mod:`abglib.methods`).

    Each runs on the whole batch of runs and returns the one-step predictions only
    (seed 001 scores ``x_pred``, eq 26); grids are ``<name>_start, _stop, _n``
    (:func:`numpy.linspace`); M5's ``causal`` is 0 (the paper's rule, which looks at the
    current measurement) or 1 (past innovations only, over ``memory`` steps).
    """
    from .. import methods as m

    fam = "Al-Wagih & Abdulla (seed 001)"
    for rule in (
        Rule(
            "alwagih_m1",
            lambda p, dt, n: lambda z: m.m1(z, p["alpha0"], dt),
            ("alpha0",),
            {},
            fam,
            False,
            "method",
            "seed 001, eqs 23a-b (M1)",
        ),
        Rule(
            "alwagih_m2",
            lambda p, dt, n: lambda z: m.m2(z, dt),
            (),
            {},
            fam,
            False,
            "method",
            "seed 001, eqs 24a-b (M2)",
        ),
        Rule(
            "alwagih_m3",
            lambda p, dt, n: lambda z: m.m3(z, _linspace(p, "w"), dt),
            (),
            {"w_start": 0.0, "w_stop": 1.0, "w_n": 21},
            fam,
            False,
            "method",
            "seed 001, eq 25, Algorithm 1 (M3)",
        ),
        Rule(
            "alwagih_m4",
            lambda p, dt, n: (
                lambda z: m.m4(z, p["alpha0"], int(p["window"]), _linspace(p, "grid"), dt)
            ),
            ("alpha0", "window"),
            {"grid_start": 0.05, "grid_stop": 1.0, "grid_n": 20},
            fam,
            False,
            "method",
            "seed 001, Algorithm 2 (M4)",
        ),
        Rule(
            "alwagih_m5",
            lambda p, dt, n: (
                lambda z: m.m5(
                    z, _linspace(p, "grid"), dt, causal=bool(p["causal"]), memory=int(p["memory"])
                )
            ),
            (),
            {"grid_start": 0.05, "grid_stop": 1.0, "grid_n": 20, "causal": 0, "memory": 1},
            fam,
            False,
            "method",
            "seed 001, Algorithm 3 (M5)",
        ),
    ):
        register(rule)


_register_alwagih_methods()
