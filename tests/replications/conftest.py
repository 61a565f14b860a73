"""Shared by the per-document claim tests.

Every published claim of every document has a unit test here, marked
``@claim_test("<doc>", "<key>")`` (or ``pytest.param(key, marks=claim_test(doc, key))`` in
a parametrized family); ``test_coverage.py`` checks that no claim is left without one.
"""

from __future__ import annotations

import functools
from pathlib import Path

import pytest

from abglib.reporting.pipeline import read_yaml

ROOT = Path(__file__).resolve().parents[2]
PUBLISHED = ROOT / "data" / "published"


def claim_test(doc: str, key: str):
    """Mark a test as the unit test of one published claim."""
    return pytest.mark.claim(doc=doc, key=key)


@functools.cache
def repo_config() -> dict:
    """The repository's ``config.yaml`` (the nominal inputs the claims are judged at)."""
    return read_yaml(ROOT / "config.yaml")


@functools.cache
def small_config() -> dict:
    """``config.yaml`` with the small test config merged over it (as Snakemake merges)."""
    cfg = repo_config()
    small = read_yaml(ROOT / "tests" / "data" / "config_small.yaml")
    return _merge(cfg, small)


def _merge(base, over):
    if isinstance(base, dict) and isinstance(over, dict):
        out = dict(base)
        for k, v in over.items():
            out[k] = _merge(base.get(k), v) if k in base else v
        return out
    return over


def published_paths(doc: str) -> list[Path]:
    return sorted((PUBLISHED / doc).glob("*.csv"))


@functools.cache
def published(doc: str):
    from abglib.replications.compare import read_published

    return read_published(published_paths(doc))


def study_for(doc: str, config: dict | None = None, extra: tuple[str, ...] = ()):
    """The study of ``doc`` at ``config`` (default: the repository's config), holding the
    document's section and the ``extra`` top-level sections it reads."""
    from abglib.replications import claims_of

    cfg = config if config is not None else repo_config()
    _, study_cls = claims_of(doc)
    sub = {k: cfg[k] for k in (doc, *extra) if k in cfg}
    return study_cls(sub, published(doc))
