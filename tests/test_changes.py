"""What changed between two report versions (abglib.reporting.changes, ``abglib changes``)."""

from __future__ import annotations

from pathlib import Path

import pandas as pd
import pytest

from abglib._checks import AbglibValueError
from abglib.reporting.changes import (
    CHANGES_COLUMNS,
    diff_folders,
    match_rows,
    previous_version,
    write_changes,
)
from abglib.reporting.cli import main

REPO = Path(__file__).resolve().parents[1]

# an old table without depends_on/robust (as v0.2.0 wrote it), and the new one
OLD = """doc,item,quantity,published,reproduced,abs_err,rel_err,tolerance,verdict,note
d,Table 1 a,gain,0.30,0.3001,0.0001,0.0003,0.005,match,
d,Table 1 b,gain,0.40,0.4300,0.03,0.075,0.005,mismatch,off
d,Table 1 c,gain,0.50,0.5010,0.001,0.002,0.005,match,
d,Table 1 d,gain,0.60,0.6000,0,0,0.005,match,
d,claim e,holds,,True,,,,match,checked
d,Table 2 gone,lag,12,12.2,0.2,0.0167,0.5,match,
d,Fig 3,lag (m),7.5,7.52,0.02,0.003,0.05,match,
d,Fig 4,width,3,,,,0.5,not_reproducible,lost figure
"""
NEW = """doc,item,quantity,published,reproduced,abs_err,rel_err,tolerance,verdict,note,\
depends_on,robust
d,Table 1 a,gain,0.30,0.3049,0.0049,0.016,0.005,match,,,
d,Table 1 b,gain,0.40,0.4300,0.03,0.075,0.005,explained,eq 9 gives it,,
d,Table 1 c,gain,0.50,0.5070,0.007,0.014,0.005,mismatch,moved,,
d,Table 1 d,gain,0.60,0.6100,0.01,0.0167,0.005,mismatch,x.gate out of range,x.gate,false
d,claim e,holds,,False,,,,mismatch,no longer holds,,
d,Fig 3,lag in metres,7.5,7.52,0.02,0.003,0.05,match,,,
d,Fig 4,width,3,3.2,0.2,0.07,0.5,not_reproducible,flips,x.gate,false
d,Table 9 new,lag,1.5,1.5,0,0,0.05,match,,,
"""


def _version(root: Path, tables: dict[str, str], index=True) -> Path:
    for doc, text in tables.items():
        (root / doc / "tables").mkdir(parents=True)
        (root / doc / "tables" / "comparison.csv").write_text(text, encoding="utf-8")
        if index:
            (root / doc / "index.html").write_text("<html></html>")
    return root


@pytest.fixture
def two(tmp_path):
    old = _version(tmp_path / "reports" / "v0.1.0", {"d": OLD})
    new = _version(tmp_path / "reports" / "v0.2.0", {"d": NEW})
    return old, new


def _by_item(ch) -> dict[str, dict]:
    return {r["item"]: r for r in ch.table.to_dict("records")}


def test_every_kind_of_change_is_found(two):
    ch = diff_folders(*two)
    rows = _by_item(ch)
    assert list(ch.table.columns) == CHANGES_COLUMNS
    # moved within the tolerance (0.0048 of 0.005): not a change; Table 1 d is a verdict
    assert "Table 1 a" not in rows
    assert rows["Table 1 b"]["change"] == "verdict"
    assert (rows["Table 1 b"]["old_verdict"], rows["Table 1 b"]["new_verdict"]) == (
        "mismatch",
        "explained",
    )
    assert rows["Table 1 b"]["note"] == "eq 9 gives it"  # the value did not move
    # the verdict changed and the value moved by 0.006, 1.2 tolerances: both said
    assert rows["Table 1 c"]["change"] == "verdict"
    assert "moved by 0.006 (1.2 tolerances of 0.005)" in rows["Table 1 c"]["note"]
    assert "robust: (empty) → false" in rows["Table 1 d"]["note"]
    assert rows["claim e"]["change"] == "verdict"
    assert "outcome True → False" in rows["claim e"]["note"]
    # same verdict, a value where there was none
    assert rows["Fig 4"]["change"] == "moved"
    assert rows["Fig 4"]["note"].startswith("now reproduced (3.2)")
    assert rows["Table 2 gone"]["change"] == "removed"
    assert rows["Table 2 gone"]["old_value"] == "12.2" and rows["Table 2 gone"]["new_value"] == ""
    assert rows["Table 9 new"]["change"] == "added"
    # Fig 3's quantity was reworded: paired by item and printed value, nothing changed
    assert "Fig 3" not in rows
    assert ch.counts().to_dict("records") == [
        {"doc": "d", "verdict": 4, "moved": 1, "note": 0, "added": 1, "removed": 1, "total": 7}
    ]
    assert ch.remarks["d"][0] == "columns new in v0.2.0: depends_on, robust"
    assert "1 rows paired although their text changed" in ch.remarks["d"][1]


