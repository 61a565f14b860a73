"""Compiled reductions behind :func:`abglib.bench.metrics.evaluate_cell` (private; numba).

One pass per (coordinate, output, chunk of runs) computes everything the numpy form of
the cell's metrics computed in a dozen array passes: the error against the truth after
the burn-in, its sum of squares, sum, maximum absolute value and finiteness, the noise and
lag parts' sums of squares, the per-run mean square of the noise part over the VRF window
and the Euclidean accumulator. They release the GIL (two cells of a process run at the
same time) and give the SAME BITS as the numpy form: every sum is evaluated in numpy's
order (:func:`_pairwise`, numpy's pairwise summation of blocks of up to 128 values, and
the iterator's chunks: a contiguous array is one block, a strided view is summed in
chunks of whole rows of up to 8192 values, numpy's buffer size). Tests compare the two
forms bit for bit (``tests/test_metrics.py``).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

#: numpy's iterator buffer (values): a strided view is reduced in chunks of whole rows
#: of at most this many values; rows longer than this take the numpy form
BUFSIZE = 8192


@njit(cache=True, nogil=True)
def _leaf(a, lo, n):
    """numpy's ``pairwise_sum`` of ``a[lo:lo+n]`` for ``n <= 128`` (8 accumulators)."""
    if n < 8:
        res = 0.0
        for i in range(lo, lo + n):
            res += a[i]
        return res
    r0, r1, r2, r3 = a[lo], a[lo + 1], a[lo + 2], a[lo + 3]
    r4, r5, r6, r7 = a[lo + 4], a[lo + 5], a[lo + 6], a[lo + 7]
    m = n - (n % 8)
    i = 8
    while i < m:
        j = lo + i
        r0 += a[j]
        r1 += a[j + 1]
        r2 += a[j + 2]
        r3 += a[j + 3]
        r4 += a[j + 4]
        r5 += a[j + 5]
        r6 += a[j + 6]
        r7 += a[j + 7]
        i += 8
    res = ((r0 + r1) + (r2 + r3)) + ((r4 + r5) + (r6 + r7))
    while i < n:
        res += a[lo + i]
        i += 1
    return res


@njit(cache=True, nogil=True)
def _pairwise(a, lo, n, wi, wf):
    """numpy's pairwise sum of the 1-D contiguous ``a[lo:lo+n]`` (``DOUBLE_pairwise_sum``:
    ``sum(a[:h]) + sum(a[h:])`` with ``h`` half of ``n`` rounded down to a multiple of 8,
    leaves of at most 128 values). The recursion runs on an explicit stack in the
    workspace ``wi``, ``wf`` (:func:`workspace`): numba's disk cache does not reload
    self-recursive functions safely."""
    if n <= 128:
        return _leaf(a, lo, n)
    # frame d: start wi[0, d], length wi[1, d], stage wi[2, d] (0 new, 1 left half
    # pending, 2 right half pending), the left half's sum wf[d]
    sp = 0
    wi[0, 0], wi[1, 0], wi[2, 0] = lo, n, 0
    ret = 0.0
    while sp >= 0:
        fl, fn, stage = wi[0, sp], wi[1, sp], wi[2, sp]
        if stage == 0 and fn <= 128:
            ret = _leaf(a, fl, fn)
            sp -= 1
            continue
        h = fn // 2
        h -= h % 8
        if stage == 0:  # descend into the left half
            wi[2, sp] = 1
            sp += 1
            wi[0, sp], wi[1, sp], wi[2, sp] = fl, h, 0
        elif stage == 1:  # left half done (ret): keep it, descend into the right half
            wf[sp] = ret
            wi[2, sp] = 2
            sp += 1
            wi[0, sp], wi[1, sp], wi[2, sp] = fl + h, fn - h, 0
        else:  # both halves done
            ret = wf[sp] + ret
            sp -= 1
    return ret


def workspace():
    """The stack of :func:`_pairwise` (64 levels: halving 2**63 values reaches a leaf)."""
    return np.zeros((3, 64), dtype=np.int64), np.zeros(64)


