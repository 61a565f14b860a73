"""Versioned reports (``CONTRACTS.md`` §4): notebook → self-contained HTML, and the index page.

A report is a jupytext percent-format notebook (``workflow/notebooks/<doc>.py``) that
*reads* what upstream rules computed. :func:`render_notebook` injects the pipeline's
parameters after the cell tagged ``parameters`` (papermill's convention), executes the
notebook headless with nbclient, strips everything that varies between runs (execution
timestamps, kernel versions, stderr streams) and exports HTML with images embedded.
:func:`write_index` writes the per-version index page with the scorecard.
"""

from __future__ import annotations

import html
from collections.abc import Mapping, Sequence
from pathlib import Path

import pandas as pd

__all__ = ["inject_parameters", "render_notebook", "strip_volatile", "write_index", "write_text"]


def write_text(path, text: str) -> None:
    """Write ``text`` to ``path`` atomically (temp file beside it, then ``os.replace``)."""
    from .pipeline import atomic_output

    with atomic_output(path) as tmp:
        tmp.write_text(text, encoding="utf-8", newline="\n")


def inject_parameters(nb, parameters: Mapping) -> None:
    """Insert a code cell assigning ``parameters`` after the cell tagged ``parameters``.

    Values must be literals (``repr`` round-trips): strings, numbers, lists, dicts.
    """
    import nbformat

    lines = ["# Parameters injected by the pipeline (abglib.report.render_notebook)"]
    lines += [f"{name} = {value!r}" for name, value in parameters.items()]
    cell = nbformat.v4.new_code_cell("\n".join(lines), metadata={"tags": ["injected-parameters"]})
    index = next(
        (i + 1 for i, c in enumerate(nb.cells) if "parameters" in c.metadata.get("tags", [])),
        0,
    )
    nb.cells.insert(index, cell)


def strip_volatile(nb) -> list[str]:
    """Remove run-dependent content in place; return the stderr text that was removed.

    Drops cell ``execution`` timestamps and ids-derived metadata, the kernel's version
    numbers and stderr stream outputs (warnings may quote absolute paths); the removed
    stderr is returned so the caller can log it.
    """
    stderr = []
    for i, cell in enumerate(nb.cells):
        cell.id = f"cell-{i}"
        cell.metadata.pop("execution", None)
        if cell.cell_type != "code":
            continue
        kept = []
        for out in cell.outputs:
            if out.get("output_type") == "stream" and out.get("name") == "stderr":
                stderr.append(out.get("text", ""))
                continue
            kept.append(out)
        cell.outputs = kept
    meta = nb.metadata
    meta.pop("widgets", None)
    meta.pop("jupytext", None)
    if "language_info" in meta:
        meta["language_info"].pop("version", None)
    return stderr


def render_notebook(
    source,
    html_path,
    parameters: Mapping,
    *,
    cwd=".",
    name: str = "report",
    timeout: int = 600,
    log=None,
) -> None:
    """Execute a jupytext percent notebook headless and export self-contained HTML.

    Parameters
    ----------
    source : path
        ``workflow/notebooks/<doc>.py`` (jupytext percent format).
    html_path : path
        Output HTML, written atomically.
    parameters : mapping
        Injected after the cell tagged ``parameters`` (relative paths, numbers, provenance).
    cwd : path
        Working directory of the kernel (the pipeline's working directory), so the
        notebook's relative paths resolve.
    name : str
        Title of the HTML page.
    timeout : int
        Per-cell timeout in seconds.
    log : callable, optional
        Receives stderr text removed from the outputs.

    Raises
    ------
    RuntimeError
        If the HTML would contain the absolute working directory (outputs must be
        relocatable and identical wherever they are built).
    """
    import tempfile

    import jupytext
    import nbclient
    from jupyter_client import KernelManager
    from nbconvert import HTMLExporter

    nb = jupytext.read(source, fmt="py:percent")
    nb.metadata["kernelspec"] = {
        "name": "python3",
        "display_name": "Python 3",
        "language": "python",
    }
    inject_parameters(nb, parameters)
    # the kernel talks to us over Unix sockets in a private temporary folder (IPC), not
    # over plain-text TCP (which the kernel warns about on every report)
    with tempfile.TemporaryDirectory(prefix="abglib-kernel-") as sockets:
        km = KernelManager(kernel_name="python3", transport="ipc", ip=str(Path(sockets) / "kernel"))
        client = nbclient.NotebookClient(
            nb, km=km, timeout=timeout, resources={"metadata": {"path": str(cwd)}}
        )
        try:
            client.execute()
        finally:
            if km.has_kernel:
                km.shutdown_kernel(now=False)
    removed = strip_volatile(nb)
    if log is not None:
        for text in removed:
            log(text)
    exporter = HTMLExporter(template_name="lab", embed_images=True)
    body, _ = exporter.from_notebook_node(nb, resources={"metadata": {"name": name}})
    absolute = str(Path(cwd).resolve())
    if absolute != "/" and absolute in body:
        raise RuntimeError(
            f"the rendered report of {name!r} contains the absolute path {absolute!r}; "
            "pass relative paths to the notebook"
        )
    write_text(html_path, body)


