r"""Monte Carlo metrics of one tracker variant on one dataset scenario (a benchmark cell).

Per coordinate of a scenario (arrays ``(runs, n)``: truth position and velocity, and the
measurements ``z``), a tracker's outputs are scored against the truth over the samples
after a burn-in:

* RMSE and maximum absolute error of the smoothed and predicted position and velocity
  (``x_smooth``, ``x_pred``, ``v_smooth``, ``v_pred``);
* the steady-state lag: the mean error after the burn-in (over runs and samples);
* the split of the error of a *linear* tracker into a noise part and a lag part. The
  recursion (seed 000, eqs 1-6) is linear in ``z`` for every initialisation
  :func:`abglib.track` offers, so with ``z = truth + noise``::

      track(z) - truth = track(noise) + (track(truth) - truth)
                          noise part    lag part (deterministic given the truth)

  The noise part is computed by tracking the noise ``z - truth`` itself; the lag part
  is the difference;
* the measured variance reduction factor: the mean square of the noise part after the
  tracker has settled, over the noise variance ``sigma^2``, against the analytic VRF
  (:func:`abglib.analysis.vrf` for white noise, :func:`coloured_vrf` for first-order
  autoregressive noise). Samples within a run are correlated, so the Monte Carlo
  confidence interval comes from the across-run spread of the per-run estimates
  (Student t with ``runs - 1`` degrees of freedom), never from the pooled samples;
* a divergence flag: unstable fixed gains (:func:`abglib.analysis.is_stable`) or
  non-finite errors.

:func:`vrf_failures` applies the build check: a fixed-gain variant on white noise whose
measured VRF lies outside its (Bonferroni-adjusted, simultaneous) confidence interval
around the exact VRF is a bug, and :class:`VRFMismatchError` is raised.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Mapping, Sequence

import numpy as np
import scipy.linalg

from .._checks import AbglibValueError, check_in_range, check_positive
from ..analysis import is_stable, pole_radius, vrf
from ..analysis._statespace import state_space
from ..engine import OUTPUTS as TRACK_OUTPUTS
from ..engine import track
from ..gains import Gains, require_gains
from . import _family

__all__ = [
    "OUTPUTS",
    "VRFMismatchError",
    "coloured_vrf",
    "evaluate_cell",
    "fail_threshold",
    "noise_vrf",
    "settle_samples",
    "t_quantile",
    "v_pred",
    "vrf_failures",
]

#: Estimates scored against the truth (defined in ``abglib.bench._family``, which the workflow's
#: parse imports without this module's numerics).
OUTPUTS = _family.OUTPUTS
# the tracker outputs (abglib.track) each scored estimate is made of (v_pred: eq 2's
# prediction from the smoothed velocity and acceleration, as _estimates computes it)
_MADE_OF = {
    "x_smooth": ("x_smooth",),
    "x_pred": ("x_pred",),
    "v_smooth": ("v_smooth",),
    "v_pred": ("v_smooth", "a_smooth"),
}


class VRFMismatchError(RuntimeError):
    """A fixed-gain variant's measured VRF is outside its confidence interval: a bug."""


