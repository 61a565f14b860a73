"""Reporting plumbing (extra ``abglib[reporting]``): provenance, notebook rendering,
report pages, releases and the workflow's glue; the top layer of the package.

``provenance``  versions, commit, config hash and seeds of a build
``render``      report notebook -> HTML, and the index page
``pipeline``    glue for the Snakemake workflow (config checks, report rules)
``precision``   each table column's digits derived from plain and perturbed builds
``verify``      a build checked against a release (``abglib verify``)

The comparison tables themselves are :mod:`abglib.replications.compare`; the shared table
writing and figure style are :mod:`abglib.common`.
"""