def test_a_note_that_changed_under_the_same_verdict_and_value(tmp_path):
    head = "doc,item,quantity,published,reproduced,tolerance,verdict,note,robust\n"
    old = _version(
        tmp_path / "a",
        {
            "d": head
            + "d,x,q,10,10.1,0.5,match,mismatch at 4 of 7 points,false\n"
            + "d,y,q,20,20.1,0.5,match,same,true\n"
            + "d,z,q,30,30.1,0.5,match,same,true\n"
            + "d,w,q,40,40.1,0.5,match,same,true\n"
        },
    )
    new = _version(
        tmp_path / "b",
        {
            "d": head
            + "d,x,q,10,10.1,0.5,match,mismatch at 2 of 7 points,false\n"
            + "d,y,q,20,20.1,0.5,match,same,false\n"
            + "d,z,q,30,30.2,0.5,match,same,true\n"  # within its tolerance: no change
            + "d,w,quantity reworded,40,40.1,0.5,match,same,true\n"  # paired alone
        },
    )
    ch = diff_folders(old, new)
    rows = _by_item(ch)
    assert sorted(rows) == ["x", "y"]
    assert rows["x"]["change"] == "note"
    assert rows["x"]["note"] == "now: mismatch at 2 of 7 points; was: mismatch at 4 of 7 points"
    assert (rows["x"]["old_verdict"], rows["x"]["new_verdict"]) == ("match", "match")
    assert rows["y"]["change"] == "note" and rows["y"]["note"] == "robust: true → false"
    assert ch.counts().to_dict("records") == [
        {"doc": "d", "verdict": 0, "moved": 0, "note": 2, "added": 0, "removed": 0, "total": 2}
    ]
    write_changes(ch, tmp_path / "changes.csv", tmp_path / "changes.html", {})
    page = (tmp_path / "changes.html").read_text(encoding="utf-8")
    assert "same verdict and value, note changed" in page and "mismatch at 2 of 7" in page


def test_a_value_moved_beyond_its_tolerance_with_the_same_verdict(tmp_path):
    head = "doc,item,quantity,published,reproduced,tolerance,verdict,note\n"
    old = _version(tmp_path / "a", {"d": head + "d,x,q,10,11,0.5,mismatch,far\n"})
    new = _version(tmp_path / "b", {"d": head + "d,x,q,10,12.5,0.5,mismatch,far\n"})
    (row,) = diff_folders(old, new).table.to_dict("records")
    assert row["change"] == "moved"
    assert row["note"] == "moved by 1.5 (3 tolerances of 0.5)"
    # exactly half a unit, computed in binary, is not a move
    new2 = _version(tmp_path / "c", {"d": head + "d,x,q,10,11.5,0.5,mismatch,far\n"})
    assert diff_folders(old, new2).table.empty


def test_a_document_new_or_gone_is_all_added_or_removed(tmp_path):
    old = _version(tmp_path / "a", {"d": OLD, "gone": OLD})
    new = _version(tmp_path / "b", {"d": OLD, "fresh": NEW})
    ch = diff_folders(old, new)
    counts = ch.counts().set_index("doc")
    assert counts.loc["d", "total"] == 0
    assert counts.loc["gone", "removed"] == 8 and counts.loc["gone", "total"] == 8
    assert counts.loc["fresh", "added"] == 8 and counts.loc["fresh", "total"] == 8
    assert ch.remarks["fresh"] == ["new in b: every row is added"]


