"""matplotlib: the title artists of an Axes, through public API, checked.

For matplotlib's maintainers, what abglib needs and which public API would replace it:
:func:`abglib.common.plotting.cut_off` checks that no title, label or legend of a
figure reaches beyond its edge, so it needs the ``Text`` artists of an Axes' three
titles (center, left, right). ``Axes.title`` is the center one; the left and right ones
are only the private ``Axes._left_title`` and ``Axes._right_title``, and
``Axes.get_title(loc)`` returns their text, not the artist. :func:`axes_titles` finds
them among ``Axes.get_children()`` (public: the Text children that are not in
``Axes.texts``) and checks the result against ``Axes.title`` and ``get_title`` for each
``loc``, failing loudly if the children change. Wanted: ``Axes.get_title_artist(loc)``
(or ``Axes.titles``).

Replaced by a public mechanism: a figure's suptitle (``Figure._suptitle``) is one of
``Figure.texts`` (``Figure.suptitle`` adds it there), so it is no longer looked up.

Checked against matplotlib 3.11.2 (older sources were not read; the version-range builds
run the check at the lower bound).
"""

from __future__ import annotations

from . import changed

__all__ = ["LOCATIONS", "axes_titles"]

#: the title locations of an Axes, in the order :func:`axes_titles` returns them
LOCATIONS = ("center", "left", "right")


def axes_titles(ax) -> list:
    """The ``Text`` artists of ``ax``'s titles: center, left and right (empty ones too).

    Raises
    ------
    UpstreamChanged
        ``ax.get_children()`` no longer holds exactly three Text artists besides
        ``ax.texts``, the first of them ``ax.title``, with the texts ``ax.get_title(loc)``.
    """
    from matplotlib.text import Text

    own = {id(t) for t in ax.texts}
    titles = [c for c in ax.get_children() if isinstance(c, Text) and id(c) not in own]
    ok = (
        len(titles) == len(LOCATIONS)
        and titles[0] is ax.title
        and [t.get_text() for t in titles] == [ax.get_title(loc) for loc in LOCATIONS]
    )
    if not ok:
        raise changed(
            "matplotlib",
            "Axes.get_children()",
            "no longer lists the center, left and right title artists after the texts",
            "matplotlib",
        )
    return titles
