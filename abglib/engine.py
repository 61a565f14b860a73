"""The tracker recursion: one exact, compiled implementation of seed 000, eqs 1-6.

:func:`track` runs the alpha-beta(-gamma) recursion over measurements ``z`` of shape
``(..., n)`` (batch axes first, time last), with gains, sample intervals and detection
masks broadcast against ``z``. The per-series loop is compiled with numba as a
generalised ufunc, so numpy does the broadcasting over batch axes and the inner loop
runs at compiled speed without copying broadcast operands.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from ._checks import AbglibValueError, as_float_array, check_positive, describe
from .gains import Gains, require_gains

__all__ = ["INIT_MODES", "OUTPUTS", "TrackResult", "track"]

#: Output arrays :func:`track` can return, in :class:`TrackResult` order.
OUTPUTS = ("x_pred", "x_smooth", "v_smooth", "a_smooth")

#: Initialisation names accepted by :func:`track` (besides an explicit state array).
INIT_MODES = ("zero", "two_point", "three_point")

# number of leading samples consumed by a point initialisation
_POINTS = {"zero": 0, "two_point": 2, "three_point": 3}


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

    An output not requested through ``track(..., outputs=...)`` is ``None``.
    """

    x_pred: np.ndarray | None
    x_smooth: np.ndarray | None
    v_smooth: np.ndarray | None
    a_smooth: np.ndarray | None

    def __iter__(self):
        yield from (self.x_pred, self.x_smooth, self.v_smooth, self.a_smooth)


# --------------------------------------------------------------------------- kernel
def _recursion(z, alpha, beta, gamma, dt, detected, state0, npoints, xp, xs, vs, acc, done):
    """Literal recursion of seed 000, eqs 1-6, for one series (numba-compiled).

    ``npoints`` leading samples (0, 2 or 3) initialise the state from the measurements
    (seed 001, section 3, and its three-point analogue) instead of being filtered.
    The four output buffers are written in place; a buffer of length 1 (an output the
    caller did not request) is skipped, which saves its memory traffic.
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
            # point initialisation: the measurement is taken as the prediction
            # (seed 001, section 3), the state is fitted through the first points
            if i == 0:
                x = z[0]
                v = 0.0
                a = 0.0
            elif i == 1:
                v = (z[1] - z[0]) / T
                x = z[1]
                a = 0.0
            else:
                d1 = (z[1] - z[0]) / dt[1]
                d2 = (z[2] - z[1]) / T
                a = 2.0 * (d2 - d1) / (dt[1] + T)
                v = d2 + 0.5 * a * T
                x = z[2]
            x_p = z[i]
        else:
            # predictor, eqs 4-6
            x_p = x + T * v + 0.5 * T * T * a
            v_p = v + T * a
            if detected[i]:
                # corrector, eqs 1-3
                r = z[i] - x_p
                x = x_p + alpha[i] * r
                v = v_p + (beta[i] / T) * r
                a = a + (gamma[i] / (T * T)) * r
            else:
                # missed detection: coast on the prediction
                x = x_p
                v = v_p
        if w_xp:
            xp[i] = x_p
        if w_xs:
            xs[i] = x
        if w_vs:
            vs[i] = v
        if w_as:
            acc[i] = a
    done[0] = 1


def _recursion_ab(z, alpha, beta, dt, detected, state0, npoints, xp, xs, vs, done):
    """The same recursion with gamma = 0 and no acceleration state (seed 000, eqs 1-2, 4).

    Bit-for-bit what :func:`_recursion` computes when gamma and the initial acceleration
    are zero (the dropped terms are exact zeros), with a shorter dependency chain.
    """
    x = state0[0]
    v = state0[1]
    n = z.shape[0]
    w_xp = xp.shape[0] == n
    w_xs = xs.shape[0] == n
    w_vs = vs.shape[0] == n
    for i in range(n):
        T = dt[i]
        if i < npoints:
            # two-point initialisation (seed 001, section 3, eqs 9-10)
            if i == 0:
                v = 0.0
            else:
                v = (z[1] - z[0]) / T
            x = z[i]
            x_p = z[i]
        else:
            x_p = x + T * v
            if detected[i]:
                r = z[i] - x_p
                x = x_p + alpha[i] * r
                v = v + (beta[i] / T) * r
            else:
                x = x_p
        if w_xp:
            xp[i] = x_p
        if w_xs:
            xs[i] = x
        if w_vs:
            vs[i] = v
    done[0] = 1


@functools.cache
def _kernel(order: int = 3):
    """Compile the recursion into a numba gufunc on first use (cached on disk)."""
    from numba import guvectorize

    # The output buffers are passed as inputs with their own core dimension (n or 1) so
    # that unrequested outputs cost no memory; numpy hands the kernel views of the
    # caller's float64 buffers (no casting, no overlap with inputs), so the writes land
    # there. ``done`` is a dummy per-series output that gufuncs require.
    if order == 2:
        sig = "void(f8[:], f8[:], f8[:], f8[:], u1[:], f8[:], i8, f8[:], f8[:], f8[:], u1[:])"
        layout = "(n),(n),(n),(n),(n),(m),(),(p),(q),(r)->()"
        return guvectorize([sig], layout, nopython=True, cache=True)(_recursion_ab)
    sig = (
        "void(f8[:], f8[:], f8[:], f8[:], f8[:], u1[:], f8[:], i8, "
        "f8[:], f8[:], f8[:], f8[:], u1[:])"
    )
    layout = "(n),(n),(n),(n),(n),(n),(m),(),(p),(q),(r),(s)->()"
    return guvectorize([sig], layout, nopython=True, cache=True)(_recursion)


# --------------------------------------------------------------------------- checks
def _time_operand(name: str, arr: np.ndarray, n: int) -> np.ndarray:
    """Broadcast an operand's time axis to length ``n`` (a view, never a copy)."""
    if arr.ndim == 0:
        return np.broadcast_to(arr, (n,))
    if arr.shape[-1] not in (1, n):
        raise AbglibValueError(
            f"{name} has last (time) axis of length {arr.shape[-1]}, but z has {n} samples; "
            f"the last axis must have length 1 or {n} (for a bank of gains add a trailing "
            f"axis, e.g. alpha[:, None])"
        )
    return np.broadcast_to(arr, arr.shape[:-1] + (n,))


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


