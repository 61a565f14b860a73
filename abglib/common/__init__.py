"""What every layer above the tracker core shares (extras: pandas, matplotlib).

The benchmark (:mod:`abglib.bench`), the replications (:mod:`abglib.replications`) and the
reports (:mod:`abglib.reporting`) write the same kind of tables and figures; their one
home is here, one layer above the core and below all three, so that none of them imports
a layer above it (``docs/architecture.md``, checked by ``tests/test_layers.py``). The
name follows ``workflow/rules/common.smk``, the snakemake-workflow template's file for
what every rule shares; scipy's private ``scipy._lib`` plays the same part for its
subpackages. It imports the core (the verdict engine's number formatting) and never a
layer above it.

``tables``    a table's column precisions, its deterministic CSV text, the atomic write
              and the read back (pandas); the generated ``_precision_table``
``files``     atomic outputs, canonical JSON and a config's sha256 (standard library)
``jobs``      a pipeline job's threads and its log (numba, logging)
``plotting``  the one figure style, its colours and legends, deterministic PNGs
              (matplotlib: imported only here and by the figure modules)
``pngmeta``   a PNG's alt text read back with the standard library
``memo``      a least-recently-used cache bounded by bytes (standard library)

Nothing is imported here: ``import abglib.common.files`` does not bring pandas or
matplotlib.
"""
