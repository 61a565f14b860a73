# Shared by every rule: config validation, the report version, paths and input functions.

import re
import sys
from pathlib import Path

import abglib
from abglib import AbglibValueError
from abglib._compat import snakemake as smk_compat
from abglib.reporting.codehash import code_hash
from abglib.reporting.pipeline import prepend_pythonpath, validate_config
from abglib.reporting.workers import run_script as run_in_worker, script_object, warm_up
from snakemake.exceptions import WorkflowError
from snakemake.utils import min_version

min_version("9.18")

CONFIG_SCHEMA = Path(workflow.basedir) / "workflow" / "schemas" / "config.schema.yaml"

# snakemake.utils.validate's check and defaults, with the schema parsed by libyaml
# (abglib.reporting.pipeline.validate_config: ~0.15 s less on every run); skipped, as
# validate skips it, where a workflow using this one as a module says skip_validation
if not smk_compat.skip_validation(workflow):
    try:
        validate_config(config, CONFIG_SCHEMA)
    except AbglibValueError as err:
        raise WorkflowError(str(err)) from None

# every job imports abglib from this repository, whatever environment runs it (--sdm conda)
prepend_pythonpath(workflow.basedir)

# the report version is the package version (CONTRACTS.md §4), never a config value. A build
# writes its reports under results/; the committed release reports/v<version> is written
# only by the deliberate `abglib release` (docs/releases.md), never by a build
VERSION = abglib.__version__
REPORTS = f"results/reports/v{VERSION}"
DOCS = config["docs"]

# published numbers are part of the repository, found from the Snakefile's folder so that
# the pipeline can run in any working directory (snakemake -d)
REPO = workflow.basedir
PUBLISHED = Path(workflow.basedir) / "data" / "published"
NOTEBOOKS = Path(workflow.basedir) / "workflow" / "notebooks"

# each rule depends on the library code it runs; its param `code` is the hash of the abglib
# modules its script (or its run: block's module) imports, transitively, read statically
# and without docstrings or comments (abglib.reporting.codehash.code_hash). Editing a
# docstring reruns nothing; editing a module reruns only the rules that import it.
ABGLIB_DIR = Path(workflow.basedir) / "abglib"
SCRIPTS_DIR = Path(workflow.basedir) / "workflow" / "scripts"
_CODE_HASHES = {}
# parsed files by path, size and mtime: a no-op build parses no source (a cache only).
# It lives beside the sources, like Python's and numba's caches, not in the working
# directory: a build in a new directory (-d) parses nothing either (~1.5 s of a clean
# build's start, when no job runs yet); an unwritable source tree only loses the cache
CODE_CACHE = Path(workflow.basedir) / ".snakemake" / "abglib-code-cache.json"


def code_of(*sources, extra=()):
    """Code hash of a rule: ``sources`` are script names of workflow/scripts, other Python
    files (a notebook) or abglib module names; ``extra`` files are hashed as they are.
    """
    key = (tuple(map(str, sources)), tuple(map(str, extra)))
    if key not in _CODE_HASHES:
        paths = [
            (
                str(SCRIPTS_DIR / s)
                if isinstance(s, str) and s.endswith(".py") and "/" not in s
                else str(s)
            )
            for s in sources
        ]
        _CODE_HASHES[key] = code_hash(
            *paths, package_dir=ABGLIB_DIR, extra=extra, cache=CODE_CACHE
        )
    return _CODE_HASHES[key]


def script_params(script, *sources, extra=()):
    """The params ``script`` and ``code`` of a job that runs ``workflow/scripts/<script>``.

    ``script`` is the script's path in the repository (what run_script runs and what the
    reports' captions name); ``code`` is the code hash of the script and ``sources``
    (code_of).
    """
    return {
        "script": f"workflow/scripts/{script}",
        "code": code_of(script, *sources, extra=extra),
    }


def jobs_run_here():
    """Whether this Snakemake process runs the jobs itself (a local build), so that their
    scripts go to the warm worker; a cluster's jobs run in processes of their own
    (abglib._compat.snakemake.jobs_run_here: Snakemake has no public flag for it)."""
    return smk_compat.jobs_run_here(workflow)