# --------------------------------------------------------------------------- public
def track(z, gains: Gains, dt=1.0, init="zero", detected=None, outputs=OUTPUTS) -> TrackResult:
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
    outputs : sequence of str, default all of ``OUTPUTS``
        Which of ``x_pred``, ``x_smooth``, ``v_smooth``, ``a_smooth`` to return; the
        others are ``None`` and cost no memory (useful in large Monte Carlo runs).

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
        detections (or samples) it needs.

    Notes
    -----
    Unstable gains run without complaint (users study instability); see
    :func:`abglib.analysis.is_stable`. The recursion is seed 000, eqs 1-6:

    .. math::
        x_p = \\bar x_{n-1} + T\\bar v_{n-1} + \\tfrac12 T^2 \\bar a_{n-1},\\quad
        \\bar x_n = x_p + \\alpha r,\\ \\bar v_n = v_p + \\tfrac{\\beta}{T} r,\\
        \\bar a_n = a_p + \\tfrac{\\gamma}{T^2} r,\\quad r = z_n - x_p.

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
    z = as_float_array("z", z)
    if z.ndim == 0:
        raise AbglibValueError("z must have a time axis (shape (..., n)), got a scalar")
    if z.size == 0:
        raise AbglibValueError(f"z must not be empty, got shape {z.shape}")
    n = z.shape[-1]

    dt = check_positive("dt", dt)
    if detected is None:
        det = np.ones((1,), dtype=np.uint8)
    else:
        det = np.asarray(detected)
        if det.dtype != bool:
            raise AbglibValueError(f"detected must be a boolean array, got dtype {det.dtype}")
        det = det.view(np.uint8)

    operands = {
        "z": z,
        "alpha": np.asarray(gains.alpha, dtype=np.float64),
        "beta": np.asarray(gains.beta, dtype=np.float64),
        "gamma": np.asarray(gains.gamma, dtype=np.float64),
        "dt": dt,
        "detected": det,
    }
    operands = {k: _time_operand(k, v, n) for k, v in operands.items()}
    try:
        full = np.broadcast_shapes(*(v.shape for v in operands.values()))
    except ValueError:
        shapes = ", ".join(f"{k} {v.shape}" for k, v in operands.items())
        raise AbglibValueError(f"operands do not broadcast together: {shapes}") from None

    # measurements must be finite wherever they are used; a finite sum proves it in one
    # cheap pass (an overflowing sum of finite values falls through to the exact check)
    det_full = operands["detected"].astype(bool)
    if np.isfinite(np.sum(z)):
        bad = np.zeros((), dtype=bool)
    else:
        bad = ~np.isfinite(operands["z"]) & det_full
    if bad.any():
        idx = tuple(int(i) for i in np.argwhere(bad)[0])
        zb = np.broadcast_to(operands["z"], full)
        raise AbglibValueError(
            f"z must be finite where detected, got {describe(zb[idx])} at index {idx}; "
            "mark missed detections with detected=False (or a masked array)"
        )

    state0, npoints = _initial_state(init, full[:-1])
    if npoints:
        if n < npoints:
            raise AbglibValueError(f"init={init!r} needs at least {npoints} samples, got n={n}")
        if not det_full[..., :npoints].all():
            raise AbglibValueError(
                f"init={init!r} needs detections at samples 0..{npoints - 1}; "
                "some are marked missed"
            )
        if npoints == 3 and np.any(operands["gamma"] == 0.0):
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

    batch = full[:-1]
    alpha_beta = npoints < 3 and not np.any(operands["gamma"]) and not np.any(state0[..., 2])
    buffers = {
        name: np.empty(full) if name in outputs else np.empty(batch + (1,)) for name in OUTPUTS
    }
    common = (operands["z"], operands["alpha"], operands["beta"])
    if alpha_beta:
        # alpha-beta tracker: acceleration stays exactly zero (np.zeros maps zero pages
        # lazily, so an unread a_smooth costs nothing)
        if "a_smooth" in outputs:
            buffers["a_smooth"] = np.zeros(full)
        _kernel(2)(
            *common,
            operands["dt"],
            operands["detected"],
            state0,
            npoints,
            buffers["x_pred"],
            buffers["x_smooth"],
            buffers["v_smooth"],
        )
    else:
        _kernel(3)(
            *common,
            operands["gamma"],
            operands["dt"],
            operands["detected"],
            state0,
            npoints,
            *buffers.values(),
        )
    return TrackResult(**{k: (v if k in outputs else None) for k, v in buffers.items()})
