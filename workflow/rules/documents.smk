# Every source document's study, claims and report rules, from one definition (issue 23):
# a loop over the documents declaring each rule (script_rule, common.smk; defined in
# scripts.smk).
#
# A document is a folder abglib/replications/<doc>/ (study.py, claims.py, optionally
# figures.py and report.py), its transcriptions data/published/<doc>/*.csv and a config
# entry (its key in `docs`, its section). What the workflow must know before any job runs
# (parsing imports no study) is data: DOCUMENTS below for the five replicated documents,
# and a document.yaml in the folder of any other (docs/new-document.md).
#
# Rule names and outputs, per document <doc>:
#   <doc>_study    results/<doc>/<table>.csv, one per table of the study
#   <doc>_claims   results/<doc>/comparison.csv and robustness.csv
#   <doc>_figures  results/<doc>/figures/<figure>.png (a document without a figures rule
#                  of its own in workflow/rules/<doc>.smk: its figures.py's figure())
#   <doc>_report   results/reports/v<version>/<doc>/ (steelman1978: steelman_report)

import yaml

# the five replicated documents, in seed order (shared/seeds/README.md,
# abglib.replications.DOCS). Per document:
#   title          the index page's title
#   tables         the study's tables (abglib.replications.<doc>.study's Study.tables();
#                  reproduce.py checks that the two lists agree)
#   report_tables  the tables its report shows and copies beside itself
#   figures        the figure stems its report shows
#   sections       other top-level config sections its study reads (its own is always in)
#   report_rule    the report rule's name, when it is not <doc>_report
#   claims_priority  the claims job's scheduling priority
DOCUMENTS = {
    "steelman1978": {
        "title": "J. E. Steelman, Frequency Response of α-β-γ Trackers (WSMR, 1978)",
        "tables": [
            "gains",
            "design_example",
            "tables345",
            "approximations",
            "equations",
            "stability",
        ],
        "report_tables": [
            "comparison",
            "robustness",
            "gains",
            "design_example",
            "tables345",
            "approximations",
            "equations",
            "stability",
        ],
        "figures": sorted(config["steelman1978"]["figures"]),
        "report_rule": "steelman_report",
    },
    "alwagih": {
        "title": "Al-Wagih and Abdulla, A Study of αβ Tracker ...",
        # the study generates the ten experiments in memory from config["datasets"]
        # (seeded, the same data as the dataset rule writes)
        "tables": [
            "table1",
            "table2",
            "mc_rmse",
            "tables34",
            "ttests",
            "tables56",
            "consistency",
            "causal",
            "sensitivity",
            "m5_bank",
            "tracks",
            "experiments",
            "settings",
        ],
        "report_tables": [
            "comparison",
            "table1",
            "table2",
            "mc_rmse",
            "tables34",
            "ttests",
            "tables56",
            "consistency",
            "causal",
            "sensitivity",
            "m5_bank",
            "experiments",
            "settings",
            "robustness",
        ],
        "figures": ["fig5_tracks", "fig6_tracks", "fig7_rmse", "fig8_rmse", "causal"],
        "sections": ["datasets"],
    },
    "huang": {
        "title": "Huang, Yang and Ma, Research on Fixed-gain Range Tracking Loop",
        "tables": [
            "bandwidth_curves",
            "thermal",
            "tables12",
            "enbw_routes",
            "track",
            "track_metrics",
        ],
        "report_tables": [
            "comparison",
            "robustness",
            "tables12",
            "enbw_routes",
            "track_metrics",
            "bandwidth_curves",
            "thermal",
        ],
        "figures": ["fig2", "fig3", "fig4", "fig5", "fig6", "fig7"],
    },
    "faa_bendix": {
        "title": "Elwell (FAA), Bendix Alpha-Beta Tracking Filter Test",
        "tables": [
            "responses",
            "gains",
            "memo_table",
            "rounding",
            "row7",
            "damping_lags",
            "captions",
        ],
        "report_tables": [
            "comparison",
            "gains",
            "memo_table",
            "rounding",
            "row7",
            "damping_lags",
            "responses",
            "captions",
            "robustness",
        ],
        "figures": ["impulse", "ramp", "triangle"],
    },
    "antenna": {
        "title": "LQ preview control and Kalman estimation for a radar tracking antenna",
        # app. H's design-error sweep is design_errors (robustness.csv is the claim
        # model's sweep over assumed inputs)
        "tables": [
            "parameters",
            "checks",
            "taylor",
            "tracking",
            "omega_sweep",
            "vw_search",
            "kalman_runs",
            "kalman_sweep",
            "design_errors",
            "stability",
            "abg",
        ],
        "report_tables": [
            "comparison",
            "parameters",
            "checks",
            "vw_search",
            "stability",
            "abg",
            "omega_sweep",
            "kalman_sweep",
            "design_errors",
            "taylor",
            "robustness",
        ],
        "figures": [
            "taylor",
            "tracking",
            "omega_sweep",
            "kalman_vw",
            "kalman_sweep",
            "amplitude",
            "robustness",
            "abg",
        ],
        # the build's longest job (~30 s of ~120 job-seconds): first, so that it never
        # ends the build alone
        "claims_priority": 3,
    },
}
# documents whose figures rule lives in workflow/rules/<doc>.smk (their inputs differ)
OWN_FIGURE_RULES = set(DOCUMENTS)

