"""The verdict engine (abglib.verdicts): reading families, their look-elsewhere chance,
the random-value rate, one sentence one judgement, the vague-word table."""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from abglib._checks import AbglibValueError
from abglib.verdicts import (
    GENERIC_FAMILIES,
    OCR_PAIRS,
    THRESHOLD,
    VAGUE,
    Reading,
    chance,
    explain,
    find_vague,
    judge,
    reference_span,
    threshold_range,
    tolerance_from_printed,
    vague_tolerances,
)
from abglib.verdicts._judge import _assess, judge_sentences
from abglib.verdicts.readings import CLAIM_FAMILIES, Row, typographic_variants


def _row(printed, reproduced, **related):
    return Row(printed, reproduced, tolerance_from_printed(printed), related)


def _labels(row, readings=()):
    return {h.candidate.label for h in explain(row, readings).hits}


def _pub(key, published, item="item", quantity="q"):
    return SimpleNamespace(key=key, item=item, quantity=quantity, published=published)


# ----------------------------------------------------------------------- each family
@pytest.mark.parametrize(
    "printed, reproduced, label",
    [
        # hand-made rows: the printed number is a slip of the reproduced one
        ("0.0402", 0.402, "typo:decimal point shifted"),  # x10^-1
        ("0.153", 0.1353, "typo:digit dropped"),  # 0.1353 -> 0.153
        ("0.1335", 0.135, "typo:digit doubled"),  # 0.135 -> 0.1335
        ("0.153", 0.135, "typo:two digits transposed"),
        ("0.175", 0.115, "typo:OCR confusion"),  # second 1 read as 7
        ("-0.135", 0.135, "typo:sign lost"),
        ("0.13338", 0.1333861, "typo:truncated"),  # Steelman Table 5: sqrt(beta/2) truncated
        ("0.13325", 0.1332449653, "typo:double rounding"),  # Steelman Table 5, exact
        ("2.468", 1.234, "convention:factor 2"),  # two-sided bandwidth
        ("12.34", 0.1234, "convention:percent vs fraction"),
        ("57.30", 1.0, "convention:radians vs degrees"),
    ],
)
def test_each_generic_family_finds_its_slip(printed, reproduced, label):
    assert label in _labels(_row(printed, reproduced))


def test_generic_family_candidates_are_declared_functions():
    names = [f.name for f in GENERIC_FAMILIES]
    assert len(names) == len(set(names)) == 11
    for fam in (*GENERIC_FAMILIES, *CLAIM_FAMILIES):
        assert fam.candidates.__doc__, fam.name


def test_typographic_variants_keep_the_printed_unit():
    v = typographic_variants("0.135")
    assert ("0.153", "digits 2-3 (35) transposed") in v["two digits transposed"]
    assert {t for t, _ in v["digit dropped"]} == {"0.35", "0.15", "0.13"}
    assert ("0.1335", "digit 2 (3) doubled") in v["digit doubled"]
    assert ("0.185", "3 read as 8 at digit 2") in v["OCR confusion"]
    assert all(len(p) == 2 and p[0] != p[1] for p in OCR_PAIRS)


def test_claim_families_from_related_quantities():
    values = [1.0, 2.0, 3.0, 10.0]
    # printed "4.00" is the mean, not the median (2.5) the claim computed
    assert "aggregation:mean" in _labels(_row("4.00", 2.5, values=values))
    assert "aggregation:RMS" in _labels(_row("5.34", 2.5, values=values))  # sqrt(114/4)
    assert "scope:alpha = .3 row" in _labels(
        _row("0.655", 0.1987, neighbours={"alpha = .3 row": 0.6553})
    )
    assert "convention:per second vs per sample" in _labels(_row("234", 1.0, dt=1 / 234.0))
    # a typo in an input: the printed number computed from T = .0034 instead of .0043
    row = _row("294", 232.6, inputs={"T": (".0043", lambda t: 1.0 / t)})
    assert "typo:in input T" in _labels(row)


