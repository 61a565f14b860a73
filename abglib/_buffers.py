"""Recycled output memory for :func:`abglib.track`.

A large new array costs the operating system's page faults and zeroing on first touch:
on the development machine 320 MB of fresh outputs (four outputs of 10^4 runs x 10^3
samples) took ~175 ms with 4 kB pages, ~45 ms with transparent huge pages but then
~0.9 s at random (compaction), while tracking them takes ~35 ms. A Monte Carlo loop that
calls ``track`` again and again without ``out=`` buffers paid that on every call.

Here the memory of a large output, once every array that uses it is gone, goes back to
a small pool, and the next output of the same size reuses it: pages already mapped, so
nothing to fault. An array handed out is a plain ndarray whose base chain ends at an
owner object (:class:`_Owner`); the memory returns to the pool only when that owner is
collected, i.e. when no array or view of it is left anywhere. The pool keeps at most
:func:`pool_limit` bytes (:data:`DEFAULT_LIMIT` unless ``ABGLIB_POOL_BYTES`` or
:func:`set_pool_limit` says otherwise; 0 switches it off); :func:`release` empties it.
"""

from __future__ import annotations

import math
import mmap
import os
import threading

import numpy as np

from ._checks import AbglibValueError

__all__ = [
    "DEFAULT_LIMIT",
    "LAZY_ZEROS_BYTES",
    "MIN_BYTES",
    "empty",
    "pool_bytes",
    "pool_limit",
    "release",
    "set_pool_limit",
    "zero_fill",
    "zeros",
]

#: Bytes the pool keeps at most, by default (the outputs of one 10^7-sample call, twice).
DEFAULT_LIMIT = 1 << 30
#: Outputs smaller than this come from numpy as usual (the allocator recycles them).
MIN_BYTES = 1 << 22
#: Zero arrays at least this large are mapped lazily (:func:`zeros`).
LAZY_ZEROS_BYTES = 1 << 20

_LOCK = threading.RLock()
_POOL: dict[int, list[mmap.mmap]] = {}
_STATE = {"bytes": 0, "limit": None}


def _limit_from_env() -> int:
    text = os.environ.get("ABGLIB_POOL_BYTES")
    if text is None:
        return DEFAULT_LIMIT
    try:
        value = int(text)
    except ValueError:
        value = -1
    if value < 0:
        raise AbglibValueError(
            f"ABGLIB_POOL_BYTES must be a whole number of bytes >= 0, got {text!r}"
        )
    return value


def pool_limit() -> int:
    """Bytes the pool keeps at most."""
    if _STATE["limit"] is None:
        _STATE["limit"] = _limit_from_env()
    return _STATE["limit"]


def set_pool_limit(nbytes: int) -> None:
    """Set the pool's limit (bytes, >= 0; 0 switches recycling off) and trim to it."""
    if isinstance(nbytes, bool) or not isinstance(nbytes, (int, np.integer)) or nbytes < 0:
        raise AbglibValueError(
            f"the pool limit must be a whole number of bytes >= 0, got {nbytes!r}"
        )
    with _LOCK:
        _STATE["limit"] = int(nbytes)
        while _STATE["bytes"] > _STATE["limit"] and _POOL:
            size = max(_POOL)
            _POOL[size].pop()
            _STATE["bytes"] -= size
            if not _POOL[size]:
                del _POOL[size]


def release() -> None:
    """Give every pooled block back to the operating system."""
    with _LOCK:
        _POOL.clear()
        _STATE["bytes"] = 0


def pool_bytes() -> int:
    """Bytes the pool holds now."""
    return _STATE["bytes"]


class _Owner(np.ndarray):
    """The last array of a recycled block's base chain (never handed out): numpy stops
    collapsing a view's base at an array of another type, so every array or view of the
    block keeps this owner alive, and its collection means the block is free."""

    def __del__(self):
        raw = self.base
        if raw is None:  # pragma: no cover - interpreter shutdown
            return
        try:
            size = len(raw)
            with _LOCK:
                if _STATE["bytes"] + size <= pool_limit():
                    _POOL.setdefault(size, []).append(raw)
                    _STATE["bytes"] += size
        except Exception:  # noqa: BLE001 - a finaliser must not raise; the block is just freed
            pass


