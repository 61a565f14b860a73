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
    v = a[lo : lo + n]  # a view indexed from 0: the loop vectorises
    if n < 8:
        res = 0.0
        for i in range(n):
            res += v[i]
        return res
    r0, r1, r2, r3 = v[0], v[1], v[2], v[3]
    r4, r5, r6, r7 = v[4], v[5], v[6], v[7]
    m = n - (n % 8)
    for i in range(8, m, 8):
        r0 += v[i]
        r1 += v[i + 1]
        r2 += v[i + 2]
        r3 += v[i + 3]
        r4 += v[i + 4]
        r5 += v[i + 5]
        r6 += v[i + 6]
        r7 += v[i + 7]
    res = ((r0 + r1) + (r2 + r3)) + ((r4 + r5) + (r6 + r7))
    for i in range(m, n):
        res += v[i]
    return res


@njit(cache=True, nogil=True)
def _tree(a, lo, n, wi, wf, mode, plan):
    """numpy's pairwise sum of ``n`` values (``DOUBLE_pairwise_sum``: ``sum(v[:h]) +
    sum(v[h:])`` with ``h`` half of ``n`` rounded down to a multiple of 8, leaves of at
    most 128 values), on an explicit stack in the workspace ``wi``, ``wf``
    (:func:`workspace`; numba's disk cache does not reload self-recursive functions
    safely). The leaves come left to right; ``mode`` says what a leaf is:

    * 0: the values ``a[lo:lo+n]`` themselves (returns the sum);
    * 1: the next entry of ``a``, a leaf's sum computed beforehand (returns the sum);
    * 2: write each leaf's length to ``plan`` (returns the number of leaves).
    """
    sp = 0
    wi[0, 0], wi[1, 0], wi[2, 0] = lo, n, 0
    ret = 0.0
    idx = 0
    while sp >= 0:
        fl, fn, stage = wi[0, sp], wi[1, sp], wi[2, sp]
        if stage == 0 and fn <= 128:
            if mode == 0:
                ret = _leaf(a, fl, fn)
            elif mode == 1:
                ret = a[idx]
            else:
                plan[idx] = fn
            idx += 1
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
    return float(idx) if mode == 2 else ret


@njit(cache=True, nogil=True)
def _pairwise(a, lo, n, wi, wf):
    """numpy's pairwise sum of the 1-D contiguous ``a[lo:lo+n]`` (:func:`_tree`)."""
    if n <= 128:
        return _leaf(a, lo, n)
    return _tree(a, lo, n, wi, wf, 0, wi[0])


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
def score(src, acc, mode, nsrc, nacc, has_nz, dt, truth, b, n_vrf, s2, eu, eu_first, vrf, wi, wf):
    """One output of one coordinate over a chunk of runs (rows).

    ``src``/``acc``/``mode``: the estimate (:func:`_value`); ``nsrc``/``nacc``: the same
    output of the tracked noise (read if ``has_nz``); ``truth`` (R, n); ``b`` the burn-in;
    ``n_vrf`` (>= ``b``) the first sample of the VRF window (< 0: none), ``s2`` the noise
    variance; ``eu`` (R * (n - b),) the Euclidean accumulator (set if ``eu_first``, else
    added to); ``vrf`` (R,) written with the per-run VRFs; ``wi``, ``wf``
    :func:`workspace`.

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
