"""Compiled kernels behind :func:`abglib.track` (private; numba, cached on disk).

One literal recursion (seed 000, eqs 1-6) in :func:`_step3` / :func:`_step2`, driven two
ways:

* **per series** (:func:`series3`, :func:`series2`, compiled as numba generalised ufuncs
  by :mod:`abglib.engine`): gains, sample interval and detections may change at every
  sample; numpy broadcasts over the batch axes and calls the loop once per series.
* **batched** (:func:`run3`, :func:`run2` and their ``_par`` twins): gains and sample
  interval constant in time within each series (the Monte Carlo case). Four series are
  advanced together, sample by sample, in one loop: their recursions are independent,
  so the processor overlaps four dependency chains instead of waiting on one (the
  recursion is latency-bound), and the ``_par`` twins split the series over threads
  with ``prange``. The per-series quotients ``beta / T``, ``gamma / T^2`` and
  ``T^2 / 2`` are computed once per series instead of once per sample.

Both drivers evaluate the same expressions in the same order, without ``fastmath``, so
their results are bit-identical to each other and to the literal recursion's rounding.
"""

from __future__ import annotations

import numpy as np
from numba import njit, prange

# series advanced together by one batched block (independent dependency chains)
LANES = 4


def read_only(a: np.ndarray) -> np.ndarray:
    """A read-only view of ``a``, for the array arguments a compiled loop only reads.

    numba types a read-only array apart from a writeable one, so a loop called with both
    kinds (a broadcast view is read-only, a fresh array is not) compiles once for every mix
    seen: five signatures of :func:`run3` in one test session, about four times the cold
    compile time. Passing every read argument read-only keeps one signature a loop.
    """
    v = a.view()
    v.flags.writeable = False
    return v


# --------------------------------------------------------------------------- one step
@njit(cache=True, inline="always")
def _step3(x, v, a, zi, d, T, h, alpha, b, c):
    """One sample of seed 000, eqs 1-6: returns ``(x_p, x, v, a)`` after sample ``zi``.

    ``h = T*T/2`` (as ``0.5 * T * T``), ``b = beta / T``, ``c = gamma / (T * T)``; ``d``
    False is a missed detection (coast on the prediction; ``zi`` is not read).
    """
    x_p = x + T * v + h * a  # eq 4
    v_p = v + T * a  # eq 5
    if d:
        r = zi - x_p
        return x_p, x_p + alpha * r, v_p + b * r, a + c * r  # eqs 1-3
    return x_p, x_p, v_p, a


@njit(cache=True, inline="always")
def _step2(x, v, zi, d, T, alpha, b):
    """:func:`_step3` with ``gamma = a = 0`` (the dropped terms are exact zeros)."""
    x_p = x + T * v
    if d:
        r = zi - x_p
        return x_p, x_p + alpha * r, v + b * r
    return x_p, x_p, v


@njit(cache=True, inline="always")
def _point(z0, z1, z2, T1, T2, i):
    """State ``(x, v, a)`` after point-initialisation sample ``i`` (0, 1 or 2).

    Seed 001, section 3 (eqs 9-10) for samples 0-1 and its three-point (parabola)
    analogue for sample 2; ``T1``, ``T2`` are the intervals before samples 1 and 2.
    """
    if i == 0:
        return z0, 0.0, 0.0
    if i == 1:
        return z1, (z1 - z0) / T1, 0.0
    d1 = (z1 - z0) / T1
    d2 = (z2 - z1) / T2
    a = 2.0 * (d2 - d1) / (T1 + T2)
    return z2, d2 + 0.5 * a * T2, a


