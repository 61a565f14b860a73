"""LICENSE and CITATION.cff: how abglib is licensed and cited, and the five sources it cites.

``CITATION.cff`` (Citation File Format 1.2.0; ``cffconvert --validate`` accepts it, run by
hand: cffconvert pins ``jsonschema<4``, which the pipeline's ``jsonschema>=4`` excludes from
this environment) is checked here for the keys the format requires and for its references:
one per source document, each as the README's table of the five documents states it, and
as the project's index of sources (``shared/seeds/README.md``, beside the repository, not
in a clone elsewhere) names it.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
import tomllib
import zipfile
from datetime import date
from pathlib import Path

import pytest
import yaml

import abglib
from abglib.reporting.versions import version_key

from .conftest import require

REPO = Path(__file__).resolve().parents[1]
SEEDS = REPO.parent / "shared" / "seeds" / "README.md"
#: The source documents' keys (shared/seeds/README.md, column ``key``), seeds 000-004.
KEYS = ("steelman1978", "alwagih", "huang", "faa_bendix", "antenna")


@pytest.fixture(scope="module")
def cff() -> dict:
    return yaml.safe_load((REPO / "CITATION.cff").read_text(encoding="utf-8"))


def _seed_rows() -> dict[str, str]:
    """``{key: document cell}`` of the index of sources' table."""
    rows = {}
    for line in SEEDS.read_text(encoding="utf-8").splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) >= 3 and cells[1] in KEYS:
            rows[cells[1]] = cells[2]
    return rows


def _key(ref: dict) -> str:
    m = re.search(r"\bkey (\w+)", ref.get("notes", ""))
    assert m, f"reference {ref['title']!r}: its notes name no source key"
    return m.group(1)


def test_license_is_mit_as_the_package_says():
    text = (REPO / "LICENSE").read_text(encoding="utf-8")
    assert text.startswith("MIT License\n\nCopyright (c) 2026 the abglib developers\n")
    assert "Permission is hereby granted, free of charge" in text
    meta = tomllib.loads((REPO / "pyproject.toml").read_text(encoding="utf-8"))
    assert meta["project"]["license"] in ({"text": "MIT"}, "MIT")


def test_citation_has_the_keys_the_format_requires(cff):
    assert cff["cff-version"] == "1.2.0"
    for key in ("message", "title", "authors", "version", "date-released", "license", "type"):
        assert cff.get(key), key
    assert cff["type"] == "software" and cff["license"] == "MIT"
    assert cff["authors"] == [{"name": "The abglib developers"}]
    assert "repository-code" not in cff  # no public address yet
    assert isinstance(cff["date-released"], date)
    # the citation names the release being cut or the code's own: never an older one
    assert version_key(f"v{cff['version']}") >= version_key(f"v{abglib.__version__}")
    for ref in cff["references"]:
        assert ref["type"] in ("report", "article") and ref["title"] and ref["authors"], ref


def _check_references(refs: dict, rows: dict[str, str]) -> None:
    """Each reference of CITATION.cff as the table row ``rows[key]`` states the document."""
    assert sorted(rows) == sorted(KEYS)
    for key, ref in refs.items():
        doc = rows[key]
        # the title as the table prints it (in *italics*; the antenna report has none)
        assert f"*{ref['title']}*" in doc or (key == "antenna" and doc.startswith(ref["title"]))
        for person in ref["authors"]:
            if "family-names" in person:
                assert person["family-names"] in doc, (key, person)
        if "institution" in ref:
            assert ref["institution"]["name"] in doc, key
        for field in ("number", "year"):
            if field in ref:
                assert str(ref[field]) in doc, (key, field)
    assert refs["steelman1978"]["month"] == 9 and "September 1978" in rows["steelman1978"]
    assert "Sinsky" in refs["faa_bendix"]["notes"] and "Sinsky" in rows["faa_bendix"]


def _readme_rows() -> dict[str, str]:
    """``{key: document cell}`` of the README's table of the five source documents."""
    rows = {}
    for line in (REPO / "README.md").read_text(encoding="utf-8").splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 4 and cells[1].strip("`") in KEYS:
            rows[cells[1].strip("`")] = cells[3]
    return rows


def test_citation_references_the_five_source_documents_as_the_readme_does(cff):
    refs = {_key(ref): ref for ref in cff["references"]}
    assert sorted(refs) == sorted(KEYS) and len(cff["references"]) == len(KEYS)
    _check_references(refs, _readme_rows())


def test_citation_references_the_five_source_documents_as_the_index_does(cff):
    """Against the project's index of sources itself (beside the repository: present on
    the project's machines and CI, where its absence fails; a clone elsewhere skips)."""
    if not SEEDS.is_file():
        require(f"the index of sources {SEEDS} is not beside the repository")
    _check_references({_key(ref): ref for ref in cff["references"]}, _seed_rows())


@pytest.mark.install
def test_the_wheel_carries_the_license(tmp_path):
    """``pip wheel`` of the package (its sources copied out, so that no ``build/`` or stale
    ``abglib.egg-info`` is left in the checkout) puts LICENSE in the wheel's metadata.
    setuptools includes ``LICEN[CS]E*`` by default from the declared floor (68) to today's
    release, so pyproject.toml names no ``license-files`` (``project.license-files`` needs
    setuptools 77; ``tool.setuptools.license-files`` is deprecated from 77 on)."""
    src = tmp_path / "src"
    shutil.copytree(REPO / "abglib", src / "abglib", ignore=shutil.ignore_patterns("__pycache__"))
    for name in ("pyproject.toml", "README.md", "LICENSE"):
        shutil.copyfile(REPO / name, src / name)
    out = subprocess.run(
        [sys.executable, "-m", "pip", "wheel", "--no-deps", "-q", "-w", str(tmp_path), str(src)],
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert out.returncode == 0, out.stderr[-3000:]
    (wheel,) = tmp_path.glob("abglib-*.whl")
    with zipfile.ZipFile(wheel) as zf:
        names = zf.namelist()
        (meta,) = [n for n in names if n.endswith(".dist-info/METADATA")]
        text = zf.read(meta).decode("utf-8")
        (lic,) = [n for n in names if n.endswith("LICENSE") and ".dist-info/" in n]
        assert zf.read(lic) == (REPO / "LICENSE").read_bytes()
    assert "License-File: LICENSE" in text
