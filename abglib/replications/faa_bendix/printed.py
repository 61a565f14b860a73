"""The printed forms of seed 003, read from its transcription (``data/published/faa_bendix``).

``memo_gains``   Sinsky's memo table: the gain set of every update period (three decimals)
``captions``     the plot captions: gains, period and scale factor SFY per input and period
``truncate``     a printed number cut (not rounded) to fewer decimals
``round_half_up``  a printed number rounded to fewer decimals as a person would
"""

from __future__ import annotations

import re
from decimal import ROUND_DOWN, ROUND_HALF_UP, Decimal

import pandas as pd

from ..._checks import AbglibValueError
from ...verdicts import parse_printed

__all__ = ["captions", "memo_gains", "round_half_up", "truncate"]

_MEMO = re.compile(r"memo\.T(\d+)\.(alpha|beta)")
_CAPTION = re.compile(r"captions\.(impulse|ramp)\.T(\d+)\.(alpha|beta|period|sfy)")


def _matching(published: pd.DataFrame, pattern: re.Pattern) -> list[tuple[tuple, str]]:
    out = []
    for key, text in zip(published["key"], published["published"], strict=True):
        m = pattern.fullmatch(key)
        if m:
            out.append((m.groups(), text))
    return out


def memo_gains(published: pd.DataFrame) -> pd.DataFrame:
    """The memo's gain sets: ``period_s`` (index), ``alpha``, ``beta`` (floats) and the
    printed strings ``alpha_printed``, ``beta_printed`` (keys ``memo.T<p>.alpha|beta``).

    Raises
    ------
    AbglibValueError
        If a period lacks one of its two gains.
    """
    rows: dict[int, dict] = {}
    for (p, name), text in _matching(published, _MEMO):
        row = rows.setdefault(int(p), {"period_s": int(p)})
        row[name] = float(parse_printed(text))
        row[f"{name}_printed"] = text
    df = pd.DataFrame(sorted(rows.values(), key=lambda r: r["period_s"]))
    if df.empty or df[["alpha", "beta"]].isna().any().any():
        raise AbglibValueError("faa_bendix: every memo period needs memo.T<p>.alpha and .beta")
    return df.set_index("period_s")


def captions(published: pd.DataFrame) -> pd.DataFrame:
    """The captions' numbers: one row per (``input``, ``period_s``) with ``alpha``,
    ``beta``, ``T``, ``sfy`` (floats) and their printed strings (``*_printed``; ``T`` is
    the key ``period``)."""
    rows: dict[tuple, dict] = {}
    for (kind, p, name), text in _matching(published, _CAPTION):
        row = rows.setdefault((kind, int(p)), {"input": kind, "period_s": int(p)})
        col = "T" if name == "period" else name
        row[col] = float(parse_printed(text))
        row[f"{col}_printed"] = text
    df = pd.DataFrame([rows[k] for k in sorted(rows)])
    need = ["alpha", "beta", "T", "sfy"]
    if df.empty or any(c not in df for c in need) or df[need].isna().any().any():
        raise AbglibValueError("faa_bendix: every caption group needs alpha, beta, period, sfy")
    return df


def _digits(printed: str) -> int:
    return -parse_printed(printed).as_tuple().exponent


def truncate(value: str, like: str) -> float:
    """``value`` (a printed string) cut to the decimals of ``like``: ``('.066', '0.06')`` ->
    0.06."""
    q = Decimal(1).scaleb(-_digits(like))
    return float(parse_printed(value).quantize(q, rounding=ROUND_DOWN))


def round_half_up(value: str, like: str) -> float:
    """``value`` rounded half up to the decimals of ``like``: ``('.465', '0.46')`` -> 0.47."""
    q = Decimal(1).scaleb(-_digits(like))
    return float(parse_printed(value).quantize(q, rounding=ROUND_HALF_UP))


#: The kinds of :func:`cut_kind`, in words (the FAA report's caption paragraph).
CUT_KINDS = {
    "exact": "exact at the caption's decimals",
    "same": "rounding and truncation agree",
    "tie": "a half-unit tie: rounding, half up, prints it a unit higher than truncation",
    "beyond": "truncation and rounding differ beyond a tie",
}


def cut_kind(value: str, like: str) -> str:
    """How the printed ``value`` (a memo gain) meets the decimals of ``like`` (its caption),
    in exact decimal arithmetic: ``'exact'`` (no digit to cut), ``'same'`` (rounding half
    up and truncation give the same number), ``'tie'`` (``value`` is midway between them,
    so a caption printed low is a truncation *or* a rounding half down) or ``'beyond'``
    (they differ and ``value`` is not midway: only truncation prints it low), the keys of
    :data:`CUT_KINDS`.

    Examples
    --------
    >>> [cut_kind(v, "0.06") for v in (".25", ".431", ".465", ".066")]
    ['exact', 'same', 'tie', 'beyond']
    """
    q = Decimal(1).scaleb(-_digits(like))
    v = parse_printed(value)
    if v == v.quantize(q, rounding=ROUND_DOWN):
        return "exact"
    cut = v.quantize(q, rounding=ROUND_DOWN)
    if cut == v.quantize(q, rounding=ROUND_HALF_UP):
        return "same"
    return "tie" if v - cut == q / 2 else "beyond"
