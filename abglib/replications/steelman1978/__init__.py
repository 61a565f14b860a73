"""Seed 000: J. E. Steelman, *Frequency Response of α-β-γ Trackers* (WSMR, 1978).

``study``      the study: Tables 1-5, the design example, the statements about the figures
``equations``  the table of agreement of every numbered equation and the stability checks
``claims``     one declaration per published claim (the claim model)
``figures``    the responses of Figs. 1-6 and their drawing (matplotlib only when drawing)
"""
