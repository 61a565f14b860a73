"""Test configuration: hypothesis under CI, every collected test kept, CI fails what it needs.

Locally hypothesis explores new examples on every run (that is how it finds bugs); on CI
(``CI`` set, as ``.ci/run`` is run) it uses a fixed, derandomised search so that a green
main stays green. Failing examples found locally are pinned as explicit tests.

Every test collected in a session is kept (``COLLECTED``) before ``-m``, ``-k`` or
``--deselect`` drop any, so that ``tests/replications/test_coverage.py`` judges which claims
have a unit test from what exists, whatever a run selects. With ``ABGLIB_CLAIM_MARKS=<path>``
set, the ``claim`` marks of the collected tests are also written there as JSON (the coverage
test collects ``tests/replications`` in a subprocess that way when its session did not).

``require(reason)`` and ``require_module(name)``: a test that needs a tool or an optional
package that CI installs (Chromium, git, nbclient, filterpy, snakemake) skips without it on a
developer's machine and fails under CI (``CI`` set to anything but ``""``, ``0``, ``false``
or ``no``), so that a missing install cannot turn a check into a skip there.
"""

from __future__ import annotations

import importlib
import json
import os
from pathlib import Path

import pytest
from hypothesis import settings

settings.register_profile("ci", derandomize=True, print_blob=True)
if os.environ.get("CI"):
    settings.load_profile("ci")

#: Every item the session collected, before any deselection.
COLLECTED = pytest.StashKey[list]()


def on_ci() -> bool:
    """True when the tests run under CI (``CI=true``, as ``.ci/run`` is run)."""
    return os.environ.get("CI", "").strip().lower() not in ("", "0", "false", "no")


def require(reason: str) -> None:
    """Skip the calling test because ``reason`` (a tool is missing); fail instead under CI."""
    if on_ci():
        pytest.fail(f"CI={os.environ['CI']} but {reason}", pytrace=False)
    pytest.skip(reason)


def require_module(name: str):
    """``pytest.importorskip(name)``, failing instead under CI (where ``.[dev]`` installs it)."""
    if on_ci():
        try:
            return importlib.import_module(name)
        except ImportError as exc:
            msg = f"CI={os.environ['CI']} but {name} cannot be imported: {exc}"
            pytest.fail(msg, pytrace=False)
    return pytest.importorskip(name)


def claim_marks(items) -> dict[str, list[str]]:
    """``{doc: sorted keys}`` of the ``claim(doc, key)`` marks of ``items``."""
    out: dict[str, set[str]] = {}
    for item in items:
        for mark in item.iter_markers("claim"):
            doc, key = mark.kwargs.get("doc"), mark.kwargs.get("key")
            if doc is not None and key is not None:
                out.setdefault(doc, set()).add(key)
    return {doc: sorted(keys) for doc, keys in sorted(out.items())}


@pytest.hookimpl(tryfirst=True)
def pytest_collection_modifyitems(session, config, items):
    session.stash[COLLECTED] = list(items)
    out = os.environ.get("ABGLIB_CLAIM_MARKS")
    if out:
        modules = sorted({item.module.__name__ for item in items if hasattr(item, "module")})
        record = {"modules": modules, "claims": claim_marks(items)}
        Path(out).write_text(json.dumps(record), encoding="utf-8")
