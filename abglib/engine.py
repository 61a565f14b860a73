"""The tracker recursion: one exact, compiled implementation of seed 000, eqs 1-6.

:func:`track` runs the alpha-beta(-gamma) recursion over measurements ``z`` of shape
``(..., n)`` (batch axes first, time last), with gains, sample intervals and detection
masks broadcast against ``z``. The per-series loop is compiled with numba as a
generalised ufunc, so numpy does the broadcasting over batch axes and the inner loop
runs at compiled speed without copying broadcast operands.
"""

from __future__ import annotations

import functools
import math
import threading
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from . import _buffers
from ._checks import AbglibValueError, as_float_array, check_positive, describe
from ._perturb import perturb
from .gains import Gains, require_gains

__all__ = ["INIT_MODES", "OUTPUTS", "TrackResult", "track"]

#: Output arrays :func:`track` can return, in :class:`TrackResult` order.
OUTPUTS = ("x_pred", "x_smooth", "v_smooth", "a_smooth")

#: Initialisation names accepted by :func:`track` (besides an explicit state array).
INIT_MODES = ("zero", "two_point", "three_point")

# number of leading samples consumed by a point initialisation
_POINTS = {"zero": 0, "two_point": 2, "three_point": 3}

# series the batched kernel advances together (abglib._kernels.LANES, kept here so that
# importing abglib does not import numba)
_LANES = 4
# below this many samples (series x n) the batched kernel runs on one thread
_PARALLEL_SAMPLES = 1 << 16
# one threaded kernel at a time in a process: numba's workqueue threading layer (the one
# left where neither TBB nor OpenMP is present) aborts on concurrent parallel launches, and
# two callers' threads would only oversubscribe the cores. A caller that finds it taken
# (another thread of the process: Snakemake's in-process jobs) runs the serial kernel,
# which gives bit-identical results.
_PARALLEL_LOCK = threading.Lock()


@dataclass(frozen=True, eq=False)
class TrackResult:
    """Outputs of :func:`track`, each an array shaped like the broadcast input ``(..., n)``.

    Attributes
    ----------
    x_pred : array (..., n)
        ``x_pred[..., k]``: position predicted for sample ``k`` before ``z[k]`` arrived
        (seed 000, eq 4).
    x_smooth, v_smooth, a_smooth : array (..., n)
        Smoothed (corrected) position, velocity and acceleration after sample ``k``
        (seed 000, eqs 1-3). ``a_smooth`` is identically zero for an alpha-beta tracker
        started from zero acceleration.

    Notes
    -----
    An output not requested through ``track(..., outputs=...)`` is ``None``.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 1-6: the smoothed and predicted outputs.
    """

    x_pred: np.ndarray | None
    x_smooth: np.ndarray | None
    v_smooth: np.ndarray | None
    a_smooth: np.ndarray | None

    def __iter__(self):
        yield from (self.x_pred, self.x_smooth, self.v_smooth, self.a_smooth)


# --------------------------------------------------------------------------- kernel
@functools.cache
def _kernel(order: int = 3):
    """The per-series recursion as a numba generalised ufunc (compiled once, cached on disk).

    Used when a gain or the sample interval changes along time; numpy broadcasts the
    operands over the batch axes and calls the loop once per series.
    """
    from numba import guvectorize

    from . import _kernels

    # The output buffers are passed as inputs with their own core dimension (n or 1) so
    # that unrequested outputs cost no memory; numpy hands the kernel views of the
    # caller's float64 buffers (no casting, no overlap with inputs), so the writes land
    # there. ``done`` is a dummy per-series output that gufuncs require.
    if order == 2:
        sig = "void(f8[:], f8[:], f8[:], f8[:], u1[:], f8[:], i8, f8[:], f8[:], f8[:], u1[:])"
        layout = "(n),(n),(n),(n),(n),(m),(),(p),(q),(r)->()"
        return guvectorize([sig], layout, nopython=True, cache=True)(_kernels.series2)
    sig = (
        "void(f8[:], f8[:], f8[:], f8[:], f8[:], u1[:], f8[:], i8, "
        "f8[:], f8[:], f8[:], f8[:], u1[:])"
    )
    layout = "(n),(n),(n),(n),(n),(n),(m),(),(p),(q),(r),(s)->()"
    return guvectorize([sig], layout, nopython=True, cache=True)(_kernels.series3)


@functools.cache
def _batch_kernel(order: int, parallel: bool):
    """The batched kernel (gains and dt constant in time; see :mod:`abglib._kernels`)."""
    from . import _kernels

    return getattr(_kernels, f"run{order}" + ("_par" if parallel else ""))


