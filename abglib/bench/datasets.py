r"""Simulated radar datasets: seeded target tracks, noisy measurements, Parquet + manifest.

A *scenario* is one mapping of ``config.yaml`` (``datasets.scenarios.<name>``)::

    dt: 1.0                       # sample interval T (s)
    n_samples: 300                # samples per run
    runs: 500                     # Monte Carlo runs (independent noise realisations)
    seed: 6001                    # seed of the noise
    noise: {sigma: 25.0, colour: ar1, rho: 0.8}   # colour: white | ar1
    tracks:                       # kinematics, per coordinate (or per XY plane)
      x: {kind: constant_velocity, p0: 0.0, v0: 150.0}
      y: {kind: sinusoid, p0: 0.0, v0: 0.0, amplitude: 2000.0, period: 60.0}

Kinds (``p0`` position at ``t = 0``, ``v0`` velocity, all SI units, ``t = k T``):

``constant_velocity`` (``p0, v0``)
    :math:`p = p_0 + v_0 t`.
``constant_acceleration`` (``p0, v0, a0``)
    :math:`p = p_0 + v_0 t + a_0 t^2 / 2` (seed 001, eq 1).
``polynomial`` (``p0, v0, a0, jerk``)
    :math:`p = p_0 + v_0 t + a_0 t^2/2 + j t^3/6`, e.g. Huang's range track (seed 002)
    with :math:`a_0 = 1000` m/s², :math:`j = 40` m/s³.
``sinusoid`` (``p0, v0, amplitude, period``, optional ``phase`` in rad)
    :math:`p = p_0 + v_0 t + A \sin(2\pi t / P + \varphi)`.
``segments`` (``p0, v0, segments``)
    Constant velocity, interrupted by segments ``{t_start, t_end, acc}`` (piecewise
    constant acceleration) or, in the XY plane, ``{t_start, t_end, turn_rate}`` (a
    coordinated turn: constant speed, velocity rotating at ``turn_rate`` rad/s,
    positive counter-clockwise). Under the key ``xy`` it produces the two coordinates
    ``x`` and ``y`` (``p0``, ``v0`` and ``acc`` are pairs); under any other key it is
    one coordinate (scalars; no turns). Segments are sorted and must not overlap. The
    state is propagated in closed form between boundaries, so samples are exact.

Noise (independent per coordinate, one :class:`numpy.random.SeedSequence` child per
coordinate in order): ``white`` Gaussian of standard deviation ``sigma``, or ``ar1``,
the stationary first-order autoregressive process of :func:`abglib.simulate.ar1_noise`
(every sample has standard deviation ``sigma``, lag-1 correlation ``rho``).

Storage (:func:`write`, :func:`read`): Parquet in long format, one row per
``(run, sample)``, columns :data:`BASE_COLUMNS` then, per coordinate ``c``,
``c_true`` (m), ``c_vel_true`` (m/s), ``c_acc_true`` (m/s²), ``c_meas`` (m); beside it a
JSON manifest with the scenario spec, its sha256 (``abglib.common.files.config_hash``),
the seed, the abglib and generator versions, the schema (names, dtypes, units), and the
sha256 of the Parquet file. Rewriting the same scenario gives byte-identical files.
"""

from __future__ import annotations

import copy
import hashlib
import json
import math
import numbers
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .._checks import AbglibValueError, check_finite, check_in_range, check_positive
from ..simulate import ar1_noise, polynomial_kinematics, sample_times, white_noise

__all__ = [
    "BASE_COLUMNS",
    "COLOURS",
    "GENERATOR_VERSION",
    "KINDS",
    "Dataset",
    "column_schema",
    "generate",
    "read",
    "write",
    "build",
]

#: Version of the generator; bump when the same spec would give different numbers.
GENERATOR_VERSION = "1"

#: Kinematics kinds a track may name.
KINDS = ("constant_velocity", "constant_acceleration", "polynomial", "sinusoid", "segments")

#: Noise colours.
COLOURS = ("white", "ar1")

#: Columns common to every dataset: (name, dtype, unit, description).
BASE_COLUMNS = (
    ("run", "int32", "", "Monte Carlo run index, 0-based"),
    ("sample", "int32", "", "sample index k, 0-based"),
    ("t", "float64", "s", "sample time t = k T"),
)