# --------------------------------------------------------------------------- per series
def series3(z, alpha, beta, gamma, dt, detected, state0, npoints, xp, xs, vs, acc, done):
    """One series, every operand per sample (body of the order-3 generalised ufunc).

    ``npoints`` leading samples (0, 2 or 3) initialise the state from the measurements
    instead of being filtered. An output buffer of length 1 (not requested) is skipped.
    """
    x = state0[0]
    v = state0[1]
    a = state0[2]
    n = z.shape[0]
    w_xp = xp.shape[0] == n
    w_xs = xs.shape[0] == n
    w_vs = vs.shape[0] == n
    w_as = acc.shape[0] == n
    for i in range(n):
        T = dt[i]
        if i < npoints:
            # the measurement is taken as the prediction (seed 001, section 3)
            x, v, a = _point(z[0], z[min(1, n - 1)], z[min(2, n - 1)], dt[min(1, n - 1)], T, i)
            x_p = z[i]
        else:
            h, b, c = 0.5 * T * T, beta[i] / T, gamma[i] / (T * T)
            x_p, x, v, a = _step3(x, v, a, z[i], detected[i], T, h, alpha[i], b, c)
        if w_xp:
            xp[i] = x_p
        if w_xs:
            xs[i] = x
        if w_vs:
            vs[i] = v
        if w_as:
            acc[i] = a
    done[0] = 1


def series2(z, alpha, beta, dt, detected, state0, npoints, xp, xs, vs, done):
    """:func:`series3` with gamma = 0 and no acceleration state (order-2 gufunc body)."""
    x = state0[0]
    v = state0[1]
    n = z.shape[0]
    w_xp = xp.shape[0] == n
    w_xs = xs.shape[0] == n
    w_vs = vs.shape[0] == n
    for i in range(n):
        T = dt[i]
        if i < npoints:
            x, v, _ = _point(z[0], z[min(1, n - 1)], z[0], dt[min(1, n - 1)], T, i)
            x_p = z[i]
        else:
            x_p, x, v = _step2(x, v, z[i], detected[i], T, alpha[i], beta[i] / T)
        if w_xp:
            xp[i] = x_p
        if w_xs:
            xs[i] = x
        if w_vs:
            vs[i] = v
    done[0] = 1


# --------------------------------------------------------------------------- batched
# Arguments of the batched kernels, for B series of n samples:
#   z (P, n) C-contiguous; rz (B,) the row of z of each series
#   prm (B, 5): dt, 0.5 * dt * dt, alpha, beta / dt, gamma / (dt * dt) of each series
#   st (B, 3): state (x, v, a) before the first sample; npoints: point-initialised samples
#   det (Q, n) uint8 and rd (B,): detections, read only if has_det
#   outs: (x_pred, x_smooth, v_smooth[, a_smooth]) arrays (B, n), each written only where
#     its flag in w is True (else any (1, 1) array)
#   zs (B,): written with the sum of each series' used measurements (the caller's
#     finiteness check, done here to save a pass over z)


@njit(cache=True, inline="always")
def _store4(out, write, i, s0, u0, u1, u2, u3):
    """Write sample ``i`` of series ``s0 .. s0 + 3`` into ``out`` if ``write``."""
    if write:
        out[s0, i] = u0
        out[s0 + 1, i] = u1
        out[s0 + 2, i] = u2
        out[s0 + 3, i] = u3


@njit(cache=True)
def _one3(s, z, rz, prm, st, npoints, det, rd, has_det, outs, w, zs):
    """One series of the batch, order 3 (a leftover of the four-series blocks, or a single
    series: one dependency chain, docs/engine-speed.md)."""
    n = z.shape[1]
    r, q = rz[s], rd[s]
    T, h, al, b, c = prm[s, 0], prm[s, 1], prm[s, 2], prm[s, 3], prm[s, 4]
    x, v, a = st[s, 0], st[s, 1], st[s, 2]
    j1, j2 = min(1, n - 1), min(2, n - 1)
    tot = 0.0
    for i in range(n):
        zi = z[r, i]
        if i < npoints:
            x, v, a = _point(z[r, 0], z[r, j1], z[r, j2], T, T, i)
            x_p = zi
            tot += zi
        else:
            d = det[q, i] != 0 if has_det else True
            x_p, x, v, a = _step3(x, v, a, zi, d, T, h, al, b, c)
            tot += zi if d else 0.0
        if w[0]:
            outs[0][s, i] = x_p
        if w[1]:
            outs[1][s, i] = x
        if w[2]:
            outs[2][s, i] = v
        if w[3]:
            outs[3][s, i] = a
    zs[s] = tot


