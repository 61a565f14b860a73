"""Notebooks executed in the calling process (abglib.reporting.execute): the outputs a
Jupyter kernel would give, failures named, nothing leaking between notebooks, ``cwd``."""

import builtins
import copy
import os
import sys
import time
import warnings

import nbformat
import numpy as np
import pandas as pd
import pytest

from abglib.reporting.execute import CellExecutionError, CellTimeoutError, execute_notebook
from abglib.reporting.render import render_notebook, strip_volatile

from .conftest import require_module


def notebook(*sources, tags=None):
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_markdown_cell("# A notebook")]
    for i, src in enumerate(sources):
        cell = nbformat.v4.new_code_cell(src)
        if tags and i in tags:
            cell.metadata["tags"] = tags[i]
        nb.cells.append(cell)
    return nb


def outputs(nb):
    """(output_type, content) of every output of every code cell, in order."""
    out = []
    for cell in nb.cells[1:]:
        for o in cell.outputs:
            if o.output_type == "stream":
                out.append(("stream", o.name, o.text))
            elif o.output_type == "error":
                out.append(("error", o.ename, o.evalue))
            else:
                out.append((o.output_type, dict(o.data), dict(o.metadata)))
    return out


def test_streams_displays_and_results_are_captured_in_order(tmp_path):
    nb = notebook(
        "import sys\nprint('one')\nprint('two')\nprint('err', file=sys.stderr)",
        "from IPython.display import HTML, Markdown, display\n"
        "display(HTML('<p>shown</p>'))\n"
        "display({'text/markdown': 'Short.', 'text/plain': 'Short.'}, raw=True,"
        " metadata={'abstract': True})\n"
        "40 + 2",
        "x = 1;",  # nothing shown
        "3.5;",  # a trailing semicolon hides the result, as in Jupyter
        "",  # an empty cell is not executed
    )
    execute_notebook(nb, cwd=tmp_path)
    assert outputs(nb) == [
        ("stream", "stdout", "one\ntwo\n"),
        ("stream", "stderr", "err\n"),
        (
            "display_data",
            {"text/html": "<p>shown</p>", "text/plain": "<IPython.core.display.HTML object>"},
            {},
        ),
        ("display_data", {"text/markdown": "Short.", "text/plain": "Short."}, {"abstract": True}),
        ("execute_result", {"text/plain": "42"}, {}),
    ]
    assert [c.get("execution_count") for c in nb.cells[1:]] == [1, 2, 3, 4, None]
    assert nb.cells[2].outputs[-1].execution_count == 2
    assert nb.metadata.language_info["name"] == "python"


def test_a_report_table_and_an_updated_display_are_html(tmp_path):
    """Report installs its table formatter on get_ipython(): that is the notebook's shell."""
    nb = notebook(
        "import pandas as pd\n"
        "from IPython.display import HTML, display\n"
        "from abglib.reporting.notebook import Report\n"
        "R = Report('d', {}, {})\n"
        "display(pd.DataFrame({'x': [1.5]}))",
        "h = display(HTML('first'), display_id='d1')\nh.update(HTML('second'))",
    )
    execute_notebook(nb, cwd=tmp_path)
    table = nb.cells[1].outputs[0].data["text/html"]
    assert table.startswith('<figure class="abg-table" id="tab-1">') and ">1.5<" in table
    assert nb.cells[2].outputs[0].data["text/html"] == "second"


def test_a_failing_cell_fails_with_its_source_and_error(tmp_path):
    nb = notebook("x = 1", "print('so far')\ny = {}['missing']", "z = 3")
    with pytest.raises(CellExecutionError) as info:
        execute_notebook(nb, cwd=tmp_path)
    err = info.value
    assert (err.ename, err.evalue) == ("KeyError", "'missing'")
    text = str(err)
    assert text.startswith("An error occurred while executing the following cell:")
    assert "y = {}['missing']" in text and "----- stdout -----\nso far" in text
    assert "KeyError: 'missing'" in text and "\x1b[" not in text  # plain text, no colours
    assert nb.cells[2].outputs[-1].output_type == "error"
    assert nb.cells[3].outputs == []  # not executed


def test_a_syntax_error_fails_and_a_cell_tagged_raises_exception_may_fail(tmp_path):
    with pytest.raises(CellExecutionError, match="SyntaxError") as info:
        # an unmatched bracket: a SyntaxError on every Python (an unclosed one is
        # _IncompleteInputError on 3.13)
        execute_notebook(notebook("x = 1)"), cwd=tmp_path)
    assert info.value.ename == "SyntaxError"
    nb = notebook("1 / 0", "'went on'", tags={0: ["raises-exception"]})
    execute_notebook(nb, cwd=tmp_path)
    assert outputs(nb)[0] == ("error", "ZeroDivisionError", "division by zero")
    assert outputs(nb)[1][1]["text/plain"] == "'went on'"