_PER_COORD = (
    ("true", "m", "true position"),
    ("vel_true", "m/s", "true velocity"),
    ("acc_true", "m/s^2", "true acceleration"),
    ("meas", "m", "noisy measured position (truth + noise)"),
)

# parameters each kind requires (besides 'kind'); optional ones with their default
_REQUIRED = {
    "constant_velocity": ("p0", "v0"),
    "constant_acceleration": ("p0", "v0", "a0"),
    "polynomial": ("p0", "v0", "a0", "jerk"),
    "sinusoid": ("p0", "v0", "amplitude", "period"),
    "segments": ("p0", "v0", "segments"),
}
_OPTIONAL = {"sinusoid": {"phase": 0.0}}
_SCENARIO_KEYS = ("dt", "n_samples", "runs", "seed", "noise", "tracks", "description")


@dataclass(frozen=True, eq=False)
class Dataset:
    """One simulated scenario: truth and noisy measurements of every coordinate.

    Attributes
    ----------
    name : str
        Scenario name (the key in ``config.yaml``).
    dt : float
        Sample interval ``T`` (s).
    t : array (n,)
        Sample times ``k T`` (s).
    coords : tuple of str
        Coordinate names, e.g. ``("x", "y")`` or ``("r",)``.
    truth_pos, truth_vel, truth_acc : dict coord -> array (runs, n)
        True position (m), velocity (m/s), acceleration (m/s²).
    z : dict coord -> array (runs, n)
        Measured positions (m): truth plus noise.
    noise : dict
        ``{"sigma": float, "colour": "white" | "ar1", "rho": float}`` (``rho = 0`` for
        white noise).
    manifest : dict
        Provenance and schema (see the module docstring).
    """

    name: str
    dt: float
    t: np.ndarray
    coords: tuple[str, ...]
    truth_pos: dict
    truth_vel: dict
    truth_acc: dict
    z: dict
    noise: dict
    manifest: dict

    @property
    def runs(self) -> int:
        """Number of Monte Carlo runs."""
        return int(self.z[self.coords[0]].shape[0])

    @property
    def n_samples(self) -> int:
        """Number of samples per run."""
        return int(self.t.shape[0])

    @property
    def nbytes(self) -> int:
        """Bytes of its arrays (times, truth and measurements of every coordinate)."""
        series = (self.truth_pos, self.truth_vel, self.truth_acc, self.z)
        return int(self.t.nbytes) + sum(int(a.nbytes) for d in series for a in d.values())


# --------------------------------------------------------------------------- checks
def _where(name: str, key: str) -> str:
    return f"dataset {name!r}: {key}"


def _number(name: str, key: str, value) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise AbglibValueError(f"{_where(name, key)} must be a real number, got {value!r}")
    return float(check_finite(_where(name, key), value))


def _int(name: str, key: str, value, low: int) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < low:
        raise AbglibValueError(f"{_where(name, key)} must be an integer >= {low}, got {value!r}")
    return int(value)


def _mapping(name: str, key: str, value) -> Mapping:
    if not isinstance(value, Mapping):
        raise AbglibValueError(f"{_where(name, key)} must be a mapping, got {value!r}")
    return value


def _no_unknown(name: str, key: str, spec: Mapping, allowed) -> None:
    unknown = sorted(set(map(str, spec)) - set(allowed))
    if unknown:
        raise AbglibValueError(
            f"{_where(name, key)} has unknown key(s) {unknown}; allowed keys: "
            f"{', '.join(sorted(allowed))}"
        )


def _noise(name: str, spec) -> dict:
    spec = _mapping(name, "noise", spec)
    _no_unknown(name, "noise", spec, ("sigma", "colour", "rho"))
    for key in ("sigma", "colour"):
        if key not in spec:
            raise AbglibValueError(f"{_where(name, 'noise')} is missing the key {key!r}")
    sigma = float(
        check_positive(_where(name, "noise.sigma"), _number(name, "noise.sigma", spec["sigma"]))
    )
    colour = spec["colour"]
    if colour not in COLOURS:
        raise AbglibValueError(
            f"{_where(name, 'noise.colour')} must be one of {list(COLOURS)}, got {colour!r}"
        )
    if colour == "ar1":
        if "rho" not in spec:
            raise AbglibValueError(f"{_where(name, 'noise')} with colour 'ar1' needs 'rho'")
        rho = float(
            check_in_range(
                _where(name, "noise.rho"), _number(name, "noise.rho", spec["rho"]), -1.0, 1.0
            )
        )
    else:
        if "rho" in spec and float(spec["rho"]) != 0.0:
            raise AbglibValueError(
                f"{_where(name, 'noise.rho')} must be 0 (or absent) for white noise, "
                f"got {spec['rho']!r}"
            )
        rho = 0.0
    return {"sigma": sigma, "colour": colour, "rho": rho}