def test_hand_written_reading_goes_through_the_chance_check():
    r = Reading("two-sided ENBW", 6.94, "sec 6", family="convention:two-sided bandwidth")
    ex = explain(_row("7", 9.82), [r])
    hit = [h for h in ex.hits if h.family == "convention:two-sided bandwidth"][0]
    # a one-digit number: one candidate of nine numbers in [1, 10): chance 1/9 > 0.05
    assert math.isclose(hit.chance, 1 / 9)
    assert not hit.accepted and ex.best is None or ex.best.family != hit.family
    # the same reading of a four-digit number is accepted (1 of 9000)
    r4 = Reading("two-sided ENBW", 6.943, "sec 6", family="convention:two-sided bandwidth")
    best = explain(_row("6.943", 9.82), [r4]).best
    assert best.family == "convention:two-sided bandwidth" and best.chance < 2e-4


# ----------------------------------------------------------------------- chance
def test_chance_of_one_candidate_is_one_printed_number_of_the_span():
    for printed, n in (("7", 9), ("40", 90), (".135", 900), ("1452", 9000), ("1.20", 900)):
        unit = 2 * tolerance_from_printed(printed)
        inside = reference_span(printed)[0] + 2.8 * unit  # 0.3 units from a number
        assert math.isclose(chance([inside], printed), 1 / n)


def test_chance_counts_overlapping_windows_once_and_clips_to_the_span():
    # 0.5 and 0.5004 cover the number .500 once; .5007 adds .501: 2 of 900
    assert math.isclose(chance([0.5, 0.5, 0.5004], ".135"), 1 / 900)
    assert math.isclose(chance([0.5, 0.5007], ".135"), 2 / 900)
    assert chance([5.0, 0.01, float("nan")], ".135") == 0.0
    # a wider tolerance (an override) widens every window: .498 .. .502
    assert math.isclose(chance([0.5], ".135", 0.002), 5 / 900)


@pytest.mark.parametrize("printed", ["7", "40", ".135", "0.0402", "1452", "-3.25"])
def test_chance_agrees_with_a_direct_monte_carlo_estimate(printed):
    """Unrelated numbers of the printed precision, drawn uniformly over the span's printed
    grid, land within tolerance of the candidates as often as the chance says."""
    rng = np.random.default_rng(20261201)  # seeded: the test is deterministic
    t = tolerance_from_printed(printed)
    unit = 2 * t
    lo, hi = reference_span(printed)
    cands = rng.uniform(lo, hi, size=7)
    grid = np.arange(math.ceil(lo / unit), math.floor(hi / unit) + 1) * unit
    grid = grid[(grid >= lo) & (grid < hi)]
    draws = rng.choice(grid, size=20000)
    hit = (np.abs(draws[:, None] - cands[None, :]) <= t * (1 + 1e-9)).any(axis=1).mean()
    c = chance(cands, printed)
    assert abs(hit - c) < 4 * math.sqrt(c * (1 - c) / draws.size) + 1e-9


@pytest.mark.parametrize("digits", [2, 3, 4])
def test_random_published_values_are_explained_at_most_at_the_declared_rate(digits):
    """Random published values (seeded, same printed precision, unrelated to the
    reproduced value) are explained by the catalogue at no more than THRESHOLD."""
    rng = np.random.default_rng(1000 + digits)
    explained = n = 0
    for _ in range(1500):
        exp = int(rng.integers(-4, 3))
        mantissa = int(rng.integers(10 ** (digits - 1), 10**digits))
        printed = str(np.format_float_positional(mantissa * 10.0**exp, trim="-"))
        printed = f"{mantissa * 10.0**exp:.{max(0, -exp)}f}"
        reproduced = float(rng.uniform(0.1, 10.0)) * 10.0 ** (exp + digits - 1)
        row = _row(printed, reproduced)
        if abs(reproduced - float(printed)) <= row.tolerance:
            continue
        n += 1
        explained += explain(row).best is not None
    rate = explained / n
    # the bound, plus 3 binomial standard errors at the threshold
    assert rate <= THRESHOLD + 3 * math.sqrt(THRESHOLD * (1 - THRESHOLD) / n), rate


