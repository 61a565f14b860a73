"""The figure style's machinery: alt text in the PNG, the overlap checks, the colours."""

from __future__ import annotations

import numpy as np
import pytest

from abglib.common import plotting as P
from abglib.common.plotting import (
    FAMILY_COLOURS,
    cut_off,
    describe,
    family_colour,
    layout_problems,
    legend_outside,
    legend_overlaps,
    plt,
    png_description,
    save_figure,
    styled,
    text_overlaps,
)


@styled
def _line_figure(legend: str = "outside"):
    fig, ax = plt.subplots()
    x = np.linspace(0.0, 1.0, 200)
    ax.plot(x, x, label="diagonal")
    ax.plot(x, 1 - x, label="anti-diagonal")
    if legend == "centre":  # the centre is where the two lines cross: over the data
        ax.legend(loc="center")
    else:
        legend_outside(ax, side="right")
    return fig


def test_alt_text_round_trips_through_the_png_in_latin1_and_unicode(tmp_path):
    for alt, chunk in (("peak of 1.8 at wT = 0.9", b"tEXt"), ("peak of 1.8 at ωT = 0.9", b"iTXt")):
        path = tmp_path / "f.png"
        save_figure(_line_figure(), path, alt=alt)
        assert png_description(path) == alt
        data = path.read_bytes()
        assert chunk + b"Description" in data
        assert b"Software" not in data and b"matplotlib" not in data


def test_alt_text_attached_by_describe_is_used_and_whitespace_folded(tmp_path):
    fig = describe(_line_figure(), "two lines\n   crossing at (0.5, 0.5)")
    save_figure(fig, tmp_path / "f.png")
    assert png_description(tmp_path / "f.png") == "two lines crossing at (0.5, 0.5)"


def test_a_figure_without_alt_text_is_refused_and_nothing_is_written(tmp_path):
    with pytest.raises(ValueError, match="no alt text"):
        save_figure(_line_figure(), tmp_path / "f.png")
    assert not (tmp_path / "f.png").exists()
    with pytest.raises(ValueError, match="empty"):
        describe(_line_figure(), "   ")


def test_alt_must_be_text_and_dpi_a_keyword(tmp_path):
    with pytest.raises(TypeError, match="alt must be a str"):
        save_figure(_line_figure(), tmp_path / "f.png", 100)
    assert not (tmp_path / "f.png").exists()


def test_bad_dpi_is_refused_naming_the_range(tmp_path):
    with pytest.raises(ValueError, match=r"dpi must be a number in \[20, 600\], got 5000"):
        save_figure(_line_figure(), tmp_path / "f.png", alt="x", dpi=5000)


def test_png_is_deterministic_and_a_palette_image(tmp_path):
    from PIL import Image

    a, b = tmp_path / "a.png", tmp_path / "b.png"
    save_figure(_line_figure(), a, alt="two lines")
    save_figure(_line_figure(), b, alt="two lines")
    assert a.read_bytes() == b.read_bytes()
    with Image.open(a) as im:
        assert im.mode == "P"
        assert im.size == (round(P.WIDTH * P.DPI), round(4.4 * P.DPI))


@styled
def _loglog_figure():
    fig, axes = plt.subplots(1, 2, sharey=True)
    x = np.logspace(-2, 1, 40)
    axes[0].loglog(x, x**2, ".-", label="x²")
    axes[1].loglog(x, 1 + 0 * x, label="1")  # less than a decade: minor labels, no major
    axes[1].set_ylim(0.5, 2.0)
    return describe(fig, "two log-log panels")


