"""The one figure style, its colours, legend placement, alt text and PNG saving.

matplotlib is imported only here and by the figure modules (of the benchmark, of each
document); the style sits in :mod:`abglib.common`, below every layer that draws.
Computing and plotting are separate (python-control style): the workflow computes a table,
a figure function draws it. Every figure function

- runs under :data:`STYLE` (decorate it with :func:`styled`): one font, one set of sizes
  and line widths, constrained layout (no blank bands, nothing cut off);
- colours a curve by its variant family or gain-design rule (:func:`family_colour`), the
  same colour in every document and in the benchmark;
- puts its legends outside the data area (:func:`legend_outside`), or in a corner that
  :func:`legend_overlaps` finds empty;
- attaches an alt text saying what the figure shows (:func:`describe`), computed from its
  data where natural.

:func:`save_figure` writes the PNG (deterministic, no software version or timestamp,
atomically) with the alt text in its ``Description`` text chunk; :func:`png_description`
reads it back with the standard library only.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Iterable

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
from matplotlib.colors import to_rgb  # noqa: E402
from matplotlib.ticker import Locator, LogLocator  # noqa: E402
from matplotlib.transforms import Bbox  # noqa: E402

from .._compat.matplotlib import axes_titles  # noqa: E402
from .pngmeta import png_description  # noqa: E402  (re-exported)

__all__ = [
    "DPI",
    "FAMILY_COLOURS",
    "REFERENCE",
    "STYLE",
    "WIDTH",
    "cut_off",
    "describe",
    "description",
    "family_colour",
    "frequency_response_figure",
    "layout_problems",
    "legend_outside",
    "legend_overlaps",
    "png_description",
    "save_figure",
    "shades",
    "styled",
    "suptitle",
    "text_overlaps",
    "tint",
]

#: width of a full-width figure (inches) and the resolution it is saved at: 7 in x 100 dpi
#: = 700 px, the width of a report's text column, so a figure is shown at its own size
WIDTH = 7.0
DPI = 100

#: colours of things that are not a tracker: the truth, measurements, reference levels
REFERENCE = {"truth": "black", "measured": "0.6", "level": "0.45", "zero": "0.2"}

#: one colour per variant family / gain-design rule, used in every document and the
#: benchmark (tab10 first, then darker colours for the rules that need their own)
FAMILY_COLOURS = {
    "standard α-β-γ": "#1f77b4",
    "standard α-β": "#ff7f0e",
    "QD α-β-γ": "#2ca02c",
    "Benedict-Bordner α-β": "#d62728",  # = Al-Wagih's M1 (seed 001, eq 23b)
    "Simpson α-β-γ": "#9467bd",
    "Kalata α-β": "#8c564b",
    "Kalata α-β-γ": "#e377c2",
    "Kalman": "#4d4d4d",  # steady-state Kalman filters (DARE), any model order
    "Huang type I α-β": "#bcbd22",
    "Huang type I α-β-γ": "#556b2f",
    "Huang type II α-β": "#17becf",
    "Huang type II α-β-γ": "#b03060",
    "Bendix α-β": "#00008b",
    "growing memory α-β": "#b8860b",  # = Al-Wagih's M2 (seed 001, eqs 24a-b)
    "Al-Wagih M3": "#1b9e77",
    "Al-Wagih M4": "#e7298a",
    "Al-Wagih M5": "#6a3d9a",
}

# (pattern on the lower-cased name, family): first match wins; names are benchmark
# family labels, variant and rule names, the documents' curve labels
_ALIASES = [
    (r"(huang.*(type ?ii|type2|t2)|huang2).*(α-β-γ|abg|order=3)", "Huang type II α-β-γ"),
    (r"huang.*(type ?ii|type2|t2)|huang2", "Huang type II α-β"),
    (r"huang.*(α-β-γ|abg|order=3)", "Huang type I α-β-γ"),
    (r"huang", "Huang type I α-β"),
    (r"\bqd\b|^qd_", "QD α-β-γ"),
    (r"benedict|^bb_|\bm1\b|_m1\b", "Benedict-Bordner α-β"),
    (r"growing|\bm2\b|_m2\b", "growing memory α-β"),
    (r"\bm3\b|_m3\b", "Al-Wagih M3"),
    (r"\bm4\b|_m4\b", "Al-Wagih M4"),
    (r"(\b|_)m5", "Al-Wagih M5"),
    (r"simpson", "Simpson α-β-γ"),
    (r"kalata.*(α-β-γ|abg)", "Kalata α-β-γ"),
    (r"kalata", "Kalata α-β"),
    (r"kalman|dare", "Kalman"),
    (r"bendix", "Bendix α-β"),
    (r"(standard|std|critically damped).*(α-β-γ|abg)", "standard α-β-γ"),
    (r"standard|std_ab|critically damped", "standard α-β"),
]

# colours for names outside the table (a family added to the config), in order
_SPARE = ["#66a61e", "#a6761d", "#e6ab02", "#7570b3", "#d95f02", "#666666"]

#: the style every figure function runs under (a fixed style, so that a rebuild draws
#: identical pixels whatever the user's matplotlibrc)
STYLE = {
    "figure.figsize": (WIDTH, 4.4),
    "figure.dpi": DPI,
    "savefig.dpi": DPI,
    "figure.facecolor": "white",
    "savefig.facecolor": "white",
    "figure.constrained_layout.use": True,
    "figure.constrained_layout.h_pad": 0.04,
    "figure.constrained_layout.w_pad": 0.04,
    "font.family": "DejaVu Sans",
    "font.size": 9,
    "axes.titlesize": 9,
    "axes.labelsize": 9,
    "figure.titlesize": 10,
    "figure.labelsize": 9,
    "xtick.labelsize": 8,
    "ytick.labelsize": 8,
    "legend.fontsize": 8,
    "legend.title_fontsize": 8,
    "legend.frameon": False,
    "legend.handlelength": 2.2,
    "axes.grid": True,
    "grid.alpha": 0.35,
    "grid.linewidth": 0.6,
    "axes.linewidth": 0.8,
    "axes.spines.top": False,
    "axes.spines.right": False,
    "axes.prop_cycle": matplotlib.cycler(color=list(FAMILY_COLOURS.values())[:10]),
    "lines.linewidth": 1.4,
    "lines.markersize": 4.0,
    "image.cmap": "viridis",
    "svg.hashsalt": "abglib",
}


def styled(func):
    """Decorator: run a figure function under :data:`STYLE`."""

    @functools.wraps(func)
    def wrapper(*args, **kwargs):
        with plt.rc_context(STYLE):
            return func(*args, **kwargs)

    return wrapper


def family_colour(name: str, _spare: dict = {}) -> str:  # noqa: B006 (a deliberate memo)
    """The colour of a variant family or gain-design rule, whatever it is called.

    ``name`` may be a benchmark family (``'standard α-β-γ'``, ``'Kalata α-β'``), a variant
    or rule name (``'std_abg_a0.3'``, ``'kalata_ab'``, ``'M5'``) or a curve label of a
    document (``'X̄/X, QD, α=0.3'``). A name outside :data:`FAMILY_COLOURS` gets a spare
    colour, the same one for the same name in one process.
    """
    if name in FAMILY_COLOURS:
        return FAMILY_COLOURS[name]
    key = str(name).lower().replace("alpha-beta-gamma", "α-β-γ").replace("alpha-beta", "α-β")
    for pattern, family in _ALIASES:
        if re.search(pattern, key):
            return FAMILY_COLOURS[family]
    if name not in _spare:
        _spare[name] = _SPARE[len(_spare) % len(_SPARE)]
    return _spare[name]


def shades(colour, n: int) -> list:
    """``n`` shades of ``colour``, dark to light, for curves of one family told apart by
    a parameter (with line styles, so that they stay apart in grey print too)."""
    if n < 1:
        raise ValueError(f"n must be >= 1, got {n!r}")
    rgb = np.asarray(to_rgb(colour))
    if n == 1:
        return [tuple(rgb)]
    out = []
    for f in np.linspace(-0.55, 0.25, n):  # <0: towards black, >0: towards white
        c = rgb * (1 + f) if f < 0 else rgb + (1 - rgb) * f
        out.append(tuple(np.clip(c, 0, 1)))
    return out


def tint(colour, f: float) -> tuple:
    """``colour`` mixed with white by ``f`` (0 = the colour, 1 = white)."""
    if not 0.0 <= f <= 1.0:
        raise ValueError(f"f must satisfy 0 <= f <= 1, got {f!r}")
    rgb = np.asarray(to_rgb(colour))
    return tuple(rgb + (1.0 - rgb) * f)


LINESTYLES = ["-", "--", "-.", ":", (0, (5, 1, 1, 1, 1, 1))]


def suptitle(fig, text: str, **kwargs):
    """The figure's title, wrapped to the figure's width (constrained layout does not wrap)."""
    import textwrap

    text = " ".join(text.split())
    chars = int(fig.bbox.width / (0.53 * plt.rcParams["figure.titlesize"] * fig.dpi / 72))
    title = fig.suptitle(textwrap.fill(text, chars), **kwargs)
    renderer = fig.canvas.get_renderer()
    while chars > 20 and title.get_window_extent(renderer).width > 0.98 * fig.bbox.width:
        chars = int(chars * 0.92)  # wide letters (capitals): wrap shorter
        title.set_text(textwrap.fill(text, chars))
    return title


# ------------------------------------------------------------------ legends, overlaps


def legend_outside(where, handles=None, labels=None, side: str = "right", ncol: int = 1, **kwargs):
    """A legend outside the data area of ``where`` (an Axes or a Figure).

    ``side``: ``'right'`` (beside the axes, top-aligned), ``'top'`` (above the axes or, for
    a figure, under its title) or ``'bottom'`` (a figure: under everything). Constrained
    layout makes room for it.
    """
    if side not in ("right", "top", "bottom"):
        raise ValueError(f"side must be one of ['right', 'top', 'bottom'], got {side!r}")
    if handles is None:
        axes = [where] if hasattr(where, "transData") else where.axes
        seen = {}
        for ax in axes:
            for h, lab in zip(*ax.get_legend_handles_labels(), strict=True):
                seen.setdefault(lab, h)
        labels, handles = list(seen), list(seen.values())
    if hasattr(where, "transData"):  # an Axes
        loc, anchor = {
            "right": ("upper left", (1.02, 1.0)),
            "top": ("lower left", (0.0, 1.02)),
            "bottom": ("upper left", (0.0, -0.18)),
        }[side]
        return where.legend(
            handles, labels, loc=loc, bbox_to_anchor=anchor, ncol=ncol, borderaxespad=0.0, **kwargs
        )
    if side == "top":  # above the first axes: a figure legend would run into the title
        return legend_outside(where.axes[0], handles, labels, "top", ncol, **kwargs)
    loc = {"right": "outside right upper", "bottom": "outside lower center"}[side]
    return where.legend(handles, labels, loc=loc, ncol=ncol, **kwargs)


def _legends(fig) -> list:
    out = list(fig.legends)
    for sub in getattr(fig, "subfigs", []):
        out += _legends(sub)
    for ax in fig.axes:
        if ax.get_legend() is not None:
            out.append(ax.get_legend())
    return out


def _data_extents(ax, renderer) -> Iterable:
    """(label, kind, display-space object) of each visible data artist of ``ax``."""
    for line in ax.get_lines():
        if not line.get_visible():
            continue
        path = line.get_transform().transform_path(line.get_path())
        yield line.get_label(), "line", (path, line.get_linestyle() not in ("None", ""))
    for coll in ax.collections:
        if not coll.get_visible():
            continue
        for p in coll.get_paths():
            yield coll.get_label(), "area", coll.get_transform().transform_path(p)
        offs = coll.get_offsets()
        if len(offs) and coll.get_offset_transform() is not None:
            pts = coll.get_offset_transform().transform(offs)
            yield coll.get_label(), "points", pts
    owner = {id(p): c.get_label() for c in ax.containers for p in c if p is not None}
    for patch in ax.patches:
        if patch.get_visible():
            label = owner.get(id(patch), patch.get_label())
            yield label, "box", patch.get_window_extent(renderer)
    for img in ax.images:
        yield "image", "box", img.get_window_extent(renderer)
    for text in ax.texts:
        if text.get_visible() and text.get_text():
            yield text.get_text(), "box", text.get_window_extent(renderer)


def _hits(kind, obj, box: Bbox) -> bool:
    if kind == "line":
        path, joined = obj
        v = path.vertices
        v = v[np.all(np.isfinite(v), axis=1)]
        if v.size and np.any(
            (v[:, 0] >= box.x0) & (v[:, 0] <= box.x1) & (v[:, 1] >= box.y0) & (v[:, 1] <= box.y1)
        ):
            return True
        if not joined or len(v) < 2:
            return False
        from matplotlib.path import Path as MPath

        return MPath(v).intersects_bbox(box, filled=False)
    if kind == "area":
        return len(obj.vertices) > 1 and obj.intersects_bbox(box, filled=True)
    if kind == "points":
        v = obj[np.all(np.isfinite(obj), axis=1)]
        return bool(
            np.any(
                (v[:, 0] >= box.x0)
                & (v[:, 0] <= box.x1)
                & (v[:, 1] >= box.y0)
                & (v[:, 1] <= box.y1)
            )
        )
    return box.overlaps(obj) and obj.width > 0 and obj.height > 0


def legend_overlaps(fig, redraw: bool = True) -> list:
    """Every (legend entry, data artist) pair of ``fig`` whose ink meets: a legend drawn
    over a curve, a marker, a bar, an image or a text of any axes. Only the part of the
    legend inside an axes counts (artists are clipped to their axes). Empty = clean."""
    if redraw:  # False: the caller has drawn the figure since its last change
        fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    found = []
    for leg in _legends(fig):
        lbox = leg.get_window_extent(renderer)
        name = ", ".join(t.get_text() for t in leg.get_texts())[:60]
        for ax in fig.axes:
            inner = Bbox.intersection(lbox, ax.bbox)
            if inner is None or inner.width <= 0 or inner.height <= 0:
                continue
            for label, kind, obj in _data_extents(ax, renderer):
                if _hits(kind, obj, inner):
                    found.append((name, str(label)))
    return found


def text_overlaps(fig, redraw: bool = True) -> list:
    """Every pair of texts drawn into the axes of ``fig`` (annotations, labels of points)
    whose boxes overlap, as ``(text, text)``; and texts that spill over an axes' edge."""
    if redraw:  # False: the caller has drawn the figure since its last change
        fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    found = []
    for ax in fig.axes:
        texts = [t for t in ax.texts if t.get_visible() and t.get_text()]
        boxes = [t.get_window_extent(renderer) for t in texts]
        for i in range(len(texts)):
            for j in range(i + 1, len(texts)):
                if boxes[i].overlaps(boxes[j]):
                    found.append((texts[i].get_text(), texts[j].get_text()))
    return found