@njit(cache=True, nogil=True, inline="always")
def _value(src, acc, mode, dt, r, j):
    """The scored estimate at ``[r, j]``: ``src`` itself (mode 0) or the predicted
    velocity ``v_p(j) = v(j-1) [+ dt a(j-1)]`` of :func:`abglib.bench.metrics.v_pred`
    (mode 1 without, 2 with the acceleration ``acc``)."""
    if mode == 0:
        return src[r, j]
    if j == 0:
        return 0.0
    if mode == 1:
        return src[r, j - 1]
    return src[r, j - 1] + dt * acc[r, j - 1]


@njit(cache=True, nogil=True)
def score(
    src, acc, mode, nsrc, nacc, has_nz, dt, truth, b, n_vrf, s2, eu, eu_first, e, s, sn, sl, vrf,
    wi, wf,
):  # fmt: skip
    """One output of one coordinate over a chunk of runs (rows).

    ``src``/``acc``/``mode``: the estimate (:func:`_value`); ``nsrc``/``nacc``: the same
    output of the tracked noise (read if ``has_nz``); ``truth`` (R, n); ``b`` the burn-in;
    ``n_vrf`` (>= ``b``) the first sample of the VRF window (< 0: none), ``s2`` the noise
    variance; ``eu`` (R * (n - b),) the Euclidean accumulator (set if ``eu_first``, else
    added to); ``e``, ``s``, ``sn``, ``sl`` scratch (R * (n - b),): the error, its
    square, the noise part's and the lag part's squares; ``vrf`` (R,) written with the
    per-run VRFs; ``wi``, ``wf`` :func:`workspace`.

    Returns ``(finite, sum of squares, sum, max |error|, noise sum of squares, lag sum of
    squares)`` of the error after the burn-in, each as the numpy form computes it.
    """
    rows, n = truth.shape
    c = n - b
    finite = True
    nan = False
    mx = 0.0
    k = 0
    for r in range(rows):
        for j in range(b, n):
            x = _value(src, acc, mode, dt, r, j) - truth[r, j]
            e[k] = x
            sq = x * x
            s[k] = sq
            if eu_first:
                eu[k] = sq
            else:
                eu[k] = eu[k] + sq
            if has_nz:
                y = _value(nsrc, nacc, mode, dt, r, j)
                sn[k] = y * y
                u = x - y
                sl[k] = u * u
            if not math.isfinite(x):
                finite = False
                nan = nan or math.isnan(x)
            ax = abs(x)
            if ax > mx:
                mx = ax
            k += 1
    if nan:
        mx = np.nan
    total_sq = 0.0 + _pairwise(s, 0, k, wi, wf)
    # the sum of a strided view (b > 0): chunks of whole rows of at most BUFSIZE values;
    # with no burn-in the error is contiguous, one chunk
    per = max(1, BUFSIZE // c) * c if b > 0 else max(k, 1)
    total = 0.0
    lo = 0
    while lo < k:
        m = min(per, k - lo)
        total += _pairwise(e, lo, m, wi, wf)
        lo += m
    noise_sq = 0.0
    lag_sq = 0.0
    if has_nz:
        noise_sq = 0.0 + _pairwise(sn, 0, k, wi, wf)
        lag_sq = 0.0 + _pairwise(sl, 0, k, wi, wf)
        if n_vrf >= 0:
            w = n - n_vrf
            for r in range(rows):
                vrf[r] = ((0.0 + _pairwise(sn, r * c + (n_vrf - b), w, wi, wf)) / w) / s2
    return finite, total_sq, total, mx, noise_sq, lag_sq


@njit(cache=True, nogil=True)
def euclid(eu, wi, wf):
    """``(np.sum(eu), np.max(np.sqrt(eu)))`` of the Euclidean accumulator (contiguous,
    flattened): the square root is monotonic and correctly rounded, so the maximum's
    root is the roots' maximum (NaN if any is NaN)."""
    mx = 0.0
    nan = False
    for k in range(eu.size):
        v = eu[k]
        if v > mx:
            mx = v
        elif v != v:
            nan = True
    return 0.0 + _pairwise(eu, 0, eu.size, wi, wf), (np.nan if nan else math.sqrt(mx))
