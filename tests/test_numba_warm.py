"""The test session's warm numba cache (tests/_numba_warm.py): parts, waiting, copies."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import textwrap
import threading
import time
from pathlib import Path

import pytest

from . import _numba_warm as warm

MODULE = textwrap.dedent(
    """
    from numba import njit


    @njit(cache=True)
    def twice(x):
        return 2.0 * x
    """
)
CALL = (
    "from abglib.loops import twice; twice(1.5); "
    "s = twice.stats; print(sum(s.cache_hits.values()), sum(s.cache_misses.values()))"
)


def _run(src, cache):
    """(cache hits, misses) of calling the loop of ``src``'s abglib with ``cache`` as
    NUMBA_CACHE_DIR (None: numba's default, ``__pycache__`` beside the source)."""
    env = dict(os.environ, PYTHONPATH=str(src))
    env.pop("NUMBA_CACHE_DIR", None)
    if cache is not None:
        env["NUMBA_CACHE_DIR"] = str(cache)
    out = subprocess.run(
        [sys.executable, "-c", CALL], env=env, capture_output=True, text=True, cwd=src
    )
    assert out.returncode == 0, out.stderr[-2000:]
    hits, misses = map(int, out.stdout.split())
    return hits, misses


@pytest.mark.slow  # five processes compiling or loading a loop
def test_a_copy_of_the_sources_loads_the_seeded_loops_instead_of_compiling(tmp_path, monkeypatch):
    """seed_copy names the copy's cache folders as numba does (its one use of numba's
    cache internals): a copy made with its mtimes kept loads the loop from the cache; an
    edited copy compiles it again (numba checks the source's stamp)."""
    repo, cache = tmp_path / "repo", tmp_path / "cache"
    (repo / "abglib").mkdir(parents=True)
    (repo / "abglib" / "__init__.py").write_text("", encoding="utf-8")
    (repo / "abglib" / "loops.py").write_text(MODULE, encoding="utf-8")
    assert _run(repo, cache) == (0, 1)  # compiled and cached
    assert _run(repo, cache) == (1, 0)

    copy = tmp_path / "copy"
    shutil.copytree(repo, copy, ignore=shutil.ignore_patterns("__pycache__"))
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(cache))
    env = warm.seed_copy(copy, repo)
    assert env == {"NUMBA_CACHE_DIR": str(tmp_path / "copy-numba")}  # a folder of its own
    assert len(list((tmp_path / "copy-numba").rglob("*.nb[ic]"))) == 2  # index, overload
    assert _run(copy, env["NUMBA_CACHE_DIR"]) == (1, 0)

    edited = tmp_path / "edited"
    shutil.copytree(repo, edited, ignore=shutil.ignore_patterns("__pycache__"))
    (edited / "abglib" / "loops.py").write_text(MODULE + "\n# edited\n", encoding="utf-8")
    assert _run(edited, warm.seed_copy(edited, repo)["NUMBA_CACHE_DIR"]) == (0, 1)


@pytest.mark.slow  # four processes compiling or loading a loop
def test_a_warm_part_starts_from_what_a_build_compiled(tmp_path):
    """seed_from_builds finds a build's entries where numba put them, in ``__pycache__``
    (no NUMBA_CACHE_DIR: the README's build) or in the tests' base folder (the version
    matrix's build), and the part's cache then loads the loop instead of compiling it."""
    repo, base = tmp_path / "repo", tmp_path / "base"
    (repo / "abglib").mkdir(parents=True)
    (repo / "abglib" / "__init__.py").write_text("", encoding="utf-8")
    (repo / "abglib" / "loops.py").write_text(MODULE, encoding="utf-8")
    base.mkdir()
    assert warm.seed_from_builds(tmp_path / "none", base, repo) == 0  # nothing built yet
    assert _run(repo, None) == (0, 1)  # a build with numba's default: __pycache__
    assert len(list((repo / "abglib" / "__pycache__").glob("*.nb[ic]"))) == 2
    assert warm.seed_from_builds(tmp_path / "part1", base, repo) == 2
    assert _run(repo, tmp_path / "part1") == (1, 0)
    shutil.rmtree(repo / "abglib" / "__pycache__")
    assert _run(repo, base) == (0, 1)  # a build given the tests' base folder
    assert warm.seed_from_builds(tmp_path / "part2", base, repo) == 2
    assert _run(repo, tmp_path / "part2") == (1, 0)


