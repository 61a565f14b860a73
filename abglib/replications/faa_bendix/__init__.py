"""Seed 003: Elwell (FAA), *Bendix Alpha-Beta Tracking Filter Test*, with Sinsky's memo.

``program``  the test program's difference equations, test inputs and the memo's table
``figures``  the report's figures (imports matplotlib; not loaded here)
"""

from .program import *  # noqa: F403