def test_input_is_refused_rather_than_waiting(tmp_path):
    with pytest.raises(CellExecutionError, match="StdinNotImplementedError"):
        execute_notebook(notebook("input('name? ')"), cwd=tmp_path)


def test_a_cell_past_the_timeout_is_stopped(tmp_path):
    start = time.monotonic()
    with pytest.raises(CellTimeoutError, match="after 0.3 seconds") as info:
        slow = notebook("x = 1", "import time\ntime.sleep(20)")
        execute_notebook(slow, timeout=0.3, cwd=tmp_path)
    assert time.monotonic() - start < 10
    assert "time.sleep(20)" in str(info.value)
    with pytest.raises(ValueError, match="timeout must satisfy timeout >= 0"):
        execute_notebook(notebook("x = 1"), timeout=-1, cwd=tmp_path)


def test_nothing_leaks_between_two_notebooks_or_into_the_process(tmp_path):
    before = {
        "cwd": os.getcwd(),
        "path": list(sys.path),
        "env": dict(os.environ),
        "main": sys.modules["__main__"],
        "builtins": set(vars(builtins)),
        "precision": pd.get_option("display.precision"),
        "np": np.get_printoptions(),
        "filters": list(warnings.filters),
        "stdout": sys.stdout,
    }
    first = notebook(
        "import os, sys, builtins, warnings\n"
        "import numpy as np, pandas as pd\n"
        "secret = 42\n"
        "pd.set_option('display.precision', 1)\n"
        "np.set_printoptions(precision=2)\n"
        "os.environ['ABGLIB_TEST_LEAK'] = 'yes'\n"
        "sys.path.append('/nowhere')\n"
        "builtins.leaked = True\n"
        "warnings.simplefilter('error')\n"
        "os.chdir('/')"
    )
    second = notebook(
        "import os, builtins, pandas as pd\n"
        "print('secret' in globals(), pd.get_option('display.precision'),"
        " 'ABGLIB_TEST_LEAK' in os.environ, hasattr(builtins, 'leaked'))"
    )
    execute_notebook(first, cwd=tmp_path)
    execute_notebook(second, cwd=tmp_path)
    assert outputs(second) == [("stream", "stdout", "False 6 False False\n")]
    after = {
        "cwd": os.getcwd(),
        "path": list(sys.path),
        "env": dict(os.environ),
        "main": sys.modules["__main__"],
        "builtins": set(vars(builtins)),
        "precision": pd.get_option("display.precision"),
        "np": np.get_printoptions(),
        "filters": list(warnings.filters),
        "stdout": sys.stdout,
    }
    assert after == before
    from IPython import get_ipython

    assert get_ipython() is None  # the notebook's shell was this process's only while it ran


def test_pandas_shows_dataframes_as_in_a_kernel(tmp_path):
    """A kernel's pandas truncates at 20 columns; outside IPython the default is 0."""
    nb = notebook("import pandas as pd\npd.get_option('display.max_columns')")
    with pd.option_context("display.max_columns", 3):
        execute_notebook(nb, cwd=tmp_path)
        assert pd.get_option("display.max_columns") == 3
    assert outputs(nb)[0][1]["text/plain"] == "20"


def test_the_notebook_runs_in_cwd_which_it_can_import_from(tmp_path):
    (tmp_path / "data.csv").write_text("a\n7\n")
    (tmp_path / "helper_abglib_test.py").write_text("VALUE = 'imported from cwd'\n")
    nb = notebook(
        "import os, pandas as pd\n"
        "from helper_abglib_test import VALUE\n"
        "print(os.getcwd(), int(pd.read_csv('data.csv')['a'][0]), VALUE)"
    )
    cwd = os.getcwd()
    try:
        execute_notebook(nb, cwd=tmp_path)
    finally:
        sys.modules.pop("helper_abglib_test", None)
    assert outputs(nb) == [("stream", "stdout", f"{tmp_path.resolve()} 7 imported from cwd\n")]
    assert os.getcwd() == cwd
    with pytest.raises(NotADirectoryError, match="cwd must be an existing folder"):
        execute_notebook(notebook("1"), cwd=tmp_path / "absent")


def test_a_pyplot_figure_left_open_is_shown_as_png_and_closed(tmp_path):
    import matplotlib.pyplot as plt

    nb = notebook(
        "import matplotlib.pyplot as plt\nfig, ax = plt.subplots(figsize=(1, 1))\nax.plot([0, 1]);"
    )
    open_before = plt.get_fignums()
    execute_notebook(nb, cwd=tmp_path)
    ((kind, data, _),) = outputs(nb)
    assert kind == "display_data" and data["image/png"].startswith("iVBORw0KGgo")  # PNG, base64
    assert plt.get_fignums() == open_before


