"""The verdict engine: how a printed number is judged against a reproduced one.

One home for judging (``shared/CONTRACTS.md`` section 3). Documents declare claims and
their readings (``abglib.replications``); this package judges them. It imports the core
and numpy only, never ``abglib.replications``, ``abglib.bench`` or ``abglib.reporting``.

Numbers (``abglib.verdicts._numbers``)
    ``parse_printed`` (a printed number, exactly), ``tolerance_from_printed`` (half a unit
    in the last printed digit), ``printed_unit``, ``reference_span`` (the decade an
    unrelated number of the same precision is drawn from), ``within_tolerance``,
    ``format_number`` (deterministic significant digits).
Verdicts (``abglib.verdicts._judge``)
    ``Reading`` (a claim's hand-written reading, with its ``family:detail`` label),
    ``Alternative`` (a reading tied to a key), ``verdict`` (by tolerance alone),
    ``judge`` (one ``comparison.csv`` row: tolerance, vague words, the reading catalogue
    and its chance check), ``judge_sentences`` (the rows of one printed sentence share a
    reading).
The reading catalogue (:mod:`abglib.verdicts.readings`)
    ``GENERIC_FAMILIES``, ``CLAIM_FAMILIES``, ``OCR_PAIRS``, ``THRESHOLD``, ``chance``
    (a family's look-elsewhere cost), ``explain``.
Vague words (``abglib.verdicts.vague``)
    ``VAGUE`` (one table for every document), ``find_vague``, ``vague_tolerances``,
    ``threshold_range``.
"""

from ._judge import HAND_WRITTEN, Alternative, Reading, judge, judge_sentences, verdict
from ._numbers import (
    SIGNIFICANT_DIGITS,
    format_number,
    parse_printed,
    printed_unit,
    reference_span,
    tolerance_from_printed,
    within_tolerance,
)
from .readings import CLAIM_FAMILIES, GENERIC_FAMILIES, OCR_PAIRS, THRESHOLD, chance, explain
from .vague import VAGUE, find_vague, threshold_range, vague_tolerances

__all__ = [
    "CLAIM_FAMILIES",
    "GENERIC_FAMILIES",
    "HAND_WRITTEN",
    "OCR_PAIRS",
    "SIGNIFICANT_DIGITS",
    "THRESHOLD",
    "VAGUE",
    "Alternative",
    "Reading",
    "chance",
    "explain",
    "find_vague",
    "format_number",
    "judge",
    "judge_sentences",
    "parse_printed",
    "printed_unit",
    "reference_span",
    "threshold_range",
    "tolerance_from_printed",
    "vague_tolerances",
    "verdict",
    "within_tolerance",
]
