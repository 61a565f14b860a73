"""Printed numbers: exact parsing, their precision, tolerances and deterministic formatting.

The one home of the number rules every verdict uses (``shared/CONTRACTS.md`` section 3:
"half a unit in the last printed digit"); :mod:`abglib.replications.compare` re-exports them.
"""

from __future__ import annotations

import math
from decimal import Decimal, InvalidOperation

import numpy as np

from .._checks import AbglibValueError

__all__ = [
    "SIGNIFICANT_DIGITS",
    "format_number",
    "parse_printed",
    "printed_unit",
    "reference_span",
    "tolerance_from_printed",
    "within_tolerance",
]

#: Default number of significant digits written to deterministic tables.
SIGNIFICANT_DIGITS = 10

# a relative slack on the tolerance so that an error of exactly half a unit in the last
# digit, computed in binary floating point, is not lost to representation error
_TOL_SLACK = 1e-9


def parse_printed(text: str) -> Decimal:
    """Parse a number as printed (``'.135'``, ``'-3'``, ``'1.20'``, ``'2e-3'``) exactly.

    Raises
    ------
    AbglibValueError
        If ``text`` is not a plain decimal number.
    """
    s = str(text).strip().replace("\u2212", "-")  # a typeset minus sign
    try:
        value = Decimal(s)
    except InvalidOperation:
        raise AbglibValueError(
            f"published must be a number as printed (e.g. '.135', '1452', '-3'), got {text!r}"
        ) from None
    if not value.is_finite():
        raise AbglibValueError(f"published must be finite, got {text!r}")
    return value


def printed_unit(text: str) -> float:
    """One unit in the last printed digit: ``'.135'`` → 1e-3, ``'1452'`` → 1, ``'1.20'`` → 0.01."""
    return float(Decimal(10) ** parse_printed(text).as_tuple().exponent)


def tolerance_from_printed(text: str) -> float:
    """Half a unit in the last printed digit of ``text``.

    ``'0.0402'`` → 5e-5, ``'.135'`` → 5e-4, ``'1.20'`` → 5e-3 (the trailing zero is a
    printed digit), ``'23'``, ``'1452'`` and ``'-3'`` → 0.5, ``'2.5e-3'`` → 5e-5.

    Examples
    --------
    >>> tolerance_from_printed('.135')
    0.0005
    >>> tolerance_from_printed('1452')
    0.5
    """
    exponent = parse_printed(text).as_tuple().exponent
    return float(Decimal(5) * Decimal(10) ** (exponent - 1))


def reference_span(text: str) -> tuple[float, float]:
    """The plausible values of an unrelated number printed like ``text``: its decade.

    The look-elsewhere model of :mod:`abglib.verdicts.readings`: a number unrelated to the
    study, printed with the same precision, is taken as uniform over the printed decade of
    ``text`` on its side of zero: the numbers ``10^d, 10^d + u, ..., 10^(d+1) - u`` with
    ``d = floor(log10|p|)`` and ``u`` the printed unit, each owning the cell of one unit
    around it, so the span is ``[10^d - u/2, 10^(d+1) - u/2)`` (``'.135'`` →
    [0.0995, 0.9995), ``'1452'`` → [999.5, 9999.5)); a printed zero spans the numbers
    ``0 .. 9u``. The span holds ``9 * 10^(s-1)`` numbers of the printed precision for
    ``s`` significant digits.

    Returns
    -------
    (low, high) : floats with ``low < high``.
    """
    p = parse_printed(text)
    unit = printed_unit(text)
    if p == 0:
        lo, hi = 0.0, 10.0 * unit
    else:
        d = math.floor(math.log10(abs(float(p))))
        lo, hi = 10.0**d, 10.0 ** (d + 1)
    # each printed number owns the cell of one unit around it: the span of the numbers
    # 10^d, 10^d + u, ..., 10^(d+1) - u is [10^d - u/2, 10^(d+1) - u/2)
    lo, hi = lo - unit / 2, hi - unit / 2
    if p < 0:
        lo, hi = -hi, -lo
    return lo, hi


def within_tolerance(a: float, b: float, tolerance: float) -> bool:
    """Whether ``a`` and ``b`` differ by at most ``tolerance`` (with the binary slack
    ``_TOL_SLACK``, so that an error of exactly half a unit in the last digit counts as
    within): the one rule of a match and of a value that did not move."""
    return abs(float(a) - float(b)) <= tolerance * (1.0 + _TOL_SLACK)


def format_number(x, digits: int = SIGNIFICANT_DIGITS) -> str:
    """Format a number with ``digits`` significant digits, deterministically.

    Empty string for ``None``/NaN; booleans as ``True``/``False``; ``-0`` becomes ``0``.
    """
    if x is None:
        return ""
    if isinstance(x, (bool, np.bool_)):
        return "True" if x else "False"
    if isinstance(x, str):
        return x
    xf = float(x)
    if math.isnan(xf):
        return ""
    if xf == 0.0:
        return "0"
    return f"{xf:.{digits}g}"
