"""Snakemake internals the workflow uses, each checked and failing loudly.

For Snakemake's maintainers, what abglib needs and which public API would replace it:

- **Switching off the job rate limiter of a local run**
  (:func:`disable_job_rate_limit`: ``workflow.scheduler.job_rate_limiter = None``).
  Since 8.17 every scheduling round under a rate limit starts a ``threading.Timer`` for
  another round one timespan later, and every ended job triggers a round, so each ended
  job adds a chain of rounds (one a second, by default) lasting until the build ends: a
  clean build of this workflow ran ~5700 rounds for 166 jobs, 10-20 s of the scheduler's
  CPU. ``--max-jobs-per-timespan`` cannot say "no limit" (its format is
  ``<count>/<timespan>``; a long timespan leaves non-daemon timers that keep the process
  alive, a short one makes the chain a busy loop). Wanted: ``--max-jobs-per-timespan
  none`` (or a scheduler that arms one timer at a time, only while jobs wait).
- **Whether this process runs the jobs itself** (:func:`jobs_run_here`:
  ``workflow.local_exec`` and ``workflow.exec_mode``): a ``run:`` block hands its script
  to a warm worker only in Snakemake's own process of a local build. Wanted: a documented
  ``workflow.exec_mode`` / "is local" flag (``ExecMode`` itself is public, in
  ``snakemake_interface_executor_plugins.settings``). Using ``exec_mode`` (8.0+) instead
  of ``workflow.remote_exec`` / ``workflow.subprocess_exec`` (the latter only 9.1+) keeps
  Snakemake 8.x working.
- **The ``snakemake`` object of a script** (:func:`script_object_class`:
  ``snakemake.script.Snakemake``, 11 positional parameters): a ``run:`` block runs a
  workflow script with the object ``script:`` would give it. It is defined in
  ``snakemake.script`` up to 9.16, in ``snakemake.io.container`` in 9.17 and in
  ``snakemake.iocontainers`` from 9.18, and ``snakemake.script`` imports it in every one
  of them, so that name is used (``snakemake.iocontainers`` would need 9.18). Wanted: a
  public constructor, e.g. ``snakemake.script.script_object(job)``, or a ``script:``
  directive that can run in a persistent worker.
- **Which rule writes a file, and its script** (:func:`rules_of`, :func:`rule_produces`,
  :func:`rule_script`, :func:`rule_snakefile`, :func:`rule_params`: ``workflow.rules``,
  ``Rule.is_producer``, ``Rule.script``, ``Rule.snakefile``, ``Rule.params``) for the
  reports' captions (which rule and script made each figure). The documented ``rules``
  namespace gives a rule's ``output`` but not the matching of a path against it. Wanted:
  ``workflow.rule_producing(path)`` or ``rules.<name>.produces(path)``.
- **Whether the config check is skipped** (:func:`skip_validation`:
  ``workflow.modifier.skip_validation``), as ``snakemake.utils.validate`` skips it for a
  module used with ``skip_validation=True``; the workflow checks its config with its own
  faster validator (libyaml). Wanted: a public ``workflow.skip_validation``.

Where each internal first appeared (read from upstream's tags, for the supported range):
``Workflow.modifier.skip_validation`` 6.0.0; ``Rule.is_producer`` 2.4.8 (``Rule.script``,
``Rule.snakefile``, ``Workflow.rules``, ``Workflow.scheduler``, ``Workflow.local_exec``,
``Workflow.exec_mode`` all in 8.0.0); ``snakemake.script.Snakemake`` with these 11
parameters in 8.0.0; ``JobScheduler.job_rate_limiter`` 8.17.0 (8.0-8.16 have a
``Throttler`` without the timer chain, so there is nothing to switch off:
:func:`disable_job_rate_limit` returns ``False`` there). ``Workflow.remote_exec`` is in
8.0.0 and ``Workflow.subprocess_exec`` in 9.1.0, but neither is used any more. Checked
against 9.27.1.

One use is quiet on purpose: the fork server's preload list
(``abglib.reporting.workers.PRELOAD``) names ``snakemake.cli`` and ``snakemake.io`` as
modules to import ahead; one that fails to import is skipped, which costs only time.
"""

from __future__ import annotations

from . import changed, check_parameters, version_of

__all__ = [
    "SCRIPT_PARAMETERS",
    "disable_job_rate_limit",
    "jobs_run_here",
    "rule_params",
    "rule_produces",
    "rule_script",
    "rule_snakefile",
    "rules_of",
    "script_object_class",
    "skip_validation",
]

_LIB = "snakemake"
_HERE = "snakemake"

#: the parameters of ``snakemake.script.Snakemake`` (8.0.0 to 9.27.1 at least)
SCRIPT_PARAMETERS = (
    "self",
    "input_",
    "output",
    "params",
    "wildcards",
    "threads",
    "resources",
    "log",
    "config",
    "rulename",
    "bench_iteration",
    "scriptdir",
)

#: the first Snakemake with ``JobScheduler.job_rate_limiter`` (and its timer chain)
RATE_LIMITER_SINCE = (8, 17)


def _release() -> tuple[int, ...]:
    """The installed Snakemake's release as integers (``9.27.1`` -> ``(9, 27, 1)``)."""
    out = []
    for part in version_of(_LIB).split("."):
        digits = "".join(c for c in part if c.isdigit())
        if not digits or digits != part:
            break
        out.append(int(digits))
    return tuple(out)


def _attribute(obj, name: str, owner: str):
    """``obj.name``, or :class:`~abglib._compat.UpstreamChanged` naming ``owner.name``."""
    try:
        return getattr(obj, name)
    except AttributeError:
        raise changed(_LIB, f"{owner}.{name}", "does not exist", _HERE) from None


