#!/usr/bin/env bash
# The paper's cylinder compression (section 4.1) with penalty 10E, 100E,
# 1000E and the augmented Lagrangian: plate force against plate
# displacement, with the analytic homogeneous-compression curve. Writes
# doc/data/cylinder_<variant>.csv, doc/data/cylinder_study.csv and
# doc/cylinder_force.png.    bash benchmarks/cylinder_study.sh [build/tribos]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tribos=${1:-$root/build/tribos}
out=$(mktemp -d)
mkdir -p "$root/doc/data"
for variant in 10E 100E 1000E augmented; do
  if [ $variant = augmented ]; then
    sets=(--set "Contact/Method=augmented lagrangian" --set "Contact/Augmentation tolerance=1e-6")
  else
    sets=(--set "Contact/Penalty factor=${variant%E}*E")
  fi
  start=$(date +%s.%N)
  "$tribos" "$root/parameters/cylinder_compression.prm" "${sets[@]}" \
    --set "Output/Directory=$out/$variant" --set "Output/Write VTU=false" > /dev/null
  end=$(date +%s.%N)
  cp "$out/$variant/history.csv" "$root/doc/data/cylinder_$variant.csv"
  echo "$variant $(echo "$end - $start" | bc)" >> "$out/times"
done
python3 - "$root" "$out/times" <<'PY'
import csv, math, sys
root, times = sys.argv[1], dict(l.split() for l in open(sys.argv[2]))
E, s0, sinf, delta, H, r = 206.9, 0.45, 0.715, 16.93, 0.12924, 6.35
area = 4 * r * r * math.sin(math.pi / 16)
eps_p = alpha = 0.0
analytic = []
for k in range(1, 26):
    stretch = (r - 0.2 * k) / r
    trial = E * (math.log(stretch) - eps_p)
    y = lambda a: s0 + (sinf - s0) * (1 - math.exp(-delta * a)) + H * a
    if abs(trial) > y(alpha):
        da = 0.0
        for _ in range(60):
            da += (abs(trial) - E * da - y(alpha + da)) / (
                E + (sinf - s0) * delta * math.exp(-delta * (alpha + da)) + H)
        eps_p += math.copysign(da, trial); alpha += da
    analytic.append(abs(E * (math.log(stretch) - eps_p) / stretch * area))
with open(root + "/doc/data/cylinder_analytic.csv", "w") as f:
    f.write("displacement,force\n" + "".join("%g,%.8g\n" % (0.2 * (k + 1), a) for k, a in enumerate(analytic)))
with open(root + "/doc/data/cylinder_study.csv", "w") as f:
    f.write("variant,newton_iterations,wall_time,final_force,final_error,max_error\n")
    for v in ("10E", "100E", "1000E", "augmented"):
        rows = list(csv.DictReader(open(root + "/doc/data/cylinder_%s.csv" % v)))
        errors = [abs(abs(float(x["pair0_Fz"])) - a) / a for x, a in zip(rows, analytic)]
        f.write("%s,%d,%s,%.6g,%.3e,%.3e\n" % (v, sum(int(x["newton_iterations"]) for x in rows),
                times[v], abs(float(rows[-1]["pair0_Fz"])), errors[-1], max(errors)))
print(open(root + "/doc/data/cylinder_study.csv").read())
PY
cd "$root"
gnuplot <<'GP'
set datafile separator ","
set terminal pngcairo size 900,600 font ",11" noenhanced
set output "doc/cylinder_force.png"
set grid
set key left top
set title "Cylinder compression (1/8 model): plate force against plate displacement"
set xlabel "plate displacement [mm]"
set ylabel "plate force on the 1/8 model [kN]"
plot "doc/data/cylinder_analytic.csv" using 1:2 with points pt 6 ps 1.5 title "analytic (homogeneous compression)", \
     for [v in "10E 100E 1000E augmented"] "doc/data/cylinder_".v.".csv" using (0.2*column("time")):(-column("pair0_Fz")) with lines lw 2 title v
GP
echo "wrote doc/data/cylinder_study.csv, doc/cylinder_force.png"
