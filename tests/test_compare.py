"""Published-versus-reproduced logic (abglib.replications.compare; shared/CONTRACTS.md §3)."""

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from abglib import AbglibValueError
from abglib.common.tables import csv_text, format_table, with_precision, write_csv
from abglib.replications.compare import (
    COMPARISON_COLUMNS,
    build_comparison,
    read_published,
    scorecard,
)
from abglib.verdicts import Alternative, format_number, tolerance_from_printed, verdict


# printed strings of seed 000 (Steelman 1978) and the half unit of their last digit
@pytest.mark.parametrize(
    ("printed", "tol"),
    [
        (".135", 5e-4),  # design example, omega*T at -3 dB
        ("0.0014", 5e-5),  # Table 1, gamma
        ("1452", 0.5),  # design example, omega of the first undesired maximum
        ("235", 0.5),  # design example, samples per second
        ("-3", 0.5),  # dB level
        ("1.20", 5e-3),  # Table 3: the trailing zero is a printed digit
        ("0.0402", 5e-5),  # Table 5
        ("23", 0.5),  # design example, dB down
        ("0.13325", 5e-6),  # Table 5
        ("2.5e-3", 5e-5),  # scientific notation keeps its mantissa digits
        ("\u22123", 0.5),  # a typeset minus sign
    ],
)
def test_tolerance_from_printed_precision(printed, tol):
    assert tolerance_from_printed(printed) == pytest.approx(tol, rel=1e-12)


@pytest.mark.parametrize("bad", ["", "about 23", "1,452", "nan", "inf"])
def test_tolerance_rejects_non_numbers(bad):
    with pytest.raises(AbglibValueError, match="published must be"):
        tolerance_from_printed(bad)


def test_verdict_match_at_exactly_half_a_unit():
    # 0.1345 vs '.135': error 5e-4, exactly the tolerance (binary rounding must not flip it)
    assert verdict(".135", 0.1345, 5e-4)[0] == "match"
    assert verdict(".135", 0.13449, 5e-4)[0] == "mismatch"


def test_verdicts_numeric_and_missing():
    assert verdict("1452", 1451.9, 0.5) == ("match", None)
    assert verdict("1452", 1462.6, 0.5) == ("mismatch", None)
    assert verdict("1452", None, 0.5) == ("not_reproducible", None)
    assert verdict("1452", float("nan"), 0.5) == ("not_reproducible", None)
    assert verdict("1452", "", 0.5) == ("not_reproducible", None)


def test_verdict_qualitative():
    assert verdict("", True, None)[0] == "match"
    assert verdict("", "False", None)[0] == "mismatch"
    with pytest.raises(AbglibValueError, match="True or False"):
        verdict("", "maybe", None)


def test_verdict_explained_only_by_an_alternative_within_tolerance():
    near = Alternative("k", "arithmetic on the printed inputs", 1451.9, "3. Design example")
    far = Alternative("k", "something else", 1440.0, "3. Design example")
    assert verdict("1452", 1462.6, 0.5, [far]) == ("mismatch", None)
    v, alt = verdict("1452", 1462.6, 0.5, [far, near])
    assert v == "explained" and alt is near
    # a match never needs an explanation
    assert verdict("1452", 1452.2, 0.5, [near]) == ("match", None)


def _published():
    return pd.DataFrame(
        {
            "key": ["a", "b", "c", "d", "e"],
            "item": ["Table 1, beta", "p. 8, omega", "p. 8, rate", "Fig. 7", "eq 50 claim"],
            "quantity": ["gain", "1/s", "1/s", "lost figure", "minimum at pi"],
            "published": ["0.0356", "1452", "235", "0.5", ""],
            "where": ["Table 1"] * 5,
        }
    )


def _reproduced():
    return pd.DataFrame(
        {
            "key": ["a", "b", "c", "d", "e"],
            "reproduced": ["0.03558372292", "1462.64", "234.29", "", "True"],
            "note": ["", "", "1/T is 234.3", "figure lost in the scan", "checked on a grid"],
        }
    )


def test_build_comparison_contract_columns_and_verdicts():
    alts = pd.DataFrame(
        {
            "key": ["b"],
            "alternative": ["printed arithmetic"],
            "value": [1451.9],
            "section": ["3. The design example"],
        }
    )
    comp = build_comparison("steelman1978", _published(), _reproduced(), alts)
    assert list(comp.columns) == COMPARISON_COLUMNS
    assert list(comp["verdict"]) == ["match", "explained", "mismatch", "not_reproducible", "match"]
    # every non-match has a note; the explained note names the alternative and the section
    assert all(comp.loc[comp["verdict"] != "match", "note"].str.len() > 0)
    assert "printed arithmetic" in comp.loc[1, "note"]
    assert "3. The design example" in comp.loc[1, "note"]
    # errors: reproduced - published, relative to |published|; empty for a claim
    assert comp.loc[0, "abs_err"] == pytest.approx(0.03558372292 - 0.0356)
    assert comp.loc[2, "rel_err"] == pytest.approx((234.29 - 235) / 235)
    assert pd.isna(comp.loc[4, "abs_err"]) and pd.isna(comp.loc[4, "tolerance"])
    assert comp.loc[0, "published"] == "0.0356"  # kept as printed


