"""One warm numba cache for a test session, copied into each pytest-xdist worker's own.

With numba's cache cold a small build compiled for about 31 of its 72 CPU-seconds, and
each test worker compiled the same loops again (issue 24). So ``tests/conftest.py`` starts
:func:`start_warm_up` as pytest-xdist starts its workers: the parts of :data:`PARTS` are
compiled at once, each in a process of its own, into ``<base>/warm/<stamp>/<part>``, where
the stamp names the sources (every ``abglib`` file's size and mtime, this file, Python's
and numba's versions) and each part's folder appears whole or not at all. Before its first
test each worker waits for the parts it needs (:func:`wait_for_warm_cache`: the engine's
first, every part before a build or an antenna test) and copies them into its own cache
folder (:func:`seed_numba_cache`); a build a test starts inherits its worker's folder.
Workers keep folders of their own: two workers writing one cache at once on a cold clone
segfaulted a worker inside a cached gufunc (.ci/run, 2026-12-02). Once compiled, the warm
cache serves every later session until a source changes; a part starts from an earlier
warm cache, or else from what a build of the same sources compiled
(:func:`seed_from_builds`: the README's ``snakemake -c2`` before ``pytest``).

Usage: ``python -m tests._numba_warm <folder>`` builds a warm cache into ``folder``;
``python -m tests._numba_warm --part <part>`` compiles one part into ``NUMBA_CACHE_DIR``.
Only the standard library is imported at the top: the workers import this module before
numba reads ``NUMBA_CACHE_DIR``.
"""

from __future__ import annotations

