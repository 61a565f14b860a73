"""Simulated radar datasets: exact kinematics, noise statistics, storage, errors."""

from __future__ import annotations

import copy
from pathlib import Path

import numpy as np
import pytest

from abglib import AbglibValueError
from abglib.bench import datasets
from abglib.reporting.pipeline import config_errors, read_yaml

REPO = Path(__file__).resolve().parents[1]
SCHEMA = REPO / "workflow" / "schemas" / "config.schema.yaml"
CONFIG = read_yaml(REPO / "config.yaml")


def _spec(tracks, noise=None, n=40, runs=3, dt=0.5, seed=11):
    return {
        "dt": dt,
        "n_samples": n,
        "runs": runs,
        "seed": seed,
        "noise": noise or {"sigma": 2.0, "colour": "white"},
        "tracks": tracks,
    }


# --------------------------------------------------------------------------- kinematics
def test_polynomial_is_the_closed_form_huang_range_track():
    # Huang et al. (seed 002) range track: A = 1000 m/s^2, B = 40 m/s^3 (a0 and jerk)
    spec = _spec({"r": {"kind": "polynomial", "p0": 1e4, "v0": -300.0, "a0": 1000.0, "jerk": 40.0}})
    ds = datasets.generate("huang", spec)
    t = np.arange(40) * 0.5
    assert ds.coords == ("r",)
    np.testing.assert_allclose(
        ds.truth_pos["r"][1], 1e4 - 300 * t + 500 * t**2 + 40 * t**3 / 6, rtol=1e-15
    )
    np.testing.assert_allclose(ds.truth_vel["r"][2], -300 + 1000 * t + 20 * t**2, rtol=1e-15)
    np.testing.assert_allclose(ds.truth_acc["r"][0], 1000 + 40 * t, rtol=1e-15)
    # velocity is the derivative of position: central differences of a cubic are exact
    # up to the jerk term h^2 j / 6 (here h = 0.5)
    p = ds.truth_pos["r"][0]
    cd = (p[2:] - p[:-2]) / 1.0
    np.testing.assert_allclose(cd, ds.truth_vel["r"][0, 1:-1] + 0.25 * 40 / 6, rtol=1e-12)


@pytest.mark.parametrize(
    "kind, extra, pos",
    [
        ("constant_velocity", {}, lambda t: 3.0 + 7.0 * t),
        ("constant_acceleration", {"a0": -2.0}, lambda t: 3.0 + 7.0 * t - t**2),
    ],
)
def test_constant_velocity_and_acceleration(kind, extra, pos):
    ds = datasets.generate("k", _spec({"x": {"kind": kind, "p0": 3.0, "v0": 7.0, **extra}}))
    np.testing.assert_allclose(ds.truth_pos["x"][0], pos(ds.t), rtol=1e-15, atol=1e-12)
    assert np.all(ds.truth_acc["x"] == extra.get("a0", 0.0))


def test_sinusoid_closed_form():
    spec = _spec(
        {
            "y": {
                "kind": "sinusoid",
                "p0": 1.0,
                "v0": 2.0,
                "amplitude": 50.0,
                "period": 8.0,
                "phase": 0.3,
            }
        }
    )
    ds = datasets.generate("s", spec)
    w = 2 * np.pi / 8.0
    t = ds.t
    np.testing.assert_allclose(ds.truth_pos["y"][0], 1 + 2 * t + 50 * np.sin(w * t + 0.3))
    np.testing.assert_allclose(ds.truth_vel["y"][0], 2 + 50 * w * np.cos(w * t + 0.3))
    np.testing.assert_allclose(ds.truth_acc["y"][0], -50 * w * w * np.sin(w * t + 0.3))


