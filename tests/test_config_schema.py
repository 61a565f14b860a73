"""config.yaml against its schema: errors name the bad key and what is allowed."""

import copy
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from abglib.reporting.pipeline import config_errors, read_yaml

from .conftest import require

REPO = Path(__file__).resolve().parents[1]
SCHEMA = REPO / "workflow" / "schemas" / "config.schema.yaml"
CONFIG = read_yaml(REPO / "config.yaml")
SMALL = read_yaml(REPO / "tests" / "data" / "config_small.yaml")


@pytest.mark.parametrize("cfg", [CONFIG, SMALL], ids=["config.yaml", "config_small.yaml"])
def test_shipped_configs_are_valid(cfg):
    assert config_errors(cfg, SCHEMA) == []


def _with(path, value):
    cfg = copy.deepcopy(CONFIG)
    *parents, last = path
    node = cfg
    for p in parents:
        node = node[p]
    node[last] = value
    return cfg


def test_unknown_key_is_named_with_the_allowed_keys():
    cfg = _with(["steelman1978", "grids", "logg"], {"start": 0.1, "stop_over_pi": 1, "n": 5})
    (msg,) = config_errors(cfg, SCHEMA)
    assert "config key 'steelman1978.grids'" in msg
    assert "'logg' was unexpected" in msg
    assert "allowed keys: linear, log" in msg


def test_top_level_typo_is_named():
    cfg = _with(["significant_digit"], 10)
    (msg,) = config_errors(cfg, SCHEMA)
    assert "'significant_digit' was unexpected" in msg and "significant_digits" in msg


def test_bad_enum_value_lists_allowed_values():
    cfg = _with(["steelman1978", "figures", "fig2", "axes"], "loglog")
    (msg,) = config_errors(cfg, SCHEMA)
    assert "config key 'steelman1978.figures.fig2.axes'" in msg
    assert "'loglog' is not one of ['linear', 'bode']" in msg


def test_out_of_range_number_is_named():
    cfg = _with(["steelman1978", "design_example", "alpha"], 1.5)
    (msg,) = config_errors(cfg, SCHEMA)
    assert "config key 'steelman1978.design_example.alpha'" in msg
    assert "1.5 is greater than the maximum of 1" in msg


def test_wrong_type_is_named():
    cfg = _with(["steelman1978", "equation_checks", "stability_seed"], "abc")
    (msg,) = config_errors(cfg, SCHEMA)
    assert "stability_seed" in msg and "is not of type 'integer'" in msg


def test_tolerance_override_needs_a_reason():
    cfg = _with(["tolerance_overrides", "steelman1978", "design.T"], {"tolerance": 0.1})
    (msg,) = config_errors(cfg, SCHEMA)
    assert "design.T" in msg and "'reason' is a required property" in msg


@pytest.mark.slow
def test_snakemake_reports_the_bad_key(tmp_path):
    exe = Path(sys.executable).parent / "snakemake"
    if shutil.which("snakemake") is None and not exe.exists():
        require("snakemake not installed")  # skips; fails under CI
    bad = _with(["steelman1978", "figures", "fig1", "axes"], "semilog")
    cfgfile = tmp_path / "bad.yaml"
    cfgfile.write_text(yaml.safe_dump(bad, allow_unicode=True), encoding="utf-8")
    out = subprocess.run(
        [
            str(exe if exe.exists() else "snakemake"),
            "-n",
            "-s",
            str(REPO / "Snakefile"),
            "-d",
            str(tmp_path),
            "--configfile",
            str(cfgfile),
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert out.returncode != 0
    text = out.stdout + out.stderr
    assert "config key 'steelman1978.figures.fig1.axes'" in text
    assert "['linear', 'bode']" in text


def test_small_config_declares_the_same_plausible_ranges():
    """The small config is used alone (--configfile replaces config.yaml): its documents must
    judge robustness over the same ranges as the release config."""
    root = Path(__file__).resolve().parents[1]
    big = read_yaml(root / "config.yaml")
    small = read_yaml(root / "tests" / "data" / "config_small.yaml")
    for doc in small["docs"]:
        ranges = {
            k: {kk: vv for kk, vv in v.items() if kk != "basis"}
            for k, v in big[doc].get("plausible", {}).items()
        }
        got = {
            k: {kk: vv for kk, vv in v.items() if kk != "basis"}
            for k, v in small[doc].get("plausible", {}).items()
        }
        assert got == ranges, doc


def test_read_yaml_gives_what_safe_load_gives():
    from abglib.reporting.pipeline import read_yaml

    for path in (REPO / "config.yaml", SCHEMA, REPO / "tests" / "data" / "config_small.yaml"):
        assert read_yaml(path) == yaml.safe_load(path.read_text(encoding="utf-8"))


def test_validate_config_fills_the_defaults_snakemake_validate_fills():
    # the Snakefile's check (validate_config) against Snakemake's own (snakemake.utils.validate)
    from snakemake.utils import validate

    from abglib.reporting.pipeline import validate_config

    cfg = copy.deepcopy(CONFIG)
    curves = cfg["steelman1978"]["figures"]["fig1"]["curves"]
    for c in curves:
        c.pop("scale", None)
    ours, theirs = copy.deepcopy(cfg), copy.deepcopy(cfg)
    validate_config(ours, SCHEMA)
    validate(theirs, schema=str(SCHEMA))
    assert ours == theirs
    assert all(c["scale"] == 1.0 for c in ours["steelman1978"]["figures"]["fig1"]["curves"])
    assert ours != cfg  # the defaults were written in


def test_validate_config_names_every_bad_key():
    from abglib import AbglibValueError
    from abglib.reporting.pipeline import validate_config

    cfg = _with(["significant_digits"], "six")
    cfg["figure_dpi"] = -3
    with pytest.raises(AbglibValueError) as err:
        validate_config(cfg, SCHEMA)
    text = str(err.value)
    assert "config.schema.yaml" in text
    assert "config key 'significant_digits'" in text
    assert "config key 'figure_dpi'" in text