# --------------------------------------------------------------------------- theory
def coloured_vrf(gains: Gains, rho: float, dt: float = 1.0) -> dict:
    r"""Steady-state output variance per unit noise variance for AR(1) measurement noise.

    Parameters
    ----------
    gains : Gains
        Scalar, stable canonical gains.
    rho : float
        Lag-one correlation of the noise, ``-1 < rho < 1`` (``rho = 0``: white noise,
        equal to :func:`abglib.analysis.vrf`).
    dt : float
        Sample interval ``T`` > 0.

    Returns
    -------
    dict
        Keys ``x_smooth, v_smooth, a_smooth, x_pred, v_pred, a_pred``.

    Notes
    -----
    The noise ``w(n) = rho w(n-1) + sqrt(1 - rho^2) e(n)`` (unit variance, ``e`` white)
    drives the tracker ``s(n) = F s(n-1) + K w(n)`` (seed 000, eqs 1-6; state space of
    :func:`abglib.analysis.state_space`). The augmented state ``[s, w]`` has

    .. math::
        A = \begin{bmatrix} F & \rho K \\ 0 & \rho \end{bmatrix},\quad
        B = \sqrt{1-\rho^2}\begin{bmatrix} K \\ 1 \end{bmatrix},\quad
        P = A P A^T + B B^T,

    and the VRFs are the diagonal of the ``s`` block (smoothed) and of
    ``Phi P_s Phi^T`` (predicted). Equivalently :math:`\sum_{k,l} h_k h_l
    \rho^{|k-l|}` for the impulse response ``h`` of each output (direct summation, the
    test's independent route).
    """
    g = require_gains(gains)
    if g.shape != ():
        raise AbglibValueError(f"coloured_vrf needs scalar gains, got a bank of shape {g.shape}")
    r = float(check_in_range("rho", rho, -1.0, 1.0))
    if not is_stable(g):
        raise AbglibValueError(f"gains {g!r} are unstable: the steady-state variance is unbounded")
    ss = state_space(g, float(check_positive("dt", dt)))
    n = ss.n
    A = np.zeros((n + 1, n + 1))
    A[:n, :n] = ss.F
    A[:n, n] = r * ss.K
    A[n, n] = r
    B = math.sqrt(1.0 - r * r) * np.append(ss.K, 1.0)
    P = scipy.linalg.solve_discrete_lyapunov(A, np.outer(B, B), method="bilinear")[:n, :n]
    Pp = ss.Phi @ P @ ss.Phi.T
    p, pp = np.diag(P), np.diag(Pp)
    if n == 2:
        return dict(
            x_smooth=p[0], v_smooth=p[1], a_smooth=0.0, x_pred=pp[0], v_pred=pp[1], a_pred=0.0
        )
    return dict(
        x_smooth=p[0], v_smooth=p[1], a_smooth=p[2], x_pred=pp[0], v_pred=pp[1], a_pred=pp[2]
    )


def noise_vrf(gains: Gains, noise: Mapping, dt: float = 1.0) -> dict | None:
    """Analytic VRF for a noise description, or None where there is no exact theory.

    ``noise``: ``{"model": "white"}`` (:func:`abglib.analysis.vrf`) or
    ``{"model": "ar1", "rho": r}`` (:func:`coloured_vrf`); None for time-varying or
    unstable gains. An unknown noise model raises: it must not switch the check off quietly.
    """
    g = require_gains(gains)
    if g.shape != () or not is_stable(g):
        return None
    model = noise.get("model")
    if model == "white":
        return vrf(g, dt)
    if model == "ar1":
        if "rho" not in noise:
            raise AbglibValueError("noise model 'ar1' needs 'rho', got keys " + str(sorted(noise)))
        return coloured_vrf(g, float(noise["rho"]), dt)
    raise AbglibValueError(f"noise model must be one of ['white', 'ar1'], got {model!r}")


def settle_samples(gains: Gains, eps: float = 1e-8, cap: int = 10**6) -> int:
    """Samples after which a transient of the tracker has decayed below ``eps`` (relative).

    ``ceil(log(eps) / log(r))`` for the pole radius ``r`` (:func:`abglib.analysis.pole_radius`);
    ``eps = 1e-8`` leaves margin for the polynomial factors of repeated poles. 0 for
    deadbeat gains (``r = 0``); ``cap`` for time-varying or unstable gains.
    """
    g = require_gains(gains)
    if g.shape != () or not is_stable(g):
        return cap
    r = float(pole_radius(g))
    if r <= 0.0:
        return 0
    return min(cap, math.ceil(math.log(eps) / math.log(r)))


def fail_threshold(runs: int, n_checks: int, family_alpha: float) -> float:
    """``|t|`` above which a measured VRF fails the build.

    Bonferroni over ``n_checks`` simultaneous checks at family-wise error ``family_alpha``
    (two-sided), Student t with ``runs - 1`` degrees of freedom: with exact theory a
    correct build fails with probability at most ``family_alpha``.
    """
    if runs < 2:
        raise AbglibValueError(f"runs must be >= 2 for a confidence interval, got {runs!r}")
    a = float(check_in_range("family_alpha", family_alpha, 0.0, 1.0))
    n = max(int(n_checks), 1)
    import scipy.stats  # lazy: 0.8 s of import the workflow's parse does not need

    return float(scipy.stats.t.ppf(1.0 - a / (2.0 * n), runs - 1))


