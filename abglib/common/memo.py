"""A least-recently-used cache bounded by the bytes it holds, not by its number of entries.

``functools.lru_cache(maxsize=n)`` bounds a cache by its entries. Where one entry is a
small config's dataset of a few kilobytes and another is the default config's 1.9 MB,
no single ``n`` fits both: Al-Wagih's claims job on the small config generated 2,935
datasets for 1,380 distinct ones under ``maxsize=24``, and computed 26,830 RMSE arrays
for 21,360 distinct ones under ``maxsize=8192`` (2026-12-02, issue 24). A budget in bytes
keeps every small entry and as many large ones as the budget allows.

Standard library only; ``nbytes`` tells the size of a value.
"""

from __future__ import annotations

import functools
from collections import OrderedDict
from collections.abc import Callable, Hashable
from typing import Any, NamedTuple

from .._checks import AbglibValueError

__all__ = ["CacheInfo", "lru_cache_bytes"]


class CacheInfo(NamedTuple):
    """Hits, misses, entries held and their bytes, and the budget (bytes)."""

    hits: int
    misses: int
    entries: int
    nbytes: int
    max_bytes: int


def lru_cache_bytes(max_bytes: int, nbytes: Callable[[Any], int]):
    """Decorator: memoise a function of hashable arguments, evicting the least recently
    used results once their sizes (``nbytes(result)``) add up to more than ``max_bytes``.

    A result larger than the whole budget is returned and not kept. The wrapped function
    gets ``cache_info()`` (:class:`CacheInfo`) and ``cache_clear()``, as with
    :func:`functools.lru_cache`. Keyword arguments are not supported (the callers pass
    positional keys). Not thread-safe.

    Examples
    --------
    >>> calls = []
    >>> @lru_cache_bytes(10, len)
    ... def word(n):
    ...     calls.append(n)
    ...     return "x" * n
    >>> word(4), word(4), word(8), word(4)
    ('xxxx', 'xxxx', 'xxxxxxxx', 'xxxx')
    >>> calls  # 4 + 8 > 10: the 4 was evicted when the 8 came
    [4, 8, 4]
    """
    if isinstance(max_bytes, bool) or not isinstance(max_bytes, int) or max_bytes < 0:
        raise AbglibValueError(f"max_bytes must be a whole number of bytes >= 0, got {max_bytes!r}")

    def decorate(func):
        held: OrderedDict[Hashable, tuple[Any, int]] = OrderedDict()
        state = {"hits": 0, "misses": 0, "bytes": 0}

        @functools.wraps(func)
        def wrapper(*key):
            if key in held:
                held.move_to_end(key)
                state["hits"] += 1
                return held[key][0]
            state["misses"] += 1
            value = func(*key)
            size = int(nbytes(value))
            if size <= max_bytes:
                held[key] = (value, size)
                state["bytes"] += size
                while state["bytes"] > max_bytes:
                    _, (_, old) = held.popitem(last=False)
                    state["bytes"] -= old
            return value

        def cache_info() -> CacheInfo:
            return CacheInfo(state["hits"], state["misses"], len(held), state["bytes"], max_bytes)

        def cache_clear() -> None:
            held.clear()
            state.update(hits=0, misses=0, bytes=0)

        wrapper.cache_info = cache_info
        wrapper.cache_clear = cache_clear
        return wrapper

    return decorate
