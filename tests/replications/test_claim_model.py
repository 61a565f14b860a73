"""The claim model (abglib.replications._claims): resolution, ranges, robustness verdicts."""

from __future__ import annotations

from functools import cached_property

import pandas as pd
import pytest

from abglib import AbglibValueError
from abglib.replications import ClaimSet, Reading, Result, Study, evaluate, plausible_ranges
from abglib.replications._claims import config_get, config_with
from abglib.replications.compare import COMPARISON_COLUMNS, scorecard

PUB = pd.DataFrame(
    [
        # key, item, quantity, published, where
        ("x.value", "eq. 1", "x (m)", "2.0", "p. 1"),
        ("x.claim", "p. 2", "claim: x exceeds 1", "", "p. 2"),
        ("gate.lost", "p. 3", "claim: the error stays inside the gate", "", "p. 3"),
        ("t.a", "Table 1, a", "a", "0.50", "Table 1"),
        ("t.b", "Table 1, b", "b", "0.25", "Table 1"),
    ],
    columns=["key", "item", "quantity", "published", "where"],
)


class ToyStudy(Study):
    doc = "toy"
    calls = 0

    @cached_property
    def x(self) -> float:
        ToyStudy.calls += 1
        return 2.0 * self.cfg["scale"]

    @cached_property
    def error_m(self) -> float:
        return 40.0


CLAIMS = ClaimSet("toy")


@CLAIMS.claim("x.value", depends_on=("toy.scale",))
def _x_value(s):
    return Result(s.x, "twice the scale")


@CLAIMS.claim("x.claim")
def _x_claim(s):
    return Result(s.x > 1.0, f"x = {s.x:g}")


@CLAIMS.claim("gate.lost", depends_on=("toy.gate_m",))
def _gate(s):
    return Result(s.error_m < s.cfg["gate_m"], f"error {s.error_m:g} m")


@CLAIMS.family(r"t\.[ab]")
def _table(s, key):
    value = {"t.a": 0.5004, "t.b": 0.3}[key]
    return Result(value, readings=(Reading("the b of another rule", 0.2502, "section 4"),))


def config(scale=1.0, gate=75.0):
    return {
        "toy": {
            "scale": scale,
            "gate_m": gate,
            "plausible": {
                # 0.995 keeps x = 2 * scale within the printed 2.0 +- 0.05 ... up to 1.025
                "toy.scale": {"low": 0.99, "high": 1.02, "n": 4, "basis": "test"},
                "toy.gate_m": {"values": [30, 50, 111], "basis": "no gate printed"},
            },
        }
    }


def run(cfg=None):
    cfg = cfg or config()
    study = ToyStudy(cfg, PUB)
    return evaluate("toy", CLAIMS, PUB, study, lambda c: ToyStudy(c, PUB))


def test_comparison_has_the_contract_columns_in_order():
    comp, _ = run()
    assert list(comp.columns) == COMPARISON_COLUMNS
    assert COMPARISON_COLUMNS[-4:] == ["depends_on", "robust", "reading", "chance"]


def test_robust_verdict_is_kept_and_marked():
    comp, points = run()
    row = comp.set_index("published").loc["2.0"]
    # x = 2 * scale with scale in 0.99..1.02: |x - 2| <= 0.04 < 0.05 everywhere
    assert row["verdict"] == "match" and row["robust"] == "true"
    assert row["depends_on"] == "toy.scale"
    sweep = points[points["key"] == "x.value"]
    assert len(sweep) == 4 and set(sweep["verdict"]) == {"match"}
    assert sweep["nominal"].sum() == 1


def test_a_flip_becomes_not_reproducible_with_the_ranges():
    comp, points = run()
    row = comp.set_index("item").loc["p. 3"]
    assert row["verdict"] == "not_reproducible" and row["robust"] == "false"
    # the error is 40 m: lost against 30 m, kept at 50, 75 and 111 m
    assert "toy.gate_m" in row["note"]
    assert "mismatch at 30" in row["note"] and "match at 50-111" in row["note"]
    assert "At the nominal inputs: match" in row["note"]
    assert list(points[points["key"] == "gate.lost"]["verdict"]) == [
        "mismatch",
        "match",
        "match",
        "match",
    ]


def test_rows_without_assumed_inputs_leave_robust_empty():
    comp, _ = run()
    row = comp.set_index("item").loc["p. 2"]
    assert row["verdict"] == "match" and row["depends_on"] == "" and row["robust"] == ""


def test_alternative_readings_explain_a_mismatch():
    comp, _ = run()
    t = comp.set_index("item")
    assert t.loc["Table 1, a", "verdict"] == "match"
    assert t.loc["Table 1, b", "verdict"] == "explained"
    assert "the b of another rule" in t.loc["Table 1, b", "note"]


def test_variant_studies_are_built_once_per_point():
    ToyStudy.calls = 0
    run()
    # nominal + 3 other scale points; the gate sweep never touches x
    assert ToyStudy.calls == 4


def test_scorecard_counts_robust_and_fragile():
    comp, _ = run()
    card = scorecard([comp]).iloc[0]
    assert (card["robust"], card["fragile"]) == (1, 1)
    assert card["total"] == 5 and card["not_reproducible"] == 1