# --------------------------------------------------------------------------- estimates
def v_pred(v_smooth: np.ndarray, a_smooth: np.ndarray | None, dt) -> np.ndarray:
    """Predicted velocity ``v_p(n) = v̄(n-1) + T ā(n-1)`` (seed 000, eq 5); 0 at n = 0.

    Matches the zero initial state of :func:`abglib.track` (``init="zero"``); for a point
    initialisation the first samples are inside the burn-in anyway.
    """
    out = np.zeros_like(v_smooth)
    out[..., 1:] = v_smooth[..., :-1]
    if a_smooth is not None:
        out[..., 1:] += np.asarray(dt) * a_smooth[..., :-1]
    return out


def _estimates(result, dt) -> dict:
    """The scored estimates of a tracker result; None for those it does not provide
    (e.g. an estimation method returning only ``x_pred``)."""
    a = getattr(result, "a_smooth", None)
    vs = getattr(result, "v_smooth", None)
    xs = getattr(result, "x_smooth", None)
    return {
        "x_smooth": None if xs is None else np.asarray(xs),
        "x_pred": np.asarray(result.x_pred),
        "v_smooth": None if vs is None else np.asarray(vs),
        "v_pred": None
        if vs is None
        else v_pred(np.asarray(vs), None if a is None else np.asarray(a), dt),
    }


def _ci(per_run: np.ndarray, level: float) -> tuple[float, float, float, float]:
    """Mean, standard error and the two-sided Student-t CI of per-run estimates."""
    m = float(np.mean(per_run))
    se = float(np.std(per_run, ddof=1) / math.sqrt(per_run.size))
    q = t_quantile(0.5 + level / 2.0, per_run.size - 1)
    return m, se, m - q * se, m + q * se


@functools.lru_cache(maxsize=256)
def t_quantile(p: float, dof: int) -> float:
    """Student-t quantile ``scipy.stats.t.ppf(p, dof)``, cached: it costs ~1 ms a call and
    a build asks for the same few (one level, one number of runs) thousands of times."""
    import scipy.stats

    return float(scipy.stats.t.ppf(p, dof))