def cut_off(fig, redraw: bool = True) -> list:
    """Legends, titles and texts of ``fig`` that reach beyond the figure's edge (constrained
    layout cannot shrink a legend that is wider than the figure), by their text."""
    if redraw:  # False: the caller has drawn the figure since its last change
        fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    box = fig.bbox.padded(1.0)
    found = []
    texts = []
    for leg in _legends(fig):
        texts += leg.get_texts()
    figs = [fig, *getattr(fig, "subfigs", [])]
    for f in figs:
        texts += list(f.texts)  # a suptitle is one of them (Figure.suptitle adds it there)
    for ax in fig.axes:
        texts += [*axes_titles(ax), ax.xaxis.label, ax.yaxis.label]
        texts += [t for t in ax.texts if not t.get_clip_on()]
    for t in texts:
        if t is None or not t.get_visible() or not t.get_text():
            continue
        b = t.get_window_extent(renderer)
        if b.x0 < box.x0 or b.x1 > box.x1 or b.y0 < box.y0 or b.y1 > box.y1:
            found.append(t.get_text()[:60])
    return found


def layout_problems(fig, redraw: bool = True) -> list[str]:
    """What a reader would trip over in ``fig``: :func:`legend_overlaps` ("legend over
    data"), :func:`text_overlaps` ("labels over each other") and :func:`cut_off` ("cut off
    at the edge"), one message per check that found anything (its first three finds).
    Empty = clean. :func:`save_figure` returns them for the drawing it saves."""
    if redraw:  # False: the caller has drawn the figure since its last change
        fig.canvas.draw()
    checks = (
        ("legend over data", legend_overlaps),
        ("labels over each other", text_overlaps),
        ("cut off at the edge", cut_off),
    )
    return [f"{what}: {found[:3]}" for what, check in checks if (found := check(fig, False))]