def test_build_comparison_tolerance_override_needs_reason():
    over = {"c": {"tolerance": 1.0, "reason": "read off the graph"}}
    comp = build_comparison("doc", _published(), _reproduced(), overrides=over)
    assert comp.loc[2, "verdict"] == "match" and comp.loc[2, "tolerance"] == 1.0
    assert "read off the graph" in comp.loc[2, "note"]
    with pytest.raises(AbglibValueError, match="must give a reason"):
        build_comparison("doc", _published(), _reproduced(), overrides={"c": {"tolerance": 1}})
    with pytest.raises(AbglibValueError, match="unknown keys"):
        build_comparison("doc", _published(), _reproduced(), overrides={"zz": {}})


def test_build_comparison_rejects_key_drift():
    with pytest.raises(AbglibValueError, match="not reproduced: \\['e'\\]"):
        build_comparison("doc", _published(), _reproduced().iloc[:4])


def test_not_reproducible_needs_a_note():
    rep = _reproduced()
    rep.loc[3, "note"] = ""
    with pytest.raises(AbglibValueError, match="needs a note"):
        build_comparison("doc", _published(), rep)


def test_scorecard_counts_add_up():
    comp = build_comparison("steelman1978", _published(), _reproduced())
    card = scorecard([comp])
    assert list(card.columns) == [
        "doc",
        "match",
        "mismatch",
        "explained",
        "not_reproducible",
        "total",
        "robust",
        "fragile",
    ]
    row = card.iloc[0]
    assert row["match"] + row["mismatch"] + row["explained"] + row["not_reproducible"] == 5
    assert row["total"] == 5
    assert row["robust"] == row["fragile"] == 0  # no row depends on an assumed input


@pytest.mark.parametrize(
    ("x", "text"),
    [
        (0.1, "0.1"),
        (1.0 / 3.0, "0.3333333333"),
        (-0.0, "0"),
        (1452.0, "1452"),
        (2.0e-12, "2e-12"),
        (np.float64(0.0402), "0.0402"),
        (True, "True"),
        (None, ""),
        (float("nan"), ""),
    ],
)
def test_format_number_fixed_significant_digits(x, text):
    assert format_number(x) == text


def test_write_csv_is_byte_identical_and_atomic(tmp_path):
    comp = build_comparison("steelman1978", _published(), _reproduced())
    a, b = tmp_path / "a.csv", tmp_path / "b.csv"
    write_csv(comp, a)
    write_csv(comp.copy(), b)
    assert a.read_bytes() == b.read_bytes()
    assert not list(tmp_path.glob(".*.tmp"))  # no temporary file left behind
    # and the table reads back to the same verdicts
    back = pd.read_csv(a, dtype=str, keep_default_na=False)
    assert list(back.columns) == COMPARISON_COLUMNS
    assert list(back["verdict"]) == list(comp["verdict"])


def test_read_published_keeps_printed_strings_and_checks(tmp_path):
    p = tmp_path / "t.csv"
    p.write_text("# comment\nkey,item,quantity,published,where\nk,i,q,.1350,p. 8\n")
    df = read_published([p])
    assert df.loc[0, "published"] == ".1350"
    p.write_text("key,item,quantity,published,where\nk,i,q,abc,p. 8\n")
    with pytest.raises(AbglibValueError, match="t.csv, key 'k'"):
        read_published([p])
    p.write_text("key,item,published,where\nk,i,.1,p. 8\n")
    with pytest.raises(AbglibValueError, match="missing \\['quantity'\\]"):
        read_published([p])


def test_non_matches_keeps_only_rows_to_judge():
    from abglib.replications.compare import non_matches

    comp = pd.DataFrame(
        {
            "item": ["a", "b", "c"],
            "published": ["1", "2", ""],
            "reproduced": ["1", "2.5", "True"],
            "verdict": ["match", "mismatch", "explained"],
            "note": ["", "off by .5", "other reading"],
            "tolerance": ["0.5", "0.5", ""],
        }
    )
    out = non_matches(comp)
    assert list(out["item"]) == ["b", "c"]
    assert list(out.columns) == ["item", "published", "reproduced", "verdict", "note"]
    with pytest.raises(AbglibValueError, match="lacks columns"):
        non_matches(comp.drop(columns="note"))


