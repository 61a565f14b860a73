"""Imported by the warm worker's fork server only (:data:`.workers.PRELOAD`): loads the
compiled loops most jobs call (:func:`.workers.load_kernels`), so that a job forked from
the server finds them in memory instead of loading each from numba's disk cache again
(0.35-0.5 s a job). Importing it anywhere else only costs that load once."""

from .workers import load_kernels

load_kernels()