@njit(cache=True)
def _block3(s0, z, rz, prm, st, npoints, det, rd, has_det, outs, w, zs):
    """Series ``s0 .. s0 + 3`` of the batch, order 3, advanced together sample by sample."""
    n = z.shape[1]
    xp, xs, vs, acc = outs
    s1, s2, s3 = s0 + 1, s0 + 2, s0 + 3
    r0, r1, r2, r3 = rz[s0], rz[s1], rz[s2], rz[s3]
    q0, q1, q2, q3 = rd[s0], rd[s1], rd[s2], rd[s3]
    T0, h0, al0, b0, c0 = prm[s0, 0], prm[s0, 1], prm[s0, 2], prm[s0, 3], prm[s0, 4]
    T1, h1, al1, b1, c1 = prm[s1, 0], prm[s1, 1], prm[s1, 2], prm[s1, 3], prm[s1, 4]
    T2, h2, al2, b2, c2 = prm[s2, 0], prm[s2, 1], prm[s2, 2], prm[s2, 3], prm[s2, 4]
    T3, h3, al3, b3, c3 = prm[s3, 0], prm[s3, 1], prm[s3, 2], prm[s3, 3], prm[s3, 4]
    x0, v0, a0 = st[s0, 0], st[s0, 1], st[s0, 2]
    x1, v1, a1 = st[s1, 0], st[s1, 1], st[s1, 2]
    x2, v2, a2 = st[s2, 0], st[s2, 1], st[s2, 2]
    x3, v3, a3 = st[s3, 0], st[s3, 1], st[s3, 2]
    t0 = t1 = t2 = t3 = 0.0
    j1, j2 = min(1, n - 1), min(2, n - 1)
    for i in range(npoints):
        x0, v0, a0 = _point(z[r0, 0], z[r0, j1], z[r0, j2], T0, T0, i)
        x1, v1, a1 = _point(z[r1, 0], z[r1, j1], z[r1, j2], T1, T1, i)
        x2, v2, a2 = _point(z[r2, 0], z[r2, j1], z[r2, j2], T2, T2, i)
        x3, v3, a3 = _point(z[r3, 0], z[r3, j1], z[r3, j2], T3, T3, i)
        y0, y1, y2, y3 = z[r0, i], z[r1, i], z[r2, i], z[r3, i]
        t0, t1, t2, t3 = t0 + y0, t1 + y1, t2 + y2, t3 + y3
        _store4(xp, w[0], i, s0, y0, y1, y2, y3)
        _store4(xs, w[1], i, s0, x0, x1, x2, x3)
        _store4(vs, w[2], i, s0, v0, v1, v2, v3)
        _store4(acc, w[3], i, s0, a0, a1, a2, a3)
    d0 = d1 = d2 = d3 = True
    for i in range(npoints, n):
        if has_det:
            d0, d1, d2, d3 = det[q0, i] != 0, det[q1, i] != 0, det[q2, i] != 0, det[q3, i] != 0
        y0, y1, y2, y3 = z[r0, i], z[r1, i], z[r2, i], z[r3, i]
        p0, x0, v0, a0 = _step3(x0, v0, a0, y0, d0, T0, h0, al0, b0, c0)
        p1, x1, v1, a1 = _step3(x1, v1, a1, y1, d1, T1, h1, al1, b1, c1)
        p2, x2, v2, a2 = _step3(x2, v2, a2, y2, d2, T2, h2, al2, b2, c2)
        p3, x3, v3, a3 = _step3(x3, v3, a3, y3, d3, T3, h3, al3, b3, c3)
        if has_det:
            t0 += y0 if d0 else 0.0
            t1 += y1 if d1 else 0.0
            t2 += y2 if d2 else 0.0
            t3 += y3 if d3 else 0.0
        else:
            t0, t1, t2, t3 = t0 + y0, t1 + y1, t2 + y2, t3 + y3
        _store4(xp, w[0], i, s0, p0, p1, p2, p3)
        _store4(xs, w[1], i, s0, x0, x1, x2, x3)
        _store4(vs, w[2], i, s0, v0, v1, v2, v3)
        _store4(acc, w[3], i, s0, a0, a1, a2, a3)
    zs[s0], zs[s1], zs[s2], zs[s3] = t0, t1, t2, t3