import contextlib
import glob
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
    metrics, as the workflow's fork server loads them; then what the fork server leaves
    out and the test workers compiled on their own (issue 24, 2026-12-03: 3.9-5.3 s a
    worker, the threaded kernels in both): the threaded batch kernels (8 series or more
    and 65,536 samples or more, abglib.engine) and M4/M5 on read-only measurements."""
    import numpy as np

    from abglib import methods, track
    from abglib.design import standard_from_alpha
    from abglib.reporting.workers import load_kernels

    load_kernels()
    z = np.cumsum(np.ones((64, 1024)), axis=-1)
    for order in (2, 3):
        track(z, standard_from_alpha(0.5, order=order), dt=1.0)
    z = np.cumsum(np.ones((2, 32)), axis=-1)
    z.flags.writeable = False
    methods.m4(z, 0.5, 4, np.linspace(0.1, 0.9, 3))
    methods.m5(z, np.linspace(0.1, 0.9, 3))


def antenna() -> None:
    """The antenna's compiled loops (Riccati, Kalman, phase ensembles) with the signatures a
    small build's antenna claims job compiles: the study of the small config, the compiled
    Riccati routes of a spectral radius (app. H) and a few steps of the phase ensembles
    (Kalman filter of each order, alpha-beta-gamma) on tiny inputs.

    Judging the whole small config's claims, as this part did before, compiled the same 16
    signatures (compared entry by entry, 2026-12-04) in 13.6 s instead of 8.9 s: the
    rest was the claims' own work. A loop the claims start to call with a new signature is
    then compiled by each worker on its own (slower, never wrong) until it is added here."""
    from abglib import design
    from abglib.replications.antenna.ensemble import simulate_phases
    from abglib.replications.antenna.robustness import spectral_radius
    from tests.replications.conftest import small_config, study_for

    s = study_for("antenna", small_config())
    k = s.cfg["kalman"]
    ctrl = s.controller("q")
    vw = s.vw_filter(10.0 ** float(k["vw_exponents"][0]))
    kw = dict(amplitude=10.0, omega=0.1, n_steps=8, phases=[0.0, 1.0])
    for order in sorted(set(k["orders"])):
        spectral_radius(s.params, "p_a", 1.0, s.dt, s.q, s.r, order, vw, s.vv)
        simulate_phases(
            s.params, ctrl, mode="kalman", order=order, v_w=vw, v_v=s.vv, resolution=s.res, **kw
        )
    abg = design.huang_for_enbw(0.01, s.dt, rule="type2", order=3)
    simulate_phases(s.params, ctrl, mode="abg", abg=abg, **kw)


PARTS = {"engine": engine, "antenna": antenna}
DAY = 86400.0


def _copy_entry(index: Path, out_dir: Path) -> int:
    """Copy numba's cache entry ``index`` (``<name>.nbi``) with the compiled overloads it
    numbers (``<name>.<n>.nbc``) into ``out_dir``, replacing ``out_dir``'s entry of that
    name whole: never mixed with the files of one compiled there (the same numbers can
    name other signatures there), the overloads first and the index last, each under a
    temporary name renamed into place, so that a reader never sees an index without its
    overloads or half a file. Returns how many files were copied."""
    copied = 0
    out = out_dir / index.name
    entry = glob.escape(index.name.removesuffix(".nbi")) + ".*.nbc"
    out_dir.mkdir(parents=True, exist_ok=True)
    out.unlink(missing_ok=True)
    for old in out_dir.glob(entry):
        old.unlink(missing_ok=True)
    for src in [*index.parent.glob(entry), index]:
        tmp = out_dir / f"{src.name}.{os.getpid()}.tmp"
        try:
            shutil.copy2(src, tmp)
            os.replace(tmp, out_dir / src.name)
        except OSError:  # removed meanwhile: the reader compiles it itself
            break
        copied += 1
    return copied


def _newer(index: Path, out_dir: Path) -> bool:
    """Whether the entry ``index`` is newer than ``out_dir``'s entry of that name (or
    ``out_dir`` has none)."""
    out = out_dir / index.name
    return not out.exists() or out.stat().st_mtime < index.stat().st_mtime


def seed_numba_cache(warm: Path, dest: Path, parts=None) -> int:
    """Copy numba's cache entries from the part folders of ``warm`` (a :func:`warm_folder`;
    ``parts``: those named, default every finished part) into ``dest`` where ``dest`` has
    no such entry or an older one (:func:`_copy_entry`); returns how many files were
    copied.

    numba names a cache folder after the source folder's path, so the copy serves the same
    sources, and numba checks each source file's stamp when it loads an entry.
    """
    copied = 0
    names = sorted(PARTS if parts is None else parts)
    for part in (warm / name for name in names if (warm / name).is_dir()):
        for index in part.rglob("*.nbi"):
            out_dir = dest / index.parent.relative_to(part)
            if _newer(index, out_dir):
                copied += _copy_entry(index, out_dir)
    return copied


def seed_from_builds(dest: Path, base: Path = NUMBA_BASE, repo: Path = REPO) -> int:
    """Copy into ``dest`` (the ``NUMBA_CACHE_DIR`` a warm part compiles into) the entries
    that builds of these very sources compiled: in ``abglib``'s own ``__pycache__``
    folders (a build with ``NUMBA_CACHE_DIR`` unset: the README's ``snakemake -c2``) and in
    ``base``'s folders for them (a build given the tests' cache folder:
    tools/version-matrix.sh). The newest entry of a name wins, whole (:func:`_copy_entry`);
    numba checks each entry's source stamp when it loads one, so an edited file's loops
    are compiled again. Returns how many files were copied; with no build's entry in sight
    it returns 0 without importing numba (a fresh clone)."""
    pycache = [p for p in (repo / "abglib").rglob("*.nbi") if p.parent.name == "__pycache__"]
    if not pycache and not any(base.glob("*/*.nbi")):  # depth 1: a build's, not gw*/warm
        return 0
    copied = 0
    folders = [repo / "abglib", *(d for d in (repo / "abglib").rglob("*") if d.is_dir())]
    for src_dir in (d for d in folders if d.name != "__pycache__"):
        sub = _cache_subfolder(src_dir)
        indexes = [*(src_dir / "__pycache__").glob("*.nbi"), *(base / sub).glob("*.nbi")]
        for index in sorted(indexes, key=lambda p: p.stat().st_mtime):  # the newest last
            if _newer(index, dest / sub):
                copied += _copy_entry(index, dest / sub)
    return copied


def _cache_subfolder(source_dir: Path) -> str:
    """The folder of ``NUMBA_CACHE_DIR`` where numba caches the loops of the sources in
    ``source_dir`` (numba's own naming: the folder's name and a hash of its path). The one
    use of numba's cache internals here: a numba without them fails the copying tests."""
    from numba.core import caching

    locator = caching.UserProvidedCacheLocator  # numba 0.62 (the lowest) to 0.68 at least
    return locator.get_suitable_cache_subpath(str(source_dir / "__init__.py"))


