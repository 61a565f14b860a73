"""The report pages' pieces: table HTML, equations as MathML, the PNG alt-text reader, the
page builder and the index (abglib.reporting.tables / page / notebook / render)."""

import re
import struct
import zlib

import nbformat
import numpy as np
import pandas as pd
import pytest

from abglib.common.pngmeta import png_description
from abglib.reporting.notebook import Report
from abglib.reporting.page import (
    build_page,
    index_page,
    link_sections,
    markdown_html,
    math_html,
    read_headline,
    verdict_bar,
)
from abglib.reporting.render import verdict_counts, write_assets
from abglib.reporting.tables import cell_strings, group_runs, section_of, table_html


def comparison(n_same=8):
    """A comparison.csv-like frame: two singles, then a run of ``n_same`` identical rows."""
    return pd.DataFrame(
        {
            "item": ["Table 1, a", "eq 5, b"] + [f"Table 2, row {i}" for i in range(n_same)],
            "published": ["1.0", "2"] + [""] * n_same,
            "reproduced": [1.0, np.nan] + [3.25] * n_same,
            "verdict": ["match", "mismatch"] + ["not_reproducible"] * n_same,
            "note": ["", "off by one"] + ["trajectories not published"] * n_same,
            "robust": ["true", "false"] + [""] * n_same,
        }
    )


def test_empty_cells_are_blank_never_nan():
    df = pd.DataFrame({"x": [1.5, np.nan], "s": ["a", None], "i": pd.array([1, None], "Int64")})
    assert cell_strings(df) == [["1.5", "a", "1"], ["", "", ""]]
    out = table_html(df)
    assert "NaN" not in out and "nan" not in out and "&lt;NA&gt;" not in out and "None" not in out


def test_numbers_are_formatted_as_pandas_displays_them():
    with pd.option_context("display.precision", 5):
        assert cell_strings(pd.DataFrame({"x": [1.0, 0.123456789]})) == [["1.00000"], ["0.12346"]]


def test_verdict_and_robust_cells_carry_the_shared_classes():
    out = table_html(comparison(0))
    assert '<span class="v v-match">match</span>' in out
    assert '<span class="v v-mismatch">mismatch</span>' in out
    assert '<span class="v r-false">false</span>' in out
    assert 'data-verdict="match"' in out and 'data-section="Table 1"' in out
    assert 'data-filters="verdict item robust"' in out


def test_no_index_column_unless_it_means_something():
    df = comparison(0)
    plain = table_html(df[df["verdict"] != "match"])  # filtered: integer index 1
    assert plain.count("<th>") == 6
    labelled = table_html(df.set_index("item")[["verdict"]])
    assert "<th>item</th>" in labelled and labelled.count("<th>") == 2


def test_a_long_run_of_one_verdict_and_note_is_one_group_with_every_row():
    out = table_html(comparison(8), group_min=6)
    assert out.count('<tr class="group"') == 1
    summary = re.search(r"<summary>(.*?)</summary>", out).group(1)
    assert summary.startswith("8 rows, all") and "trajectories not published" in summary
    inner = re.search(r'<table class="data inner">(.*?)</table>', out).group(1)
    assert inner.count("<tr>") == 8 + 1  # every row of the run, plus its header
    assert "<th>note</th>" not in inner  # the shared note is said once, in the summary
    assert table_html(comparison(5), group_min=6).count('class="group"') == 0


def test_group_runs_and_sections():
    assert group_runs(["a", "a", "a", "b", None, None, None], 3) == [(0, 3)]
    assert group_runs(list("aabbbb"), 2) == [(0, 2), (2, 6)]
    assert section_of("Table 4, alpha=0.3, exact overshoot") == "Table 4"


def test_group_by_a_column_for_tables_without_verdicts():
    df = pd.DataFrame({"equation": ["eq 11"] * 7 + ["eq 12"] * 2, "case": range(9)})
    out = table_html(df, group_by=("equation",), group_min=6)
    assert "7 rows with equation = eq 11" in out and out.count('class="group"') == 1
    # interleaved rows of one key are brought together, in order of first appearance
    mixed = pd.DataFrame({"equation": ["b", "a", "b", "a", "b", "a"], "case": range(6)})
    out = table_html(mixed, group_by=("equation",), group_min=3)
    assert out.index("3 rows with equation = b") < out.index("3 rows with equation = a")
    assert re.findall(r"<td class=\"num\">(\d)</td>", out) == ["0", "2", "4", "1", "3", "5"]
    with pytest.raises(KeyError, match="group_by"):
        table_html(df, group_by=("nope",))


