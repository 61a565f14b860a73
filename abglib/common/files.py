"""Files a rebuild must reproduce: written atomically, hashed in a canonical form.

Shared by every layer above the core (the benchmark's datasets and cells, the replications'
tables, the reports' pages and figures): :func:`atomic_output` (an interrupted job leaves
no half-written output that a rerun would trust), :func:`canonical_json` and
:func:`config_hash` (the sha256 of a config or a dataset's spec, whatever its key order).
Standard library only.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import tempfile
from collections.abc import Mapping
from pathlib import Path

__all__ = ["atomic_output", "canonical_json", "config_hash"]


def canonical_json(obj) -> str:
    """JSON with sorted keys and no insignificant whitespace (the hashed form)."""
    return json.dumps(obj, sort_keys=True, separators=(",", ":"), ensure_ascii=True, default=str)


def config_hash(config: Mapping) -> str:
    """sha256 of the canonical JSON of ``config`` (key order and layout do not matter)."""
    return hashlib.sha256(canonical_json(config).encode("utf-8")).hexdigest()


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