# ------------------------------------------------------------------ alt text and saving


def describe(fig, alt: str):
    """Attach the alt text ``alt`` (what the figure shows) to ``fig``; returns ``fig``."""
    alt = " ".join(str(alt).split()).lstrip(". ")  # '. Two panels' when there is no title
    if not alt:
        raise ValueError("an alt text must say what the figure shows, got an empty one")
    fig._abglib_alt = alt
    return fig


def description(fig) -> str:
    """The alt text attached to ``fig`` by :func:`describe` ('' if none)."""
    return getattr(fig, "_abglib_alt", "")


class _InView(Locator):
    """A log axis's tick locator that keeps only the ticks inside the view.

    matplotlib's :class:`~matplotlib.ticker.LogLocator` returns the ticks of a decade or
    more beyond each end of the view; the axis makes a tick (two lines, a grid line and
    two labels) for each of them and lays all of them out several times a draw
    (constrained layout, label and title placement), then draws only those inside. A
    log axis's labels are formatted one tick at a time, so dropping the ticks outside
    changes no pixel; it halves the ticks a log panel makes and updates.
    """

    def __init__(self, base: LogLocator):
        self.base = base

    def set_axis(self, axis):
        super().set_axis(axis)
        self.base.set_axis(axis)

    def __call__(self):
        locs = np.asarray(self.base())
        if locs.size == 0:
            return locs
        scale = self.axis.get_transform()
        lo, hi = sorted(scale.transform(np.asarray(self.axis.get_view_interval(), float)))
        t = scale.transform(locs)
        eps = 1e-10 * (hi - lo)  # the axis's own test of a tick being in view
        return locs[(t >= lo - eps) & (t <= hi + eps)]

    def tick_values(self, vmin, vmax):
        return self.base.tick_values(vmin, vmax)

    def nonsingular(self, v0, v1):
        return self.base.nonsingular(v0, v1)

    def view_limits(self, vmin, vmax):
        return self.base.view_limits(vmin, vmax)