@njit(cache=True, inline="always")
def _tail2(x, v, tot, z, r, det, q, has_det, outs, w, s, npoints, T, al, b):
    """Samples ``npoints ..`` of series ``s``, order 2; returns the sum of its measurements.

    Inlined twice into :func:`_one2`: with ``T`` the literal ``1.0`` the compiler drops
    ``T * v`` (exact there). The order-3 chain runs through ``h * a`` as well, so there a
    ``T == 1`` copy gained ~5 % on one series and cost ~2 s more of cold compilation:
    :func:`_one3` keeps one loop.
    """
    n = z.shape[1]
    d = True
    for i in range(npoints, n):
        zi = z[r, i]
        if has_det:
            d = det[q, i] != 0
        x_p, x, v = _step2(x, v, zi, d, T, al, b)
        tot += zi if d else 0.0
        if w[0]:
            outs[0][s, i] = x_p
        if w[1]:
            outs[1][s, i] = x
        if w[2]:
            outs[2][s, i] = v
    return tot


@njit(cache=True)
def _one2(s, z, rz, prm, st, npoints, det, rd, has_det, outs, w, zs):
    """One series of the batch, order 2 (gamma = 0, no acceleration state), or a single
    series: one dependency chain, each sample waiting for the previous estimate (seed
    000, eqs 1-6; docs/engine-speed.md). ``T == 1`` (the default ``dt``) takes a copy
    of the loop without ``T * v``, exact there (bit-identical): one multiply fewer on the
    dependency chain, ~20 % faster."""
    n = z.shape[1]
    r, q = rz[s], rd[s]
    T, al, b = prm[s, 0], prm[s, 2], prm[s, 3]
    x, v = st[s, 0], st[s, 1]
    j1 = min(1, n - 1)
    tot = 0.0
    for i in range(npoints):
        zi = z[r, i]
        x, v, _ = _point(z[r, 0], z[r, j1], z[r, 0], T, T, i)
        tot += zi
        if w[0]:
            outs[0][s, i] = zi
        if w[1]:
            outs[1][s, i] = x
        if w[2]:
            outs[2][s, i] = v
    if T == 1.0:
        tot = _tail2(x, v, tot, z, r, det, q, has_det, outs, w, s, npoints, 1.0, al, b)
    else:
        tot = _tail2(x, v, tot, z, r, det, q, has_det, outs, w, s, npoints, T, al, b)
    zs[s] = tot


