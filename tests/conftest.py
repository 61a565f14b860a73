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

Speed (issue 24). ``pytest`` runs on every core (``-n auto --dist loadgroup``, pyproject.toml).
Tests marked ``install``, ``slurm`` or ``docs`` run only when the ``-m`` expression names
their marker (``pytest -m docs``), so that any other ``-m`` (the development loop
``pytest -m "not slow"``) still leaves them out. ``pipeline`` and ``browser`` tests are
``slow`` too. One small build (``small_build``: ``snakemake -c2`` of
``tests/data/config_small.yaml``) is made once per session, shared by every xdist worker
through a file lock (:func:`shared_dir`), and read, or copied and extended, by every test
that needs a build; the tests that read it share an xdist group, so they run on one worker
while the other runs unit tests.
"""

from __future__ import annotations

import os as _os
import sys as _sys

from ._numba_warm import NUMBA_BASE

# The tests write Python's bytecode (``__pycache__``, ignored by git) even where the
# environment sets PYTHONDONTWRITEBYTECODE (as many container images do, this project's
# machines among them): without it every pytest-xdist worker rewrote the asserts of every
# test module again on every run (about 5 s a worker) and every job of a build compiled
# abglib afresh. The development loop took 33.5 and 35.7 s with it set, 26.1 and 27.3 s
# without (2026-12-02, issue 24). Unset here, the builds and workers started later inherit it.
if _os.environ.pop("PYTHONDONTWRITEBYTECODE", None) is not None:
    _sys.dont_write_bytecode = False

# Each pytest-xdist worker compiles into its own numba cache (before numba is imported; the
# builds a test starts inherit it). Two workers writing one cache at once on a cold clone
# segfaulted a worker inside a cached gufunc (.ci/run, 2026-12-02: "Fatal Python error:
# Segmentation fault" in abglib.engine.track, called through numba's gufunc __call__).
# The folder gets the session's warm cache part by part (warm_numba: the engine's before
# the first test), so the loops every worker and every small build needs are compiled once
# (issue 24).
if _os.environ.get("PYTEST_XDIST_WORKER"):
    _os.environ["NUMBA_CACHE_DIR"] = str(NUMBA_BASE / _os.environ["PYTEST_XDIST_WORKER"])

import contextlib
import importlib
import json
import os
import re
import shutil
import subprocess
import sys
import time
import traceback
from collections.abc import Callable
from pathlib import Path

import pytest
from hypothesis import settings

from . import _numba_warm

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


#: Markers whose tests run only when the ``-m`` expression names them (``pytest -m docs``).
OPT_IN = ("install", "slurm", "docs")
#: Markers that make a test ``slow`` (left out of the development loop ``-m "not slow"``).
SLOW = ("pipeline", "browser", *OPT_IN)


def opted_in(markexpr: str) -> set[str]:
    """The :data:`OPT_IN` markers that the ``-m`` expression ``markexpr`` names."""
    return {m for m in OPT_IN if re.search(rf"\b{m}\b", markexpr or "")}


@pytest.hookimpl(tryfirst=True)
def pytest_collection_modifyitems(session, config, items):
    session.stash[COLLECTED] = list(items)
    out = os.environ.get("ABGLIB_CLAIM_MARKS")
    if out:
        modules = sorted({item.module.__name__ for item in items if hasattr(item, "module")})
        record = {"modules": modules, "claims": claim_marks(items)}
        Path(out).write_text(json.dumps(record), encoding="utf-8")
    named = opted_in(config.option.markexpr)
    keep, drop = [], []
    for item in items:
        marks = {m.name for m in item.iter_markers()}
        if any(m in marks for m in SLOW) and "slow" not in marks:
            item.add_marker(pytest.mark.slow)
        # a module-scoped build (docs, slurm) stays on one xdist worker
        for m in OPT_IN:
            if m in marks and "xdist_group" not in marks:
                item.add_marker(pytest.mark.xdist_group(m))
        (drop if (marks & set(OPT_IN)) - named else keep).append(item)
    if drop:
        config.hook.pytest_deselected(items=drop)
        items[:] = keep
    # the builds first (a stable sort): pytest-xdist hands out tests in this order, and the
    # long ones reached last left one worker alone with them at the end of the run
    items.sort(key=lambda item: item.get_closest_marker("pipeline") is None)


#: The background compilation of the session's warm numba cache, and the folder it makes
#: (controller only).
WARM_UP = pytest.StashKey[tuple[subprocess.Popen, Path] | None]()


def pytest_configure(config):
    """Before pytest-xdist starts its workers: start compiling the warm numba cache they
    copy part by part (:mod:`tests._numba_warm`, :func:`warm_numba`), unless it is
    complete."""
    if os.environ.get("PYTEST_XDIST_WORKER") or not config.pluginmanager.hasplugin("xdist"):
        return
    if config.getoption("numprocesses", None) and not config.getoption("collectonly"):
        config.stash[WARM_UP] = _numba_warm.start_warm_up()


def pytest_unconfigure(config):
    """A warm-up still running when the session ends (a short run) is stopped."""
    started = config.stash.get(WARM_UP, None)
    if started is not None:
        _numba_warm.stop_warm_up(*started)


#: The parts of the warm numba cache this worker has copied (or given up waiting for).
_SEEDED: set[str] = set()
#: How long a worker waits for the warm cache in all (s), from its first wait.
WARM_WAIT = 600.0
_WAIT_UNTIL: list[float] = []


def _seed_warm_parts(parts, wait: bool) -> None:
    worker = os.environ["PYTEST_XDIST_WORKER"]
    folder = _numba_warm.warm_folder(NUMBA_BASE)
    todo = [p for p in parts if p not in _SEEDED]
    if not wait:
        todo = [p for p in todo if _numba_warm.finished(folder, [p])]
    if todo:
        _WAIT_UNTIL[:] = _WAIT_UNTIL or [time.monotonic() + WARM_WAIT]
        left = max(0.0, _WAIT_UNTIL[0] - time.monotonic())
        _numba_warm.wait_for_warm_cache(folder, todo, timeout=left)
        _numba_warm.seed_numba_cache(folder, NUMBA_BASE / worker, todo)
        _SEEDED.update(todo)


def warm_numba(item) -> None:
    """A pytest-xdist worker's numba cache gets the session's warm cache (the warm-up the
    controller started), before a test's fixtures are set up: the engine's part before its
    first test, every part before a build (marker ``pipeline``) or a test with "antenna" in
    its id, and any part as soon as it is finished. So the unit tests start while the
    antenna's loops still compile."""
    if not os.environ.get("PYTEST_XDIST_WORKER") or _SEEDED >= set(_numba_warm.PARTS):
        return
    _seed_warm_parts(["engine"], wait=True)
    every = item.get_closest_marker("pipeline") is not None or "antenna" in item.nodeid
    _seed_warm_parts(list(_numba_warm.PARTS), wait=every)


