"""Per-rule code hashes: a workflow rule depends on the abglib code it runs.

:func:`code_hash` is a rule parameter (``code``, ``workflow/rules/common.smk``): the hash
of the abglib modules a rule's script, notebook or ``run:`` module imports, followed
transitively and read statically (no code runs), each as its syntax tree without
docstrings or comments. Snakemake reruns a rule when that hash changes, so editing a
docstring or a comment reruns nothing, and editing a module reruns only the rules that
import it. No job imports this module, so changing it reruns nothing either.
"""

from __future__ import annotations

import functools
import os
import time
from pathlib import Path

from .._checks import AbglibValueError

__all__ = ["code_fingerprint", "code_hash", "module_closure"]


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
    # an absolute path is key enough (the cache maps a path, size and mtime to what the
    # file holds; two names of one file only cost a second parse)
    name = os.path.abspath(path)
    key = f"{name}|{st.st_mtime_ns}|{st.st_size}"
    hit = _DISK["entries"].get(key)
    if hit is None:
        hit = _parse_cached(name, st.st_mtime_ns, st.st_size)
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
    # imports and docstrings are statements: walk the statement lists only (a tenth of
    # the nodes ast.walk visits, which spends most of its time in expressions)
    imports = []
    todo = [tree]
    while todo:
        node = todo.pop()
        if isinstance(node, ast.Import):
            imports.extend([0, a.name, []] for a in node.names)
            continue
        if isinstance(node, ast.ImportFrom):
            imports.append([node.level, node.module or "", [a.name for a in node.names]])
            continue
        for field in ("body", "orelse", "finalbody", "handlers", "cases"):
            block = getattr(node, field, None)
            if isinstance(block, list):
                todo.extend(reversed(block))
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
        from ..common.files import atomic_output

        with atomic_output(_DISK["path"]) as tmp:
            tmp.write_text(json.dumps(_DISK["entries"]), encoding="utf-8")
        _DISK["dirty"] = False
    except OSError:
        pass  # a cache: never worth failing a build for


#: The last module index of each package directory, with its directories' mtimes.
_INDEX: dict = {}


def _package_modules(package_dir: Path) -> dict[str, Path]:
    """The file of every module of the package at ``package_dir`` by its dotted name (one
    walk of the tree, instead of two ``stat`` calls per import looked up); a package
    ``a.b`` is its ``a/b/__init__.py``, and wins over a module file ``a/b.py``.

    The index is kept while no directory of the tree changes (a file added, removed or
    renamed changes its directory's mtime; a new directory, its parent's): the 30-odd
    code hashes of a workflow parse walk the tree once."""
    hit = _INDEX.get(package_dir)
    if hit is not None:
        stamps, modules = hit
        try:
            if all(os.stat(d).st_mtime_ns == m for d, m in stamps):
                return modules
        except OSError:
            pass
    package = package_dir.name
    out: dict[str, Path] = {}
    stamps = []
    todo: list[tuple[str, ...]] = [()]
    while todo:
        rel = todo.pop()
        here = package_dir.joinpath(*rel)
        # the mtime before the listing: a file added after it changes the mtime again
        stamps.append((str(here), os.stat(here).st_mtime_ns))
        with os.scandir(here) as entries:
            for e in entries:
                if e.is_dir():
                    if e.name != "__pycache__":
                        todo.append((*rel, e.name))
                elif e.name == "__init__.py":
                    out[".".join((package, *rel))] = here / e.name
                elif e.name.endswith(".py"):
                    out.setdefault(".".join((package, *rel, e.name[:-3])), here / e.name)
    # a directory changed within the file system's timestamp granularity (coarse on some
    # kernels) might change again without a new mtime: index it again next time
    recent = time.time_ns() - 2_000_000_000
    if all(m < recent for _, m in stamps):
        _INDEX[package_dir] = (tuple(stamps), out)
    else:
        _INDEX.pop(package_dir, None)
    return out


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
    modules = _package_modules(root)
    seen: dict[str, Path] = {}
    todo: list[tuple[str | None, Path]] = []
    for src in sources:
        f = modules.get(src) if isinstance(src, str) and "/" not in src else None
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
        if name is not None and name in seen:
            continue
        deps = _imports(path, name, package)
        if name is not None:
            seen[name] = path
            # importing a.b.c runs a/__init__ and a/b/__init__ first
            parts = name.split(".")
            deps = deps | {".".join(parts[:i]) for i in range(1, len(parts))}
        for dep in deps:
            f = modules.get(dep)
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
