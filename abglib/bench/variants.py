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
=================== =====================================================  ===================
rule                parameters (``[]`` optional, default)                  abglib.design
=================== =====================================================  ===================
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
=================== =====================================================  ===================

The methods of :mod:`abglib.methods` (seed 001, Al-Wagih & Abdulla) are
registered too, as rules of kind ``"method"`` scored on their one-step predictions:
``alwagih_m1`` (alpha0), ``alwagih_m2``, ``alwagih_m3`` ([w_start, w_stop, w_n]),
``alwagih_m4`` (alpha0, window, [grid_start, grid_stop, grid_n]), ``alwagih_m5``
([grid_start, grid_stop, grid_n], [causal=0], [memory=1]).

A user's own tracker
--------------------
A variant may name a Python callable of the user's own instead of a rule::

    my_ab:    {callable: "my_trackers.py:my_gains", alpha: 0.4}       # a file
    my_filt:  {callable: "mypackage.trackers:my_filter", q: 0.1,     # an importable module
               family: "my filters"}

``callable`` is ``<file>.py:<function>`` (a relative path is taken from the repository,
``base`` of :func:`resolve_callable`) or ``<module>:<function>`` (importable). Every other
key except ``label`` and ``family`` (the league's design family; default
``"user: <function>"``) is passed to the function as a keyword argument. Its signature::

    def my_variant(dt: float, n_samples: int, **params):
        # return abglib.Gains (or a tuple (alpha, beta[, gamma]), canonical convention:
        #   scalars = a fixed-gain tracker, arrays (n_samples,) = time-varying gains),
        #   run by abglib.track and scored like the built-in rules (fixed gains are
        #   checked against the exact VRF on white noise);
        # or return a function run(z) -> result, z the measurements (runs, n_samples),
        #   result an object or mapping with x_pred (runs, n_samples) and, if the
        #   tracker has them, x_smooth and v_smooth (and a_smooth): the one-step
        #   prediction of z[:, k] made before it, the estimates after it.