def test_without_a_cache_folder_the_copy_gets_the_pycache_entries(tmp_path, monkeypatch):
    repo, copy = tmp_path / "repo", tmp_path / "copy"
    for d in (repo, copy):
        (d / "abglib" / "sub").mkdir(parents=True)
    cached = repo / "abglib" / "sub" / "__pycache__"
    cached.mkdir()
    for name in ("loops.twice-5.py311.nbi", "loops.twice-5.py311.1.nbc", "loops.pyc"):
        (cached / name).write_bytes(b"x")
    monkeypatch.delenv("NUMBA_CACHE_DIR", raising=False)
    assert warm.seed_copy(copy, repo) == {}
    assert sorted(p.name for p in (copy / "abglib" / "sub" / "__pycache__").iterdir()) == [
        "loops.twice-5.py311.1.nbc",
        "loops.twice-5.py311.nbi",
    ]


def _quick(folder, parts=None):
    """wait_for_warm_cache's answer, which must come at once (not by its timeout)."""
    t = time.monotonic()
    ok = warm.wait_for_warm_cache(folder, parts, timeout=60)
    assert time.monotonic() - t < 5
    return ok


def test_each_part_is_waited_for_on_its_own(tmp_path):
    folder = tmp_path / "warm" / "stamp"
    (folder / "engine").mkdir(parents=True)
    assert warm.finished(folder, ["engine"]) and not warm.finished(folder)
    # no warm-up running (no pid file, a dead pid, a zombie): no waiting
    assert _quick(folder, ["engine"]) and not _quick(folder)
    pid = folder.with_name("stamp.pid")
    code = "import os; print(os.getpid())"
    dead = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True).stdout
    pid.write_text(dead.strip(), encoding="utf-8")
    assert not _quick(folder, ["antenna"])
    zombie = subprocess.Popen([sys.executable, "-c", "pass"])
    stat = Path(f"/proc/{zombie.pid}/stat")
    for _ in range(100):  # until it ended, not reaped: os.kill(pid, 0) still succeeds
        if stat.read_text(encoding="utf-8").rpartition(")")[2].split()[0] == "Z":
            break
        time.sleep(0.05)
    pid.write_text(str(zombie.pid), encoding="utf-8")
    assert not _quick(folder, ["antenna"])
    zombie.wait()
    # a running warm-up: the wait ends when the part appears, or when it failed
    pid.write_text(str(os.getpid()), encoding="utf-8")
    timer = threading.Timer(0.3, (folder / "antenna").mkdir)
    timer.start()
    t = time.monotonic()
    assert warm.wait_for_warm_cache(folder, timeout=60)
    assert 0.25 < time.monotonic() - t < 5
    timer.join()
    folder.with_name("stamp.failed").write_text("gamma: boom", encoding="utf-8")
    assert not _quick(folder, ["gamma"])


def _entry(folder, name, files):
    folder.mkdir(parents=True, exist_ok=True)
    for suffix, text in files.items():
        (folder / f"{name}{suffix}").write_text(text, encoding="utf-8")


def test_seeding_copies_only_the_parts_asked_for_and_whole_entries(tmp_path):
    folder, dest = tmp_path / "warm", tmp_path / "gw0"
    for part in ("engine", "antenna"):
        _entry(folder / part / f"{part}_abc", "m.f-3.py311", {".nbi": part, ".1.nbc": part})
    assert warm.seed_numba_cache(folder, dest, ["engine"]) == 2
    assert [p.name for p in dest.iterdir()] == ["engine_abc"]
    assert warm.seed_numba_cache(folder, dest) == 2  # engine's entry is there already
    assert sorted(p.name for p in dest.iterdir()) == ["antenna_abc", "engine_abc"]
    assert not list(dest.rglob("*.tmp"))


def test_an_entry_the_worker_compiled_is_replaced_whole_or_kept_whole(tmp_path):
    """numba numbers a function's overloads in its index: the worker's own ``.1.nbc`` may
    hold another signature than the warm cache's ``.1.nbc``, so the two never mix."""
    part, dest = tmp_path / "warm" / "antenna" / "lq_abc", tmp_path / "gw0" / "lq_abc"
    _entry(dest, "lq.loop-9.py311", {".nbi": "own", ".1.nbc": "own A", ".2.nbc": "own B"})
    _entry(part, "lq.loop-9.py311", {".nbi": "warm", ".1.nbc": "warm B"})
    old = time.time() - 60
    for f in part.iterdir():  # the worker's entry is newer: kept whole
        os.utime(f, (old, old))
    assert warm.seed_numba_cache(tmp_path / "warm", tmp_path / "gw0") == 0
    assert (dest / "lq.loop-9.py311.1.nbc").read_text(encoding="utf-8") == "own A"
    for f in dest.iterdir():  # the warm cache's entry is newer: replaced whole
        os.utime(f, (old - 60, old - 60))
    assert warm.seed_numba_cache(tmp_path / "warm", tmp_path / "gw0") == 2
    texts = {f.name: f.read_text(encoding="utf-8") for f in dest.iterdir()}
    assert texts == {"lq.loop-9.py311.nbi": "warm", "lq.loop-9.py311.1.nbc": "warm B"}
