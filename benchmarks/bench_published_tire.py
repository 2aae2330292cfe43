"""The tire models of the published MF-Swift reference tire's size beside it, in one table.

Run on demand (never as a timed test; the loaded FE tire's three load cases take minutes each)::

    python benchmarks/bench_published_tire.py                       # the three 205/60 R15 files
    python benchmarks/bench_published_tire.py --tires 205_60R15     # some of them

Each tire file of ``--tires`` (default: the ring, the cross-section and the loaded FE 205/60 R15,
each built from its own files at the published tire's size and nominal pressure, none tuned to it)
is loaded on the flat road at 2, 4 and 6 kN through the tire-model interface
(:func:`roadnoise_utils.experiments.mf_swift.published_comparison`), beside the TNO MF-Swift 6.1
205/60 R15 reference tire (``data/published/205_60R15_mf_swift.toml``): the tangent vertical
stiffness at 4 kN, how it changes to 2 and 6 kN, the deflection and the contact length at 4 kN.
Prints the table and each model's time (the stage cache keeps its load cases).
"""

from __future__ import annotations

import argparse
import time

import pandas as pd

from roadnoise_utils.experiments.mf_swift import mf_swift_tire, published_comparison

TIRES = ("205_60R15", "205_60R15_cross_section", "205_60R15_loaded")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tires", nargs="+", default=list(TIRES))
    args = parser.parse_args()
    published = mf_swift_tire()
    rows = [published_comparison(published, [])]
    for name in args.tires:
        start = time.perf_counter()
        rows.append(published_comparison(published, [name]).iloc[1:])
        print(f"{name}: {time.perf_counter() - start:.0f} s", flush=True)
    with pd.option_context("display.width", 200, "display.max_columns", 20, "display.precision", 3):
        print(pd.concat(rows).T.to_string())


if __name__ == "__main__":
    main()