def test_equations_become_mathml_and_no_dollar_is_left():
    out = markdown_html(r"Then $e^{j\omega T}$ and $$\frac{a}{b}$$ hold; price 5 $ stays.")
    assert "<msup>" in out and "<mfrac>" in out and 'display="block"' in out
    assert "$e" not in out and "$$" not in out and "\\frac" not in out
    assert math_html(r"(1-\alpha)^{1/3}").startswith('<math display="inline">')


def test_an_equation_whose_mathml_would_show_a_backslash_is_refused():
    # a TeX control space "\\ " cut by a line break is an unknown command to latex2mathml,
    # printed as text (abglib.track's docstring had one: "\ā" in its API page)
    with pytest.raises(ValueError, match="backslash"):
        math_html("r,\\\n\\bar a = a_p")
    assert "\\" not in math_html("r,\\quad\n\\bar a = a_p")


def test_section_references_become_links_only_where_the_section_exists():
    out = link_sections(
        "<p>see section 3, sections 4 and 3, not section 9 nor §4 <code>section 3</code></p>",
        {"sec-3", "sec-4"},
    )
    assert '<a href="#sec-3">section 3</a>' in out
    assert '<a href="#sec-4">sections 4</a> and <a href="#sec-3">3</a>' in out
    assert "#sec-9" not in out and "§4 " in out  # § is the source's own section: not linked
    assert "<code>section 3</code>" in out


def _png(chunks):
    def chunk(kind, body):
        return (
            struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
        )

    ihdr = struct.pack(">IIBBBBB", 1, 1, 8, 0, 0, 0, 0)
    out = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr)
    for kind, body in chunks:
        out += chunk(kind, body)
    return out + chunk(b"IDAT", zlib.compress(b"\0\0")) + chunk(b"IEND", b"")


def test_png_description_reads_text_ztxt_and_itxt(tmp_path):
    p = tmp_path / "f.png"
    p.write_bytes(
        _png(
            [
                (b"tEXt", b"Description\0Bode plot of X/X, alpha = .3"),
                (b"zTXt", b"Comment\0\0" + zlib.compress(b"compressed words")),
                (b"iTXt", b"Title\0\0\0en\0Titel\0\xce\xb1-\xce\xb2 tracker"),
            ]
        )
    )
    assert png_description(p) == "Bode plot of X/X, alpha = .3"
    q = tmp_path / "g.png"
    q.write_bytes(
        _png(
            [
                (b"zTXt", b"Description\0\0" + zlib.compress(b"compressed words")),
                (b"iTXt", b"Title\0\0\0en\0Titel\0other"),
            ]
        )
    )
    assert png_description(q) == "compressed words"
    r = tmp_path / "h.png"
    r.write_bytes(_png([(b"iTXt", b"Description\0\0\0en\0Titel\0\xce\xb1-\xce\xb2 tracker")]))
    assert png_description(r) == "α-β tracker"
    (tmp_path / "i.png").write_bytes(_png([]))
    assert png_description(tmp_path / "i.png") == ""
    (tmp_path / "x.png").write_bytes(b"GIF89a")
    with pytest.raises(ValueError, match="not a PNG"):
        png_description(tmp_path / "x.png")


def test_png_description_reads_what_matplotlib_writes(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(1, 1))
    fig.savefig(tmp_path / "m.png", metadata={"Description": "a line", "Software": None})
    plt.close(fig)
    assert png_description(tmp_path / "m.png") == "a line"


