#!/usr/bin/env bash
# Necking bar (parameters/necking_bar.prm, 2D axisymmetric Q2) on its mesh
# (8 x 20 cells) and refined once (16 x 40): plate force and neck radius
# against the total elongation. Writes doc/data/necking_r<k>.csv,
# doc/data/necking_study.csv and doc/necking.png.
#   bash benchmarks/necking_study.sh [build/tribos]        (~2.5 minutes)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tribos=${1:-$root/build/tribos}
out=$(mktemp -d)
mkdir -p "$root/doc/data"
for refinement in 0 1; do
  start=$(date +%s.%N)
  "$tribos" "$root/parameters/necking_bar.prm" --set "Scene/Refinement=$refinement" \
    --set "Output/Directory=$out/r$refinement" --set "Output/Write VTU=false" > /dev/null
  end=$(date +%s.%N)
  echo "$refinement $(echo "$end - $start" | bc)" >> "$out/times"
  python3 - "$out/r$refinement/history.csv" > "$root/doc/data/necking_r$refinement.csv" <<'PY'
import csv, sys
# total elongation (both halves), full-section force, neck radius
r0 = 6.413 * (1 - 0.018)
print("elongation,force,neck_radius")
for r in csv.DictReader(open(sys.argv[1])):
    print("%.6g,%.8g,%.8g" % (14 * float(r["time"]), float(r["RF3_y"]), r0 + float(r["probe0_ux"])))
PY
done
python3 - "$root" "$out/times" <<'PY'
import csv, sys
root, times = sys.argv[1], dict(l.split() for l in open(sys.argv[2]))
with open(root + "/doc/data/necking_study.csv", "w") as f:
    f.write("refinement,wall_time,max_force,elongation_at_max,final_force,drop,final_neck_radius\n")
    for k in ("0", "1"):
        rows = [{c: float(v) for c, v in r.items()} for r in csv.DictReader(open(root + "/doc/data/necking_r%s.csv" % k))]
        peak = max(rows, key=lambda r: r["force"])
        f.write("%s,%s,%.6g,%.4g,%.6g,%.4f,%.5g\n" % (k, times[k], peak["force"], peak["elongation"],
                rows[-1]["force"], 1 - rows[-1]["force"] / peak["force"], rows[-1]["neck_radius"]))
print(open(root + "/doc/data/necking_study.csv").read())
PY
cd "$root"
gnuplot <<'GP'
set datafile separator ","
set terminal pngcairo size 1200,500 font ",11" noenhanced
set output "doc/necking.png"
set multiplot layout 1,2 title "Necking bar (2D axisymmetric Q2, J2 finite strain)"
set grid
set key right bottom
set xlabel "total elongation [mm]"
set ylabel "axial force [kN]"
plot "doc/data/necking_r0.csv" using 1:2 with lines lw 2 title "8 x 20 cells", \
     "doc/data/necking_r1.csv" using 1:2 with lines lw 2 dt 2 title "16 x 40 cells"
set key right top
set ylabel "neck radius [mm]"
plot "doc/data/necking_r0.csv" using 1:3 with lines lw 2 title "8 x 20 cells", \
     "doc/data/necking_r1.csv" using 1:3 with lines lw 2 dt 2 title "16 x 40 cells"
unset multiplot
GP
echo "wrote doc/data/necking_study.csv, doc/necking.png"
