"""pandas internals the reports use, each checked and failing loudly.

For pandas' maintainers, what abglib needs and which public API would replace it:

- **Every option's default, without setting it** (:func:`option_defaults`:
  ``pandas._config.config._registered_options[key].defval`` and
  ``_deprecated_options``): a report notebook runs in the calling process with pandas'
  options as in a fresh kernel, and the caller's options come back afterwards
  (:mod:`abglib.reporting.execute`). ``pandas.reset_option("all")`` would reset them, but
  it sets every option, unchanged ones too, which runs their validators (setting
  ``plotting.backend`` imports the plotting backend, matplotlib) and warns for the
  deprecated ones; and no public function lists the options. Wanted:
  ``pandas.list_options()`` and ``pandas.get_option_default(key)`` (or
  ``describe_option`` returning data).
- **A column formatted as pandas displays it** (:func:`format_column`:
  ``pandas.io.formats.format.format_array``, not in the API reference): the reports'
  HTML tables show each column's cells as ``DataFrame`` display writes them (one common
  number of digits per float column, ``display.precision``), one string per cell.
  ``Series.to_string`` gives one text for the column, with footers for categoricals and
  ``Series([], ...)`` when empty, not the cells. Wanted: a public
  ``Series.format_cells()`` (or ``pandas.io.formats.format.format_array`` documented).

Replaced by a public mechanism: ``Series._values`` (the column's array) is
:func:`column_array`, from ``Series.to_numpy()`` and ``Series.array``.

Checked against pandas 3.1.1 (older sources were not read; the version-range builds run
the checks at the lower bound).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from . import changed

__all__ = ["column_array", "format_column", "option_defaults"]

_HERE = "pandas"
_FORMAT_ARRAY = "pandas.io.formats.format.format_array"


def option_defaults() -> dict:
    """``{key: default}`` of every option pandas registers that is not deprecated.

    Raises
    ------
    UpstreamChanged
        ``pandas._config.config`` has no ``_registered_options`` or ``_deprecated_options``
        mapping, an entry has no ``defval``, or ``display.precision`` is not among them.
    """
    try:
        from pandas._config import config as cf
    except ImportError:
        raise changed(_HERE, "pandas._config.config", "cannot be imported", _HERE) from None
    registered = getattr(cf, "_registered_options", None)
    deprecated = getattr(cf, "_deprecated_options", None)
    for name, value in (("_registered_options", registered), ("_deprecated_options", deprecated)):
        if not isinstance(value, dict):
            raise changed(_HERE, f"pandas._config.config.{name}", "is not a dict", _HERE)
    if "display.precision" not in registered:
        raise changed(
            _HERE,
            "pandas._config.config._registered_options",
            "does not hold display.precision",
            _HERE,
        )
    out = {}
    for key, option in registered.items():
        if key in deprecated:
            continue
        if not hasattr(option, "defval"):
            raise changed(
                _HERE, "pandas._config.config.RegisteredOption.defval", "does not exist", _HERE
            )
        out[key] = option.defval
    return out


def column_array(values: pd.Series):
    """The array behind a column, as display formatting takes it: a NumPy array for a
    NumPy dtype, the extension array (``Series.array``) for an extension dtype and for
    datetimes and timedeltas (``DatetimeArray``, ``TimedeltaArray``): what the internal
    ``Series._values`` gives, through public API."""
    dtype = values.dtype
    if isinstance(dtype, np.dtype) and dtype.kind not in "mM":
        return values.to_numpy()
    return values.array


def format_column(values: pd.Series, digits: int, na_rep: str = "") -> list[str]:
    """Each cell of the column ``values`` as text, as a ``DataFrame`` display writes it
    (``format_array``: one format for the whole column, ``digits`` significant digits for
    floats, ``na_rep`` for missing values), padded to a common width.

    Raises
    ------
    UpstreamChanged
        ``format_array`` is missing, lacks the parameters ``values, formatter`` (first)
        and ``na_rep``, ``digits``, or does not return one string per cell.
    """
    import inspect

    try:
        from pandas.io.formats.format import format_array
    except ImportError:
        raise changed(_HERE, _FORMAT_ARRAY, "does not exist", _HERE) from None
    names = list(inspect.signature(format_array).parameters)
    if names[:2] != ["values", "formatter"] or not {"na_rep", "digits"} <= set(names):
        raise changed(_HERE, _FORMAT_ARRAY, f"takes ({', '.join(names)})", _HERE)
    out = format_array(column_array(values), None, na_rep=na_rep, digits=digits)
    if len(out) != len(values) or not all(isinstance(s, str) for s in out):
        raise changed(_HERE, _FORMAT_ARRAY, "did not return one str per cell", _HERE)
    return list(out)
