"""IPython (and traitlets) internals that the in-process notebook runner uses.

:mod:`abglib.reporting.execute` runs a report notebook in a fresh
:class:`IPython.core.interactiveshell.InteractiveShell` of the calling process, without a
kernel. For IPython's maintainers, what it needs and which public API would replace it:

- **A cell's error as data** (:func:`error_routing_shell`: overriding
  ``InteractiveShell._showtraceback(etype, evalue, stb)``, as ipykernel's
  ``ZMQInteractiveShell`` does): the runner records the exception's name, value and
  formatted traceback as an nbformat ``error`` output instead of printing them. Wanted: a
  documented hook, e.g. a configurable ``traceback_publisher`` like ``display_pub_class``.
- **Making a shell the current one for a while** (:func:`current_shell`: traitlets'
  ``SingletonConfigurable._walk_mro()`` and the ``_instance`` of each class it yields),
  so that ``get_ipython()`` and ``display()`` inside the notebook reach its shell and the
  process's own shell (if any, e.g. when called from Jupyter) comes back afterwards.
  ``InteractiveShell.instance()`` can create the singleton but refuses a second one and
  cannot put the previous one back. Wanted: a public context manager
  ``InteractiveShell.as_current()`` (or ``SingletonConfigurable.set_instance``).

Replaced by public mechanisms (no internal used any more):

- ``input()`` refused: ``builtins.input`` is replaced while the notebook runs (what
  ipykernel does with ``raw_input``) instead of ``shell.builtin_trap.auto_builtins``;
- the exit handler a shell registers: :func:`without_exit_handlers` keeps the shell's
  ``atexit.register`` calls from registering at all (``atexit.register`` is looked up at
  call time), instead of ``atexit.unregister(shell.atexit_operations)``, which would go
  quiet if IPython registered another callable;
- ``print_figure`` (``IPython.core.pylabtools``, documented), the display publisher and
  display hook classes (``display_pub_class``, ``displayhook_class``) are public.

Checked against IPython 8.12.3 and traitlets 5.15.0 (older sources were not read; the
version-range builds run the checks at the lower bound).
"""

from __future__ import annotations

import atexit
import threading
from contextlib import contextmanager

from . import changed, check_parameters

__all__ = ["current_shell", "error_routing_shell", "without_exit_handlers"]

_HERE = "ipython"
_SHOWTRACEBACK = ("self", "etype", "evalue", "stb")
_BASE = None


def error_routing_shell():
    """A subclass of ``InteractiveShell`` whose cell errors go to ``self.show_error``.

    A subclass defines ``show_error(etype, evalue, stb)`` (``stb``: the formatted
    traceback, a list of str); it replaces IPython's printing of the traceback
    (``InteractiveShell._showtraceback``, which it overrides). Built once.

    Raises
    ------
    UpstreamChanged
        ``InteractiveShell._showtraceback`` is missing or takes other parameters than
        ``(self, etype, evalue, stb)``.
    """
    global _BASE
    if _BASE is not None:
        return _BASE
    from IPython.core.interactiveshell import InteractiveShell

    original = getattr(InteractiveShell, "_showtraceback", None)
    if original is None:
        raise changed("ipython", "InteractiveShell._showtraceback", "does not exist", _HERE)
    check_parameters(original, _SHOWTRACEBACK, "ipython", "InteractiveShell._showtraceback", _HERE)

    class ErrorRoutingShell(InteractiveShell):
        """An ``InteractiveShell`` handing each cell error to ``show_error``."""

        def _showtraceback(self, etype, evalue, stb):
            self.show_error(etype, evalue, stb)

        def show_error(self, etype, evalue, stb):
            raise NotImplementedError("a subclass says where a cell's error goes")

    _BASE = ErrorRoutingShell
    return _BASE


def _singleton_classes(shell) -> list:
    """Every class of ``shell``'s MRO that holds the singleton (traitlets' ``_walk_mro``)."""
    from traitlets.config.configurable import SingletonConfigurable

    walk = getattr(SingletonConfigurable, "_walk_mro", None)
    if walk is None or not callable(walk):
        raise changed("traitlets", "SingletonConfigurable._walk_mro", "does not exist", _HERE)
    if "_instance" not in vars(SingletonConfigurable):
        raise changed("traitlets", "SingletonConfigurable._instance", "does not exist", _HERE)
    return list(type(shell)._walk_mro())


@contextmanager
def current_shell(shell):
    """Make ``shell`` the process's IPython (``get_ipython()``, ``display``) in the block;
    the previous one (or none) is current again afterwards.

    Raises
    ------
    UpstreamChanged
        traitlets' ``_walk_mro`` or ``_instance`` is missing, or setting them does not make
        ``InteractiveShell.instance()`` return ``shell``.
    """
    from IPython.core.interactiveshell import InteractiveShell

    classes = _singleton_classes(shell)
    saved = {c: c.__dict__.get("_instance") for c in classes}
    for c in classes:
        c._instance = shell
    try:
        if not (InteractiveShell.initialized() and InteractiveShell.instance() is shell):
            raise changed(
                "traitlets",
                "SingletonConfigurable._instance",
                "no longer decides InteractiveShell.instance()",
                _HERE,
            )
        yield shell
    finally:
        for c, inst in saved.items():
            c._instance = inst


_REGISTERING = threading.Lock()


def without_exit_handlers(factory, *args, **kwargs):
    """``factory(*args, **kwargs)`` (a shell's constructor) with the exit handlers it
    registers (``atexit.register``, from this thread) left unregistered.

    An ``InteractiveShell`` registers its ``atexit_operations`` when it is built; a
    registered handler keeps the shell (and the notebook's namespace) alive until the
    process ends, one per executed notebook. Returns what ``factory`` returns.
    """
    me = threading.get_ident()
    with _REGISTERING:
        real = atexit.register

        def register(func, *a, **kw):
            if threading.get_ident() == me:
                return func  # atexit.register's return value
            return real(func, *a, **kw)

        atexit.register = register
        try:
            return factory(*args, **kwargs)
        finally:
            atexit.register = real