def test_every_key_needs_exactly_one_claim():
    extra = pd.concat(
        [PUB, pd.DataFrame([("y", "i", "q", "1", "w")], columns=PUB.columns)],
        ignore_index=True,
    )
    with pytest.raises(AbglibValueError, match=r"without a claim: \['y'\]"):
        CLAIMS.resolve(extra["key"])
    with pytest.raises(AbglibValueError, match=r"matching no published key: \['x.claim'\]"):
        CLAIMS.resolve([k for k in PUB["key"] if k != "x.claim"])


def test_a_claim_declared_twice_is_refused():
    cs = ClaimSet("toy")
    cs.claim("a")(lambda s: Result(1.0))
    with pytest.raises(AbglibValueError, match="declared twice"):
        cs.claim("a")(lambda s: Result(2.0))


def test_an_input_without_a_range_is_refused():
    cfg = config()
    del cfg["toy"]["plausible"]["toy.gate_m"]
    with pytest.raises(AbglibValueError, match=r"without a plausible range .*toy.gate_m"):
        run(cfg)


def test_a_claim_must_return_a_result():
    cs = ClaimSet("toy")
    cs.claim("a")(lambda s: 1.0)
    with pytest.raises(AbglibValueError, match="must return an abglib.replications.Result"):
        cs.compute(None, "a")


@pytest.mark.parametrize(
    "spec, match",
    [
        ({"low": 1.0, "high": 2.0, "n": 3}, "basis"),
        ({"low": 2.0, "high": 1.0, "n": 3, "basis": "b"}, "low < high"),
        ({"low": 1.5, "high": 2.0, "n": 3, "basis": "b"}, "nominal value 1.0 must lie"),
        ({"low": 0.0, "high": 2.0, "n": 3, "scale": "log", "basis": "b"}, "low > 0"),
        ({"low": 0.5, "high": 2.0, "basis": "b"}, "missing 'n'"),
    ],
)
def test_bad_ranges_name_the_input(spec, match):
    cfg = {"toy": {"scale": 1.0, "plausible": {"toy.scale": spec}}}
    with pytest.raises(AbglibValueError, match=match):
        plausible_ranges(cfg, "toy")


def test_ranges_hold_the_nominal_and_keep_integer_inputs_integer():
    cfg = {
        "toy": {
            "n": 5,
            "x": 0.3,
            "plausible": {
                "toy.n": {"low": 2, "high": 10, "n": 3, "basis": "b"},
                "toy.x": {"low": 0.1, "high": 1.0, "n": 2, "scale": "log", "basis": "b"},
            },
        }
    }
    r = plausible_ranges(cfg, "toy")
    assert r["toy.n"].values == (2, 5, 6, 10)
    assert r["toy.x"].values == pytest.approx((0.1, 0.3, 1.0))


def test_config_paths():
    cfg = {"a": {"b": [1, {"c": 2}]}}
    assert config_get(cfg, "a.b.1.c") == 2
    new = config_with(cfg, "a.b.1.c", 5)
    assert config_get(new, "a.b.1.c") == 5 and config_get(cfg, "a.b.1.c") == 2
    with pytest.raises(AbglibValueError, match="no entry 'a.z'"):
        config_with(cfg, "a.z", 1)


def test_a_qualitative_claim_must_return_a_bool():
    cs = ClaimSet("toy")
    cs.claim("x.claim")(lambda s: Result(-0.5, "a margin, not a check"))
    pub = PUB[PUB["key"] == "x.claim"]
    with pytest.raises(AbglibValueError, match="must be True or False, got -0.5"):
        evaluate("toy", cs, pub, ToyStudy(config(), pub), lambda c: ToyStudy(c, pub))


def test_a_range_without_another_value_is_refused():
    cfg = {"toy": {"scale": 1.0, "plausible": {"toy.scale": {"values": [1.0], "basis": "b"}}}}
    with pytest.raises(AbglibValueError, match="needs a value besides the nominal"):
        plausible_ranges(cfg, "toy")


def test_a_zero_tolerance_override_is_refused():
    study = ToyStudy(config(), PUB)
    overrides = {"x.value": {"tolerance": 0.0, "reason": "none"}}
    with pytest.raises(AbglibValueError, match="must be > 0, got 0.0"):
        evaluate("toy", CLAIMS, PUB, study, lambda c: ToyStudy(c, PUB), overrides)


def test_one_blas_thread_limits_every_loaded_openblas():
    """The studies run their thousands of tiny BLAS/LAPACK calls on one thread (scipy's own
    OpenBLAS included, which numpy's import alone does not load), and the limit is lifted
    on exit."""
    from threadpoolctl import threadpool_info

    from abglib.replications import one_blas_thread

    with one_blas_thread():
        inside = [i for i in threadpool_info() if i["user_api"] == "blas"]
        assert len(inside) >= 2  # numpy's and scipy's OpenBLAS
        assert all(i["num_threads"] == 1 for i in inside)
    after = {i["filepath"]: i["num_threads"] for i in threadpool_info() if i["user_api"] == "blas"}
    assert set(after) == {i["filepath"] for i in inside}
