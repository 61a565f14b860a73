"""tools/slurm-cluster.sh's claim on the config path the jobs' Slurm commands read.

The loopback cluster links /etc/slurm/slurm.conf to its own config while it runs. A run
killed before its ``stop`` (a session or CI job ended in the middle of the SLURM test)
leaves that link behind, pointing into the killed cluster's directory, and the next
``start`` refused it as "another SLURM" (the CI run of stop 26 failed on exactly that).
These tests drive the script's ``link`` step, the one ``start`` runs, against a config
path moved into a temporary folder (ABGLIB_SLURM_DEFAULT_CONF): no root, no daemons, no
SLURM packages. A live daemon is a copy of ``sleep`` named ``slurmd`` (the script tells
its own daemons by the PID it recorded and the process's name).

Marked slow (subprocesses), so it runs in the full suite, not the development loop.
"""

import os
import shutil
import subprocess
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow

SCRIPT = Path(__file__).resolve().parents[1] / "tools" / "slurm-cluster.sh"
HEADER = "# written by tools/slurm-cluster.sh (rewritten on every start)\n"


def _cluster_dir(root: Path, name: str, cluster: str = "abglib") -> Path:
    """A state directory as `start` leaves it: etc/slurm.conf with the header, pid/."""
    d = root / name
    (d / "etc").mkdir(parents=True)
    (d / "pid").mkdir()
    (d / "etc" / "slurm.conf").write_text(f"{HEADER}ClusterName={cluster}\n")
    return d


def _link(new: Path, conf: Path, ci: bool = False) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if k not in ("CI", "SLURM_CONF")}
    env.update(ABGLIB_SLURM_DIR=str(new), ABGLIB_SLURM_DEFAULT_CONF=str(conf))
    if ci:
        env["CI"] = "true"
    return subprocess.run(
        ["bash", str(SCRIPT), "link"], env=env, capture_output=True, text=True, timeout=60
    )


@pytest.fixture
def conf(tmp_path: Path) -> Path:
    return tmp_path / "etc-slurm" / "slurm.conf"


def test_links_when_no_config_is_there(tmp_path, conf):
    new = _cluster_dir(tmp_path, "new")
    r = _link(new, conf)
    assert r.returncode == 0, r.stderr
    assert os.readlink(conf) == str(new / "etc" / "slurm.conf")


def test_takes_over_the_stale_link_of_a_killed_cluster(tmp_path, conf):
    old = _cluster_dir(tmp_path, "old")
    # a PID file whose process is gone: the daemons were killed with the run
    (old / "pid" / "slurmd.pid").write_text("999999999\n")
    conf.parent.mkdir(parents=True)
    conf.symlink_to(old / "etc" / "slurm.conf")
    new = _cluster_dir(tmp_path, "new")
    r = _link(new, conf)
    assert r.returncode == 0, r.stderr
    assert "stale" in r.stderr and str(old) in r.stderr
    assert os.readlink(conf) == str(new / "etc" / "slurm.conf")


def test_replaces_a_dangling_link(tmp_path, conf):
    old = _cluster_dir(tmp_path, "old")
    conf.parent.mkdir(parents=True)
    conf.symlink_to(old / "etc" / "slurm.conf")
    shutil.rmtree(old)
    new = _cluster_dir(tmp_path, "new")
    r = _link(new, conf)
    assert r.returncode == 0, r.stderr
    assert os.readlink(conf) == str(new / "etc" / "slurm.conf")


@pytest.fixture
def live_slurmd(tmp_path):
    """A process named slurmd (a copy of sleep), killed at the end whatever happens."""
    exe = tmp_path / "bin" / "slurmd"
    exe.parent.mkdir()
    shutil.copy(shutil.which("sleep"), exe)
    proc = subprocess.Popen([str(exe), "300"])
    yield proc
    proc.kill()
    proc.wait()


def _left_running(tmp_path: Path, conf: Path, pid: int) -> tuple[Path, Path]:
    """An earlier cluster whose slurmd (``pid``) still runs and whose link is at
    ``conf``, and a new cluster's directory: (old, new)."""
    old = _cluster_dir(tmp_path, "old")
    (old / "pid" / "slurmd.pid").write_text(f"{pid}\n")
    conf.parent.mkdir(parents=True)
    conf.symlink_to(old / "etc" / "slurm.conf")
    return old, _cluster_dir(tmp_path, "new")


def test_refuses_a_running_earlier_cluster_outside_ci(tmp_path, conf, live_slurmd):
    old, new = _left_running(tmp_path, conf, live_slurmd.pid)
    r = _link(new, conf)
    assert r.returncode == 1
    assert "still running (slurmd)" in r.stderr and f"ABGLIB_SLURM_DIR={old}" in r.stderr
    assert os.readlink(conf) == str(old / "etc" / "slurm.conf")  # left alone
    assert live_slurmd.poll() is None


def test_stops_a_running_earlier_cluster_under_ci(tmp_path, conf, live_slurmd):
    _, new = _left_running(tmp_path, conf, live_slurmd.pid)
    r = _link(new, conf, ci=True)
    assert r.returncode == 0, r.stderr
    assert f"stopped slurmd ({live_slurmd.pid})" in r.stderr
    assert live_slurmd.wait(timeout=10) is not None
    assert os.readlink(conf) == str(new / "etc" / "slurm.conf")


@pytest.mark.parametrize(
    "content",
    [
        "ClusterName=production\n",  # a real SLURM's file
        f"{HEADER}ClusterName=other\n",  # our header, another cluster name
    ],
)
@pytest.mark.parametrize("as_link", [False, True])
def test_never_touches_another_slurm(tmp_path, conf, content, as_link):
    conf.parent.mkdir(parents=True)
    if as_link:
        target = tmp_path / "site" / "etc" / "slurm.conf"
        target.parent.mkdir(parents=True)
        target.write_text(content)
        conf.symlink_to(target)
    else:
        conf.write_text(content)
    new = _cluster_dir(tmp_path, "new")
    r = _link(new, conf)
    assert r.returncode == 1
    assert "another SLURM is configured here" in r.stderr
    assert conf.read_text() == content
    assert conf.is_symlink() == as_link
