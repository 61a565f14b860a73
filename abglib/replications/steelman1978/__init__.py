"""Seed 000: J. E. Steelman, *Frequency Response of α-β-γ Trackers* (WSMR, 1978)."""
