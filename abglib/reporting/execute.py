"""Execute a notebook in the calling process: IPython's shell, no kernel, no ZMQ.

:func:`execute_notebook` runs the code cells of an nbformat notebook one by one in a
fresh IPython shell (:class:`IPython.core.interactiveshell.InteractiveShell`, one per
notebook, never the process's global one) and fills in each cell's outputs as nbclient
does with a Jupyter kernel: ``stream`` (stdout, stderr), ``display_data``,
``execute_result`` and ``error`` outputs, with the same data a kernel would send
(mime bundles through JSON, images base64), the cells' execution counts and the
notebook's ``language_info``. A failing cell raises :class:`CellExecutionError` with
nbclient's message (the cell's source, its stream output, the traceback); a cell running
past ``timeout`` raises :class:`CellTimeoutError`. Starting a kernel costs a new Python
process that imports IPython, numpy, pandas and abglib again; this costs a few
milliseconds in a process that has them.

Isolation: the notebook runs in its own namespace (``__main__`` while it runs), in
``cwd`` (also first on ``sys.path``, as in a kernel started there), with matplotlib's
non-interactive Agg backend and pandas' options as in a fresh kernel; afterwards the
process gets back its working directory, ``sys.path``, ``sys.modules["__main__"]``,
builtins, standard streams, hooks, environment, warning filters, pandas, numpy and
matplotlib options, and the pyplot figures the notebook left open are closed. Modules a
notebook imports stay imported (as a cache; module-level state they keep is not undone).

What is put back is process-wide (working directory, the IPython instance, pandas'
options): notebooks executed from several threads of one process run one at a time (a
lock), and other threads see the notebook's state while it runs (except its output
streams: what they print goes where it went before). Run concurrent reports in separate
processes (forked jobs are fine).

Differences from a kernel, none of which the report notebooks meet: output that C code
or subprocesses write to file descriptors 1 and 2 goes to the process's own stdout and
stderr, not to the notebook; ``input()`` raises (as with nbclient); a pyplot figure a
cell leaves open is shown as a PNG at the end of the cell (as the inline backend does)
but without the inline backend's ``needs_background`` metadata; the timeout uses
``SIGALRM``, so it applies in the main thread on POSIX only, and a cell stuck in
compiled code (numba, C) overruns it until it returns to Python.
"""

from __future__ import annotations

import base64
import builtins
import json
import os
import platform
import signal
import sys
import threading
import time
import warnings
from contextlib import ExitStack, contextmanager
from pathlib import Path

from nbformat import from_dict

__all__ = ["CellExecutionError", "CellTimeoutError", "execute_notebook"]

# nbclient's wording (nbclient/exceptions.py), so a failed report reads as it always did
_ERROR_MESSAGE = """\
An error occurred while executing the following cell:
------------------
{source}
------------------
{streams}

{traceback}
"""
_TIMEOUT_MESSAGE = """\
A cell timed out while it was being executed, after {timeout} seconds.
Here is a preview of the cell contents:
-------------------
{source}
-------------------
"""
# what ipykernel's kernel_info reply gives (strip_volatile drops the version)
_LANGUAGE_INFO = {
    "codemirror_mode": {"name": "ipython", "version": 3},
    "file_extension": ".py",
    "mimetype": "text/x-python",
    "name": "python",
    "nbconvert_exporter": "python",
    "pygments_lexer": "ipython3",
}
_ONE_AT_A_TIME = threading.Lock()


class CellExecutionError(RuntimeError):
    """A cell of the notebook raised; the message names the cell and the error.

    ``ename`` and ``evalue`` are the exception's type name and text, ``traceback`` the
    whole message (as :class:`nbclient.exceptions.CellExecutionError`).
    """

    def __init__(self, traceback: str, ename: str, evalue: str):
        super().__init__(traceback)
        self.traceback = traceback
        self.ename = ename
        self.evalue = evalue


class CellTimeoutError(CellExecutionError, TimeoutError):
    """A cell ran longer than the timeout."""


class _Timeout(BaseException):
    """Raised into a cell by the alarm (a BaseException: ``except Exception`` lets it by)."""


# -- the shell --------------------------------------------------------------------------


def _jsonable(obj):
    """``obj`` as it comes out of a kernel message: through JSON, binary data base64."""

    def default(o):
        if isinstance(o, bytes | bytearray):
            return base64.b64encode(o).decode("ascii")
        if isinstance(o, set | frozenset):
            return sorted(o, key=repr)
        if hasattr(o, "tolist"):  # numpy scalars and arrays
            return o.tolist()
        raise TypeError(f"display data of type {type(o).__name__} is not JSON serialisable")

    return json.loads(json.dumps(obj, default=default))


