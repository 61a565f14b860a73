"""Glue shared by the workflow's rules, scripts and report notebooks.

Small, tested helpers so that no rule or script repeats them: turning a gain
specification of ``config.yaml`` into :class:`abglib.Gains`, building an omega*T grid,
explaining a config that fails its schema, and sending a script's stderr to its log.
"""

from __future__ import annotations

import contextlib
import functools
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
    "code_fingerprint",
    "code_hash",
    "DESIGNS",
    "OUTPUT_LABELS",
    "config_errors",
    "curve_label",
    "gains_from_spec",
    "job_log",
    "log_to",
    "module_closure",
    "prepend_pythonpath",
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


def config_errors(config: Mapping, schema_path) -> list[str]:
    """Every schema violation of ``config``, one message each naming the key.

    Messages read ``config key 'a.b.c': <what is wrong>``; for an unknown key they list
    the allowed keys, for a bad value the allowed values (jsonschema says these).
    """
    import jsonschema
    import yaml

    schema = yaml.safe_load(Path(schema_path).read_text(encoding="utf-8"))
    validator = jsonschema.Draft202012Validator(schema)
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
    """A job run inside Snakemake's own process failed; the message names its log."""


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


# ----------------------------------------------------------------- code hashes
def code_fingerprint(path) -> str:
    """SHA-256 of one Python file's code: its syntax tree without docstrings.

    Comments, blank lines, line numbers and docstrings (of the module, its classes and
    functions) do not enter it, so editing them changes nothing; any other edit does.
    The tree's text form is Python's (``ast.dump``), so a new Python version may change
    every fingerprint once.
    """
    return _parsed(Path(path))[0]


#: On-disk cache of fingerprints and imports (see :func:`code_hash`'s ``cache``).
_DISK: dict = {"path": None, "entries": {}, "dirty": False}


def _parsed(path: Path) -> tuple[str, list]:
    """(fingerprint, imports) of a file, cached while its size and mtime stay; an import
    is ``(level, module or '', names)`` (level 0 and names ``()`` for ``import x``)."""
    try:
        st = path.stat()
    except OSError as exc:
        raise AbglibValueError(f"cannot read Python source {path}: {exc}") from None
    key = f"{path.resolve()}|{st.st_mtime_ns}|{st.st_size}"
    hit = _DISK["entries"].get(key)
    if hit is None:
        hit = _parse_cached(str(path.resolve()), st.st_mtime_ns, st.st_size)
        if _DISK["path"] is not None:
            _DISK["entries"][key] = hit
            _DISK["dirty"] = True
    return hit


@functools.lru_cache(maxsize=4096)
def _parse_cached(path: str, mtime_ns: int, size: int) -> tuple[str, list]:
    import ast
    import hashlib

    try:
        text = Path(path).read_text(encoding="utf-8")
        tree = ast.parse(text, filename=path)
    except (OSError, SyntaxError, ValueError) as exc:
        raise AbglibValueError(f"cannot read Python source {path}: {exc}") from None
    imports = []
    for n in ast.walk(tree):
        if isinstance(n, ast.Import):
            imports.extend([0, a.name, []] for a in n.names)
        elif isinstance(n, ast.ImportFrom):
            imports.append([n.level, n.module or "", [a.name for a in n.names]])
    for node in ast.walk(tree):
        body = getattr(node, "body", None)
        if (
            isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef))
            and body
            and isinstance(body[0], ast.Expr)
            and isinstance(body[0].value, ast.Constant)
            and isinstance(body[0].value.value, str)
        ):
            node.body = body[1:] or [ast.Pass()]
    digest = hashlib.sha256(ast.dump(tree, include_attributes=False).encode()).hexdigest()
    return digest, imports


def _use_disk_cache(cache) -> None:
    import json

    cache = None if cache is None else str(cache)
    if cache == _DISK["path"]:
        return
    _DISK.update(path=cache, entries={}, dirty=False)
    if cache is not None:
        try:
            _DISK["entries"] = json.loads(Path(cache).read_text(encoding="utf-8"))
        except (OSError, ValueError):
            pass