def test_coordinated_turn_keeps_speed_and_turns_by_rate_times_duration():
    # a quarter turn: 200 m/s, turn rate pi/20 rad/s for 10 s, then straight again
    rate = np.pi / 20
    spec = _spec(
        {
            "xy": {
                "kind": "segments",
                "p0": [0.0, 0.0],
                "v0": [200.0, 0.0],
                "segments": [{"t_start": 5.0, "t_end": 15.0, "turn_rate": rate}],
            }
        },
        n=41,
        dt=0.5,
    )
    ds = datasets.generate("turn", spec)
    vx, vy = ds.truth_vel["x"][0], ds.truth_vel["y"][0]
    np.testing.assert_allclose(np.hypot(vx, vy), 200.0, rtol=1e-13)
    t = ds.t
    after = t >= 15.0
    np.testing.assert_allclose(vx[after], 0.0, atol=1e-10)
    np.testing.assert_allclose(vy[after], 200.0, rtol=1e-13)
    # closed form of the arc: radius R = v / rate, centre (1000, R) for the turn start (1000, 0)
    R = 200.0 / rate
    during = (t >= 5.0) & (t < 15.0)
    th = rate * (t[during] - 5.0)
    np.testing.assert_allclose(ds.truth_pos["x"][0, during], 1000 + R * np.sin(th), rtol=1e-13)
    np.testing.assert_allclose(ds.truth_pos["y"][0, during], R * (1 - np.cos(th)), atol=1e-9)
    # after the turn: straight up from (1000 + R, R)
    np.testing.assert_allclose(ds.truth_pos["x"][0, after], 1000 + R, rtol=1e-13)
    np.testing.assert_allclose(ds.truth_pos["y"][0, after], R + 200 * (t[after] - 15), rtol=1e-13)
    # centripetal acceleration v^2 / R during, zero outside
    acc = np.hypot(ds.truth_acc["x"][0], ds.truth_acc["y"][0])
    np.testing.assert_allclose(acc[during], 200.0 * rate, rtol=1e-13)
    assert np.all(acc[~during] == 0.0)


def test_acceleration_steps_integrate_exactly():
    spec = _spec(
        {
            "y": {
                "kind": "segments",
                "p0": 10.0,
                "v0": 1.0,
                "segments": [
                    {"t_start": 2.0, "t_end": 4.0, "acc": 3.0},
                    {"t_start": 6.0, "t_end": 7.0, "acc": -6.0},
                ],
            }
        },
        n=20,
        dt=0.5,
    )
    ds = datasets.generate("steps", spec)

    # independent route: fine Euler-free integration by exact piecewise formulas, by hand
    def truth(t):
        p, v = 10.0 + 1.0 * t, 1.0
        if t > 2.0:
            tau = min(t, 4.0) - 2.0
            p += 1.5 * tau**2
            v += 3.0 * tau
            if t > 4.0:
                p += 6.0 * (min(t, 6.0) - 4.0)  # extra velocity 6 m/s after the first step
        if t > 6.0:
            p += 6.0 * (t - 6.0)
            tau = min(t, 7.0) - 6.0
            p += -3.0 * tau**2
            v = 1.0 + 6.0 - 6.0 * tau
            if t > 7.0:
                p += -6.0 * (t - 7.0)
        return p, v

    expect = np.array([truth(t) for t in ds.t])
    np.testing.assert_allclose(ds.truth_pos["y"][0], expect[:, 0], rtol=1e-14)
    np.testing.assert_allclose(ds.truth_vel["y"][0, ds.t <= 2.0], 1.0)
    np.testing.assert_allclose(ds.truth_vel["y"][0, ds.t >= 7.0], 1.0)
    assert ds.truth_acc["y"][0, ds.t == 2.0] == 3.0 and ds.truth_acc["y"][0, ds.t == 4.0] == 0.0


def test_truth_is_the_same_in_every_run_and_measurements_are_truth_plus_noise():
    ds = datasets.generate("cv", _spec({"x": {"kind": "constant_velocity", "p0": 0, "v0": 1}}))
    assert ds.z["x"].shape == (3, 40) and ds.truth_pos["x"].shape == (3, 40)
    assert np.all(ds.truth_pos["x"] == ds.truth_pos["x"][0])
    assert not np.allclose(ds.z["x"][0], ds.z["x"][1])