def _log_ticks_in_view(fig) -> None:
    """Wrap the default locators of every log axis of ``fig`` in :class:`_InView`."""
    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            if axis.get_scale() != "log":
                continue
            if type(axis.get_major_locator()) is LogLocator:
                axis.set_major_locator(_InView(axis.get_major_locator()))
            if type(axis.get_minor_locator()) is LogLocator:
                axis.set_minor_locator(_InView(axis.get_minor_locator()))


def save_figure(fig, path, alt: str | None = None, *, dpi: int = DPI) -> list[str]:
    """Save ``fig`` as a deterministic PNG at ``path`` (temp file, then ``os.replace``).

    The alt text (``alt``, else the one attached by :func:`describe`) is stored in the
    PNG's ``Description`` text chunk (``tEXt``; ``iTXt`` when it has characters outside
    Latin-1, such as α); no software version or timestamp is written. The image is
    reduced to a 256-colour palette without dithering (a line figure has few colours:
    the PNG is about three times smaller and looks the same). Raises ``ValueError`` if
    there is no alt text. Returns the :func:`layout_problems` of the drawing saved (empty
    when the figure is clean), checked on that same drawing (the checks cost about 1 % of
    the drawing: a test need not draw the figure again to check it).

    The figure is drawn once, on an Agg canvas at ``dpi``, and its pixels go straight to
    Pillow: ``fig.savefig`` would draw it twice (a layout pass, then the drawing: with
    constrained layout every tick and label is laid out in both) and encode a PNG that
    is decoded again here. The pixels are the same (the canvas's draw runs the layout
    engine, then draws). Log axes make ticks only inside their view (:class:`_InView`,
    same pixels). The PNG is compressed at zlib's default level 6: level 9 (Pillow's
    ``optimize``) took seven times as long for 9 % smaller files.
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from PIL import Image, PngImagePlugin

    from .files import atomic_output

    try:
        if alt is not None and not isinstance(alt, str):
            raise TypeError(f"alt must be a str (what the figure shows), got {alt!r}")
        alt = " ".join((alt or description(fig)).split())
        if not alt:
            raise ValueError(
                f"save_figure({str(path)!r}): no alt text; pass alt= or describe(fig, ...)"
            )
        if not isinstance(dpi, int | float) or not 20 <= dpi <= 600:
            raise ValueError(f"dpi must be a number in [20, 600], got {dpi!r}")
        canvas = fig.canvas if isinstance(fig.canvas, FigureCanvasAgg) else FigureCanvasAgg(fig)
        _log_ticks_in_view(fig)
        old_dpi = fig.dpi
        fig.dpi = dpi
        try:
            canvas.draw()
            img = Image.fromarray(np.asarray(canvas.buffer_rgba())).convert("RGB")
            problems = layout_problems(fig, redraw=False)
        finally:
            fig.dpi = old_dpi
        img = img.quantize(colors=256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
        info = PngImagePlugin.PngInfo()
        info.add_text("Description", alt)  # Pillow writes iTXt if not Latin-1
        with atomic_output(path) as tmp:
            img.save(tmp, format="png", pnginfo=info, compress_level=6)
    finally:
        plt.close(fig)
    return problems


def _fmt(x: float) -> str:
    return f"{x:.3g}"


@styled
def frequency_response_figure(data: pd.DataFrame, axes: str, title: str = ""):
    """Magnitude (top) and phase (bottom) of one or more frequency responses.

    Parameters
    ----------
    data : DataFrame
        Long table with columns ``curve`` (legend label), ``wT`` (rad/sample),
        ``magnitude`` (linear) and ``phase_deg`` (unwrapped), in plotting order; with a
        ``design`` column, curves are coloured by design family (:func:`family_colour`)
        and told apart within a family by shade and line style.
    axes : {'linear', 'bode'}
        ``'linear'``: linear magnitude and omega*T axes (seed 000, Fig. 1);
        ``'bode'``: magnitude in dB against log omega*T (seed 000, Figs. 2-6).
    title : str
        Figure title (the caption of the source figure).

    Returns
    -------
    matplotlib.figure.Figure
        With an alt text naming each curve's peak and the ωT where it falls.
    """
    if axes not in ("linear", "bode"):
        raise ValueError(f"axes must be one of ['linear', 'bode'], got {axes!r}")
    groups = list(data.groupby("curve", sort=False))
    design = [str(d["design"].iloc[0]) if "design" in d else lab for lab, d in groups]
    families = list(dict.fromkeys(design))
    per_family = {f: [i for i, d in enumerate(design) if d == f] for f in families}
    colour, style = {}, {}
    for f, idx in per_family.items():
        name = {"standard_abg": "standard α-β-γ", "standard_ab": "standard α-β", "qd": "QD"}
        base = family_colour(name.get(f, f))
        for k, (i, c) in enumerate(zip(idx, shades(base, len(idx)), strict=True)):
            colour[i], style[i] = c, LINESTYLES[k % len(LINESTYLES)]
    fig, (ax_mag, ax_ph) = plt.subplots(2, 1, sharex=True, figsize=(WIDTH, 5.6))
    peaks = []
    for i, (label, d) in enumerate(groups):
        wt = d["wT"].to_numpy()
        mag = d["magnitude"].to_numpy()
        y = 20.0 * np.log10(mag) if axes == "bode" else mag
        kw = dict(color=colour[i], ls=style[i], label=label)
        if axes == "bode":
            ax_mag.semilogx(wt, y, **kw)
            ax_ph.semilogx(wt, d["phase_deg"], **kw)
        else:
            ax_mag.plot(wt, y, **kw)
            ax_ph.plot(wt, d["phase_deg"], **kw)
        k = int(np.nanargmax(mag))
        unit = " dB" if axes == "bode" else ""
        peaks.append(f"{label}: peak {_fmt(y[k])}{unit} at ωT = {_fmt(wt[k])}")
    if axes == "bode":
        ax_mag.set_ylabel("magnitude (dB)")
        ax_mag.axhline(-3.0, color=REFERENCE["level"], lw=0.8, ls="--", label="−3 dB")
    else:
        ax_mag.set_ylabel("magnitude")
        ax_mag.axhline(2.0**-0.5, color=REFERENCE["level"], lw=0.8, ls="--", label="1/√2 (−3 dB)")
    ax_ph.set_ylabel("phase (degrees)")
    ax_ph.set_xlabel("ωT (radians per sample)")
    if title:
        suptitle(fig, title)
    legend_outside(fig, *_handles(ax_mag), side="top", ncol=2)
    scale = "log" if axes == "bode" else "linear"
    describe(
        fig,
        f"{title}. Two panels against ωT on a {scale} axis from {_fmt(data['wT'].min())} to "
        f"{_fmt(data['wT'].max())} rad/sample: magnitude"
        f"{' in dB' if axes == 'bode' else ''} (top) and phase in degrees (bottom) of "
        f"{len(groups)} curves. " + "; ".join(peaks) + ".",
    )
    return fig


def _handles(ax):
    h, lab = ax.get_legend_handles_labels()
    return h, lab


# ----------------------------------------------------------- FAA Bendix report (seed 003)