class _Recorder:
    """The outputs of the cell being executed, as nbformat output nodes."""

    def __init__(self):
        self.outputs: list = []
        self.clear_pending = False
        self.by_display_id: dict[str, list] = {}

    def add(self, out, display_id=None) -> None:
        if self.clear_pending:
            self.outputs.clear()
            self.clear_pending = False
        self.outputs.append(out)
        if display_id:
            self.by_display_id.setdefault(display_id, []).append(out)

    def stream(self, name: str, text: str) -> None:
        if not text:
            return
        last = self.outputs[-1] if self.outputs and not self.clear_pending else None
        if last is not None and last.output_type == "stream" and last.name == name:
            last.text += text
        else:
            self.add(from_dict({"output_type": "stream", "name": name, "text": text}))

    def update(self, display_id, data, metadata) -> None:
        for out in self.by_display_id.get(display_id, []):
            out.data, out.metadata = data, metadata

    def clear(self, wait: bool) -> None:
        if wait:
            self.clear_pending = True
        else:
            self.outputs.clear()


class _Stream:
    """``sys.stdout`` / ``sys.stderr`` of a running cell: the cell's writes become stream
    outputs; other threads' writes go where they went before."""

    encoding = "utf-8"
    errors = "strict"

    def __init__(self, name: str, recorder: _Recorder, elsewhere):
        self.name = name
        self._recorder = recorder
        self._elsewhere = elsewhere
        self._thread = threading.get_ident()

    def write(self, text: str) -> int:
        if threading.get_ident() != self._thread and self._elsewhere is not None:
            return self._elsewhere.write(text)
        if not isinstance(text, str):
            raise TypeError(f"write() argument must be str, not {type(text).__name__}")
        self._recorder.stream(self.name, text)
        return len(text)

    def writelines(self, lines) -> None:
        for line in lines:
            self.write(line)

    def flush(self) -> None:
        pass

    def isatty(self) -> bool:
        return False

    def writable(self) -> bool:
        return True

    def readable(self) -> bool:
        return False

    def fileno(self) -> int:
        import io

        raise io.UnsupportedOperation("a notebook's output stream has no file descriptor")

    @property
    def closed(self) -> bool:
        return False


def _shell_class():
    """The shell class, built on first use (importing IPython costs ~0.1 s)."""
    global _SHELL
    if _SHELL is not None:
        return _SHELL
    from IPython.core.displayhook import DisplayHook
    from IPython.core.displaypub import DisplayPublisher
    from traitlets import Type

    from .._compat.ipython import error_routing_shell

    class Publisher(DisplayPublisher):
        """``display(...)`` → a ``display_data`` output (ipykernel's ZMQDisplayPublisher)."""

        def publish(self, data, metadata=None, source=None, *, transient=None, update=False, **kw):
            data, metadata = _jsonable(data), _jsonable(metadata or {})
            display_id = (transient or {}).get("display_id")
            rec = self.shell.recorder
            if display_id:  # nbclient updates every earlier output with this id
                rec.update(display_id, data, metadata)
            if not update:
                out = {"output_type": "display_data", "data": data, "metadata": metadata}
                rec.add(from_dict(out), display_id)

        def clear_output(self, wait=False):
            self.shell.recorder.clear(wait)

    class Hook(DisplayHook):
        """A cell's last expression → an ``execute_result`` (ipykernel's display hook)."""

        def start_displayhook(self):
            self.bundle = None

        def write_output_prompt(self):
            pass

        def write_format_data(self, format_dict, md_dict=None):
            self.bundle = (format_dict, md_dict or {})

        def finish_displayhook(self):
            if self.bundle and self.bundle[0]:
                data, metadata = self.bundle
                out = {
                    "output_type": "execute_result",
                    "data": _jsonable(data),
                    "metadata": _jsonable(metadata),
                    "execution_count": self.prompt_count,
                }
                self.shell.recorder.add(from_dict(out))
            self.bundle = None

    class NotebookShell(error_routing_shell()):
        """An IPython shell whose outputs become nbformat outputs of the current cell."""

        display_pub_class = Type(Publisher)
        displayhook_class = Type(Hook)

        def show_error(self, etype, evalue, stb):
            out = {
                "output_type": "error",
                "ename": str(etype.__name__),
                "evalue": str(evalue),
                "traceback": list(stb),
            }
            self.recorder.add(from_dict(out))

    _SHELL = NotebookShell
    return _SHELL


_SHELL = None


def _no_input(*args, **kwargs):
    from IPython.core.error import StdinNotImplementedError

    raise StdinNotImplementedError(
        "raw_input was called, but this frontend does not support input requests."
    )


