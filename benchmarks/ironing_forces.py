#!/usr/bin/env python3
"""Reaction forces of the ironing punch over the slide (doc/robustness.md,
doc/mortar.md): the apparent friction ratio |Fx/Fy| and, for Fx, Fy and
Fx/Fy,

* sd / mean: the standard deviation over the window relative to the mean
  (issue 18's measure of the force oscillation);
* drift: the standard deviation of the moving average over one foundation
  segment of slide, relative to the mean: the slow change of the mean
  force (the pile-up growing), which the sd / mean contains as well;
* oscillation: the rms (and the largest) deviation of each increment's
  value from that moving average, relative: the segment-to-segment
  oscillation alone.

    python3 benchmarks/ironing_forces.py output/ironing/history.csv
        [--from 2.0] [--to 1e9] [--window 0.1] [--reference other.csv]

--from, --to: the evaluation window in time (t = 1 + slide/2 in
ironing.prm, so 2.0 is 2 mm of slide); --window: moving-average width in
time (0.1 = 0.2 mm of slide = one foundation segment of
parameters/ironing.prm); the moving average reads the increments on both
sides of the window's ends. --reference: a second history (node to
segment, say), whose measures are printed too, with the ratios of the
first's to its. Columns RF13_x, RF13_y: the reaction at the punch's top
(boundary id 13).
"""

import argparse
import csv
import math
import statistics


def measures(path, start, end, width):
    """The window's means and, per quantity, (sd / mean, drift,
    oscillation rms, oscillation max) as fractions."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    t = [float(r["time"]) for r in rows]
    fx = [float(r["RF13_x"]) for r in rows]
    fy = [float(r["RF13_y"]) for r in rows]
    ratio = [abs(a / b) if b != 0 else 0. for a, b in zip(fx, fy)]
    inside = [i for i, ti in enumerate(t) if start <= ti <= end]
    if not inside:
        raise SystemExit("%s: no increments in [%g, %g]" % (path, start, end))

    def moving_average(values, i):
        window = [values[j] for j in range(len(t))
                  if abs(t[j] - t[i]) <= width / 2 + 1e-12]
        return sum(window) / len(window)

    result = {"n": len(inside),
              "Fy": statistics.mean(fy[i] for i in inside),
              "Fx": statistics.mean(fx[i] for i in inside)}
    for name, values in (("Fy", fy), ("Fx", fx), ("Fx/Fy", ratio)):
        window = [values[i] for i in inside]
        mean = abs(statistics.mean(window))
        averages = [moving_average(values, i) for i in inside]
        deviations = [abs(v - a) / abs(a) for v, a in zip(window, averages)]
        result[name + " measures"] = (
            statistics.pstdev(window) / mean,
            statistics.pstdev(averages) / mean,
            math.sqrt(sum(d * d for d in deviations) / len(deviations)),
            max(deviations))
    return result


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("history")
    parser.add_argument("--from", dest="start", type=float, default=2.0)
    parser.add_argument("--to", dest="end", type=float, default=1e9)
    parser.add_argument("--window", type=float, default=0.1)
    parser.add_argument("--reference")
    args = parser.parse_args()

    runs = [(args.history, measures(args.history, args.start, args.end,
                                    args.window))]
    if args.reference:
        runs.append((args.reference, measures(args.reference, args.start,
                                              args.end, args.window)))
    for path, m in runs:
        print("%s: %d increments in [%g, %g]; means Fx %.4g, Fy %.4g, "
              "|Fx/Fy| %.4f" % (path, m["n"], args.start, min(args.end, 1e9),
                                m["Fx"], m["Fy"], abs(m["Fx"] / m["Fy"])))
        for name in ("Fy", "Fx", "Fx/Fy"):
            sd, drift, rms, peak = m[name + " measures"]
            print("  %-5s sd/mean %.3f %%, drift %.3f %%, oscillation about "
                  "its moving average: rms %.3f %%, max %.2f %%"
                  % (name, 100 * sd, 100 * drift, 100 * rms, 100 * peak))
    if args.reference:
        first, second = runs[0][1], runs[1][1]
        for name in ("Fy", "Fx"):
            a, b = first[name + " measures"], second[name + " measures"]
            print("ratio to the reference, %-2s: sd/mean %.3f, drift %.3f, "
                  "oscillation rms %.3f" % (name, a[0] / b[0], a[1] / b[1],
                                            a[2] / b[2]))


if __name__ == "__main__":
    main()
