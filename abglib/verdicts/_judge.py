"""The verdict of one row, and of the rows of one printed sentence.

``match`` when the reproduced value is within tolerance of the printed one; ``explained``
when it is not but a reading of the catalogue (:mod:`abglib.verdicts.readings`) or a
hand-written :class:`Reading` reproduces the printed number within tolerance at a chance
within its budget; ``mismatch`` otherwise; ``not_reproducible`` without a value, or when
the verdict flips across a vague word's declared range (``abglib.verdicts.vague``).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._checks import AbglibValueError
from ._numbers import format_number, parse_printed, tolerance_from_printed, within_tolerance
from .readings import THRESHOLD, Explanation, Row, explain
from .vague import find_vague, vague_tolerances

__all__ = ["Alternative", "Reading", "judge", "judge_sentences", "verdict"]

#: The family label of a hand-written :class:`Reading` that names none.
HAND_WRITTEN = "claim:hand-written reading"


@dataclass(frozen=True)
class Reading:
    """An alternative reading of a printed number, computed by a claim.

    ``description`` says what is computed instead (it goes into the note), ``value`` is
    its value, ``section`` the report section that demonstrates it and ``family`` its
    ``family:detail`` label (``convention:two-sided bandwidth``, ...). It explains a
    non-matching row only within tolerance and at a look-elsewhere chance of at most
    :data:`~abglib.verdicts.THRESHOLD` (readings with one label form one family).

    A reading of a *qualitative* row (empty ``published``) has ``value`` True when the
    check holds under the reading, and must give its ``chance``: a check has no printed
    precision to derive it from, so the claim computes it (e.g. the probability that an
    unrelated closed form agrees with the other quantity to the check's tolerance).
    """

    description: str
    value: float
    section: str
    family: str = HAND_WRITTEN
    chance: float | None = None


@dataclass(frozen=True)
class Alternative:
    """A :class:`Reading` tied to the published key it may explain (``comparison.csv``
    inputs of :func:`abglib.replications.compare.build_comparison`)."""

    key: str
    alternative: str
    value: float
    section: str
    family: str = HAND_WRITTEN
    chance: float | None = None

    @property
    def description(self) -> str:
        return self.alternative


def verdict(published, reproduced, tolerance, alternatives: Iterable = ()):
    """Verdict and the explaining alternative (or None) for one row, by tolerance alone.

    Parameters
    ----------
    published : str
        The printed number, or ``''`` for a qualitative claim.
    reproduced : float, bool or None
        Our value; for a qualitative claim, whether the check holds; None or NaN when
        not reproducible.
    tolerance : float or None
        Accepted absolute error (ignored for a qualitative claim).
    alternatives : iterable of Alternative
        Alternative readings; the first within tolerance explains a non-match (no
        chance check: :func:`judge` adds it).

    Returns
    -------
    (str, Alternative or None)
    """
    if _is_missing(reproduced):
        return "not_reproducible", None
    if not str(published).strip():
        return ("match" if _as_bool(reproduced) else "mismatch"), None
    pub = float(parse_printed(published))
    if within_tolerance(reproduced, pub, tolerance):
        return "match", None
    for alt in alternatives:
        if not _is_missing(alt.value) and within_tolerance(alt.value, pub, tolerance):
            return "explained", alt
    return "mismatch", None


@dataclass
class _Judged:
    row: dict
    explanation: Explanation | None = None
    tolerance: float | None = None
    published: float | None = None
    readings: Sequence = field(default_factory=tuple)


def judge(
    doc: str,
    row,
    value,
    note,
    alternatives=(),
    overrides=None,
    related: Mapping[str, Any] | None = None,
    bound: str = "",
) -> dict:
    """One row of ``comparison.csv`` (without ``depends_on``; ``robust`` and ``vague``,
    the vague words judged across their range as ``('vague:about',)``, only when the
    printed text carries one).

    Parameters
    ----------
    doc : str
        Document key.
    row
        The published row (attributes ``key, item, quantity, published``).
    value : float, bool or None
        The reproduced value (a bool for a qualitative claim; None when not reproducible).
    note : str
        The evidence; required when ``value`` is missing.
    alternatives : iterable of Reading or Alternative
        Hand-written readings (each tried through the chance check of its family).
    overrides : mapping, optional
        ``{key: {"tolerance": float, "reason": str}}``.
    related : mapping, optional
        Related quantities for the claim-specific reading families
        (:mod:`abglib.verdicts.readings`).
    bound : {"", ">", "<"}
        ``">"`` (``"<"``): ``value`` is not the quantity but a bound on it, which lies
        beyond (below) it, e.g. a stability edge past the end of the grid searched. The
        row is then a ``mismatch`` when the printed number lies on the excluded side by
        more than the tolerance, with no reading tried (a reading of a bound would explain
        a number the quantity is known not to be), and ``not_reproducible`` when it lies
        where the quantity may be.
    """
    return _assess(doc, row, value, note, alternatives, overrides, related, bound).row


#: The sides a bound can give (:func:`judge`'s ``bound``), in words.
BOUNDS = {">": "above", "<": "below"}


def _assess(
    doc, row, value, note, alternatives=(), overrides=None, related=None, bound=""
) -> _Judged:
    if bound and bound not in BOUNDS:
        raise AbglibValueError(f"bound must be '', '>' or '<', got {bound!r}")
    overrides = overrides or {}
    note = _text(note)
    qualitative = not str(row.published).strip()
    tol, tol_note = None, ""
    if not qualitative:
        tol = tolerance_from_printed(row.published)
        if row.key in overrides:
            ov = overrides[row.key]
            reason = _text(ov.get("reason", ""))
            if not reason:
                raise AbglibValueError(
                    f"{doc}: tolerance override for {row.key!r} must give a reason"
                )
            tol = float(ov["tolerance"])
            if not tol > 0:
                raise AbglibValueError(
                    f"{doc}: tolerance override for {row.key!r} must be > 0, got {tol!r}"
                )
            tol_note = f"tolerance {format_number(tol)} ({reason})"
    readings = tuple(alternatives)
    v, _ = verdict(row.published, value, tol)
    out = {"reading": "", "chance": None}
    abs_err = rel_err = pub = None
    if not qualitative and v != "not_reproducible":
        pub = float(parse_printed(row.published))
        abs_err = float(value) - pub
        rel_err = abs_err / abs(pub) if pub != 0 else None
    if v == "not_reproducible" and not note:
        raise AbglibValueError(f"{doc}: not-reproducible key {row.key!r} needs a note saying why")
    if bound and pub is not None:
        return _bounded(doc, row, float(value), pub, tol, bound, note, out, abs_err, rel_err)
    vague_note = ""
    if pub is not None and row.key not in overrides:
        words = find_vague(f"{row.quantity} {row.item}")
        windows = vague_tolerances(pub, tol, words)
        if windows:
            ends = ["match" if lo <= abs_err <= hi else "mismatch" for lo, hi in windows]
            w = [x for x in words if x.kind == "relative"][0]
            span = f"{format_number(100 * w.low, 3)}-{format_number(100 * w.high, 3)} %"
            out["vague"] = (f"vague:{w.word}",)
            if v == "match":  # within half a unit: a match under every reading of the word
                out["robust"] = "true"
            elif ends[0] == ends[1]:
                out["robust"] = "true"
                vague_note = f"'{w.word}' read as within {span} ({w.basis}): {ends[0]} at both ends"
                if ends[0] == "match":
                    v = "match"
                    tol = max(-windows[1][0], windows[1][1])
            else:
                out["robust"] = "false"
                vague_note = (
                    f"verdict hinges on how '{w.word}' is read ({span}; {w.basis}): "
                    f"{ends[1]} at {format_number(100 * w.high, 3)} %, {ends[0]} at "
                    f"{format_number(100 * w.low, 3)} %"
                )
                v = "not_reproducible"
    explanation = None
    if v == "mismatch" and pub is not None and np.isfinite(float(value)):
        explanation = explain(Row(row.published, float(value), tol, dict(related or {})), readings)
        best = explanation.best
        if best is not None:
            v = "explained"
            out["reading"], out["chance"] = best.candidate.label, _chance(best.chance)
            note = _explained_note(best, explanation, row.published) + (f". {note}" if note else "")
        else:
            note = (note or _unexplained(abs_err, tol)) + _tried_note(explanation, row.published)
    elif v == "mismatch" and pub is not None:  # an unbounded value: no reading scales it
        note = (note or _unexplained(abs_err, tol)) + (
            "; reading families tried: none applies to a value that is not finite"
        )
    elif v == "mismatch" and pub is None:
        hit = _qualitative_reading(readings)
        if hit is not None:
            v = "explained"
            out["reading"], out["chance"] = hit.family, _chance(hit.chance)
            note = (
                f"reading {hit.family} ({hit.description}): the check holds, at chance "
                f"{format_number(_chance(hit.chance))} (budget {format_number(THRESHOLD)})"
                + (f"; see report section '{hit.section}'" if hit.section else "")
                + (f". {note}" if note else "")
            )
        elif not note:
            note = "qualitative check does not hold"
    elif v == "mismatch" and not note:
        note = _unexplained(abs_err, tol)
    elif v == "match":
        note = note if qualitative else ""
    if vague_note:
        note = f"{vague_note}. {note}" if note else vague_note
    if tol_note:
        note = f"{note}; {tol_note}" if note else tol_note
    out = _row(doc, row, _reproduced_value(value, qualitative), abs_err, rel_err, tol, v, note, out)
    return _Judged(out, explanation, tol, pub, readings)


def _row(doc, row, reproduced, abs_err, rel_err, tol, verdict, note, extra) -> dict:
    """One row of ``comparison.csv`` as the judge returns it (``extra``: reading, chance,
    and robust/vague when the printed text carries a vague word)."""
    return {
        "doc": doc,
        "item": row.item,
        "quantity": row.quantity,
        "published": row.published,
        "reproduced": reproduced,
        "abs_err": abs_err,
        "rel_err": rel_err,
        "tolerance": tol,
        "verdict": verdict,
        "note": note,
        **extra,
    }


def _bounded(doc, row, value, pub, tol, bound, note, out, abs_err, rel_err) -> _Judged:
    """A row whose reproduced ``value`` is a bound (:func:`judge`'s ``bound``)."""
    side = BOUNDS[bound]
    excluded = pub < value - tol if bound == ">" else pub > value + tol
    where = f"the quantity lies {side} {format_number(value, NOTE_DIGITS)} (a bound, not its value)"
    if excluded:
        v = "mismatch"
        text = f"{where}, and the printed {row.published} does not: no reading is tried on a bound"
    else:
        v = "not_reproducible"
        text = f"{where}, where the printed {row.published} may lie: not decidable"
    note = f"{text}. {note}" if note else text
    return _Judged(_row(doc, row, value, abs_err, rel_err, tol, v, note, out), None, tol, pub, ())


def _qualitative_reading(readings):
    """The first reading under which a failed qualitative check holds, at a chance (which
    it must state) within :data:`~abglib.verdicts.THRESHOLD`."""
    for r in readings:
        if isinstance(r.value, (bool, np.bool_)) and bool(r.value):
            c = getattr(r, "chance", None)
            if c is None:
                raise AbglibValueError(
                    f"a reading of a qualitative row must give its chance, got none for "
                    f"{r.description!r}"
                )
            if 0 <= float(c) <= THRESHOLD:
                return r
    return None


def _chance(c: float) -> float:
    """A chance written with 3 significant digits (a model's number, not a measurement)."""
    return float(f"{c:.3g}")


#: significant digits of a reading's value in a note, at least: enough to see it meet the
#: printed number, few enough to hold on any machine (a value from a root finder or an
#: optimiser holds to ~6 digits, and a note is compared letter for letter by
#: ``abglib verify``)
NOTE_DIGITS = 4
#: ... and at most, for a printed number with more digits than :data:`NOTE_DIGITS`
NOTE_MAX_DIGITS = 6


def note_value(x, published: str) -> str:
    """A reading's value as a note writes it beside the printed number ``published``.

    With :data:`NOTE_DIGITS` significant digits, or with the printed number's own digits
    (trailing zeros kept, at most :data:`NOTE_MAX_DIGITS`) when it has more, so that a
    reading that gives the printed number reads as that number: Steelman's Table 5 prints
    0.13338 for sqrt(β/2) = 0.1333861, truncated; written at 4 digits the truncation would
    read "0.1334", the rounding it is not.

    Examples
    --------
    >>> note_value(0.13338, "0.13338"), note_value(77.079, "77.0790")
    ('0.13338', '77.0790')
    >>> note_value(2.1643, "2"), note_value(1452.0, "1452")
    ('2.164', '1452')
    """
    digits = len(parse_printed(published).as_tuple().digits)
    xf = float(x)
    if digits <= NOTE_DIGITS or not math.isfinite(xf) or xf == 0.0:
        return format_number(x, NOTE_DIGITS)
    text = f"{xf:#.{min(digits, NOTE_MAX_DIGITS)}g}"
    return text[:-1] if text.endswith(".") else text


def _unexplained(abs_err, tol) -> str:
    return (
        f"not explained: differs by {format_number(abs_err, 3)} "
        f"({format_number(abs(abs_err) / tol, 3)} tolerances)"
    )


def _explained_note(hit, explanation: Explanation, published: str) -> str:
    c = hit.candidate
    what = c.detail or c.label
    where = f"; see report section '{c.section}'" if c.section else ""
    return (
        f"reading {c.label} ({what}) gives {note_value(c.value, published)}, which "
        "matches the "
        f"printed value at chance {format_number(_chance(hit.chance))} (budget "
        f"{format_number(_chance(hit.budget))}){where}; families tried: "
        f"{explanation.tried_text()}"
    )


def _tried_note(explanation: Explanation, published: str) -> str:
    near = [h for h in explanation.hits if not h.accepted]
    text = f"; reading families tried (chance): {explanation.tried_text()}"
    if near:
        h = near[0]
        text += (
            f"; {h.candidate.label} ({h.candidate.detail or h.candidate.label}) gives "
            f"{note_value(h.candidate.value, published)} but at chance "
            f"{format_number(_chance(h.chance))} > budget {format_number(_chance(h.budget))}"
        )
    return text


# ----------------------------------------------------------------------- sentences
def judge_sentences(judged: Sequence[_Judged], sentences: Sequence[str]) -> list[dict]:
    """One sentence, one judgement: the rows of one printed sentence share a reading.

    ``sentences[i]`` is the grouping key of ``judged[i]`` (empty: a row of its own).
    Within a group, a shared reading (a convention, an aggregation, a scope: not a
    misprint of one number; ``shared`` of its :class:`~abglib.verdicts.readings.Family`)
    accepted for one row is tried for all: it stands only when, for every numeric row of the
    group that it gives a value for, that value is within tolerance of the printed
    number, and when the product of the chances of the rows it explains is within
    budget. A reading that fails is withdrawn from every row of the group (they become
    ``mismatch``, the note saying which sibling it contradicts), so that rows never
    carry contradicting readings.

    Returns
    -------
    list of dict : the rows, in order.
    """
    rows = [j.row for j in judged]
    groups: dict[str, list[int]] = {}
    for i, s in enumerate(sentences):
        if str(s).strip():
            groups.setdefault(str(s).strip(), []).append(i)
    for members in groups.values():
        if len(members) < 2:
            continue
        for i in members:
            j = judged[i]
            if rows[i]["verdict"] != "explained" or j.explanation is None:
                continue
            best = j.explanation.best
            if not best.shared:
                continue
            label = best.candidate.label
            conflicts, joint = [], best.chance
            for k in members:
                if (
                    k == i
                    or judged[k].published is None
                    or rows[k]["verdict"] == "not_reproducible"
                ):
                    continue
                got = _value_under(judged[k], label)
                if got is None:
                    if rows[k]["verdict"] != "match":
                        conflicts.append(f"'{rows[k]['item']}' (no value under it)")
                    continue
                if not within_tolerance(got, judged[k].published, judged[k].tolerance):
                    conflicts.append(f"'{rows[k]['item']}' ({format_number(got, 6)})")
                elif rows[k]["verdict"] != "match":
                    joint *= _row_chance(judged[k], label)
            if joint > best.budget and not conflicts:
                conflicts.append(f"joint chance {format_number(_chance(joint))}")
            if conflicts:
                rows[i]["verdict"] = "mismatch"
                rows[i]["reading"], rows[i]["chance"] = "", None
                rows[i]["note"] = (
                    f"reading {label} would explain this row alone but is withdrawn: the "
                    f"same sentence ({sentences[i]}) under it contradicts "
                    f"{', '.join(conflicts)}; {rows[i]['note']}"
                )
    return rows


def _value_under(j: _Judged, label: str):
    """The value row ``j`` takes under the reading ``label`` (hand-written or catalogue)."""
    for r in j.readings:
        if getattr(r, "family", HAND_WRITTEN) == label:
            return float(r.value)
    if j.explanation is not None:
        for h in j.explanation.hits:
            if h.candidate.label == label:
                return h.candidate.value
    return None


def _row_chance(j: _Judged, label: str) -> float:
    for h in j.explanation.hits if j.explanation else ():
        if h.candidate.label == label:
            return h.chance
    return 1.0


# ----------------------------------------------------------------------- helpers
def _is_missing(x) -> bool:
    if x is None:
        return True
    if isinstance(x, str):
        return not x.strip()
    try:
        return bool(np.isnan(x))
    except TypeError:
        return False


def _as_bool(x) -> bool:
    if isinstance(x, str):
        s = x.strip().lower()
        if s in ("true", "1", "1.0"):
            return True
        if s in ("false", "0", "0.0"):
            return False
        raise AbglibValueError(f"a qualitative check must be True or False, got {x!r}")
    if isinstance(x, (bool, np.bool_)):
        return bool(x)
    if isinstance(x, (int, float, np.integer, np.floating)) and float(x) in (0.0, 1.0):
        return bool(x)
    raise AbglibValueError(
        f"a qualitative check must be True or False, got {x!r} (a claim with an empty "
        "published value returns whether its check holds, not a number)"
    )


def _reproduced_value(value, qualitative: bool):
    if _is_missing(value):
        return None
    return _as_bool(value) if qualitative else float(value)


def _text(x) -> str:
    return "" if _is_missing(x) else str(x).strip()
