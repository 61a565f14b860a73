"""The digits each table column is reproducible to, derived by perturbing the computation.

Every number a build writes carries only the digits that survive a perturbation of the
computation itself (``shared/CONTRACTS.md`` §3), so that a build on any CPU, BLAS kernel
or supported dependency set verifies against the release (``abglib verify``).

How the digits are found (``abglib precision``, :func:`derive_precision`):

1. The table targets of a config (:data:`TABLE_TARGETS`) are built ``1 + runs`` times in
   fresh directories, with every float written at :data:`abglib.common.tables.RAW_DIGITS`
   significant digits (``ABGLIB_RAW_TABLES=1``: no declared precision, no bounds): once
   plain and once for each perturbation seed ``k = 1..runs`` (``ABGLIB_PERTURB=k``: every
   floating-point input of the numerical core moved by up to 7 ulps,
   :mod:`abglib._perturb`).
2. For each numeric cell, its deviation ``e`` is the largest difference between a
   perturbed run and the plain one, times the safety factor :data:`SAFETY`. A cell
   written with ``n`` significant digits is reproducible when one unit of its last digit
   is at least ``2 e`` (it can then only flip by one unit at a rounding boundary, which
   ``abglib verify`` accepts): ``n = floor(log10|x|) + 1 - log10(2 e)``.
3. A cell that keeps fewer than :data:`MIN_DIGITS` digits is round-off (a value that is
   zero in exact arithmetic, a residual between two exact routes): its column gets a bound
   ``<B``, the smallest power of ten above every such cell (plus its deviation) that no
   other cell comes within its deviation of. The column's spec is then ``"<B:n"`` (the
   others at ``n`` digits), ``"<B"`` when every cell is round-off, or ``n`` when none is;
   ``n`` is the fewest digits any cell above the bound keeps, at most the config's
   ``significant_digits``.
4. The specs of every config derived are merged (the stricter wins) into
   :mod:`abglib.common._precision_table`, a generated module that
   :func:`abglib.common.tables.precision_for` reads whenever
   :func:`~abglib.common.tables.write_csv` writes a table: a new table gets its precision
   by running the command again, and a column with no derived spec keeps the config's
   digits (or what the code that makes it declares; the stricter of the two wins).

Text cells (notes, verdicts) that differ between the runs are listed by the command: a
note must write a round-off number as a bound (:func:`abglib.common.tables.roundoff`)
and a verdict must not move, so each such cell is a bug to fix, not a precision to derive.
"""

from __future__ import annotations

import math
import os
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .._checks import AbglibValueError
from ..common.files import atomic_output
from ..common.tables import RAW_ENV, _parse, _spec, merge_specs, stricter, table_key

__all__ = [
    "MIN_DIGITS",
    "SAFETY",
    "TABLE_TARGETS",
    "ColumnPrecision",
    "Derivation",
    "column_spec",
    "derive_folders",
    "write_table_module",
]

#: the observed perturbation deviation is multiplied by this before digits are kept:
#: a handful of seeds samples the deviation, it does not bound it
SAFETY = 10.0
#: a cell reproducible to fewer digits than this is round-off, written as a bound
MIN_DIGITS = 3
#: Snakemake targets that make every table of a build (no figures, no reports)
#: (rule ``tables``, workflow/rules/compare.smk; the datasets for their bytes)
TABLE_TARGETS = ("datasets", "tables")


# --------------------------------------------------------------------------- derivation
def _pow10_above(x: float) -> float:
    """The smallest power of ten strictly above ``x`` (> 0)."""
    return 10.0 ** (math.floor(math.log10(x)) + 1)


