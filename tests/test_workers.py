"""Workflow scripts in warm worker processes (abglib.reporting.workers): the script sees
Snakemake's ``snakemake`` object, runs in a process of its own, and its failure names the
script, the error and the log."""

import os
import sys
import time

import pytest

from abglib.common.jobs import JobFailed
from abglib.reporting.workers import run_script, script_object

SCRIPT = """
import gc, json, os, sys
from abglib.common.jobs import log_to

log_to(snakemake.log[0])
print("to the log", file=sys.stderr)
if snakemake.params.fail:
    raise ValueError(f"bad value {snakemake.params.value}")
leaked = hasattr(json, "_abglib_marker")
import numba
json._abglib_marker = True  # a module-level change a later job must not see
with open(snakemake.output.out, "w") as fh:
    json.dump({"pid": os.getpid(), "value": snakemake.params.value,
               "wildcard": snakemake.wildcards.w, "leaked": leaked, "cwd": os.getcwd(),
               "numba_threads": numba.get_num_threads(), "frozen": gc.get_freeze_count(),
               "mplbackend": os.environ.get("MPLBACKEND")}, fh)
"""


def _job(tmp_path, name, **params):
    from snakemake.iocontainers import Log, Namedlist, OutputFiles, Params, Wildcards

    def named(cls, **items):
        nl = cls(list(items.values()))
        for i, k in enumerate(items):
            nl._set_name(k, i)
        return nl

    return script_object(
        Namedlist([]),
        named(OutputFiles, out=str(tmp_path / f"{name}.json")),
        named(Params, **{"fail": False, "value": 1, **params}),
        named(Wildcards, w=name),
        1,
        Namedlist([]),
        Log([str(tmp_path / f"{name}.log")]),
        {},
        "rule_x",
        str(tmp_path),
    )


@pytest.fixture
def script(tmp_path):
    path = tmp_path / "job.py"
    path.write_text(SCRIPT, encoding="utf-8")
    return path


#: The tests that run a job through the fork server share one worker (pytest-xdist
#: ``--dist loadgroup``) and so one server: each server imports the scientific stack once
#: (about 3.5 CPU-s), and on two workers the session paid for two.
fork_server = pytest.mark.xdist_group("fork_server")


def _read(tmp_path, name):
    import json

    return json.loads((tmp_path / f"{name}.json").read_text(encoding="utf-8"))


