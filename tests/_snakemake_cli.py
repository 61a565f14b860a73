"""Snakemake's command line for the tests, its runs that execute no job forked from one warm
process per test worker.

A ``snakemake`` the tests start spends about half of its 1.8-2.4 CPU-seconds importing
Snakemake (its command line, its API, its plugins' registries) before it reads the
workflow. The
dry runs, the lint and the rule listing of the tests (a dozen a session) execute no job,
so they share that import: :func:`run` sends them to a server, a fresh interpreter of this
virtual environment that imports Snakemake once (:data:`PRELOAD`) and then forks a child
for each request. The child takes the request's working directory (and Snakemake's run directory,
which Snakemake reads as it is imported), environment and arguments, sends
its output to files (stdin from ``/dev/null``), and runs ``snakemake.cli.main()``, as the
``snakemake`` console script does, then its ``atexit`` handlers. Its exit code and output
come back as a :class:`subprocess.CompletedProcess`, as :func:`subprocess.run` gives them.

Everything else is a real ``snakemake`` process, and so is a run whose environment changes
anything an interpreter reads as it starts (``PYTHONPATH``, ``PYTHONPROFILEIMPORTTIME``;
only :data:`LATE_ENV` may differ): a build, a run in a copy of the repository with its own
``PYTHONPATH``, the import-time profile of a parse. A test that needs a fresh interpreter
passes ``fresh=True``.
"""

from __future__ import annotations

import atexit
import json
import os
import select
import signal
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

#: The arguments of a Snakemake run that executes no job.
NO_JOB = frozenset({"-n", "--dry-run", "--dryrun", "--lint", "--list-rules", "-l"})
#: Environment variables that may differ from the test worker's for a forked run: read after
#: the start, by what the run imports (numba is not imported by a dry run's parse at all).
LATE_ENV = frozenset({"NUMBA_CACHE_DIR"})

#: What the server imports once: Snakemake's command line and what its runs import next
#: (its API, the workflow, the DAG, the metadata, the report plugins' registry), and pandas,
#: which Snakemake imports to check a rule's params against a build's metadata. A fresh
#: dry run of the small config took 2.26 s in a built working directory and 1.87 s in an
#: empty one; forked from the server 1.08 and 1.09 s (with ``snakemake.cli`` alone, 1.68
#: and 1.32 s).
PRELOAD = (
    "snakemake.cli",
    "snakemake.api",
    "snakemake.workflow",
    "snakemake.dag",
    "snakemake.persistence",
    "snakemake.report",
    "pandas",
)

#: The server: reads one JSON request a line, forks, answers "pid N", then "exit C".
SERVER = r"""
import json, os, sys
import importlib
for name in json.loads(sys.argv[2]):  # the imports every request shares
    importlib.import_module(name)
import snakemake.cli

def child(req):
    os.chdir(req["cwd"])
    os.environ.clear()
    os.environ.update(req["env"])
    null = os.open(os.devnull, os.O_RDONLY)
    os.dup2(null, 0)
    os.close(null)
    for fd, path in ((1, req["stdout"]), (2, req["stderr"])):
        out = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
        os.dup2(out, fd)
        os.close(out)
    sys.argv = list(req["argv"])
    # Snakemake's Workflow takes its run directory (the "Run directory" it logs) from the
    # working directory as its module is imported, a class attribute: that was the
    # server's, so the child gives it its own. tests/test_snakemake_cli.py compares a
    # forked run's output with a fresh one's, so a change upstream fails there.
    from snakemake.workflow import Workflow
    if hasattr(Workflow, "_rundir"):
        Workflow._rundir = os.path.abspath(os.getcwd())
    # as the console script: its exit code, or a traceback and 1; then the interpreter's
    # own exit (atexit handlers, flushed output)
    sys.exit(snakemake.cli.main())

answer = os.fdopen(int(sys.argv[1]), "w", buffering=1)
for line in sys.stdin:
    req = json.loads(line)
    pid = os.fork()
    if pid == 0:
        answer.close()
        child(req)
    answer.write(f"pid {pid}\n")
    _, status = os.waitpid(pid, 0)
    answer.write(f"exit {os.waitstatus_to_exitcode(status)}\n")
"""


