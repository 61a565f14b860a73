"""Recycled output memory (abglib._buffers): a block is reused only once no array or view
of it is left, the pool keeps to its limit, and track's results are unchanged by it."""

import gc

import numpy as np
import pytest

import abglib
from abglib import AbglibValueError, _buffers, design

SHAPE = (64, 1 << 14)  # 8 MiB: above MIN_BYTES


def _address(a):
    return a.__array_interface__["data"][0]


@pytest.fixture(autouse=True)
def _fresh_pool():
    _buffers.release()
    limit = _buffers.pool_limit()
    yield
    _buffers.set_pool_limit(limit)
    _buffers.release()


def test_a_dropped_output_is_reused_and_a_viewed_one_is_not():
    a = _buffers.empty(SHAPE)
    addr = _address(a)
    del a
    gc.collect()
    assert _buffers.pool_bytes() == np.prod(SHAPE) * 8
    b = _buffers.empty(SHAPE)
    assert _address(b) == addr  # the same block, back from the pool
    b[:] = 7.0
    tail = b[5:, 3:][::2]  # a view of a view of b outlives b
    del b
    gc.collect()
    assert _buffers.pool_bytes() == 0  # still in use through the view
    c = _buffers.empty(SHAPE)
    assert _address(c) != addr
    c[:] = -1.0
    assert np.all(tail == 7.0)  # the view's numbers were not overwritten
    del tail
    gc.collect()
    assert _buffers.pool_bytes() == np.prod(SHAPE) * 8


def test_small_arrays_and_a_zero_limit_bypass_the_pool():
    small = _buffers.empty((10, 10))
    assert small.shape == (10, 10) and small.base is None  # numpy's own array
    _buffers.set_pool_limit(0)
    big = _buffers.empty(SHAPE)
    assert big.base is None
    del big
    gc.collect()
    assert _buffers.pool_bytes() == 0


def test_the_pool_keeps_to_its_limit():
    nbytes = int(np.prod(SHAPE)) * 8
    _buffers.set_pool_limit(nbytes)
    a, b = _buffers.empty(SHAPE), _buffers.empty(SHAPE)
    del a, b
    gc.collect()
    assert _buffers.pool_bytes() == nbytes  # the second block was freed, not kept
    _buffers.set_pool_limit(0)
    assert _buffers.pool_bytes() == 0  # lowering the limit trims the pool


@pytest.mark.parametrize("bad", [-1, 1.5, "1", True])
def test_a_bad_limit_is_named(bad):
    with pytest.raises(AbglibValueError, match="whole number of bytes"):
        _buffers.set_pool_limit(bad)


def test_bad_environment_limit_is_named(monkeypatch):
    monkeypatch.setenv("ABGLIB_POOL_BYTES", "lots")
    monkeypatch.setitem(_buffers._STATE, "limit", None)
    with pytest.raises(AbglibValueError, match="ABGLIB_POOL_BYTES"):
        _buffers.pool_limit()
    monkeypatch.setenv("ABGLIB_POOL_BYTES", "0")
    assert _buffers.pool_limit() == 0


def test_track_on_recycled_memory_gives_the_same_numbers():
    """Results from reused blocks equal a fresh call's, bit for bit, and an earlier
    result still held is never overwritten by a later call."""
    rng = np.random.default_rng(1)
    z = np.cumsum(rng.normal(size=SHAPE), axis=-1)
    g = design.standard_from_alpha(0.4, order=3)
    first = abglib.track(z, g, dt=0.5)
    keep = first.x_smooth.copy()
    again = abglib.track(z + 1.0, g, dt=0.5)  # `first` is alive: fresh blocks
    np.testing.assert_array_equal(first.x_smooth, keep)
    del again
    gc.collect()
    assert _buffers.pool_bytes() > 0
    third = abglib.track(z, g, dt=0.5)  # from the pool
    for name in abglib.engine.OUTPUTS:
        np.testing.assert_array_equal(getattr(third, name), getattr(first, name))


@pytest.mark.parametrize("make", [_buffers.zeros, _buffers.empty])
def test_large_arrays_are_private_to_a_forked_child(make):
    """A forked child's writes never reach the parent's array (private mappings: the
    lazily mapped zeros of alpha-beta's a_smooth, and pooled blocks)."""
    import os

    a = make(SHAPE)
    a[...] = 0.0
    pid = os.fork()
    if pid == 0:  # the child writes and leaves at once
        a[...] = 5.0
        os._exit(0)
    os.waitpid(pid, 0)
    assert not np.any(a)


def test_zeros_are_zero_and_never_come_from_the_pool():
    a = _buffers.empty(SHAPE)
    a[...] = 3.0
    del a
    gc.collect()
    assert _buffers.pool_bytes() > 0
    z = _buffers.zeros(SHAPE)
    assert z.shape == SHAPE and z.flags.writeable and not np.any(z)
    assert _buffers.pool_bytes() > 0  # the pooled block is still there, unused
    assert _buffers.zeros((3, 4)).shape == (3, 4)  # small: numpy's own


def test_zero_fill_gives_back_only_a_whole_zeros_block(monkeypatch):
    """zero_fill re-zeroes a whole zeros() block by giving its pages back (madvise), every
    view of it sees zeros; part of a block, a pooled block or a numpy array is filled."""
    calls = []
    real = _buffers._ZeroMap.madvise

    def spy(self, *args):
        calls.append(args)
        return real(self, *args)

    monkeypatch.setattr(_buffers._ZeroMap, "madvise", spy)
    z = _buffers.zeros(SHAPE)
    z[...] = 7.0
    view = z[::3, 5:]
    _buffers.zero_fill(z)
    assert calls and not np.any(z) and not np.any(view)
    z[...] = 7.0
    _buffers.zero_fill(z[:, ::1].reshape(-1))  # the same memory, another shape: whole
    assert len(calls) == 2 and not np.any(z)
    z[...] = 5.0
    _buffers.zero_fill(z[:10])  # part of the block: filled, the rest untouched
    assert len(calls) == 2 and not np.any(z[:10]) and np.all(z[10:] == 5.0)
    for other in (_buffers.empty(SHAPE), np.empty(SHAPE), np.empty((3, 4))):
        other[...] = 2.0
        _buffers.zero_fill(other)
        assert not np.any(other)
    assert len(calls) == 2


def test_alpha_beta_out_a_smooth_is_rezeroed_through_its_pages():
    """A previous alpha-beta result handed back as out= (the benchmark's loop): its
    a_smooth is zero again after the call even when the caller wrote into it."""
    z = np.random.default_rng(8).normal(size=SHAPE).cumsum(axis=-1)
    g = abglib.Gains(0.4, 0.1)
    res = abglib.track(z, g)
    res.a_smooth[3, 7] = 1.0
    again = abglib.track(z, g, out=res)
    assert again.a_smooth is res.a_smooth and not np.any(again.a_smooth)
    np.testing.assert_array_equal(again.x_smooth, abglib.track(z, g).x_smooth)