def test_report_figure_uses_the_png_description_and_names_its_rule(tmp_path, monkeypatch):
    p = tmp_path / "fig1.png"
    p.write_bytes(_png([(b"tEXt", b"Description\0three curves")]))
    shown = []
    monkeypatch.setattr("IPython.display.display", lambda obj, **kw: shown.append(obj))
    r = Report("d", {"fig1": str(p)}, {}, {"fig1.png": ("d_figures", "workflow/scripts/d.py")})
    r.figure("fig1", "Caption with *emphasis*.")
    html = shown[0].data
    assert 'alt="three curves"' in html and 'src="figures/fig1.png"' in html
    assert "<b>Figure 1.</b> Caption with <em>emphasis</em>." in html
    assert "<code>d_figures</code>" in html and "workflow/scripts/d.py" in html
    q = tmp_path / "fig2.png"
    q.write_bytes(_png([]))
    r.figures["fig2"] = str(q)
    r.figure("fig2", "A *plain* caption")
    assert 'alt="A plain caption"' in shown[1].data and "Figure 2." in shown[1].data


def test_report_table_says_where_it_came_from(tmp_path):
    csv = tmp_path / "comparison.csv"
    comparison(0).to_csv(csv, index=False)
    r = Report(
        "d",
        {},
        {"comparison": str(csv)},
        {"comparison.csv": ("d_reproduce", "s.py")},
        install=False,
    )
    df = r.read("comparison", dtype=str, keep_default_na=False)
    out = r.table_markup(df[df["verdict"] == "mismatch"])
    assert out.startswith('<figure class="abg-table" id="tab-1">')
    assert 'href="tables/comparison.csv"' in out and "d_reproduce" in out
    assert "notebook.py" in r.table_markup(pd.DataFrame({"a": [1]}))


def test_report_links_only_the_tables_it_copies(tmp_path):
    """A table the page shows but does not copy beside it (wall-clock timings) is named by
    its place in the build, never linked: a link to it would be broken in the release."""
    for name in ("league", "engine_speed"):
        pd.DataFrame({"a": [1.0]}).to_csv(tmp_path / f"{name}.csv", index=False)
    tables = {n: str(tmp_path / f"{n}.csv") for n in ("league", "engine_speed")}
    r = Report("benchmark", {}, tables, install=False, released=["league.csv"])
    assert 'href="tables/league.csv"' in r.table_markup(r.read("league"))
    speed = r.table_markup(r.read("engine_speed"))
    assert "href=" not in speed and "engine_speed.csv</code> of the build" in speed


def _notebook():
    nb = nbformat.v4.new_notebook()
    nb.cells = [
        nbformat.v4.new_markdown_cell("# A *report*\n\nIntro with $x^2$."),
        nbformat.v4.new_code_cell("x = 1"),
        nbformat.v4.new_markdown_cell(
            "## 1. First\n\nSee section 2.\n\n## 2. Second\n\n## Provenance"
        ),
    ]
    nb.cells[1].outputs = [
        nbformat.v4.new_output(
            "display_data",
            data={"text/markdown": "Short **summary**.", "text/plain": ""},
            metadata={"abstract": True},
        ),
        nbformat.v4.new_output("display_data", data={"text/html": "<p>shown html</p>"}),
    ]
    return nb


def test_page_hides_code_numbers_sections_and_links_back():
    page = build_page(
        _notebook(),
        doc="d",
        version="9.9",
        counts={"match": 3, "mismatch": 1},
        robust=(2, 1),
        nav={"next": {"doc": "e", "title": "E's report"}},
        files={"tables": ["comparison.csv"], "figures": ["f.png"]},
        notebook="workflow/notebooks/d.py",
    )
    assert "x = 1" not in page and "In&nbsp;[" not in page and "Parameters injected" not in page
    assert "<h1><em>" not in page and "<h1>A <em>report</em></h1>" in page
    assert '<h2 id="sec-1">1. First</h2>' in page and '<a href="#sec-2">section 2</a>' in page
    assert '<a href="#provenance">Provenance</a>' in page  # in the table of contents
    assert '<meta name="description" content="Short summary.">' in page
    assert 'href="../index.html"' in page and 'href="../e/index.html"' in page
    assert 'href="tables/comparison.csv"' in page and 'href="figures/f.png"' in page
    assert 'href="../assets/report.css"' in page and "http" not in page
    assert '<span class="v v-match">3 match</span>' in page and "2 robust" in page


def test_verdict_bar_widths_are_the_counts():
    bar = verdict_bar({"match": 5, "not_reproducible": 2})
    assert 'style="flex:5"' in bar and 'style="flex:2"' in bar and "7 published" in bar
    assert 'v-mismatch" style' not in bar  # no segment for a zero count


