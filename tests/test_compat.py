"""abglib._compat: every undocumented attribute of Snakemake, IPython (traitlets), pandas and
matplotlib that the project uses works on the installed versions, fails loudly (naming the
library, its version and the attribute) when taken away, and is used nowhere else.

Issue 22, item 4. Each accessor has two tests: on the real installed objects, and with the
attribute monkeypatched away or reshaped (the message is pinned). The last tests walk
abglib/, workflow/ and the Snakefile for private access outside abglib/_compat.
"""

from __future__ import annotations

import ast
import atexit
import gc
import io
import json
import subprocess
import sys
import threading
import tokenize
import weakref
from pathlib import Path
from types import SimpleNamespace

import pytest

from abglib._compat import UpstreamChanged, version_of


@pytest.fixture(autouse=True)
def _main_module_kept():
    """An InteractiveShell makes its namespace ``sys.modules["__main__"]`` (execute.py puts
    it back after a notebook); the shells built here must too, or a later test's
    multiprocessing (the fork server reads ``__main__.__spec__``) meets IPython's stand-in."""
    main = sys.modules.get("__main__")
    yield
    sys.modules["__main__"] = main


REPO = Path(__file__).resolve().parents[1]


def _message(distribution: str, attribute: str) -> str:
    """The start of :func:`abglib._compat.changed`'s message, as a regex."""
    import re

    return re.escape(f"{distribution} {version_of(distribution)}: {attribute}")


# ----------------------------------------------------------------------------- Snakemake

TINY_SNAKEFILE = """
import json
from abglib._compat import snakemake as c


rule make:
    output:
        "out/a.txt",
    params:
        value=7,
    shell:
        "echo a > {output}"


rule scripted:
    output:
        "out/{name}.dat",
    script:
        "s.py"


onstart:
    rules = {r.name: r for r in c.rules_of(workflow)}
    make = rules["make"]
    report = {
        "rules": sorted(rules),
        "jobs_run_here": c.jobs_run_here(workflow),
        "skip_validation": c.skip_validation(workflow),
        "make_produces": c.rule_produces(make, "out/a.txt"),
        "make_produces_other": c.rule_produces(make, "out/b.dat"),
        "scripted_produces": c.rule_produces(rules["scripted"], "out/b.dat"),
        "make_script": c.rule_script(make),
        "scripted_script": c.rule_script(rules["scripted"]),
        "snakefile": c.rule_snakefile(make),
        "value": c.rule_params(make).value,
        "limiter_before": workflow.scheduler.job_rate_limiter is not None,
        "removed": c.disable_job_rate_limit(workflow),
        "limiter_after": workflow.scheduler.job_rate_limiter,
        "removed_again": c.disable_job_rate_limit(workflow),
    }
    with open("report.json", "w") as fh:
        json.dump(report, fh)
"""


