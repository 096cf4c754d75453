#!/usr/bin/env python3
"""Reaction forces of the ironing punch over the slide (doc/robustness.md):
the apparent friction ratio |Fx/Fy| and the segment-to-segment oscillation
of Fx, Fy and Fx/Fy, measured as the deviation of each increment's value
from its moving average over one foundation segment of slide.

    python3 benchmarks/ironing_forces.py output/ironing/history.csv
        [--from 2.0] [--window 0.1]

--from: first time of the evaluation (t = 1 + slide/2 in ironing.prm, so
2.0 is 2 mm of slide); --window: moving-average width in time (0.1 = 0.2
mm of slide = one foundation segment of parameters/ironing.prm).
Columns RF13_x, RF13_y: the reaction at the punch's top (boundary id 13).
"""

import argparse
import csv
import math
import statistics


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("history")
    parser.add_argument("--from", dest="start", type=float, default=2.0)
    parser.add_argument("--window", type=float, default=0.1)
    args = parser.parse_args()

    with open(args.history) as f:
        rows = [r for r in csv.DictReader(f) if float(r["time"]) >= args.start]
    if not rows:
        raise SystemExit("no increments after t = %g" % args.start)
    t = [float(r["time"]) for r in rows]
    fx = [float(r["RF13_x"]) for r in rows]
    fy = [float(r["RF13_y"]) for r in rows]
    ratio = [abs(a / b) for a, b in zip(fx, fy)]

    def oscillation(values):
        """Max and rms of |v - moving average| / |moving average|."""
        deviations = []
        first = 0
        for i, ti in enumerate(t):
            while t[first] < ti - args.window / 2:
                first += 1
            window = [values[j] for j in range(first, len(t))
                      if t[j] <= ti + args.window / 2]
            mean = sum(window) / len(window)
            deviations.append(abs(values[i] - mean) / abs(mean))
        return max(deviations), math.sqrt(
            sum(d * d for d in deviations) / len(deviations))

    print("increments from t = %g: %d" % (args.start, len(rows)))
    print("Fx/Fy: mean %.4f, sd %.4f, min %.4f, max %.4f"
          % (statistics.mean(ratio), statistics.pstdev(ratio), min(ratio),
             max(ratio)))
    print("Fy: mean %.4g, Fx: mean %.4g" % (statistics.mean(fy),
                                           statistics.mean(fx)))
    for name, values in (("Fy", fy), ("Fx", fx), ("Fx/Fy", ratio)):
        peak, rms = oscillation(values)
        print("oscillation of %s about its moving average: rms %.2f %%, "
              "max %.2f %%" % (name, 100 * rms, 100 * peak))


if __name__ == "__main__":
    main()
