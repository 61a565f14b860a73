"""Glue shared by the workflow's rules, scripts and report notebooks.

Small, tested helpers so that no rule or script repeats them: turning a gain
specification of ``config.yaml`` into :class:`abglib.Gains`, building an omega*T grid,
explaining a config that fails its schema, and sending a script's stderr to its log.
"""

from __future__ import annotations

import contextlib
import logging
import os
import sys
import tempfile
from collections.abc import Mapping
from pathlib import Path

import numpy as np

from .._checks import AbglibValueError
from ..gains import Gains

__all__ = [
    "atomic_output",
    "DESIGNS",
    "OUTPUT_LABELS",
    "config_errors",
    "curve_label",
    "gains_from_spec",
    "job_log",
    "job_threads",
    "log_to",
    "prepend_pythonpath",
    "read_yaml",
    "validate_config",
    "wt_grid",
]

#: Gain designs a config curve may name (seed 000: eqs 22-24, the alpha-beta analogue, 28-30).
DESIGNS = ("standard_abg", "standard_ab", "qd")

#: How each transfer-function output is written in seed 000 (times the curve's scale).
OUTPUT_LABELS = {
    "x_smooth": "X̄/X",
    "x_pred": "X_p/X",
    "v_smooth": "T·V̄/X",
    "a_smooth": "T²·Ā/X",
}


def gains_from_spec(spec: Mapping) -> Gains:
    """Gains of a config curve ``{design, alpha | m, ...}``.

    ``standard_abg``: critically damped alpha-beta-gamma (seed 000, eqs 22-24) with the
    given alpha; ``standard_ab``: critically damped alpha-beta (seed 000, p. 5);
    ``qd``: QD tracker (seed 000, eqs 28-30) with memory ``m``, or the ``m`` that gives
    the stated alpha.
    """
    from ..bench.variants import variant_gains

    kind = spec.get("design")
    if kind not in DESIGNS:
        raise AbglibValueError(f"design must be one of {list(DESIGNS)}, got {kind!r}")
    # one dispatch from names to design rules: the variant registry's
    if kind == "qd":
        variant = (
            {"rule": "qd_m", "m": spec["m"]}
            if "m" in spec
            else {"rule": "qd_alpha", "alpha": spec["alpha"]}
        )
    else:
        order = 3 if kind == "standard_abg" else 2
        variant = {"rule": "standard_alpha", "alpha": spec["alpha"], "order": order}
    return variant_gains(variant, dt=1.0, name=f"curve {kind}")


def curve_label(spec: Mapping, gains: Gains) -> str:
    """Legend text of a config curve, e.g. ``'X̄/X, standard α-β-γ, α=0.3'``."""
    scale = float(spec.get("scale", 1.0))
    out = OUTPUT_LABELS[spec["output"]]
    if scale != 1.0:
        out = f"{scale:g}·{out}"
    name = {"standard_abg": "standard α-β-γ", "standard_ab": "standard α-β", "qd": "QD"}
    label = f"{out}, {name[spec['design']]}, α={float(gains.alpha):.4g}"
    if spec["design"] == "qd" and "m" in spec:
        label += f" (m={float(spec['m']):g})"
    return label


def wt_grid(grid: Mapping, kind: str) -> np.ndarray:
    """omega*T grid from a config grid ``{start, stop_over_pi, n}``.

    ``kind='linear'``: evenly spaced; ``'log'``: log-spaced (``start`` must be > 0).
    """
    start, stop, n = float(grid["start"]), float(grid["stop_over_pi"]) * np.pi, int(grid["n"])
    if kind == "linear":
        return np.linspace(start, stop, n)
    if kind == "log":
        if start <= 0:
            raise AbglibValueError(f"a log grid needs start > 0, got {start!r}")
        return np.geomspace(start, stop, n)
    raise AbglibValueError(f"kind must be one of ['linear', 'log'], got {kind!r}")


def read_yaml(path):
    """The contents of a YAML file, parsed by libyaml where PyYAML was built with it.

    The same objects as ``yaml.safe_load``, about 8x faster: the workflow's schema
    (30 kB) takes 0.02 s instead of the 0.17 s of the pure-Python parser, on every
    Snakemake run, a no-op's included.
    """
    import yaml

    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    with open(path, encoding="utf-8") as fh:
        return yaml.load(fh, Loader=loader)  # noqa: S506 - a safe loader


