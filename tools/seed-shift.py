#!/usr/bin/env python
"""Seed-shift check of the verdicts (issue 21): does a rebuild with every random seed moved
flip a row marked robust=true?

Judges one document's claims (abglib.replications.judge_claims, the <doc>_claims job) with
the configured seeds and with every seed of abglib.verdicts.robustness.seed_paths (the
document's section and ``datasets``) moved by each prime given, then lists the rows marked
``robust=true`` under the configured seeds whose verdict changes.

    python tools/seed-shift.py alwagih 104729 7919 1299709 [--configfile config.yaml]

Exit status 1 when some robust=true row flips. Costs one claims job per shift (Al-Wagih
about 1 min on an idle 2-core machine, 4-7 min on a loaded one).
"""

from __future__ import annotations

import argparse
import glob
import sys
import time

import yaml

from abglib.replications import DOCS, judge_claims
from abglib.verdicts.robustness import with_seeds_shifted


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("doc", choices=list(DOCS))
    ap.add_argument("shifts", nargs="+", type=int, help="seed shifts (primes)")
    ap.add_argument("--configfile", default="config.yaml")
    args = ap.parse_args(argv)
    with open(args.configfile, encoding="utf-8") as fh:
        cfg = yaml.safe_load(fh)
    paths = sorted(glob.glob(f"data/published/{args.doc}/*.csv"))
    overrides = (cfg.get("tolerance_overrides") or {}).get(args.doc, {})
    judged = {}
    for shift in [0, *args.shifts]:
        t0 = time.perf_counter()
        c = cfg if shift == 0 else with_seeds_shifted(cfg, args.doc, shift)
        judged[shift] = judge_claims(args.doc, c, paths, overrides)["comparison"]
        counts = judged[shift].groupby(["verdict", "robust"]).size().to_dict()
        print(f"{args.doc} shift {shift}: {time.perf_counter() - t0:.0f} s, {counts}")
    base = judged[0]
    bad = 0
    for shift in args.shifts:
        other = judged[shift]
        changed = base["verdict"] != other["verdict"]
        flips = base[changed & (base["robust"] == "true")]
        bad += len(flips)
        print(
            f"{args.doc} shift {shift}: {int(changed.sum())} verdicts change, "
            f"{len(flips)} of them in rows marked robust=true"
        )
        for i in flips.index:
            print(f"    {base.at[i, 'item']}: {base.at[i, 'verdict']} -> {other.at[i, 'verdict']}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
