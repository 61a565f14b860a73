"""The reading catalogue: what a printed number may mean when it is not a match.

Before a referee writes "the source is wrong" they try what the author may have meant
(``shared/STYLE.md``, "Judging a printed number"). This module declares those tries as
reading *families*: each is a small function mapping a :class:`Row` (the printed string,
its tolerance, the reproduced value and any related quantities the claim supplies) to
candidate values, each labelled ``family:detail`` (``shared/CONTRACTS.md`` section 3,
column ``reading``). :func:`explain` applies every family to a non-match row.

Generic families (need only the printed and the reproduced numbers; tried on every
non-match numeric row):

``typo:decimal point shifted``
    the reproduced value times 10^k, k = ±1, ±2, ±3
``typo:digit dropped``
    one digit of the rounded reproduced value left out
``typo:digit doubled``
    one digit of it printed twice
``typo:two digits transposed``
    two adjacent (different) digits swapped
``typo:OCR confusion``
    one digit replaced by its scan look-alike, pairs :data:`OCR_PAIRS`
``typo:sign lost``
    the negated value
``typo:truncated``
    truncated, not rounded, at the printed digit
``typo:double rounding``
    rounded at one digit more, then at the printed one
``convention:factor 2``
    x2 and /2: one- vs two-sided bandwidth, 10 vs 20 log dB
``convention:percent vs fraction``
    x100 and /100
``convention:radians vs degrees``
    x180/pi and xpi/180

Claim-specific families (from the ``related`` field of a :class:`Row`, which a claim
returns in ``Result.related``):

``values``
    a sequence of per-row values → ``aggregation:<mean|median|rms|...>``
``neighbours``
    ``{label: value}`` (the neighbouring grid point, order or row) → ``scope:<label>``
``dt``
    the sample interval T → ``convention:per second`` (x1/T, xT, x1/T², xT²)
``inputs``
    ``{name: (printed input, f)}``, ``f`` recomputing the value from that input →
    ``typo:in input <name>`` (every typographic variant of the input)
``readings``
    hand-written readings (``Reading(..., family="convention:...")``), one family per
    label kind

No explaining by luck
---------------------
Each family's look-elsewhere cost (:func:`chance`) is the probability that a number
unrelated to the study, printed with the same precision, lands within tolerance of one of
the family's candidates: the union of the candidates' tolerance windows ``[c - t, c + t]``
inside the printed value's reference span (:func:`~abglib.verdicts.reference_span`:
its printed decade), over the span's length. With the half-unit tolerance a window is one
printed unit wide, so a single candidate costs ``1 / (9 * 10^(s-1))`` for ``s``
significant digits (1/9 for '7', 1/90 for '40', 1/900 for '.135').

A reading explains a row only when its family's chance is at most the row's budget:
the generic families share :data:`THRESHOLD` (0.05, the conventional 1-in-20 rate of a
false finding) split equally over the generic families tried on the row (Bonferroni), so
that an unrelated printed number is explained by the generic catalogue at most 5 % of the
time (``tests/test_verdicts.py`` feeds it seeded random values); a claim-specific family
is a stated hypothesis about that one row and must itself cost at most :data:`THRESHOLD`.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from decimal import ROUND_HALF_UP, Decimal
from typing import Any

import numpy as np

from ._numbers import (
    _TOL_SLACK,
    format_number,
    parse_printed,
    printed_unit,
    reference_span,
    tolerance_from_printed,
)

__all__ = [
    "CLAIM_FAMILIES",
    "GENERIC_FAMILIES",
    "OCR_PAIRS",
    "THRESHOLD",
    "Candidate",
    "Explanation",
    "Family",
    "Hit",
    "Row",
    "chance",
    "explain",
    "typographic_variants",
]

#: The rate at which the generic catalogue may explain an unrelated number (per row), and
#: the largest look-elsewhere cost of a claim-specific family: one in twenty.
THRESHOLD = 0.05

#: Digit pairs a scan of a typewritten or typeset page confuses, both ways: 1/7 (a serif
#: 1 with a long flag), 3/8 (an open loop closed by ink), 5/6 (the 5's top bar lost and
#: its bowl closed), 0/8 (a broken waist), 1/4 (the 4's open top read as a serif 1).
OCR_PAIRS = ((1, 7), (3, 8), (5, 6), (0, 8), (1, 4))


@dataclass(frozen=True)
class Row:
    """What a reading family sees of one row.

    Attributes
    ----------
    printed : str
        The number as printed.
    reproduced : float
        Our value.
    tolerance : float
        The accepted absolute error.
    related : mapping
        Related quantities the claim supplies (keys in the module docstring).
    """

    printed: str
    reproduced: float
    tolerance: float
    related: Mapping[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class Candidate:
    """One value a family proposes: ``label`` (``family:detail``), ``value``, and the
    ``detail`` of this one candidate in words (for the note) and the report ``section``
    that demonstrates it (hand-written readings)."""

    label: str
    value: float
    detail: str = ""
    section: str = ""


@dataclass(frozen=True)
class Family:
    """A reading family: a name, whether it is generic (tried on every row with only the
    printed and reproduced numbers), whether the rows of one sentence share it (an
    interpretation does, a misprint of one number does not) and its candidates."""

    name: str
    generic: bool
    shared: bool
    candidates: Callable[[Row], list[Candidate]]


def chance(candidates: Iterable[float], printed: str, tolerance: float | None = None) -> float:
    """Look-elsewhere cost of a set of candidate values (module docstring).

    The fraction of the numbers of the printed precision in the reference span of
    ``printed`` (:func:`~abglib.verdicts.reference_span`) that lie within
    ``tolerance`` (default half a unit in the last printed digit) of some candidate: the
    probability that a number unrelated to the study, printed like ``printed``, would be
    reproduced by one of the candidates. For candidates one unit or more apart this is the
    sum of their tolerance windows inside the span over the span's length.

    Examples
    --------
    >>> chance([0.5], '.135')  # one 3-digit candidate: 1 of the 900 numbers .100 .. .999
    0.0011111111111111111
    """
    unit = printed_unit(printed)
    t = tolerance_from_printed(printed) if tolerance is None else float(tolerance)
    lo, hi = reference_span(printed)
    k_lo, k_hi = math.ceil(lo / unit), math.floor(hi / unit)  # the span's numbers k * unit
    if k_hi * unit >= hi:
        k_hi -= 1
    slack = t * _TOL_SLACK
    hit: set[int] = set()
    for c in (float(v) for v in candidates):
        if not math.isfinite(c):
            continue
        a = max(k_lo, math.ceil((c - t - slack) / unit))
        b = min(k_hi, math.floor((c + t + slack) / unit))
        hit.update(range(a, b + 1))
    return len(hit) / (k_hi - k_lo + 1)


# ----------------------------------------------------------------------- typographic
def _digits(x: float, unit: float) -> tuple[int, str]:
    """Sign and digit string of ``x`` rounded to multiples of ``unit``."""
    n = int(round(abs(x) / unit))
    return (-1 if x < 0 else 1), str(n)


def typographic_variants(text: str) -> dict[str, list[tuple[str, str]]]:
    """Every single-slip misprint of a printed number, by kind.

    ``{'digit dropped': [(variant, detail), ...], 'digit doubled': ..., 'two digits
    transposed': ..., 'OCR confusion': ...}``; ``detail`` says which slip. The digit
    sequence ends at the printed last digit: a transposition or a look-alike keeps the
    unit of ``text``, a dropped digit ends one place earlier (``'0.1353'`` → ``'0.153'``)
    and a doubled one a place later (``'0.135'`` → ``'0.1335'``).
    """
    value = parse_printed(text)
    exp = value.as_tuple().exponent
    sign, s = ("-" if value < 0 else ""), str(abs(int(value.scaleb(-exp))))

    def as_text(digits: str, shift: int = 0) -> str:
        if not digits:
            return ""
        return sign + str(Decimal(int(digits)).scaleb(exp + shift))

    out: dict[str, list[tuple[str, str]]] = {
        "digit dropped": [],
        "digit doubled": [],
        "two digits transposed": [],
        "OCR confusion": [],
    }
    for i, d in enumerate(s):
        if len(s) > 1:
            out["digit dropped"].append(
                (as_text(s[:i] + s[i + 1 :], 1), f"digit {i + 1} ({d}) dropped")
            )
        out["digit doubled"].append(
            (as_text(s[:i] + d + s[i:], -1), f"digit {i + 1} ({d}) doubled")
        )
        if i + 1 < len(s) and s[i] != s[i + 1]:
            out["two digits transposed"].append(
                (
                    as_text(s[:i] + s[i + 1] + s[i] + s[i + 2 :]),
                    f"digits {i + 1}-{i + 2} ({d}{s[i + 1]}) transposed",
                )
            )
        for a, b in OCR_PAIRS:
            for x, y in ((a, b), (b, a)):
                if int(d) == x:
                    out["OCR confusion"].append(
                        (as_text(s[:i] + str(y) + s[i + 1 :]), f"{x} read as {y} at digit {i + 1}")
                    )
    return {k: [(t, w) for t, w in v if t] for k, v in out.items()}


def _rounded_text(row: Row, shift: int = 0) -> str:
    """The reproduced value written at the printed precision (``shift`` places finer)."""
    unit = Decimal(10) ** (parse_printed(row.printed).as_tuple().exponent - shift)
    return str(Decimal(repr(float(row.reproduced))).quantize(unit))


# the source digits of a slip: a dropped digit leaves one digit fewer than the author
# wrote, a doubled one a digit more
_SHIFT = {"digit dropped": 1, "digit doubled": -1}


def _typo(kind: str) -> Callable[[Row], list[Candidate]]:
    def candidates(row: Row) -> list[Candidate]:
        source = _rounded_text(row, _SHIFT.get(kind, 0))
        if not parse_printed(source):
            return []
        return [
            Candidate(f"typo:{kind}", float(parse_printed(t)), f"{w} in {source}")
            for t, w in typographic_variants(source)[kind]
        ]

    candidates.__doc__ = f"typo:{kind} of the reproduced value rounded at the printed digit."
    return candidates


def _decimal_shift(row: Row) -> list[Candidate]:
    """The reproduced value with its decimal point shifted by 1-3 places either way."""
    return [
        Candidate("typo:decimal point shifted", row.reproduced * 10.0**k, f"x10^{k}")
        for k in (-3, -2, -1, 1, 2, 3)
    ]


def _sign(row: Row) -> list[Candidate]:
    """The reproduced value with its sign lost (or gained)."""
    return [Candidate("typo:sign lost", -row.reproduced, "negated")] if row.reproduced else []


def _truncated(row: Row) -> list[Candidate]:
    """The reproduced value truncated (towards zero) at the printed digit, when that
    differs from rounding."""
    unit = printed_unit(row.printed)
    t = math.trunc(row.reproduced / unit) * unit
    if abs(t - round(row.reproduced / unit) * unit) < unit / 2:
        return []
    return [Candidate("typo:truncated", t, "truncated instead of rounded")]


def _double_rounding(row: Row) -> list[Candidate]:
    """The reproduced value rounded (half up) at one digit more than printed, then again
    at the printed digit, when that differs from rounding once (0.1332449 → 0.133245 →
    0.13325)."""
    once = _rounded_text(row)
    exp = parse_printed(row.printed).as_tuple().exponent
    twice = Decimal(_rounded_text(row, 1)).quantize(Decimal(10) ** exp, rounding=ROUND_HALF_UP)
    if twice == Decimal(once):
        return []
    return [
        Candidate("typo:double rounding", float(twice), f"{_rounded_text(row, 1)} rounded again")
    ]


def _factors(label: str, factors: Sequence[tuple[float, str]]) -> Callable[[Row], list[Candidate]]:
    def candidates(row: Row) -> list[Candidate]:
        return [Candidate(label, row.reproduced * f, w) for f, w in factors]

    candidates.__doc__ = f"{label}: the reproduced value times {[w for _, w in factors]}."
    return candidates


# ----------------------------------------------------------------------- claim-specific
def _aggregation(row: Row) -> list[Candidate]:
    """Other aggregates of the per-row values the claim supplies (``related['values']``)."""
    v = np.asarray(row.related.get("values", ()), dtype=float)
    if v.size == 0:
        return []
    stats = {
        "mean": v.mean(),
        "median": np.median(v),
        "mean absolute": np.abs(v).mean(),
        "mean square": (v**2).mean(),
        "RMS": math.sqrt((v**2).mean()),
        "maximum": v.max(),
        "maximum absolute": np.abs(v).max(),
        "minimum": v.min(),
        "sum": v.sum(),
    }
    return [
        Candidate(f"aggregation:{k}", float(x), f"{k} of {v.size} values") for k, x in stats.items()
    ]


def _scope(row: Row) -> list[Candidate]:
    """The neighbouring grid point, order or row (``related['neighbours']``)."""
    return [
        Candidate(f"scope:{label}", float(x), label)
        for label, x in dict(row.related.get("neighbours", {})).items()
    ]


def _per_second(row: Row) -> list[Candidate]:
    """Per sample vs per second (``related['dt']`` = T): x1/T, xT, x1/T², xT²."""
    if "dt" not in row.related:
        return []
    T = float(row.related["dt"])
    return [
        Candidate("convention:per second vs per sample", row.reproduced * f, w)
        for f, w in ((1 / T, "x1/T"), (T, "xT"), (T**-2, "x1/T^2"), (T**2, "xT^2"))
    ]


def _input_typo(row: Row) -> list[Candidate]:
    """A misprint in an input the printed number was computed from
    (``related['inputs'] = {name: (printed input, f)}``)."""
    out = []
    for name, (text, fn) in dict(row.related.get("inputs", {})).items():
        value = parse_printed(text)
        shifted = [(str(value.scaleb(k)), f"decimal point x10^{k}") for k in (-1, 1)]
        slips = [x for v in typographic_variants(text).values() for x in v]
        for t, w in [*shifted, *slips]:
            try:
                y = float(fn(float(parse_printed(t))))
            except (ValueError, ZeroDivisionError, ArithmeticError):
                continue
            out.append(
                Candidate(f"typo:in input {name}", y, f"{name} = {t} ({w}) instead of {text}")
            )
    return out


#: The generic reading families, in the order tried (typographic slips and conventions):
#: they need only the printed and the reproduced numbers.
GENERIC_FAMILIES: tuple[Family, ...] = (
    Family("typo:decimal point shifted", True, False, _decimal_shift),
    Family("typo:digit dropped", True, False, _typo("digit dropped")),
    Family("typo:digit doubled", True, False, _typo("digit doubled")),
    Family("typo:two digits transposed", True, False, _typo("two digits transposed")),
    Family("typo:OCR confusion", True, False, _typo("OCR confusion")),
    Family("typo:sign lost", True, False, _sign),
    Family("typo:truncated", True, False, _truncated),
    Family("typo:double rounding", True, False, _double_rounding),
    Family(
        "convention:factor 2",
        True,
        True,
        _factors("convention:factor 2", ((2.0, "x2"), (0.5, "/2"))),
    ),
    Family(
        "convention:percent vs fraction",
        True,
        True,
        _factors("convention:percent vs fraction", ((100.0, "x100"), (0.01, "/100"))),
    ),
    Family(
        "convention:radians vs degrees",
        True,
        True,
        _factors(
            "convention:radians vs degrees",
            ((180 / math.pi, "x180/pi"), (math.pi / 180, "xpi/180")),
        ),
    ),
)

#: The claim-specific reading families (aggregation, scope, per second, an input's typo):
#: each needs what a claim returns in ``Result.related``.
CLAIM_FAMILIES: tuple[Family, ...] = (
    Family("aggregation", False, True, _aggregation),
    Family("scope", False, True, _scope),
    Family("convention:per second vs per sample", False, True, _per_second),
    Family("typo:in input", False, False, _input_typo),
)


# ----------------------------------------------------------------------- explaining
@dataclass(frozen=True)
class Hit:
    """A candidate within tolerance of the printed number, with its family's chance and
    the budget it had to meet."""

    candidate: Candidate
    family: str
    chance: float
    budget: float
    shared: bool

    @property
    def accepted(self) -> bool:
        return self.chance <= self.budget


@dataclass(frozen=True)
class Explanation:
    """What :func:`explain` found for one row: the families tried (with their chance),
    and the hits (candidates within tolerance), best first (accepted, then lowest chance)."""

    tried: tuple[tuple[str, float], ...]
    hits: tuple[Hit, ...]

    @property
    def best(self) -> Hit | None:
        ok = [h for h in self.hits if h.accepted]
        return ok[0] if ok else None

    def tried_text(self) -> str:
        return ", ".join(f"{name} ({format_number(c, 2)})" for name, c in self.tried)


def _hand_written(readings: Iterable) -> list[Family]:
    """One family per hand-written reading label (``Reading.family``)."""
    by_label: dict[str, list[Candidate]] = {}
    for r in readings:
        by_label.setdefault(r.family, []).append(
            Candidate(r.family, float(r.value), r.description, r.section)
        )
    return [Family(label, False, True, (lambda _row, c=c: c)) for label, c in by_label.items()]


def explain(row: Row, readings: Iterable = (), within=None) -> Explanation:
    """Try every reading family on one row (module docstring).

    Parameters
    ----------
    row : Row
        The printed number, its tolerance, the reproduced value and related quantities.
    readings : iterable of Reading
        Hand-written readings of the claim (each with a ``family`` label).
    within : callable, optional
        ``within(candidate_value, printed_value, tolerance) -> bool`` (default
        :func:`~abglib.verdicts.within_tolerance`).

    Returns
    -------
    Explanation
    """
    from ._numbers import within_tolerance

    within = within or within_tolerance
    pub = float(parse_printed(row.printed))
    generic, specific = [], []
    for fam in (*GENERIC_FAMILIES, *CLAIM_FAMILIES, *_hand_written(readings)):
        cands = [c for c in fam.candidates(row) if math.isfinite(c.value)]
        if cands:
            (generic if fam.generic else specific).append((fam, cands))
    budget_generic = THRESHOLD / max(1, len(generic))
    tried, hits = [], []
    for fam, cands in (*generic, *specific):
        c = chance([x.value for x in cands], row.printed, row.tolerance)
        tried.append((fam.name, c))
        budget = budget_generic if fam.generic else THRESHOLD
        for cand in cands:
            if within(cand.value, pub, row.tolerance):
                hits.append(Hit(cand, fam.name, c, budget, fam.shared))
    # hand-written first among equals (they come with a report section), then cheapest
    order = sorted(hits, key=lambda h: (not h.accepted, h.chance, not h.candidate.section))
    return Explanation(tuple(tried), tuple(order))
