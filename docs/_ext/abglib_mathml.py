"""Sphinx math as MathML, at build time: no MathJax, no script, no network request.

Sphinx's default HTML math renderer (MathJax) loads its script from a CDN, which an offline
reader cannot reach. This renderer converts every ``:math:`` role and ``.. math::`` block
with :func:`abglib.reporting.page.math_html` (the reports' converter, latex2mathml), so the
pages show every equation with nothing but the browser. An equation latex2mathml cannot
parse, or converts with a backslash left in its text (a command it took
for a character), is a build warning (an error under ``-W``), never raw TeX on the page.
"""

from __future__ import annotations

from docutils import nodes
from sphinx.util import logging

logger = logging.getLogger(__name__)


def _mathml(self, node, display: bool) -> str:
    from abglib.reporting.page import math_html  # the reports' converter, one home

    latex = node.astext().strip()
    try:
        return math_html(latex, display)
    except ValueError as exc:
        logger.warning("%s", exc, location=node)
        return f"<code>{self.encode(latex)}</code>"


def visit_math(self, node):
    self.body.append(_mathml(self, node, display=False))
    raise nodes.SkipNode


def visit_math_block(self, node):
    html = _mathml(self, node, display=True)
    if node.get("number"):
        html = f'<span class="eqno">({node["number"]})</span>' + html
    self.body.append(f'<div class="math">{html}</div>')
    raise nodes.SkipNode


def setup(app):
    app.add_html_math_renderer(
        "mathml", inline_renderers=(visit_math, None), block_renderers=(visit_math_block, None)
    )
    return {"parallel_read_safe": True, "parallel_write_safe": True}
