"""Every published claim of every document resolves to one declaration and has a unit test."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from abglib.replications import DOCS, claims_of

from ..conftest import COLLECTED, claim_marks
from .conftest import ROOT, published


@pytest.mark.parametrize("doc", DOCS)
def test_every_published_key_has_exactly_one_claim(doc):
    claims, _ = claims_of(doc)
    resolved = claims.resolve(published(doc)["key"])
    assert set(resolved) == set(published(doc)["key"])


def _collected_here(session) -> list | None:
    """This session's items before any deselection, when it collected every claim test
    (the whole of each ``test_<doc>_claims.py``); None otherwise."""
    items = session.stash.get(COLLECTED, None)
    if items is None or any("::" in str(arg) for arg in session.config.args):
        return None  # a node id collects part of a module
    modules = {item.module.__name__.rsplit(".", 1)[-1] for item in items if hasattr(item, "module")}
    return items if {f"test_{doc}_claims" for doc in DOCS} <= modules else None


def _collect_in_a_subprocess(tmp: Path) -> dict[str, list[str]]:
    """Collect ``tests/replications`` with no selection (``-o addopts=``: no ``-m``) in a
    subprocess; tests/conftest.py writes the claim marks to ``ABGLIB_CLAIM_MARKS``."""
    out = tmp / "claim_marks.json"
    env = dict(os.environ, ABGLIB_CLAIM_MARKS=str(out))
    cmd = [sys.executable, "-m", "pytest", "--collect-only", "-q", "-p", "no:cacheprovider"]
    run = subprocess.run(
        [*cmd, "-o", "addopts=", str(ROOT / "tests" / "replications")],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert run.returncode == 0 and out.is_file(), run.stdout[-3000:] + run.stderr[-3000:]
    record = json.loads(out.read_text(encoding="utf-8"))
    missing = {f"test_{doc}_claims" for doc in DOCS} - {
        m.rsplit(".", 1)[-1] for m in record["modules"]
    }
    assert not missing, f"not collected: {sorted(missing)}"
    return record["claims"]


@pytest.fixture(scope="module")
def covered(request, tmp_path_factory) -> dict[str, list[str]]:
    """``{doc: keys}`` of every test marked ``claim``, whatever this run selects (-m, -k)."""
    items = _collected_here(request.session)
    if items is not None:
        return claim_marks(items)
    return _collect_in_a_subprocess(tmp_path_factory.mktemp("coverage"))


@pytest.mark.parametrize("doc", DOCS)
def test_every_claim_has_a_unit_test(doc, covered):
    """Every published key of ``doc`` is the ``claim`` mark of some test, and every mark is a
    published key. Counted over all tests of ``tests/replications`` before any deselection
    (this session's, or a collection of its own when this session collected part of them),
    so that it judges the same under any ``-m`` or ``-k`` and when run alone."""
    keys = set(published(doc)["key"])
    marked = set(covered.get(doc, ()))
    missing = sorted(keys - marked)
    assert not missing, f"{doc}: {len(missing)} claims without a unit test: {missing}"
    assert not sorted(marked - keys), "tests mark keys that are not published"
    assert marked, doc
