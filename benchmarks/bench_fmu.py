"""Benchmark of the tire FMU: its cost per step beside ru.simulate's per sample, in one run.

Run on demand (never as a timed test)::

    python benchmarks/bench_fmu.py                 # 3 repeats, 100 000 steps
    python benchmarks/bench_fmu.py --steps 20000 --repeats 5

The paper's 165/65 R14 exported at 30 km/h (959 states, 73 tasselli, one road input at its
5 kHz step) and the car's 195/65 R15 at 120 km/h and 10 kHz. For each, timed in the same run:

* **FMU, C loop**: a small C driver (compiled here, outside the package) that loads the FMU's
  binary and calls ``fmi2SetReal``, ``fmi2GetReal`` and ``fmi2DoStep`` per step: the FMU's own
  cost, what a vehicle tool pays;
* **FMU, fmpy loop**: the same calls from Python through fmpy (ctypes), as chapter 15's master;
* **ru.simulate**: the fixed-hub tire on the tassello inputs of the same road, per sample;
* **road_hub_force**: our aggregated road-to-force simulation, per sample.

Ratios are of best times over the repeats; "x real time" is the step over the cost of a step.
"""

from __future__ import annotations

import argparse
import subprocess
import tempfile
import time
import zipfile
from pathlib import Path

import numpy as np

import roadnoise_utils as ru
from roadnoise_utils.fmu.drive import TireSlave
from roadnoise_utils.fmu.export import MODEL_IDENTIFIER, compiler, platform_folder
from roadnoise_utils.rm.aggregated import road_hub_force
from roadnoise_utils.road.input import profile_input

DRIVER = r"""
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "fmi2Functions.h"
static void logger(fmi2ComponentEnvironment e, fmi2String n, fmi2Status s, fmi2String c, fmi2String m, ...) {
    fprintf(stderr, "%s\n", m);
}
int main(int argc, char **argv) {
    void *lib = dlopen(argv[1], RTLD_NOW);
    int steps = atoi(argv[3]), strips = atoi(argv[4]), k, j;
    double dt = atof(argv[5]), out[3], inputs[64];
    fmi2CallbackFunctions callbacks = {logger, calloc, free, NULL, NULL};
    fmi2InstantiateTYPE *instantiate = (fmi2InstantiateTYPE *)dlsym(lib, "fmi2Instantiate");
    fmi2SetRealTYPE *set = (fmi2SetRealTYPE *)dlsym(lib, "fmi2SetReal");
    fmi2GetRealTYPE *get = (fmi2GetRealTYPE *)dlsym(lib, "fmi2GetReal");
    fmi2DoStepTYPE *step = (fmi2DoStepTYPE *)dlsym(lib, "fmi2DoStep");
    fmi2ValueReference in_refs[65], out_refs[3] = {0, 1, 2};
    struct timespec a, b;
    double checksum = 0.0;
    fmi2Component c = instantiate("bench", fmi2CoSimulation, "", argv[2], &callbacks, 0, 0);
    if (!c) return 1;
    in_refs[0] = 3;
    for (j = 0; j < strips; j++) in_refs[j + 1] = 10 + j;
    clock_gettime(CLOCK_MONOTONIC, &a);
    for (k = 0; k < steps; k++) {
        inputs[0] = 0.0;
        for (j = 0; j < strips; j++) inputs[j + 1] = 1e-3 * ((k * 7919 + j * 104729) % 1000) / 1000.0;
        set(c, in_refs, strips + 1, inputs);
        get(c, out_refs, 3, out);
        checksum += out[0];
        if (step(c, k * dt, dt, fmi2True) != fmi2OK) return 2;
    }
    clock_gettime(CLOCK_MONOTONIC, &b);
    printf("%.9f %.6e\n", (b.tv_sec - a.tv_sec) + 1e-9 * (b.tv_nsec - a.tv_nsec), checksum);
    return 0;
}
"""


def c_driver(folder: Path, sources: Path) -> Path:
    """The C driver above, compiled against the FMU's own headers."""
    (folder / "driver.c").write_text(DRIVER)
    target = folder / "driver"
    subprocess.run([compiler(), "-O2", f"-I{sources}", "-o", str(target), str(folder / "driver.c"), "-ldl"], check=True)
    return target