def _pair_or_scalar(name: str, key: str, value, planar: bool):
    if planar:
        if not isinstance(value, (list, tuple)) or len(value) != 2:
            raise AbglibValueError(
                f"{_where(name, key)} must be a pair [x, y] for an 'xy' track, got {value!r}"
            )
        return np.array([_number(name, f"{key}[{i}]", v) for i, v in enumerate(value)])
    return np.array([_number(name, key, value)])


# --------------------------------------------------------------------------- kinematics
def _sinusoid(t, p0, v0, amplitude, period, phase):
    w = 2.0 * math.pi / period
    arg = w * t + phase
    pos = p0 + v0 * t + amplitude * np.sin(arg)
    vel = v0 + amplitude * w * np.cos(arg)
    acc = -amplitude * w * w * np.sin(arg)
    return pos, vel, acc


def _propagate(p, v, tau, acc=None, turn_rate=None):
    """State ``(p, v, a)`` after ``tau`` s under constant ``acc`` or a coordinated turn.

    ``p, v`` are arrays (d,) (d = 1 or 2); ``tau`` an array (m,); returns arrays (m, d).
    Turn: velocity ``v(τ) = R(ωτ) v``, position ``p + [sin ωτ, -(1 - cos ωτ); 1 - cos ωτ,
    sin ωτ] v / ω``, acceleration ``ω (-v_y, v_x)``.
    """
    tau = np.asarray(tau, dtype=float)[:, None]
    if turn_rate is not None and turn_rate != 0.0:
        w = turn_rate
        c, s = np.cos(w * tau[:, 0]), np.sin(w * tau[:, 0])
        vx, vy = v
        vel = np.stack([c * vx - s * vy, s * vx + c * vy], axis=1)
        pos = p + np.stack([s * vx - (1 - c) * vy, (1 - c) * vx + s * vy], axis=1) / w
        acc = w * np.stack([-vel[:, 1], vel[:, 0]], axis=1)
        return pos, vel, acc
    a = np.zeros_like(p) if acc is None else acc
    pos = p + v * tau + 0.5 * a * tau**2
    vel = v + a * tau
    return pos, vel, np.broadcast_to(a, pos.shape).astype(float)


def _segments(name: str, key: str, t, spec: Mapping):
    """Exact samples of a piecewise track (see the module docstring)."""
    planar = key == "xy"
    p = _pair_or_scalar(name, f"tracks.{key}.p0", spec["p0"], planar)
    v = _pair_or_scalar(name, f"tracks.{key}.v0", spec["v0"], planar)
    segs = spec["segments"]
    if not isinstance(segs, (list, tuple)):
        raise AbglibValueError(
            f"{_where(name, f'tracks.{key}.segments')} must be a list, got {segs!r}"
        )
    parsed = []
    for i, seg in enumerate(segs):
        where = f"tracks.{key}.segments[{i}]"
        seg = _mapping(name, where, seg)
        _no_unknown(name, where, seg, ("t_start", "t_end", "acc", "turn_rate"))
        for k in ("t_start", "t_end"):
            if k not in seg:
                raise AbglibValueError(f"{_where(name, where)} is missing the key {k!r}")
        t0 = _number(name, f"{where}.t_start", seg["t_start"])
        t1 = _number(name, f"{where}.t_end", seg["t_end"])
        if not (0.0 <= t0 < t1):
            raise AbglibValueError(
                f"{_where(name, where)} must satisfy 0 <= t_start < t_end, "
                f"got t_start={t0!r}, t_end={t1!r}"
            )
        if ("acc" in seg) == ("turn_rate" in seg):
            raise AbglibValueError(
                f"{_where(name, where)} needs exactly one of 'acc' or 'turn_rate', got "
                f"{sorted(seg)}"
            )
        if "turn_rate" in seg:
            if not planar:
                raise AbglibValueError(
                    f"{_where(name, where)}.turn_rate: a coordinated turn needs the XY "
                    f"plane (track key 'xy'), got track key {key!r}"
                )
            parsed.append((t0, t1, None, _number(name, f"{where}.turn_rate", seg["turn_rate"])))
        else:
            acc = _pair_or_scalar(name, f"{where}.acc", seg["acc"], planar)
            parsed.append((t0, t1, acc, None))
    parsed.sort(key=lambda s: s[0])
    for (_a0, a1, *_), (b0, _b1, *_) in zip(parsed, parsed[1:], strict=False):
        if b0 < a1:
            raise AbglibValueError(
                f"{_where(name, f'tracks.{key}.segments')} overlap: a segment starts at "
                f"t={b0!r} before the previous one ends at t={a1!r}"
            )
    # pieces: (start, end, acc, turn) covering [0, inf), constant velocity between segments
    pieces, now = [], 0.0
    for t0, t1, acc, turn in parsed:
        if t0 > now:
            pieces.append((now, t0, None, None))
        pieces.append((t0, t1, acc, turn))
        now = t1
    pieces.append((now, math.inf, None, None))

    d = p.shape[0]
    pos = np.empty((t.shape[0], d))
    vel = np.empty_like(pos)
    acc_out = np.empty_like(pos)
    for t0, t1, acc, turn in pieces:
        sel = (t >= t0) & (t < t1)
        if sel.any():
            pos[sel], vel[sel], acc_out[sel] = _propagate(p, v, t[sel] - t0, acc, turn)
        if math.isfinite(t1):
            pe, ve, _ = _propagate(p, v, np.array([t1 - t0]), acc, turn)
            p, v = pe[0], ve[0]
    return pos, vel, acc_out