def without_rate_limit():
    """Switch off the scheduler's submission rate limit (``--max-jobs-per-timespan``,
    default 100/1s) for a local build, where it limits nothing: with 2 cores a build starts
    a few jobs a second at most.

    Why: in Snakemake 9 (checked up to 9.27) every scheduling round with a rate limit ends
    by starting a timer that triggers another round one timespan later, and each job's end
    triggers a round as well, so every job that ends adds a chain of rounds, one a second,
    that lasts until the build ends. A clean default build ran ~5700 rounds for 166 jobs;
    each recomputes the size of every ready job's inputs (the 100-odd cells' datasets) and
    holds the GIL, costing Snakemake's own process 10-20 s of CPU next to the jobs'.
    Without the limit a round runs when a job ends, as before Snakemake 8.17 introduced it.
    A cluster build (jobs_run_here() false) keeps it: there it paces ``sbatch``.

    Snakemake has no option for "no limit": this sets an internal of its scheduler
    (abglib._compat.snakemake.disable_job_rate_limit), which raises naming the Snakemake
    version if the attribute has moved, rather than going quiet.
    """
    smk_compat.disable_job_rate_limit(workflow)


def run_script(input, output, params, wildcards, threads, resources, log, rulename):
    """The body of a rule's ``run:`` block: its script (``params.script``) with the same
    ``snakemake`` object as under ``script:``. In Snakemake's own process (a local build)
    it runs in a fork of a warm worker; in a job's own process (a cluster) it runs in place
    (abglib.reporting.workers)."""
    smk = script_object(
        input,
        output,
        params,
        wildcards,
        threads,
        resources,
        log,
        config,
        rulename,
        str(SCRIPTS_DIR),
    )
    run_in_worker(
        Path(workflow.basedir) / params.script,
        smk,
        in_worker=jobs_run_here(),
        benchmark=getattr(log, "benchmark", None),
    )


# every script job of the workflow, by rule name; declared with script_rule in
# the rule files, defined by the one rule block of scripts.smk (included last)
SCRIPT_RULES = {}


def script_rule(
    name,
    script,
    *sources,
    output,
    log,
    input=None,
    params=None,
    benchmark=True,
    extra=(),
    priority=0,
    threads=None,
    resources=None,
):
    """Declare the rule ``name`` that runs ``workflow/scripts/<script>`` (run_script).

    Only what varies between such rules is given: ``input`` and ``output`` (named files),
    ``params`` beyond ``script`` and ``code`` (script_params of ``script``, ``sources``
    and ``extra``), the log's stem ``log`` (``logs/<log>.log``, and with ``benchmark``
    a second log, the job's benchmark record ``benchmarks/results/<log>.tsv``, which
    run_script writes: abglib.common.jobs.write_benchmark says why not Snakemake's
    ``benchmark:``), and any ``priority``, ``threads`` and ``resources``. Every such rule
    gets the same conda environment and the same ``run:`` (scripts.smk). Returns the
    declaration (its ``output`` stands for ``rules.<name>.output``, which exists only once
    scripts.smk has run).
    """
    if name in SCRIPT_RULES:
        raise WorkflowError(f"rule {name!r} is declared twice")
    SCRIPT_RULES[name] = {
        "input": dict(input or {}),
        "output": dict(output),
        # the job's own log first (a script's snakemake.log[0]), then its benchmark record
        "log": {"job": f"logs/{log}.log"}
        | ({"benchmark": f"benchmarks/results/{log}.tsv"} if benchmark else {}),
        "params": {**script_params(script, *sources, extra=extra), **(params or {})},
        "priority": priority,
        "threads": threads,
        "resources": dict(resources or {}),
    }
    return SCRIPT_RULES[name]


# per document: its title, tables and figures (DOCUMENTS, REPORT_CONTENT): documents.smk


def published_tables_of(doc):
    """Transcription files of one document (data/published/<doc>/*.csv)."""
    files = sorted((PUBLISHED / doc).glob("*.csv"))
    if not files:
        raise WorkflowError(f"no published tables in {PUBLISHED / doc}")
    return [str(f) for f in files]