def _savefig_pixels(fig, dpi):
    """matplotlib's own savefig of ``fig``, reduced to the palette as save_figure does."""
    import io

    from PIL import Image

    buf = io.BytesIO()
    fig.savefig(buf, dpi=dpi, format="png")
    buf.seek(0)
    img = Image.open(buf).convert("RGB")
    img = img.quantize(colors=256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
    return np.asarray(img.convert("RGB"))


@pytest.mark.parametrize("make", [_line_figure, _loglog_figure])
@pytest.mark.parametrize("dpi", [100, 72])
def test_save_figure_draws_the_pixels_of_matplotlibs_savefig(tmp_path, make, dpi):
    from PIL import Image

    save_figure(make(), tmp_path / "f.png", alt="x", dpi=dpi)
    got = np.asarray(Image.open(tmp_path / "f.png").convert("RGB"))
    ref = _savefig_pixels(make(), dpi)
    assert got.shape == ref.shape == (int(4.4 * dpi), int(P.WIDTH * dpi), 3)  # truncated
    assert np.array_equal(got, ref)


def test_log_axes_make_ticks_only_inside_their_view(tmp_path):
    ref = _loglog_figure()
    ref.canvas.draw()
    fig = _loglog_figure()
    save_figure(fig, tmp_path / "f.png")
    for ax, ax_ref in zip(fig.axes, ref.axes, strict=True):
        for axis, axis_ref in ((ax.xaxis, ax_ref.xaxis), (ax.yaxis, ax_ref.yaxis)):
            lo, hi = sorted(axis.get_view_interval())
            for which in ("major", "minor"):
                locs = axis.get_ticklocs(minor=which == "minor")
                assert np.all((locs >= lo * (1 - 1e-9)) & (locs <= hi * (1 + 1e-9)))
                full = axis_ref.get_ticklocs(minor=which == "minor")
                inside = full[(full >= lo * (1 - 1e-9)) & (full <= hi * (1 + 1e-9))]
                np.testing.assert_array_equal(locs, inside)
    # the default locators return ticks beyond the view; the trimmed axis made fewer
    assert len(ref.axes[0].xaxis.minorTicks) > len(fig.axes[0].xaxis.minorTicks) > 0
    assert [t.get_text() for t in fig.axes[1].yaxis.get_ticklabels(minor=True)] == [
        t.get_text()
        for t in ref.axes[1].yaxis.get_ticklabels(minor=True)
        if 0.5 <= t.get_position()[1] <= 2.0
    ]
    plt.close(ref)


def test_png_description_of_a_png_without_one_and_of_a_non_png(tmp_path):
    from PIL import Image

    Image.new("RGB", (4, 4)).save(tmp_path / "plain.png")
    assert png_description(tmp_path / "plain.png") == ""
    (tmp_path / "x.png").write_bytes(b"GIF89a")
    with pytest.raises(ValueError, match="not a PNG"):
        png_description(tmp_path / "x.png")


def test_legend_over_data_is_found_and_a_legend_outside_is_clean():
    bad = _line_figure("centre")
    found = legend_overlaps(bad)
    assert {label for _, label in found} == {"diagonal", "anti-diagonal"}
    assert legend_overlaps(_line_figure()) == []
    plt.close("all")


def test_legend_over_bars_and_markers_is_found():
    @styled
    def fig_():
        fig, ax = plt.subplots()
        ax.bar([0, 1, 2], [3, 3, 3], label="bars")
        ax.plot([2.0], [2.9], "o", label="dot")
        ax.legend(loc="upper right")
        return fig

    assert {label for _, label in legend_overlaps(fig_())} >= {"bars"}
    plt.close("all")


def test_overlapping_labels_and_a_legend_wider_than_the_figure_are_found():
    @styled
    def fig_():
        fig, ax = plt.subplots(figsize=(3, 2))
        ax.plot([0, 1], [0, 1])
        ax.annotate("std_ab_a0.3", (0.5, 0.5))
        ax.annotate("std_abg_a0.3", (0.52, 0.51))
        legend_outside(
            fig, [plt.Line2D([], [])] * 3, ["a very long legend entry"] * 3, side="bottom", ncol=3
        )
        return fig

    fig = fig_()
    assert text_overlaps(fig) == [("std_ab_a0.3", "std_abg_a0.3")]
    cut = cut_off(fig)  # the first and last entries run over the edges
    assert len(cut) >= 2 and set(cut) == {"a very long legend entry"}
    plt.close("all")


def test_save_figure_returns_the_layout_problems_of_the_drawing_it_saved(tmp_path):
    """One drawing serves the PNG and the checks: the problems save_figure returns are
    those of the figure drawn apart (layout_problems), one message per check that found
    anything, and a clean figure returns none."""

    @styled
    def crowded():
        fig, ax = plt.subplots(figsize=(3, 2))
        x = np.linspace(0.0, 1.0, 50)
        ax.plot(x, x, label="diagonal")
        ax.legend(loc="center")
        ax.annotate("std_ab_a0.3", (0.5, 0.5))
        ax.annotate("std_abg_a0.3", (0.52, 0.51))
        return describe(fig, "a diagonal under its legend and two labels over each other")

    apart = layout_problems(crowded())
    assert [m.split(":")[0] for m in apart] == ["legend over data", "labels over each other"]
    assert save_figure(crowded(), tmp_path / "crowded.png") == apart
    clean = describe(_line_figure(), "two crossing lines, the legend outside on the right")
    assert save_figure(clean, tmp_path / "clean.png") == []
    plt.close("all")


@pytest.mark.parametrize(
    "names, family",
    [
        (
            ["standard (critically damped) α-β-γ", "std_abg_a0.3", "X̄/X, standard α-β-γ, α=0.3"],
            "standard α-β-γ",
        ),
        (
            ["standard (critically damped) α-β", "std_ab_a0.3", "critically damped α-β"],
            "standard α-β",
        ),
        (["QD α-β-γ", "qd_m21"], "QD α-β-γ"),
        (["M1", "bb_a0.5", "Benedict-Bordner α-β", "alwagih_M1"], "Benedict-Bordner α-β"),
        (["M2", "growing_memory", "alwagih_M2"], "growing memory α-β"),
        (["M5", "alwagih_M5"], "Al-Wagih M5"),
        (["Kalata α-β", "kalata_ab_L1", "Kalman (Kalata index) α-β", "kalata_ab"], "Kalata α-β"),
        (["Kalata α-β-γ", "kalata_abg_L0.1"], "Kalata α-β-γ"),
        (["Kalman (DARE) α-β", "kalman_ab_q1_r100", "kalman_ss"], "Kalman"),
        (["Huang type I α-β (ENBW)", "huang1_ab_0.1Hz"], "Huang type I α-β"),
        (["Huang type II α-β-γ", "huang2_abg_0.1Hz"], "Huang type II α-β-γ"),
        (["Bendix α-β", "bendix_T3"], "Bendix α-β"),
        (["Simpson α-β-γ (γ = 0.01)", "simpson_a0.5_g0.05"], "Simpson α-β-γ"),
    ],
)
def test_a_family_has_one_colour_under_all_its_names(names, family):
    assert {family_colour(n) for n in names} == {FAMILY_COLOURS[family]}


def test_family_colours_are_distinct_and_an_unknown_family_gets_a_stable_spare():
    assert len(set(FAMILY_COLOURS.values())) == len(FAMILY_COLOURS)
    spare = family_colour("a family added to the config")
    assert spare not in FAMILY_COLOURS.values()
    assert family_colour("a family added to the config") == spare


def test_shades_and_tint_check_their_arguments():
    assert len(P.shades("C0", 4)) == 4
    with pytest.raises(ValueError, match="n must be >= 1, got 0"):
        P.shades("C0", 0)
    with pytest.raises(ValueError, match="f must satisfy 0 <= f <= 1, got 2"):
        P.tint("C0", 2)
    with pytest.raises(ValueError, match="side must be one of"):
        legend_outside(_line_figure(), side="left")
    plt.close("all")