PERCENT = """\
# %% [markdown]
# # The *title*
#
# Intro.

# %% tags=["parameters"]
value = 0

# %%
from IPython.display import Markdown, display

display(Markdown(f"The value is **{value}**."))
"""


def test_render_notebook_injects_parameters_and_writes_the_page(tmp_path):
    src = tmp_path / "nb.py"
    src.write_text(PERCENT)
    html = tmp_path / "out" / "index.html"
    render_notebook(src, html, {"value": 7}, cwd=tmp_path, name="t")
    page = html.read_text()
    assert "The value is <strong>7</strong>." in page and "<h1>The <em>title</em></h1>" in page
    with pytest.raises(ValueError, match=r"engine must be one of \('inprocess', 'kernel'\)"):
        render_notebook(src, html, {}, engine="papermill")


@pytest.mark.slow
def test_in_process_and_kernel_give_the_same_notebook(tmp_path):
    """The two engines agree output for output (nbclient and ipykernel: extra 'kernel')."""
    require_module("nbclient")  # skips without it; fails under CI
    from abglib.reporting.render import _execute_in_kernel

    nb = notebook(
        "import sys\nimport pandas as pd\nfrom IPython.display import HTML, Markdown, display\n"
        "print('out')\nprint('err', file=sys.stderr)\n"
        "display(Markdown('*m*'), metadata={'abstract': True})",
        # one stream in two of the kernel's messages (a flush between the writes, as its
        # output thread does when it fires in between under load): still one output
        "sys.stdout.write('o')\nsys.stdout.flush()\nprint('ut')",
        "df = pd.DataFrame({'a': [1.23456789, None], 'b': ['x', 'y']})\ndisplay(df)\ndf",
        "pd.DataFrame([list(range(30))] * 2)",
        "h = display(HTML('1'), display_id='d')\nh.update(HTML('2'))\n{'k': (1, 2.5)}",
        "import matplotlib.pyplot as plt\nfig, ax = plt.subplots(figsize=(1, 1), dpi=20)\n"
        "ax.plot([0, 1]);",
    )
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Py", "language": "python"}
    a, b = copy.deepcopy(nb), copy.deepcopy(nb)
    execute_notebook(a, cwd=tmp_path)
    _execute_in_kernel(b, tmp_path, 120)
    assert strip_volatile(a) == strip_volatile(b) == ["err\n"]
    assert nbformat.writes(a) == nbformat.writes(b)


def test_another_threads_prints_stay_out_of_the_notebook(tmp_path, capsys):
    nb = notebook(
        "import threading\n"
        "t = threading.Thread(target=print, args=('from another thread',))\n"
        "t.start(); t.join()\n"
        "print('from the cell')"
    )
    execute_notebook(nb, cwd=tmp_path)
    assert outputs(nb) == [("stream", "stdout", "from the cell\n")]
    assert "from another thread" in capsys.readouterr().out


@pytest.mark.slow  # a kernel
def test_the_kernel_draws_its_figures_whatever_backend_the_caller_set(tmp_path, monkeypatch):
    """A workflow job runs under MPLBACKEND=Agg (abglib.reporting._server_env); the
    kernel it starts still shows a cell's figure, as the in-process engine does."""
    require_module("nbclient")  # skips without it; fails under CI
    from abglib.reporting.render import _execute_in_kernel

    monkeypatch.setenv("MPLBACKEND", "Agg")
    nb = notebook("import matplotlib.pyplot as plt\nplt.plot([0, 1]);")
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Py", "language": "python"}
    _execute_in_kernel(nb, tmp_path, 120)
    assert [o.output_type for o in nb.cells[1].outputs] == ["display_data"]
    assert "image/png" in nb.cells[1].outputs[0].data


def test_merge_streams_joins_only_consecutive_outputs_of_one_stream():
    from abglib.reporting.render import merge_streams

    def stream(name, text):
        return nbformat.v4.new_output("stream", name=name, text=text)

    nb = notebook("pass")
    shown = nbformat.v4.new_output("display_data", data={"text/plain": "x"})
    nb.cells[1].outputs = [
        stream("stdout", "a"), stream("stdout", "b\n"), stream("stderr", "e"),
        stream("stdout", "c"), shown, stream("stdout", "d"), stream("stdout", "e"),
    ]  # fmt: skip
    merge_streams(nb)
    got = [(o.output_type, o.get("name"), o.get("text")) for o in nb.cells[1].outputs]
    assert got == [
        ("stream", "stdout", "ab\n"),
        ("stream", "stderr", "e"),
        ("stream", "stdout", "c"),
        ("display_data", None, None),
        ("stream", "stdout", "de"),
    ]