@pytest.fixture(scope="module")
def tiny_run(tmp_path_factory):
    """What the Snakemake accessors give inside a real local run (onstart) of a tiny
    workflow, on the installed Snakemake."""
    d = tmp_path_factory.mktemp("tiny")
    (d / "Snakefile").write_text(TINY_SNAKEFILE, encoding="utf-8")
    (d / "s.py").write_text("open(snakemake.output[0], 'w').close()\n", encoding="utf-8")
    exe = Path(sys.executable).parent / "snakemake"
    out = subprocess.run(
        [str(exe) if exe.exists() else "snakemake", "-c1", "out/a.txt"],
        cwd=d,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert out.returncode == 0, out.stdout[-2000:] + out.stderr[-3000:]
    return json.loads((d / "report.json").read_text(encoding="utf-8")), d


@pytest.mark.slow
def test_snakemake_accessors_in_a_real_run(tiny_run):
    report, d = tiny_run
    assert report["rules"] == ["make", "scripted"]
    assert report["jobs_run_here"] is True
    assert report["skip_validation"] is False
    assert report["make_produces"] is True
    assert report["make_produces_other"] is False
    assert report["scripted_produces"] is True  # wildcards matched
    assert report["make_script"] is None
    assert report["scripted_script"] == "s.py"
    assert Path(report["snakefile"]).resolve() == (d / "Snakefile").resolve()
    assert report["value"] == 7


@pytest.mark.slow
def test_the_rate_limiter_is_really_switched_off(tiny_run):
    report, _ = tiny_run
    # the default --max-jobs-per-timespan (100/1s) gives a local run a limiter
    assert report["limiter_before"] is True
    assert report["removed"] is True and report["limiter_after"] is None
    assert report["removed_again"] is False


def _scheduler_workflow(**scheduler):
    return SimpleNamespace(scheduler=SimpleNamespace(**scheduler))


def test_rate_limiter_missing_is_loud_not_quiet():
    from abglib._compat.snakemake import disable_job_rate_limit

    with pytest.raises(
        UpstreamChanged, match=_message("snakemake", "JobScheduler.job_rate_limiter")
    ):
        disable_job_rate_limit(_scheduler_workflow())
    with pytest.raises(UpstreamChanged, match=_message("snakemake", "Workflow.scheduler")):
        disable_job_rate_limit(SimpleNamespace())
    with pytest.raises(UpstreamChanged, match="is None in onstart"):
        disable_job_rate_limit(SimpleNamespace(scheduler=None))
    with pytest.raises(UpstreamChanged, match="not a JobRateLimiter"):
        disable_job_rate_limit(_scheduler_workflow(job_rate_limiter=object()))


def test_rate_limiter_shape_and_older_snakemake(monkeypatch):
    from abglib._compat import snakemake as c

    limiter = SimpleNamespace(timespan=1, get_free_jobs=lambda: 100)
    wf = _scheduler_workflow(job_rate_limiter=limiter)
    assert c.disable_job_rate_limit(wf) is True
    assert wf.scheduler.job_rate_limiter is None
    # Snakemake 8.0-8.16 have no job_rate_limiter (nor its timer chain): nothing to remove
    monkeypatch.setattr(c, "version_of", lambda dist: "8.16.0")
    assert c.disable_job_rate_limit(_scheduler_workflow()) is False
    monkeypatch.setattr(c, "version_of", lambda dist: "8.17.0")
    with pytest.raises(UpstreamChanged, match="job_rate_limiter does not exist"):
        c.disable_job_rate_limit(_scheduler_workflow())


def test_jobs_run_here_by_exec_mode_and_loud_without_it():
    from snakemake_interface_executor_plugins.settings import ExecMode

    from abglib._compat.snakemake import jobs_run_here

    assert jobs_run_here(SimpleNamespace(local_exec=True, exec_mode=ExecMode.DEFAULT))
    assert not jobs_run_here(SimpleNamespace(local_exec=True, exec_mode=ExecMode.SUBPROCESS))
    assert not jobs_run_here(SimpleNamespace(local_exec=True, exec_mode=ExecMode.REMOTE))
    assert not jobs_run_here(SimpleNamespace(local_exec=False, exec_mode=ExecMode.DEFAULT))
    with pytest.raises(UpstreamChanged, match=_message("snakemake", "Workflow.exec_mode")):
        jobs_run_here(SimpleNamespace(local_exec=True))
    with pytest.raises(UpstreamChanged, match=_message("snakemake", "Workflow.local_exec")):
        jobs_run_here(SimpleNamespace(exec_mode=ExecMode.DEFAULT))
    with pytest.raises(UpstreamChanged, match="not a bool"):
        jobs_run_here(SimpleNamespace(local_exec="yes", exec_mode=ExecMode.DEFAULT))
    with pytest.raises(UpstreamChanged, match="not an ExecMode"):
        jobs_run_here(SimpleNamespace(local_exec=True, exec_mode=0))


def test_the_workflow_properties_exist_on_the_installed_class():
    import snakemake.api  # noqa: F401 - snakemake.workflow needs it imported first
    from snakemake.rules import Rule
    from snakemake.workflow import Workflow

    for name in ("scheduler", "local_exec", "exec_mode", "modifier", "rules"):
        assert isinstance(vars(Workflow).get(name), property), name
    assert isinstance(vars(Rule).get("snakefile"), property)
    assert callable(vars(Rule).get("is_producer"))


def test_skip_validation_and_rules_loud_without_them():
    from abglib._compat import snakemake as c

    assert c.skip_validation(SimpleNamespace(modifier=SimpleNamespace(skip_validation=True)))
    with pytest.raises(UpstreamChanged, match=_message("snakemake", "WorkflowModifier.skip")):
        c.skip_validation(SimpleNamespace(modifier=SimpleNamespace()))
    with pytest.raises(UpstreamChanged, match=_message("snakemake", "Workflow.modifier")):
        c.skip_validation(SimpleNamespace())
    with pytest.raises(UpstreamChanged, match="not a bool"):
        c.skip_validation(SimpleNamespace(modifier=SimpleNamespace(skip_validation=None)))
    with pytest.raises(UpstreamChanged, match=_message("snakemake", "Workflow.rules")):
        c.rules_of(SimpleNamespace())
    with pytest.raises(UpstreamChanged, match=_message("snakemake", "Rule.is_producer")):
        c.rule_produces(SimpleNamespace(), "x")
    with pytest.raises(UpstreamChanged, match="returned a str, not a bool"):
        c.rule_produces(SimpleNamespace(is_producer=lambda p: "yes"), "x")
    with pytest.raises(UpstreamChanged, match=_message("snakemake", "Rule.script")):
        c.rule_script(SimpleNamespace())
    with pytest.raises(UpstreamChanged, match="not a str"):
        c.rule_script(SimpleNamespace(script=Path("s.py")))
    with pytest.raises(UpstreamChanged, match=_message("snakemake", "Rule.snakefile")):
        c.rule_snakefile(SimpleNamespace())
    with pytest.raises(UpstreamChanged, match=_message("snakemake", "Rule.params")):
        c.rule_params(SimpleNamespace())


def test_script_object_class_builds_what_script_jobs_see(tmp_path):
    from snakemake.iocontainers import Log, Namedlist, Params

    from abglib._compat.snakemake import script_object_class

    params = Params([3])
    params._set_name("value", 0)
    smk = script_object_class()(
        Namedlist([]), Namedlist([]), params, Namedlist([]), 2, Namedlist([]),
        Log([str(tmp_path / "x.log")]), {"k": 1}, "rule_x", 0, str(tmp_path),
    )  # fmt: skip
    assert (smk.params.value, smk.threads, smk.config, smk.rule) == (3, 2, {"k": 1}, "rule_x")
    assert smk.log[0] == str(tmp_path / "x.log")


def test_script_object_class_loud_when_moved_or_reshaped(monkeypatch):
    import snakemake.script

    from abglib._compat.snakemake import script_object_class

    class Other:
        def __init__(self, input_, output, params):
            pass

    monkeypatch.setattr(snakemake.script, "Snakemake", Other)
    with pytest.raises(UpstreamChanged, match=r"takes \(self, input_, output, params\)"):
        script_object_class()
    monkeypatch.delattr(snakemake.script, "Snakemake")
    with pytest.raises(UpstreamChanged, match=_message("snakemake", "snakemake.script.Snakemake")):
        script_object_class()


def test_common_smk_fails_loudly_when_the_rate_limiter_moved():
    """without_rate_limit (common.smk) goes through the compat module, no getattr that
    turns a moved attribute into a no-op."""
    text = (REPO / "workflow" / "rules" / "common.smk").read_text(encoding="utf-8")
    body = text.split("def without_rate_limit", 1)[1].split("\ndef ", 1)[0]
    assert "smk_compat.disable_job_rate_limit(workflow)" in body
    assert "getattr" not in body and "job_rate_limiter" not in body.split('"""')[-1]


# ------------------------------------------------------------------------------- IPython


def test_error_routing_shell_hands_errors_over():
    from traitlets.config import Config

    from abglib._compat.ipython import current_shell, error_routing_shell, without_exit_handlers

    seen = []

    class Shell(error_routing_shell()):
        def show_error(self, etype, evalue, stb):
            seen.append((etype, str(evalue), stb))

    config = Config()
    config.HistoryManager.enabled = False
    shell = without_exit_handlers(Shell, config=config, colors="nocolor")
    with current_shell(shell):
        result = shell.run_cell("1/0")
    assert not result.success
    [(etype, evalue, stb)] = seen
    assert etype is ZeroDivisionError and "division by zero" in evalue
    assert any("ZeroDivisionError" in line for line in stb)


def test_error_routing_shell_loud_when_showtraceback_changes(monkeypatch):
    from IPython.core.interactiveshell import InteractiveShell

    from abglib._compat import ipython as c

    monkeypatch.setattr(c, "_BASE", None)
    monkeypatch.setattr(InteractiveShell, "_showtraceback", lambda self, exc: None)
    with pytest.raises(UpstreamChanged, match=r"_showtraceback takes \(self, exc\)"):
        c.error_routing_shell()
    monkeypatch.delattr(InteractiveShell, "_showtraceback")
    with pytest.raises(
        UpstreamChanged, match=_message("ipython", "InteractiveShell._showtraceback")
    ):
        c.error_routing_shell()


def _plain_shell():
    from IPython.core.interactiveshell import InteractiveShell
    from traitlets.config import Config

    from abglib._compat.ipython import without_exit_handlers

    config = Config()
    config.HistoryManager.enabled = False
    return without_exit_handlers(InteractiveShell, config=config, colors="nocolor")


def test_current_shell_makes_it_get_ipython_and_puts_back():
    from IPython import get_ipython
    from IPython.core.interactiveshell import InteractiveShell

    from abglib._compat.ipython import current_shell

    before = get_ipython()
    outer, inner = _plain_shell(), _plain_shell()
    with current_shell(outer):
        assert get_ipython() is outer
        with current_shell(inner):
            assert get_ipython() is inner and InteractiveShell.instance() is inner
        assert get_ipython() is outer
    assert get_ipython() is before


def test_current_shell_loud_when_traitlets_changes(monkeypatch):
    from IPython.core.interactiveshell import InteractiveShell
    from traitlets.config.configurable import SingletonConfigurable

    from abglib._compat.ipython import current_shell

    shell = _plain_shell()
    monkeypatch.setattr(InteractiveShell, "instance", classmethod(lambda cls: None))
    with pytest.raises(UpstreamChanged, match="no longer decides InteractiveShell.instance"):
        with current_shell(shell):
            pass
    assert InteractiveShell.__dict__.get("_instance") is None  # put back all the same
    monkeypatch.delattr(SingletonConfigurable, "_walk_mro")
    with pytest.raises(
        UpstreamChanged, match=_message("traitlets", "SingletonConfigurable._walk_mro")
    ):
        with current_shell(shell):
            pass


def test_current_shell_loud_without_the_instance_slot(monkeypatch):
    from traitlets.config.configurable import SingletonConfigurable

    from abglib._compat.ipython import current_shell

    shell = _plain_shell()
    monkeypatch.delattr(SingletonConfigurable, "_instance")
    with pytest.raises(
        UpstreamChanged, match=_message("traitlets", "SingletonConfigurable._instance")
    ):
        with current_shell(shell):
            pass


def test_a_shell_built_without_exit_handlers_is_freed():
    """An InteractiveShell registers an exit handler that keeps it alive; built through
    without_exit_handlers it is freed once dropped (built plainly it is not: the check
    can fail)."""
    from IPython.core.interactiveshell import InteractiveShell
    from traitlets.config import Config

    from abglib._compat.ipython import without_exit_handlers

    config = Config()
    config.HistoryManager.enabled = False
    shell = without_exit_handlers(InteractiveShell, config=config, colors="nocolor")
    ref = weakref.ref(shell)
    shell.user_ns.clear()  # (the namespace holds get_ipython, bound to the shell)
    del shell
    gc.collect()
    assert ref() is None
    # built plainly, with its handlers kept (in a list here, not in atexit), it stays
    kept = []
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(atexit, "register", lambda f, *a, **k: kept.append(f) or f)
        shell = InteractiveShell(config=config, colors="nocolor")
    ref = weakref.ref(shell)
    shell.user_ns.clear()
    del shell
    gc.collect()
    assert kept and ref() is not None
    kept.clear()
    gc.collect()
    assert ref() is None


def test_without_exit_handlers_keeps_other_threads_handlers(monkeypatch):

    from abglib._compat.ipython import without_exit_handlers

    recorded = []
    monkeypatch.setattr(atexit, "register", lambda f, *a, **k: recorded.append(f) or f)

    def other():
        pass

    def mine():
        pass

    def factory():
        atexit.register(mine)
        t = threading.Thread(target=atexit.register, args=(other,))
        t.start()
        t.join()
        raise ValueError("the factory failed")

    real = atexit.register
    with pytest.raises(ValueError, match="the factory failed"):
        without_exit_handlers(factory)
    assert recorded == [other]
    assert atexit.register is real  # put back after a failure too


# -------------------------------------------------------------------------------- pandas


def test_option_defaults_are_what_reset_option_sets():
    """Every default from the compat module equals what the public reset_option gives."""
    import warnings

    import pandas as pd

    from abglib._compat.pandas import option_defaults

    defaults = option_defaults()
    assert defaults["display.precision"] == 6 and defaults["display.max_columns"] in (0, 20)
    saved = {k: pd.get_option(k) for k in defaults}
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            for key, value in defaults.items():
                pd.reset_option(key)
                assert pd.get_option(key) == value, key
    finally:
        for key, value in saved.items():
            if pd.get_option(key) != value:
                pd.set_option(key, value)


def test_option_defaults_loud_when_pandas_changes(monkeypatch):
    from pandas._config import config as cf

    from abglib._compat.pandas import option_defaults

    monkeypatch.setattr(cf, "_registered_options", {"display.precision": object()})
    with pytest.raises(UpstreamChanged, match=_message("pandas", r"pandas._config.config.Reg")):
        option_defaults()
    monkeypatch.setattr(cf, "_registered_options", {})
    with pytest.raises(UpstreamChanged, match="does not hold display.precision"):
        option_defaults()
    monkeypatch.delattr(cf, "_deprecated_options")
    with pytest.raises(UpstreamChanged, match=_message("pandas", "pandas._config.config._dep")):
        option_defaults()


def test_column_array_is_the_internal_values():
    """The public route gives the very array ``Series._values`` gives, for every kind of
    column a table has (and a few it may get)."""
    import pandas as pd

    from abglib._compat.pandas import column_array

    for s in _COLUMNS():
        got, internal = column_array(s), s._values
        assert type(got) is type(internal), s.dtype
        assert got.dtype == internal.dtype, s.dtype
        assert list(pd.Series(got).astype(str)) == list(pd.Series(internal).astype(str))


def _COLUMNS():
    """Every kind of column a table has (and a few it may get)."""
    import numpy as np
    import pandas as pd

    return [
        pd.Series([1.5, np.nan]),
        pd.Series([1, 2]),
        pd.Series([True, False]),
        pd.Series(["a", None]),
        pd.Series([1, None], dtype="Int64"),
        pd.Series([1.0, None], dtype="Float64"),
        pd.Series(["a", None], dtype="string"),
        pd.Series(["a", "b"], dtype="category"),
        pd.Series(pd.to_datetime(["2020-01-01", None])),
        pd.Series(pd.date_range("2020", periods=2, tz="UTC")),
        pd.Series(pd.to_timedelta([1, 2], unit="s")),
        pd.Series(pd.period_range("2020", periods=2, freq="M")),
    ]


def test_format_column_as_pandas_displays():
    import numpy as np
    import pandas as pd

    from abglib._compat.pandas import format_column

    # one format for the whole column: 2 decimals because 2.25 needs them
    assert [s.strip() for s in format_column(pd.Series([1.5, np.nan, 2.25]), 6)] == [
        "1.50",
        "",
        "2.25",
    ]
    assert [s.strip() for s in format_column(pd.Series([1 / 3]), 3)] == ["0.333"]
    # through the public column_array, the cells the internal Series._values gives
    from pandas.io.formats.format import format_array

    for s in _COLUMNS():
        internal = format_array(s._values, None, na_rep="", digits=6)
        assert format_column(s, 6) == internal, s.dtype
    # the same cells as a DataFrame's display
    df = pd.DataFrame({"x": [0.1, 12.345678, 1e-9]})
    shown = df.to_string(index=False).splitlines()[1:]
    assert [s.strip() for s in format_column(df["x"], 6)] == [s.strip() for s in shown]


def test_format_column_loud_when_format_array_changes(monkeypatch):
    import pandas as pd
    import pandas.io.formats.format as fmt

    from abglib._compat.pandas import format_column

    s = pd.Series([1.0, 2.0])
    monkeypatch.setattr(
        fmt, "format_array", lambda values, formatter, na_rep="", digits=None: ["1.0"]
    )
    with pytest.raises(UpstreamChanged, match="did not return one str per cell"):
        format_column(s, 6)
    monkeypatch.setattr(fmt, "format_array", lambda values, formatter: [])
    with pytest.raises(UpstreamChanged, match=r"format_array takes \(values, formatter\)"):
        format_column(s, 6)
    monkeypatch.delattr(fmt, "format_array")
    with pytest.raises(UpstreamChanged, match=_message("pandas", "pandas.io.formats.format")):
        format_column(s, 6)


# ---------------------------------------------------------------------------- matplotlib


@pytest.fixture
def axes():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    yield ax
    plt.close(fig)


def test_axes_titles_are_the_three_title_artists(axes):
    from abglib._compat.matplotlib import axes_titles

    axes.set_title("C")
    axes.set_title("L", loc="left")
    axes.text(0.5, 0.5, "a text")
    axes.annotate("a note", (0.1, 0.1))
    titles = axes_titles(axes)
    assert [t.get_text() for t in titles] == ["C", "L", ""]
    # the private attributes they stand for (read here only, to check the public route)
    assert titles == [axes.title, axes._left_title, axes._right_title]


def test_axes_titles_loud_when_children_change(axes, monkeypatch):
    from abglib._compat.matplotlib import axes_titles

    children = axes.get_children()
    monkeypatch.setattr(axes, "get_children", lambda: [c for c in children if c is not axes.title])
    with pytest.raises(UpstreamChanged, match=_message("matplotlib", "Axes.get_children()")):
        axes_titles(axes)


def test_cut_off_sees_a_left_title_and_a_suptitle_beyond_the_edge():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from abglib.common.plotting import cut_off

    fig, ax = plt.subplots(figsize=(2, 2))
    ax.set_title("a left title far too long for a figure this narrow " * 2, loc="left")
    fig.suptitle("a suptitle far too long for a figure this narrow " * 2)
    found = cut_off(fig)
    plt.close(fig)
    assert len(found) == 2  # each once (the suptitle is one of Figure.texts)
    assert found[0].startswith("a suptitle") and found[1].startswith("a left title")


# ------------------------------------------------------------- no private access elsewhere

#: the libraries whose internals must go through abglib._compat (import roots)
UPSTREAM = {"snakemake", "IPython", "traitlets", "pandas", "matplotlib", "mpl_toolkits"}
#: Snakemake modules that are public API (the others are internals: snakemake.workflow,
#: snakemake.iocontainers, snakemake.script, snakemake.dag ...)
SNAKEMAKE_PUBLIC = {"snakemake", "snakemake.utils", "snakemake.io", "snakemake.exceptions"}
#: documented attributes of the Snakefile's ``workflow`` object
WORKFLOW_PUBLIC = {"basedir", "current_basedir", "source_path", "snakefile", "cores"}
#: attributes the project itself puts on other libraries' objects
OWN_PREFIX = "_abglib"
#: undocumented attributes without a leading underscore (issue 22's list): only through
#: abglib._compat
KNOWN_INTERNALS = {
    "atexit_operations",
    "auto_builtins",
    "builtin_trap",
    "exec_mode",
    "is_producer",
    "job_rate_limiter",
    "local_exec",
    "modifier",
    "remote_exec",
    "skip_validation",
    "subprocess_exec",
}
#: pandas modules that are internals although no part of their name starts with "_"
PANDAS_INTERNAL = ("pandas.core", "pandas.io.formats")
PANDAS_PUBLIC = ("pandas.io.formats.style",)


def _private(name: str) -> bool:
    return (
        name.startswith("_")
        and not (name.startswith("__") and name.endswith("__"))
        and not name.startswith(OWN_PREFIX)
    )


def _internal(name: str) -> bool:
    return _private(name) or name in KNOWN_INTERNALS


def _under(module: str, prefixes) -> bool:
    return any(module == p or module.startswith(p + ".") for p in prefixes)


def _bad_module(module: str) -> bool:
    parts = module.split(".")
    if parts[0] not in UPSTREAM:
        return False
    if any(_private(p) for p in parts):
        return True
    if parts[0] == "pandas":
        return _under(module, PANDAS_INTERNAL) and not _under(module, PANDAS_PUBLIC)
    return parts[0] == "snakemake" and module not in SNAKEMAKE_PUBLIC


class _Walker(ast.NodeVisitor):
    """Private access to the upstream libraries in one Python module."""

    def __init__(self):
        self.found: list[tuple[int, str]] = []
        self.modules: dict[str, str] = {}  # local name -> the module (or name) it imports
        self.upstream_classes: list[ast.ClassDef] = []

    def _upstream(self, name: str) -> bool:
        return self.modules.get(name, "").split(".")[0] in UPSTREAM

    def visit_Import(self, node):
        for a in node.names:
            self.modules[(a.asname or a.name).split(".")[0]] = a.name
            if _bad_module(a.name):
                self.found.append((node.lineno, f"import {a.name}"))

    def visit_ImportFrom(self, node):
        if node.level:  # the project's own modules
            for a in node.names:
                self.modules[a.asname or a.name] = "." * node.level + (node.module or "")
        elif node.module:
            if _bad_module(node.module):
                self.found.append((node.lineno, f"from {node.module} import ..."))
            for a in node.names:
                full = f"{node.module}.{a.name}"
                self.modules[a.asname or a.name] = full
                if _private(a.name) and full.split(".")[0] in UPSTREAM:
                    self.found.append((node.lineno, f"from {node.module} import {a.name}"))

    def visit_Attribute(self, node):
        base = node.value
        own = isinstance(base, ast.Name) and (
            base.id in ("self", "cls") or (base.id in self.modules and not self._upstream(base.id))
        )
        if _internal(node.attr) and not own:
            self.found.append((node.lineno, f".{node.attr}"))
        if isinstance(base, ast.Name) and base.id == "workflow":
            if node.attr not in WORKFLOW_PUBLIC:
                self.found.append((node.lineno, f"workflow.{node.attr}"))
        self.generic_visit(node)

    def visit_Call(self, node):
        f = node.func
        if isinstance(f, ast.Name) and f.id in ("getattr", "hasattr", "setattr", "delattr"):
            if len(node.args) > 1 and isinstance(node.args[1], ast.Constant):
                name = node.args[1].value
                on_workflow = isinstance(node.args[0], ast.Name) and node.args[0].id == "workflow"
                if isinstance(name, str) and (
                    _internal(name) or (on_workflow and name not in WORKFLOW_PUBLIC)
                ):
                    self.found.append((node.lineno, f"{f.id}(..., {name!r})"))
        self.generic_visit(node)

    def visit_ClassDef(self, node):
        # a subclass of an upstream class overriding or reading its private members
        roots = [b.func if isinstance(b, ast.Call) else b for b in node.bases]
        names = [r.id if isinstance(r, ast.Name) else getattr(r, "attr", "") for r in roots]
        if any(self._upstream(n) for n in names):
            for item in node.body:
                if isinstance(item, ast.FunctionDef | ast.AsyncFunctionDef) and _private(item.name):
                    self.found.append((item.lineno, f"def {item.name} in a subclass"))
            for sub in ast.walk(node):
                if (
                    isinstance(sub, ast.Attribute)
                    and isinstance(sub.value, ast.Name)
                    and sub.value.id == "self"
                    and _private(sub.attr)
                ):
                    self.found.append((sub.lineno, f"self.{sub.attr} in a subclass"))
        self.generic_visit(node)


def python_findings(source: str) -> list[tuple[int, str]]:
    """(line, what) of every private access to the upstream libraries in ``source``."""
    walker = _Walker()
    tree = ast.parse(source)
    for node in ast.walk(tree):  # the names every import binds, wherever it stands
        if isinstance(node, ast.Import | ast.ImportFrom):
            walker.visit(node)
    walker.found = []
    walker.visit(tree)
    return sorted(set(walker.found))


def snakefile_findings(source: str) -> list[tuple[int, str]]:
    """The same for Snakemake's language (not Python: read token by token): ``._x``,
    ``getattr(..., "_x")``, ``workflow.<undocumented>`` and internal imports."""
    toks = [
        t
        for t in tokenize.generate_tokens(io.StringIO(source).readline)
        if t.type not in (tokenize.NL, tokenize.COMMENT)
    ]
    statement_start = (tokenize.NEWLINE, tokenize.INDENT, tokenize.DEDENT)
    found = []
    # names the file imports from abglib: their attributes are the project's own
    own = set()
    for line in source.splitlines():
        words = line.replace(",", " ").split()
        if words[:1] == ["from"] and words[1].split(".")[0] == "abglib" and "import" in words:
            names = words[words.index("import") + 1 :]
            own |= {n for k, n in enumerate(names) if k + 1 == len(names) or names[k + 1] != "as"}
    in_import = False  # abglib._compat in an import is the project's own
    for i, t in enumerate(toks):
        prev = toks[i - 1] if i else None
        at_start = prev is None or prev.type in statement_start
        in_import = (at_start and t.string in ("import", "from")) or (
            in_import and t.type != tokenize.NEWLINE
        )
        if t.type == tokenize.NAME and prev is not None and prev.string == "." and not in_import:
            before = toks[i - 2].string if i >= 2 else ""
            if _internal(t.string) and before not in ("self", "cls", *own):
                found.append((t.start[0], f".{t.string}"))
            if before == "workflow" and t.string not in WORKFLOW_PUBLIC:
                found.append((t.start[0], f"workflow.{t.string}"))
        if t.type == tokenize.NAME and t.string in ("getattr", "hasattr", "setattr", "delattr"):
            if i + 1 < len(toks) and toks[i + 1].string == "(":
                depth = 0
                for j in range(i + 1, len(toks) - 1):
                    if toks[j].type == tokenize.OP and toks[j].string in "([{":
                        depth += 1
                    elif toks[j].type == tokenize.OP and toks[j].string in ")]}":
                        depth -= 1
                    if depth == 0:
                        break
                    if depth == 1 and toks[j].string == "," and toks[j + 1].type == tokenize.STRING:
                        try:
                            name = ast.literal_eval(toks[j + 1].string)
                        except ValueError:  # an f-string: not a fixed name
                            name = None
                        on_workflow = toks[i + 2].string == "workflow" and j == i + 3
                        if isinstance(name, str) and (
                            _internal(name) or (on_workflow and name not in WORKFLOW_PUBLIC)
                        ):
                            found.append((t.start[0], f"{t.string}(..., {name!r})"))
                        break
        if t.type == tokenize.NAME and t.string in ("import", "from") and at_start:
            module = ""
            for u in toks[i + 1 :]:
                if u.string in ("import", "as", ",") or not (
                    u.type == tokenize.NAME or u.string == "."
                ):
                    break
                module += u.string
            if module and _bad_module(module):
                found.append((t.start[0], f"{t.string} {module}"))
    return sorted(set(found))


def _scanned_files() -> list[Path]:
    files = [p for p in (REPO / "abglib").rglob("*.py") if "_compat" not in p.parts]
    files += sorted((REPO / "workflow").rglob("*.py"))
    files += sorted((REPO / "workflow").rglob("*.smk")) + [REPO / "Snakefile"]
    return sorted(files)


def test_no_private_access_outside_compat():
    problems = []
    for path in _scanned_files():
        text = path.read_text(encoding="utf-8")
        scan = python_findings if path.suffix == ".py" else snakefile_findings
        for line, what in scan(text):
            problems.append(f"{path.relative_to(REPO)}:{line}: {what}")
    assert not problems, "private internals used outside abglib/_compat:\n" + "\n".join(problems)


@pytest.mark.parametrize(
    "source, what",
    [
        ("import pandas as pd\npd.Series([1])._values\n", "._values"),
        ("from pandas._config import config\n", "from pandas._config import ..."),
        ("import pandas._config.config\n", "import pandas._config.config"),
        ("from snakemake.iocontainers import Snakemake\n", "from snakemake.iocontainers"),
        ("def f(ax):\n    return ax._left_title\n", "._left_title"),
        ("def f(fig):\n    return getattr(fig, '_suptitle', None)\n", "getattr(..., '_suptitle')"),
        ("def f(s):\n    return type(s)._walk_mro()\n", "._walk_mro"),
        (
            "from IPython.core.interactiveshell import InteractiveShell\n"
            "class S(InteractiveShell):\n    def _showtraceback(self, a, b, c):\n        pass\n",
            "def _showtraceback in a subclass",
        ),
        ("def f(workflow):\n    return workflow.local_exec\n", "workflow.local_exec"),
        ("from pandas.io.formats.format import format_array\n", "pandas.io.formats.format"),
        ("def f(shell):\n    shell.builtin_trap.auto_builtins['input'] = 1\n", ".builtin_trap"),
        ("def f(r, p):\n    return r.is_producer(p)\n", ".is_producer"),
        ("def f(s):\n    return getattr(s, 'job_rate_limiter', None)\n", "'job_rate_limiter'"),
    ],
)
def test_the_python_scan_finds_private_access(source, what):
    assert any(what in w for _, w in python_findings(source)), python_findings(source)


def test_the_python_scan_lets_the_projects_own_names_be():
    source = (
        "import os\nfrom abglib import design\nfrom . import _buffers\nfrom .. import variants\n"
        "from pandas.io.formats.style import Styler\nvariants._order_suffix({})\n"
        "class A:\n    def _f(self):\n        return self._x\n"
        "def g(fig):\n    os._exit(0)\n    design._check_order(2)\n    fig._abglib_alt = 1\n"
        "    return getattr(fig, '_abglib_alt', ''), fig.__class__, workflow.basedir\n"
    )
    assert python_findings(source) == []


@pytest.mark.parametrize(
    "source, what",
    [
        ("x = workflow.scheduler.job_rate_limiter\n", "workflow.scheduler"),
        ('if not getattr(workflow.modifier, "skip_validation", False):\n    pass\n', "modifier"),
        ('s = getattr(workflow, "_scheduler", None)\n', "getattr(..., '_scheduler')"),
        ('s = getattr(workflow, "scheduler", None)\n', "getattr(..., 'scheduler')"),
        ("s.job_rate_limiter = None\n", ".job_rate_limiter"),
        ("rule a:\n    run:\n        x = shell._values\n", "._values"),
        ("from snakemake.iocontainers import Snakemake\n", "from snakemake.iocontainers"),
        ("import snakemake.workflow\n", "import snakemake.workflow"),
    ],
)
def test_the_snakefile_scan_finds_private_access(source, what):
    found = snakefile_findings("\n" + source)
    assert any(what in w for _, w in found), found


def test_the_snakefile_scan_lets_public_use_be():
    source = (
        "\nfrom snakemake.utils import min_version\n"
        "from snakemake.exceptions import WorkflowError\n"
        "from abglib._compat import snakemake as smk_compat\n"
        "if not smk_compat.skip_validation(workflow):\n    pass\n"
        'X = Path(workflow.basedir) / "x"\n'
        "rule a:\n    input:\n        rules.b.output,\n    run:\n        self._x = 1\n"
    )
    assert snakefile_findings(source) == []


def test_compat_imports_no_upstream_library_until_used():
    """abglib._compat and its Snakemake, IPython and matplotlib modules import with those
    libraries blocked (the tracker core installs without them); each imports its library
    only inside the accessor that needs it."""
    code = (
        "import sys\n"
        "class Block:\n"
        "    def find_spec(self, name, path=None, target=None):\n"
        "        if name.split('.')[0] in {'snakemake', 'IPython', 'traitlets', 'matplotlib',\n"
        "                                  'snakemake_interface_executor_plugins'}:\n"
        "            raise ImportError(f'blocked: {name}')\n"
        "sys.meta_path.insert(0, Block())\n"
        "import abglib._compat, abglib._compat.snakemake, abglib._compat.ipython\n"
        "import abglib._compat.matplotlib\n"
        "try:\n"
        "    abglib._compat.snakemake.script_object_class()\n"
        "except ImportError as err:\n"
        "    print('used:', err)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr[-2000:]
    assert "used: blocked: snakemake" in out.stdout