@pytest.mark.parametrize(
    "x, spec, text",
    [
        (0.123456789012, 4, "0.1235"),
        (3.2e-16, "<1e-12", "<1e-12"),  # round-off: the bound, not the noise
        (-4e-13, "<1e-12", "<1e-12"),
        (0.25, "<1e-12", "0.25"),
        (0.123456789, "<1e-9:3", "0.123"),
        (float("nan"), "<1e-12", ""),
    ],
)
def test_format_cell_at_the_declared_precision(x, spec, text):
    from abglib.common.tables import format_cell

    assert format_cell(x, spec) == text


def test_write_csv_uses_the_tables_declared_precision(tmp_path):
    df = pd.DataFrame({"a": [1.23456789], "noise": [2e-17], "b": [9.87654321]})
    df.attrs["precision"] = {"a": 3, "noise": "<1e-12"}
    write_csv(df, tmp_path / "t.csv")
    assert (tmp_path / "t.csv").read_text() == "a,noise,b\n1.23,<1e-12,9.87654321\n"
    df.attrs["precision"] = {"missing": 3}
    with pytest.raises(AbglibValueError, match=r"columns the table lacks: \['missing'\]"):
        write_csv(df, tmp_path / "u.csv")
    with pytest.raises(AbglibValueError, match="a precision must be digits"):
        write_csv(df, tmp_path / "v.csv", precision={"a": "1e-3"})


def test_read_table_reads_bounds_as_zero(tmp_path):
    from abglib.common.tables import read_table

    df = pd.DataFrame({"name": ["a", "b"], "d": [0.25, 3e-16], "n": [1.5, 2.5]})
    write_csv(with_precision(df, d="<1e-12"), tmp_path / "t.csv")
    back = read_table(tmp_path / "t.csv")
    assert back["d"].tolist() == [0.25, 0.0] and back["name"].tolist() == ["a", "b"]
    # asked for text, every cell as written (a comparison table's columns are read so)
    assert read_table(tmp_path / "t.csv", dtype=str)["d"].tolist() == ["0.25", "<1e-12"]
    assert read_table(tmp_path / "t.csv", dtype={"d": str})["d"].tolist() == ["0.25", "<1e-12"]


def _pandas_route(df, digits=10, precision=None):
    return format_table(df, digits, precision).to_csv(index=False, lineterminator="\n")


def test_csv_text_writes_what_pandas_writes_for_every_dtype():
    """The fast route of write_csv against format_table + to_csv, column kind by kind:
    floats (NaN, -0, round-off bounds), objects (None, bools, text, numbers), ints, bools,
    strings with NA, text needing quotes, and the dtypes that take pandas' route."""
    df = pd.DataFrame(
        {
            "x": [1.0, np.nan, -0.0, 1.23456789012345e-13],
            "obj": [None, True, "a,b", 2.5],
            "i": np.array([1, -2, 3, 40], dtype=np.int64),
            "b": [True, False, True, False],
            "s": pd.array(["p", None, 'q"uote', "line\nbreak"], dtype="str"),
            "rel": [1e-15, 2e-3, np.nan, -3e-13],
            "": [0.5, 0.25, 0.125, 1.0],
        }
    )
    df = with_precision(df, rel="<1e-12:3", x=4)
    assert csv_text(df) == _pandas_route(df)
    assert "<1e-12" in csv_text(df)
    for other in (
        pd.array([1, None, 3, 4], dtype="Int64"),
        pd.Categorical(["a", "b", "a", "c"]),
        pd.array([True, None, False, True], dtype="boolean"),
        pd.date_range("2020-01-01", periods=4),
    ):
        t = df.assign(other=other)
        assert csv_text(t) == _pandas_route(t)
    empty = df.iloc[:0]
    assert csv_text(empty) == _pandas_route(empty)
    assert csv_text(pd.DataFrame()) == _pandas_route(pd.DataFrame())
    two = pd.DataFrame([[1.5, 2.5]], columns=pd.MultiIndex.from_tuples([("a", "b"), ("a", "c")]))
    assert csv_text(two) == _pandas_route(two)


@given(
    st.lists(
        st.tuples(
            st.floats(allow_nan=True, allow_infinity=False, width=64),
            st.one_of(st.none(), st.text(max_size=4), st.floats(allow_infinity=False)),
            st.integers(-(2**62), 2**62),
        ),
        min_size=1,
        max_size=6,
    ),
    st.integers(1, 17),
)
@settings(max_examples=60, deadline=None)
def test_csv_text_matches_pandas_on_random_tables(rows, digits):
    df = pd.DataFrame(rows, columns=["f", "o", "i"])
    assert csv_text(df, digits) == _pandas_route(df, digits)


def test_csv_text_names_a_precision_for_a_missing_column():
    with pytest.raises(AbglibValueError, match="lacks"):
        csv_text(with_precision(pd.DataFrame({"a": [1.0]}), b=3).drop(columns="a").assign(c=1.0))
