"""The test session's own machinery (tests/conftest.py), not abglib's."""

import os

from .conftest import share_blas_cores, usable_cores


def _blas_threads() -> list[int]:
    from threadpoolctl import threadpool_info

    return [i["num_threads"] for i in threadpool_info() if i["user_api"] == "blas"]


def test_a_worker_gets_its_share_of_the_blas_cores(monkeypatch):
    """``usable cores // workers`` threads at most for every loaded BLAS pool (numpy's and
    scipy's), at least one; the session's own share is put back afterwards."""
    cores = usable_cores()
    try:
        monkeypatch.setenv("PYTEST_XDIST_WORKER_COUNT", str(2 * cores))
        assert share_blas_cores() == 1
        threads = _blas_threads()
        assert len(threads) >= 2 and set(threads) == {1}, threads
        monkeypatch.setenv("PYTEST_XDIST_WORKER_COUNT", "1")
        assert share_blas_cores() == cores
    finally:
        monkeypatch.undo()
        share = share_blas_cores()
    if os.environ.get("PYTEST_XDIST_WORKER"):  # this worker holds its share
        workers = int(os.environ["PYTEST_XDIST_WORKER_COUNT"])
        assert share == max(1, cores // workers)
        assert max(_blas_threads()) <= share  # fewer if OPENBLAS_NUM_THREADS says so