# --------------------------------------------------------------------------- the cell
def evaluate_cell(
    coords: Mapping,
    dt: float,
    *,
    gains: Gains | None = None,
    runner: Callable | None = None,
    noise: Mapping | None = None,
    burn_in: int = 0,
    init="two_point",
    ci_level: float = 0.95,
    chunk_runs: int = 1000,
    outputs: Sequence[str] = OUTPUTS,
) -> list[dict]:
    """Score a tracker on one scenario over its Monte Carlo runs.

    Parameters
    ----------
    coords : mapping
        ``coord -> {"truth_pos": (runs, n), "truth_vel": (runs, n), "z": (runs, n),
        "sigma": float}`` (``sigma``: the standard deviation of that coordinate's noise).
    dt : float
        Sample interval ``T`` (s).
    gains : Gains, optional
        A fixed-gain or time-varying-gain tracker (run with :func:`abglib.track`).
    runner : callable, optional
        Instead of ``gains``: ``runner(z (runs, n)) -> object with x_pred`` and, where the
        method has them, ``x_smooth``, ``v_smooth``, ``a_smooth`` (metrics of missing
        outputs are empty), for estimation methods that are not a gain recursion; no
        noise/lag split and no VRF for these.
    noise : mapping, optional
        Noise description for the analytic VRF (:func:`noise_vrf`), e.g.
        ``{"model": "white"}`` or ``{"model": "ar1", "rho": 0.8}``.
    burn_in : int
        Leading samples excluded from every metric. The VRF is measured from
        ``max(burn_in, settle_samples(gains))`` on.
    init : str
        :func:`abglib.track` initialisation (linear in ``z`` for every choice).
    ci_level : float
        Level of the reported confidence interval of the measured VRF.
    chunk_runs : int
        Runs tracked at once (bounds memory for large Monte Carlo sizes).
    outputs : sequence of str, default all of ``OUTPUTS``
        The estimates to score (the columns of the others are left out); a fixed-gain
        tracker computes only the outputs these need. The scores of an output do not
        depend on which others are scored.

    Returns
    -------
    list of dict
        One row per coordinate and a row ``coord="all"`` (RMSE of the Euclidean error,
        maximum Euclidean error; the VRF columns are those of the first coordinate pooled
        with the others when they share sigma, else empty).
    """
    if (gains is None) == (runner is None):
        raise AbglibValueError("evaluate_cell needs exactly one of gains and runner")
    outputs = tuple(outputs)
    unknown = [o for o in outputs if o not in OUTPUTS]
    if unknown or not outputs or len(set(outputs)) != len(outputs):
        raise AbglibValueError(
            f"outputs must be distinct names from {list(OUTPUTS)}, got {list(outputs)}"
        )
    needed = {t for o in outputs for t in _MADE_OF[o]}
    track_outputs = tuple(t for t in TRACK_OUTPUTS if t in needed)
    names = list(coords)
    if not names:
        raise AbglibValueError("coords must hold at least one coordinate")
    first = coords[names[0]]["z"]
    runs, n = np.shape(first)
    burn_in = int(burn_in)
    if not 0 <= burn_in < n:
        raise AbglibValueError(f"burn_in must satisfy 0 <= burn_in < {n}, got {burn_in}")
    linear = gains is not None
    fixed = linear and require_gains(gains).shape == ()
    stable = bool(is_stable(gains)) if fixed else None
    theory = noise_vrf(gains, noise, dt) if (fixed and noise is not None) else None
    settle = settle_samples(gains) if fixed else n
    n_vrf = max(burn_in, settle)
    vrf_window = theory is not None and n - n_vrf >= 2
    # accumulators per coordinate (and Euclidean over all)
    acc = {c: {o: {"sq": 0.0, "max": 0.0, "sum": 0.0} for o in outputs} for c in names}
    split = {c: {o: {"noise_sq": 0.0, "lag_sq": 0.0} for o in outputs} for c in names}
    per_run_vrf = {c: {o: [] for o in outputs} for c in names}
    eu = {o: {"sq": 0.0, "max": 0.0} for o in outputs}
    finite = True
    m = n - burn_in
    fast = _fast_scoring(n - burn_in)
    score = _score_fast if fast else _score_numpy
    scratch: dict = {}
    with np.errstate(over="ignore", invalid="ignore"):
        for lo in range(0, runs, int(chunk_runs)):
            hi = min(runs, lo + int(chunk_runs))
            eu_sq = {o: 0.0 for o in outputs}
            for c in names:
                d = coords[c]
                z = np.asarray(d["z"][lo:hi], dtype=float)
                truth = {
                    "x": np.asarray(d["truth_pos"][lo:hi], dtype=float),
                    "v": np.asarray(d["truth_vel"][lo:hi], dtype=float),
                }
                sigma = float(check_positive("sigma", d["sigma"]))
                if linear:
                    res = track(z, gains, dt, init=init, outputs=track_outputs)
                    nres = track(z - truth["x"], gains, dt, init=init, outputs=track_outputs)
                else:
                    res, nres = runner(z), None
                for o in outputs:
                    r = score(
                        res,
                        nres,
                        o,
                        dt,
                        truth[o[0]],
                        burn_in,
                        n_vrf,
                        vrf_window,
                        sigma**2,
                        eu_sq[o],
                        scratch,
                    )
                    if r is None:
                        acc[c][o]["missing"] = True
                        continue
                    ok, sq, tot, mx, noise_sq, lag_sq, vrf_runs, eu_sq[o] = r
                    finite &= ok
                    a = acc[c][o]
                    a["sq"] += sq
                    a["sum"] += tot
                    a["max"] = max(a["max"], mx)
                    if linear:
                        split[c][o]["noise_sq"] += noise_sq
                        split[c][o]["lag_sq"] += lag_sq
                        if vrf_window:
                            per_run_vrf[c][o].append(vrf_runs)
            for o in outputs:
                if np.ndim(eu_sq[o]) == 0:  # output not provided
                    eu[o]["missing"] = True
                    continue
                sq, mx = _euclid(eu_sq[o], fast, scratch)
                eu[o]["sq"] += sq
                eu[o]["max"] = max(eu[o]["max"], mx)
    diverged = (stable is False) or not finite
    common = {
        "runs": runs,
        "samples": n,
        "burn_in": burn_in,
        "vrf_from_sample": n_vrf if vrf_window else None,
        "stable": stable,
        "diverged": diverged,
        "fixed_gain": fixed,
    }
    rows = []
    for c in names:
        row = {"coord": c, "sigma": float(coords[c]["sigma"]), **common}
        for o in outputs:
            a = acc[c][o]
            have = not a.get("missing")
            row[f"rmse_{o}"] = _finite(math.sqrt(a["sq"] / (runs * m))) if have else None
            row[f"max_{o}"] = _finite(a["max"]) if have else None
            row[f"lag_{o}"] = _finite(a["sum"] / (runs * m)) if have else None
            row[f"noise_rms_{o}"] = (
                _finite(math.sqrt(split[c][o]["noise_sq"] / (runs * m))) if linear else None
            )
            row[f"lag_rms_{o}"] = (
                _finite(math.sqrt(split[c][o]["lag_sq"] / (runs * m))) if linear else None
            )
            _vrf_columns(row, o, per_run_vrf[c][o], theory, ci_level)
        rows.append(row)
    if diverged:  # the numbers of a diverging recursion are overflow, not metrics
        for r in rows:
            for k in list(r):
                if k.split("_")[0] in ("rmse", "max", "lag", "noise"):
                    r[k] = None
        linear = False
    row = {"coord": "all", "sigma": None, **common}
    for o in outputs:
        gone = diverged or eu[o].get("missing", False)
        row[f"rmse_{o}"] = None if gone else _finite(math.sqrt(eu[o]["sq"] / (runs * m)))
        row[f"max_{o}"] = None if gone else _finite(eu[o]["max"])
        row[f"lag_{o}"] = None
        for k in ("noise_rms", "lag_rms"):
            vals = [r[f"{k}_{o}"] for r in rows]
            row[f"{k}_{o}"] = (
                _finite(math.sqrt(sum(v**2 for v in vals)))
                if linear and all(v is not None for v in vals)
                else None
            )
        _vrf_columns(row, o, [], None, ci_level)
    rows.append(row)
    return rows


