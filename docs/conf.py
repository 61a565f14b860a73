"""Sphinx configuration of abglib's site: the API reference, the gallery, the guides
(``docs/*.md``, read by MyST) and the current release's reports (``docs/README.md``).

Build, offline, warnings as errors::

    sphinx-build -W --keep-going -b html docs docs/_build/html

No extension fetches anything: no intersphinx, equations as MathML at build time
(``_ext/abglib_mathml.py``), the gallery runs locally, and the current release's reports
(``reports/v<version>``) are copied into the site under the same relative path.
"""

from __future__ import annotations

import os
import shutil
import sys
from pathlib import Path

DOCS = Path(__file__).resolve().parent
REPO = DOCS.parent
sys.path.insert(0, str(DOCS / "_ext"))
sys.path.insert(0, str(REPO))

os.environ.setdefault("MPLBACKEND", "Agg")

import abglib  # noqa: E402

project = "abglib"
author = "the abglib authors"
copyright = "the abglib authors, MIT licence"  # noqa: A001
version = release = abglib.__version__
#: the release folder whose reports the site carries (one site holds both)
REPORTS = Path("reports") / f"v{release}"

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "numpydoc",
    "sphinx_gallery.gen_gallery",
    "abglib_mathml",
    # the guides (docs/*.md) and the findings notes are Markdown: MyST reads them, and a
    # link to another page's .md file (as on GitHub) becomes a link to its page here
    "myst_parser",
]

root_doc = "index"
templates_path = ["_templates"]
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
#: Markdown files of docs/ that are not pages: the README findings block's template
#: (`abglib findings` reads it; its placeholders are not prose)
NOT_PAGES = ["readme_findings.md"]
exclude_patterns = ["_build", "**/GALLERY_HEADER.rst", "examples/*.py", *NOT_PAGES]

# -- guides: docs/*.md, read by MyST -----------------------------------------------------
#: The guides in reading order. Every other docs/*.md page follows them alphabetically, so
#: a new page is in the site (and its navigation) without an edit here; a page in no
#: toctree would fail the -W build.
GUIDES = [
    "overview",
    "installation",
    "reading-reports",
    "extending",
    "new-document",
    "releases",
    "performance",
    "engine-speed",
    "cluster",
    "testing",
    "architecture",
    "README",
]
#: the line of index.rst that _guides_toctree replaces with the guides' toctree
GUIDES_MARKER = ".. guides: the toctree of docs/*.md, written here by conf.py (GUIDES)"
# GitHub's anchors for headings down to ###, so that "page.md#a-heading" links work in
# both places
myst_heading_anchors = 3


def guide_pages() -> list[str]:
    """The guides' document names (``docs/*.md`` but NOT_PAGES), in GUIDES order."""
    found = {p.stem for p in DOCS.glob("*.md") if p.name not in NOT_PAGES}
    return [g for g in GUIDES if g in found] + sorted(found - set(GUIDES))


def _guides_toctree(app, docname, source):
    """Write the guides' toctree into the front page, at GUIDES_MARKER."""
    if docname != root_doc:
        return
    if GUIDES_MARKER not in source[0]:
        raise ValueError(f"{root_doc}.rst lost the line {GUIDES_MARKER!r} (conf.py fills it)")
    entries = "".join(f"   {page}\n" for page in guide_pages())
    toctree = f".. toctree::\n   :caption: Guides\n   :maxdepth: 1\n   :hidden:\n\n{entries}"
    source[0] = source[0].replace(GUIDES_MARKER, toctree)


# -- API reference: autosummary pages, numpydoc docstrings ------------------------------
autosummary_generate = True
autosummary_imported_members = True  # abglib.analysis re-exports its submodules' names
autosummary_ignore_module_all = False  # a module's __all__ is its public API
autodoc_default_options = {"member-order": "bysource"}
autodoc_typehints = "none"  # the numpydoc Parameters sections say the types
#: the modules of api.rst: an object is documented once, on the page of its home (the
#: deepest of these modules that holds the module it is defined in); other modules that
#: re-export it (``abglib.analysis`` re-exports its submodules' names) link it
API_MODULES = [
    line.strip()
    for line in (DOCS / "api.rst").read_text().splitlines()
    if line.startswith("   abglib")
]


def api_home(modname: str, name: str) -> str:
    """The documented module that is the home of ``modname.name`` (see API_MODULES)."""
    import importlib

    obj = getattr(importlib.import_module(modname), name)
    defined = getattr(obj, "__module__", None)
    if not isinstance(defined, str) or not callable(obj):
        return modname  # constants are documented where they are listed
    # defined in a private module (abglib.bench._family): at home where a documented
    # module of the same public package lists it
    public = defined.split("._", 1)[0]
    if public != defined and modname in API_MODULES and f"{modname}.".startswith(public + "."):
        return modname
    homes = [m for m in API_MODULES if defined == m or defined.startswith(m + ".")]
    return max(homes, key=len) if homes else modname


def _plain(obj) -> bool:
    """A number, a string, or a tuple of them (nested): a value worth printing as is."""
    if isinstance(obj, tuple):
        return all(_plain(x) for x in obj)
    return isinstance(obj, (int, float, str))