def test_verdict_counts_of_a_comparison_table():
    counts, robust = verdict_counts(comparison(3).astype(str))
    assert counts == {"match": 1, "mismatch": 1, "explained": 0, "not_reproducible": 3}
    assert robust == (1, 1)


def test_index_page_and_headline(tmp_path):
    page = build_page(_notebook(), doc="d", version="1")
    (tmp_path / "d.html").write_text(page, encoding="utf-8")
    assert read_headline(tmp_path / "d.html") == "Short summary."
    idx = index_page(
        "1",
        [
            {
                "doc": "d",
                "title": "D",
                "href": "d/index.html",
                "headline": "Short summary.",
                "counts": {"match": 2},
                "robust": 1,
                "fragile": 0,
            }
        ],
        "<table></table>",
        "<table></table>",
    )
    assert 'href="d/index.html"' in idx and 'href="changes.html"' in idx
    assert "Short summary." in idx and 'class="vbar"' in idx and "http" not in idx


def test_assets_are_written_once_per_folder_and_load_nothing_from_the_network(tmp_path):
    names = sorted(p.name for p in write_assets(tmp_path))
    assert names == ["report.css", "report.js"]
    for p in tmp_path.iterdir():
        text = p.read_text(encoding="utf-8")
        assert "http" not in text and "@import" not in text and "url(" not in text


def test_rows_whose_notes_share_a_reason_group_and_keep_their_own_notes():
    df = pd.DataFrame(
        {
            "item": [f"Table 1, row {i}" for i in range(7)],
            "verdict": ["not_reproducible"] * 7,
            "note": [f"trajectory not published; reconstruction: {i}.0 m" for i in range(7)],
        }
    )
    out = table_html(df, group_min=6)
    assert out.count('class="group"') == 1
    assert "with notes starting: trajectory not published</summary>" in out
    assert "reconstruction: 6.0 m" in out and "<th>note</th>" in out.split("inner")[1]
    assert 'class="scroll"' in out and 'class="scroll long"' not in out
    long = table_html(pd.DataFrame({"x": range(40)}))
    assert 'class="scroll long"' in long


def test_report_page_names_neighbours_and_the_rule_behind_each_file():
    from types import SimpleNamespace

    from abglib.reporting.pipeline import report_page

    def rule(name, out, script, params=None):
        return SimpleNamespace(
            name=name,
            script=script,
            params=params,
            snakefile="/repo/workflow/rules/x.smk",
            is_producer=lambda p: p.startswith(out),
        )

    wf = SimpleNamespace(
        basedir="/repo",
        rules=[
            rule("d_report", "results/d", "../scripts/render_report.py"),
            rule("d_figures", "results/d/figures/", "../scripts/d_figures.py"),
            # a run: rule names its script in params (run_script, workflow/rules/common.smk)
            rule("d_study", "results/d/s", None, SimpleNamespace(script="workflow/scripts/s.py")),
            rule("d_reproduce", "results/d/", "../scripts/reproduce.py"),
        ],
    )
    files = SimpleNamespace(
        figures=["results/d/figures/f.png"],
        tables=["results/d/s/study.csv", "results/d/comparison.csv"],
    )
    page = report_page(wf, ["c", "d", "e"], {"c": "C", "e": "E"}, "d", files)
    assert page["nav"] == {"prev": {"doc": "c", "title": "C"}, "next": {"doc": "e", "title": "E"}}
    assert page["made_by"] == {
        "f.png": ("d_figures", "workflow/scripts/d_figures.py"),
        "comparison.csv": ("d_reproduce", "workflow/scripts/reproduce.py"),
        "study.csv": ("d_study", "workflow/scripts/s.py"),
    }
    assert report_page(wf, ["d"], {}, "d", files)["nav"] == {}


def test_and_list_writes_a_list_into_a_sentence():
    from abglib.reporting.notebook import and_list

    assert and_list(["eq 25", "eq 26", "eq 31"]) == "eq 25, eq 26 and eq 31"
    assert and_list(("X", "Y")) == "X and Y"
    assert and_list(["X"]) == "X" and and_list([]) == ""
    assert and_list([1, 2]) == "1 and 2"