REPLICATIONS = Path(workflow.basedir) / "abglib" / "replications"
DOCUMENT_KEYS = {"title", "tables", "report_tables", "figures", "sections"}
NAME = re.compile(r"[a-z][a-z0-9_]*")


def _names(value, where, what):
    """A list of table or figure stems (lower-case identifiers), or a clear error."""
    if not isinstance(value, list) or not all(
        isinstance(v, str) and NAME.fullmatch(v) for v in value
    ):
        raise WorkflowError(
            f"{where}: {what} must be a list of names ([a-z][a-z0-9_]*), got {value!r}"
        )
    if len(set(value)) != len(value):
        raise WorkflowError(f"{where}: {what} lists a name twice: {value!r}")
    return list(value)


def read_document(doc):
    """The workflow's description of a document outside DOCUMENTS, from its folder's
    ``document.yaml`` (docs/new-document.md): ``title``, ``tables`` (its study's tables),
    optionally ``figures`` (drawn by its figures.py), ``sections`` (other top-level config
    sections its study reads) and ``report_tables`` (default: comparison, the tables,
    robustness)."""
    reserved = {"benchmark", "assets", "datasets", "documents", *config}
    if doc in reserved:
        raise WorkflowError(
            f"config docs lists {doc!r}, which names a config section or a report of its "
            f"own (results/reports/v{VERSION}/{doc}); an added document needs another key"
        )
    folder = REPLICATIONS / doc
    spec_file = folder / "document.yaml"
    if not spec_file.is_file():
        known = sorted(
            {*DOCUMENTS, *(p.parent.name for p in REPLICATIONS.glob("*/document.yaml"))}
        )
        raise WorkflowError(
            f"config docs lists {doc!r}, which is no document: a document is one of "
            f"{', '.join(known)} or a folder abglib/replications/<doc>/ with a "
            f"document.yaml (docs/new-document.md); {spec_file} does not exist"
        )
    spec = yaml.safe_load(spec_file.read_text(encoding="utf-8")) or {}
    where = str(spec_file)
    if not isinstance(spec, dict):
        raise WorkflowError(f"{where}: must be a mapping, got {type(spec).__name__}")
    unknown = sorted(set(spec) - DOCUMENT_KEYS)
    if unknown:
        raise WorkflowError(
            f"{where}: unknown keys {unknown}; allowed: {', '.join(sorted(DOCUMENT_KEYS))}"
        )
    if not isinstance(spec.get("title"), str) or not spec["title"].strip():
        raise WorkflowError(f"{where}: title must be a non-empty string")
    for module in ("study.py", "claims.py"):
        if not (folder / module).is_file():
            raise WorkflowError(f"document {doc!r} has no {folder / module}")
    tables = _names(spec.get("tables"), where, "tables")
    if not tables or {"comparison", "robustness"} & set(tables):
        raise WorkflowError(
            f"{where}: tables must name at least one table and neither 'comparison' nor "
            f"'robustness' (the claims job writes those), got {tables!r}"
        )
    figures = _names(spec.get("figures", []), where, "figures")
    if figures and not (folder / "figures.py").is_file():
        raise WorkflowError(
            f"{where} declares figures {figures} but {folder / 'figures.py'} does not exist"
        )
    report_tables = spec.get("report_tables", ["comparison", *tables, "robustness"])
    report_tables = _names(report_tables, where, "report_tables")
    missing = sorted(set(report_tables) - {"comparison", "robustness", *tables})
    if missing:
        raise WorkflowError(
            f"{where}: report_tables {missing} are no table of the document"
        )
    sections = _names(spec.get("sections", []), where, "sections")
    return {
        "title": spec["title"].strip(),
        "tables": tables,
        "report_tables": report_tables,
        "figures": figures,
        "sections": sections,
    }