def test_a_claim_family_explains_random_values_at_most_at_its_budget():
    """With per-row values supplied (the aggregation family, its own budget THRESHOLD),
    random printed values are explained at most at 2 x THRESHOLD: the generic catalogue's
    share plus the one claim family's."""
    rng = np.random.default_rng(77)
    explained = n = 0
    for _ in range(1500):
        values = rng.uniform(1.0, 9.0, size=5)
        printed = f"{rng.uniform(1.0, 9.99):.2f}"
        row = _row(printed, float(np.median(values)), values=values)
        if abs(row.reproduced - float(printed)) <= row.tolerance:
            continue
        n += 1
        explained += explain(row).best is not None
    bound = 2 * THRESHOLD
    assert explained / n <= bound + 3 * math.sqrt(bound * (1 - bound) / n), explained / n


# ----------------------------------------------------------------------- judge
def test_judge_names_the_reading_the_chance_and_the_families_tried():
    row = judge("d", _pub("k", "0.13338"), 0.1333861, "")
    assert row["verdict"] == "explained"
    assert row["reading"] == "typo:truncated" and 0 < row["chance"] < 1e-4
    assert "families tried" in row["note"] and "typo:two digits transposed" in row["note"]
    miss = judge("d", _pub("k", "0.500"), 0.731, "")
    assert miss["verdict"] == "mismatch" and miss["reading"] == "" and miss["chance"] is None
    assert "reading families tried" in miss["note"]
    assert judge("d", _pub("k", "0.500"), 0.5001, "")["reading"] == ""
    unbounded = judge("d", _pub("k", "10"), float("inf"), "printed gains unstable")
    assert unbounded["verdict"] == "mismatch" and "not finite" in unbounded["note"]


@pytest.mark.parametrize(
    "printed, reproduced, gives",
    [
        # Steelman's Table 5: the reading gives the printed number itself, and the note
        # must read so (at 4 digits the truncation read "0.1334", the double rounding
        # "0.1333", neither of them the printed value)
        ("0.13338", 0.1333861367, "gives 0.13338, which matches"),
        ("0.13325", 0.1332449653, "gives 0.13325, which matches"),
        # Al-Wagih's Table 5 prints 4 decimals, the trailing zero among them
        ("77.0790", 77.07908088, "gives 77.0790, which matches"),
        # a printed number of fewer digits than NOTE_DIGITS: the reading's value at 4
        ("2.468", 1.234, "gives 2.468, which matches"),
    ],
)
def test_an_explained_note_writes_the_reading_with_the_printed_digits(printed, reproduced, gives):
    row = judge("d", _pub("k", printed), reproduced, "")
    assert row["verdict"] == "explained"
    assert gives in row["note"], row["note"]


def test_judge_qualitative_and_missing_rows_are_unchanged():
    assert judge("d", _pub("k", ""), True, "holds")["verdict"] == "match"
    assert judge("d", _pub("k", ""), False, "")["note"] == "qualitative check does not hold"
    with pytest.raises(AbglibValueError, match="needs a note"):
        judge("d", _pub("k", "1.5"), None, "")


# ----------------------------------------------------------------------- sentences
def _two_sided(value):
    return (Reading("two-sided", value, "s6", family="convention:two-sided bandwidth"),)


def test_one_sentence_one_judgement_withdraws_a_contradicted_reading():
    # row a alone: explained under the two-sided reading (4 digits: chance 1/9000)
    a = _assess("d", _pub("a", "6.943", "a"), 9.82, "", _two_sided(6.943))
    # row b, same sentence: the two-sided reading gives 40.65, not the printed 40.00
    b = _assess("d", _pub("b", "40.00", "b"), 20.32, "", _two_sided(40.65))
    assert a.row["verdict"] == "explained"
    rows = judge_sentences([a, b], ["s", "s"])
    assert rows[0]["verdict"] == "mismatch" and rows[0]["reading"] == ""
    assert "withdrawn" in rows[0]["note"] and "'b'" in rows[0]["note"]
    assert {r["reading"] for r in rows} == {""}  # no contradicting readings