def freeze_collected() -> None:
    """Collect the collection's garbage once, then move every object still alive (the
    scientific stack's modules, numba's dispatchers, about 2,000 test items: some 400,000
    objects a worker) into the garbage collector's permanent generation (:func:`gc.freeze`),
    so that the full collections the tests trigger, and pytest's own at the session's end,
    no longer traverse them. They live until the worker exits anyway (an object frozen here
    that later becomes cyclic garbage is never freed); what the tests create is collected
    as before. A worker spent 3.8-4.2 s of a fast loop in the collector, 1.3-1.9 s with
    them frozen (issue 24, 2026-12-02)."""
    import gc

    gc.collect()
    gc.freeze()


def usable_cores() -> int:
    """The cores this process may run on (its CPU affinity where the system says, as
    pytest-xdist's ``-n auto`` counts them), at least 1."""
    if hasattr(os, "sched_getaffinity"):
        return max(1, len(os.sched_getaffinity(0)))
    return max(1, os.cpu_count() or 1)


def share_blas_cores() -> int:
    """Limit a pytest-xdist worker's BLAS/LAPACK pools (numpy's and scipy's OpenBLAS) to
    its share of the cores, ``usable_cores() // workers`` (at least 1), and return it.

    OpenBLAS starts a thread per core and, after each call, keeps its idle threads
    spinning for a while before they sleep. Two workers on two cores, each making
    thousands of tiny BLAS/LAPACK calls on two threads (the studies of the claim tests,
    outside :func:`abglib.replications.one_blas_thread`), competed for four: the
    development loop took 50-56 CPU-s with the pools as they were and 43.6-45.2 CPU-s with
    this limit (2026-12-04, issue 24). The builds and dry runs a test starts are
    processes of their own and keep OpenBLAS's default, as a user's build does. scikit-learn's
    test suite limits its workers the same way. The libraries must be loaded first
    (threadpoolctl limits the loaded ones), so numpy's and scipy's linear algebra are
    imported here."""
    import numpy  # noqa: F401
    import scipy.linalg  # noqa: F401
    from threadpoolctl import threadpool_limits

    workers = int(os.environ.get("PYTEST_XDIST_WORKER_COUNT", "1"))
    share = max(1, usable_cores() // max(1, workers))
    threadpool_limits(limits=share, user_api="blas")  # held until changed: no restore on exit
    return share


#: Why this worker's tests cannot run as scheduled ("" if they can).
GROUPS_LOST = pytest.StashKey[str]()


def pytest_collection_finish(session):
    """Give a pytest-xdist worker its share of the BLAS cores (:func:`share_blas_cores`),
    freeze what the imports and the collection made (:func:`freeze_collected`), and fail
    every test of a pytest-xdist worker whose ``--dist loadgroup`` groups nothing.

    pytest-xdist marks a grouped test by appending ``@<group>`` to its node id; pytest 9.2
    made node ids structured and the suffix is lost, so every test is scheduled alone
    (pytest-dev/pytest-xdist#1386). A module's fixtures would then be built on every
    worker, and the timed pair of tests/test_slurm.py would run at once. pyproject.toml
    keeps pytest below 9.2; this check makes the break loud if that bound is lifted early
    (each test fails with the reason: a worker cannot stop the session cleanly).
    """
    if os.environ.get("PYTEST_XDIST_WORKER"):
        share_blas_cores()
    freeze_collected()
    config = session.config
    config.stash[GROUPS_LOST] = ""
    if not (os.environ.get("PYTEST_XDIST_WORKER") and getattr(config.option, "loadgroup", False)):
        return
    lost = [i.nodeid for i in session.items if i.get_closest_marker("xdist_group")]
    lost = [n for n in lost if "@" not in n]
    if lost:
        config.stash[GROUPS_LOST] = (
            f"pytest-xdist --dist loadgroup groups nothing on pytest {pytest.__version__} "
            f"({len(lost)} grouped tests without their @group, e.g. {lost[0]}; "
            'pytest-dev/pytest-xdist#1386): install pytest<9.2 (pip install -e ".[dev]") '
            "or run without workers (-n 0)"
        )


@pytest.hookimpl(tryfirst=True)
def pytest_runtest_setup(item):
    """Before the test's fixtures: fail if its groups are lost, give the worker the warm
    numba cache it needs (:func:`warm_numba`)."""
    lost = item.config.stash.get(GROUPS_LOST, "")
    if lost:
        pytest.fail(lost, pytrace=False)
    warm_numba(item)


# ------------------------------------------------------------------ one build per session
REPO = Path(__file__).resolve().parents[1]
SMALL = REPO / "tests" / "data" / "config_small.yaml"
SNAKEMAKE = Path(sys.executable).parent / "snakemake"
#: The xdist group of the tests that read the small build (one worker runs them all).
SMALL_BUILD = "small_build"


def snakemake(workdir: Path, *args: str, configs=(SMALL,), env=None, snakefile=None):
    """``snakemake -s <repo>/Snakefile -d workdir --configfile <configs> <args>``."""
    exe = str(SNAKEMAKE) if SNAKEMAKE.exists() else "snakemake"
    cmd = [exe, "-s", str(snakefile or REPO / "Snakefile"), "-d", str(workdir)]
    cmd += ["--configfile", *map(str, configs), *args]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=900, env=env)