# --------------------------------------------------------------------------- noise
def test_white_noise_std_within_monte_carlo_bounds():
    sigma, runs, n = 7.0, 400, 250
    ds = datasets.generate(
        "w",
        _spec(
            {"x": {"kind": "constant_velocity", "p0": 0, "v0": 0}},
            {"sigma": sigma, "colour": "white"},
            n=n,
            runs=runs,
        ),
    )
    w = ds.z["x"] - ds.truth_pos["x"]
    m = w.size
    # sample std of m Gaussians: relative standard error 1/sqrt(2m); 5 of them
    assert abs(w.std() / sigma - 1) < 5 / np.sqrt(2 * m)
    assert abs(w.mean()) < 5 * sigma / np.sqrt(m)
    lag1 = np.mean(w[:, 1:] * w[:, :-1]) / np.mean(w * w)
    assert abs(lag1) < 5 / np.sqrt(m)


@pytest.mark.parametrize("rho", [0.5, 0.9, -0.4])
def test_ar1_noise_std_and_lag1_correlation(rho):
    sigma, runs, n = 3.0, 400, 250
    ds = datasets.generate(
        "c",
        _spec(
            {"x": {"kind": "constant_velocity", "p0": 0, "v0": 0}},
            {"sigma": sigma, "colour": "ar1", "rho": rho},
            n=n,
            runs=runs,
        ),
    )
    w = ds.z["x"] - ds.truth_pos["x"]
    m = w.size
    # effective sample size of an AR(1) series for the variance: m (1 - rho^2) / (1 + rho^2)
    m_eff = m * (1 - rho**2) / (1 + rho**2)
    assert abs(w.std() / sigma - 1) < 5 / np.sqrt(2 * m_eff)
    # the stationary start: sample 0 already has std sigma (over runs)
    assert abs(w[:, 0].std() / sigma - 1) < 5 / np.sqrt(2 * runs)
    lag1 = np.mean(w[:, 1:] * w[:, :-1]) / np.mean(w * w)
    # standard error of the lag-1 autocorrelation estimate ~ sqrt((1 - rho^2) / m)
    assert abs(lag1 - rho) < 5 * np.sqrt((1 - rho**2) / m) + 0.01
    assert ds.noise == {"sigma": sigma, "colour": "ar1", "rho": rho}


def test_coordinates_get_independent_noise_and_the_seed_decides_it():
    tr = {
        "x": {"kind": "constant_velocity", "p0": 0, "v0": 0},
        "y": {"kind": "constant_velocity", "p0": 0, "v0": 0},
    }
    a = datasets.generate("a", _spec(tr, runs=200, n=100))
    b = datasets.generate("a", _spec(tr, runs=200, n=100))
    c = datasets.generate("a", _spec(tr, runs=200, n=100), seed=12)
    assert np.array_equal(a.z["x"], b.z["x"]) and np.array_equal(a.z["y"], b.z["y"])
    assert not np.array_equal(a.z["x"], c.z["x"])
    corr = np.corrcoef(a.z["x"].ravel(), a.z["y"].ravel())[0, 1]
    assert abs(corr) < 5 / np.sqrt(a.z["x"].size)
    assert c.manifest["seed"] == 12 and c.manifest["spec"]["seed"] == 12
    assert c.manifest["config_sha256"] != a.manifest["config_sha256"]


# --------------------------------------------------------------------------- storage
def _example():
    return _spec(
        {
            "xy": {
                "kind": "segments",
                "p0": [0.0, 100.0],
                "v0": [50.0, 0.0],
                "segments": [
                    {"t_start": 3.0, "t_end": 6.0, "turn_rate": 0.2},
                    {"t_start": 8.0, "t_end": 9.0, "acc": [1.0, -2.0]},
                ],
            }
        },
        {"sigma": 4.0, "colour": "ar1", "rho": 0.6},
        n=30,
        runs=5,
    )


def test_write_read_round_trip_is_identical(tmp_path):
    ds = datasets.generate("ex", _example())
    pq, mf = tmp_path / "ex.parquet", tmp_path / "ex.manifest.json"
    datasets.write(ds, pq, mf)
    back = datasets.read(pq)
    assert back.name == ds.name and back.dt == ds.dt and back.coords == ds.coords
    assert back.noise == ds.noise
    assert np.array_equal(back.t, ds.t)
    for field in ("truth_pos", "truth_vel", "truth_acc", "z"):
        for c in ds.coords:
            assert np.array_equal(getattr(back, field)[c], getattr(ds, field)[c]), (field, c)
    for key, value in ds.manifest.items():
        assert back.manifest[key] == value, key
    assert back.manifest["rows"] == 5 * 30
    # the documented schema is the file's schema
    import pyarrow.parquet as papq

    schema = papq.read_schema(pq)
    assert [c["name"] for c in back.manifest["schema"]] == schema.names
    assert {c["name"]: c["dtype"] for c in back.manifest["schema"]} == {
        f.name: str(f.type).replace("double", "float64") for f in schema
    }
    assert not list(tmp_path.glob("*.tmp"))


