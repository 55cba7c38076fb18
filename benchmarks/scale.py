"""Scale-out benchmark (issue 26): a sweep streamed to a Parquet dataset, in this
process and on one and two local Dask workers.

``make bench`` runs this file. On the design problem of ``hitch_003_design.toml``
(the seed-003 hitch, its four frame pivots within ±30 mm) at ``--positions`` positions,
a sweep of ``--designs`` designs (``sweep_to``: the designs drawn by the workers, each
chunk's part written by the client as it completes) is timed

* in this process;
* on a LocalCluster of 1 and of 2 worker processes (one thread each; the cluster's
  start and the workers' first chunk — the problem rebuilt from its content, the
  kernel loaded — are outside the figure: a small sweep runs first);

and for each: designs·positions/s, the evaluation time (from the first submission to
the last part written) and the overhead after the last chunk (writing the manifest,
the summary), which must stay within 10 % of the evaluation time (before issue 26 the
client concatenated every result: 95 s of a 235 s run at 1e7 designs). The peak
resident memory of this process is printed too.

Figures are printed for people to read; nothing here is a test.

Usage: ``python benchmarks/scale.py [--designs 2e6] [--positions 10]``
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import sys
import tempfile
import time

from assur import io
from assur.io import load_problem
from assur.synthesis.search.scale import Executor, sweep_to


def run(pb, designs, workers, where):
    stamps = {}

    def progress(done, total):
        stamps.setdefault("first", time.perf_counter())
        if done == total:
            stamps["last"] = time.perf_counter()

    ex = Executor(workers=workers, chunk=16384, progress=progress)
    with ex:
        sweep_to(pb, os.path.join(where, "warm"), samples=4 * 4096, seed=0, executor=ex)
        stamps.clear()
        t0 = time.perf_counter()
        r = sweep_to(pb, os.path.join(where, f"w{workers}"), samples=designs, seed=1,
                     executor=ex)
        t1 = time.perf_counter()
    evaluation = stamps["last"] - t0
    after = t1 - stamps["last"]
    return r, evaluation, after


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--designs", type=float, default=2e6)
    ap.add_argument("--positions", type=int, default=10)
    args = ap.parse_args(argv)
    designs = int(args.designs)
    pb = load_problem(io.bundled("hitch_003_design"), positions=args.positions)
    print(f"scale-out: {designs:.3g} designs × {pb.n_positions} positions of "
          f"{pb.name} (pivots ±30 mm), usable CPUs {len(os.sched_getaffinity(0))}")
    where = tempfile.mkdtemp(prefix="assur-bench-scale-")
    try:
        ref = None
        for workers, label in ((0, "this process"), (1, "1 local worker"),
                               (2, "2 local workers")):
            r, ev, after = run(pb, designs, workers, where)
            rate = designs * pb.n_positions / ev
            share = 100 * after / ev
            print(f"  {label:16s} {rate:10.3g} designs·positions/s   evaluation {ev:6.1f} s"
                  f"   after the last chunk {after:5.2f} s ({share:.1f} % of it"
                  f"{'' if share <= 10 else ', ABOVE the 10 % target'})")
            same = ref is None or (r.feasible, r.best) == ref
            ref = ref or (r.feasible, r.best)
            if not same:
                print("    the results differ from the in-process run!")
        peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
        print(f"  peak resident memory of this process: {peak:.0f} MiB")
    finally:
        shutil.rmtree(where, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