def _validator(schema: Mapping, fill_defaults: bool):
    """A JSON-schema (draft 2020-12) validator; with ``fill_defaults`` it also writes the
    ``default`` of every absent property into the instance it validates (jsonschema's FAQ
    recipe, as ``snakemake.utils.validate(..., set_default=True)``)."""
    import jsonschema

    cls = jsonschema.Draft202012Validator
    if fill_defaults:
        check_properties = cls.VALIDATORS["properties"]

        def properties(validator, props, instance, schema):
            if validator.is_type(instance, "object"):
                for name, sub in props.items():
                    if isinstance(sub, Mapping) and "default" in sub:
                        instance.setdefault(name, sub["default"])
            yield from check_properties(validator, props, instance, schema)

        cls = jsonschema.validators.extend(cls, {"properties": properties})
    return cls(schema)


def config_errors(config: Mapping, schema_path, *, fill_defaults: bool = False) -> list[str]:
    """Every schema violation of ``config``, one message each naming the key.

    Messages read ``config key 'a.b.c': <what is wrong>``; for an unknown key they list
    the allowed keys, for a bad value the allowed values (jsonschema says these).
    ``fill_defaults``: write the schema's defaults into ``config`` on the way
    (:func:`validate_config`).
    """
    validator = _validator(read_yaml(schema_path), fill_defaults)
    messages = []
    for err in sorted(validator.iter_errors(config), key=lambda e: list(map(str, e.path))):
        where = ".".join(str(p) for p in err.absolute_path) or "<top level>"
        msg = err.message
        if err.validator == "additionalProperties":
            allowed = sorted(err.schema.get("properties", {}))
            patterns = sorted(err.schema.get("patternProperties", {}))
            msg += f"; allowed keys: {', '.join(allowed + patterns) or '(free-form)'}"
        messages.append(f"config key '{where}': {msg}")
    return messages


def validate_config(config: dict, schema_path) -> None:
    """Check the workflow's config against its schema and fill in the schema's defaults,
    as ``snakemake.utils.validate(config, schema)`` does (the Snakefile's check).

    Raises
    ------
    AbglibValueError
        Listing every violation (:func:`config_errors`), each naming its key.
    """
    errors = config_errors(config, schema_path, fill_defaults=True)
    if errors:
        raise AbglibValueError(
            f"the config does not match {Path(schema_path).name}:\n  " + "\n  ".join(errors)
        )


def log_to(path) -> logging.Logger:
    """Send stderr and a logger named ``abglib.pipeline`` to the rule's log file.

    Call first thing in a workflow script (``log_to(snakemake.log[0])``). An uncaught
    exception is written to the log with its traceback, and its message to the console.
    """
    fh = open(path, "w", encoding="utf-8")  # noqa: SIM115 - lives as long as the script
    console = sys.stderr
    sys.stderr = fh

    def excepthook(kind, value, tb):
        # the traceback goes to the log; the message also to the console, so that a
        # failed job says what to do where the user is looking
        sys.__excepthook__(kind, value, tb)
        fh.flush()
        print(f"{kind.__name__}: {value}\n(full traceback in {path})", file=console)

    sys.excepthook = excepthook
    logger = logging.getLogger("abglib.pipeline")
    logger.handlers[:] = [logging.StreamHandler(fh)]
    logger.setLevel(logging.INFO)
    logging.captureWarnings(True)
    return logger


class JobFailed(RuntimeError):
    """A job run inside Snakemake's own process, or in its worker, failed; the message
    names its log."""


@contextlib.contextmanager
def job_threads(n):
    """Run the enclosed code on at most ``n`` threads of numba's parallel loops: a job
    uses the cores Snakemake gave it (the rule's ``threads:``), no more.

    Without it a 1-thread job's batched tracking ran on all of numba's threads (2 here),
    and two such jobs side by side (two cores) competed for three or four: a job next to
    one that does slowed by up to 40 %. The count is the calling thread's own (numba's
    ``set_num_threads``), so it holds for a thread of Snakemake's process (the cells) as
    for a worker process, and it is put back on exit. Parallel and serial tracking give
    the same bits (:func:`abglib.track`).
    """
    import numba

    n = int(n)
    if n < 1:
        raise AbglibValueError(f"a job needs at least 1 thread, got {n}")
    old = numba.get_num_threads()
    numba.set_num_threads(min(n, numba.config.NUMBA_NUM_THREADS))
    try:
        yield
    finally:
        numba.set_num_threads(old)