# --------------------------------------------------------------------------- checks
def _time_shape(name: str, arr: np.ndarray, n: int) -> tuple:
    """The shape of an operand with its time axis broadcast to length ``n``."""
    if arr.ndim == 0:
        return (n,)
    if arr.shape[-1] not in (1, n):
        raise AbglibValueError(
            f"{name} has last (time) axis of length {arr.shape[-1]}, but z has {n} samples; "
            f"the last axis must have length 1 or {n} (for a bank of gains add a trailing "
            f"axis, e.g. alpha[:, None])"
        )
    return arr.shape[:-1] + (n,)


class _TimeOperands(dict):
    """The operands with their time axes broadcast to ``n`` samples (views, never copies),
    each made on first use: the batched path of a constant-gain call needs none of them,
    and making six views cost a fifth of a small call's time."""

    def __init__(self, given: dict, n: int):
        super().__init__()
        self._given, self._n = given, n

    def __missing__(self, name: str) -> np.ndarray:
        arr = self._given[name]
        view = self[name] = np.broadcast_to(arr, _time_shape(name, arr, self._n))
        return view


def _initial_state(init, batch_shape):
    """Return ``(state0 array (..., 3), npoints)`` for the ``init`` argument."""
    if isinstance(init, str):
        if init not in _POINTS:
            raise AbglibValueError(
                f"init must be one of {', '.join(map(repr, INIT_MODES))} or an explicit "
                f"state array [x, v] or [x, v, a], got {init!r}"
            )
        return np.zeros(batch_shape + (3,)), _POINTS[init]
    state = as_float_array("init", init)
    if state.ndim == 0 or state.shape[-1] not in (2, 3):
        raise AbglibValueError(
            "an explicit init state must have last axis [x, v] or [x, v, a] (length 2 or 3), "
            f"got shape {state.shape}"
        )
    if not np.isfinite(state).all():
        raise AbglibValueError(f"init state must be finite, got {describe(state)}")
    if state.shape[-1] == 2:
        state = np.concatenate([state, np.zeros(state.shape[:-1] + (1,))], axis=-1)
    return state, 0


def _out_buffers(out, outputs, full: tuple, inputs: dict) -> dict:
    """Validate ``track(..., out=)``; return ``{name: buffer}`` of the buffers given."""
    if out is None:
        return {}
    if isinstance(out, TrackResult):
        out = dict(zip(OUTPUTS, out, strict=True))
    elif not isinstance(out, Mapping):
        raise AbglibValueError(
            f"out must be a dict of arrays keyed by {', '.join(OUTPUTS)} (or a TrackResult), "
            f"got {type(out).__name__}"
        )
    buffers = {}
    for name, buf in out.items():
        if name not in OUTPUTS:
            raise AbglibValueError(
                f"out has an unknown key {name!r}; the keys are {', '.join(OUTPUTS)}"
            )
        if buf is None:
            continue
        if name not in outputs:
            raise AbglibValueError(
                f"out[{name!r}] is given but {name!r} is not in outputs={tuple(outputs)!r}"
            )
        if not isinstance(buf, np.ndarray):
            raise AbglibValueError(f"out[{name!r}] must be a numpy array, got {type(buf).__name__}")
        if buf.dtype != np.float64:
            raise AbglibValueError(f"out[{name!r}] must have dtype float64, got {buf.dtype}")
        if buf.shape != full:
            raise AbglibValueError(
                f"out[{name!r}] has shape {buf.shape}, but the outputs have shape {full} "
                "(z broadcast against the gains, dt and detected)"
            )
        if not buf.flags.writeable:
            raise AbglibValueError(f"out[{name!r}] is read-only")
        others = {**inputs, **{f"out[{k!r}]": v for k, v in buffers.items()}}
        for other, arr in others.items():
            if isinstance(arr, np.ndarray) and np.may_share_memory(buf, arr):
                raise AbglibValueError(
                    f"out[{name!r}] shares memory with {other}; output buffers must not "
                    "overlap the inputs or each other"
                )
        buffers[name] = buf
    return buffers