@njit(cache=True)
def _block2(s0, z, rz, prm, st, npoints, det, rd, has_det, outs, w, zs):
    """Series ``s0 .. s0 + 3`` of the batch, order 2, advanced together sample by sample."""
    n = z.shape[1]
    xp, xs, vs = outs
    s1, s2, s3 = s0 + 1, s0 + 2, s0 + 3
    r0, r1, r2, r3 = rz[s0], rz[s1], rz[s2], rz[s3]
    q0, q1, q2, q3 = rd[s0], rd[s1], rd[s2], rd[s3]
    T0, al0, b0 = prm[s0, 0], prm[s0, 2], prm[s0, 3]
    T1, al1, b1 = prm[s1, 0], prm[s1, 2], prm[s1, 3]
    T2, al2, b2 = prm[s2, 0], prm[s2, 2], prm[s2, 3]
    T3, al3, b3 = prm[s3, 0], prm[s3, 2], prm[s3, 3]
    x0, v0 = st[s0, 0], st[s0, 1]
    x1, v1 = st[s1, 0], st[s1, 1]
    x2, v2 = st[s2, 0], st[s2, 1]
    x3, v3 = st[s3, 0], st[s3, 1]
    t0 = t1 = t2 = t3 = 0.0
    j1 = min(1, n - 1)
    for i in range(npoints):
        x0, v0, _ = _point(z[r0, 0], z[r0, j1], z[r0, 0], T0, T0, i)
        x1, v1, _ = _point(z[r1, 0], z[r1, j1], z[r1, 0], T1, T1, i)
        x2, v2, _ = _point(z[r2, 0], z[r2, j1], z[r2, 0], T2, T2, i)
        x3, v3, _ = _point(z[r3, 0], z[r3, j1], z[r3, 0], T3, T3, i)
        y0, y1, y2, y3 = z[r0, i], z[r1, i], z[r2, i], z[r3, i]
        t0, t1, t2, t3 = t0 + y0, t1 + y1, t2 + y2, t3 + y3
        _store4(xp, w[0], i, s0, y0, y1, y2, y3)
        _store4(xs, w[1], i, s0, x0, x1, x2, x3)
        _store4(vs, w[2], i, s0, v0, v1, v2, v3)
    d0 = d1 = d2 = d3 = True
    for i in range(npoints, n):
        if has_det:
            d0, d1, d2, d3 = det[q0, i] != 0, det[q1, i] != 0, det[q2, i] != 0, det[q3, i] != 0
        y0, y1, y2, y3 = z[r0, i], z[r1, i], z[r2, i], z[r3, i]
        p0, x0, v0 = _step2(x0, v0, y0, d0, T0, al0, b0)
        p1, x1, v1 = _step2(x1, v1, y1, d1, T1, al1, b1)
        p2, x2, v2 = _step2(x2, v2, y2, d2, T2, al2, b2)
        p3, x3, v3 = _step2(x3, v3, y3, d3, T3, al3, b3)
        if has_det:
            t0 += y0 if d0 else 0.0
            t1 += y1 if d1 else 0.0
            t2 += y2 if d2 else 0.0
            t3 += y3 if d3 else 0.0
        else:
            t0, t1, t2, t3 = t0 + y0, t1 + y1, t2 + y2, t3 + y3
        _store4(xp, w[0], i, s0, p0, p1, p2, p3)
        _store4(xs, w[1], i, s0, x0, x1, x2, x3)
        _store4(vs, w[2], i, s0, v0, v1, v2, v3)
    zs[s0], zs[s1], zs[s2], zs[s3] = t0, t1, t2, t3


# Drivers: the series in blocks of LANES, the leftover series one by one; the ``_par``
# twins hand the blocks to numba's thread pool (each block owns its rows: no races).
# All release the GIL (nogil): two threads of a process (Snakemake's in-process jobs)
# track at the same time instead of taking turns.
# The arguments are those of _block3 / _block2 after the first.
@njit(cache=True, nogil=True)
def run3(z, rz, prm, st, npoints, det, rd, has_det, outs, w, zs):
    nblk = rz.shape[0] // LANES
    for k in range(nblk + rz.shape[0] % LANES):
        if k < nblk:
            _block3(k * LANES, z, rz, prm, st, npoints, det, rd, has_det, outs, w, zs)
        else:
            _one3(nblk * (LANES - 1) + k, z, rz, prm, st, npoints, det, rd, has_det, outs, w, zs)


@njit(cache=True, parallel=True, nogil=True)
def run3_par(z, rz, prm, st, npoints, det, rd, has_det, outs, w, zs):
    nblk = rz.shape[0] // LANES
    for k in prange(nblk + rz.shape[0] % LANES):
        if k < nblk:
            _block3(k * LANES, z, rz, prm, st, npoints, det, rd, has_det, outs, w, zs)
        else:
            _one3(nblk * (LANES - 1) + k, z, rz, prm, st, npoints, det, rd, has_det, outs, w, zs)


@njit(cache=True, nogil=True)
def run2(z, rz, prm, st, npoints, det, rd, has_det, outs, w, zs):
    nblk = rz.shape[0] // LANES
    for k in range(nblk + rz.shape[0] % LANES):
        if k < nblk:
            _block2(k * LANES, z, rz, prm, st, npoints, det, rd, has_det, outs, w, zs)
        else:
            _one2(nblk * (LANES - 1) + k, z, rz, prm, st, npoints, det, rd, has_det, outs, w, zs)


