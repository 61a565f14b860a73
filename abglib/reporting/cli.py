"""The ``abglib`` command: ``verify``, ``release``, ``changes``, ``precision`` and ``findings``.

``abglib verify``
    Compare the tables of a build (default ``results/reports/v<version>``, what
    ``snakemake -c2`` writes) with a release folder (default the committed
    ``reports/v<version>``) within the precision each number is written to; print, per
    document, the rows compared, the verdicts that are identical and the largest
    deviation and where; exit 1 on any difference.
``abglib release``
    Cut a release: copy a build to ``reports/v<version>``. The one deliberate step that
    writes the committed release (a build never does); it refuses to replace an existing
    release folder without ``--force``, and refuses a build whose pages do not state the
    provenance of one build of that version (``abglib.reporting.provenance.release_problems``:
    each page's abglib version is the release's, one commit, one set of dependency versions).
``abglib changes OLD NEW``
    What changed between two version folders (e.g. ``reports/v0.2.0`` and
    ``reports/v0.3.0``, or a build's ``results/reports/v<version>``), per document: rows
    added or removed, verdicts changed, reproduced values moved beyond their tolerance,
    notes changed under the same verdict and value. Prints the counts; writes
    ``changes.csv`` and ``changes.html`` to ``--out``.
``abglib precision``
    Derive the digits every table column is reproducible to, by building the tables plain
    and under several perturbations of the arithmetic (:mod:`abglib.reporting.precision`),
    and write them to ``abglib/common/_precision_table.py``; a text cell (a note, a
    verdict) that moves is listed and makes it exit 1.
``abglib findings``
    Rewrite the README's findings from the release's tables (``docs/readme_findings.md`` is the
    template); ``--check`` only reports whether the README is current.
"""

from __future__ import annotations

import argparse
import os
import shutil
import sys
from pathlib import Path

from .. import __version__
from .verify import compare_folders, format_report

BUILD = Path("results") / "reports" / f"v{__version__}"
RELEASE = Path("reports") / f"v{__version__}"
#: What ``abglib --help`` says first (the module docstring's first line, without its markup).
DESCRIPTION = (
    "abglib's command: verify a build against a release, cut a release, list the changes "
    "between two versions, derive the tables' precision, rewrite the README's findings."
)


def _at_least(low: int):
    """An argparse ``type``: an integer ``>= low``; anything else is refused by name."""

    def parse(text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"must be an integer >= {low}, got {text!r}") from None
        if value < low:
            raise argparse.ArgumentTypeError(f"must be an integer >= {low}, got {value}")
        return value

    parse.__name__ = f"integer >= {low}"
    return parse


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="abglib", description=DESCRIPTION)
    p.add_argument("--version", action="version", version=f"abglib {__version__}")
    sub = p.add_subparsers(dest="command", required=True)
    v = sub.add_parser("verify", help="compare a build's tables with a release")
    v.add_argument("build", nargs="?", type=Path, default=BUILD, help=f"default: {BUILD}")
    v.add_argument("--release", type=Path, default=RELEASE, help=f"default: {RELEASE}")
    v.add_argument(
        "--limit", type=_at_least(0), default=5, help="differences listed per document (>= 0)"
    )
    v.add_argument(
        "--partial",
        action="store_true",
        help="compare only the tables the build has (a build of some documents or tables)",
    )
    r = sub.add_parser("release", help="copy a build to reports/v<version>")
    r.add_argument("build", nargs="?", type=Path, default=BUILD, help=f"default: {BUILD}")
    r.add_argument("--to", type=Path, default=RELEASE, help=f"default: {RELEASE}")
    r.add_argument("--force", action="store_true", help="replace an existing release folder")
    c = sub.add_parser("changes", help="what changed between two version folders")
    c.add_argument("old", type=Path, help="the older version folder, e.g. reports/v0.2.0")
    c.add_argument("new", type=Path, help="the newer version folder, e.g. reports/v0.3.0")
    c.add_argument(
        "--out",
        type=Path,
        default=None,
        help="folder for changes.csv and changes.html (default: print the counts only)",
    )
    pr = sub.add_parser("precision", help="derive each table column's reproducible digits")
    pr.add_argument(
        "--configfile",
        type=Path,
        action="append",
        help="config(s) to build (default: config.yaml and tests/data/config_small.yaml)",
    )
    pr.add_argument(
        "--runs", type=_at_least(2), default=3, help="perturbation seeds, >= 2 (default 3)"
    )
    pr.add_argument("--cores", type=_at_least(1), default=2, help="cores (default 2)")
    pr.add_argument("--check", action="store_true", help="exit 1 if the table would change")
    f = sub.add_parser("findings", help="rewrite the README's findings from a release")
    f.add_argument("--release", type=Path, default=RELEASE, help=f"default: {RELEASE}")
    f.add_argument("--readme", type=Path, default=Path("README.md"))
    f.add_argument("--template", type=Path, default=Path("docs") / "readme_findings.md")
    f.add_argument("--check", action="store_true", help="exit 1 if the README is not current")
    return p


