"""Provenance of a report: versions, git commit, config hash, seeds (``CONTRACTS.md`` §4).

Everything here is deterministic for a given environment, checkout and config: no
timestamps, no host names, no absolute paths.
"""

from __future__ import annotations

import hashlib
import json
import platform
import subprocess
from collections.abc import Mapping
from importlib import metadata
from pathlib import Path

__all__ = [
    "PACKAGES",
    "canonical_json",
    "collect",
    "config_hash",
    "find_seeds",
    "git_commit",
    "package_versions",
    "to_markdown",
]

#: Distributions whose versions every report states.
PACKAGES = ("abglib", "numpy", "scipy", "pandas", "matplotlib", "numba", "snakemake")


def canonical_json(obj) -> str:
    """JSON with sorted keys and no insignificant whitespace (the hashed form)."""
    return json.dumps(obj, sort_keys=True, separators=(",", ":"), ensure_ascii=True, default=str)


def config_hash(config: Mapping) -> str:
    """sha256 of the canonical JSON of ``config`` (key order and layout do not matter)."""
    return hashlib.sha256(canonical_json(config).encode("utf-8")).hexdigest()


def git_commit(path=".", ignore=("reports",)) -> str | None:
    """The commit checked out at ``path``, ``+dirty`` if tracked files changed, or None.

    Changes under ``ignore`` (top-level folders of the repository) do not count: a build
    rewrites the committed reports it is building, and that must not mark the code it was
    built from as modified. None when git is missing or ``path`` is not in a repository
    (e.g. an unpacked tarball).
    """

    def git(*args):
        return subprocess.run(
            ["git", *args], cwd=Path(path), capture_output=True, text=True, check=True, timeout=30
        ).stdout

    try:
        commit = git("rev-parse", "HEAD").strip()
        top = git("rev-parse", "--show-toplevel").strip()
        excludes = [f":(exclude,top){d}" for d in ignore]
        changed = subprocess.run(
            ["git", "status", "--porcelain", "--untracked-files=no", "--", top, *excludes],
            cwd=Path(path),
            capture_output=True,
            text=True,
            check=True,
            timeout=30,
        ).stdout
    except (OSError, subprocess.SubprocessError):
        return None
    if not commit:
        return None
    return commit + ("+dirty" if changed.strip() else "")


def package_versions(packages=PACKAGES) -> dict[str, str]:
    """Installed versions of ``packages`` (``'not installed'`` when absent), plus Python."""
    versions = {"python": platform.python_version()}
    for name in packages:
        try:
            versions[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            versions[name] = "not installed"
    return versions


def find_seeds(config, prefix: str = "") -> dict[str, int]:
    """Every integer in ``config`` under a key named ``seed`` or ending in ``_seed``."""
    seeds: dict[str, int] = {}
    if isinstance(config, Mapping):
        for key, value in config.items():
            name = f"{prefix}.{key}" if prefix else str(key)
            if (key == "seed" or str(key).endswith("_seed")) and isinstance(value, int):
                seeds[name] = value
            else:
                seeds.update(find_seeds(value, name))
    elif isinstance(config, list):
        for i, value in enumerate(config):
            seeds.update(find_seeds(value, f"{prefix}[{i}]"))
    return seeds


def collect(config: Mapping, repo=".") -> dict:
    """Provenance record of a report built with ``config`` from the checkout at ``repo``."""
    return {
        "abglib_version": package_versions(("abglib",))["abglib"],
        "git_commit": git_commit(repo) or "unknown (not a git checkout)",
        "config_sha256": config_hash(config),
        "versions": package_versions(),
        "seeds": find_seeds(config),
    }


def to_markdown(prov: Mapping) -> str:
    """A small markdown table of a :func:`collect` record, for a report's provenance cell."""
    lines = ["| item | value |", "| --- | --- |"]
    lines.append(f"| abglib version | `{prov['abglib_version']}` |")
    lines.append(f"| git commit | `{prov['git_commit']}` |")
    lines.append(f"| config sha256 | `{prov['config_sha256']}` |")
    for name, version in prov["versions"].items():
        lines.append(f"| {name} | `{version}` |")
    seeds = prov.get("seeds") or {}
    text = ", ".join(f"`{k}` = {v}" for k, v in sorted(seeds.items())) or "none used"
    lines.append(f"| random seeds | {text} |")
    return "\n".join(lines)
