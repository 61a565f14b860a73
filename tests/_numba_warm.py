"""One warm numba cache for a test session, copied into each pytest-xdist worker's own.

With numba's cache cold a small build compiled for about 31 of its 72 CPU-seconds, and
each test worker compiled the same loops again (issue 24). So ``tests/conftest.py`` starts
:func:`start_warm_up` as pytest-xdist starts its workers: the parts of :data:`PARTS` are
compiled at once, each in a process of its own, into ``<base>/warm/<stamp>/<part>``, where
the stamp names the sources (every ``abglib`` file's size and mtime, this file, Python's
and numba's versions) and the folder appears whole or not at all. Before its first test
each worker waits for it (:func:`wait_for_warm_cache`) and copies it into its own cache
folder (:func:`seed_numba_cache`); a build a test starts inherits its worker's folder.
Workers keep folders of their own: two workers writing one cache at once on a cold clone
segfaulted a worker inside a cached gufunc (.ci/run, 2026-12-02). Once compiled, the warm
cache serves every later session until a source changes.

Usage: ``python -m tests._numba_warm <folder>`` builds a warm cache into ``folder``;
``python -m tests._numba_warm --part <part>`` compiles one part into ``NUMBA_CACHE_DIR``.
Only the standard library is imported at the top: the workers import this module before
numba reads ``NUMBA_CACHE_DIR``.
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from importlib.metadata import version
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]

#: numba's cache of this user's test sessions: ``warm/`` and a folder per pytest-xdist
#: worker (a cache dir given by the caller, as tools/version-matrix.sh gives one, is used
#: instead of the temporary folder).
NUMBA_BASE = Path(
    os.environ.get("NUMBA_CACHE_DIR")
    or os.path.join(tempfile.gettempdir(), f"abglib-numba-{os.getuid()}")
)


def engine() -> None:
    """The tracker (batched and per series, both orders), methods M1-M5 and the benchmark
    metrics, as the workflow's fork server loads them."""
    from abglib.reporting.workers import load_kernels

    load_kernels()


def antenna() -> None:
    """The antenna's compiled loops (Riccati, Kalman, phase ensembles), by judging its claims
    on the small config, as a small build's antenna claims job does."""
    from abglib.replications import judge_claims
    from tests.replications.conftest import published_paths, small_config

    judge_claims("antenna", small_config(), published_paths("antenna"), None)


PARTS = {"engine": engine, "antenna": antenna}
DAY = 86400.0


def seed_numba_cache(warm: Path, dest: Path) -> int:
    """Copy numba's cache files from the part folders of ``warm`` (a complete
    :func:`warm_folder`) into ``dest`` where
    ``dest`` has no such file or an older one; returns how many were copied.

    numba names a cache folder after the source folder's path, so the copy serves the same
    sources, and numba checks each source file's stamp when it loads an entry. A file is
    written under a temporary name and renamed, so that a reader never sees half of it.
    """
    copied = 0
    for part in sorted(p for p in warm.glob("*") if p.is_dir()):
        for src in part.rglob("*"):
            if not src.is_file():
                continue
            out = dest / src.relative_to(part)
            if out.exists() and out.stat().st_mtime >= src.stat().st_mtime:
                continue
            out.parent.mkdir(parents=True, exist_ok=True)
            tmp = out.with_name(f"{out.name}.{os.getpid()}.tmp")
            try:
                shutil.copy2(src, tmp)
                os.replace(tmp, out)
            except OSError:  # removed meanwhile: the worker compiles it itself
                continue
            copied += 1
    return copied


def sources_stamp() -> str:
    """What a warm cache is compiled from: every ``abglib`` source file's size and mtime,
    this file, Python's and numba's versions."""
    h = hashlib.sha256(f"{sys.version} numba {version('numba')}".encode())
    for path in sorted([*(REPO / "abglib").rglob("*.py"), Path(__file__)]):
        st = path.stat()
        h.update(f"{path.relative_to(REPO)} {st.st_size} {st.st_mtime_ns}\n".encode())
    return h.hexdigest()[:16]


def warm_folder(base: Path = NUMBA_BASE) -> Path:
    """``<base>/warm/<stamp>``: the warm cache of the sources as they are now."""
    return base / "warm" / sources_stamp()


def _marker(folder: Path, kind: str) -> Path:
    """``<folder>.pid`` (the running warm-up's process) or ``<folder>.failed`` (why it
    failed), beside the warm cache ``folder``."""
    return folder.with_name(f"{folder.name}.{kind}")