def c_loop(driver: Path, unzipped: Path, steps: int, strips: int, dt: float) -> float:
    binary = unzipped / "binaries" / platform_folder() / f"{MODEL_IDENTIFIER}.so"
    resources = (unzipped / "resources").as_uri()
    done = subprocess.run([str(driver), str(binary), resources, str(steps), str(strips), repr(dt)],
                          capture_output=True, text=True, check=True)  # fmt: skip
    return float(done.stdout.split()[0])


def fmpy_loop(path: Path, steps: int) -> float:
    with TireSlave(path) as slave:
        road = np.zeros(slave.n_strips)
        started = time.perf_counter()
        for k in range(steps):
            road[:] = 1e-3 * ((k * 7919) % 1000) / 1000.0
            slave.set(road, 0.0)
            slave.outputs()
            slave.step()
        return time.perf_counter() - started


def ours(tire: str, speed: float, rate: float, steps: int, lateral: bool) -> tuple[float, float]:
    """Seconds of ru.simulate on the tassello inputs and of road_hub_force, for ``steps`` samples of a random road."""
    static, fits = ru.stages.solve_static(tire), ru.stages.fit_tasselli(tire)
    sections = ru.rm.modal_sections(ru.assemble_fixed_hub(fits))
    travel = speed * (steps - 1) / rate
    heights = np.random.default_rng(1).normal(size=steps + 200) * 1e-3
    grid = np.arange(heights.size) * speed / rate - 0.2

    def profile(s, y=None):
        return np.interp(s, grid, heights)

    road = profile_input(static, profile, speed, (0.0, travel), rate)
    started = time.perf_counter()
    ru.simulate(sections, road)
    simulate_seconds = time.perf_counter() - started
    started = time.perf_counter()
    road_hub_force(sections, static, profile, speed, (0.0, travel), rate)
    return simulate_seconds, time.perf_counter() - started


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=100000)
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    cases = [("165_65R14", 30 / 3.6, None, False), ("195_65R15", 120 / 3.6, 10000.0, True)]
    with tempfile.TemporaryDirectory() as work:
        folder = Path(work)
        print(f"{'tire':10s} {'states':>6s} {'step (us)':>9s} | per step (us), best of {args.repeats}: "
              f"{'C loop':>8s} {'fmpy':>8s} {'simulate':>9s} {'road_hub_force':>14s} | C loop x real time, / simulate")  # fmt: skip
        for tire, speed, rate, lateral in cases:
            path = ru.export_fmu(tire, folder / f"{tire}.fmu", speed, rate, lateral=lateral)
            tables = ru.experiments.fmu_export.fmu_tables(tire, speed, rate, lateral)
            unzipped = folder / tire
            zipfile.ZipFile(path).extractall(unzipped)
            driver = c_driver(folder, unzipped / "sources")
            c_times = [c_loop(driver, unzipped, args.steps, tables.n_strips, tables.dt) for _ in range(args.repeats)]
            fmpy_times = [fmpy_loop(path, args.steps) for _ in range(args.repeats)]
            ours_times = [ours(tire, speed, 1 / tables.dt, args.steps, lateral) for _ in range(args.repeats)]
            per = {
                "C": min(c_times) / args.steps,
                "fmpy": min(fmpy_times) / args.steps,
                "simulate": min(t[0] for t in ours_times) / args.steps,
                "aggregated": min(t[1] for t in ours_times) / args.steps,
            }
            spread = f"C loop {min(c_times) / args.steps * 1e6:.2f}-{max(c_times) / args.steps * 1e6:.2f} us"
            print(
                f"{tire:10s} {tables.n_states:6d} {tables.dt * 1e6:9.1f} | {per['C'] * 1e6:25.2f} {per['fmpy'] * 1e6:8.2f} "
                f"{per['simulate'] * 1e6:9.2f} {per['aggregated'] * 1e6:14.2f} | {tables.dt / per['C']:6.1f}x, "
                f"{per['C'] / per['simulate']:.1f}x   ({spread})"
            )


if __name__ == "__main__":
    main()