_INDEX_CSS = """
body { font-family: sans-serif; max-width: 60em; margin: 2em auto; line-height: 1.4; }
table { border-collapse: collapse; } td, th { border: 1px solid #bbb; padding: .25em .6em; }
th { background: #eee; } td.num { text-align: right; } code { background: #f4f4f4; }
"""


def write_index(
    path,
    version: str,
    scorecard: pd.DataFrame,
    documents: Sequence[Mapping],
    provenance: Mapping,
    extras: Sequence[Mapping] = (),
) -> None:
    """Write ``reports/v<version>/index.html``: the scorecard and links to each report.

    Parameters
    ----------
    path : path
        Output HTML.
    version : str
        Package version (the folder name without ``v``).
    scorecard : DataFrame
        ``results/scorecard.csv``.
    documents : sequence of mapping
        ``{"doc", "title", "href"}`` per report, ``href`` relative to the index.
    provenance : mapping
        From :func:`abglib.provenance.collect`.
    extras : sequence of mapping
        ``{"title", "href", "description"}`` per report that replicates no source document
        (e.g. the benchmark matrix), listed under "Other reports".
    """
    from .provenance import to_markdown

    esc = html.escape
    titles = {d["doc"]: d for d in documents}
    rows = []
    for rec in scorecard.to_dict("records"):
        d = titles.get(rec["doc"], {"title": rec["doc"], "href": ""})
        link = f'<a href="{esc(d["href"])}">{esc(rec["doc"])}</a>' if d["href"] else rec["doc"]
        cells = "".join(
            f'<td class="num">{int(rec[c])}</td>'
            for c in ("match", "mismatch", "explained", "not_reproducible", "total")
        )
        rows.append(f"<tr><td>{link}</td><td>{esc(d['title'])}</td>{cells}</tr>")
    prov_rows = []
    for line in to_markdown(provenance).splitlines()[2:]:
        cells = [c.strip() for c in line.strip("|").split("|")]
        prov_rows.append(
            "<tr>" + "".join(f"<td>{esc(c).replace('`', '')}</td>" for c in cells) + "</tr>"
        )
    other = ""
    if extras:
        items = "".join(
            f'<li><a href="{esc(e["href"])}">{esc(e["title"])}</a>: {esc(e["description"])}</li>'
            for e in extras
        )
        other = f"<h2>Other reports</h2>\n<ul>{items}</ul>\n"
    page = f"""<!DOCTYPE html>
<html lang="en">
<head><meta charset="utf-8"><title>abglib reports v{esc(version)}</title>
<style>{_INDEX_CSS}</style></head>
<body>
<h1>abglib replication reports, version {esc(version)}</h1>
<p>Each report regenerates the figures and tables of one source document and compares every
published number with the value abglib reproduces (<code>comparison.csv</code> in each
report's <code>tables/</code> folder). Verdicts: <b>match</b> (within half a unit of the
last printed digit, unless the
report states another tolerance), <b>explained</b> (a different quantity or reading,
demonstrated in the report, reproduces the printed number), <b>mismatch</b>,
<b>not_reproducible</b>.</p>
<h2>Scorecard</h2>
<table>
<tr><th>document</th><th>title</th><th>match</th><th>mismatch</th><th>explained</th>
<th>not reproducible</th><th>total</th></tr>
{chr(10).join(rows)}
</table>
<p>Machine-readable: <a href="scorecard.csv">scorecard.csv</a>.</p>
{other}<h2>Provenance</h2>
<table>
<tr><th>item</th><th>value</th></tr>
{chr(10).join(prov_rows)}
</table>
</body>
</html>
"""
    write_text(path, page)
