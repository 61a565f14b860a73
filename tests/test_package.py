"""The package's lazy submodules: every advertised name imports, every module is advertised."""

import importlib
import pkgutil

import pytest

import abglib

# helpers for the workflow only, not part of the advertised namespace
_INTERNAL = {"engine", "gains"}


def test_every_lazy_submodule_imports():
    for name in sorted(abglib._SUBMODULES):
        assert getattr(abglib, name) is importlib.import_module(f"abglib.{name}")


def test_every_public_module_is_advertised():
    found = {m.name for m in pkgutil.iter_modules(abglib.__path__) if not m.name.startswith("_")}
    assert found - _INTERNAL == abglib._SUBMODULES


def test_unknown_attribute_is_an_attribute_error():
    with pytest.raises(AttributeError, match="no attribute 'nonexistent'"):
        abglib.nonexistent  # noqa: B018


def test_version_matches_pyproject():
    import tomllib
    from pathlib import Path

    meta = tomllib.loads((Path(__file__).resolve().parents[1] / "pyproject.toml").read_text())
    assert meta["project"]["version"] == abglib.__version__