def test_one_sentence_keeps_a_reading_its_siblings_agree_with():
    a = _assess("d", _pub("a", "6.943", "a"), 9.82, "", _two_sided(6.943))
    b = _assess("d", _pub("b", "40.65", "b"), 20.32, "", _two_sided(40.65))
    rows = judge_sentences([a, b], ["s", "s"])
    assert [r["reading"] for r in rows] == ["convention:two-sided bandwidth"] * 2
    # rows of different sentences are judged alone
    b2 = _assess("d", _pub("b", "40.00", "b"), 20.32, "", _two_sided(40.65))
    a2 = _assess("d", _pub("a", "6.943", "a"), 9.82, "", _two_sided(6.943))
    assert judge_sentences([a2, b2], ["s", "t"])[0]["verdict"] == "explained"


def test_a_misprint_of_one_number_is_not_shared_by_its_sentence():
    a = _assess("d", _pub("a", "0.13338", "a"), 0.1333861, "")  # truncated
    b = _assess("d", _pub("b", "0.500", "b"), 0.5001, "")  # match, no truncation
    rows = judge_sentences([a, b], ["s", "s"])
    assert rows[0]["reading"] == "typo:truncated"


# ----------------------------------------------------------------------- vague words
def test_vague_table_declares_a_range_and_basis_for_every_word():
    words = {v.word for v in VAGUE}
    for w in ("about", "approximately", "nearly", "similar", "considerably", "hardly"):
        assert w in words
    assert "very highly significant" in words
    for v in VAGUE:
        assert 0 < v.low < v.high and v.basis.strip(), v.word
    assert threshold_range("similar") == (1.12, 1.41)
    with pytest.raises(AbglibValueError, match="word must be one of"):
        threshold_range("somewhat")


def test_find_vague_matches_whole_words_longest_first():
    assert [v.word for v in find_vague("max error, 'about 20 %'")] == ["about"]
    assert [v.word for v in find_vague("p < .001: very highly significant")] == [
        "very highly significant"
    ]
    assert find_vague("roundabout") == []


def test_about_is_judged_across_its_range():
    # 'about 20 %' with 20.9: outside half a unit, inside 5 % and 20 %: match, robust
    out = judge("d", _pub("k", "20", quantity="error (%), 'about 20 %'"), 20.9, "")
    assert out["verdict"] == "match" and out["robust"] == "true"
    assert out["tolerance"] == pytest.approx(4.0)
    # 23: a match when 'about' is read as 20 %, not at 5 %: the verdict hinges on the word
    out = judge("d", _pub("k", "20", quantity="error (%), 'about 20 %'"), 23.0, "")
    assert out["verdict"] == "not_reproducible" and out["robust"] == "false"
    assert "'about'" in out["note"]
    # without the word: half a unit in the last digit, no robustness from a word
    out = judge("d", _pub("k", "20"), 20.9, "")
    assert out["verdict"] == "mismatch" and "robust" not in out and "vague" not in out
    # a match at half a unit is one under every reading: unchanged, robust
    out = judge("d", _pub("k", "20", quantity="'about 20 %'"), 20.4, "")
    assert (out["verdict"], out["tolerance"], out["note"]) == ("match", 0.5, "")
    assert out["robust"] == "true" and out["vague"] == ("vague:about",)
    assert vague_tolerances(20.0, 0.5, find_vague("nearly")) == [(-0.5, 0.5), (-2.0, 0.5)]