def report_figures(doc):
    return [f"results/{doc}/figures/{f}.png" for f in REPORT_CONTENT[doc]["figures"]]


def report_tables(doc):
    return [f"results/{doc}/{t}.csv" for t in REPORT_CONTENT[doc]["tables"]]


# simulated radar datasets (datasets.smk): scenario name -> spec
DATASET_SCENARIOS = config.get("datasets", {}).get("scenarios", {})


def dataset_files(name):
    """[parquet, manifest] of one dataset scenario (rule dataset, datasets.smk)."""
    if name not in DATASET_SCENARIOS:
        raise WorkflowError(
            f"no dataset scenario {name!r} in config['datasets']['scenarios']; "
            f"configured: {', '.join(sorted(DATASET_SCENARIOS)) or 'none'}"
        )
    return [
        f"results/datasets/{name}.parquet",
        f"results/datasets/{name}.manifest.json",
    ]


def all_targets():
    targets = [
        "results/scorecard.csv",
        f"{REPORTS}/index.html",
        f"{REPORTS}/scorecard.csv",
        f"{REPORTS}/changes.html",  # against the previous version (rule changes, reports.smk)
        f"{REPORTS}/changes.csv",
    ]
    for doc in DOCS:
        targets.append(f"{REPORTS}/{doc}/index.html")
    for name in DATASET_SCENARIOS:
        targets.extend(dataset_files(name))
    return targets


def doc_config(doc, *extra):
    """What a document's study reads: its own config section and the ``extra`` top-level
    sections, as one mapping (a rule param, so that a change to them reruns the rule).
    A document's section is ``config[doc]``, or ``config["documents"][doc]`` for a
    document added beside the five (docs/new-document.md); the study sees it as
    ``config[doc]`` either way.
    """
    out = {k: config[k] for k in (doc, *extra) if k in config}
    if doc not in out and doc in config.get("documents", {}):
        out = {doc: config["documents"][doc], **out}
    return out


def claims_outputs(doc):
    """Named outputs of a ``<doc>_claims`` rule: the comparison and the robustness sweep."""
    return {t: f"results/{doc}/{t}.csv" for t in ("comparison", "robustness")}


# ---------------------------------------------------------------- benchmark matrix
# (benchmark.smk): the variants and scenarios of config['benchmark'], checked at parse
# time, and the input functions of its rules.
from abglib.bench.variants import callable_file, check_variant, resolve_callable

BENCH = config.get("benchmark", {})
# a user's variant (callable: <file>.py:<function>) names its file from the repository;
# its cells get the resolved path (the league's variants table shows it as written)
BENCH_VARIANTS = BENCH.get("variants", {})
BENCH_SPECS = {n: resolve_callable(s, REPO) for n, s in BENCH_VARIANTS.items()}
BENCH_SCENARIOS = list(BENCH.get("scenarios", []))


def _check_benchmark():
    """Fail at parse time on an unknown scenario, rule or parameter, on a variant no
    scenario can realise, or on a user's callable that cannot be loaded, raises or returns
    neither gains nor a tracker on any scenario: one error naming every such variant, so
    that a config with several mistakes is mended in one go."""
    for s in BENCH_SCENARIOS:
        dataset_files(s)
    problems = []
    for name, spec in BENCH_SPECS.items():
        errors = []
        for s in BENCH_SCENARIOS:
            sc = DATASET_SCENARIOS[s]
            try:
                check_variant(spec, float(sc["dt"]), int(sc["n_samples"]), name)
            except ValueError as exc:
                if "callable" in spec:
                    problems.append(f"benchmark variant {name!r}: {exc}")
                    break
                errors.append((s, str(exc)))
        if errors and len(errors) == len(BENCH_SCENARIOS):  # a callable broke out above
            reasons = {why for _, why in errors}
            # the same reason on every scenario (a gain out of range): said once
            if len(reasons) == 1:
                detail = f" ({', '.join(s for s, _ in errors)}): {reasons.pop()}"
            else:
                detail = ":\n  " + "\n  ".join(f"{s}: {why}" for s, why in errors)
            problems.append(
                f"benchmark variant {name!r} is infeasible on every scenario{detail}"
            )
    if problems:
        raise WorkflowError("\n".join(problems))