# --------------------------------------------------------------------------- public
def track(
    z, gains: Gains, dt=1.0, init="zero", detected=None, outputs=OUTPUTS, out=None
) -> TrackResult:
    """Run a fixed-gain alpha-beta(-gamma) tracker over measurements.

    Parameters
    ----------
    z : array (..., n)
        Measured positions; batch axes (e.g. Monte Carlo runs) first, time last.
        A :class:`numpy.ma.MaskedArray` marks missed detections by its mask.
    gains : Gains
        Canonical gains (seed 000, eqs 1-3). Each of alpha, beta, gamma broadcasts
        against ``z``: a last axis of length ``n`` is a time-varying gain, leading axes
        form a bank (``Gains(a[:, None, None], ...)`` against ``z`` of shape
        ``(runs, n)`` gives outputs ``(k, runs, n)``).
    dt : float or array (..., n), default 1.0
        Sample interval ``T``; ``dt[..., k]`` is the interval from sample ``k - 1`` to
        ``k`` (``dt[..., 0]`` is used to predict from an explicit initial state). Must be
        finite and > 0. An array gives irregular sampling.
    init : {"zero", "two_point", "three_point"} or array (..., 2 | 3), default "zero"
        ``"zero"``: state ``(x, v, a) = 0`` before the first sample. ``"two_point"``:
        seed 001, section 3 (eqs 9-10): samples 0 and 1 are taken as predictions and
        fix ``v = (z1 - z0) / T``; filtering starts at sample 2. ``"three_point"``: the
        alpha-beta-gamma analogue, a parabola through samples 0-2; filtering starts at
        sample 3 (requires nonzero gamma). An array gives the smoothed state
        ``[x, v]`` or ``[x, v, a]`` before the first sample.
    detected : bool array (..., n), optional
        False where the detection was missed: the tracker coasts on its prediction
        (``x_smooth = x_pred``), and ``z`` there is ignored (it may be NaN).
    outputs : sequence of str, default all four
        Which of ``x_pred``, ``x_smooth``, ``v_smooth``, ``a_smooth`` to return; the
        others are ``None`` and cost no memory (useful in large Monte Carlo runs).
    out : dict of str to array, or TrackResult, optional
        Caller-owned buffers to write outputs into, keyed by output name (a previous
        call's :class:`TrackResult` works too; its ``None`` entries are skipped). Each
        must be a writeable float64 array of the broadcast output shape ``(..., n)``
        that shares no memory with the inputs or the other buffers; outputs without a
        buffer are allocated. Reusing buffers across calls saves fresh memory pages
        (the main cost of a large batched call); a non-contiguous buffer works but costs
        a copy. The returned arrays are these buffers. If ``track`` raises, a buffer's
        contents are unspecified. Without ``out``, large outputs (>= 4 MB) reuse the
        memory of earlier outputs that are gone (no array or view of them left), so a
        loop that drops each result before the next call pays no fresh pages either
        (``abglib._buffers``; at most 1 GiB is kept, ``ABGLIB_POOL_BYTES`` sets it).

    Returns
    -------
    TrackResult
        ``x_pred``, ``x_smooth``, ``v_smooth``, ``a_smooth``, each of the broadcast
        shape ``(..., n)`` (``None`` if not requested).

    Raises
    ------
    ValueError
        Empty ``z``; NaN or infinite measurements where detected; ``dt <= 0``; shapes
        that do not broadcast; an unknown ``init``; a point initialisation without the
        detections (or samples) it needs; an ``out`` buffer of the wrong name, type,
        dtype or shape, read-only, overlapping an input or another buffer, or given for
        an output not requested.

    Notes
    -----
    Unstable gains run without complaint (users study instability); see
    :func:`abglib.analysis.is_stable`.

    When gains and ``dt`` are constant along time (any batch shape, any ``init`` and
    ``detected``), a batched kernel advances four series at a time in one loop, on all of
    numba's threads for large batches; gains or ``dt`` that change along time go through
    a per-series loop. Both evaluate the same expressions in the same order (no
    fast-math), so the results do not depend on the path. The recursion is seed 000,
    eqs 1-6:

    .. math::
        x_p = \\bar x_{n-1} + T\\bar v_{n-1} + \\tfrac12 T^2 \\bar a_{n-1},\\quad
        v_p = \\bar v_{n-1} + T\\bar a_{n-1},\\quad a_p = \\bar a_{n-1},

    .. math::
        \\bar x_n = x_p + \\alpha r,\\ \\bar v_n = v_p + \\tfrac{\\beta}{T} r,\\quad
        \\bar a_n = a_p + \\tfrac{\\gamma}{T^2} r,\\quad r = z_n - x_p.

    References
    ----------
    Steelman (1978), seed 000 (``steelman1978``), eqs 1-6: the recursion.
    Al-Wagih & Abdulla, seed 001 (``alwagih``), section 3, eqs 9-10: the two-point start.

    Examples
    --------
    >>> import numpy as np
    >>> from abglib import Gains, track
    >>> out = track(np.arange(5.0), Gains(0.5, 0.2), init="two_point")
    >>> out.x_smooth
    array([0., 1., 2., 3., 4.])
    """
    require_gains(gains)
    if isinstance(outputs, str):
        outputs = (outputs,)
    unknown = [o for o in outputs if o not in OUTPUTS]
    if unknown or not outputs:
        raise AbglibValueError(
            f"outputs must be a non-empty subset of {', '.join(OUTPUTS)}, got {list(outputs)!r}"
        )

    if isinstance(z, np.ma.MaskedArray):
        mask_det = ~np.ma.getmaskarray(z)
        z = np.ma.getdata(z).astype(np.float64)
        detected = mask_det if detected is None else (np.asarray(detected, bool) & mask_det)
    # perturbed arithmetic (ABGLIB_PERTURB, abglib._perturb): a no-op in a plain build
    z = perturb(as_float_array("z", z))
    if z.ndim == 0:
        raise AbglibValueError("z must have a time axis (shape (..., n)), got a scalar")
    if z.size == 0:
        raise AbglibValueError(f"z must not be empty, got shape {z.shape}")
    n = z.shape[-1]

    dt = perturb(check_positive("dt", dt))
    if detected is None:
        det = np.ones((1,), dtype=np.uint8)
    else:
        det = np.asarray(detected)
        if det.dtype != bool:
            raise AbglibValueError(f"detected must be a boolean array, got dtype {det.dtype}")
        det = det.view(np.uint8)

    given = {
        "z": z,
        "alpha": np.asarray(gains.alpha, dtype=np.float64),
        "beta": np.asarray(gains.beta, dtype=np.float64),
        "gamma": np.asarray(gains.gamma, dtype=np.float64),
        "dt": dt,
        "detected": det,
    }
    shapes = {k: _time_shape(k, v, n) for k, v in given.items()}
    try:
        full = np.broadcast_shapes(*shapes.values())
    except ValueError:
        listed = ", ".join(f"{k} {v}" for k, v in shapes.items())
        raise AbglibValueError(f"operands do not broadcast together: {listed}") from None
    operands = _TimeOperands(given, n)

    # the batched kernel needs gains and dt constant along time; it checks z's
    # finiteness itself (a sum per series), saving a pass over z
    batched = n == 1 or all(
        given[k].ndim == 0 or given[k].shape[-1] == 1 for k in ("alpha", "beta", "gamma", "dt")
    )
    if not batched:
        _check_measurements(operands, full, quick=True)

    state0, npoints = _initial_state(init, full[:-1])
    if npoints:
        if n < npoints:
            raise AbglibValueError(f"init={init!r} needs at least {npoints} samples, got n={n}")
        if detected is not None and not (operands["detected"][..., :npoints] != 0).all():
            raise AbglibValueError(
                f"init={init!r} needs detections at samples 0..{npoints - 1}; "
                "some are marked missed"
            )
        if npoints == 3 and np.any(given["gamma"] == 0.0):
            raise AbglibValueError(
                "init='three_point' estimates an acceleration that gamma=0 would never "
                "correct; use init='two_point' for an alpha-beta tracker"
            )
    try:
        np.broadcast_shapes(state0.shape[:-1], full[:-1])
    except ValueError:
        raise AbglibValueError(
            f"init state of shape {state0.shape} does not broadcast against the batch "
            f"shape {full[:-1]}"
        ) from None

    inputs = {k: v for k, v in given.items() if k != "detected"}
    inputs.update(detected=detected, init=init if isinstance(init, np.ndarray) else None)
    user = _out_buffers(out, outputs, full, inputs)
    has_det = detected is not None
    order = 2 if npoints < 3 and not np.any(given["gamma"]) and not np.any(state0[..., 2]) else 3
    buffers = {}
    for name in outputs:
        if name in user:
            buffers[name] = user[name]
        elif name == "a_smooth" and order == 2:
            # an alpha-beta tracker's acceleration stays exactly zero
            buffers[name] = _buffers.zeros(full)
        else:
            # recycled memory of earlier outputs when large (abglib._buffers)
            buffers[name] = _buffers.empty(full)
    if order == 2 and "a_smooth" in user:
        # a previous alpha-beta result's untouched zero pages cost nothing to re-zero
        _buffers.zero_fill(user["a_smooth"])

    if batched:
        _run_batched(order, given, operands, full, state0, npoints, has_det, buffers)
    else:
        _run_series(order, operands, full, state0, npoints, buffers)
    return TrackResult(**{k: buffers.get(k) for k in OUTPUTS})


