# gnuplot -c benchmarks/plots.gp   (from the repository root)
# Plots of doc/data/*.csv into doc/*.png.
set datafile separator ","
set terminal pngcairo size 900,600 font ",11" noenhanced
set grid
set key outside right

set output "doc/hertz_error_vs_time.png"
set title "Hertz: error of p0 against wall time (each point: mesh level x penalty)"
set logscale xy
set xlabel "wall time of the run [s]"
set ylabel "relative error of p0"
plot for [scene in "2d_rigid 2d_block 3d_rigid"] for [eps in "10*E/h 100*E/h 1000*E/h 1e4*E/h"] \
  "< awk -F, -v s=".scene." -v e=".eps." '$1==s && $3==e' doc/data/hertz_study.csv" \
  using 6:12 with linespoints title scene." ".eps

set output "doc/hertz_error_vs_penalty.png"
set title "Hertz: error of p0 and Newton iterations against the penalty factor"
set xlabel "penalty factor k = eps_N h / E"
set ylabel "relative error of p0"
set y2label "Newton iterations"
set y2tics
set logscale x
set logscale y
unset logscale y2
plot for [scene in "2d_rigid 2d_block 3d_rigid"] \
  "< awk -F, -v s=".scene." '$1==s && NR>1 {split($3,a,\"*\"); print a[1]\",\"$0}' doc/data/hertz_study.csv | sort -t, -k3,3n | awk -F, 'BEGIN{m=0} {if ($3>m) m=$3} {l[NR]=$0; lv[NR]=$3} END{for(i=1;i<=NR;i++) if (lv[i]==m) print l[i]}'" \
  using 1:13 with linespoints title scene." p0 error (finest)", \
  for [scene in "2d_rigid 2d_block 3d_rigid"] \
  "< awk -F, -v s=".scene." '$1==s && NR>1 {split($3,a,\"*\"); print a[1]\",\"$0}' doc/data/hertz_study.csv | sort -t, -k3,3n | awk -F, 'BEGIN{m=0} {if ($3>m) m=$3} {l[NR]=$0; lv[NR]=$3} END{for(i=1;i<=NR;i++) if (lv[i]==m) print l[i]}'" \
  using 1:6 axes x1y2 with linespoints dashtype 2 title scene." iterations"
unset y2label
unset y2tics

set output "doc/search_scaling.png"
set title "Contact search (AABB tree + exact projection) against slave nodes"
set xlabel "slave nodes n"
set ylabel "seconds per search"
set logscale xy
f(x) = c * x * log(x) / log(2)
c = 1e-7
fit f(x) "doc/data/search_scaling.csv" using 1:3 via c
plot "doc/data/search_scaling.csv" using 1:3 with linespoints pt 7 title "measured (median of 5)", \
  f(x) title sprintf("%.3g n log2 n", c)

# benchmarks/adaptivity.py
set output "doc/adaptivity_error_vs_dofs.png"
set title "Hertz 2D: pressure profile error against the converged profile, by dofs"
unset y2label
unset y2tics
set logscale xy
set xlabel "dofs (final mesh)"
set ylabel "relative L2 error of the pressure profile (against the converged one)"
plot for [kind in "uniform graded adaptive indicator_only"] \
  "< awk -F, -v k=".kind." '$1==k' doc/data/adaptivity_hertz.csv" \
  using 3:10 with linespoints title kind

set output "doc/adaptivity_error_vs_time.png"
set title "Hertz 2D: pressure profile error against wall time (all cycles)"
set xlabel "wall time of the run [s]"
plot for [kind in "uniform graded adaptive indicator_only"] \
  "< awk -F, -v k=".kind." '$1==k' doc/data/adaptivity_hertz.csv" \
  using 6:10 with linespoints title kind
