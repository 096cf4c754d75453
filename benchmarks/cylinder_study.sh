#!/usr/bin/env bash
# The paper's cylinder compression (section 4.1) with penalty 10E, 100E,
# 1000E, the augmented Lagrangian and Lagrange multipliers: plate force
# against plate displacement, with the analytic homogeneous-compression
# curve; the relative error of every variant at every step; the
# axisymmetric model and a finer 3D mesh (cost of the model); the friction
# variant (mu = 0.2, top and side surfaces against the plate) with penalty
# and Lagrange multipliers. Writes doc/data/cylinder_<variant>.csv,
# doc/data/cylinder_study.csv, doc/data/cylinder_errors.csv and
# doc/cylinder_force.png.  bash benchmarks/cylinder_study.sh [build/tribos]
# (~2 minutes)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
tribos=${1:-$root/build/tribos}
out=$(mktemp -d)
mkdir -p "$root/doc/data"
prm=parameters/cylinder_compression.prm
friction=(--set "Contact/Friction coefficient=0.2" --set "Contact/Pairs=3, 4 : plate")
for variant in 10E 100E 1000E augmented lagrange axisymmetric 3d_fine \
               friction_penalty friction_lagrange; do
  prm=parameters/cylinder_compression.prm
  case $variant in
    augmented) sets=(--set "Contact/Method=augmented lagrangian" --set "Contact/Augmentation tolerance=1e-6") ;;
    lagrange) sets=(--set "Contact/Method=lagrange multiplier") ;;
    axisymmetric) prm=parameters/cylinder_compression_axisymmetric.prm; sets=() ;;
    3d_fine) sets=(--set "Scene/Cylinder compression/Radial refinements=3") ;;
    friction_penalty) sets=("${friction[@]}") ;;
    friction_lagrange) sets=("${friction[@]}" --set "Contact/Method=lagrange multiplier") ;;
    # The paper's 10E, 100E, 1000E: absolute values (E = 206.9, mm).
    *) sets=(--set "Contact/Penalty factor=$(( ${variant%E} * 2069 / 10 ))") ;;
  esac
  start=$(date +%s.%N)
  "$tribos" "$root/$prm" "${sets[@]}" \
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
full = math.pi * r * r / area  # full section / 1/8-model section
def force(row, variant):
    if variant == "axisymmetric":  # full section
        return abs(float(row["pair0_Fy"])) / full
    return abs(sum(float(row[k]) for k in row if k.startswith("pair") and k.endswith("_Fz")))
variants = ("10E", "100E", "1000E", "augmented", "lagrange", "axisymmetric", "3d_fine",
            "friction_penalty", "friction_lagrange")
errors = {}
with open(root + "/doc/data/cylinder_study.csv", "w") as f:
    f.write("variant,steps,increments,newton_iterations,cutbacks,wall_time,final_force,final_error,max_error\n")
    for v in variants:
        rows = list(csv.DictReader(open(root + "/doc/data/cylinder_%s.csv" % v)))
        final = {}
        for x in rows:
            final[int(x["step"])] = x
        steps = [final[k] for k in sorted(final)]
        # 3d_fine: its section is the 16-chord polygon.
        scale = (8 * math.sin(math.pi / 32)) / (4 * math.sin(math.pi / 16)) if v == "3d_fine" else 1.0
        errors[v] = [force(x, v) / (a * scale) - 1 for x, a in zip(steps, analytic)]
        f.write("%s,%d,%d,%d,%d,%s,%.6g,%.3e,%.3e\n" % (
            v, len(steps), len(rows), sum(int(x["newton_iterations"]) for x in rows),
            sum(1 for x in rows if int(x["cutbacks"]) > 0), times[v], force(steps[-1], v),
            errors[v][-1], max(abs(e) for e in errors[v])))
with open(root + "/doc/data/cylinder_errors.csv", "w") as f:
    f.write("step,displacement," + ",".join(variants[:6]) + "\n")
    for k in range(25):
        f.write("%d,%.1f,%s\n" % (k + 1, 0.2 * (k + 1), ",".join("%.3e" % errors[v][k] for v in variants[:6])))
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
     for [v in "10E 100E 1000E augmented lagrange"] "doc/data/cylinder_".v.".csv" using (0.2*column("time")):(-column("pair0_Fz")) with lines lw 2 title v, \
     "doc/data/cylinder_axisymmetric.csv" using (0.2*column("time")):(column("pair0_Fy")/(pi/(4*sin(pi/16)))) with points pt 2 title "axisymmetric (/ section ratio)", \
     "doc/data/cylinder_friction_penalty.csv" using (0.2*column("time")):(-column("pair0_Fz")-column("pair1_Fz")) with lines lw 2 dt 2 title "mu = 0.2, penalty 1000E", \
     "doc/data/cylinder_friction_lagrange.csv" using (0.2*column("time")):(-column("pair0_Fz")-column("pair1_Fz")) with lines lw 2 dt 3 title "mu = 0.2, Lagrange"
GP
echo "wrote doc/data/cylinder_study.csv, doc/cylinder_force.png"