def _fast_scoring(cols: int) -> bool:
    """Whether the compiled scoring reproduces numpy's sums for rows of ``cols`` values
    (a strided view is summed in buffer chunks of whole rows; longer rows are split in a
    way the kernels do not follow, so they take the numpy form)."""
    from . import _metric_kernels

    return 1 <= cols <= _metric_kernels.BUFSIZE


def _score_numpy(res, nres, o, dt, truth, burn_in, n_vrf, vrf_window, s2, eu_prev, scratch):
    """The metrics of output ``o`` of one coordinate over one chunk of runs, in numpy.

    ``res``/``nres``: the tracker's result on the measurements and (linear trackers) on
    the noise alone; ``eu_prev`` the Euclidean accumulator so far (0.0 or an array).
    Returns None if the tracker does not provide ``o``, else ``(finite, sum of squares,
    sum, max |error|, noise sum of squares, lag sum of squares, per-run VRFs or None,
    Euclidean accumulator)``. The reference for :func:`_score_fast` (same bits)."""
    est = _estimates(res, dt)[o]
    if est is None:
        return None
    err = (est - truth)[:, burn_in:]
    ok = bool(np.all(np.isfinite(err)))
    sq = float(np.sum(err**2))
    tot = float(np.sum(err))
    mx = float(np.max(np.abs(err)))
    eu_new = eu_prev + err**2
    noise_sq = lag_sq = 0.0
    vrf_runs = None
    if nres is not None:
        nz = _estimates(nres, dt)[o]
        noise_part = nz[:, burn_in:]
        lag_part = err - noise_part
        noise_sq = float(np.sum(noise_part**2))
        lag_sq = float(np.sum(lag_part**2))
        if vrf_window:
            w = nz[:, n_vrf:]
            vrf_runs = np.mean(w**2, axis=1) / s2
    return ok, sq, tot, mx, noise_sq, lag_sq, vrf_runs, eu_new


def _output_operands(res, o):
    """``(src, acc, mode)`` of :func:`abglib.bench._metric_kernels.score` for output
    ``o`` of a tracker result (None if it does not provide it)."""
    if o in ("x_smooth", "x_pred"):
        src = getattr(res, o, None)
        return None if src is None else (np.asarray(src), None, 0)
    vs = getattr(res, "v_smooth", None)
    if vs is None:
        return None
    a = getattr(res, "a_smooth", None)
    if o == "v_smooth":
        return np.asarray(vs), None, 0
    return np.asarray(vs), (None if a is None else np.asarray(a)), (1 if a is None else 2)


def _scratch(scratch: dict, key: str, shape) -> np.ndarray:
    buf = scratch.get(key)
    if buf is None or buf.shape != shape:
        buf = scratch[key] = np.empty(shape)
    return buf