def test_pairing_prefers_key_then_item_quantity_published():
    old = pd.DataFrame(
        {
            "key": ["k1", "k2", ""],
            "item": ["A", "B", "C"],
            "quantity": ["q", "q", "q"],
            "published": ["1", "2", "3"],
        }
    )
    new = old.iloc[::-1].reset_index(drop=True).copy()
    new.loc[0, "published"] = "3.0"  # C re-transcribed: paired by item and quantity
    new.loc[2, "item"] = "A renamed"  # A: paired by key
    pairs = match_rows(old, new)
    assert pairs == [
        (0, 2, "paired by key"),
        (1, 1, "paired by key"),
        (2, 0, "paired by item and quantity (the printed value changed)"),
    ]
    # without keys, the renamed item is paired by quantity and printed value
    pairs = match_rows(old.drop(columns="key"), new.drop(columns="key"))
    assert (0, 2, "paired by quantity and printed value (the item was renamed)") in pairs


def test_ambiguous_rows_are_not_paired_by_a_loose_key():
    old = pd.DataFrame({"item": ["A", "B"], "quantity": ["q", "q"], "published": ["1", "1"]})
    new = pd.DataFrame({"item": ["X", "Y"], "quantity": ["q", "q"], "published": ["1", "1"]})
    assert match_rows(old, new) == []  # two candidates each: added and removed, not guessed


def test_missing_columns_and_folders_are_refused(tmp_path):
    bad = _version(tmp_path / "bad", {"d": "doc,item,verdict\nd,x,match\n"})
    good = _version(tmp_path / "good", {"d": OLD})
    missing = r"missing \['quantity', 'published', 'reproduced'\]"
    with pytest.raises(AbglibValueError, match=missing):
        diff_folders(bad, good)
    with pytest.raises(AbglibValueError, match="must be a directory, got"):
        diff_folders(tmp_path / "absent", good)
    (tmp_path / "empty").mkdir()
    with pytest.raises(AbglibValueError, match="'.*empty' and '.*empty' hold no <doc>/tables"):
        diff_folders(tmp_path / "empty", tmp_path / "empty")
    # a folder above the version folders (reports/) holds no table of its own: refused, not
    # read as a version without documents (every row of the other reported added)
    with pytest.raises(AbglibValueError) as exc:
        diff_folders(good.parent, good)
    assert str(exc.value).startswith(f"{str(good.parent)!r} holds no <doc>/tables/comparison.csv")


def test_previous_version_is_the_highest_below(tmp_path):
    for v in ("v0.1.0", "v0.2.0", "v0.10.0", "v0.3.0", "notes"):
        (tmp_path / v).mkdir()
    assert previous_version(tmp_path, "0.3.0").name == "v0.2.0"
    assert previous_version(tmp_path, "0.11.0").name == "v0.10.0"
    assert previous_version(tmp_path, "0.1.0") is None
    assert previous_version(tmp_path / "absent", "0.3.0") is None
    with pytest.raises(AbglibValueError, match="version must look like 0.3.0, got 'x'"):
        previous_version(tmp_path, "x")


def test_pages_are_written_offline_and_link_back(two, tmp_path):
    ch = diff_folders(*two)
    out = tmp_path / "out"
    write_changes(ch, out / "changes.csv", out / "changes.html", {"d": "d/index.html"})
    page = (out / "changes.html").read_text(encoding="utf-8")
    assert '<a href="index.html">' in page and '<a href="d/index.html">report</a>' in page
    assert "http" not in page  # no network request of any kind
    assert "What changed: v0.2.0 against v0.1.0" in page
    assert pd.read_csv(out / "changes.csv").shape == (7, len(CHANGES_COLUMNS))
    write_changes(None, out / "c2.csv", out / "c2.html", version="0.1.0", releases="reports")
    assert "no version folder below v0.1.0 under <code>reports/</code>" in (
        out / "c2.html"
    ).read_text(encoding="utf-8")
    assert (out / "c2.csv").read_text(encoding="utf-8").strip() == ",".join(CHANGES_COLUMNS)


