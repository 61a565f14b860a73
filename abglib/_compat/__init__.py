"""Every use of another library's undocumented internals, in one place, failing loudly.

abglib relies on a few attributes that Snakemake, IPython (with traitlets), pandas and
matplotlib do not document. Each is reached only through one small module here, one per
library (:mod:`.snakemake`, :mod:`.ipython`, :mod:`.pandas`, :mod:`.matplotlib`), whose
functions name what they touch, check that it is there with the shape they expect, and
raise :class:`UpstreamChanged` naming the library, its installed version and the
attribute when it is not: an upgrade that moves an internal stops the build with a
message saying what moved, never turns a workaround into a silent no-op. Where a public
mechanism does the job the project uses it instead (each module's docstring says which
uses were replaced, and tells upstream's maintainers what public API would replace the
rest). ``tests/test_compat.py`` checks every accessor against the installed versions,
takes each attribute away to see the message, and walks the package and the workflow for
private attribute access outside this package.

Nothing here imports Snakemake, IPython, pandas or matplotlib when :mod:`abglib` is
imported (the tracker core installs without them): each module imports its library
itself, when it is imported, and only the layers that need it import the module.
"""

from __future__ import annotations

__all__ = ["UpstreamChanged", "changed", "check_parameters", "version_of"]


class UpstreamChanged(RuntimeError):
    """An undocumented attribute abglib relies on is gone or has another shape.

    The message names the library, its installed version, the attribute and the module of
    :mod:`abglib._compat` that uses it.
    """


def version_of(distribution: str) -> str:
    """The installed version of ``distribution`` (``'unknown'`` if it has no metadata)."""
    from importlib import metadata

    try:
        return metadata.version(distribution)
    except metadata.PackageNotFoundError:
        return "unknown"


def changed(distribution: str, attribute: str, problem: str, module: str) -> UpstreamChanged:
    """The error for ``attribute`` of ``distribution`` having changed (``problem`` says how).

    ``module`` is the :mod:`abglib._compat` module using it, named in the message so that
    a user knows where to look; the caller raises the result.
    """
    return UpstreamChanged(
        f"{distribution} {version_of(distribution)}: {attribute} {problem}. abglib relies "
        f"on this undocumented attribute (abglib/_compat/{module}.py says why and what "
        f"would replace it); this {distribution} version is not supported by this abglib"
    )


def check_parameters(
    func, expected: tuple[str, ...], distribution: str, attribute: str, module: str
) -> None:
    """Raise :func:`changed` unless ``func``'s parameters are named ``expected``, in order."""
    import inspect

    try:
        names = tuple(inspect.signature(func).parameters)
    except (TypeError, ValueError) as err:
        raise changed(
            distribution, attribute, f"has no readable signature ({err})", module
        ) from None
    if names != expected:
        raise changed(
            distribution,
            attribute,
            f"takes ({', '.join(names)}), expected ({', '.join(expected)})",
            module,
        )
