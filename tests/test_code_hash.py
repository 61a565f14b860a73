"""Per-rule code hashes (abglib.reporting.codehash): a rule depends on the abglib code it
imports, read statically, without docstrings or comments."""

from pathlib import Path

import pytest

from abglib import AbglibValueError
from abglib.reporting.codehash import code_fingerprint, code_hash, module_closure

REPO = Path(__file__).resolve().parents[1]


def _package(tmp_path) -> Path:
    pkg = tmp_path / "pkg"
    (pkg / "sub").mkdir(parents=True)
    (pkg / "__init__.py").write_text('"""Top."""\nfrom .core import f\n')
    (pkg / "core.py").write_text('"""Core."""\n\n\ndef f():\n    """Doc."""\n    return 1\n')
    (pkg / "sub" / "__init__.py").write_text("")
    (pkg / "sub" / "a.py").write_text(
        "def g():\n    from ..other import h  # lazy\n    return h()\n"
    )
    (pkg / "sub" / "b.py").write_text("from . import a\nfrom .a import g\n")
    (pkg / "other.py").write_text("import numpy\n\n\ndef h():\n    return 2\n")
    (pkg / "unused.py").write_text("x = 1\n")
    return pkg


def _names(files, pkg):
    return sorted(f.relative_to(pkg).as_posix() for f in files)


def test_closure_follows_relative_lazy_and_parent_imports(tmp_path):
    pkg = _package(tmp_path)
    got = _names(module_closure(["pkg.sub.b"], pkg), pkg)
    assert got == ["__init__.py", "core.py", "other.py", "sub/__init__.py", "sub/a.py", "sub/b.py"]
    assert _names(module_closure(["pkg.core"], pkg), pkg) == ["__init__.py", "core.py"]
    script = tmp_path / "script.py"
    script.write_text("import os\nfrom pkg.other import h\n")
    # pkg/__init__ runs first and imports core
    assert _names(module_closure([str(script)], pkg), pkg) == ["__init__.py", "core.py", "other.py"]


def test_a_module_added_or_removed_is_seen_by_the_next_closure(tmp_path):
    # the package's module index is kept between calls while no directory changes
    pkg = _package(tmp_path)
    assert _names(module_closure(["pkg.sub.b"], pkg), pkg)[-1] == "sub/b.py"
    (pkg / "sub" / "c.py").write_text("x = 2\n")
    (pkg / "sub" / "b.py").write_text("from . import a, c\n")
    assert "sub/c.py" in _names(module_closure(["pkg.sub.b"], pkg), pkg)
    (pkg / "sub" / "deeper").mkdir()
    (pkg / "sub" / "deeper" / "__init__.py").write_text("")
    (pkg / "sub" / "b.py").write_text("from . import deeper\n")
    assert "sub/deeper/__init__.py" in _names(module_closure(["pkg.sub.b"], pkg), pkg)
    (pkg / "sub" / "deeper" / "__init__.py").unlink()
    (pkg / "sub" / "deeper").rmdir()
    assert "sub/deeper/__init__.py" not in _names(module_closure(["pkg.sub.b"], pkg), pkg)


def test_docstrings_and_comments_do_not_change_the_hash_code_does(tmp_path):
    pkg = _package(tmp_path)
    h = code_hash("pkg.sub.b", package_dir=pkg)
    fp = code_fingerprint(pkg / "core.py")
    (pkg / "core.py").write_text(
        '"""Core, edited."""\n# a comment\n\ndef f():\n    """Other doc."""\n\n    return 1\n'
    )
    assert code_fingerprint(pkg / "core.py") == fp
    assert code_hash("pkg.sub.b", package_dir=pkg) == h
    (pkg / "unused.py").write_text("x = 2\n")  # not imported: no change
    assert code_hash("pkg.sub.b", package_dir=pkg) == h
    (pkg / "other.py").write_text("import numpy\n\n\ndef h():\n    return 3\n")
    assert code_hash("pkg.sub.b", package_dir=pkg) != h
    assert code_hash("pkg.core", package_dir=pkg) == code_hash("pkg.core", package_dir=pkg)