def test_rewrite_is_byte_identical(tmp_path):
    for sub in ("a", "b"):
        d = tmp_path / sub
        datasets.write(
            datasets.generate("ex", _example()), d / "ex.parquet", d / "ex.manifest.json"
        )
    for name in ("ex.parquet", "ex.manifest.json"):
        assert (tmp_path / "a" / name).read_bytes() == (tmp_path / "b" / name).read_bytes()


def test_read_detects_a_changed_file(tmp_path):
    ds = datasets.generate("ex", _example())
    datasets.write(ds, tmp_path / "ex.parquet", tmp_path / "ex.manifest.json")
    other = datasets.generate("ex", _example(), seed=99)
    datasets.write(other, tmp_path / "ex.parquet", tmp_path / "other.manifest.json")
    with pytest.raises(AbglibValueError, match="does not match its manifest"):
        datasets.read(tmp_path / "ex.parquet")


# --------------------------------------------------------------------------- errors
@pytest.mark.parametrize(
    "edit, match",
    [
        (lambda s: s.pop("dt"), "missing the key 'dt'"),
        (lambda s: s.update(dt=-1.0), r"dt must be > 0, got -1.0"),
        (lambda s: s.update(n_samples=1), r"n_samples must be an integer >= 2, got 1"),
        (lambda s: s.update(runs=2.5), r"runs must be an integer >= 1, got 2.5"),
        (lambda s: s.update(seed=-3), r"seed must be an integer >= 0, got -3"),
        (lambda s: s.update(speed=3), r"unknown key\(s\) \['speed'\]"),
        (
            lambda s: s["noise"].update(colour="pink"),
            r"noise.colour must be one of \['white', 'ar1'\], got 'pink'",
        ),
        (
            lambda s: s["noise"].update(colour="ar1", rho=1.2),
            r"noise.rho must satisfy -1 < .*noise.rho < 1, got 1.2",
        ),
        (lambda s: s["noise"].update(colour="ar1"), r"colour 'ar1' needs 'rho'"),
        (lambda s: s["noise"].update(sigma=0.0), r"noise.sigma must be > 0, got 0.0"),
        (
            lambda s: s["tracks"]["x"].update(kind="zigzag"),
            r"tracks.x.kind must be one of .*got 'zigzag'",
        ),
        (
            lambda s: s["tracks"]["x"].pop("v0"),
            r"tracks.x \(constant_velocity\) is missing the key 'v0'",
        ),
        (
            lambda s: s["tracks"]["x"].update(v0="fast"),
            r"tracks.x.v0 must be a real number, got 'fast'",
        ),
        (
            lambda s: s["tracks"].update(
                x={"kind": "sinusoid", "p0": 0, "v0": 0, "amplitude": 1, "period": 0}
            ),
            r"tracks.x.period must be > 0, got 0.0",
        ),
        (
            lambda s: s["tracks"].update(
                x={
                    "kind": "segments",
                    "p0": 0,
                    "v0": 0,
                    "segments": [{"t_start": 1, "t_end": 2, "turn_rate": 0.1}],
                }
            ),
            r"coordinated turn needs the XY plane",
        ),
        (
            lambda s: s["tracks"].update(
                x={
                    "kind": "segments",
                    "p0": 0,
                    "v0": 0,
                    "segments": [{"t_start": 3, "t_end": 2, "acc": 1}],
                }
            ),
            r"0 <= t_start < t_end, got t_start=3.0, t_end=2.0",
        ),
        (
            lambda s: s["tracks"].update(
                x={
                    "kind": "segments",
                    "p0": 0,
                    "v0": 0,
                    "segments": [
                        {"t_start": 0, "t_end": 4, "acc": 1},
                        {"t_start": 3, "t_end": 5, "acc": 2},
                    ],
                }
            ),
            r"overlap: a segment starts at t=3.0 before the previous one ends at t=4.0",
        ),
        (
            lambda s: s["tracks"].update(
                xy={"kind": "segments", "p0": [0, 0], "v0": 1, "segments": []}
            ),
            r"tracks.xy.v0 must be a pair \[x, y\]",
        ),
    ],
)
def test_bad_settings_raise_naming_the_key_and_value(edit, match):
    spec = _spec({"x": {"kind": "constant_velocity", "p0": 0.0, "v0": 1.0}})
    edit(spec)
    with pytest.raises(AbglibValueError, match=match):
        datasets.generate("bad", spec)