def _save_disk_cache() -> None:
    import json

    if _DISK["path"] is None or not _DISK["dirty"]:
        return
    try:
        with atomic_output(_DISK["path"]) as tmp:
            tmp.write_text(json.dumps(_DISK["entries"]), encoding="utf-8")
        _DISK["dirty"] = False
    except OSError:
        pass  # a cache: never worth failing a build for


def _module_file(package_dir: Path, name: str) -> Path | None:
    """The file of module ``name`` (dotted, starting with the package's name), or None."""
    parts = name.split(".")
    if parts[0] != package_dir.name:
        return None
    base = package_dir.joinpath(*parts[1:])
    for f in (base / "__init__.py", base.with_suffix(".py")):
        if f.is_file():
            return f
    return None


def _imports(path: Path, module: str | None, package: str) -> set[str]:
    """Dotted names of every module of ``package`` that ``path`` imports, anywhere in it
    (lazy imports inside functions included), with ``from X import y`` counted both as X
    and as X.y (y may be a submodule)."""
    is_pkg = path.name == "__init__.py"
    names: set[str] = set()
    for level, mod, imported in _parsed(path)[1]:
        if not imported:  # import x.y
            names.add(mod)
            continue
        if level:
            if module is None:
                continue  # a relative import outside the package: not ours
            parts = module.split(".")
            keep = len(parts) - level + (1 if is_pkg else 0)
            base = ".".join(parts[:keep] + ([mod] if mod else []))
        else:
            base = mod
        names.add(base)
        names.update(f"{base}.{a}" for a in imported if a != "*")
    out = set()
    for n in names:
        if n == package or n.startswith(package + "."):
            parts = n.split(".")
            # importing a.b.c runs a/__init__, a/b/__init__ too
            out.update(".".join(parts[:i]) for i in range(1, len(parts) + 1))
    return out


def module_closure(sources, package_dir) -> list[Path]:
    """Every file of the package at ``package_dir`` that ``sources`` import, transitively.

    ``sources`` are dotted module names of the package (``'abglib.bench.benchmark'``) or
    paths of Python files anywhere (a workflow script, a notebook in jupytext form, a
    user's own module); the imports are read from the source (statically, no code runs),
    every parent package's ``__init__`` included. Returns the package's files, sorted.
    """
    root = Path(package_dir).resolve()
    package = root.name
    seen: dict[str, Path] = {}
    todo: list[tuple[str | None, Path]] = []
    for src in sources:
        f = _module_file(root, str(src)) if isinstance(src, str) and "/" not in src else None
        if f is not None:
            todo.append((str(src), f))
        elif Path(src).is_file():
            todo.append((None, Path(src)))
        else:
            raise AbglibValueError(
                f"code source {src!r} is neither a module of {package} nor a file"
            )
    while todo:
        name, path = todo.pop()
        deps = _imports(path, name, package)
        if name is not None:
            if name in seen:
                continue
            seen[name] = path
            # importing a.b.c runs a/__init__ and a/b/__init__ first
            parts = name.split(".")
            deps |= {".".join(parts[:i]) for i in range(1, len(parts))}
        for dep in deps:
            f = _module_file(root, dep)
            if f is not None and dep not in seen:
                todo.append((dep, f))
    return sorted(set(seen.values()))


def code_hash(*sources, package_dir, extra=(), cache=None) -> str:
    """SHA-256 of the code a job runs: the package files ``sources`` import
    (:func:`module_closure`) and the ``extra`` files (e.g. a user's own variant module),
    each by :func:`code_fingerprint`.

    A rule parameter: Snakemake reruns the rule when the library code it uses changes,
    and only then; an edit to a docstring or a comment, or to a module it does not
    import, reruns nothing. ``cache``: a JSON file keeping each file's fingerprint and
    imports by path, size and mtime, so that a no-op build parses nothing (a missing or
    unreadable cache is rebuilt; the hash never depends on it).
    """
    import hashlib

    _use_disk_cache(cache)
    root = Path(package_dir).resolve()
    h = hashlib.sha256()
    for f in module_closure(sources, root):
        h.update(f"{f.relative_to(root.parent).as_posix()}\0{code_fingerprint(f)}\0".encode())
    for f in extra:
        h.update(f"extra\0{code_fingerprint(f)}\0".encode())
    _save_disk_cache()
    return h.hexdigest()
