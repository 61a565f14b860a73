"""The replications of the five source documents (extra ``abglib[replications]``).

One folder per document (keys of ``shared/seeds/README.md``): its printed forms, its
study, its claims (one shared claim model, :mod:`._claims`) and its figures' data; and
:mod:`.compare`, the published-versus-reproduced table every document's claims make
(``comparison.csv``, the scorecard: ``shared/CONTRACTS.md`` section 3).

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
    "documents",
    "evaluate",
    "judge_claims",
    "one_blas_thread",
    "plausible_ranges",
    "reproduce",
    "study_of",
    "study_tables",
]


def documents() -> tuple[str, ...]:
    """Every document key: :data:`DOCS`, then, sorted, every other folder of this package
    with a ``study.py`` and a ``claims.py`` (a document added beside the five, as
    ``docs/new-document.md`` describes)."""
    from pathlib import Path

    here = Path(__file__).parent
    added = sorted(
        p.name
        for p in here.iterdir()
        if p.name not in DOCS and (p / "study.py").is_file() and (p / "claims.py").is_file()
    )
    return (*DOCS, *added)


def claims_of(doc: str):
    """``(CLAIMS, STUDY)`` of one document: its :class:`ClaimSet` and its study class
    (module ``abglib.replications.<doc>.claims``)."""
    import importlib

    from .._checks import AbglibValueError

    if doc not in documents():
        raise AbglibValueError(f"doc must be one of {list(documents())}, got {doc!r}")
    mod = importlib.import_module(f"{__name__}.{doc}.claims")
    return mod.CLAIMS, mod.STUDY


def study_of(doc: str):
    """The study class of one document, from ``abglib.replications.<doc>.study`` alone
    (without its claims, so that the study's job does not depend on their code)."""
    import importlib

    from .._checks import AbglibValueError

    if doc not in documents():
        raise AbglibValueError(f"doc must be one of {list(documents())}, got {doc!r}")
    mod = importlib.import_module(f"{__name__}.{doc}.study")
    found = [
        v
        for v in vars(mod).values()
        if isinstance(v, type) and issubclass(v, Study) and v is not Study and v.doc == doc
    ]
    if len(found) != 1:
        raise AbglibValueError(
            f"{mod.__name__} must define exactly one Study subclass with doc = {doc!r}, "
            f"found {[c.__name__ for c in found]}"
        )
    return found[0]


def one_blas_thread():
    """A context in which BLAS/LAPACK run on one thread (threadpoolctl).

    The studies call LAPACK and BLAS on matrices of a few dozen entries, thousands of
    times: a pool of OpenBLAS threads only adds its wake-up and synchronisation to every
    call (``scipy.linalg.expm`` of a 7 x 7 matrix: 3.3 ms with two threads on a loaded
    2-core machine, 0.075 ms with one). Every table of both pipeline configs was checked
    byte-identical either way.
    """
    import scipy.linalg  # noqa: F401  (load scipy's own OpenBLAS: only loaded ones are limited)
    from threadpoolctl import threadpool_limits

    return threadpool_limits(limits=1, user_api="blas")


def study_tables(doc: str, config, published_paths) -> dict:
    """The report tables of one document's study at ``config`` (:meth:`Study.tables`), by
    file stem: the ``<doc>_study`` job, which reruns when the study's code or config
    changes, not when a claim's does."""
    from .compare import read_published

    published = read_published(published_paths)
    with one_blas_thread():
        return dict(study_of(doc)(config, published).tables())


def judge_claims(doc: str, config, published_paths, overrides=None) -> dict:
    """``{'comparison': ..., 'robustness': ...}`` of one document: every published claim
    judged (:func:`evaluate`) on a study built at ``config`` and at the points of its
    plausible ranges. The ``<doc>_claims`` job; it computes only what the claims use (the
    study's members are lazy)."""
    from .compare import read_published

    claims, study_cls = claims_of(doc)
    published = read_published(published_paths)
    with one_blas_thread():
        study = study_cls(config, published)
        comparison, robustness = evaluate(
            doc, claims, published, study, lambda c: study_cls(c, published), overrides
        )
    return {"comparison": comparison, "robustness": robustness}


def reproduce(doc: str, config, published_paths, overrides=None) -> dict:
    """Every table of one document's replication, by file stem.

    Builds the study at ``config`` (``{doc: section, ...}``), takes its report tables
    (:meth:`Study.tables`) and judges every published claim (:func:`evaluate`): the
    result holds ``comparison`` (``shared/CONTRACTS.md`` section 3) and ``robustness``
    (every point of every sweep over an assumed input) beside the study's own tables.
    """
    from .compare import read_published

    claims, study_cls = claims_of(doc)
    published = read_published(published_paths)
    with one_blas_thread():
        study = study_cls(config, published)
        tables = dict(study.tables())
        comparison, robustness = evaluate(
            doc, claims, published, study, lambda c: study_cls(c, published), overrides
        )
    tables["comparison"] = comparison
    tables["robustness"] = robustness
    return tables