def column_spec(
    values: np.ndarray,
    cap: int = 10,
    safety: float = SAFETY,
    min_digits: int = MIN_DIGITS,
):
    """The precision spec of one column from its values in every run.

    Parameters
    ----------
    values : array (runs, rows)
        Row 0 is the plain build, the others perturbed builds (NaN where empty). A cell
        that is NaN in some runs and not in others cannot be reproduced at all.
    cap : int
        The most digits written (the config's ``significant_digits``).
    safety, min_digits : float, int
        :data:`SAFETY` and :data:`MIN_DIGITS`.

    Returns
    -------
    int, str or None
        ``None`` when every cell keeps ``cap`` digits, else ``n``, ``"<B:n"`` or ``"<B"``
        (:func:`abglib.common.tables.format_cell`).

    Raises
    ------
    AbglibValueError
        When a cell is empty in some runs only (no precision makes it reproducible).
    """
    values = np.asarray(values, dtype=float)
    if values.ndim != 2 or values.shape[0] < 2:
        raise AbglibValueError(f"values must be (runs >= 2, rows), got shape {values.shape}")
    nan = np.isnan(values)
    partly = nan.any(axis=0) & ~nan.all(axis=0)
    if partly.any():
        raise AbglibValueError(
            f"{int(partly.sum())} cells are empty in some runs only (first at row "
            f"{int(np.argmax(partly))})"
        )
    ok = ~nan[0]
    x = values[0, ok]
    other = values[1:, ok]
    with np.errstate(invalid="ignore"):  # inf - inf: equal infinities do not move
        moved = np.where(other == x, 0.0, np.abs(other - x))
    dev = safety * np.max(np.nan_to_num(moved, nan=np.inf), axis=0)
    ax = np.abs(x)
    with np.errstate(divide="ignore"):
        keep = np.where(
            dev == 0,
            np.inf,
            np.floor(np.floor(np.log10(np.where(ax > 0, ax, 1.0))) + 1 - np.log10(2 * dev)),
        )
    keep = np.where((ax == 0) & (dev > 0), -np.inf, keep)
    noise = keep < min_digits
    bound = None
    if noise.any():
        bound = _pow10_above(float(np.max(ax[noise] + dev[noise])))
        # no cell may sit within its deviation of the bound: written as a bound here and
        # as a number on another machine (or the reverse) would not verify
        while np.any(np.abs(ax - bound) <= dev):
            bound *= 10.0
        noise = ax < bound
    rest = keep[~noise]
    digits = int(min(cap, rest.min())) if rest.size else None
    if digits is not None and digits < 1:
        digits = 1
    if bound is None:
        return None if digits is None or digits >= cap else digits
    return _spec(bound, digits)


@dataclass
class ColumnPrecision:
    """One column's derivation: its spec and what it rests on."""

    table: str
    column: str
    spec: object
    cells: int
    roundoff_cells: int
    largest_deviation: float


@dataclass
class Derivation:
    """What :func:`derive_folders` found: the specs, and what no spec can fix."""

    columns: list[ColumnPrecision] = field(default_factory=list)
    #: ``(table, row, column, plain, perturbed)`` of text cells that moved
    text_differences: list[tuple[str, int, str, str, str]] = field(default_factory=list)
    #: tables whose shape differs between runs, or cells empty in some runs only
    problems: list[str] = field(default_factory=list)

    def specs(self) -> dict[str, dict[str, object]]:
        out: dict[str, dict[str, object]] = {}
        for c in self.columns:
            if c.spec is not None:
                dest = out.setdefault(c.table, {})
                dest[c.column] = stricter(dest.get(c.column), c.spec)
        return out


def _number(text: str) -> float | None:
    if text == "":
        return math.nan
    try:
        return float(text)
    except ValueError:
        return None


def _is_int(text: str) -> bool:
    return text.lstrip("-").isdigit()


def derive_folders(
    plain: Path, perturbed: Sequence[Path], cap: int = 10, skip: Iterable[str] = ("engine_speed",)
) -> Derivation:
    """Derive the spec of every float column of every CSV under ``plain`` (a raw build's
    ``results/``) from the same tables under each of ``perturbed``.

    A column is numeric when every cell of it parses as a float in every run; integer
    columns (counts) must be equal and get no spec; other columns are text and must be
    identical (each difference is listed). Tables whose stem is in ``skip`` (wall-clock
    timings) are left out.
    """
    import csv

    def read(path: Path) -> list[list[str]]:
        with path.open(newline="", encoding="utf-8") as fh:
            return list(csv.reader(fh))

    out = Derivation()
    skip = set(skip)
    for path in sorted(Path(plain).rglob("*.csv")):
        if path.stem in skip:
            continue
        rel = path.relative_to(plain)
        key = table_key(rel)
        runs = [read(path)]
        for other in perturbed:
            q = Path(other) / rel
            if not q.is_file():
                out.problems.append(f"{rel}: missing from {other}")
                break
            runs.append(read(q))
        else:
            shapes = {(len(r), tuple(r[0]) if r else ()) for r in runs}
            if len(shapes) != 1:
                out.problems.append(f"{rel}: rows or columns differ between runs")
                continue
            if not runs[0]:
                continue
            header = runs[0][0]
            for j, col in enumerate(header):
                _derive_column(out, rel, key, col, [[row[j] for row in r[1:]] for r in runs], cap)
    return out