class _Server:
    """One server process and its two pipes; requests one at a time (a lock)."""

    def __init__(self) -> None:
        read, write = os.pipe()
        # the server's own errors (its import failing) go to a file its failure quotes
        self.errors = tempfile.TemporaryFile()
        self.proc = subprocess.Popen(
            [sys.executable, "-c", SERVER, str(write), json.dumps(PRELOAD)],
            stdin=subprocess.PIPE,
            stdout=subprocess.DEVNULL,
            stderr=self.errors,
            text=True,
            pass_fds=(write,),
        )
        os.close(write)
        self.answers = read
        self.buffer = b""
        self.lock = threading.Lock()

    def _line(self, deadline: float | None) -> str:
        while b"\n" not in self.buffer:
            left = None if deadline is None else max(0.0, deadline - time.monotonic())
            ready, _, _ = select.select([self.answers], [], [], left)
            if not ready:
                raise TimeoutError
            chunk = os.read(self.answers, 4096)
            if not chunk:
                self.proc.wait(timeout=10)
                self.errors.seek(0)
                said = self.errors.read().decode(errors="replace")[-2000:]
                raise RuntimeError(
                    f"the Snakemake server of tests/_snakemake_cli.py ended (exit code "
                    f"{self.proc.returncode}): {said}"
                )
            self.buffer += chunk
        line, self.buffer = self.buffer.split(b"\n", 1)
        return line.decode()

    def run(self, argv, cwd, env, timeout):
        with self.lock, tempfile.TemporaryDirectory(prefix="abglib-smk-") as tmp:
            out, err = Path(tmp, "stdout"), Path(tmp, "stderr")
            req = {"argv": argv, "cwd": cwd, "env": env, "stdout": str(out), "stderr": str(err)}
            self.proc.stdin.write(json.dumps(req) + "\n")
            self.proc.stdin.flush()
            deadline = None if timeout is None else time.monotonic() + timeout
            pid = int(self._line(deadline).split()[1])
            try:
                code = int(self._line(deadline).split()[1])
            except TimeoutError:
                os.kill(pid, signal.SIGKILL)
                self._line(None)  # the server reaps it and answers
                raise subprocess.TimeoutExpired(argv, timeout) from None
            return subprocess.CompletedProcess(
                argv,
                code,
                out.read_text(encoding="utf-8", errors="replace"),
                err.read_text(encoding="utf-8", errors="replace"),
            )

    def close(self) -> None:
        if self.proc.poll() is None:
            self.proc.stdin.close()
            try:
                self.proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self.proc.kill()
        os.close(self.answers)
        self.errors.close()


_SERVER: list[_Server] = []
_SERVER_LOCK = threading.Lock()


def _server() -> _Server:
    with _SERVER_LOCK:
        if not _SERVER or _SERVER[0].proc.poll() is not None:
            _SERVER[:] = [_Server()]
            atexit.register(_SERVER[0].close)
        return _SERVER[0]


def forkable(cmd, env=None, fresh: bool = False) -> bool:
    """Whether :func:`run` forks ``cmd`` from the server rather than starting it: a
    ``snakemake`` (the console script beside this interpreter, or on PATH) that executes no
    job (:data:`NO_JOB`), with an environment that differs from this process's only in
    :data:`LATE_ENV`, on a system with ``fork``."""
    if fresh or not hasattr(os, "fork") or Path(cmd[0]).name != "snakemake":
        return False
    if not NO_JOB & set(cmd[1:]):
        return False
    if env is not None:
        changed = {k for k in {*env, *os.environ} if env.get(k) != os.environ.get(k)}
        if changed - LATE_ENV:
            return False
    return True


def run(cmd, *, cwd=None, env=None, timeout=None, fresh: bool = False):
    """``subprocess.run(cmd, capture_output=True, text=True, cwd=cwd, env=env,
    timeout=timeout)`` for a ``snakemake`` command; forked from the warm server where
    :func:`forkable` says so."""
    cmd = [str(c) for c in cmd]
    if not forkable(cmd, env, fresh):
        return subprocess.run(
            cmd, capture_output=True, text=True, cwd=cwd, env=env, timeout=timeout
        )
    full_env = dict(os.environ if env is None else env)
    return _server().run(cmd, str(cwd or os.getcwd()), full_env, timeout)
