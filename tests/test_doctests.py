"""The tracker core's ``>>>`` examples run as tests (issue 23), as python-control's do.

Every module of the core (``abglib`` without its layers ``bench``, ``replications``,
``reporting``, ``verdicts`` and the upstream shims ``_compat``) is found by walking the
package, so a new core module's examples run without being listed here. Each module with
examples is one test; the examples run with numpy imported as ``np`` and the module's own
namespace, and compare output with ``ELLIPSIS`` and ``NORMALIZE_WHITESPACE`` only.
"""

from __future__ import annotations

import doctest
import importlib
import pkgutil

import numpy as np
import pytest

import abglib

#: the layers above the core and the shims of other libraries' internals
NOT_CORE = ("bench", "replications", "reporting", "verdicts", "_compat")


def core_modules() -> list[str]:
    """Every importable module of the tracker core, sorted."""
    names = ["abglib"]
    for info in pkgutil.walk_packages(abglib.__path__, "abglib."):
        if info.name.split(".")[1] in NOT_CORE:
            continue
        names.append(info.name)
    return sorted(names)


def examples(modname: str) -> list[doctest.DocTest]:
    """The doctests of one module that hold at least one example."""
    finder = doctest.DocTestFinder(exclude_empty=True)
    mod = importlib.import_module(modname)
    globs = {"np": np, **vars(mod)}  # the module's own namespace, as doctest.testmod
    return [t for t in finder.find(mod, globs=globs) if t.examples]


WITH_EXAMPLES = [m for m in core_modules() if examples(m)]


def test_the_core_modules_with_examples_are_found():
    found = set(WITH_EXAMPLES)
    # the core files that held examples when this test was written (issue 23): a walk
    # that misses one of them is broken, not a module without examples
    assert {
        "abglib.gains",
        "abglib.engine",
        "abglib.design",
        "abglib.conventions",
        "abglib.analysis._transfer",
        "abglib.analysis._variance",
        "abglib.analysis._enbw",
    } <= found, found
    assert not any(m.split(".")[1] in NOT_CORE for m in found if "." in m)


@pytest.mark.parametrize("modname", WITH_EXAMPLES)
def test_doctests(modname):
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    report: list[str] = []
    n = 0
    for test in examples(modname):
        runner.run(test, out=report.append)
        n += len(test.examples)
    assert runner.tries == n > 0
    assert runner.failures == 0, "".join(report)
