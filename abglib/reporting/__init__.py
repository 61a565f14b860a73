"""Reporting plumbing (extra ``abglib[reporting]``): published-versus-reproduced tables,
provenance, notebook rendering and the shared figure style.

``compare``     ``comparison.csv`` and the scorecard (``shared/CONTRACTS.md`` section 3)
``provenance``  versions, commit, config hash and seeds of a build
``render``      report notebook -> HTML, and the index page
``plotting``    the one figure style and deterministic PNG saving (imports matplotlib)
``pipeline``    glue for the Snakemake workflow (logging, atomic outputs, config checks)
"""