def start_warm_up(base: Path = NUMBA_BASE) -> tuple[subprocess.Popen, Path] | None:
    """Start compiling the warm cache of the sources as they are now in the background
    (``python -m tests._numba_warm``), unless it exists; returns the process and the
    folder it makes, or None."""
    folder = warm_folder(base)
    if folder.is_dir():
        return None
    folder.parent.mkdir(parents=True, exist_ok=True)
    proc = subprocess.Popen(
        [sys.executable, "-m", "tests._numba_warm", str(folder)],
        cwd=REPO,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
        start_new_session=True,  # stopped as a group (tests/conftest.py, a short session)
    )
    # written here, not by the warm-up, so that a worker never finds it missing
    _marker(folder, "pid").write_text(str(proc.pid), encoding="utf-8")
    return proc, folder


def stop_warm_up(proc: subprocess.Popen, folder: Path) -> None:
    """Stop a warm-up :func:`start_warm_up` started if it still runs (a short session):
    its whole process group, parts included, and its pid file."""
    if proc.poll() is not None:
        return
    with contextlib.suppress(ProcessLookupError):
        os.killpg(proc.pid, signal.SIGTERM)
    proc.wait()
    _marker(folder, "pid").unlink(missing_ok=True)


def wait_for_warm_cache(folder: Path, timeout: float = 600.0) -> bool:
    """Wait until ``folder`` is complete (True) or its warm-up failed, ended without it or
    ``timeout`` passed (False)."""
    deadline = time.monotonic() + timeout
    pid_file = _marker(folder, "pid")
    while not folder.is_dir():
        if _marker(folder, "failed").exists() or time.monotonic() > deadline:
            return False
        try:
            os.kill(int(pid_file.read_text(encoding="utf-8")), 0)
        except (OSError, ValueError):  # no warm-up running (any more)
            return folder.is_dir()
        time.sleep(0.2)
    return True


def build_warm_cache(folder: Path) -> None:
    """Compile every part of :data:`PARTS` at once, each into ``<tmp>/<part>`` (a process of
    its own), then rename ``<tmp>`` to ``folder``: readers see a complete folder or none.
    On a part's failure ``<folder>.failed`` holds its error: the warm cache saves time, it
    never decides a result."""
    pid_file = _marker(folder, "pid")
    # stopped by stop_warm_up: leave through the finally clause, no half folder left
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(1))
    tmp = Path(tempfile.mkdtemp(prefix=folder.name + ".", dir=folder.parent))
    try:
        # start from the newest earlier warm cache: after an edit numba recompiles only what
        # the edited files hold (it checks every entry's source file stamp)
        earlier = [d for d in folder.parent.iterdir() if d.is_dir() and "." not in d.name]
        if earlier:
            newest = max(earlier, key=lambda d: d.stat().st_mtime)
            for part in PARTS:
                if (newest / part).is_dir():
                    shutil.copytree(newest / part, tmp / part, dirs_exist_ok=True)
        procs = {
            part: subprocess.Popen(
                [sys.executable, "-m", "tests._numba_warm", "--part", part],
                cwd=REPO,
                env=dict(os.environ, NUMBA_CACHE_DIR=str(tmp / part)),
                stdout=subprocess.DEVNULL,
                stderr=subprocess.PIPE,
                text=True,
            )
            for part in PARTS
        }
        failed = []
        for part, proc in procs.items():
            _, err = proc.communicate(timeout=900)
            if proc.returncode != 0:
                failed.append(f"{part}: {(err.strip().splitlines() or [proc.returncode])[-1]}")
        if failed:
            _marker(folder, "failed").write_text("\n".join(failed), encoding="utf-8")
            return
        try:
            os.rename(tmp, folder)
        except OSError:  # another session made it meanwhile
            return
        # other sources' caches (edited sources, other clones) unused for a day
        for old in folder.parent.iterdir():
            if old.name.split(".")[0] == folder.name or time.time() - old.stat().st_mtime < DAY:
                continue
            shutil.rmtree(old, ignore_errors=True) if old.is_dir() else old.unlink()
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
        pid_file.unlink(missing_ok=True)


if __name__ == "__main__":
    if sys.argv[1] == "--part":
        PARTS[sys.argv[2]]()
    else:
        build_warm_cache(Path(sys.argv[1]))
