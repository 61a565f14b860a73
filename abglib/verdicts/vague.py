"""Vague words read as plausible inputs: one table for every document.

A printed "about 20 %" is not the exact number 20 with half a unit of tolerance: the word
widens it. Each word of :data:`~abglib.verdicts.VAGUE` has a declared interpretation
range (the low and high reading of its width) and its basis; a numeric row whose printed
text carries the word is judged at both ends of the range (:func:`vague_tolerances`), and
is robust only when the verdict is the same at both (``shared/CONTRACTS.md`` section 3:
"a declared range for a vague word counts as an input"). Words that qualify a comparison
("similar", "considerably", "much", "hardly", "very highly significant") give the
thresholds a qualitative check may use (:func:`threshold_range`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass

__all__ = ["VAGUE", "VagueWord", "find_vague", "threshold_range", "vague_tolerances"]


@dataclass(frozen=True)
class VagueWord:
    """A vague word: ``kind`` is ``'relative'`` (a number's relative half-width; one-sided
    ``'below'`` for words that approach from under), ``'ratio'`` (how far apart two things
    are), ``'p_value'`` (a significance level); ``low``/``high`` the declared range,
    ``basis`` why."""

    word: str
    kind: str
    low: float
    high: float
    basis: str
    side: str = "both"


#: Every vague word with its declared interpretation range and why (one table for every
#: document).
VAGUE: tuple[VagueWord, ...] = (
    VagueWord(
        "about",
        "relative",
        0.05,
        0.20,
        "a round number stands for its neighbourhood: at least the next finer round step "
        "(5 %), at most the gap to the next coarser one (2 vs 2.5 differs by 20-25 %)",
    ),
    VagueWord("approximately", "relative", 0.05, 0.20, "as 'about'"),
    VagueWord("approx.", "relative", 0.05, 0.20, "as 'about' (Steelman's table header)"),
    VagueWord("around", "relative", 0.05, 0.20, "as 'about'"),
    VagueWord(
        "nearly",
        "relative",
        0.02,
        0.10,
        "just short of the number: within 2-10 % below it",
        side="below",
    ),
    VagueWord("almost", "relative", 0.02, 0.10, "as 'nearly'", side="below"),
    VagueWord(
        "similar",
        "ratio",
        1.12,
        1.41,
        "two magnitudes a reader of a log plot calls similar: within 1-3 dB (ratio 1.12-1.41)",
    ),
    VagueWord(
        "considerably",
        "ratio",
        1.2,
        2.0,
        "a change worth remarking: at least 20 %, and a factor 2 is certainly considerable",
    ),
    VagueWord("considerable", "ratio", 1.2, 2.0, "as 'considerably'"),
    VagueWord("much", "ratio", 2.0, 10.0, "'much larger/less': a factor 2 to a decade"),
    VagueWord(
        "hardly",
        "ratio",
        1.01,
        1.10,
        "'hardly affects': a change of 1-10 %, below what a reader of the plots would notice",
    ),
    VagueWord(
        "very highly significant",
        "p_value",
        0.001,
        0.01,
        "the star convention of significance tables: * 0.05, ** 0.01, *** 0.001; 'very "
        "highly' is *** at its strictest and ** at its loosest",
    ),
)

_BY_WORD = {v.word: v for v in VAGUE}


def find_vague(text: str) -> list[VagueWord]:
    """The vague words of :data:`~abglib.verdicts.VAGUE` in ``text`` (case-insensitive, whole words;
    'very highly significant' before its parts)."""
    found, rest = [], str(text).lower()
    for v in sorted(VAGUE, key=lambda v: -len(v.word)):
        pattern = rf"(?<![\w]){re.escape(v.word)}(?![\w])"
        if re.search(pattern, rest):
            found.append(v)
            rest = re.sub(pattern, " ", rest)
    return found


def vague_tolerances(published: float, half_unit: float, words) -> list[tuple[float, float]]:
    """The accepted intervals around ``published`` at the low and high reading of the
    first relative vague word in ``words``, as ``[(lo, hi), (lo, hi)]`` offsets from
    ``published`` (never narrower than ``half_unit``); empty when none applies.

    Examples
    --------
    >>> vague_tolerances(20.0, 0.5, [_BY_WORD["about"]])
    [(-1.0, 1.0), (-4.0, 4.0)]
    """
    for v in words:
        if v.kind != "relative":
            continue
        out = []
        for r in (v.low, v.high):
            w = max(half_unit, r * abs(published))
            out.append((-w, half_unit) if v.side == "below" else (-w, w))
        return out
    return []


def threshold_range(word: str) -> tuple[float, float]:
    """The declared ``(low, high)`` range of one word of :data:`~abglib.verdicts.VAGUE`.

    Raises
    ------
    AbglibValueError
        For a word the table lacks.
    """
    from .._checks import AbglibValueError

    if word not in _BY_WORD:
        raise AbglibValueError(f"word must be one of {sorted(_BY_WORD)}, got {word!r}")
    v = _BY_WORD[word]
    return v.low, v.high