def bench_cell_code(wildcards):
    """Code hash of a cell: abglib.bench.cell's imports, and a user's variant's file."""
    f = callable_file(BENCH_SPECS[wildcards.variant])
    return code_of("abglib.bench.cell", extra=[f] if f else [])


def bench_cell(input, output, params, wildcards, threads, log):
    """The benchmark_cell rule's job, in Snakemake's process: one cell of the matrix
    (abglib.bench.cell.cell_job). A function, so that the rule's run: stays one call
    (snakemake --lint measures a run: block by its bytecode, longer on Python 3.13)."""
    from abglib.bench.cell import cell_job

    cell_job(
        input.parquet,
        output.cell,
        log[0],
        variant=wildcards.variant,
        spec=params.spec,
        scenario=wildcards.scenario,
        scenario_spec=params.scenario_spec,
        settings=params.settings,
        seed=params.seed,
        digits=params.digits,
        threads=threads,
    )


def bench_runs(scenario):
    """Monte Carlo runs of a cell: the config override, else the dataset's own runs."""
    runs = BENCH.get("runs")
    return int(runs) if runs else int(DATASET_SCENARIOS[scenario]["runs"])


def bench_mem_mb(wildcards):
    """Memory of a cell: the dataset (4 arrays per coordinate) plus two tracked chunks."""
    sc = DATASET_SCENARIOS[wildcards.scenario]
    n, runs = int(sc["n_samples"]), bench_runs(wildcards.scenario)
    chunk = min(runs, int(BENCH["chunk_runs"]))
    return 400 + (runs * n * 2 * 5 + chunk * n * 2 * 16) * 8 // 10**6


def _check_family_size():
    """The Bonferroni bound assumes at most family_size VRF checks in the matrix (the
    count imports no numerics: abglib.bench._family)."""
    from abglib.bench._family import n_vrf_checks

    n = n_vrf_checks(len(BENCH_VARIANTS), len(BENCH_SCENARIOS))
    if n > int(BENCH["family_size"]):
        raise WorkflowError(
            f"the benchmark matrix can hold {n} VRF checks, more than "
            f"benchmark.family_size = {BENCH['family_size']}; raise family_size"
        )


# the checks compute every variant's gains on every scenario and import the design rules'
# numerics (scipy): about a second. A build skips them when this very matrix passed them
# before with the same code: the key holds the variants, the scenarios, the family size
# and the code hash of the checks and of the users' own variant files.
MATRIX_CHECKED = Path(".snakemake") / "abglib-matrix-checked"


def _matrix_key():
    import hashlib
    import json

    files = [f for f in map(callable_file, BENCH_SPECS.values()) if f]
    code = code_of("abglib.bench.variants", "abglib.bench.benchmark", extra=files)
    scenarios = {s: DATASET_SCENARIOS.get(s) for s in BENCH_SCENARIOS}
    payload = [BENCH_SPECS, scenarios, BENCH.get("family_size"), code]
    text = json.dumps(payload, sort_keys=True, default=str)
    return hashlib.sha256(text.encode()).hexdigest()


def _check_matrix():
    key = _matrix_key()
    try:
        if MATRIX_CHECKED.read_text(encoding="utf-8") == key:
            return
    except OSError:
        pass
    _check_benchmark()
    _check_family_size()
    try:
        MATRIX_CHECKED.parent.mkdir(parents=True, exist_ok=True)
        MATRIX_CHECKED.write_text(key, encoding="utf-8")
    except OSError:
        pass  # a record only: the next build checks again


if BENCH:
    _check_matrix()


def bench_cells():
    return expand(
        "results/benchmark/cells/{variant}/{scenario}.csv",
        variant=list(BENCH_VARIANTS),
        scenario=BENCH_SCENARIOS,
    )


def bench_targets():
    return [f"{REPORTS}/benchmark/index.html"] if BENCH else []
