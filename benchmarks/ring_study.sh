#!/usr/bin/env bash
# The ring on a foundation (paper section 4.2) with penalty, augmented
# Lagrangian and Lagrange multipliers, on the paper's mesh (64 x 2 ring)
# and refined once (128 x 4), Lagrange also twice (256 x 8), all Q1 node to
# segment; and Q2 mortar on the paper's mesh and refined once:
# copies each history.csv to doc/data/ring_<variant>.csv, writes
# doc/data/ring_study.csv (dofs, Newton iterations, wall time, max
# penetration, final reaction) and plots doc/ring_force.png.
#   bash benchmarks/ring_study.sh [build/tribos]        (~5 minutes)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tribos=${1:-$root/build/tribos}
out=$(mktemp -d)
mkdir -p "$root/doc/data"
echo "variant,dofs,newton_iterations,cutbacks,wall_time,max_penetration,final_reaction" \
  > "$root/doc/data/ring_study.csv"
# Q1 node to segment: three methods, the paper's mesh and refined once;
# multipliers refined twice. Q2 mortar (quadratic dual basis): multipliers
# and penalty on the paper's mesh and refined once (the multipliers refined
# once are the reference of tests/verification/ring_q2_mortar.py).
variants=()
for refinement in 0 1 2; do
  for method in penalty "augmented lagrangian" "lagrange multiplier"; do
    [ $refinement = 2 ] && [ "$method" != "lagrange multiplier" ] && continue
    variants+=("1|$method|$refinement")
  done
done
variants+=("2|lagrange multiplier|0" "2|penalty|0" "2|lagrange multiplier|1" "2|penalty|1")
for v in "${variants[@]}"; do
    IFS='|' read -r degree method refinement <<< "$v"
    variant="${method// /_}_r$refinement"
    extra=()
    if [ "$degree" = 2 ]; then
      variant="q2_$variant"
      extra=(--set "Finite element/Polynomial degree=2"
             --set "Contact/Discretization=mortar")
    fi
    "$tribos" "$root/parameters/ring_on_foundation.prm" \
      --set "Contact/Method=$method" --set "Scene/Refinement=$refinement" \
      "${extra[@]}" \
      --set "Output/Directory=$out/$variant" --set "Output/Write VTU=false" > /dev/null
    cp "$out/$variant/history.csv" "$root/doc/data/ring_$variant.csv"
    python3 - "$out/$variant" "$variant" >> "$root/doc/data/ring_study.csv" <<'PY'
import csv, re, sys
folder, variant = sys.argv[1], sys.argv[2]
rows = list(csv.DictReader(open(folder + "/history.csv")))
summary = open(folder + "/summary.txt").read()
dofs = re.search(r"dofs\s+(\d+)", summary).group(1)
wall = sum(float(m) for m in re.findall(r"^\S[\w ]*?\s+\d+\s+([\d.]+)\s+[\d.]+%", summary, re.M))
print("%s,%s,%d,%d,%.3f,%.4g,%.6g" % (
    variant, dofs, sum(int(r["newton_iterations"]) for r in rows),
    sum(1 for r in rows if int(r["cutbacks"]) > 0), wall,
    max(float(r["max_penetration"]) for r in rows), float(rows[-1]["RF12_y"])))
PY
done
cat "$root/doc/data/ring_study.csv"
cd "$root"
gnuplot <<'GP'
set datafile separator ","
set terminal pngcairo size 900,600 font ",11" noenhanced
set output "doc/ring_force.png"
set grid
set key left top
set title "Ring on foundation: foundation reaction against the displacement of the ring ends"
set xlabel "displacement of the ring ends (20 closes the gap)"
set ylabel "vertical reaction of the foundation (per unit thickness)"
d(t) = 20*(t < 1 ? t : 1) + 0.5*(t > 1 ? t - 1 : 0)
plot "doc/data/ring_penalty_r0.csv" using (d($3)):"RF12_y" with lines lw 2 title "penalty 1e5, 64 x 2 (paper mesh)", \
     "doc/data/ring_augmented_lagrangian_r0.csv" using (d($3)):"RF12_y" with lines dt 2 lw 2 title "augmented Lagrangian, 64 x 2", \
     "doc/data/ring_penalty_r1.csv" using (d($3)):"RF12_y" with lines lw 2 title "penalty 1e5, 128 x 4", \
     "doc/data/ring_augmented_lagrangian_r1.csv" using (d($3)):"RF12_y" with lines dt 2 lw 2 title "augmented Lagrangian, 128 x 4", \
     "doc/data/ring_lagrange_multiplier_r0.csv" using (d($3)):"RF12_y" with lines dt 3 lw 2 title "Lagrange multipliers, 64 x 2", \
     "doc/data/ring_lagrange_multiplier_r1.csv" using (d($3)):"RF12_y" with lines dt 3 lw 2 title "Lagrange multipliers, 128 x 4", \
     "doc/data/ring_lagrange_multiplier_r2.csv" using (d($3)):"RF12_y" with lines lw 2 title "Lagrange multipliers, 256 x 8", \
     "doc/data/ring_q2_lagrange_multiplier_r0.csv" using (d($3)):"RF12_y" with lines lw 3 title "Q2 mortar, multipliers, 64 x 2 (paper mesh)", \
     "doc/data/ring_q2_lagrange_multiplier_r1.csv" using (d($3)):"RF12_y" with lines dt 2 lw 3 title "Q2 mortar, multipliers, 128 x 4"
GP
echo "wrote doc/data/ring_study.csv, doc/ring_force.png"