# --------------------------------------------------------------------------- drivers
def _check_measurements(operands, full, quick):
    """Raise unless z is finite wherever it is used (detected).

    ``quick``: a finite sum proves it in one cheap pass (an overflowing sum of finite
    values falls through to the exact check).
    """
    if quick and np.isfinite(np.sum(operands["z"])):
        return
    bad = ~np.isfinite(operands["z"]) & (operands["detected"] != 0)
    if bad.any():
        idx = tuple(int(i) for i in np.argwhere(bad)[0])
        zb = np.broadcast_to(operands["z"], full)
        raise AbglibValueError(
            f"z must be finite where detected, got {describe(zb[idx])} at index {idx}; "
            "mark missed detections with detected=False (or a masked array)"
        )


def _run_series(order, operands, full, state0, npoints, buffers):
    """The per-series generalised ufunc (operands that change along time)."""
    batch = full[:-1]
    bufs = [buffers.get(k, np.empty(batch + (1,))) for k in OUTPUTS[: order + 1]]
    gains = [operands[k] for k in ("alpha", "beta", "gamma")[:order]]
    _kernel(order)(
        operands["z"], *gains, operands["dt"], operands["detected"], state0, npoints, *bufs
    )


def _rows(arr: np.ndarray, batch: tuple) -> np.ndarray:
    """For each series of ``batch`` (flattened), its row in ``arr.reshape(-1, ...)``."""
    lead = arr.shape[:-1]
    if lead == batch:  # one row per series, in order (read-only, as the broadcast below)
        idx = np.arange(math.prod(lead), dtype=np.int64)
        idx.flags.writeable = False
        return idx
    idx = np.arange(math.prod(lead), dtype=np.int64).reshape(lead)
    return np.broadcast_to(idx, batch).ravel()


