"""One claim model for every source document.

A *claim* is one published number or statement of a source document. Its printed side
(``item``, ``quantity``, ``published``, ``where``) is transcribed once in
``data/published/<doc>/*.csv``; its computing side is one declaration in
``abglib/replications/<doc>/claims.py``::

    CLAIMS = ClaimSet("huang")

    @CLAIMS.claim("fig5.overranged", depends_on=("huang.gate_fraction_of_pulse",))
    def _(s: Study) -> Result:
        return Result(s.lag_111 > s.gate_m, f"111.1 m against a {s.gate_m:.1f} m gate")

    @CLAIMS.family(r"t[12]\\.(ab|abg)\\.\\d+hz\\.enbw")   # one function, many printed keys
    def _(s: Study, key: str) -> Result: ...

A claim's function takes the document's *study* (a lazily computed object built from the
configuration; :class:`Study`) and returns a :class:`Result`: the reproduced value (a
number, a bool for a qualitative claim, ``None`` when not reproducible), a note, and
any alternative readings (:class:`Reading`) that may explain a non-match.

Verdicts that hinge on assumed inputs
-------------------------------------
``depends_on`` names the reconstructed or assumed inputs the value depends on, as dotted
config paths (``antenna.model.beta_a``). Each such input has a *plausible range* in the
document's config section (``<doc>.plausible.<dotted path>``: ``values: [...]`` or
``low, high, n`` with ``scale: linear|log``, and its ``basis`` in the text).
:func:`evaluate` recomputes the claim one input at a time over that range (the others at
their nominal values), at the points of the document's joint design over those inputs
(corners, or a Latin hypercube when a row has many), and, when the claim's result moves
with the random seeds (a Monte Carlo result), under every seed set and under
``robustness.joint_seed_sets`` seed sets at each joint point
(:mod:`abglib.verdicts.robustness`), and judges each point with the same tolerance. The
same verdict everywhere gives that verdict with ``robust=true``; a flip gives
``not_reproducible``, ``robust=false`` and a note saying where each verdict holds
(``shared/CONTRACTS.md`` section 3). A Monte Carlo row's ``depends_on`` ends in
``seeds``.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import numpy as np
import pandas as pd

from .._checks import AbglibValueError
from ..verdicts import Alternative, Reading, format_number, robustness
from ..verdicts._judge import _assess, judge_sentences
from ..verdicts.robustness import ROBUSTNESS_COLUMNS, config_get, with_values
from .compare import COMPARISON_COLUMNS, SENTENCE_COLUMN

__all__ = [
    "ROBUSTNESS_COLUMNS",
    "Claim",
    "ClaimSet",
    "PlausibleRange",
    "Reading",
    "Result",
    "Study",
    "config_get",
    "config_with",
    "evaluate",
    "plausible_ranges",
]


# --------------------------------------------------------------------------- results
@dataclass(frozen=True)
class Result:
    """What a claim's function returns.

    Attributes
    ----------
    value : float, bool or None
        The reproduced number; for a qualitative claim (empty ``published``) whether the
        check holds; ``None`` when not reproducible (then ``note`` says why).
    note : str
        The evidence, in words, with the numbers behind the value.
    readings : sequence of Reading
        Alternative readings of the printed number (for ``explained``), each with its
        ``family`` label (:class:`abglib.verdicts.Reading`).
    related : mapping
        Related quantities for the claim-specific reading families of
        :mod:`abglib.verdicts.readings` (``values``, ``neighbours``, ``dt``, ``inputs``).
    bound : {"", ">", "<"}
        ``">"`` (``"<"``) when ``value`` is only a bound the quantity lies above (below),
        e.g. a stability edge past the end of the grid searched: judged without readings
        (:func:`abglib.verdicts.judge`'s ``bound``).
    """

    value: Any
    note: str = ""
    readings: Sequence[Reading] = ()
    related: Mapping[str, Any] = field(default_factory=dict)
    bound: str = ""


# --------------------------------------------------------------------------- claims
@dataclass(frozen=True)
class Claim:
    """The computing side of one published claim (or of a family of them).

    ``pattern`` is the published key, or a regular expression that matches every key of
    the family (:meth:`ClaimSet.family`); ``compute(study)`` (or ``compute(study, key)``
    for a family) returns a :class:`Result`; ``depends_on`` lists the assumed inputs
    (dotted config paths), or is a function of the key that returns them.
    """

    pattern: str
    compute: Callable[..., Result]
    depends_on: tuple[str, ...] | Callable[[str], Iterable[str]] = ()
    is_family: bool = False

    def matches(self, key: str) -> bool:
        if self.is_family:
            return re.fullmatch(self.pattern, key) is not None
        return key == self.pattern

    def inputs(self, key: str) -> tuple[str, ...]:
        dep = self.depends_on(key) if callable(self.depends_on) else self.depends_on
        return tuple(dict.fromkeys(dep))

    def run(self, study, key: str) -> Result:
        out = self.compute(study, key) if self.is_family else self.compute(study)
        if not isinstance(out, Result):
            raise AbglibValueError(
                f"claim {key!r} must return an abglib.replications.Result, got {type(out).__name__}"
            )
        return out


class ClaimSet:
    """The claims of one document, declared with :meth:`claim` and :meth:`family`."""

    def __init__(self, doc: str):
        self.doc = doc
        self._claims: list[Claim] = []

    def claim(self, key: str, *, depends_on=()):
        """Decorator: ``fn(study) -> Result`` computes the published key ``key``."""

        def deco(fn):
            if any(c.pattern == key and not c.is_family for c in self._claims):
                raise AbglibValueError(f"{self.doc}: claim {key!r} is declared twice")
            self._claims.append(Claim(key, fn, _deps(depends_on), False))
            return fn

        return deco

    def family(self, pattern: str, *, depends_on=()):
        """Decorator: ``fn(study, key) -> Result`` computes every key matching ``pattern``."""
        re.compile(pattern)

        def deco(fn):
            self._claims.append(Claim(pattern, fn, _deps(depends_on), True))
            return fn

        return deco

    def __iter__(self):
        return iter(self._claims)

    def __len__(self) -> int:
        return len(self._claims)

    def resolve(self, keys: Iterable[str]) -> dict[str, Claim]:
        """The claim of every published key; each key must have exactly one, and each
        declaration must match at least one key (a claim with no printed row is a bug).

        Raises
        ------
        AbglibValueError
            Naming the keys without a claim, with several, and the unused declarations.
        """
        keys = list(keys)
        found: dict[str, Claim] = {}
        none, many = [], []
        for k in keys:
            hits = [c for c in self._claims if c.matches(k)]
            if not hits:
                none.append(k)
            elif len(hits) > 1:
                many.append(k)
            else:
                found[k] = hits[0]
        unused = [c.pattern for c in self._claims if not any(c.matches(k) for k in keys)]
        if none or many or unused:
            raise AbglibValueError(
                f"{self.doc}: every published key needs exactly one claim; "
                f"without a claim: {none}; with several: {many}; "
                f"declarations matching no published key: {unused}"
            )
        return found

    def compute(self, study, key: str) -> Result:
        """The :class:`Result` of one published key on ``study`` (for unit tests)."""
        hits = [c for c in self._claims if c.matches(key)]
        if len(hits) != 1:
            raise AbglibValueError(
                f"{self.doc}: key {key!r} must match exactly one claim, got {len(hits)}"
            )
        return hits[0].run(study, key)

    def depends_on(self, key: str) -> tuple[str, ...]:
        """The assumed inputs of one published key."""
        hits = [c for c in self._claims if c.matches(key)]
        if len(hits) != 1:
            raise AbglibValueError(
                f"{self.doc}: key {key!r} must match exactly one claim, got {len(hits)}"
            )
        return hits[0].inputs(key)


def _deps(depends_on):
    if callable(depends_on):
        return depends_on
    if isinstance(depends_on, str):
        return (depends_on,)
    return tuple(depends_on)


# --------------------------------------------------------------------------- studies
class Study:
    """Base of a document's study: the configuration and the published table.

    A subclass computes what its claims and report tables need in
    :func:`functools.cached_property` members, so that a claim recomputed at another
    value of an assumed input (:func:`evaluate`) pays only for what it uses.
    ``config`` holds the document's section under its key (``config[doc]``) and any other
    top-level section the study reads (e.g. ``datasets``).
    """

    doc: str = ""

    def __init__(self, config: Mapping, published: pd.DataFrame):
        self.config = config
        self.published = published

    @property
    def cfg(self) -> Mapping:
        """The document's own config section."""
        return self.config[self.doc]

    @cached_property
    def _printed_by_key(self) -> dict:
        # claims ask for thousands of keys: the published table indexed once per study
        return dict(zip(self.published["key"], self.published["published"], strict=True))

    def printed(self, key: str) -> str:
        """The printed string of one published key."""
        pub = self._printed_by_key
        if key not in pub:
            raise AbglibValueError(f"{self.doc}: no published key {key!r}")
        return pub[key]

    def tables(self) -> dict[str, pd.DataFrame]:
        """The report tables of the study, by file stem (``results/<doc>/<stem>.csv``)."""
        return {}


# --------------------------------------------------------------------------- ranges
def config_with(config: Mapping, path: str, value) -> dict:
    """A deep copy of ``config`` with the dotted ``path`` set to ``value``
    (:func:`abglib.verdicts.robustness.with_values` of one path)."""
    return with_values(config, {path: value})


@dataclass(frozen=True)
class PlausibleRange:
    """The plausible values of one assumed input and why (its basis in the text)."""

    name: str
    nominal: Any
    values: tuple
    basis: str
    low: Any = None
    high: Any = None
    numeric: bool = field(default=True)

    def describe(self) -> str:
        if self.numeric and self.low is not None:
            return _span(self.low, self.high)
        return ", ".join(_fmt(v) for v in self.values)


def plausible_ranges(config: Mapping, doc: str) -> dict[str, PlausibleRange]:
    """The plausible ranges declared in ``config[doc]['plausible']``.

    Each entry is keyed by a dotted config path and gives either ``values: [...]`` or
    ``low``, ``high`` and ``n`` (``scale: linear`` or ``log``), and ``basis`` (where the
    text leaves the value open and why this range). The nominal value (the one the path
    holds) is always one of the grid's points.

    Raises
    ------
    AbglibValueError
        A path the config lacks, a missing basis, an empty or inverted range, or a
        nominal value outside it.
    """
    specs = config.get(doc, {}).get("plausible", {}) or {}
    out = {}
    for name, spec in specs.items():
        nominal = config_get(config, name)
        basis = str(spec.get("basis", "")).strip()
        if not basis:
            raise AbglibValueError(f"{doc}.plausible.{name}: give the basis in the text")
        if "values" in spec:
            values = list(spec["values"])
            if not values:
                raise AbglibValueError(f"{doc}.plausible.{name}: values must not be empty")
            numeric = all(_is_number(v) for v in [*values, nominal])
            if nominal not in values:
                values.append(nominal)
            if numeric:
                values = sorted(set(values))
            lo = min(values) if numeric else None
            hi = max(values) if numeric else None
        else:
            try:
                lo, hi, n = float(spec["low"]), float(spec["high"]), int(spec["n"])
            except KeyError as exc:
                raise AbglibValueError(
                    f"{doc}.plausible.{name}: give values: [...] or low, high and n "
                    f"(missing {exc.args[0]!r})"
                ) from None
            scale = spec.get("scale", "linear")
            if not (lo < hi) or n < 2:
                raise AbglibValueError(
                    f"{doc}.plausible.{name}: need low < high and n >= 2, got "
                    f"low={lo}, high={hi}, n={n}"
                )
            if scale == "log":
                if lo <= 0:
                    raise AbglibValueError(
                        f"{doc}.plausible.{name}: a log range needs low > 0, got {lo}"
                    )
                grid = np.geomspace(lo, hi, n)
            elif scale == "linear":
                grid = np.linspace(lo, hi, n)
            else:
                raise AbglibValueError(
                    f"{doc}.plausible.{name}: scale must be 'linear' or 'log', got {scale!r}"
                )
            if not _is_number(nominal) or not (lo <= float(nominal) <= hi):
                raise AbglibValueError(
                    f"{doc}.plausible.{name}: the nominal value {nominal!r} must lie in "
                    f"[{lo}, {hi}]"
                )
            as_int = isinstance(nominal, int) and not isinstance(nominal, bool)
            grid = [int(round(v)) if as_int else float(v) for v in grid]
            values = sorted(set(grid) | {nominal})
            numeric = True
        if len(values) < 2:
            raise AbglibValueError(
                f"{doc}.plausible.{name}: a range needs a value besides the nominal "
                f"{nominal!r}, got {list(values)}"
            )
        out[name] = PlausibleRange(name, nominal, tuple(values), basis, lo, hi, numeric)
    return out


def _is_number(v) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _fmt(v) -> str:
    return format_number(v, 4) if _is_number(v) else str(v)


def _span(a, b) -> str:
    """``'0.01-0.1'``, or ``'-74.9 to 30'`` where an end is negative (``'-74.9-30'`` would
    read as a difference, ``'-74.9--30'`` worse)."""
    neg = any(_is_number(v) and float(v) < 0 for v in (a, b))
    return f"{_fmt(a)} to {_fmt(b)}" if neg else f"{_fmt(a)}-{_fmt(b)}"


# --------------------------------------------------------------------------- evaluation
def evaluate(
    doc: str,
    claims: ClaimSet,
    published: pd.DataFrame,
    study,
    make_study: Callable[[Mapping], Any],
    overrides: Mapping[str, Mapping] | None = None,
) -> tuple[pd.DataFrame, pd.DataFrame]:
    """Judge every published claim of one document, and its robustness.

    Parameters
    ----------
    doc : str
        Document key.
    claims : ClaimSet
        The document's declarations.
    published : DataFrame
        From :func:`abglib.replications.compare.read_published`.
    study
        The study at the nominal configuration (``study.config``).
    make_study : callable
        ``make_study(config)`` builds the study at another configuration (used to
        recompute claims at the points of the robustness designs: one input at a time,
        jointly, and under the seed sets; one study per point, shared by every row).
    overrides : mapping, optional
        ``{key: {"tolerance": float, "reason": str}}`` (``config.yaml``
        ``tolerance_overrides``).

    Returns
    -------
    (comparison, robustness)
        ``comparison.csv`` rows (:data:`~abglib.replications.compare.COMPARISON_COLUMNS`) and
        every judged point of every robustness design (:data:`ROBUSTNESS_COLUMNS`).

    Notes
    -----
    The designs' sizes come from ``study.config['robustness']``
    (:func:`abglib.verdicts.robustness.settings`); see that module for the corner,
    hypercube and seed-shift rules.
    """
    overrides = dict(overrides or {})
    resolved = claims.resolve(published["key"])
    unknown = sorted(set(overrides) - set(resolved))
    if unknown:
        raise AbglibValueError(f"{doc}: tolerance override for unknown keys {unknown}")
    ranges = plausible_ranges(study.config, doc)
    needed = {i for k, c in resolved.items() for i in c.inputs(k)}
    undeclared = sorted(needed - set(ranges))
    if undeclared:
        raise AbglibValueError(
            f"{doc}: claims depend on inputs without a plausible range in "
            f"config['{doc}']['plausible']: {undeclared}"
        )
    design = robustness.settings(study.config)
    joint = robustness.joint_design(ranges, [c.inputs(k) for k, c in resolved.items()], design)
    seeded = robustness.seed_sets(study.config, doc, design)
    oat_sets, joint_sets = robustness.point_seed_sets(ranges, joint, len(seeded))
    # every point of the document's designs numbered (0 the nominal inputs), for the seed
    # sets of the extra draws under chance (robustness.extra_draws)
    oat_ids = {key: 1 + i for i, key in enumerate(oat_sets)}
    n_points = 1 + len(oat_sets) + len(joint)
    studies: dict[tuple, Any] = {}

    def at(values: Mapping[str, Any], k: int):
        # one study per point off the nominal one (with its seed set k), shared by every
        # row and design
        key = tuple(sorted((n, _hashable(v)) for n, v in values.items()))
        if not key:
            return study
        if (key, k) not in studies:
            studies[key, k] = make_study(robustness.with_values(config_of_set(k), values))
        return studies[key, k]

    def config_of_set(k: int):
        # the configured seeds (0), a seed set of the design, or an extra one drawn for a
        # row undecided under chance
        if k == 0:
            return study.config
        if k <= len(seeded):
            return seeded[k - 1]
        return robustness.seed_set(study.config, doc, k, design)

    seed_studies: dict[int, Any] = {}

    def under(k: int):
        if k not in seed_studies:
            seed_studies[k] = make_study(config_of_set(k))
        return seed_studies[k]

    def judge_chance(nominal_verdict, draws, mixture, by_set, pub, claim, point):
        # the row's verdict under chance (abglib.verdicts.robustness.chance_judgement);
        # while undecided, one more draw at a time over the row's mixture of points (its
        # nominal inputs, then each design point that is not a flip, in turn) with seed
        # sets beyond the design's (robustness.extra_draws), each study shared by every
        # row drawn at the same point and set
        lucky = robustness.chance_judgement(
            nominal_verdict, draws, design.chance_tolerance, design.chance_confidence
        )
        j = 0
        ids = [m[0] for m in mixture]
        while lucky.state == "undecided" and len(draws) < design.chance_draws:
            ((i, k),) = robustness.extra_draws(ids, n_points, len(seeded), 1, start=j)
            j += 1
            if i == 0:
                v, rep = judged_at(under(k), pub, claim)[1:]
                point("seed_set", "seeds", str(k), k, False, rep, v)
                by_set.append((v, rep, k))
            else:
                _, design_name, names, shown, values = mixture[i]
                v, rep = judged_at(at(values, k), pub, claim)[1:]
                point(design_name, names, shown, k, False, rep, v)
            draws.append(v)
            lucky = robustness.chance_judgement(
                nominal_verdict, draws, design.chance_tolerance, design.chance_confidence
            )
        return lucky

    def judged_at(other_study, pub, claim):
        r = claim.run(other_study, pub.key)
        other = _judged(doc, pub, r, overrides).row
        return r, other["verdict"], other["reproduced"]

    rows, points, judged = [], [], []
    for pub in published.itertuples(index=False):
        claim = resolved[pub.key]
        first_point = len(points)
        res = claim.run(study, pub.key)
        judged.append(_judged(doc, pub, res, overrides))
        row = judged[-1].row
        vague = row.pop("robust", "")
        inputs = claim.inputs(pub.key)
        row["depends_on"] = ";".join((*inputs, *row.pop("vague", ())))
        row["robust"] = vague
        nominal_verdict = row["verdict"]

        def point(design_name, inp, value, k, nominal, rep, v, key=pub.key):
            points.append(
                {
                    "key": key,
                    "design": design_name,
                    "input": inp,
                    "value": value,
                    "seed_set": k,
                    "nominal": nominal,
                    "reproduced": rep,
                    "verdict": v,
                }
            )

        # a row whose result moves under seed set 1 rests on a Monte Carlo result
        chance = False
        if seeded:
            r1, v1, rep1 = judged_at(under(1), pub, claim)
            chance = robustness.rests_on_chance(res, r1)
        confirm = design.confirm_draws if chance else 1
        scheduled_draws = [nominal_verdict]  # the draws the share under chance counts
        # the points those draws come from, each with its number among the document's
        # points (0 the nominal inputs) and how to draw there: the nominal inputs, then
        # every design point that is not a flip, where judge_chance's extra draws go in turn
        mixture: list = [(0,)]

        def draws_at(
            design_name,
            names,
            shown,
            values,
            k0,
            per_point,
            pid,
            *,
            pub=pub,
            claim=claim,
            chance=chance,
            nominal_verdict=nominal_verdict,
            confirm=confirm,
            scheduled_draws=scheduled_draws,
            mixture=mixture,
        ):
            # the scheduled draws of one design point and, for a Monte Carlo row whose
            # draws there contradict its nominal verdict, the confirmation draws
            # (abglib.verdicts.robustness.point_verdict); returns the point's verdict
            ks = robustness.draws_of_point(k0, len(seeded), per_point)
            got = [judged_at(at(values, k), pub, claim)[1:] for k in ks]
            if chance and any(v != nominal_verdict for v, _ in got):
                extra = robustness.confirmation_draws(k0, len(seeded), len(ks), confirm)
                ks += extra
                got += [judged_at(at(values, k), pub, claim)[1:] for k in extra]
            for k, (v, rep) in zip(ks, got, strict=True):
                point(design_name, names, shown, k, False, rep, v)
            verdict = robustness.point_verdict(nominal_verdict, [v for v, _ in got], confirm)
            if verdict == nominal_verdict:
                scheduled_draws.extend(v for v, _ in got[:per_point])
                mixture.append((pid, design_name, names, shown, values))
            return verdict

        # one at a time: each input over its grid, the others nominal
        flips = []
        for name in inputs:
            rng = ranges[name]
            by_value = []
            for value in rng.values:
                if _same(value, rng.nominal):
                    point(
                        "one_at_a_time",
                        name,
                        _fmt(value),
                        0,
                        True,
                        row["reproduced"],
                        nominal_verdict,
                    )
                    by_value.append((value, nominal_verdict))
                    continue
                at_key = (name, _hashable(value))
                v = draws_at(
                    "one_at_a_time",
                    name,
                    _fmt(value),
                    {name: value},
                    oat_sets[at_key],
                    1,
                    oat_ids[at_key],
                )
                by_value.append((value, v))
            if len({v for _, v in by_value}) > 1:
                flips.append(_describe_flip(rng, by_value))
        # jointly: the document's design, projected onto the row's inputs; a Monte Carlo
        # row under design.joint_seed_sets seed sets at each point (the point's own set
        # and the next ones in turn), any other row under the point's own
        per_point = design.joint_seed_sets if chance else 1
        by_point, seen = [], set()
        for i, (p, k0) in enumerate(zip(joint, joint_sets, strict=True)):
            proj = robustness.project(p, inputs)
            key = tuple((n, _hashable(v)) for n, v in proj)
            if len(proj) < 2 or key in seen:
                continue
            seen.add(key)
            names = ";".join(n for n, _ in proj)
            shown = ";".join(_fmt(x) for _, x in proj)
            pid = 1 + len(oat_sets) + i
            v = draws_at("joint", names, shown, p.values, k0, per_point, pid)
            by_point.append((proj, v))
        # seed sets: a Monte Carlo row under every set at its nominal inputs, as
        # (verdict, reproduced, set)
        by_set = []
        if chance:
            by_set = [(nominal_verdict, row["reproduced"], 0), (v1, rep1, 1)]
            by_set += [(*judged_at(under(k), pub, claim)[1:], k) for k in range(2, len(seeded) + 1)]
            for v, rep, k in by_set:
                point("seed_set", "seeds", str(k), k, k == 0, rep, v)
            scheduled_draws.extend(v for v, _, _ in by_set[1:])
            row["depends_on"] = ";".join(x for x in (row["depends_on"], "seeds") if x)
        if inputs or by_set:
            parts = []
            causes = []
            drawn = ", each point under its own seed set" if seeded else ""
            if flips:
                parts.append(f"one at a time (others nominal{drawn}): {'; '.join(flips)}")
            if any(e[1] != nominal_verdict for e in by_point):
                parts.append(robustness.describe_joint(by_point, drawn=drawn))
            if parts:
                causes.append("inputs the document does not give")
            lucky = None
            if chance:
                lucky = judge_chance(
                    nominal_verdict, scheduled_draws, mixture, by_set, pub, claim, point
                )
                if not lucky.robust:
                    parts.append(
                        f"under chance it {lucky.describe()}; "
                        + robustness.describe_seed_sets(
                            [v for v, _, _ in by_set], design, [k for _, _, k in by_set]
                        )
                    )
                    causes.append("chance")
            row["robust"] = "false" if parts or vague == "false" else "true"
            if parts:
                row["verdict"] = "not_reproducible"
                row["note"] = (
                    f"verdict hinges on {' and on '.join(causes)}: "
                    f"{'. '.join(parts)}. At the nominal inputs: {nominal_verdict}"
                    + (f" ({row['note']})" if row["note"] else "")
                )
            elif lucky is not None and lucky.agree < lucky.draws:
                row["note"] = "; ".join(
                    x for x in (row["note"], f"under chance it {lucky.describe()}") if x
                )
        if _missing(row["reproduced"]) and all(
            _missing(p["reproduced"]) for p in points[first_point:]
        ):
            # no value at the nominal inputs, at any point or under any seed set: nothing
            # an input or a draw could change, so neither robust nor fragile
            # (shared/CONTRACTS.md section 3: robust is empty when depends_on is)
            row["depends_on"] = row["robust"] = ""
        rows.append(row)
    sentences = published[SENTENCE_COLUMN] if SENTENCE_COLUMN in published else [""] * len(rows)
    rows = judge_sentences(judged, list(sentences))
    comparison = pd.DataFrame(rows, columns=COMPARISON_COLUMNS)
    return comparison, pd.DataFrame(points, columns=ROBUSTNESS_COLUMNS)


def _missing(x) -> bool:
    """No reproduced value: ``None`` or NaN."""
    return x is None or (isinstance(x, float) and math.isnan(x))


def _alternatives(key: str, res: Result) -> list[Alternative]:
    return [
        Alternative(key, r.description, r.value, r.section, r.family, r.chance)
        for r in res.readings
    ]


def _judged(doc: str, pub, res: Result, overrides):
    """One row judged by the verdict engine (:mod:`abglib.verdicts`), with what the
    sentence rule needs."""
    return _assess(
        doc,
        pub,
        res.value,
        res.note,
        _alternatives(pub.key, res),
        overrides,
        res.related,
        res.bound,
    )


def _same(a, b) -> bool:
    if _is_number(a) and _is_number(b):
        return math.isclose(float(a), float(b), rel_tol=1e-12, abs_tol=0.0) or a == b
    return a == b


def _hashable(v):
    if isinstance(v, (list, dict)):
        return repr(v)
    return v


def _describe_flip(rng: PlausibleRange, by_value) -> str:
    """``'antenna.dt' (plausible 0.01-0.1; basis): match at 0.01-0.04, mismatch at 0.05-0.1'``."""
    runs: list[list] = []
    for value, v in by_value:
        if runs and runs[-1][0] == v:
            runs[-1][2] = value
        else:
            runs.append([v, value, value])
    parts = []
    for v, a, b in runs:
        span = _fmt(a) if _same(a, b) else _span(a, b)
        parts.append(f"{v} at {span}")
    return f"{rng.name} (plausible {rng.describe()}, nominal {_fmt(rng.nominal)}): " + ", ".join(
        parts
    )