@contextlib.contextmanager
def _file_lock(path: Path):
    """An exclusive lock on ``path`` (fcntl.flock; released when the file is closed)."""
    import fcntl

    with open(path, "a+") as f:
        fcntl.flock(f, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(f, fcntl.LOCK_UN)


def shared_dir(tmp_path_factory, name: str, build: Callable[[Path], None]) -> Path:
    """``<session tmp>/<name>``, made once per test session by ``build(folder)``.

    Under pytest-xdist every worker has its own basetemp below the session's folder; the
    folder and a lock live in that common parent, so the first worker to ask builds and the
    others wait for it and read the result (pytest-xdist's "Making session-scoped fixtures
    execute only once"). A failed build is recorded: every later request fails with its
    message instead of building again."""
    root = tmp_path_factory.getbasetemp()
    if os.environ.get("PYTEST_XDIST_WORKER"):
        root = root.parent
    folder, done, failed = root / name, root / f"{name}.done", root / f"{name}.failed"
    with _file_lock(root / f"{name}.lock"):
        if failed.exists():
            pytest.fail(failed.read_text(encoding="utf-8"), pytrace=False)
        if not done.exists():
            if folder.exists():
                shutil.rmtree(folder)
            folder.mkdir()
            try:
                build(folder)
            except BaseException as exc:
                msg = f"building {name} failed (once for the session): {exc}"
                failed.write_text(msg + "\n" + traceback.format_exc(), encoding="utf-8")
                raise
            done.write_text("built\n", encoding="utf-8")
    return folder


def copy_build(build: Path, dest: Path) -> Path:
    """A copy of a finished build (results, logs and Snakemake's metadata, mtimes kept), in
    which Snakemake schedules only what a change adds: extend the copy, never the original."""
    shutil.copytree(build, dest, symlinks=True, ignore=shutil.ignore_patterns("locks"))
    return dest


#: What a build of this version must leave alone: an older version's report in its folder.
OLD_REPORT = "<html>an older version's report</html>"


def _seed_old_report(d: Path) -> None:
    old = d / "reports" / "v0.0.0" / "steelman1978" / "index.html"
    old.parent.mkdir(parents=True)
    old.write_text(OLD_REPORT, encoding="utf-8")


def _build(d: Path, *args: str, env=None) -> None:
    _seed_old_report(d)
    out = snakemake(d, "-c2", *args, env=env)
    (d / "snakemake.out").write_text(out.stdout + out.stderr, encoding="utf-8")
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]


def _build_perturbed(d: Path) -> None:
    from abglib._perturb import ENV as PERTURB
    from abglib.reporting import precision

    env = dict(os.environ, **{PERTURB: "1"})
    _build(d, "--verbose", "--", *precision.TABLE_TARGETS, env=env)


@pytest.fixture(scope="session")
def small_build(tmp_path_factory) -> Path:
    """The whole small build (``snakemake -c2`` of tests/data/config_small.yaml) in a clean
    working directory holding an older version's report (:data:`OLD_REPORT`), once per
    session; its log in ``snakemake.out``. Read it, or :func:`copy_build` it to extend it."""
    return shared_dir(tmp_path_factory, "small_build", _build)


@pytest.fixture(scope="session")
def perturbed_tables(tmp_path_factory) -> Path:
    """The small config's tables again, with perturbed arithmetic (``ABGLIB_PERTURB``,
    abglib._perturb: every float input of the numerical core moved by up to 7 ulps, what
    another CPU, BLAS kernel or dependency set moves one operation by), in a clean working
    directory, logging the scheduler's rounds (``--verbose``: "Ready jobs: N" once a round)."""
    return shared_dir(tmp_path_factory, "perturbed_tables", _build_perturbed)