def _track(name: str, key: str, spec, t) -> dict:
    """``{coord: (pos, vel, acc)}`` (arrays (n,)) of one entry of ``tracks``."""
    spec = _mapping(name, f"tracks.{key}", spec)
    kind = spec.get("kind")
    if kind not in KINDS:
        raise AbglibValueError(
            f"{_where(name, f'tracks.{key}.kind')} must be one of {list(KINDS)}, got {kind!r}"
        )
    required = _REQUIRED[kind]
    optional = _OPTIONAL.get(kind, {})
    _no_unknown(name, f"tracks.{key}", spec, ("kind", *required, *optional))
    for k in required:
        if k not in spec:
            raise AbglibValueError(
                f"{_where(name, f'tracks.{key}')} ({kind}) is missing the key {k!r}"
            )
    if kind == "segments":
        pos, vel, acc = _segments(name, key, t, spec)
        coords = ("x", "y") if key == "xy" else (key,)
        return {c: (pos[:, i], vel[:, i], acc[:, i]) for i, c in enumerate(coords)}
    if key == "xy":
        raise AbglibValueError(
            f"{_where(name, 'tracks.xy')}: the key 'xy' is reserved for kind 'segments' "
            f"(a planar track), got kind {kind!r}"
        )
    par = {k: _number(name, f"tracks.{key}.{k}", spec[k]) for k in required}
    par.update(
        {k: _number(name, f"tracks.{key}.{k}", spec.get(k, dflt)) for k, dflt in optional.items()}
    )
    if kind == "sinusoid":
        period = float(check_positive(_where(name, f"tracks.{key}.period"), par["period"]))
        return {key: _sinusoid(t, par["p0"], par["v0"], par["amplitude"], period, par["phase"])}
    # constant velocity and acceleration are cubics with the higher terms zero
    pva = polynomial_kinematics(t, par["p0"], par["v0"], par.get("a0", 0.0), par.get("jerk", 0.0))
    return {key: pva}


# --------------------------------------------------------------------------- public
def column_schema(coords) -> list[dict]:
    """The Parquet columns of a dataset with ``coords``: name, dtype, unit, description."""
    cols = [
        dict(zip(("name", "dtype", "unit", "description"), c, strict=True)) for c in BASE_COLUMNS
    ]
    for c in coords:
        for suffix, unit, what in _PER_COORD:
            cols.append(
                {
                    "name": f"{c}_{suffix}",
                    "dtype": "float64",
                    "unit": unit,
                    "description": f"{what}, coordinate {c}",
                }
            )
    return cols