@njit(cache=True, parallel=True, nogil=True)
def run2_par(z, rz, prm, st, npoints, det, rd, has_det, outs, w, zs):
    nblk = rz.shape[0] // LANES
    for k in prange(nblk + rz.shape[0] % LANES):
        if k < nblk:
            _block2(k * LANES, z, rz, prm, st, npoints, det, rd, has_det, outs, w, zs)
        else:
            _one2(nblk * (LANES - 1) + k, z, rz, prm, st, npoints, det, rd, has_det, outs, w, zs)


# --------------------------------------------------------------------------- numpy's sums
# numpy's pairwise summation to the bit (np.add.reduce of a contiguous row): the compiled
# loops that replace an array form and must give its bits sum in its order (the M3 search
# below; the benchmark metrics, abglib.bench._metric_kernels; tests/test_metrics.py and
# tests/test_methods.py compare them with numpy)
@njit(cache=True, nogil=True)
def pairwise_leaf(a, lo, n):
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
def pairwise_tree(a, lo, n, wi, wf, mode, plan):
    """numpy's pairwise sum of ``n`` values (``DOUBLE_pairwise_sum``: ``sum(v[:h]) +
    sum(v[h:])`` with ``h`` half of ``n`` rounded down to a multiple of 8, leaves of at
    most 128 values), on an explicit stack in the workspace ``wi``, ``wf``
    (:func:`pairwise_workspace`; numba's disk cache does not reload self-recursive functions
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
                ret = pairwise_leaf(a, fl, fn)
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
def pairwise_sum(a, lo, n, wi, wf):
    """numpy's pairwise sum of the 1-D contiguous ``a[lo:lo+n]`` (:func:`pairwise_tree`)."""
    if n <= 128:
        return pairwise_leaf(a, lo, n)
    return pairwise_tree(a, lo, n, wi, wf, 0, wi[0])


def pairwise_workspace():
    """The stack of :func:`pairwise_sum` (64 levels: halving 2**63 values reaches a leaf)."""
    return np.zeros((3, 64), dtype=np.int64), np.zeros(64)


# --------------------------------------------------------------------------- gain banks
@njit(cache=True, nogil=True)
def best_of_bank2(z, alpha, beta, T, wi, wf, xp, best):
    """Seed 001's M3 search (:func:`abglib.methods.m3`) over a bank of g alpha-beta
    trackers whose gains change along time, ``alpha`` (n,) shared and ``beta`` (g, n), on
    every series of ``z`` (b, n): each tracker two-point initialised and run by the
    arithmetic of :func:`series2` (what :func:`abglib.track` runs for such gains) with
    ``dt = T`` and every sample detected, the whole bank sample by sample (independent
    recursions: their steps overlap instead of waiting on one another); the cost of each,
    the mean squared innovation from sample 2, as ``np.mean`` sums it
    (:func:`pairwise_sum`, in the workspace ``wi``, ``wf`` of :func:`pairwise_workspace`);
    the first tracker of least cost (numpy's ``argmin``: the first NaN if any) into
    ``best`` (b,) and its predictions into ``xp`` (b, n)."""
    g = beta.shape[0]
    nb, n = z.shape
    x, v = np.empty(g), np.empty(g)
    row = np.empty((n, g))  # one series' predictions, the bank innermost
    sq = np.empty(max(n - 2, 0))
    for s in range(nb):
        z0, z1 = z[s, 0], z[s, min(1, n - 1)]
        for i in range(min(2, n)):
            x0, v0, _ = _point(z0, z1, z0, T, T, i)
            for q in range(g):
                x[q], v[q], row[i, q] = x0, v0, z[s, i]
        for i in range(2, n):
            zi, al = z[s, i], alpha[i]
            for q in range(g):
                row[i, q], x[q], v[q] = _step2(x[q], v[q], zi, True, T, al, beta[q, i] / T)
        k, low = 0, 0.0
        for q in range(g):
            for i in range(2, n):
                d = z[s, i] - row[i, q]
                sq[i - 2] = d * d
            cost = pairwise_sum(sq, 0, n - 2, wi, wf) / (n - 2)
            if q == 0 or cost < low:
                k, low = q, cost
            if np.isnan(cost):
                k = q
                break
        best[s] = k
        for i in range(n):
            xp[s, i] = row[i, k]