:func:`check_variant` calls it once per scenario when the workflow is parsed (and runs a
returned tracker on zeros), so a missing module or file, a missing function, an exception
or a wrong return stops the build with a message naming the variant.
"""

from __future__ import annotations

import importlib
import importlib.util
import numbers
import sys
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from types import SimpleNamespace

import numpy as np

from .. import design
from .._checks import AbglibValueError
from ..gains import Gains

__all__ = [
    "CURVE_DESIGNS",
    "RULES",
    "Rule",
    "callable_file",
    "check_variant",
    "describe_variant",
    "gains_from_spec",
    "register",
    "resolve_callable",
    "variant_build",
    "variant_family",
    "variant_gains",
    "variant_rule",
    "variant_runner",
]

#: Keys of a variant entry that are not rule parameters.
META_KEYS = ("rule", "label")

#: Keys of a user's variant entry (``callable:``) that are not passed to the callable.
USER_KEYS = ("callable", "label", "family")


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


#: Every gain-design rule a variant can name, by name (filled by :func:`register` below).
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
    if "callable" in spec:
        return _user_rule(spec, name)
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
    if rule.kind == "user":
        built = variant_build(spec, dt, n_samples, name)
        if isinstance(built, Gains):
            return built
        raise AbglibValueError(
            f"variant {name!r}: {spec['callable']} returns a tracker, not gains; use variant_runner"
        )
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


#: Gain designs a config curve may name (seed 000: eqs 22-24, the alpha-beta analogue, 28-30).
CURVE_DESIGNS = ("standard_abg", "standard_ab", "qd")


def gains_from_spec(spec: Mapping) -> Gains:
    """Gains of a config curve ``{design, alpha | m, ...}``.

    ``standard_abg``: critically damped alpha-beta-gamma (seed 000, eqs 22-24) with the
    given alpha; ``standard_ab``: critically damped alpha-beta (seed 000, p. 5);
    ``qd``: QD tracker (seed 000, eqs 28-30) with memory ``m``, or the ``m`` that gives
    the stated alpha.
    """
    kind = spec.get("design")
    if kind not in CURVE_DESIGNS:
        raise AbglibValueError(f"design must be one of {list(CURVE_DESIGNS)}, got {kind!r}")
    # one dispatch from names to design rules: the variant registry's
    if kind == "qd":
        variant = (
            {"rule": "qd_m", "m": spec["m"]}
            if "m" in spec
            else {"rule": "qd_alpha", "alpha": spec["alpha"]}
        )
    else:
        order = 3 if kind == "standard_abg" else 2
        variant = {"rule": "standard_alpha", "alpha": spec["alpha"], "order": order}
    return variant_gains(variant, dt=1.0, name=f"curve {kind}")


def variant_runner(spec: Mapping, dt: float, n_samples: int, name: str = "variant"):
    """A callable ``run(z) -> result`` for a variant of kind ``"method"``."""
    rule, params = variant_rule(spec, name)
    if rule.kind == "user":
        built = variant_build(spec, dt, n_samples, name)
        if not isinstance(built, Gains):
            return built
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


def variant_build(spec: Mapping, dt: float, n_samples: int | None = None, name: str = "variant"):
    """What a variant runs on a scenario: :class:`~abglib.Gains` (run by the engine) or a
    function ``run(z) -> result`` (an estimation method or a user's own tracker)."""
    rule, params = variant_rule(spec, name)
    if rule.kind == "gains":
        return variant_gains(spec, dt, n_samples, name)
    if rule.kind == "method":
        return variant_runner(spec, dt, n_samples, name)
    return _user_build(spec, dt, n_samples, name)


# --------------------------------------------------------------------------- user code
_LOADED: dict = {}


def resolve_callable(spec: Mapping, base=None) -> dict:
    """``spec`` with a ``callable: <file>.py:<function>`` made absolute (a relative file is
    taken from ``base``, the repository); other entries are returned unchanged."""
    target = spec.get("callable") if isinstance(spec, Mapping) else None
    if not isinstance(target, str) or ":" not in target:
        return dict(spec) if isinstance(spec, Mapping) else spec
    where, _, func = target.rpartition(":")
    if not _is_file_target(where):
        return dict(spec)
    path = Path(where).expanduser()
    if not path.is_absolute() and base is not None:
        path = Path(base) / path
    return {**spec, "callable": f"{path.resolve()}:{func}"}


def callable_file(spec: Mapping) -> Path | None:
    """The source file of a user's variant (for its cells' code hash): the file of
    ``<file>.py:<function>``, or the module's file of ``<module>:<function>`` (found
    without importing the module itself); None for a built-in rule."""
    target = spec.get("callable") if isinstance(spec, Mapping) else None
    if not isinstance(target, str) or ":" not in target:
        return None
    where = target.rpartition(":")[0]
    if _is_file_target(where):
        return Path(where)
    try:
        found = importlib.util.find_spec(where)
    except (ImportError, ValueError):
        found = None
    if found is None or not found.origin or not found.has_location:
        return None
    return Path(found.origin)


def _is_file_target(where: str) -> bool:
    return where.endswith(".py") or "/" in where or "\\" in where


def _load_callable(target, name: str) -> Callable:
    if not isinstance(target, str) or ":" not in target:
        raise AbglibValueError(
            f"variant {name!r}: callable must be '<module>:<function>' or "
            f"'<file>.py:<function>', got {target!r}"
        )
    where, _, func = target.rpartition(":")
    if not where or not func.isidentifier():
        raise AbglibValueError(
            f"variant {name!r}: callable must be '<module>:<function>' or "
            f"'<file>.py:<function>', got {target!r}"
        )
    if _is_file_target(where):
        path = Path(where)
        if not path.is_file():
            raise AbglibValueError(
                f"variant {name!r}: callable {target!r}: no such file {str(path)!r} "
                "(a relative path is taken from the repository)"
            )
        key = (str(path.resolve()), path.stat().st_mtime_ns)
        module = _LOADED.get(key)
        if module is None:
            mod_name = f"abglib_user_variant_{abs(hash(key[0])):x}"
            loader_spec = importlib.util.spec_from_file_location(mod_name, path)
            module = importlib.util.module_from_spec(loader_spec)
            try:
                loader_spec.loader.exec_module(module)
            except Exception as exc:
                raise AbglibValueError(
                    f"variant {name!r}: importing {str(path)!r} failed: {type(exc).__name__}: {exc}"
                ) from exc
            sys.modules.setdefault(mod_name, module)
            _LOADED[key] = module
    else:
        try:
            module = importlib.import_module(where)
        except ModuleNotFoundError as exc:
            raise AbglibValueError(
                f"variant {name!r}: callable {target!r}: module {where!r} not found ({exc}); "
                "give an importable module or a file path '<file>.py:<function>'"
            ) from None
    fn = getattr(module, func, None)
    if not callable(fn):
        known = sorted(k for k, v in vars(module).items() if callable(v) and not k.startswith("_"))
        raise AbglibValueError(
            f"variant {name!r}: callable {target!r}: {where!r} has no function {func!r}; "
            f"it defines: {', '.join(known) or '(no public functions)'}"
        )
    return fn


def _user_rule(spec: Mapping, name: str) -> tuple[Rule, dict]:
    target = spec["callable"]
    if "rule" in spec:
        raise AbglibValueError(
            f"variant {name!r}: give either rule: or callable:, not both (got {spec['rule']!r} "
            f"and {target!r})"
        )
    fn = _load_callable(target, name)
    params = {k: v for k, v in spec.items() if k not in USER_KEYS}
    rule = Rule(
        "callable",
        lambda p, dt, n: fn(dt, n, **p),
        (),
        {},
        _user_family(spec),
        fixed_gain=None,
        kind="user",
        source=str(target),
    )
    return rule, params


def _user_family(spec: Mapping) -> str:
    return str(spec.get("family") or f"user: {str(spec['callable']).rpartition(':')[2]}")


def describe_variant(spec: Mapping, name: str = "variant") -> dict:
    """One row of the variants table: ``rule, family, fixed_gain, source, parameters``
    (a user's variant is described from its entry, without loading its code: ``rule`` is
    ``callable``, ``source`` the entry's ``callable`` as written in the config)."""
    if isinstance(spec, Mapping) and "callable" in spec:
        params = {k: v for k, v in spec.items() if k not in USER_KEYS}
        rule_name, family, fixed, source = "callable", _user_family(spec), None, spec["callable"]
    else:
        rule, params = variant_rule(spec, name)
        rule_name, family, fixed, source = (
            rule.name,
            rule.family_of(params),
            rule.fixed_gain,
            rule.source,
        )
    return {
        "variant": name,
        "rule": rule_name,
        "family": family,
        "fixed_gain": fixed,
        "source": source,
        "parameters": ", ".join(f"{k}={v}" for k, v in sorted(params.items())),
    }


def _user_build(spec: Mapping, dt: float, n_samples, name: str):
    rule, params = _user_rule(spec, name)
    target = spec["callable"]
    try:
        out = rule.build(params, float(dt), None if n_samples is None else int(n_samples))
    except AbglibValueError as exc:
        raise AbglibValueError(f"variant {name!r} ({target}): {exc}") from None
    except Exception as exc:
        raise AbglibValueError(
            f"variant {name!r}: {target}(dt={dt}, n_samples={n_samples}, "
            f"{', '.join(f'{k}={v!r}' for k, v in params.items())}) raised "
            f"{type(exc).__name__}: {exc}"
        ) from exc
    if isinstance(out, Gains):
        return out
    if isinstance(out, tuple) and len(out) in (2, 3):
        try:
            return Gains(*out)
        except (AbglibValueError, TypeError) as exc:
            raise AbglibValueError(
                f"variant {name!r}: {target} returned the tuple {out!r}, which is not "
                f"(alpha, beta[, gamma]): {exc}"
            ) from None
    if callable(out):
        return _checked_runner(out, name, target)
    raise AbglibValueError(
        f"variant {name!r}: {target} must return abglib.Gains, a tuple (alpha, beta[, gamma]) "
        f"or a function run(z) -> result with x_pred; got {type(out).__name__}"
    )


def _checked_runner(run: Callable, name: str, target: str) -> Callable:
    def checked(z):
        try:
            res = run(z)
        except Exception as exc:
            raise AbglibValueError(
                f"variant {name!r}: the tracker of {target} raised {type(exc).__name__}: {exc}"
            ) from exc
        if isinstance(res, Mapping):
            res = SimpleNamespace(**res)
        shape = np.shape(z)
        for out in ("x_pred", "x_smooth", "v_smooth", "a_smooth"):
            val = getattr(res, out, None)
            if val is None:
                if out == "x_pred":
                    raise AbglibValueError(
                        f"variant {name!r}: the tracker of {target} must return x_pred "
                        f"(an object or mapping with x_pred, x_smooth, v_smooth), got "
                        f"{type(res).__name__}"
                    )
                continue
            if np.shape(val) != shape:
                raise AbglibValueError(
                    f"variant {name!r}: the tracker of {target} returned {out} of shape "
                    f"{np.shape(val)}, expected the measurements' shape {shape}"
                )
        return res

    return checked


def check_variant(spec: Mapping, dt: float, n_samples: int, name: str = "variant") -> None:
    """Raise :class:`~abglib.AbglibValueError` if the variant cannot run on a scenario of
    interval ``dt`` and length ``n_samples``: a bad rule or parameter, a design rule
    outside its domain, or a user's callable that cannot be loaded, raises, or returns
    something else than gains or a tracker (a returned tracker is run on zeros)."""
    built = variant_build(spec, dt, n_samples, name)
    if variant_rule(spec, name)[0].kind == "user" and not isinstance(built, Gains):
        built(np.zeros((2, int(n_samples))))


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
