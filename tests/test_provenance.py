"""Provenance of the reports (abglib.reporting.provenance; CONTRACTS.md §4) and pipeline helpers."""

import subprocess

import numpy as np
import pytest

from abglib import AbglibValueError
from abglib.reporting.pipeline import atomic_output, wt_grid
from abglib.reporting.provenance import collect, config_hash, find_seeds, git_commit, to_markdown


def test_config_hash_ignores_key_order_and_sees_values():
    a = {"x": 1, "y": {"b": [1, 2], "a": 0.5}}
    b = {"y": {"a": 0.5, "b": [1, 2]}, "x": 1}
    assert config_hash(a) == config_hash(b)
    assert config_hash(a) != config_hash({**a, "x": 2})
    assert len(config_hash(a)) == 64


def test_find_seeds_nested():
    cfg = {"seed": 1, "mc": {"noise_seed": 7, "n": 3}, "runs": [{"seed": 9}], "label": "s"}
    assert find_seeds(cfg) == {"seed": 1, "mc.noise_seed": 7, "runs[0].seed": 9}


def test_git_commit_tolerates_no_repository(tmp_path):
    assert git_commit(tmp_path) is None
    rec = collect({"seed": 3}, repo=tmp_path)
    assert rec["git_commit"].startswith("unknown")
    assert rec["seeds"] == {"seed": 3}
    for name in ("python", "numpy", "scipy", "pandas", "matplotlib", "snakemake"):
        assert name in rec["versions"]
    text = to_markdown(rec)
    assert "config sha256" in text and "`seed` = 3" in text
    assert str(tmp_path) not in text


def test_git_commit_in_a_repository(tmp_path):
    try:
        subprocess.run(["git", "init", "-q", str(tmp_path)], check=True)
        (tmp_path / "f").write_text("x")
        env = ["-c", "user.name=t", "-c", "user.email=t@t"]
        subprocess.run(["git", *env, "-C", str(tmp_path), "add", "f"], check=True)
        subprocess.run(["git", *env, "-C", str(tmp_path), "commit", "-qm", "m"], check=True)
    except (OSError, subprocess.CalledProcessError):
        pytest.skip("git not available")
    commit = git_commit(tmp_path)
    assert commit is not None and len(commit) == 40
    # a rebuilt committed report does not make the code dirty; any other change does
    (tmp_path / "reports").mkdir()
    (tmp_path / "reports" / "r.html").write_text("a")
    subprocess.run(["git", *env, "-C", str(tmp_path), "add", "reports"], check=True)
    subprocess.run(["git", *env, "-C", str(tmp_path), "commit", "-qm", "r"], check=True)
    commit = git_commit(tmp_path)
    (tmp_path / "reports" / "r.html").write_text("b")
    assert git_commit(tmp_path) == commit
    assert git_commit(tmp_path / "reports") == commit
    (tmp_path / "f").write_text("y")
    assert git_commit(tmp_path) == commit + "+dirty"


def test_atomic_output_leaves_nothing_on_failure(tmp_path):
    target = tmp_path / "out.csv"
    target.write_text("old")
    with pytest.raises(RuntimeError), atomic_output(target) as tmp:
        tmp.write_text("half-written")
        raise RuntimeError("interrupted")
    assert target.read_text() == "old"
    assert [p.name for p in tmp_path.iterdir()] == ["out.csv"]
    with atomic_output(target) as tmp:
        tmp.write_text("new")
    assert target.read_text() == "new"


def test_wt_grid():
    g = wt_grid({"start": 0.0, "stop_over_pi": 1.0, "n": 5}, "linear")
    assert g[0] == 0.0 and g[-1] == pytest.approx(np.pi) and g.size == 5
    lg = wt_grid({"start": 0.01, "stop_over_pi": 1.0, "n": 3}, "log")
    assert lg[1] == pytest.approx(np.sqrt(0.01 * np.pi))
    with pytest.raises(AbglibValueError, match="start > 0"):
        wt_grid({"start": 0.0, "stop_over_pi": 1.0, "n": 3}, "log")