def seed_copy(copy: Path, repo: Path = REPO) -> dict[str, str]:
    """Give the ``abglib`` of a copy of the repository (its files copied with their
    mtimes, as shutil.copy2 and copytree do) the numba cache of ``repo``'s, so that the
    builds a test makes in the copy do not compile every loop again; returns what the
    environment of the copy's builds needs (``{}`` or ``NUMBA_CACHE_DIR``).

    numba names a cache folder after the source folder's path, and checks each source
    file's stamp when it loads an entry, so an edited file of the copy still recompiles.
    With ``NUMBA_CACHE_DIR`` set (a pytest-xdist worker) the copy gets a cache folder of
    its own beside it, ``<copy>-numba`` (removed with the test's temporary folder, not
    piling up in the worker's), holding the worker's entries under the copy's names;
    unset, numba caches in each ``__pycache__`` and those entries are copied. The naming
    is numba's (:func:`_cache_subfolder`); tests/test_numba_warm.py fails if it changes.
    """
    cache = os.environ.get("NUMBA_CACHE_DIR")
    dest = copy.with_name(f"{copy.name}-numba") if cache else None
    for src_dir in [repo / "abglib", *(d for d in (repo / "abglib").rglob("*") if d.is_dir())]:
        if src_dir.name == "__pycache__":
            continue
        dst_dir = copy / src_dir.relative_to(repo)
        if not dst_dir.is_dir():
            continue
        if cache:
            src = Path(cache) / _cache_subfolder(src_dir)
            dst = dest / _cache_subfolder(dst_dir)
        else:
            src, dst = src_dir / "__pycache__", dst_dir / "__pycache__"
        for f in src.glob("*.nb[ic]") if src.is_dir() else ():
            dst.mkdir(parents=True, exist_ok=True)
            shutil.copy2(f, dst / f.name)
    if cache:
        dest.mkdir(exist_ok=True)
        return {"NUMBA_CACHE_DIR": str(dest)}
    return {}


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


def finished(folder: Path, parts=None) -> bool:
    """Whether every part of ``parts`` (default :data:`PARTS`) of the warm cache ``folder``
    is there."""
    return all((folder / part).is_dir() for part in (PARTS if parts is None else parts))


def start_warm_up(base: Path = NUMBA_BASE) -> tuple[subprocess.Popen, Path] | None:
    """Start compiling the warm cache of the sources as they are now in the background
    (``python -m tests._numba_warm``), unless it is complete; returns the process and the
    folder it makes, or None."""
    folder = warm_folder(base)
    if finished(folder):
        return None
    folder.parent.mkdir(parents=True, exist_ok=True)
    _marker(folder, "failed").unlink(missing_ok=True)  # an earlier session's failure
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


def _running(pid_file: Path) -> bool:
    """Whether the warm-up named in ``pid_file`` still runs (a zombie, ended but not yet
    reaped by the session that started it, does not)."""
    try:
        pid = int(pid_file.read_text(encoding="utf-8"))
        os.kill(pid, 0)
    except (OSError, ValueError):
        return False
    with contextlib.suppress(OSError):  # Linux: the state after the command's parenthesis
        stat = Path(f"/proc/{pid}/stat").read_text(encoding="utf-8", errors="replace")
        return stat.rpartition(")")[2].split()[0] != "Z"
    return True


