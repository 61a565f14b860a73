"""Input checks shared by every public function.

One place for the wording of errors, so that messages name the parameter, the rule it
broke and the value it got (python-control style), and tests can pin them.
"""

from __future__ import annotations

import numbers

import numpy as np

__all__ = [
    "AbglibValueError",
    "as_float_array",
    "check_finite",
    "check_in_range",
    "check_positive",
    "describe",
]


class AbglibValueError(ValueError):
    """A parameter outside its allowed domain. Subclass of :class:`ValueError`."""


def describe(value) -> str:
    """Short printable form of a (possibly array) value for an error message."""
    arr = np.asarray(value)
    if arr.ndim == 0:
        v = arr.item()
        return repr(float(v)) if isinstance(v, numbers.Real) else repr(v)
    if arr.size <= 6:
        return np.array2string(arr, separator=", ", precision=6)
    return f"array of shape {arr.shape}"


def _first_bad(arr: np.ndarray, bad: np.ndarray) -> str:
    """Describe the first offending element of ``arr`` where ``bad`` is True."""
    if arr.ndim == 0:
        return describe(arr)
    idx = tuple(int(i) for i in np.argwhere(bad)[0])
    return f"{describe(arr[idx])} at index {idx if len(idx) > 1 else idx[0]}"


def as_float_array(name: str, value) -> np.ndarray:
    """Convert ``value`` to a float64 array, or raise naming ``name``.

    Only real numbers are accepted: a string (even ``"0.3"``), ``None``, a boolean or a
    complex value is refused instead of being parsed, turned into NaN, read as 1 or 0, or
    cast to its real part.
    """
    if value is None or isinstance(value, (str, bytes)):
        raise AbglibValueError(f"{name} must be a real number or array of them, got {value!r}")
    arr = np.asarray(value)
    if arr.dtype.kind in "USV":
        raise AbglibValueError(
            f"{name} must be a real number or array of them, got strings ({describe(arr)})"
        )
    if arr.dtype.kind == "b":
        raise AbglibValueError(
            f"{name} must be a real number or array of them, got booleans "
            f"({value if arr.ndim == 0 else describe(arr)}); pass 1.0 / 0.0 if that is meant"
        )
    if arr.dtype.kind == "c":
        raise AbglibValueError(
            f"{name} must be real, got complex values ({describe(arr)}); pass {name}.real or "
            f"abs({name}) explicitly"
        )
    if arr.dtype.kind == "O":
        for v in arr.flat:
            if not isinstance(v, numbers.Real):
                raise AbglibValueError(
                    f"{name} must be a real number or array of them, got an element {v!r}"
                )
    try:
        return np.asarray(arr, dtype=np.float64)
    except (TypeError, ValueError) as exc:
        raise AbglibValueError(
            f"{name} must be a real number or array of them, got {value!r}"
        ) from exc


def check_finite(name: str, value) -> np.ndarray:
    """Return ``value`` as float64, raising if any element is NaN or infinite."""
    arr = as_float_array(name, value)
    bad = ~np.isfinite(arr)
    if bad.any():
        raise AbglibValueError(f"{name} must be finite, got {_first_bad(arr, bad)}")
    return arr


def check_positive(name: str, value) -> np.ndarray:
    """Return ``value`` as float64, raising unless every element is finite and > 0."""
    arr = check_finite(name, value)
    bad = arr <= 0
    if bad.any():
        raise AbglibValueError(f"{name} must be > 0, got {_first_bad(arr, bad)}")
    return arr


def check_in_range(
    name: str,
    value,
    low: float | None = None,
    high: float | None = None,
    *,
    low_inclusive: bool = False,
    high_inclusive: bool = False,
) -> np.ndarray:
    """Return ``value`` as float64, raising unless ``low (<)<= value (<)<= high``.

    The message spells the interval the way a reader would, e.g.
    ``"theta must satisfy 0 <= theta < 1, got 1.2"``.
    """
    arr = check_finite(name, value)
    bad = np.zeros(arr.shape, dtype=bool)
    if low is not None:
        bad |= (arr < low) if low_inclusive else (arr <= low)
    if high is not None:
        bad |= (arr > high) if high_inclusive else (arr >= high)
    if bad.any():
        parts = []
        if low is not None:
            parts.append(f"{low:g} {'<=' if low_inclusive else '<'} ")
        parts.append(name)
        if high is not None:
            parts.append(f" {'<=' if high_inclusive else '<'} {high:g}")
        raise AbglibValueError(f"{name} must satisfy {''.join(parts)}, got {_first_bad(arr, bad)}")
    return arr


def scalar_or_array(arr):
    """A Python scalar (bool for boolean, else float) for 0-d input, else the array.

    scipy's scalar-in, scalar-out convention, shared by every function that accepts a
    scalar gain set or a bank.
    """
    arr = np.asarray(arr)
    if arr.ndim:
        return arr
    return bool(arr) if arr.dtype == bool else float(arr)