def _cfg_with(path, value):
    cfg = copy.deepcopy(CONFIG)
    *parents, last = path
    node = cfg
    for p in parents:
        node = node[p]
    if value is None:
        del node[last]
    else:
        node[last] = value
    return cfg


@pytest.mark.parametrize(
    "path, value, expect",
    [
        (
            ["alwagih_w1", "dt"],
            None,
            ["config key 'datasets.scenarios.alwagih_w1'", "'dt' is a required property"],
        ),
        (
            ["alwagih_w1", "noise", "colour"],
            "pink",
            ["config key 'datasets.scenarios.alwagih_w1.noise.colour'", "['white', 'ar1']"],
        ),
        (
            ["alwagih_c1", "noise", "rho"],
            None,
            ["alwagih_c1.noise", "'rho' is a required property"],
        ),
        (
            ["alwagih_w1", "tracks", "x", "jerk"],
            2.0,
            ["alwagih_w1.tracks.x", "'jerk' was unexpected"],
        ),
        (
            ["alwagih_w1", "tracks", "x", "kind"],
            "zigzag",
            ["alwagih_w1.tracks.x.kind", "'zigzag' is not one of"],
        ),
        (["alwagih_w1", "runs"], 0, ["alwagih_w1.runs", "0 is less than the minimum of 1"]),
    ],
)
def test_schema_names_the_bad_dataset_key(path, value, expect):
    cfg = _cfg_with(["datasets", "scenarios", *path], value)
    msgs = config_errors(cfg, SCHEMA)
    assert msgs, "the schema accepted a bad scenario"
    text = "\n".join(msgs)
    for piece in expect:
        assert piece in text, text


def test_every_configured_scenario_generates():
    for name, spec in CONFIG["datasets"]["scenarios"].items():
        small = dict(spec, runs=2)
        ds = datasets.generate(name, small)
        assert ds.z[ds.coords[0]].shape == (2, spec["n_samples"])


def test_a_truncated_manifest_names_the_rebuild_command(tmp_path):
    pq, mf = tmp_path / "ex.parquet", tmp_path / "ex.manifest.json"
    datasets.write(datasets.generate("ex", _example()), pq, mf)
    mf.write_text(mf.read_text()[:40])  # an interrupted copy
    with pytest.raises(AbglibValueError, match=r"not a complete dataset manifest") as err:
        datasets.read(pq)
    assert f"snakemake -c2 --forcerun {pq}" in str(err.value)


def test_a_truncated_parquet_names_the_rebuild_command(tmp_path):
    pq, mf = tmp_path / "ex.parquet", tmp_path / "ex.manifest.json"
    datasets.write(datasets.generate("ex", _example()), pq, mf)
    pq.write_bytes(pq.read_bytes()[:100])
    with pytest.raises(AbglibValueError, match=rf"--forcerun {pq}"):
        datasets.read(pq)


def test_a_failed_script_says_why_on_the_console(tmp_path):
    """log_to: the traceback goes to the log, the message to the console (stderr)."""
    import subprocess
    import sys

    log = tmp_path / "job.log"
    code = (
        "from abglib.common.jobs import log_to\n"
        f"log_to({str(log)!r})\n"
        "raise ValueError('rebuild with snakemake -c2 --forcerun x')\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert out.returncode == 1
    assert "ValueError: rebuild with snakemake -c2 --forcerun x" in out.stderr
    assert f"full traceback in {log}" in out.stderr
    assert "Traceback" in log.read_text() and "Traceback" not in out.stderr