def _new_shell():
    """A fresh shell: no history file, plain-text tracebacks, no exit handler (which
    would keep it and the notebook's namespace alive until the process ends)."""
    from traitlets.config import Config

    from .._compat.ipython import without_exit_handlers

    config = Config()
    config.HistoryManager.enabled = False
    shell = without_exit_handlers(_shell_class(), config=config, colors="nocolor")
    shell.recorder = _Recorder()
    # a pyplot figure shown with display(fig) is a PNG, as with the inline backend
    png = shell.display_formatter.formatters["image/png"]
    png.for_type_by_name("matplotlib.figure", "Figure", _figure_png)
    return shell


def _figure_png(fig):
    from IPython.core.pylabtools import print_figure

    return print_figure(fig, "png", bbox_inches="tight", base64=True)


# -- isolation --------------------------------------------------------------------------


@contextmanager
def _restored(obj, names):
    """Put back the attributes ``names`` of ``obj`` (deleting those that were absent)."""
    missing = object()
    saved = {n: getattr(obj, n, missing) for n in names}
    try:
        yield
    finally:
        for n, v in saved.items():
            if v is missing:
                if hasattr(obj, n):
                    delattr(obj, n)
            else:
                setattr(obj, n, v)


@contextmanager
def _restored_dict(d):
    """Put back a mapping's items (``os.environ``, builtins) as they were."""
    saved = dict(d)
    try:
        yield
    finally:
        if dict(d) != saved:
            for k in [k for k in d if k not in saved]:
                del d[k]
            for k, v in saved.items():
                if d.get(k, object()) is not v:
                    d[k] = v


@contextmanager
def _pandas_as_in_a_kernel():
    """pandas' options at their defaults (a fresh kernel's) while the notebook runs.

    ``display.max_columns`` is 20 in a kernel, 0 (fit the terminal) when pandas was
    imported outside IPython, as in the process calling us.
    """
    import pandas as pd

    from .._compat.pandas import option_defaults

    defaults = option_defaults()
    saved = {k: pd.get_option(k) for k in defaults}

    def put(values):
        for k, v in values.items():
            if pd.get_option(k) != v:
                pd.set_option(k, v)

    put(defaults | {"display.max_columns": 20})
    try:
        yield
    finally:
        put(saved)


@contextmanager
def _numpy_printoptions():
    import numpy as np

    saved = np.get_printoptions()
    try:
        yield
    finally:
        np.set_printoptions(**saved)


@contextmanager
def _matplotlib_agg():
    """Agg while the notebook runs; rcParams back and the notebook's figures closed after."""
    had = "matplotlib" in sys.modules
    open_before = set(_figure_numbers())
    with ExitStack() as stack:
        if had:
            import matplotlib

            matplotlib.use("Agg")  # a no-op if it is already (abglib.common.plotting)
            stack.enter_context(matplotlib.rc_context())
        try:
            yield
        finally:
            if "matplotlib.pyplot" in sys.modules:
                plt = sys.modules["matplotlib.pyplot"]
                for num in set(_figure_numbers()) - open_before:
                    plt.close(num)
            if not had and "matplotlib" in sys.modules:
                sys.modules["matplotlib"].rc_file_defaults()


def _figure_numbers() -> list:
    plt = sys.modules.get("matplotlib.pyplot")
    return plt.get_fignums() if plt is not None else []


@contextmanager
def _isolated(cwd):
    """Everything a notebook may change in the process, put back afterwards."""
    cwd = Path(cwd).resolve()
    if not cwd.is_dir():
        raise NotADirectoryError(f"cwd must be an existing folder, got {str(cwd)!r}")
    with ExitStack() as stack:
        stack.enter_context(warnings.catch_warnings())
        stack.enter_context(_restored_dict(os.environ))
        stack.enter_context(_restored_dict(builtins.__dict__))
        builtins.input = _no_input  # no stdin, as ipykernel's raw_input without a frontend
        # IPython makes the notebook's namespace ``__main__``; modules imported meanwhile stay
        stack.callback(sys.modules.__setitem__, "__main__", sys.modules.get("__main__"))
        names = ("stdin", "stdout", "stderr", "displayhook", "excepthook", "ps1", "ps2")
        stack.enter_context(_restored(sys, names))
        saved_path = list(sys.path)
        stack.callback(sys.path.__setitem__, slice(None), saved_path)
        stack.callback(os.chdir, os.getcwd())
        stack.enter_context(_pandas_as_in_a_kernel())
        stack.enter_context(_numpy_printoptions())
        os.environ["MPLBACKEND"] = "Agg"
        stack.enter_context(_matplotlib_agg())
        os.chdir(cwd)
        sys.path.insert(0, str(cwd))
        yield


# -- the timeout ------------------------------------------------------------------------


