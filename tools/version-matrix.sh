#!/usr/bin/env bash
# Version matrix (issue 22): both ends of the supported range, each in a fresh virtual
# environment, run the small pipeline and the unit tests; then the two builds must give
# identical verdicts and their tables must verify against each other (abglib verify).
#
#   lowest  Python 3.11, the lowest version of every direct dependency
#           (uv pip install --resolution lowest-direct -e ".[pipeline,test,kernel]")
#   newest  Python 3.13, the newest versions (uv pip install -e ".[dev]")
#
# Neither end installs the slurm extra (Snakemake's generic cluster executor): only the
# slurm-marked tests use it, and they need a cluster (.ci/run runs them once, with the
# newest versions).
#
# Each session runs:
#   - the small pipeline: snakemake -s <repo>/Snakefile -d <session>/build
#     --configfile tests/data/config_small.yaml -c2 (its comparison tables, scorecard and
#     reports are written under <session>/build/results);
#   - the unit tests: pytest -m "not pipeline and not install and not slurm and not browser
#     and not docs" (the pipeline-marked tests build the same small config again, which the
#     session has just done; install and slurm run once in .ci/run, browser needs Chromium,
#     docs needs the docs extra; .ci/run's own pytest runs them once with the newest versions).
# numba's compile cache goes to the session's folder, so that neither end overwrites the
# other's (or the developer's) cache in the source tree.
#
# Usage: tools/version-matrix.sh [lowest] [newest]   (default: both, then the comparison;
#        the comparison runs whenever both sessions' builds exist in MATRIX_DIR)
#        tools/version-matrix.sh -h | --help           (this usage, in short)
# Env:   MATRIX_DIR   where the sessions live (default: a new ${TMPDIR:-/tmp}/abglib-matrix.*);
#                     each session's logs and installed versions are kept there
#        UV           the uv binary (default: uv on PATH, else pip-installed into MATRIX_DIR)
#        UV_CACHE_DIR uv's cache (default: ~/.cache/abglib-uv, outside the repository)
#        PY311, PY313 the interpreters (default: the newest pyenv 3.11.x / 3.13.x)
# A failed step is reported with the tail of its log and the rest still runs; the script exits
# non-zero at the end if any step failed.
set -euo pipefail

usage() {
    cat <<'USAGE'
Usage: tools/version-matrix.sh [lowest] [newest]
Runs each named session (default: both) in a fresh virtual environment: the small pipeline
and the unit tests. When both sessions' builds exist in MATRIX_DIR, it then checks that their
verdicts are identical and that their tables pass abglib verify against each other.
  lowest        Python 3.11, the lowest version of every direct dependency
  newest        Python 3.13, the newest versions
Environment:
  MATRIX_DIR    where the sessions live (default: a new ${TMPDIR:-/tmp}/abglib-matrix.*)
  UV            the uv binary (default: uv on PATH, else pip-installed into MATRIX_DIR)
  UV_CACHE_DIR  uv's cache (default: ~/.cache/abglib-uv)
  PY311, PY313  the interpreters (default: the newest pyenv 3.11.x / 3.13.x)
USAGE
}
# the arguments are checked before anything is created or installed
for s in "$@"; do
    case "$s" in
        lowest | newest) ;;
        -h | --help) usage; exit 0 ;;
        *) echo "!! unknown session '$s' (lowest or newest)" >&2; usage >&2; exit 1 ;;
    esac