def _run_batched(order, given, operands, full, state0, npoints, has_det, buffers):
    """The batched kernel: gains and dt constant along time within each series."""
    batch, n = full[:-1], full[-1]
    nser = math.prod(batch)
    if nser == 0:
        return

    def per_series(name):
        arr = given[name]
        if arr.ndim == 0:  # the same for every series: numpy broadcasts it into prm
            return arr
        return np.broadcast_to(arr[..., 0], batch).ravel()

    T = per_series("dt")
    prm = np.empty((nser, 5))
    prm[:, 0] = T
    prm[:, 1] = 0.5 * T * T
    prm[:, 2] = per_series("alpha")
    prm[:, 3] = per_series("beta") / T
    prm[:, 4] = per_series("gamma") / (T * T)
    st = np.ascontiguousarray(np.broadcast_to(state0, batch + (3,))).reshape(nser, 3)

    z = given["z"]
    rz = _rows(z, batch)
    z2 = np.ascontiguousarray(z.reshape(-1, n))
    if has_det:
        d = given["detected"]
        d = np.broadcast_to(d, (d.shape[:-1] if d.ndim else ()) + (n,))
        rd = _rows(d, batch)
        det = np.ascontiguousarray(d).reshape(-1, n)
    else:
        rd = np.zeros(nser, dtype=np.int64)
        det = np.ones((1, 1), dtype=np.uint8)

    # the kernel writes (series, n) C-contiguous arrays: the caller's buffer as such a
    # view when it is contiguous, else a scratch array copied back afterwards
    names = OUTPUTS[: order + 1]
    views, copy_back = [], []
    for name in names:
        buf = buffers.get(name)
        if buf is None:
            views.append(np.empty((1, 1)))
        elif buf.flags.c_contiguous:
            views.append(buf.reshape(nser, n))
        else:
            views.append(np.empty((nser, n)))
            copy_back.append((buf, views[-1]))
    write = tuple(name in buffers for name in names)
    zs = np.empty(nser)
    from ._kernels import read_only  # numba, as the kernel (never at import abglib)

    # threads pay off only on enough work (their start-up costs ~ 10-100 microseconds)
    parallel = (
        nser >= 2 * _LANES
        and nser * n >= _PARALLEL_SAMPLES
        and _PARALLEL_LOCK.acquire(blocking=False)
    )
    try:
        _batch_kernel(order, parallel)(
            *map(read_only, (z2, rz, prm, st)),
            npoints,
            *map(read_only, (det, rd)),
            has_det,
            tuple(views),
            write,
            zs,
        )
    finally:
        if parallel:
            _PARALLEL_LOCK.release()
    for buf, view in copy_back:
        buf[...] = view.reshape(full)
    if not np.isfinite(np.sum(zs)):
        _check_measurements(operands, full, quick=False)
