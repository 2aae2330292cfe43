"""Benchmark of the fitting stage: our relaxed vector fitting vs scikit-rf and pyvectorfit, side by side.

Run on demand (never as a timed test)::

    python benchmarks/bench_fitting.py [--tire 165_65R14] [--repeat 3] [--contend]

All on the direct local FRFs of every tassello (0-250 Hz, the stage cache), in one run, times as
ranges over ``--repeat`` runs (the errors do not vary between runs):

1. per tassello, at the paper's order (8) and at the pipeline's: ours from both starting pole sets
   (``starting_poles=STARTS``), ours from the linear start (the default), scikit-rf's ``VectorFitting`` and
   pyvectorfit's ``fit``; worst and median tassello error, tasselli at least as good as ours;
   then, at every order 8-20, ours against the better of the two peers, tassello by tassello;
2. the iteration cap: the worst tassello's error, best vs last iteration, as the cap rises;
3. one pole set for all tasselli (``common_poles=True``) against pyvectorfit's multi-channel fit,
   and the automatic order (``n_poles="auto"``, every tassello within 1 %): states and errors;
4. our fits with BLAS limited to one thread (as ``fit_tasselli`` runs them) and with the
   library's default threads; ``--contend`` keeps one core busy meanwhile (two notebooks at
   once, as the reproduction runs them), where the threads fight.
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import warnings

import numpy as np
from threadpoolctl import threadpool_info, threadpool_limits

import roadnoise_utils as ru
from roadnoise_utils.rm import fitting_peer
from roadnoise_utils.rm.vf_kernels import STARTS

BAND = 250.0


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tire", default="165_65R14")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument(
        "--contend", action="store_true", help="keep one core busy with another process (as a second notebook would)"
    )
    args = parser.parse_args()
    busy = subprocess.Popen([sys.executable, "-c", "while True: pass"]) if args.contend else None
    try:
        _run(args)
    finally:
        if busy is not None:
            busy.kill()


def _span(seconds: list[float]) -> str:
    return f"{min(seconds):.3f}-{max(seconds):.3f}"


def _ours(visco, repeat: int, **options) -> tuple[ru.FitSet, list[float]]:
    runs = [ru.fit_tasselli(visco.freqs, visco.H, f_max=BAND, **options) for _ in range(repeat)]
    return runs[-1], [r.seconds for r in runs]


def _peer(call, repeat: int, *args, **options) -> tuple[np.ndarray, list[float]]:
    runs = [call(*args, **options) for _ in range(repeat)]
    return runs[-1][0], [r[1] for r in runs]


def _row(poles, method, states, errors, ours, seconds) -> str:
    good = "-" if ours is None else f"{int(np.sum(errors <= ours))} of {errors.size}"
    time = "-" if seconds is None else _span(seconds)
    return f"| {poles} | {method} | {states} | {errors.max():.2e} | {np.median(errors):.2e} | {good} | {time} |"


def _run(args) -> None:
    tire = ru.load_tire(args.tire)
    visco = ru.stages.frf_visco(tire)
    order = ru.stages.fit_tasselli(tire).n_poles
    n = visco.H.shape[0]
    print(f"tire {tire.name}: {n} tassello FRFs, 0-{BAND:.0f} Hz at 1 Hz, {args.repeat} repeats\n")

    print(
        "| poles | method | states | worst rms error | median rms error | tasselli at least as good as ours | time (s) |"
    )
    print("|---|---|---|---|---|---|---|")
    for poles in (8, order):
        ours, seconds = _ours(visco, args.repeat, n_poles=poles, starting_poles=STARTS)
        linear, linear_seconds = _ours(visco, args.repeat, n_poles=poles)
        skrf = _peer(fitting_peer.skrf_vector_fit, args.repeat, visco.freqs, visco.H, poles, BAND)
        pvf = _peer(fitting_peer.pyvectorfit_fit, args.repeat, visco.freqs, visco.H, poles, BAND)
        e = ours.rms_errors
        print(_row(poles, "roadnoise, both starts", n * poles, e, e, seconds))
        print(_row(poles, "roadnoise, linear start (default)", n * poles, linear.rms_errors, e, linear_seconds))
        print(_row(poles, "scikit-rf VectorFitting", n * poles, skrf[0], e, skrf[1]))
        print(_row(poles, "pyvectorfit fit", n * poles, pvf[0], e, pvf[1]))

    print("\nEvery order 8-20: ours from both starts against the better of scikit-rf and pyvectorfit, per tassello")
    print("| poles | worst ours / best peer | tasselli above 1.2x | kept from the log start | worst rms error (ours) |")
    print("|---|---|---|---|---|")
    for poles in range(8, 21):
        ours = ru.fit_tasselli(visco.freqs, visco.H, n_poles=poles, f_max=BAND, starting_poles=STARTS)
        skrf = fitting_peer.skrf_vector_fit(visco.freqs, visco.H, poles, BAND)[0]
        pvf = fitting_peer.pyvectorfit_fit(visco.freqs, visco.H, poles, BAND)[0]
        ratio = ours.rms_errors / np.minimum(skrf, pvf)
        from_log = sum(f.start == "log" for f in ours)
        print(
            f"| {poles} | {ratio.max():.3f} | {int(np.sum(ratio > 1.2))} | {from_log} of {n} | "
            f"{ours.rms_errors.max():.3e} |"
        )

    print("\nIteration cap (tolerance 1e-3, the default): the worst tassello's rms error, best vs last iteration")
    print("| poles | iterations (cap) | best iteration (ours) | last iteration | tasselli whose last is worse |")
    print("|---|---|---|---|---|")
    for poles in sorted({12, order, 18}):
        for cap in (4, 8, 20, 50):
            fits = ru.fit_tasselli(
                visco.freqs, visco.H, n_poles=poles, f_max=BAND, iterations=cap, starting_poles=STARTS
            )
            last = np.array([f.errors[-1] for f in fits])
            worse = int(np.sum(last > fits.rms_errors * (1 + 1e-9)))
            print(f"| {poles} | {cap} | {fits.rms_errors.max():.3e} | {last.max():.3e} | {worse} |")

    print("\nOne pole set for all tasselli (common poles) and the automatic order (every tassello within 1 %):")
    print(
        "| poles | method | states | worst rms error | median rms error | tasselli at least as good as ours | time (s) |"
    )
    print("|---|---|---|---|---|---|---|")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ru.guards.RoadnoiseWarning)
        auto, seconds = _ours(visco, args.repeat, n_poles="auto", target_error=0.01)
        print(
            _row(
                f"auto: {auto.n_poles}",
                "roadnoise, own poles per tassello",
                auto.n_states,
                auto.rms_errors,
                None,
                seconds,
            )
        )
        common_auto, seconds = _ours(visco, args.repeat, n_poles="auto", target_error=0.01, common_poles=True)
        e = common_auto.rms_errors
        print(_row(f"auto: {common_auto.n_poles}", "roadnoise, common poles", common_auto.n_states, e, None, seconds))
    for poles in sorted({common_auto.n_poles, 18, 20}):
        common, seconds = _ours(visco, args.repeat, n_poles=poles, common_poles=True)
        e = common.rms_errors
        pvf = _peer(fitting_peer.pyvectorfit_fit, args.repeat, visco.freqs, visco.H, poles, BAND, common_poles=True)
        print(_row(poles, "roadnoise, common poles", common.n_states, e, e, seconds))
        print(_row(poles, "pyvectorfit fit, all tasselli as channels", poles, pvf[0], e, pvf[1]))

    blas_rows = []
    for poles in (8, order):
        with threadpool_limits(None, user_api="blas"):  # BLAS threads back to the library's default
            ru.rm.fitting.FIT_THREADS, saved = None, ru.rm.fitting.FIT_THREADS
            try:
                threaded = _ours(visco, args.repeat, n_poles=poles)[1]
            finally:
                ru.rm.fitting.FIT_THREADS = saved
        one = _ours(visco, args.repeat, n_poles=poles)[1]
        blas_rows.append(f"| {poles} | {_span(one)} | {_span(threaded)} |")
    beside = ", one core kept busy by another process" if args.contend else ""
    print(f"\nBLAS threads inside our fits ({threadpool_info()[0].get('num_threads', '?')} by default here{beside}), "
          f"time for all fits over {args.repeat} repeats (s):")  # fmt: skip
    print("| poles | 1 thread (FIT_THREADS) | library default |")
    print("|---|---|---|")
    print("\n".join(blas_rows))


if __name__ == "__main__":
    main()