@fork_server
@pytest.mark.slow
def test_a_script_runs_in_a_fresh_process_of_its_own(script, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("MPLBACKEND", raising=False)
    run_script(script, _job(tmp_path, "a", value=2.5))
    run_script(script, _job(tmp_path, "b", value=3))
    a, b = _read(tmp_path, "a"), _read(tmp_path, "b")
    assert (a["value"], a["wildcard"], b["value"]) == (2.5, "a", 3)
    assert os.getpid() not in {a["pid"], b["pid"]} and a["pid"] != b["pid"]
    # what one job changed in a module is not seen by the next (each is a new fork)
    assert not a["leaked"] and not b["leaked"]
    assert a["cwd"] == str(tmp_path)
    # jobs draw on Agg (the server's environment), and the caller's is left alone
    assert a["mplbackend"] == "Agg" and "MPLBACKEND" not in os.environ
    assert "to the log" in (tmp_path / "a.log").read_text(encoding="utf-8")
    # the server's preloaded objects are frozen (workers.freeze_preloaded): a job's
    # collections skip them (the stack's modules alone are far over 10,000 objects)
    assert a["frozen"] > 10_000 and b["frozen"] > 10_000


@fork_server
@pytest.mark.slow  # a fresh process (the fork server)
def test_a_failing_script_names_the_error_and_its_log(script, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(JobFailed, match=r"job\.py failed: ValueError: bad value 7 .*a\.log"):
        run_script(script, _job(tmp_path, "a", fail=True, value=7))
    log = (tmp_path / "a.log").read_text(encoding="utf-8")
    assert "Traceback" in log and "ValueError: bad value 7" in log
    assert not (tmp_path / "a.json").exists()


def test_in_place_runs_here_and_gives_stderr_back(script, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    stderr, hook = sys.stderr, sys.excepthook
    import numba

    threads = numba.get_num_threads()
    run_script(script, _job(tmp_path, "a"), in_worker=False)
    assert _read(tmp_path, "a")["pid"] == os.getpid()
    # on a cluster a job keeps to its cpus too, and the process's count comes back
    assert _read(tmp_path, "a")["numba_threads"] == 1
    assert numba.get_num_threads() == threads
    assert (sys.stderr, sys.excepthook) == (stderr, hook)
    with pytest.raises(JobFailed, match="ValueError: bad value 1"):
        run_script(script, _job(tmp_path, "b", fail=True), in_worker=False)
    assert (sys.stderr, sys.excepthook) == (stderr, hook)
    import json

    del json._abglib_marker  # the in-place run changed this process, as intended


BURN = """
import time
from abglib.common.jobs import log_to

log_to(snakemake.log[0])
start = time.thread_time()  # the job's own thread: at least its time on the wall clock
while time.thread_time() - start < snakemake.params.value:
    pass
open(snakemake.output.out, "w").close()
"""


def _record(path):
    import csv

    from abglib.common.jobs import BENCHMARK_COLUMNS

    with open(path, encoding="utf-8") as fh:
        rows = list(csv.reader(fh, delimiter="\t"))
    assert rows[0] == list(BENCHMARK_COLUMNS) and len(rows) == 2
    return dict(zip(rows[0], rows[1], strict=True))


@fork_server
@pytest.mark.slow  # two jobs in the fork server at once
def test_each_job_is_timed_on_its_own_process_alone(tmp_path, monkeypatch):
    """Two jobs run side by side as Snakemake runs them (threads of one process), each
    using 0.4 CPU-s: each record holds its own job's CPU time, not the other's too (what
    Snakemake's benchmark: sampler recorded, abglib.common.jobs.write_benchmark)."""
    import threading

    monkeypatch.chdir(tmp_path)
    script = tmp_path / "burn.py"
    script.write_text(BURN, encoding="utf-8")
    run_script(script, _job(tmp_path, "warm", value=0.0))  # the server's imports, first
    jobs = [
        threading.Thread(
            target=run_script,
            args=(script, _job(tmp_path, name, value=0.4)),
            kwargs={"benchmark": tmp_path / "bench" / f"{name}.tsv"},
        )
        for name in ("a", "b")
    ]
    for job in jobs:
        job.start()
    for job in jobs:
        job.join()
    for name in ("a", "b"):
        rec = _record(tmp_path / "bench" / f"{name}.tsv")
        # the job's loop (0.4 CPU-s) and its fork's own start, well under both jobs' 0.8
        assert 0.4 <= float(rec["cpu_time"]) < 0.6, rec
        assert float(rec["s"]) >= float(rec["cpu_time"]) - 0.02, rec  # one thread
        # the wall time as h:m:s (a busy machine can take over a second for the pair)
        assert float(rec["s"]) < 60 and rec["h:m:s"] == f"0:00:{int(float(rec['s'])):02d}", rec
        assert 50 < float(rec["max_rss"]) < 4096, rec  # MiB: the fork's, not the tree's
    assert not list((tmp_path / "bench").glob(".*"))  # no part file left


@fork_server
@pytest.mark.slow  # a job in the fork server
def test_a_failed_job_leaves_no_benchmark_record(script, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    bench = tmp_path / "a.tsv"
    with pytest.raises(JobFailed):
        run_script(script, _job(tmp_path, "a", fail=True), benchmark=bench)
    with pytest.raises(JobFailed):
        run_script(script, _job(tmp_path, "b", fail=True), in_worker=False, benchmark=bench)
    assert not bench.exists()


SPAN = """
import time
from pathlib import Path

t0 = time.perf_counter()
time.sleep(0.2)
Path(snakemake.output.out).write_text(f"{t0} {time.perf_counter()}")
"""


def test_in_place_scripts_in_threads_run_one_at_a_time(tmp_path, monkeypatch):
    # a SLURM group job runs its jobs in threads of one Snakemake process and their
    # scripts in place: two scripts there must never overlap (each takes over the
    # process's stderr and excepthook), and each job's record times only its own script
    import threading

    monkeypatch.chdir(tmp_path)
    script = tmp_path / "span.py"
    script.write_text(SPAN, encoding="utf-8")
    stderr, hook = sys.stderr, sys.excepthook
    names = ["a", "b", "c"]
    threads = [
        threading.Thread(
            target=run_script,
            args=(script, _job(tmp_path, n)),
            kwargs={"in_worker": False, "benchmark": f"{n}.tsv"},
        )
        for n in names
    ]
    t0 = time.perf_counter()
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    elapsed = time.perf_counter() - t0
    spans = sorted(tuple(map(float, (tmp_path / f"{n}.json").read_text().split())) for n in names)
    assert all(end <= nxt for (_, end), (nxt, _) in zip(spans, spans[1:], strict=False)), spans
    # one after another, each record is its own script's time: together no more than the
    # whole (had a record counted its wait for the others, they would add up to about twice)
    records = [float(_record(tmp_path / f"{n}.tsv")["s"]) for n in names]
    assert min(records) >= 0.2 and sum(records) <= elapsed, (records, elapsed)
    assert (sys.stderr, sys.excepthook) == (stderr, hook)


def test_in_place_a_job_is_timed_from_its_start(tmp_path, monkeypatch):
    # on a cluster the job's process ran Snakemake before the script: only the script's
    # CPU time is the job's
    monkeypatch.chdir(tmp_path)
    script = tmp_path / "burn.py"
    script.write_text(BURN, encoding="utf-8")
    stderr, hook = sys.stderr, sys.excepthook
    run_script(script, _job(tmp_path, "a", value=0.3), in_worker=False, benchmark="a.tsv")
    assert (sys.stderr, sys.excepthook) == (stderr, hook)
    rec = _record(tmp_path / "a.tsv")
    assert 0.3 <= float(rec["cpu_time"]) < 0.45, rec
    assert float(rec["s"]) >= 0.3


def test_benchmark_record_format_and_bad_times(tmp_path):
    from abglib import AbglibValueError
    from abglib.common.jobs import process_usage, write_benchmark

    usage = {"cpu_time": 3725.5, "max_rss": 1234.567}
    write_benchmark(tmp_path / "x" / "r.tsv", 3725.25, usage)
    rec = _record(tmp_path / "x" / "r.tsv")
    assert rec == {
        "s": "3725.2500",
        "h:m:s": "1:02:05",
        "max_rss": "1234.57",
        "cpu_time": "3725.50",
    }
    for bad in (-1.0, float("nan")):
        with pytest.raises(AbglibValueError, match="at least 0 s, got"):
            write_benchmark(tmp_path / "y.tsv", bad, usage)
    assert not (tmp_path / "y.tsv").exists()
    # process_usage against the standard library's own clock of this process
    import time

    before, t0 = process_usage(), time.process_time()
    while time.process_time() - t0 < 0.2:
        pass
    spent = process_usage()["cpu_time"] - before["cpu_time"]
    assert abs(spent - (time.process_time() - t0)) < 0.05
    assert process_usage()["max_rss"] > 10  # MiB: this interpreter with numpy loaded


def test_a_missing_script_is_named(tmp_path):
    with pytest.raises(JobFailed, match="no workflow script .*nope.py"):
        run_script(tmp_path / "nope.py", _job(tmp_path, "a"))


@fork_server
@pytest.mark.slow  # starts the fork server
def test_warm_up_starts_the_fork_server_and_jobs_still_run(tmp_path):
    """warm_up (the workflow's onstart) starts the server at once, without waiting for
    its imports; jobs run through it afterwards as before."""
    import json
    from multiprocessing import forkserver

    from abglib.reporting.workers import warm_up

    warm_up()
    pid = forkserver._forkserver._forkserver_pid
    assert pid is not None
    os.kill(pid, 0)  # alive
    warm_up()  # idempotent: the same server
    assert forkserver._forkserver._forkserver_pid == pid
    script = tmp_path / "job.py"
    script.write_text(SCRIPT)
    run_script(script, _job(tmp_path, "w1"))
    assert json.loads((tmp_path / "w1.json").read_text())["pid"] != os.getpid()


@fork_server
@pytest.mark.slow  # a job in the fork server (started here, ~3 s of imports)
def test_a_job_keeps_to_its_threads(tmp_path, script):
    # the job's threads (1 here) bound numba's parallel loops in its worker
    run_script(script, _job(tmp_path, "a"))
    assert _read(tmp_path, "a")["numba_threads"] == 1


def test_job_threads_sets_and_restores_the_calling_threads_count():
    import numba

    from abglib import AbglibValueError
    from abglib.common.jobs import job_threads

    before = numba.get_num_threads()
    with job_threads(1):
        assert numba.get_num_threads() == 1
    assert numba.get_num_threads() == before
    with job_threads(10_000):  # no more than numba has
        assert numba.get_num_threads() == numba.config.NUMBA_NUM_THREADS
    with pytest.raises(AbglibValueError, match="at least 1 thread, got 0"):
        with job_threads(0):
            pass


FIGURE = """
import sys
from abglib.reporting import workers
if sys.argv[2] == "warm":
    workers.load_figures()
import matplotlib.pyplot as plt
from abglib.common.plotting import STYLE, describe, save_figure
assert plt.get_fignums() == []  # the warm-up leaves no figure open
with plt.rc_context(STYLE):
    fig, ax = plt.subplots()
    ax.semilogx([0.01, 0.1, 1.0], [1.0, 0.5, 0.1], label="α = 0.5")
    ax.set_xlabel("ωT (rad/sample)")
    ax.legend()
describe(fig, "a test figure")
save_figure(fig, sys.argv[1])
"""


@pytest.mark.slow
def test_warm_figure_caches_change_no_pixel(tmp_path):
    # the fork server draws one figure first (load_figures); a job's figure must come out
    # byte for byte as it would in a fresh process
    import subprocess

    script = tmp_path / "fig.py"
    script.write_text(FIGURE, encoding="utf-8")
    for mode in ("cold", "warm"):
        subprocess.run(
            [sys.executable, str(script), str(tmp_path / f"{mode}.png"), mode], check=True
        )
    assert (tmp_path / "cold.png").read_bytes() == (tmp_path / "warm.png").read_bytes()


class _LostStatus:
    """A multiprocessing context whose Process runs its target here and then reports
    255, as forkserver's Popen does when it cannot read the child's exit status."""

    def __init__(self, exitcode):
        import multiprocessing

        self._mp = multiprocessing.get_context("spawn")
        self._exitcode = exitcode

    def Pipe(self, duplex=False):  # noqa: N802 - the multiprocessing name
        return self._mp.Pipe(duplex=duplex)

    def Process(self, target, args, name):  # noqa: N802
        ctx = self

        class _P:
            exitcode = None

            def start(self):
                # the worker's own body, here (a job that succeeds: it sends its usage
                # and closes, with no os._exit)
                target(*args)

            def join(self):
                self.exitcode = ctx._exitcode

        return _P()


@pytest.mark.parametrize("exitcode, ok", [(255, True), (1, False), (-9, False)])
def test_a_lost_exit_status_after_reported_success_counts_as_done(
    script, tmp_path, monkeypatch, exitcode, ok
):
    """Seen once in the lowest-versions matrix: the worker said it finished and the fork
    server lost its status (255). Any other non-zero code still fails the job."""
    from abglib.reporting import workers

    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(workers, "_context", lambda: _LostStatus(exitcode))
    job = _job(tmp_path, "a", value=1.5)
    bench = tmp_path / "a.tsv"
    if ok:
        run_script(script, job, benchmark=bench)
        assert _read(tmp_path, "a")["value"] == 1.5
        assert float(_record(bench)["cpu_time"]) >= 0  # a job that counts as done
        # (the message goes to this process's stderr, which the fake's in-place run of
        # the script has handed to the job's log handler: not asserted here)
    else:
        with pytest.raises(JobFailed, match=rf"no error reported \(worker exit code {exitcode}\)"):
            run_script(script, job, benchmark=bench)
        assert not bench.exists()
