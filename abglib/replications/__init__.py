"""The replications of the five source documents (extra ``abglib[replications]``).

One folder per document (keys of ``shared/seeds/README.md``): its printed forms, its
study, its claims (one shared claim model, :mod:`._claims`) and its figures' data.

``steelman1978``  seed 000, Steelman 1978
``alwagih``       seed 001, Al-Wagih and Abdulla
``huang``         seed 002, Huang, Yang and Ma
``faa_bendix``    seed 003, Elwell (FAA) and Sinsky's memo
``antenna``       seed 004, LQ preview control and Kalman estimation for a tracking antenna
"""

#: Document keys, in seed order.
DOCS = ("steelman1978", "alwagih", "huang", "faa_bendix", "antenna")

from ._claims import (  # noqa: E402
    Claim,
    ClaimSet,
    PlausibleRange,
    Reading,
    Result,
    Study,
    evaluate,
    plausible_ranges,
)

__all__ = [
    "DOCS",
    "Claim",
    "ClaimSet",
    "PlausibleRange",
    "Reading",
    "Result",
    "Study",
    "claims_of",
    "evaluate",
    "plausible_ranges",
    "reproduce",
]


def claims_of(doc: str):
    """``(CLAIMS, STUDY)`` of one document: its :class:`ClaimSet` and its study class
    (module ``abglib.replications.<doc>.claims``)."""
    import importlib

    from .._checks import AbglibValueError

    if doc not in DOCS:
        raise AbglibValueError(f"doc must be one of {list(DOCS)}, got {doc!r}")
    mod = importlib.import_module(f"{__name__}.{doc}.claims")
    return mod.CLAIMS, mod.STUDY


def reproduce(doc: str, config, published_paths, overrides=None) -> dict:
    """Every table of one document's replication, by file stem.

    Builds the study at ``config`` (``{doc: section, ...}``), takes its report tables
    (:meth:`Study.tables`) and judges every published claim (:func:`evaluate`): the
    result holds ``comparison`` (``shared/CONTRACTS.md`` section 3) and ``robustness``
    (every point of every sweep over an assumed input) beside the study's own tables.
    """
    from ..reporting.compare import read_published

    claims, study_cls = claims_of(doc)
    published = read_published(published_paths)
    study = study_cls(config, published)
    tables = dict(study.tables())
    comparison, robustness = evaluate(
        doc, claims, published, study, lambda c: study_cls(c, published), overrides
    )
    tables["comparison"] = comparison
    tables["robustness"] = robustness
    return tables