def verify(build: Path, release: Path, limit: int = 5, partial: bool = False) -> int:
    for what, folder in (("build", build), ("release", release)):
        if partial and folder.is_dir():
            continue
        if not (folder / "index.html").is_file():
            print(
                f"abglib verify: no {what} at {folder} (no index.html there); "
                + (
                    "run `snakemake -c2` first"
                    if what == "build"
                    else "give the release folder with --release"
                ),
                file=sys.stderr,
            )
            return 2
    reports = compare_folders(release, build, partial)
    print(f"abglib verify: build {build} against release {release}")
    print(format_report(reports, limit))
    if sum(r.tables for r in reports) == 0:
        print(f"abglib verify: no table of {release} found in {build}", file=sys.stderr)
        return 1
    bad = [r.doc for r in reports if not r.ok]
    if bad:
        print(f"DIFFERENT: {', '.join(bad)}", file=sys.stderr)
        return 1
    print("identical within the written precision; verdicts identical")
    return 0


def release(build: Path, to: Path, force: bool = False) -> int:
    from .._checks import AbglibValueError
    from .provenance import release_problems
    from .versions import folder_version

    if not (build / "index.html").is_file():
        print(f"abglib release: no build at {build}; run `snakemake -c2` first", file=sys.stderr)
        return 2
    try:
        version = folder_version(to)
    except AbglibValueError as exc:
        print(f"abglib release: {exc}", file=sys.stderr)
        return 2
    problems = release_problems(build, version)
    if problems:
        print(
            f"abglib release: the build {build} does not state the provenance of one build of "
            f"version {version}:\n  " + "\n  ".join(problems) + "\n"
            f"(this abglib is {__version__}; render every page in one build of it: remove "
            f"{build} and run `snakemake -c2`)",
            file=sys.stderr,
        )
        return 2
    if to.exists():
        if not force:
            print(
                f"abglib release: {to} exists; a release is replaced only on purpose: add --force",
                file=sys.stderr,
            )
            return 2
        shutil.rmtree(to)
    shutil.copytree(build, to)
    print(f"released {build} -> {to}; review `git status {to}` and commit it")
    return 0


def findings(release: Path, readme: Path, template: Path, check: bool) -> int:
    from .._checks import AbglibValueError
    from .readme_findings import update_readme

    try:
        same = update_readme(readme, template, release, check=check)
    except AbglibValueError as exc:
        print(f"abglib {exc}", file=sys.stderr)
        return 2
    if check and not same:
        print(f"{readme}: findings differ from {release}; run `abglib findings`", file=sys.stderr)
        return 1
    print(f"{readme}: findings {'current' if same else 'rewritten'} from {release}")
    return 0


def changes(old: Path, new: Path, out: Path | None) -> int:
    from .._checks import AbglibValueError
    from .changes import diff_folders, write_changes

    try:
        ch = diff_folders(old, new)
    except AbglibValueError as exc:
        print(f"abglib changes: {exc}", file=sys.stderr)
        return 2
    print(f"abglib changes: {ch.new} ({new}) against {ch.old} ({old})")
    print(ch.counts().to_string(index=False))
    if out is not None:
        # links to the reports resolve when the page sits in the newer version folder
        links = {d: f"{d}/index.html" for d in ch.docs if (new / d / "index.html").is_file()}
        if out.resolve() != new.resolve():
            links = {d: os.path.relpath(new / h, out) for d, h in links.items()}
        write_changes(ch, out / "changes.csv", out / "changes.html", links)
        print(f"wrote {out / 'changes.csv'} and {out / 'changes.html'}")
    return 0


def precision(configfiles, runs: int, cores: int, check: bool) -> int:
    from . import precision as prec

    repo = Path(prec.__file__).resolve().parents[2]
    configs = configfiles or [repo / "config.yaml", repo / "tests" / "data" / "config_small.yaml"]
    missing = [str(c) for c in configs if not Path(c).is_file()]
    if missing:
        print(f"abglib precision: no config file {', '.join(missing)}", file=sys.stderr)
        return 2
    specs, derivations = prec.derive_precision(configs, runs, cores)
    moved = [t for d in derivations for t in d.text_differences]
    problems = [p for d in derivations for p in d.problems]
    for cfg, d in zip(configs, derivations, strict=True):
        ro = sum(c.roundoff_cells for c in d.columns)
        fewer = sum(1 for c in d.columns if c.spec is not None)
        print(
            f"{cfg}: {len(d.columns)} float columns, {fewer} with fewer digits or a bound, "
            f"{ro} round-off cells"
        )
    for table, row, col, a, b in moved[:40]:
        print(f"  text moved: {table}, row {row}, {col}: {a!r} -> {b!r}")
    for p in problems[:40]:
        print(f"  problem: {p}")
    from ..common import tables

    target = Path(tables.__file__).with_name("_precision_table.py")
    how = f"abglib precision --runs {runs} on {', '.join(Path(c).name for c in configs)}"
    if check:
        from ..common._precision_table import PRECISION

        same = PRECISION == specs
        print(f"{target}: {'current' if same else 'would change'}")
        return 0 if same and not moved and not problems else 1
    prec.write_table_module(specs, target, how)
    print(f"wrote {target} ({sum(len(v) for v in specs.values())} column specs)")
    return 1 if moved or problems else 0


def main(argv=None) -> int:
    args = _parser().parse_args(argv)
    if args.command == "verify":
        return verify(args.build, args.release, args.limit, args.partial)
    if args.command == "changes":
        return changes(args.old, args.new, args.out)
    if args.command == "precision":
        return precision(args.configfile, args.runs, args.cores, args.check)
    if args.command == "findings":
        return findings(args.release, args.readme, args.template, args.check)
    return release(args.build, args.to, args.force)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