class _ZeroMap(mmap.mmap):
    """The mapping behind a large :func:`zeros` array (never pooled): its type marks the
    memory whose pages :func:`zero_fill` may give back to re-zero it."""


def _anonymous(nbytes: int, kind: type[mmap.mmap] = mmap.mmap) -> mmap.mmap:
    """Fresh private anonymous memory: zero pages, nothing faulted until touched, and
    never shared with a forked child (whose writes must not reach the parent's arrays)."""
    return kind(-1, nbytes, flags=mmap.MAP_PRIVATE | mmap.MAP_ANONYMOUS)


def _new_block(nbytes: int) -> mmap.mmap:
    """A block for the pool, with huge pages where the system allows them (as numpy asks
    for its own large arrays)."""
    raw = _anonymous(nbytes)
    if hasattr(mmap, "MADV_HUGEPAGE"):
        try:
            raw.madvise(mmap.MADV_HUGEPAGE)
        except OSError:  # pragma: no cover - kernels without transparent huge pages
            pass
    return raw


def zeros(shape) -> np.ndarray:
    """A new writeable float64 array of zeros that costs nothing until it is touched.

    Large ones (>= :data:`LAZY_ZEROS_BYTES`) are mapped straight from the operating
    system's zero pages: no page is faulted or cleared until it is read or written.
    ``np.zeros`` gets its memory from ``calloc``, which clears recycled heap memory page by
    page (an 8 MB array costs ~0.2 ms): an alpha-beta tracker's ``a_smooth``, which nobody
    may read, paid that on every call. Never pooled (a recycled block is not zero).
    """
    shape = tuple(int(s) for s in shape)
    nbytes = math.prod(shape) * 8
    if nbytes < LAZY_ZEROS_BYTES:
        return np.zeros(shape)
    return np.frombuffer(_anonymous(nbytes, _ZeroMap), dtype=np.float64).reshape(shape)


def _zero_map_of(buf: np.ndarray) -> _ZeroMap | None:
    """The :func:`zeros` mapping that ``buf`` covers exactly (every byte of it), else None."""
    base = buf
    while isinstance(base, np.ndarray):
        base = base.base
    if isinstance(base, memoryview):
        base = base.obj
    if not isinstance(base, _ZeroMap) or base.closed:
        return None
    if not buf.flags.c_contiguous or buf.nbytes != len(base):
        return None
    start = np.frombuffer(base, dtype=np.uint8, count=1).__array_interface__["data"][0]
    return base if buf.__array_interface__["data"][0] == start else None


def zero_fill(buf: np.ndarray) -> None:
    """Set every element of the float64 array ``buf`` to 0.0.

    An array that covers a whole large :func:`zeros` block (an alpha-beta tracker's
    ``a_smooth``, handed back through ``track(..., out=...)``) is re-zeroed by giving its
    pages back to the operating system (``madvise(MADV_DONTNEED)``: a private anonymous
    mapping reads as zero pages again): pages never written cost nothing, where filling
    8 MB with zeros costs ~1 ms on the development machine. Any other array is filled.
    """
    block = _zero_map_of(buf) if buf.nbytes >= LAZY_ZEROS_BYTES else None
    if block is not None and hasattr(mmap, "MADV_DONTNEED"):
        block.madvise(mmap.MADV_DONTNEED)
        return
    buf[...] = 0.0


def empty(shape) -> np.ndarray:
    """A new C-contiguous float64 array of ``shape``, from the pool when it is large.

    Its contents are undefined, as ``np.empty``'s (a recycled block holds old numbers).
    """
    shape = tuple(int(s) for s in shape)
    nbytes = math.prod(shape) * 8
    if nbytes < MIN_BYTES or pool_limit() == 0:
        return np.empty(shape)
    raw = None
    with _LOCK:
        blocks = _POOL.get(nbytes)
        if blocks:
            raw = blocks.pop()
            _STATE["bytes"] -= nbytes
            if not blocks:
                del _POOL[nbytes]
    if raw is None:
        raw = _new_block(nbytes)
    # the owner's base is the block itself (not an ndarray), so numpy cannot collapse a
    # view's base past it: every view keeps it alive
    owner = _Owner(shape=(nbytes // 8,), dtype=np.float64, buffer=raw)
    return owner.view(np.ndarray).reshape(shape)