# ----------------------------------------------------------------------- changes
def test_changes_name_the_reading_that_changed_a_verdict(tmp_path):
    import pandas as pd

    from abglib.reporting.changes import diff_tables

    base = {"doc": "d", "quantity": "q", "tolerance": 5e-6, "depends_on": "", "robust": ""}
    old = pd.DataFrame(
        [
            {**base, "item": "a", "published": "0.13338", "reproduced": 0.1333861},
            {**base, "item": "b", "published": "0.01", "reproduced": 0.0099},
        ]
    ).assign(verdict=["mismatch", "explained"], note=["x", "y"])
    new = old.assign(
        verdict=["explained", "mismatch"],
        reading=["typo:truncated", ""],
        chance=[1.11e-05, None],
    )
    old.to_csv(tmp_path / "old.csv", index=False)
    new.to_csv(tmp_path / "new.csv", index=False)
    ch = diff_tables({"d": tmp_path / "old.csv"}, {"d": tmp_path / "new.csv"})
    notes = ch.table.set_index("item")["note"]
    assert notes["a"].startswith("explained by the reading typo:truncated (chance 1.11e-05)")
    assert notes["b"].startswith("the explaining reading is no longer accepted")


def test_non_matches_shows_the_reading_beside_the_verdict():
    import pandas as pd

    from abglib.replications.compare import non_matches

    comp = pd.DataFrame(
        {
            "item": ["a", "b"],
            "published": ["1", "0.13338"],
            "reproduced": ["1", "0.1333861"],
            "verdict": ["match", "explained"],
            "note": ["", "truncated"],
            "reading": ["", "typo:truncated"],
            "chance": [None, 1.11e-05],
        }
    )
    out = non_matches(comp)
    assert list(out.columns) == [
        "item", "published", "reproduced", "verdict", "reading", "chance", "note"
    ]  # fmt: skip
    assert list(out["reading"]) == ["typo:truncated"]


def test_read_published_accepts_an_optional_sentence_column(tmp_path):
    from abglib.replications.compare import read_published

    head = "key,item,quantity,published,where"
    (tmp_path / "a.csv").write_text(f"{head},sentence\nk1,i,q,7,p,s1\nk2,i,q,40,p,s1\n")
    (tmp_path / "b.csv").write_text(f"{head}\nk3,i,q,1,p\n")
    pub = read_published([tmp_path / "a.csv", tmp_path / "b.csv"])
    assert list(pub["sentence"]) == ["s1", "s1", ""]


def test_a_qualitative_reading_must_state_its_chance():
    pub = _pub("k", "")
    ok = Reading("as the prediction VRF", True, "s5", family="convention:predicted", chance=2e-9)
    out = judge("d", pub, False, "fails as printed", [ok])
    assert (out["verdict"], out["reading"], out["chance"]) == (
        "explained",
        "convention:predicted",
        2e-9,
    )
    lucky = Reading("some reading", True, "s5", family="claim:x", chance=0.2)
    assert judge("d", pub, False, "", [lucky])["verdict"] == "mismatch"
    with pytest.raises(AbglibValueError, match="must give its chance"):
        judge("d", pub, False, "", [Reading("r", True, "s5")])


@pytest.mark.parametrize(
    "printed, bound, verdict",
    [
        # the antenna's p_a upper edge: stable to the grid's end 1.05, printed 1.005: the
        # quantity is above 1.05, so 1.005 is not it (a digit-doubled reading of 1.05 would
        # have 'explained' it)
        ("1.005", ">", "mismatch"),
        ("1.2", ">", "not_reproducible"),  # above the bound: may be the quantity
        ("1.0505", ">", "not_reproducible"),  # within the tolerance of the bound
        ("1.2", "<", "mismatch"),  # the quantity is below 1.05
        ("0.9", "<", "not_reproducible"),
    ],
)
def test_a_bound_is_judged_by_its_side_and_no_reading_is_tried(printed, bound, verdict):
    row = judge("d", _pub("k", printed), 1.05, "stable to the grid's end", bound=bound)
    assert row["verdict"] == verdict, row
    assert row["reading"] == "" and row["chance"] is None
    assert row["note"].startswith(f"the quantity lies {'above' if bound == '>' else 'below'} 1.05")
    # without the bound, the same numbers are explained by a reading (digit doubled)
    if printed == "1.005":
        assert judge("d", _pub("k", printed), 1.05, "")["verdict"] == "explained"


def test_a_bound_must_name_its_side():
    with pytest.raises(AbglibValueError, match="bound must be"):
        judge("d", _pub("k", "1.0"), 1.05, "", bound="above")