def generate(name: str, spec: Mapping, seed: int | None = None) -> Dataset:
    """Simulate one scenario: exact truth, seeded noisy measurements.

    Parameters
    ----------
    name : str
        Scenario name (recorded in the manifest, used in error messages).
    spec : mapping
        One scenario of ``config.yaml`` (``datasets.scenarios.<name>``; see the module
        docstring).
    seed : int, optional
        Noise seed; defaults to ``spec["seed"]``. The manifest records the seed used and
        hashes the spec with that seed.

    Returns
    -------
    Dataset
        Truth and measurements of shape ``(runs, n_samples)`` per coordinate.

    Raises
    ------
    AbglibValueError
        A missing, unknown or out-of-range setting, named by its key.
    """
    from .. import __version__
    from ..common.files import config_hash

    if not isinstance(name, str) or not name:
        raise AbglibValueError(f"name must be a non-empty string, got {name!r}")
    spec = _mapping(name, "spec", spec)
    _no_unknown(name, "spec", spec, _SCENARIO_KEYS)
    for key in ("dt", "n_samples", "runs", "noise", "tracks"):
        if key not in spec:
            raise AbglibValueError(f"{_where(name, 'spec')} is missing the key {key!r}")
    if seed is None:
        if "seed" not in spec:
            raise AbglibValueError(f"{_where(name, 'spec')} is missing the key 'seed'")
        seed = spec["seed"]
    seed = _int(name, "seed", seed, 0)
    dt = float(check_positive(_where(name, "dt"), _number(name, "dt", spec["dt"])))
    n = _int(name, "n_samples", spec["n_samples"], 2)
    runs = _int(name, "runs", spec["runs"], 1)
    noise = _noise(name, spec["noise"])
    tracks = _mapping(name, "tracks", spec["tracks"])
    if not tracks:
        raise AbglibValueError(f"{_where(name, 'tracks')} must name at least one coordinate")

    t = sample_times(n, dt)
    kin: dict = {}
    for key, tspec in tracks.items():
        key = str(key)
        for c, value in _track(name, key, tspec, t).items():
            if c in kin:
                raise AbglibValueError(
                    f"{_where(name, 'tracks')} defines coordinate {c!r} twice (track {key!r})"
                )
            kin[c] = value
    coords = tuple(kin)

    children = np.random.SeedSequence(seed).spawn(len(coords))
    truth_pos, truth_vel, truth_acc, z = {}, {}, {}, {}
    for c, child in zip(coords, children, strict=True):
        rng = np.random.default_rng(child)
        if noise["colour"] == "white":
            w = white_noise((runs, n), noise["sigma"], rng)
        else:
            w = ar1_noise((runs, n), noise["sigma"], noise["rho"], rng)
        pos, vel, acc = kin[c]
        truth_pos[c] = np.ascontiguousarray(np.broadcast_to(pos, (runs, n)), dtype=float)
        truth_vel[c] = np.ascontiguousarray(np.broadcast_to(vel, (runs, n)), dtype=float)
        truth_acc[c] = np.ascontiguousarray(np.broadcast_to(acc, (runs, n)), dtype=float)
        z[c] = truth_pos[c] + w

    used = copy.deepcopy(dict(spec))
    used["seed"] = seed
    manifest = {
        "format": "abglib.datasets",
        "name": name,
        "generator_version": GENERATOR_VERSION,
        "abglib_version": __version__,
        "seed": seed,
        "config_sha256": config_hash(used),
        "spec": json.loads(json.dumps(used, sort_keys=True, default=str)),
        "dt_s": dt,
        "n_samples": n,
        "runs": runs,
        "coords": list(coords),
        "noise": noise,
        "layout": "long: one row per (run, sample), sorted by run then sample",
        "schema": column_schema(coords),
    }
    return Dataset(name, dt, t, coords, truth_pos, truth_vel, truth_acc, z, noise, manifest)


def _arrow():
    try:
        import pyarrow as pa
        import pyarrow.parquet as pq
    except ImportError as exc:  # pragma: no cover - pyarrow is a pipeline dependency
        raise ImportError(
            "abglib.datasets.write/read need pyarrow: pip install 'abglib[pipeline]'"
        ) from exc
    return pa, pq


