"""Compiled reductions behind :func:`abglib.bench.metrics.evaluate_cell` (private; numba).

One pass per (coordinate, output, chunk of runs) computes everything the numpy form of
the cell's metrics computed in a dozen array passes: the error against the truth after
the burn-in, its sum of squares, sum, maximum absolute value and finiteness, the noise and
lag parts' sums of squares, the per-run mean square of the noise part over the VRF window
and the Euclidean accumulator. They release the GIL (two cells of a process run at the
same time) and give the SAME BITS as the numpy form: every sum is evaluated in numpy's
order (:func:`abglib._kernels.pairwise_sum`, numpy's pairwise summation of blocks of up
to 128 values, and the iterator's chunks: a contiguous array is one block, a strided view
is summed in chunks of whole rows of up to 8192 values, numpy's buffer size). Tests
compare the two forms bit for bit (``tests/test_metrics.py``).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from .._kernels import pairwise_leaf as _leaf
from .._kernels import pairwise_sum as _pairwise
from .._kernels import pairwise_tree as _tree

#: numpy's iterator buffer (values): a strided view is reduced in chunks of whole rows
#: of at most this many values; rows longer than this take the numpy form
BUFSIZE = 8192


@njit(cache=True, nogil=True)
def _plan(n, wi, wf):
    """The leaf lengths of the pairwise sum of ``n`` values, in order."""
    plan = np.empty(n // 32 + 8, dtype=np.int64)  # leaves hold >= 64 values but the last
    if n <= 128:
        plan[0] = n
        return plan[:1]
    k = int(_tree(wf, 0, n, wi, wf, 2, plan))
    return plan[:k]


@njit(cache=True, nogil=True)
def _combine(sums, n, wi, wf):
    """The pairwise sum of ``n`` values from its leaves' sums ``sums`` (:func:`_plan`)."""
    if n <= 128:
        return sums[0]
    return _tree(sums, 0, n, wi, wf, 1, wi[0])


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
def score(src, acc, mode, nsrc, nacc, has_nz, dt, truth, b, n_vrf, s2, eu, eu_first, vrf, wi, wf):
    """One output of one coordinate over a chunk of runs (rows).

    ``src``/``acc``/``mode``: the estimate (:func:`_value`); ``nsrc``/``nacc``: the same
    output of the tracked noise (read if ``has_nz``); ``truth`` (R, n); ``b`` the burn-in;
    ``n_vrf`` (>= ``b``) the first sample of the VRF window (< 0: none), ``s2`` the noise
    variance; ``eu`` (R * (n - b),) the Euclidean accumulator (set if ``eu_first``, else
    added to); ``vrf`` (R,) written with the per-run VRFs; ``wi``, ``wf``
    :func:`abglib._kernels.pairwise_workspace`.

    Returns ``(finite, sum of squares, sum, max |error|, noise sum of squares, lag sum of
    squares)`` of the error after the burn-in, each as the numpy form computes it: the
    values of each leaf of numpy's pairwise sums are computed into small buffers (no
    array-sized temporaries) and the leaves' sums combined in numpy's order.
    """
    rows, n = truth.shape
    c = n - b
    k = rows * c
    finite = True
    nan = False
    mx = 0.0
    bx, bs, bn, bl = np.empty(128), np.empty(128), np.empty(128), np.empty(128)
    # the error's square, the noise part's and the lag part's: one pairwise sum each over
    # the k values in row order (numpy sums contiguous temporaries in one piece)
    plan = _plan(k, wi, wf)
    sum_s, sum_n, sum_l = np.empty(plan.size), np.empty(plan.size), np.empty(plan.size)
    r, j, q = 0, b, 0
    for li in range(plan.size):
        m = plan[li]
        for t in range(m):
            x = _value(src, acc, mode, dt, r, j) - truth[r, j]
            bx[t] = x
            sq = x * x
            bs[t] = sq
            if eu_first:
                eu[q] = sq
            else:
                eu[q] = eu[q] + sq
            if has_nz:
                y = _value(nsrc, nacc, mode, dt, r, j)
                bn[t] = y * y
                u = x - y
                bl[t] = u * u
            if not math.isfinite(x):
                finite = False
                nan = nan or math.isnan(x)
            ax = abs(x)
            if ax > mx:
                mx = ax
            q += 1
            j += 1
            if j == n:
                j = b
                r += 1
        sum_s[li] = _leaf(bs, 0, m)
        if has_nz:
            sum_n[li] = _leaf(bn, 0, m)
            sum_l[li] = _leaf(bl, 0, m)
    if nan:
        mx = np.nan
    total_sq = 0.0 + _combine(sum_s, k, wi, wf)
    noise_sq = 0.0
    lag_sq = 0.0
    if has_nz:
        noise_sq = 0.0 + _combine(sum_n, k, wi, wf)
        lag_sq = 0.0 + _combine(sum_l, k, wi, wf)
    # the error's sum: numpy sums the strided view (b > 0) in chunks of whole rows of at
    # most BUFSIZE values; with no burn-in the error is contiguous, one chunk
    per = max(1, BUFSIZE // c) * c if b > 0 else k
    total = 0.0
    r, j, lo = 0, b, 0
    while lo < k:
        size = min(per, k - lo)
        cplan = _plan(size, wi, wf)
        csum = np.empty(cplan.size)
        for li in range(cplan.size):
            m = cplan[li]
            for t in range(m):
                bx[t] = _value(src, acc, mode, dt, r, j) - truth[r, j]
                j += 1
                if j == n:
                    j = b
                    r += 1
            csum[li] = _leaf(bx, 0, m)
        total += _combine(csum, size, wi, wf)
        lo += size
    # per run: the mean square of the noise part over the VRF window
    if has_nz and n_vrf >= 0:
        w = n - n_vrf
        wplan = _plan(w, wi, wf)
        wsum = np.empty(wplan.size)
        for r in range(rows):
            j = n_vrf
            for li in range(wplan.size):
                m = wplan[li]
                for t in range(m):
                    y = _value(nsrc, nacc, mode, dt, r, j)
                    bn[t] = y * y
                    j += 1
                wsum[li] = _leaf(bn, 0, m)
            vrf[r] = ((0.0 + _combine(wsum, w, wi, wf)) / w) / s2
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