def _derive_column(out: Derivation, rel, key: str, col: str, cells, cap: int) -> None:
    """One column of one table in every run (``cells[run][row]``, text as written): its
    numeric rows give the spec, its text rows (a qualitative claim's ``True`` among the
    reproduced numbers, notes, verdicts) must be identical, as must a column of counts."""
    rows = list(zip(*cells, strict=True))
    numeric = [all(_number(t) is not None for t in texts) for texts in rows]
    # a column of counts: whole numbers in every run (a float column's whole values, e.g.
    # a bias of exactly -8, are written so too, but move to a fraction in some run)
    counts = all(numeric) and all(_is_int(t) or t == "" for run in cells for t in run)
    for i, texts in enumerate(rows, start=1):
        if (not numeric[i - 1] or counts) and len(set(texts)) > 1:
            moved = next(t for t in texts[1:] if t != texts[0])
            out.text_differences.append((str(rel), i, col, texts[0], moved))
    if counts or not any(numeric):
        return
    values = np.array(
        [
            [_number(texts[k]) for texts, n in zip(rows, numeric, strict=True) if n]
            for k in range(len(cells))
        ],
        dtype=float,
    )
    try:
        spec = column_spec(values, cap)
    except AbglibValueError as exc:
        out.problems.append(f"{rel}, column {col}: {exc}")
        return
    with np.errstate(invalid="ignore"):
        diff = np.where(values[1:] == values[0], 0.0, np.abs(values[1:] - values[0]))
    out.columns.append(
        ColumnPrecision(
            key,
            col,
            spec,
            values.shape[1],
            _roundoff_cells(values, spec),
            float(np.nan_to_num(diff, nan=0.0).max()) if diff.size else 0.0,
        )
    )


def _roundoff_cells(values: np.ndarray, spec) -> int:
    if not isinstance(spec, str):
        return 0
    bound, _ = _parse(spec)
    x = values[0]
    return int(np.sum(np.abs(x[~np.isnan(x)]) < bound))


def write_table_module(specs: Mapping[str, Mapping[str, object]], path: Path, how: str) -> None:
    """Write the generated module :mod:`abglib.common._precision_table`."""
    lines = [
        '"""Derived precision of every table column (generated by ``abglib precision``; do not',
        "edit by hand: run the command again). See :mod:`abglib.reporting.precision`.",
        "",
        f"Derived by: {how}",
        '"""',
        "",
        "# {table key (folder/stem): {column: spec}}; spec: digits, '<bound' or '<bound:digits'",
        "PRECISION = {",
    ]
    for key in sorted(specs):
        cols = specs[key]
        if not cols:
            continue
        lines.append(f"    {key!r}: {{")
        for col in sorted(cols):
            lines.append(f"        {col!r}: {cols[col]!r},")
        lines.append("    },")
    lines.append("}")
    text = "\n".join(lines) + "\n"
    with atomic_output(path) as tmp:
        tmp.write_text(text, encoding="utf-8")


# --------------------------------------------------------------------------- the command
def build_tables(
    workdir: Path,
    configfile: Path,
    seed: int,
    cores: int = 2,
    snakefile: Path | None = None,
    raw: bool = True,
    targets: Sequence[str] = TABLE_TARGETS,
) -> Path:
    """Build the table targets of ``configfile`` in ``workdir`` (a fresh directory), raw
    (``ABGLIB_RAW_TABLES=1``) and perturbed with seed ``seed`` (0: plain); returns its
    ``results/``. Raises with the end of Snakemake's log when the build fails."""
    import subprocess
    import sys

    snakefile = Path(snakefile) if snakefile else Path(__file__).resolve().parents[2] / "Snakefile"
    if not snakefile.is_file():
        raise AbglibValueError(f"no Snakefile at {snakefile}; run from a clone of the project")
    exe = Path(sys.executable).parent / "snakemake"
    env = dict(os.environ)
    env[RAW_ENV] = "1" if raw else "0"
    from .._perturb import ENV as PERTURB_ENV

    env[PERTURB_ENV] = str(int(seed))
    cmd = [
        str(exe) if exe.exists() else "snakemake",
        "-s",
        str(snakefile),
        "-d",
        str(workdir),
        "--configfile",
        str(Path(configfile).resolve()),
        f"-c{int(cores)}",
        "--",
        *targets,
    ]
    out = subprocess.run(cmd, capture_output=True, text=True, env=env)
    if out.returncode != 0:
        raise AbglibValueError(
            f"the build of {configfile} (perturbation seed {seed}) failed:\n"
            + (out.stdout + out.stderr)[-3000:]
        )
    return Path(workdir) / "results"


def derive_precision(
    configfiles: Sequence[Path], runs: int = 3, cores: int = 2, workdir: Path | None = None
) -> tuple[dict, list[Derivation]]:
    """Build every config plain and under ``runs`` perturbation seeds, derive each
    column's spec (:func:`derive_folders`) and merge them over the configs."""
    import tempfile

    if runs < 2:
        raise AbglibValueError(f"runs must be >= 2 perturbation seeds, got {runs}")
    derivations = []
    with tempfile.TemporaryDirectory(prefix="abglib-precision-") as tmp:
        root = Path(workdir) if workdir else Path(tmp)
        for i, cfg in enumerate(configfiles):
            dirs = [
                build_tables(root / f"config{i}" / f"seed{k}", cfg, k, cores)
                for k in range(runs + 1)
            ]
            derivations.append(derive_folders(dirs[0], dirs[1:]))
    return merge_specs(*(d.specs() for d in derivations)), derivations