def reexported_constants(modname: str) -> list[tuple[str, str, list[str]]]:
    """The public constants ``modname`` re-exports from its submodules, documented here.

    ``abglib.verdicts`` and ``abglib.analysis`` re-export constants defined in private
    submodules, which autosummary does not list (it reads doc comments of the module itself
    only). Each is returned as ``(name, value, doc lines)``: the value's repr when it is
    short and plain (:func:`_plain`, else ``""``), the ``#:`` comment above its
    definition. A public constant without one fails the build: every public name is
    documented.
    """
    import importlib
    import types

    from sphinx.pycode import ModuleAnalyzer

    mod = importlib.import_module(modname)
    names = getattr(mod, "__all__", None) or [n for n in dir(mod) if not n.startswith("_")]
    own = ModuleAnalyzer.for_module(modname).find_attr_docs()
    found = []
    for name in names:
        obj = getattr(mod, name)
        if name.startswith("_") or callable(obj) or isinstance(obj, types.ModuleType):
            continue
        if ("", name) in own:
            continue  # autosummary lists it
        doc = None
        for sub in sorted(m for m in sys.modules if m.startswith(modname + ".")):
            if getattr(sys.modules[sub], name, None) is obj:
                doc = ModuleAnalyzer.for_module(sub).find_attr_docs().get(("", name))
                if doc:
                    break
        if not doc:
            raise ValueError(f"{modname}.{name} is public but has no #: comment where defined")
        value = repr(obj) if _plain(obj) and len(repr(obj)) <= 120 else ""
        found.append((name, value, [line for line in doc if line.strip()]))
    return found


autosummary_context = {"api_home": api_home, "reexported_constants": reexported_constants}
# every cross-reference must resolve (-W makes a miss an error), but those to numpy, scipy
# and the standard library: without intersphinx (offline) they render as code, unlinked
nitpicky = True
nitpick_ignore_regex = [
    (r"py:.*", r"(numpy|scipy|csv|python:.*|numpy:.*)(\..*)?"),
    (r"std:(ref|term)", r"(python|numpy):.*"),  # numpydoc's aliases of "bool", "iterable"
]
# a function in the config cannot be pickled with the environment: Sphinx then rereads
# every page on the next build (a clean build anyway, docs/README.md); nothing else is muted
suppress_warnings = ["config.cache"]
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
# a parameter's type is a link when it is one of abglib's own classes (the aliases); every
# other word of a type stays text (numpydoc's built-in aliases point at Python's and
# numpy's inventories, which an offline build does not have: ignored above)
numpydoc_xref_param_type = True
numpydoc_xref_ignore = "all"
numpydoc_xref_aliases = {
    "Gains": "abglib.Gains",
    "TrackResult": "abglib.TrackResult",
    "Reading": "abglib.verdicts.Reading",
    "Alternative": "abglib.verdicts.Alternative",
    "Row": "abglib.verdicts.readings.Row",
}

# -- equations: MathML at build time (no MathJax, no network) --------------------------
html_math_renderer = "mathml"

# -- gallery: every docs/examples/plot_*.py runs during the build -----------------------
sphinx_gallery_conf = {
    "examples_dirs": "examples",
    "gallery_dirs": "auto_examples",
    "filename_pattern": r"/plot_",
    "download_all_examples": False,
    "remove_config_comments": True,
    "abort_on_example_error": True,
    "show_memory": False,
    "show_signature": False,
    "matplotlib_animations": False,
    "reset_modules": ("matplotlib",),
    "within_subsection_order": "FileNameSortKey",
    "min_reported_time": 1e9,
    # the computation-times page loads jQuery and DataTables from a CDN: not written
    "write_computation_times": False,
}

# -- HTML --------------------------------------------------------------------------------
html_theme = "alabaster"
html_title = f"abglib {release}"
html_static_path = ["_static"]
html_css_files = ["abglib.css"]
html_theme_options = {
    "description": "fixed-gain alpha-beta(-gamma) trackers",
    "fixed_sidebar": False,
    "page_width": "1180px",
    "sidebar_width": "230px",
    "show_powered_by": False,
}
# the sidebar links the copied reports from every page (pathto: relative to the page)
html_sidebars = {
    "**": ["about.html", "navigation.html", "reports.html", "relations.html", "searchfield.html"]
}
html_context = {"reports_index": f"{REPORTS.as_posix()}/index.html"}
html_show_sourcelink = False
html_copy_source = False

rst_prolog = f"""
.. _current reports: {REPORTS.as_posix()}/index.html
"""


def _copy_reports(app, exception):
    """Copy ``reports/v<version>`` into the built site at the same relative path."""
    if exception is not None or app.builder.format != "html":
        return
    src = REPO / REPORTS
    if not (src / "index.html").is_file():
        raise FileNotFoundError(
            f"{src} has no index.html: the site links the release's reports (abglib release)"
        )
    dst = Path(app.outdir) / REPORTS
    if dst.exists():
        shutil.rmtree(dst)
    shutil.copytree(src, dst)


def setup(app):
    app.connect("source-read", _guides_toctree)
    app.connect("build-finished", _copy_reports)