done

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
matrix="${MATRIX_DIR:-$(mktemp -d "${TMPDIR:-/tmp}/abglib-matrix.XXXXXX")}"
mkdir -p "$matrix"
export UV_CACHE_DIR="${UV_CACHE_DIR:-$HOME/.cache/abglib-uv}"
export PIP_DISABLE_PIP_VERSION_CHECK=1
marks="not pipeline and not install and not slurm and not browser and not docs"
sessions=("$@")
[ ${#sessions[@]} -gt 0 ] || sessions=(lowest newest)

failed=()
fail() { # fail MESSAGE [LOG]: report (with the log's tail) and go on; the exit status says it
    echo "!! $1" >&2
    [ -n "${2:-}" ] && [ -f "$2" ] && { tail -n 40 "$2" >&2; echo "!! full log: $2" >&2; }
    failed+=("$1")
}
die() { fail "$@"; exit 1; }
activate() { export VIRTUAL_ENV="$1" PATH="$1/bin:$PATH"; } # activate VENV (in a subshell)

# uv: the one on PATH, else a private copy
uv="${UV:-$(command -v uv || true)}"
if [ -z "$uv" ]; then
    echo "== pip install uv (into $matrix/uv)"
    python3 -m venv "$matrix/uv" && "$matrix/uv/bin/pip" install --quiet uv
    uv="$matrix/uv/bin/uv"
fi

# the newest installed patch release of a Python minor version (pyenv), else pythonX.Y
interpreter() {
    local minor=$1 root found
    root="$(pyenv root 2>/dev/null || echo "$HOME/.pyenv")"
    found="$(ls -d "$root"/versions/"$minor".* 2>/dev/null | sort -V | tail -n 1)"
    if [ -n "$found" ] && [ -x "$found/bin/python" ]; then echo "$found/bin/python"
    elif command -v "python$minor" >/dev/null; then command -v "python$minor"
    else die "no Python $minor (pyenv install $minor, or set PY${minor/./})"; fi
}

run_session() {
    local name=$1 python extras resolution=() dir venv t0 t
    case "$name" in
        lowest) python="${PY311:-$(interpreter 3.11)}"; extras="pipeline,test,kernel"
                resolution=(--resolution lowest-direct) ;;
        newest) python="${PY313:-$(interpreter 3.13)}"; extras="dev" ;;
        *) die "unknown session '$name' (lowest or newest)" ;;
    esac
    [ -n "$python" ] || die "[$name] no interpreter"
    dir="$matrix/$name"
    venv="$dir/venv"
    rm -rf "$dir" && mkdir -p "$dir"
    echo "== [$name] $("$python" --version) in $dir"

    t0=$SECONDS
    "$uv" venv --quiet --python "$python" "$venv" >"$dir/install.log" 2>&1 \
        || { fail "[$name] uv venv failed" "$dir/install.log"; return; }
    (cd "$repo" && "$uv" pip install --python "$venv/bin/python" "${resolution[@]}" \
        -e ".[$extras]") >>"$dir/install.log" 2>&1 \
        || { fail "[$name] install failed" "$dir/install.log"; return; }
    "$uv" pip freeze --python "$venv/bin/python" >"$dir/versions.txt" 2>/dev/null
    echo "== [$name] installed in $((SECONDS - t0)) s: $(grep -iE \
        '^(numpy|scipy|numba|pandas|matplotlib|snakemake|ipython|pyarrow)==' \
        "$dir/versions.txt" | tr '\n' ' ')"

    export NUMBA_CACHE_DIR="$dir/numba-cache"
    t0=$SECONDS
    # this end's venv is the active one for its build and tests (a caller's VIRTUAL_ENV,
    # .ci/run's own, made IPython warn "Attempting to work in a virtualenv")
    (cd "$repo" && activate "$venv" && "$venv/bin/snakemake" -s "$repo/Snakefile" -d "$dir/build" \
        --configfile "$repo/tests/data/config_small.yaml" -c2) >"$dir/snakemake.log" 2>&1 \
        && touch "$dir/build.ok" || fail "[$name] small pipeline failed" "$dir/snakemake.log"
    echo "== [$name] small pipeline in $((SECONDS - t0)) s ($dir/snakemake.log)"

    t0=$SECONDS
    (cd "$repo" && activate "$venv" && "$venv/bin/pytest" -p no:cacheprovider -q -m "$marks") \
        >"$dir/pytest.log" 2>&1 || fail "[$name] unit tests failed" "$dir/pytest.log"
    echo "== [$name] unit tests in $((SECONDS - t0)) s: $(tail -n 1 "$dir/pytest.log")"
    unset NUMBA_CACHE_DIR
}

for s in "${sessions[@]}"; do run_session "$s"; done

low="$matrix/lowest/build/results"
new="$matrix/newest/build/results"
if [ ! -f "$matrix/lowest/build.ok" ] || [ ! -f "$matrix/newest/build.ok" ]; then
    echo "== not both builds: no comparison (logs in $matrix)"
    [ ${#failed[@]} = 0 ] || die "${#failed[@]} step(s) failed: ${failed[*]}"
    exit 0
fi
py="$matrix/newest/venv/bin/python"

echo "== verdicts: results/*/comparison.csv and results/scorecard.csv, lowest against newest"
"$py" - "$low" "$new" <<'EOF' || fail "verdicts differ between the two ends"
import csv
import sys
from pathlib import Path

low, new = (Path(p) for p in sys.argv[1:3])
# a row is named by doc, item, quantity; its verdict by verdict and robust (CONTRACTS.md §3)
KEY, VERDICT = ("doc", "item", "quantity"), ("verdict", "robust")


def rows(path):
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


files = sorted(p.relative_to(low) for p in low.glob("*/comparison.csv"))
other = sorted(p.relative_to(new) for p in new.glob("*/comparison.csv"))
bad = [] if files == other else [f"comparison tables: lowest {files}, newest {other}"]
n = 0
for rel in files:
    a, b = rows(low / rel), rows(new / rel)
    cols = [c for c in VERDICT if a and c in a[0]]
    pick = [[tuple(r[c] for c in KEY + tuple(cols)) for r in t] for t in (a, b)]
    n += len(pick[0])
    if pick[0] != pick[1]:
        diff = [(x, y) for x, y in zip(*pick, strict=False) if x != y][:5]
        bad.append(f"{rel}: {len(a)} rows against {len(b)}; first differences {diff}")
if rows(low / "scorecard.csv") != rows(new / "scorecard.csv"):
    bad.append("scorecard.csv differs")
for b in bad:
    print("  " + b)
print(f"  {n} verdicts in {len(files)} comparison tables; scorecard.csv", "identical" if not
      bad else "DIFFERENT")
sys.exit(1 if bad else 0)
EOF

version="$("$py" -c 'import abglib; print(abglib.__version__)')"
abglib="$matrix/newest/venv/bin/abglib"
for pair in "lowest newest" "newest lowest"; do
    set -- $pair
    echo "== abglib verify: $1's tables against $2's ($matrix/verify-$1-vs-$2.log)"
    if "$abglib" verify "$matrix/$1/build/results/reports/v$version" \
        --release "$matrix/$2/build/results/reports/v$version" --limit 20 \
        >"$matrix/verify-$1-vs-$2.log" 2>&1; then
        tail -n 1 "$matrix/verify-$1-vs-$2.log"
    else
        cat "$matrix/verify-$1-vs-$2.log" >&2
        fail "abglib verify: $1's tables against $2's"
    fi
done
[ ${#failed[@]} = 0 ] || die "${#failed[@]} step(s) failed: ${failed[*]} (logs in $matrix)"
echo "== version matrix passed (logs in $matrix)"