def _score_fast(res, nres, o, dt, truth, burn_in, n_vrf, vrf_window, s2, eu_prev, scratch):
    """:func:`_score_numpy` in one compiled pass that releases the GIL (same bits)."""
    from .._kernels import pairwise_workspace, read_only
    from . import _metric_kernels

    ops = _output_operands(res, o)
    if ops is None:
        return None
    src, acc_arr, mode = ops
    rows, n = truth.shape
    nops = _output_operands(nres, o) if nres is not None else None
    arrays = [src, truth, acc_arr, *(nops[:2] if nops else ())]
    # the numpy form's temporaries are C-ordered (and its sums follow that order) only
    # for C-ordered operands of one shape and a scalar dt
    if np.ndim(dt) != 0 or not all(
        a is None or (a.shape == truth.shape and a.dtype == np.float64 and a.flags.c_contiguous)
        for a in arrays
    ):
        return _score_numpy(
            res, nres, o, dt, truth, burn_in, n_vrf, vrf_window, s2, eu_prev, scratch
        )
    dummy = _scratch(scratch, "dummy", (1, 1))
    if "ws" not in scratch:
        scratch["ws"] = pairwise_workspace()
    first = np.ndim(eu_prev) == 0
    eu_buf = np.empty((rows, n - burn_in)) if first else eu_prev
    nsrc, nacc = (nops[0], nops[1]) if nops else (dummy, None)
    want_vrf = nres is not None and vrf_window
    vrf_runs = np.empty(rows) if want_vrf else _scratch(scratch, "vrf", (1,))
    ok, sq, tot, mx, noise_sq, lag_sq = _metric_kernels.score(
        src,
        dummy if acc_arr is None else acc_arr,
        mode,
        nsrc,
        dummy if nacc is None else nacc,
        nres is not None,
        float(dt),
        read_only(truth),  # one compiled signature, broadcast truth or not
        burn_in,
        n_vrf if want_vrf else -1,
        float(s2),
        eu_buf.reshape(-1),
        first,
        vrf_runs,
        *scratch["ws"],
    )
    return ok, sq, tot, mx, noise_sq, lag_sq, (vrf_runs if want_vrf else None), eu_buf


def _euclid(eu_sq: np.ndarray, fast: bool, scratch: dict) -> tuple[float, float]:
    """``(np.sum(eu_sq), np.max(np.sqrt(eu_sq)))`` of the Euclidean accumulator."""
    if not fast:
        return float(np.sum(eu_sq)), float(np.max(np.sqrt(eu_sq)))
    from .._kernels import pairwise_workspace
    from . import _metric_kernels

    if "ws" not in scratch:
        scratch["ws"] = pairwise_workspace()
    sq, mx = _metric_kernels.euclid(eu_sq.reshape(-1), *scratch["ws"])
    return float(sq), float(mx)


def _finite(x):
    return x if x is not None and math.isfinite(x) else None


def _vrf_columns(row: dict, o: str, chunks: list, theory, level: float) -> None:
    keys = ("theory", "measured", "se", "lo", "hi", "t")
    if not chunks or theory is None:
        row.update({f"vrf_{o}_{k}": None for k in keys})
        return
    per_run = np.concatenate(chunks)
    m, se, lo, hi = _ci(per_run, level)
    th = float(theory[o])
    row.update(
        {
            f"vrf_{o}_theory": th,
            f"vrf_{o}_measured": m,
            f"vrf_{o}_se": se,
            f"vrf_{o}_lo": lo,
            f"vrf_{o}_hi": hi,
            f"vrf_{o}_t": (m - th) / se if se > 0 else (0.0 if m == th else math.inf),
        }
    )


def vrf_failures(rows, threshold: float, noise_models=("white",), model: str | None = None):
    """Rows (and outputs) whose measured VRF is outside ``theory +- threshold * se``.

    Only fixed-gain cells whose noise model is in ``noise_models`` count (``model`` is
    the cell's noise model). Returns a list of ``(coord, output, measured, theory, t)``.
    """
    if model not in noise_models:
        return []
    bad = []
    for r in rows:
        if not r.get("fixed_gain"):
            continue
        for o in OUTPUTS:
            t = r.get(f"vrf_{o}_t")
            if t is not None and abs(t) > threshold:
                bad.append((r["coord"], o, r[f"vrf_{o}_measured"], r[f"vrf_{o}_theory"], t))
    return bad
