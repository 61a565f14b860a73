"""Versioned reports (``CONTRACTS.md`` §4): notebook → self-contained HTML, and the index page.

A report is a jupytext percent-format notebook (``workflow/notebooks/<doc>.py``) that
*reads* what upstream rules computed. :func:`render_notebook` injects the pipeline's
parameters after the cell tagged ``parameters`` (papermill's convention), executes the
notebook in the calling process (:mod:`abglib.reporting.execute`: a fresh IPython shell,
no kernel; a Jupyter kernel through nbclient with ``engine="kernel"``), strips
everything that varies between runs (execution timestamps, kernel versions, stderr
streams) and writes the page with
:func:`abglib.reporting.page.build_page` (code hidden, equations as MathML, figures
linked from ``figures/``, shared assets in ``../assets/``). :func:`write_index` writes
the per-version index page; :func:`write_assets` the shared stylesheet and script.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path

import pandas as pd

__all__ = [
    "ENGINES",
    "inject_parameters",
    "merge_streams",
    "render_notebook",
    "report_context",
    "strip_volatile",
    "verdict_counts",
    "write_assets",
    "write_index",
    "write_text",
]


def write_text(path, text: str) -> None:
    """Write ``text`` to ``path`` atomically (temp file beside it, then ``os.replace``)."""
    from ..common.files import atomic_output

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


ENGINES = ("inprocess", "kernel")


def render_notebook(
    source,
    html_path,
    parameters: Mapping,
    *,
    cwd=".",
    name: str = "report",
    timeout: int = 600,
    log=None,
    page: Mapping | None = None,
    engine: str = "inprocess",
) -> None:
    """Execute a jupytext percent notebook headless and write it as a report page.

    Parameters
    ----------
    source : path
        ``workflow/notebooks/<doc>.py`` (jupytext percent format).
    html_path : path
        Output HTML, written atomically.
    parameters : mapping
        Injected after the cell tagged ``parameters`` (relative paths, numbers, provenance).
    cwd : path
        Working directory of the notebook (the pipeline's working directory), so the
        notebook's relative paths resolve.
    name : str
        Title of the HTML page.
    timeout : int
        Per-cell timeout in seconds.
    log : callable, optional
        Receives stderr text removed from the outputs.
    page : mapping, optional
        Keyword arguments of :func:`abglib.reporting.page.build_page` (version, verdict
        counts, neighbours, files beside the page, notebook path).
    engine : {"inprocess", "kernel"}
        ``"inprocess"``: in this process, in a fresh IPython shell
        (:func:`abglib.reporting.execute.execute_notebook`: no kernel start-up);
        ``"kernel"``: in a Jupyter kernel through nbclient (needs the ``kernel`` extra:
        nbclient, ipykernel). Both give the same page.

    Raises
    ------
    abglib.reporting.execute.CellExecutionError
        A cell failed (the message gives the cell and the traceback); with
        ``engine="kernel"``, nbclient's ``CellExecutionError``.
    RuntimeError
        If the HTML would contain the absolute working directory (outputs must be
        relocatable and identical wherever they are built).
    """
    import jupytext

    if engine not in ENGINES:
        raise ValueError(f"engine must be one of {ENGINES}, got {engine!r}")
    nb = jupytext.read(source, fmt="py:percent")
    nb.metadata["kernelspec"] = {
        "name": "python3",
        "display_name": "Python 3",
        "language": "python",
    }
    inject_parameters(nb, parameters)
    if engine == "inprocess":
        from .execute import execute_notebook

        execute_notebook(nb, cwd=cwd, timeout=timeout)
    else:
        _execute_in_kernel(nb, cwd, timeout)
    removed = strip_volatile(nb)
    if log is not None:
        for text in removed:
            log(text)
    from .page import build_page

    body = build_page(nb, **{"doc": name, "version": "dev", **dict(page or {})})
    absolute = str(Path(cwd).resolve())
    if absolute != "/" and absolute in body:
        raise RuntimeError(
            f"the rendered report of {name!r} contains the absolute path {absolute!r}; "
            "pass relative paths to the notebook"
        )
    write_text(html_path, body)


def _execute_in_kernel(nb, cwd, timeout) -> None:
    """Execute ``nb`` in a Jupyter kernel (a new process) through nbclient."""
    import os
    import tempfile

    import nbclient
    from jupyter_client import KernelManager

    # the kernel talks to us over Unix sockets in a private temporary folder (IPC), not
    # over plain-text TCP (which the kernel warns about on every report)
    with tempfile.TemporaryDirectory(prefix="abglib-kernel-") as sockets:
        km = KernelManager(kernel_name="python3", transport="ipc", ip=str(Path(sockets) / "kernel"))
        client = nbclient.NotebookClient(
            nb, km=km, timeout=timeout, resources={"metadata": {"path": str(cwd)}}
        )
        # the kernel draws a cell's figures with its own inline backend, as the in-process
        # engine shows them: a backend the caller set (MPLBACKEND=Agg in a workflow job)
        # would leave them undrawn
        env = {k: v for k, v in os.environ.items() if k != "MPLBACKEND"}
        try:
            client.execute(env=env)
        finally:
            if km.has_kernel:
                km.shutdown_kernel(now=False)
    merge_streams(nb)


def merge_streams(nb) -> None:
    """Merge, in place, each run of consecutive ``stream`` outputs of one name (stdout,
    stderr) into one output, as the in-process engine records them
    (:mod:`abglib.reporting.execute`). A kernel sends a stream in as many messages as
    its output thread flushed it in, which depends on timing: ``print('out')`` is two
    writes, and a flush between them gives two outputs ("out", "\\n"), so the notebook
    could differ from run to run and from the in-process engine's (the likely cause of
    one failure of the engines' comparison test in a loaded full run, 2026-12-03; the
    test now forces such a flush)."""
    for cell in nb.cells:
        if cell.cell_type != "code":
            continue
        merged = []
        for out in cell.outputs:
            last = merged[-1] if merged else None
            if (
                out.get("output_type") == "stream"
                and last is not None
                and last.get("output_type") == "stream"
                and last.get("name") == out.get("name")
            ):
                last["text"] = last.get("text", "") + out.get("text", "")
                continue
            merged.append(out)
        cell.outputs = merged


def report_context(doc, version, input, output, *, repo, nav, made_by, provenance, settings=None):
    """The notebook's parameters and the page's arguments of one report rule.

    ``input`` has ``notebook``, ``figures`` and ``tables`` (what upstream rules wrote);
    ``output`` the ``figures`` and ``tables`` copied beside the page. ``settings``: config
    values the notebook states (e.g. the benchmark's ``rank_by``), passed as they are.
    """
    figures = {Path(p).stem: str(p) for p in input.figures}
    tables = {Path(p).stem: str(p) for p in input.tables}
    notebook = Path(input.notebook).resolve().relative_to(Path(repo).resolve()).as_posix()
    parameters = {
        "doc": doc,
        "version": version,
        "figures": figures,
        "tables": tables,
        "made_by": dict(made_by),
        "notebook": notebook,
        "provenance": provenance,
        "settings": dict(settings or {}),
        "released": [Path(p).name for p in output.tables],
    }
    page = {
        "doc": doc,
        "version": version,
        "nav": dict(nav),
        "notebook": notebook,
        "files": {
            "tables": [Path(p).name for p in output.tables],
            "figures": [Path(p).name for p in output.figures],
        },
    }
    if "comparison" in tables:
        comparison = pd.read_csv(tables["comparison"], dtype=str, keep_default_na=False)
        page["counts"], page["robust"] = verdict_counts(comparison)
    return parameters, page


def write_assets(folder) -> list[Path]:
    """Copy the shared stylesheet and script into ``folder`` (``<version>/assets``)."""
    from .page import ASSETS

    out = []
    for src in sorted(ASSETS.iterdir()):
        if src.suffix in (".css", ".js"):
            dst = Path(folder) / src.name
            write_text(dst, src.read_text(encoding="utf-8"))
            out.append(dst)
    return out


def verdict_counts(comparison: pd.DataFrame) -> tuple[dict[str, int], tuple[int, int]]:
    """Verdict counts and (robust, fragile) row counts of one ``comparison.csv``."""
    from .tables import VERDICTS

    verdict = comparison["verdict"].astype(str)
    counts = {v: int((verdict == v).sum()) for v in VERDICTS}
    robust = comparison.get("robust", pd.Series(dtype=str)).astype(str).str.lower()
    return counts, (int((robust == "true").sum()), int((robust == "false").sum()))


def write_index(
    path,
    version: str,
    scorecard: pd.DataFrame,
    documents: Sequence[Mapping],
    provenance: Mapping,
    extras: Sequence[Mapping] = (),
) -> None:
    """Write ``reports/v<version>/index.html``: every report with its headline and
    verdict bar, the changes page, the scorecard and the provenance.

    Parameters
    ----------
    path : path
        Output HTML.
    version : str
        Package version (the folder name without ``v``).
    scorecard : DataFrame
        ``results/scorecard.csv``.
    documents : sequence of mapping
        ``{"doc", "title", "href", "headline"}`` per report, ``href`` relative to the index.
    provenance : mapping
        From :func:`abglib.reporting.provenance.collect`.
    extras : sequence of mapping
        ``{"doc", "title", "href", "headline"}`` per report that replicates no source
        document (e.g. the benchmark matrix); listed after the documents, without verdicts.
    """
    from .page import index_page
    from .provenance import to_markdown
    from .tables import VERDICTS, table_html

    card = scorecard.set_index("doc")
    entries = []
    for d in documents:
        e = dict(d)
        if d["doc"] in card.index:
            rec = card.loc[d["doc"]]
            e["counts"] = {v: int(rec[v]) for v in VERDICTS if v in rec}
            for k in ("robust", "fragile"):
                if k in rec:
                    e[k] = int(rec[k])
        entries.append(e)
    entries += [dict(e, counts={}) for e in extras]
    prov_rows = []
    for line in to_markdown(provenance).splitlines()[2:]:
        cells = [c.strip().replace("`", "") for c in line.strip("|").split("|")]
        prov_rows.append(cells[:2])
    prov = pd.DataFrame(prov_rows, columns=["item", "value"])
    page = index_page(
        version,
        entries,
        table_html(scorecard, caption="Verdict counts per document.", group_min=0),
        table_html(prov, group_min=0),
    )
    write_text(path, page)
