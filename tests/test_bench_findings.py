"""The benchmark report's findings (abglib.bench.findings) on small hand-made tables."""

import pandas as pd
import pytest

from abglib.bench import findings

LEAGUE = pd.DataFrame(
    {
        "scenario": ["s1"] * 4 + ["s2"] * 3,
        "rank": [1, 2, 3, 4, 1, 2, 3],
        "variant": ["m5", "a1", "a2", "b1", "b1", "a1", "x"],
        "family": ["M", "A", "A", "B", "B", "A", "X"],
        "diverged": [False, False, False, False, False, False, True],
        "noise_colour": ["white"] * 4 + ["ar1"] * 3,
        # the ranks follow rmse_x_pred (10 < 12 < 12.5 < 15; 4 < 5), not rmse_x_smooth
        "rmse_x_pred": [10.0, 12.0, 12.5, 15.0, 4.0, 5.0, float("nan")],
        "rmse_x_smooth": [9.0, 8.0, 13.0, 14.0, 3.0, 6.0, float("nan")],
    }
)


def test_leaders_and_margin_over_the_best_other_family():
    lead = findings.leaders(LEAGUE, "rmse_x_pred", exclude=["m5"]).set_index("scenario")
    # s1 without m5: a1 (A, 12) leads; the best other family is B at 15: 25 % worse
    assert lead.loc["s1", "leader"] == "a1" and lead.loc["s1", "runner_up"] == "b1"
    assert lead.loc["s1", "margin"] == pytest.approx(15 / 12 - 1)
    # s2: the diverged x is left out; b1 leads a1 by 5/4 - 1
    assert lead.loc["s2", "family"] == "B" and lead.loc["s2", "margin"] == pytest.approx(0.25)
    # ranked by rmse_x_smooth instead: a1 (8) still leads s1, on its own value
    other = findings.leaders(LEAGUE, "rmse_x_smooth", exclude=["m5"]).set_index("scenario")
    assert other.loc["s1", "leader"] == "a1" and other.loc["s1", "value"] == 8.0
    with pytest.raises(ValueError, match="rmse_nope"):
        findings.leaders(LEAGUE, "rmse_nope")
    assert findings.leaders(LEAGUE, "rmse_x_pred").set_index("scenario").loc["s1", "leader"] == "m5"


def test_tradeoff_extremes():
    t = pd.DataFrame(
        {
            "scenario": ["ca"] * 3 + ["cv"] * 2,
            "variant": ["slow", "mid", "fast", "p", "q"],
            "output": ["x_smooth"] * 5,
            "noise_rms": [2.0, 5.0, 9.0, 7.0, 8.0],
            "lag_rms": [100.0, 3.0, 0.1, 1e-12, 2e-12],
            "rmse": [100.02, 5.83, 9.0, 7.0, 8.0],
        }
    )
    ext = findings.tradeoff_extremes(t).set_index("scenario")
    assert ext.loc["ca", "quiet"] == "slow" and ext.loc["ca", "quiet_lag"] == 100.0
    assert ext.loc["ca", "fast"] == "fast" and ext.loc["ca", "fast_noise"] == 9.0
    assert ext.loc["ca", "best_rmse_variant"] == "mid" and not ext.loc["ca", "lag_free"]
    assert ext.loc["cv", "lag_free"] and ext.loc["cv", "quiet"] == "p"
    with pytest.raises(ValueError, match="no rows for output"):
        findings.tradeoff_extremes(t, output="v_pred")


def test_peer_disagreements():
    peers = pd.DataFrame(
        {
            "peer": ["F", "F", "F", "F", "S"],
            "function": ["vrf", "batch", "bb", "ok", "lfilter"],
            "agree": ["False", "False", "False", "True", "True"],
            "supports": ["abglib", "abglib", "not comparable", "both", "both"],
        }
    )
    d = findings.peer_disagreements(peers).set_index("peer")
    assert d.loc["F"].tolist() == [4, 3, 2, 1, "vrf, batch, bb", "bb"]
    assert d.loc["S", "disagreements"] == 0