def wait_for_warm_cache(folder: Path, parts=None, timeout: float = 600.0) -> bool:
    """Wait until the ``parts`` (default all) of ``folder`` are there (True) or its warm-up
    failed, ended without them or ``timeout`` passed (False)."""
    deadline = time.monotonic() + timeout
    pid_file = _marker(folder, "pid")
    while not finished(folder, parts):
        if _marker(folder, "failed").exists() or time.monotonic() > deadline:
            return False
        if not _running(pid_file):
            return finished(folder, parts)
        time.sleep(0.2)
    return True


#: How long one part may compile before the warm-up gives it up (s).
PART_TIMEOUT = 900.0


def build_warm_cache(folder: Path) -> None:
    """Compile the missing parts of :data:`PARTS` at once, each into ``<tmp>/<part>`` (a
    process of its own), and rename each to ``folder/<part>`` as soon as it is done: a
    reader sees a complete part or none, and waits only for the parts it needs. On a
    part's failure (or after :data:`PART_TIMEOUT`) ``<folder>.failed`` holds its error at
    once: the warm cache saves time, it never decides a result."""
    pid_file = _marker(folder, "pid")
    # stopped by stop_warm_up: leave through the finally clause, no half folder left
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(1))
    tmp, procs = None, {}
    try:
        tmp = Path(tempfile.mkdtemp(prefix=folder.name + ".", dir=folder.parent))
        folder.mkdir(exist_ok=True)
        todo = [part for part in PARTS if not (folder / part).is_dir()]
        # start each part from the newest earlier warm cache that has it: after an edit
        # numba recompiles only what the edited files hold (it checks every entry's stamp)
        earlier = [d for d in folder.parent.iterdir() if d.is_dir() and "." not in d.name]
        for part in todo:
            done = [d for d in earlier if d != folder and (d / part).is_dir()]
            if done:  # a stamp folder's mtime is when its last part was renamed in
                newest = max(done, key=lambda d: d.stat().st_mtime)
                shutil.copytree(newest / part, tmp / part, dirs_exist_ok=True)
            # and what a build of these sources compiled (snakemake -c2 first), where newer:
            # an earlier warm cache may be another clone's, whose paths name other folders
            seed_from_builds(tmp / part, folder.parent.parent)
        for part in todo:
            with open(tmp / f"{part}.err", "w") as err:  # the child keeps its own copy
                procs[part] = subprocess.Popen(
                    [sys.executable, "-m", "tests._numba_warm", "--part", part],
                    cwd=REPO,
                    env=dict(os.environ, NUMBA_CACHE_DIR=str(tmp / part)),
                    stdout=subprocess.DEVNULL,
                    stderr=err,
                )
        deadline = time.monotonic() + PART_TIMEOUT
        while procs:
            for part, proc in list(procs.items()):
                if proc.poll() is None and time.monotonic() < deadline:
                    continue
                del procs[part]
                if proc.returncode != 0:
                    if proc.returncode is None:
                        proc.kill()
                        proc.wait()
                    err = (tmp / f"{part}.err").read_text(encoding="utf-8", errors="replace")
                    last = (err.strip().splitlines() or [f"exit {proc.returncode}"])[-1]
                    _marker(folder, "failed").write_text(f"{part}: {last}\n", encoding="utf-8")
                    continue
                (tmp / part).mkdir(exist_ok=True)
                with contextlib.suppress(OSError):  # another session made it meanwhile
                    os.rename(tmp / part, folder / part)
            time.sleep(0.1)
        # other sources' caches (edited sources, other clones) unused for a day
        for old in folder.parent.iterdir():
            if old.name.split(".")[0] == folder.name or time.time() - old.stat().st_mtime < DAY:
                continue
            shutil.rmtree(old, ignore_errors=True) if old.is_dir() else old.unlink()
    finally:
        signal.signal(signal.SIGTERM, signal.SIG_IGN)  # cleaning up: no second way out
        for proc in procs.values():  # an error here or a stop: no part left compiling
            proc.kill()
            proc.wait()
        if tmp is not None:
            shutil.rmtree(tmp, ignore_errors=True)
        pid_file.unlink(missing_ok=True)


if __name__ == "__main__":
    if sys.argv[1] == "--part":
        PARTS[sys.argv[2]]()
    else:
        build_warm_cache(Path(sys.argv[1]))