def test_cli_prints_counts_and_writes_both_files(two, tmp_path, capsys):
    old, new = two
    assert main(["changes", str(old), str(new), "--out", str(new)]) == 0
    out = capsys.readouterr().out
    assert "v0.2.0" in out and (new / "changes.html").is_file() and (new / "changes.csv").is_file()
    assert '<a href="d/index.html">' in (new / "changes.html").read_text(encoding="utf-8")
    # written elsewhere, the report links are relative to where the page is
    assert main(["changes", str(old), str(new), "--out", str(tmp_path / "x")]) == 0
    page = (tmp_path / "x" / "changes.html").read_text(encoding="utf-8")
    assert '<a href="../reports/v0.2.0/d/index.html">' in page
    assert main(["changes", str(old), str(tmp_path / "nope")]) == 2
    assert "must be a directory" in capsys.readouterr().err
    assert main(["changes", str(old.parent), str(new)]) == 2
    err = capsys.readouterr().err
    assert err.startswith("abglib changes: ") and "holds no <doc>/tables/comparison.csv" in err


def test_real_v020_to_v030_lists_the_replication_layer_verdict_changes():
    """The verdict changes the replication-layer issue made (its closing note): Huang 5,
    Al-Wagih 16, antenna 7; every v0.2.0 row paired by item, quantity and printed value."""
    old, new = REPO / "reports" / "v0.2.0", REPO / "reports" / "v0.3.0"
    # committed releases are frozen history, never removed (CONTRACTS.md §4)
    assert old.is_dir() and new.is_dir(), "the committed releases reports/v0.2.0, v0.3.0"
    ch = diff_folders(old, new)
    t = ch.table
    verdicts = t[t["change"] == "verdict"]
    assert verdicts.groupby("doc").size().to_dict() == {"alwagih": 16, "antenna": 7, "huang": 5}
    assert t[t["change"] == "removed"].empty  # every v0.2.0 row found in v0.3.0
    assert not any("paired by" in n for n in t["note"])  # all on item + quantity + published
    huang = verdicts[verdicts["doc"] == "huang"].set_index("item")
    assert huang["new_verdict"].to_dict() == {
        "Fig 4 text, 40 Hz": "explained",
        "Fig 5 text, 2 Hz": "not_reproducible",
        "Fig 5 text, overranged": "not_reproducible",
        "Fig 6 text, type I": "not_reproducible",
        "Fig 7 text, type II": "not_reproducible",
    }
    assert huang.loc["Fig 4 text, 40 Hz", "old_verdict"] == "mismatch"
    assert set(verdicts.loc[verdicts["doc"] != "huang", "new_verdict"]) == {"not_reproducible"}
    # rows added with v0.3.0: every new row is one of the new table's
    for doc in ("alwagih", "antenna", "faa_bendix", "huang", "steelman1978"):
        n_old, n_new = ch.rows[doc]
        assert (t[(t["doc"] == doc) & (t["change"] == "added")].shape[0]) == n_new - n_old


def test_a_build_is_compared_on_its_own_documents(tmp_path):
    """The pipeline's rule: a build of some documents does not report the others removed;
    without a previous version the page says so."""
    from abglib.reporting.changes import write_build_changes

    prev = _version(tmp_path / "reports" / "v0.1.0", {"d": OLD, "other": OLD})
    built = tmp_path / "results" / "d" / "comparison.csv"
    built.parent.mkdir(parents=True)
    built.write_text(NEW, encoding="utf-8")
    out = tmp_path / "out"
    ch = write_build_changes({"d": str(built)}, prev, "0.2.0", out / "c.csv", out / "c.html")
    assert ch.docs == ["d"] and len(ch.table) == 7
    page = (out / "c.html").read_text(encoding="utf-8")
    assert "documents of v0.1.0 not in this build, not compared: other" in page
    assert "What changed: v0.2.0 against v0.1.0" in page
    none = write_build_changes({"d": str(built)}, None, "0.2.0", out / "n.csv", out / "n.html")
    assert none is None
    assert "nothing to compare with" in (out / "n.html").read_text(encoding="utf-8")
