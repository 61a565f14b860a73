"""The text metadata of a PNG file (standard library only).

:func:`abglib.common.plotting.save_figure` stores each figure's alt text under the
``Description`` key; the report pages read it back for ``<img alt>`` without importing
matplotlib.
"""

from __future__ import annotations

import struct
import zlib
from pathlib import Path

__all__ = ["png_description"]


def png_description(path) -> str:
    """The ``Description`` text of a PNG (``tEXt``, ``zTXt`` or ``iTXt``), '' if none.

    Standard library only (the report renderer reads it to set ``<img alt>``).
    """
    data = Path(path).read_bytes()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG file")
    pos = 8
    while pos + 8 <= len(data):
        length, ctype = struct.unpack(">I4s", data[pos : pos + 8])
        body = data[pos + 8 : pos + 8 + length]
        pos += 12 + length
        if ctype == b"IEND":
            break
        if ctype not in (b"tEXt", b"zTXt", b"iTXt"):
            continue
        key, _, rest = body.partition(b"\x00")
        if key != b"Description":
            continue
        if ctype == b"tEXt":
            return rest.decode("latin-1")
        if ctype == b"zTXt":
            return zlib.decompress(rest[1:]).decode("latin-1")
        compressed, rest = rest[0], rest[2:]
        _lang, _, rest = rest.partition(b"\x00")
        _translated, _, text = rest.partition(b"\x00")
        return (zlib.decompress(text) if compressed else text).decode("utf-8")
    return ""


# ------------------------------------------------------------------ frequency responses
