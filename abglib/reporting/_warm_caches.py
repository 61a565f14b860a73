"""Imported by the warm worker's fork server only (:data:`.workers.PRELOAD`): loads the
compiled loops most jobs call (:func:`.workers.load_kernels`) and fills matplotlib's
caches a figure job's first figure would fill (:func:`.workers.load_figures`), so that a
job forked from the server finds them in memory (0.35-0.5 s a job for the loops, 0.3-0.4
s a figure job for matplotlib).

Last, everything the server holds is frozen (:func:`.workers.freeze_preloaded`): a job's
garbage collections no longer traverse the preloaded modules. Importing this module
anywhere else costs that work once and freezes that process's objects too."""

from .workers import freeze_preloaded, load_figures, load_kernels

load_kernels()
load_figures()
freeze_preloaded()
