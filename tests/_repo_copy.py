"""A copy of the repository for the tests that edit or extend it (a sixth document, the
edit reruns): its files as git lists them, with abglib's numba cache.

One home for what ``tests/test_new_document.py`` and ``tests/test_workflow.py`` both do.
"""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

from ._numba_warm import seed_copy

REPO = Path(__file__).resolve().parents[1]
#: What the builds in each copy need in their environment (seed_copy), by copy.
_ENV: dict[Path, dict[str, str]] = {}


def copy_repo(dest: Path, parts: tuple[str, ...] | None = None) -> Path:
    """Copy the repository's files into ``dest`` and return ``dest``; run its builds with
    :func:`copy_env`.

    The files are those ``git ls-files`` lists, tracked and new ones not ignored, so no
    build output, cache or ``__pycache__`` comes along; never the release reports or
    ``results/``; with ``parts`` (top-level names such as ``"abglib"`` or
    ``"Snakefile"``), only those. They keep their mtimes (``shutil.copy2``), so the numba
    cache that :func:`tests._numba_warm.seed_copy` gives the copy's abglib stays valid,
    and an edited file still recompiles.
    """
    listed = subprocess.run(
        ["git", "ls-files", "--cached", "--others", "--exclude-standard", "-z"],
        cwd=REPO,
        capture_output=True,
        text=True,
        check=True,
    ).stdout.split("\0")
    for name in listed:
        src = REPO / name
        top = name.split("/", 1)[0]
        if not name or top in ("reports", "results") or not src.is_file():
            continue
        if parts is not None and top not in parts:
            continue
        (dest / name).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(src, dest / name)
    _ENV[dest] = seed_copy(dest, REPO)
    return dest


def copy_env(repo: Path, **extra: str) -> dict[str, str]:
    """The environment of a build in the copy ``repo``: this process's, with the copy's
    numba cache (``NUMBA_CACHE_DIR`` where the copy has a folder of its own), and ``extra``."""
    return {**os.environ, **_ENV.get(repo, {}), **extra}
