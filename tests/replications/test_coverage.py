"""Every published claim of every document resolves to one declaration and has a unit test."""

from __future__ import annotations

import pytest

from abglib.replications import DOCS, claims_of

from .conftest import published


@pytest.mark.parametrize("doc", DOCS)
def test_every_published_key_has_exactly_one_claim(doc):
    claims, _ = claims_of(doc)
    resolved = claims.resolve(published(doc)["key"])
    assert set(resolved) == set(published(doc)["key"])


@pytest.mark.parametrize("doc", DOCS)
def test_every_claim_has_a_unit_test(doc, request):
    """Counts the ``claim`` marks of the tests collected in this session; runs only when the
    whole ``tests/replications`` folder was collected (a partial run cannot judge)."""
    markexpr = request.config.option.markexpr
    if request.config.option.keyword or markexpr not in ("", "not install"):
        pytest.skip("a run filtered with -k or -m cannot judge coverage")
    items = request.session.items
    modules = {item.module.__name__.rsplit(".", 1)[-1] for item in items}
    if f"test_{doc}_claims" not in modules:
        pytest.skip(f"tests/replications/test_{doc}_claims.py was not collected in this run")
    covered = set()
    for item in items:
        for mark in item.iter_markers("claim"):
            if mark.kwargs.get("doc") == doc:
                covered.add(mark.kwargs["key"])
    keys = set(published(doc)["key"])
    missing = sorted(keys - covered)
    assert not missing, f"{doc}: {len(missing)} claims without a unit test: {missing}"
    assert not sorted(covered - keys), "tests mark keys that are not published"