for _doc in DOCS:
    if _doc not in DOCUMENTS:
        DOCUMENTS[_doc] = read_document(_doc)

# titles of the source documents, for the index page
DOC_TITLES = {doc: spec["title"] for doc, spec in DOCUMENTS.items()}

# per document: figure stems and table stems a report shows and copies beside itself
REPORT_CONTENT = {
    doc: {"figures": spec["figures"], "tables": spec["report_tables"]}
    for doc, spec in DOCUMENTS.items()
}


def report_notebook(doc):
    """A document's report notebook: workflow/notebooks/<doc>.py, else its folder's
    report.py, else the generic workflow/notebooks/document.py."""
    for path in (NOTEBOOKS / f"{doc}.py", REPLICATIONS / doc / "report.py"):
        if path.is_file():
            return path
    return NOTEBOOKS / "document.py"


def report_settings(doc):
    """What the generic notebook states of a document (its title); nothing for a
    document with a notebook of its own (its params stay as they were)."""
    if report_notebook(doc) == NOTEBOOKS / "document.py":
        return {"title": DOC_TITLES[doc]}
    return None


def report_page_of(doc):
    """The report rule's ``page`` param of one document (bound now, not at the end of the
    loop below)."""
    return lambda wildcards, input: REPORT_PAGE(doc, input)


for doc, spec in DOCUMENTS.items():
    notebook = report_notebook(doc)
    settings = report_settings(doc)
    # the study's tables; its code hash covers abglib.replications.<doc>.study and what it
    # imports, not the claims, so editing a claim reruns only <doc>_claims
    script_rule(
        f"{doc}_study",
        "reproduce.py",
        f"abglib.replications.{doc}.study",
        input={"published": published_tables_of(doc)},
        output={t: f"results/{doc}/{t}.csv" for t in spec["tables"]},
        log=f"{doc}/study",
        params={
            "doc": doc,
            "part": "study",
            "cfg": doc_config(doc, *spec.get("sections", [])),
            "digits": config["significant_digits"],
        },
    )
    # every published claim judged, and its robustness over the plausible ranges
    script_rule(
        f"{doc}_claims",
        "reproduce.py",
        f"abglib.replications.{doc}.claims",
        input={"published": published_tables_of(doc)},
        output=claims_outputs(doc),
        log=f"{doc}/claims",
        priority=spec.get("claims_priority", 0),
        params={
            "doc": doc,
            "part": "claims",
            "cfg": doc_config(doc, *spec.get("sections", []), "robustness"),
            "overrides": config["tolerance_overrides"].get(doc, {}),
            "digits": config["significant_digits"],
        },
    )
    if spec["figures"] and doc not in OWN_FIGURE_RULES:
        # every figure from the study's tables: its figures.py's figure(name, tables)
        # (workflow/scripts/document_figures.py)
        script_rule(
            f"{doc}_figures",
            "document_figures.py",
            f"abglib.replications.{doc}.figures",
            input={t: f"results/{doc}/{t}.csv" for t in spec["tables"]},
            output={
                f: report(
                    f"results/{doc}/figures/{f}.png",
                    category=spec["title"],
                    subcategory="Figures",
                    labels={"figure": f},
                )
                for f in spec["figures"]
            },
            log=f"{doc}/figures",
            params={"doc": doc, "dpi": config["figure_dpi"]},
        )
    script_rule(
        spec.get("report_rule", f"{doc}_report"),
        "render_report.py",
        notebook,
        input={
            "notebook": str(notebook),
            "figures": report_figures(doc),
            "tables": report_tables(doc),
        },
        output={
            "html": f"{REPORTS}/{doc}/index.html",
            "notebook": f"{REPORTS}/{doc}/notebook.py",
            "figures": expand(
                f"{REPORTS}/{doc}/figures/{{f}}.png", f=REPORT_CONTENT[doc]["figures"]
            ),
            "tables": expand(
                f"{REPORTS}/{doc}/tables/{{t}}.csv", t=REPORT_CONTENT[doc]["tables"]
            ),
        },
        log=f"reports/{doc}",
        params={
            "doc": doc,
            "version": VERSION,
            "repo": lambda wildcards, input: REPO,
            "timeout": config["notebook_timeout"],
            "page": report_page_of(doc),
            **({"settings": settings} if settings else {}),
        },
    )
