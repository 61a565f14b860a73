"""Version folders of the reports (``reports/v<x.y.z>``, ``results/reports/v<x.y.z>``).

Path logic only (no pandas), so that the workflow can find the previous release while it
parses without importing the table code of :mod:`abglib.reporting.changes`.
"""

from __future__ import annotations

import re
from pathlib import Path

from .._checks import AbglibValueError

__all__ = ["comparison_tables", "folder_version", "previous_version", "version_key"]


def version_key(name: str) -> tuple[int, ...] | None:
    """``(0, 3, 0)`` for a folder name ``'v0.3.0'``; None for any other name."""
    m = re.fullmatch(r"v(\d+(?:\.\d+)*)", name)
    return tuple(int(x) for x in m.group(1).split(".")) if m else None


def folder_version(folder) -> str:
    """The version a version folder is named for: ``'0.4.0'`` for ``reports/v0.4.0``.

    Raises
    ------
    AbglibValueError
        When the folder's name is not ``v<x.y.z>`` (``CONTRACTS.md`` §4: ``reports/v<version>/``).
    """
    name = Path(folder).name
    if version_key(name) is None:
        raise AbglibValueError(
            f"a version folder must be named v<version> (e.g. v0.4.0), got {name!r}"
        )
    return name[1:]


def previous_version(releases, version: str) -> Path | None:
    """The folder ``releases/v<x.y.z>`` with the highest version below ``version``, or None."""
    current = version_key(f"v{version}")
    if current is None:
        raise AbglibValueError(f"version must look like 0.3.0, got {version!r}")
    releases = Path(releases)
    found = [
        (v, p)
        for p in (releases.iterdir() if releases.is_dir() else [])
        if p.is_dir() and (v := version_key(p.name)) is not None and v < current
    ]
    return max(found)[1] if found else None


def comparison_tables(folder) -> dict[str, Path]:
    """``{doc: path}`` of every ``<doc>/tables/comparison.csv`` (or ``<doc>/comparison.csv``,
    as under ``results/``) of a version folder."""
    folder = Path(folder)
    if not folder.is_dir():
        raise AbglibValueError(f"a version folder must be a directory, got {str(folder)!r}")
    out = {}
    for sub in sorted(p for p in folder.iterdir() if p.is_dir()):
        for cand in (sub / "tables" / "comparison.csv", sub / "comparison.csv"):
            if cand.is_file():
                out[sub.name] = cand
                break
    return out