def _table(ds: Dataset):
    pa, _ = _arrow()
    runs, n = ds.runs, ds.n_samples
    cols = {
        "run": np.repeat(np.arange(runs, dtype=np.int32), n),
        "sample": np.tile(np.arange(n, dtype=np.int32), runs),
        "t": np.tile(ds.t.astype(np.float64), runs),
    }
    for c in ds.coords:
        cols[f"{c}_true"] = ds.truth_pos[c].reshape(-1)
        cols[f"{c}_vel_true"] = ds.truth_vel[c].reshape(-1)
        cols[f"{c}_acc_true"] = ds.truth_acc[c].reshape(-1)
        cols[f"{c}_meas"] = ds.z[c].reshape(-1)
    return pa.table({k: pa.array(v) for k, v in cols.items()})


def _sha256(path) -> str:
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def write(dataset: Dataset, parquet_path, manifest_path) -> None:
    """Write ``dataset`` as Parquet (long format) and its JSON manifest, atomically.

    Each file is written to a temporary file beside its target and renamed into place;
    the same dataset always gives byte-identical files (no timestamps, no pandas
    metadata, fixed compression).
    """
    from ..common.files import atomic_output

    _, pq = _arrow()
    table = _table(dataset)
    with atomic_output(parquet_path) as tmp:
        pq.write_table(table, tmp, compression="zstd", compression_level=3, use_dictionary=False)
        digest = _sha256(tmp)
    manifest = dict(dataset.manifest)
    manifest["parquet_file"] = Path(parquet_path).name
    manifest["parquet_sha256"] = digest
    manifest["rows"] = table.num_rows
    text = json.dumps(manifest, indent=2, sort_keys=True, ensure_ascii=False) + "\n"
    with atomic_output(manifest_path) as tmp:
        Path(tmp).write_text(text, encoding="utf-8")


def read(parquet_path, manifest_path=None) -> Dataset:
    """Read a dataset written by :func:`write` (and the manifest beside it).

    ``manifest_path`` defaults to ``<stem>.manifest.json`` beside ``parquet_path``. The
    Parquet file's sha256 and columns are checked against the manifest.
    """
    _, pq = _arrow()
    parquet_path = Path(parquet_path)
    if manifest_path is None:
        manifest_path = parquet_path.with_name(
            parquet_path.name.removesuffix(".parquet") + ".manifest.json"
        )
    rebuild = (
        f"; the files are damaged (an interrupted copy?): rebuild them with "
        f"`snakemake -c2 --forcerun {parquet_path}`"
    )
    try:
        manifest = json.loads(Path(manifest_path).read_text(encoding="utf-8"))
        expected = [c["name"] for c in manifest["schema"]]
    except (json.JSONDecodeError, KeyError, TypeError) as exc:
        raise AbglibValueError(
            f"{manifest_path} is not a complete dataset manifest ({exc}){rebuild}"
        ) from None
    if manifest.get("parquet_sha256") not in (None, _sha256(parquet_path)):
        raise AbglibValueError(
            f"{parquet_path} does not match its manifest {manifest_path} (sha256 differs)" + rebuild
        )
    table = pq.read_table(parquet_path)
    if table.column_names != expected:
        raise AbglibValueError(
            f"{parquet_path} has columns {table.column_names}, manifest says {expected}" + rebuild
        )
    runs, n = int(manifest["runs"]), int(manifest["n_samples"])
    coords = tuple(manifest["coords"])

    def col(name):
        return table.column(name).to_numpy().reshape(runs, n).copy()

    t = col("t")[0]
    noise = dict(manifest["noise"])
    return Dataset(
        name=manifest["name"],
        dt=float(manifest["dt_s"]),
        t=t,
        coords=coords,
        truth_pos={c: col(f"{c}_true") for c in coords},
        truth_vel={c: col(f"{c}_vel_true") for c in coords},
        truth_acc={c: col(f"{c}_acc_true") for c in coords},
        z={c: col(f"{c}_meas") for c in coords},
        noise=noise,
        manifest=manifest,
    )


def build(name: str, spec: Mapping, parquet_path, manifest_path, log_path=None) -> Dataset:
    """Generate one scenario and write it (:func:`generate`, :func:`write`): the whole job of
    the workflow's ``dataset`` rule, run in-process; a one-line summary goes to ``log_path``."""
    from pathlib import Path

    ds = generate(name, spec)
    write(ds, parquet_path, manifest_path)
    if log_path is not None:
        Path(log_path).write_text(
            f"wrote {parquet_path}: {ds.runs} runs x {ds.n_samples} samples, "
            f"coords {ds.coords}, noise {ds.noise}\n",
            encoding="utf-8",
        )
    return ds