@contextmanager
def _alarm(timeout):
    """Raise :class:`_Timeout` in the running code after ``timeout`` seconds (main
    thread, POSIX); a no-op elsewhere or without a timeout."""
    usable = (
        timeout
        and hasattr(signal, "setitimer")
        and threading.current_thread() is threading.main_thread()
    )
    if not usable:
        yield
        return

    def ring(signum, frame):
        raise _Timeout

    previous = signal.signal(signal.SIGALRM, ring)
    start = time.monotonic()
    old_delay, old_interval = signal.setitimer(signal.ITIMER_REAL, timeout)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, signal.SIG_DFL if previous is None else previous)
        if old_delay:  # the caller's own timer keeps running
            left = max(old_delay - (time.monotonic() - start), 1e-3)
            signal.setitimer(signal.ITIMER_REAL, left, old_interval)


# -- execution --------------------------------------------------------------------------


def _error_message(cell, outputs, traceback: str) -> str:
    streams = [
        f"----- {o.name} -----\n{o.text.rstrip()}" for o in outputs if o.output_type == "stream"
    ]
    streams = "\n".join(["", *streams, "------------------"]) if streams else ""
    return _ERROR_MESSAGE.format(source=cell.source, streams=streams, traceback=traceback)


def _show_open_figures(open_before) -> None:
    """Display and close the pyplot figures a cell left open (the inline backend's way)."""
    from IPython.display import display

    plt = sys.modules.get("matplotlib.pyplot")
    for num in sorted(set(_figure_numbers()) - open_before):
        display(plt.figure(num))
        plt.close(num)


def execute_notebook(nb, *, cwd=".", timeout: float | None = 600):
    """Execute ``nb``'s code cells in this process; fill in their outputs (in place).

    Parameters
    ----------
    nb : nbformat.NotebookNode
        The notebook (v4); its cells' outputs and execution counts are replaced.
    cwd : path
        Working directory while the notebook runs (also first on ``sys.path``).
    timeout : float or None
        Per-cell limit in seconds (``None`` or 0: none); see the module docstring.

    Returns
    -------
    nb : the same notebook.

    Raises
    ------
    CellExecutionError
        A cell raised (unless tagged ``raises-exception``): the message gives the
        cell's source, its output streams and the traceback.
    CellTimeoutError
        A cell ran longer than ``timeout``.
    """
    from .._compat.ipython import current_shell

    if timeout is not None and not timeout >= 0:
        raise ValueError(f"timeout must satisfy timeout >= 0 (or be None), got {timeout!r}")
    with _ONE_AT_A_TIME, _isolated(cwd):
        shell = _new_shell()
        open_before = set(_figure_numbers())
        try:
            with current_shell(shell):
                _run_cells(shell, nb, timeout, open_before)
        finally:
            # (not shell.atexit_operations(): its reset runs a full gc.collect)
            shell.user_ns.clear()
    nb.metadata["language_info"] = dict(_LANGUAGE_INFO, version=platform.python_version())
    return nb


def _run_cells(shell, nb, timeout, open_before) -> None:
    count = 0
    for cell in nb.cells:
        if cell.cell_type != "code" or not cell.source.strip():
            continue
        tags = cell.metadata.get("tags", [])
        if "skip-execution" in tags:
            continue
        count += 1
        rec = shell.recorder
        rec.outputs, rec.clear_pending = [], False
        result, timed_out = None, False
        streams = sys.stdout, sys.stderr
        sys.stdout = _Stream("stdout", rec, streams[0])
        sys.stderr = _Stream("stderr", rec, streams[1])
        try:
            with _alarm(timeout):
                result = shell.run_cell(cell.source, store_history=True)
                timed_out = isinstance(result.error_in_exec, _Timeout)
                if not timed_out and "matplotlib.pyplot" in sys.modules:
                    _show_open_figures(open_before)
        except _Timeout:  # outside the cell's own code (IPython's, or showing figures)
            timed_out = True
        finally:
            sys.stdout, sys.stderr = streams
        cell.outputs = rec.outputs
        cell.execution_count = count
        if timed_out:
            raise CellTimeoutError(
                _TIMEOUT_MESSAGE.format(timeout=timeout, source=cell.source),
                "CellTimeoutError",
                f"the cell ran longer than {timeout} s",
            )
        if not result.success and "raises-exception" not in tags:
            err = next((o for o in rec.outputs if o.output_type == "error"), None)
            error = result.error_before_exec or result.error_in_exec
            ename = err.ename if err else type(error).__name__
            evalue = err.evalue if err else str(error)
            traceback = "\n".join(err.traceback) if err else f"{ename}: {evalue}"
            raise CellExecutionError(_error_message(cell, rec.outputs, traceback), ename, evalue)
