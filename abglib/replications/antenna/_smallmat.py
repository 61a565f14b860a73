"""Small dense matrix kernels written out for numba (the antenna's Riccati solvers).

The designs of seed 004 iterate Riccati equations on 6x6 (LQ, eq 2.12) and up to 12x12
(Kalman, eq 7.15) matrices thousands of times. numba's ``@`` and ``np.linalg.solve`` call
BLAS/LAPACK and allocate their results: at these sizes the call overhead and the allocation
cost more than the arithmetic. These kernels write into caller-provided buffers with plain
loops (no BLAS kernel, so no machine-dependent FMA or summation order: the same bits on
every CPU). They compute the same formulas as numpy; their round-off differs from BLAS's by
a few ulps.
"""

from __future__ import annotations

from numba import njit

__all__ = ["gauss_solve", "matmul", "matmul_nt", "matmul_tn"]


@njit(cache=True)
def matmul(a, b, out):
    """``out = a @ b`` (``out`` must not alias ``a`` or ``b``)."""
    n, k = a.shape
    m = b.shape[1]
    for i in range(n):
        for j in range(m):
            out[i, j] = 0.0
        for l in range(k):
            ail = a[i, l]
            if ail != 0.0:  # exact: skipping a zero term changes no finite sum
                for j in range(m):
                    out[i, j] += ail * b[l, j]


@njit(cache=True)
def matmul_nt(a, b, out):
    """``out = a @ b.T``."""
    n, k = a.shape
    m = b.shape[0]
    for i in range(n):
        for j in range(m):
            s = 0.0
            for l in range(k):
                s += a[i, l] * b[j, l]
            out[i, j] = s


@njit(cache=True)
def matmul_tn(a, b, out):
    """``out = a.T @ b``."""
    k, n = a.shape
    m = b.shape[1]
    for i in range(n):
        for j in range(m):
            out[i, j] = 0.0
    for l in range(k):
        for i in range(n):
            ali = a[l, i]
            if ali != 0.0:
                for j in range(m):
                    out[i, j] += ali * b[l, j]


@njit(cache=True)
def gauss_solve(w, x):
    """Solve ``w y = x`` in place (``x`` becomes ``y``, ``w`` is destroyed) by Gaussian
    elimination with partial pivoting (LAPACK's ``gesv`` algorithm). Returns False when
    ``w`` is singular."""
    n = w.shape[0]
    m = x.shape[1]
    for c in range(n):
        piv = c
        big = abs(w[c, c])
        for r in range(c + 1, n):
            if abs(w[r, c]) > big:
                big = abs(w[r, c])
                piv = r
        if big == 0.0:
            return False
        if piv != c:
            for j in range(n):
                w[c, j], w[piv, j] = w[piv, j], w[c, j]
            for j in range(m):
                x[c, j], x[piv, j] = x[piv, j], x[c, j]
        inv = 1.0 / w[c, c]
        for r in range(c + 1, n):
            f = w[r, c] * inv
            if f != 0.0:
                w[r, c] = 0.0
                for j in range(c + 1, n):
                    w[r, j] -= f * w[c, j]
                for j in range(m):
                    x[r, j] -= f * x[c, j]
    for c in range(n - 1, -1, -1):
        for j in range(m):
            s = x[c, j]
            for l in range(c + 1, n):
                s -= w[c, l] * x[l, j]
            x[c, j] = s / w[c, c]
    return True