def test_extra_files_enter_the_hash(tmp_path):
    pkg = _package(tmp_path)
    user = tmp_path / "mine.py"
    user.write_text("def v(dt, n):\n    return (0.5, 0.2)\n")
    h = code_hash("pkg.core", package_dir=pkg, extra=[user])
    user.write_text('"""Doc."""\ndef v(dt, n):\n    return (0.5, 0.2)\n')
    assert code_hash("pkg.core", package_dir=pkg, extra=[user]) == h
    user.write_text("def v(dt, n):\n    return (0.5, 0.3)\n")
    assert code_hash("pkg.core", package_dir=pkg, extra=[user]) != h


def test_bad_sources_are_refused(tmp_path):
    pkg = _package(tmp_path)
    with pytest.raises(AbglibValueError, match="neither a module of pkg nor a file"):
        code_hash("pkg.nope", package_dir=pkg)
    bad = tmp_path / "bad.py"
    bad.write_text("def (:\n")
    with pytest.raises(AbglibValueError, match="cannot read Python source"):
        code_fingerprint(bad)


def test_the_study_of_a_document_does_not_depend_on_its_claims():
    pkg = REPO / "abglib"
    for doc in ("steelman1978", "alwagih", "huang", "faa_bendix", "antenna"):
        study = _names(module_closure([f"abglib.replications.{doc}.study"], pkg), pkg)
        claims = _names(module_closure([f"abglib.replications.{doc}.claims"], pkg), pkg)
        assert f"replications/{doc}/claims.py" not in study
        assert f"replications/{doc}/claims.py" in claims
        assert set(study) <= set(claims)
    cell = _names(module_closure(["abglib.bench.cell"], pkg), pkg)
    assert "engine.py" in cell and "bench/metrics.py" in cell
    assert not [f for f in cell if f.startswith("replications/")]


def test_the_disk_cache_changes_no_hash(tmp_path):
    pkg = _package(tmp_path)
    cache = tmp_path / "cache.json"
    h = code_hash("pkg.sub.b", package_dir=pkg)
    assert code_hash("pkg.sub.b", package_dir=pkg, cache=cache) == h
    assert cache.is_file() and "core.py" in cache.read_text()
    assert code_hash("pkg.sub.b", package_dir=pkg, cache=cache) == h
    (pkg / "other.py").write_text("def h():\n    return 3\n")  # new size: a new entry
    h2 = code_hash("pkg.sub.b", package_dir=pkg, cache=cache)
    assert h2 != h
    cache.write_text("{not json")
    code_hash("pkg.core", package_dir=pkg, cache=tmp_path / "other.json")
    assert code_hash("pkg.sub.b", package_dir=pkg, cache=cache) == h2


def test_no_job_imports_the_hash_machinery():
    """Changing how code is hashed reruns no job: no script, notebook or run: module
    imports abglib.reporting.codehash."""
    pkg = REPO / "abglib"
    sources = [
        *map(str, (REPO / "workflow" / "scripts").glob("*.py")),
        *map(str, (REPO / "workflow" / "notebooks").glob("*.py")),
        "abglib.bench.cell",
        "abglib.bench.datasets",
    ]
    assert "reporting/codehash.py" not in _names(module_closure(sources, pkg), pkg)


def test_imports_and_docstrings_are_found_in_every_kind_of_block(tmp_path):
    """Imports inside if/else, try/except/finally, with, for/while, match cases and
    nested classes and functions all enter the closure; nested docstrings do not enter
    the fingerprint."""
    pkg = tmp_path / "pkg"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("")
    names = ["m_if", "m_else", "m_try", "m_exc", "m_fin", "m_with", "m_for", "m_case", "m_cls"]
    for n in names:
        (pkg / f"{n}.py").write_text("")
    src = '''
if X:
    from . import m_if
else:
    import pkg.m_else
try:
    from .m_try import a
except ImportError:
    from . import m_exc
finally:
    from . import m_fin
with open(p) as fh:
    from . import m_with
for i in range(2):
    while True:
        from . import m_for
match v:
    case 1:
        from . import m_case
class C:
    """Doc."""
    def f(self):
        """Doc."""
        class D:
            from . import m_cls
'''
    (pkg / "main.py").write_text(src)
    got = _names(module_closure(["pkg.main"], pkg), pkg)
    assert got == sorted(["__init__.py", "main.py", *[f"{n}.py" for n in names]])
    other = tmp_path / "other.py"
    other.write_text(src.replace('"""Doc."""', '"""Other words."""'))
    assert code_fingerprint(other) == code_fingerprint(pkg / "main.py")
    other.write_text(src.replace("range(2)", "range(3)"))
    assert code_fingerprint(other) != code_fingerprint(pkg / "main.py")