def disable_job_rate_limit(workflow) -> bool:
    """Switch off the scheduler's job rate limiter (``--max-jobs-per-timespan``) of a run.

    Call from ``onstart`` (the scheduler exists then, and no round has run). Touches
    ``workflow.scheduler.job_rate_limiter`` (``JobScheduler``, Snakemake 8.17+), set to
    ``None`` as Snakemake sets it for a dry run. Returns whether a limiter was removed:
    ``False`` where there was none (a dry run, or Snakemake < 8.17, which has no timer
    chain to stop).

    Raises
    ------
    UpstreamChanged
        The workflow has no scheduler, or, on Snakemake 8.17 and later, the scheduler has no
        ``job_rate_limiter`` or it is not a limiter (no ``timespan``, no
        ``get_free_jobs``).
    """
    scheduler = _attribute(workflow, "scheduler", "Workflow")
    if scheduler is None:
        raise changed(_LIB, "Workflow.scheduler", "is None in onstart", _HERE)
    if not hasattr(scheduler, "job_rate_limiter"):
        if _release() and _release() < RATE_LIMITER_SINCE:
            return False
        raise changed(_LIB, "JobScheduler.job_rate_limiter", "does not exist", _HERE)
    limiter = scheduler.job_rate_limiter
    if limiter is None:
        return False
    if not (hasattr(limiter, "timespan") and callable(getattr(limiter, "get_free_jobs", None))):
        raise changed(
            _LIB,
            "JobScheduler.job_rate_limiter",
            f"is a {type(limiter).__name__}, not a JobRateLimiter (timespan, get_free_jobs)",
            _HERE,
        )
    scheduler.job_rate_limiter = None
    return True


def jobs_run_here(workflow) -> bool:
    """Whether this Snakemake process runs the jobs itself: a local executor
    (``workflow.local_exec``) in the main process (``workflow.exec_mode`` is
    ``ExecMode.DEFAULT``, not a job's own process spawned by a cluster job or a
    subprocess).

    Raises
    ------
    UpstreamChanged
        Either attribute is missing, ``local_exec`` is not a bool or ``exec_mode`` is not an
        ``ExecMode``.
    """
    from snakemake_interface_executor_plugins.settings import ExecMode

    local = _attribute(workflow, "local_exec", "Workflow")
    mode = _attribute(workflow, "exec_mode", "Workflow")
    if not isinstance(local, bool):
        raise changed(
            _LIB, "Workflow.local_exec", f"is a {type(local).__name__}, not a bool", _HERE
        )
    if not isinstance(mode, ExecMode):
        raise changed(_LIB, "Workflow.exec_mode", f"is {mode!r}, not an ExecMode", _HERE)
    return local and mode == ExecMode.DEFAULT


def script_object_class():
    """The class of the ``snakemake`` object a ``script:`` job sees
    (``snakemake.script.Snakemake``), checked to take the 11 arguments
    ``input_, output, params, wildcards, threads, resources, log, config, rulename,
    bench_iteration, scriptdir`` in that order.

    Raises
    ------
    UpstreamChanged
        It is missing, or its parameters differ.
    """
    import snakemake.script

    cls = _attribute(snakemake.script, "Snakemake", "snakemake.script")
    check_parameters(cls.__init__, SCRIPT_PARAMETERS, _LIB, "snakemake.script.Snakemake", _HERE)
    return cls


def skip_validation(workflow) -> bool:
    """Whether the workflow is used as a module with ``skip_validation=True``
    (``workflow.modifier.skip_validation``, as ``snakemake.utils.validate`` reads it).

    Raises
    ------
    UpstreamChanged
        ``workflow.modifier`` or its ``skip_validation`` is missing, or the flag is not a
        bool.
    """
    modifier = _attribute(workflow, "modifier", "Workflow")
    flag = _attribute(modifier, "skip_validation", "WorkflowModifier")
    if not isinstance(flag, bool):
        raise changed(
            _LIB,
            "WorkflowModifier.skip_validation",
            f"is a {type(flag).__name__}, not a bool",
            _HERE,
        )
    return flag


def rules_of(workflow) -> list:
    """The workflow's rules (``workflow.rules``)."""
    return list(_attribute(workflow, "rules", "Workflow"))


def rule_produces(rule, path: str) -> bool:
    """Whether ``rule`` writes ``path`` (``Rule.is_producer``, wildcards matched).

    Raises
    ------
    UpstreamChanged
        ``is_producer`` is missing or not callable, or it returns something else than a
        bool.
    """
    producer = _attribute(rule, "is_producer", "Rule")
    if not callable(producer):
        raise changed(_LIB, "Rule.is_producer", "is not callable", _HERE)
    out = producer(path)
    if not isinstance(out, bool):
        raise changed(
            _LIB, "Rule.is_producer", f"returned a {type(out).__name__}, not a bool", _HERE
        )
    return out


def rule_script(rule) -> str | None:
    """The ``script:`` of ``rule`` as written (relative to its Snakefile), or ``None``."""
    script = _attribute(rule, "script", "Rule")
    if script is not None and not isinstance(script, str):
        raise changed(_LIB, "Rule.script", f"is a {type(script).__name__}, not a str", _HERE)
    return script


def rule_snakefile(rule) -> str:
    """The path of the Snakefile that defines ``rule`` (``Rule.snakefile``)."""
    return str(_attribute(rule, "snakefile", "Rule"))


def rule_params(rule):
    """The ``params:`` of ``rule`` (``Rule.params``; ``None`` or a named list)."""
    return _attribute(rule, "params", "Rule")