@contextlib.contextmanager
def job_log(path, name: str = "job"):
    """The log of a job that runs inside Snakemake's process (a ``run:`` block).

    Yields a logger writing to ``path`` (truncated) and nowhere else, so that jobs running
    side by side in threads keep separate logs and the process's ``sys.stderr`` is left
    alone (unlike :func:`log_to`, which is for a script's own process). An exception is
    written to the log with its traceback and raised again as :class:`JobFailed` with its
    message and the log's path.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    logger = logging.getLogger(f"abglib.job.{path.resolve()}")
    logger.propagate = False
    logger.setLevel(logging.INFO)
    handler = logging.FileHandler(path, mode="w", encoding="utf-8")
    logger.handlers[:] = [handler]
    try:
        yield logger
    except Exception as exc:
        logger.error("%s failed", name, exc_info=True)
        raise JobFailed(
            f"{name}: {type(exc).__name__}: {exc}\n(full traceback in {path})"
        ) from None
    finally:
        handler.close()
        logger.handlers.clear()
        logging.Logger.manager.loggerDict.pop(logger.name, None)


def prepend_pythonpath(path) -> None:
    """Put ``path`` first on ``PYTHONPATH`` for subprocesses (the workflow's jobs).

    So that every job imports abglib from the repository that holds the Snakefile, in
    whatever environment runs it (e.g. ``snakemake --sdm conda``).
    """
    parts = [str(path)] + [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]
    os.environ["PYTHONPATH"] = os.pathsep.join(dict.fromkeys(parts))


def _read_umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


# read once, when the module is imported: os.umask can only be read by setting it, which
# would race with other threads creating files (jobs run in threads of Snakemake's process)
_UMASK = _read_umask()


@contextlib.contextmanager
def atomic_output(path):
    """Yield a temporary path beside ``path``; on success it replaces ``path`` atomically.

    On any error the temporary file is removed and ``path`` is left as it was, so an
    interrupted or failed job never leaves a half-written output that a rerun would trust.
    The file gets the usual permissions (``0o666`` minus the umask), not ``mkstemp``'s 0600.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    os.close(fd)
    try:
        yield Path(tmp)
        os.chmod(tmp, 0o666 & ~_UMASK)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def made_by(workflow, paths) -> dict[str, tuple[str, str]]:
    """``{file name: (rule, script)}``: the rule of ``workflow`` that writes each path and
    its script relative to the repository (showyourwork-style captions). The rules are
    read through :mod:`abglib._compat.snakemake` (Snakemake has no public API for it)."""
    from .._compat.snakemake import (
        rule_params,
        rule_produces,
        rule_script,
        rule_snakefile,
        rules_of,
    )

    out = {}
    for path in paths:
        for r in rules_of(workflow):
            if r.name.endswith("_report") or not rule_produces(r, path):
                continue
            script = ""
            if rule_script(r):
                full = Path(rule_snakefile(r)).parent / rule_script(r)
                script = Path(os.path.relpath(os.path.normpath(full), workflow.basedir)).as_posix()
            elif isinstance(getattr(rule_params(r), "script", None), str):
                script = rule_params(r).script  # a run: rule's script (run_script, common.smk)
            out[Path(path).name] = (r.name, script)
            break
    return out


def report_page(workflow, order, titles, doc, input) -> dict:
    """Params of a report rule: its neighbours in ``order`` (``{"prev", "next"}`` with
    ``doc`` and ``title``) and :func:`made_by` of its figures and tables."""
    i = list(order).index(doc)
    nav = {
        rel: {"doc": order[j], "title": titles.get(order[j], order[j])}
        for rel, j in (("prev", i - 1), ("next", i + 1))
        if 0 <= j < len(order)
    }
    return {"nav": nav, "made_by": made_by(workflow, [*input.figures, *input.tables])}
