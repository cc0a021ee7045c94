#!/bin/sh
# One PNG per floor curvature k from this folder's sweep_fem_fig6_10_11.csv
# (written by `floorblock sweep --fem --figure fig6_10_11`): the sweep's own
# PNG shows only the averaged peak, with all k side by side.
# Filled points: FEM pointwise peak at the face; open points: FEM peak averaged
# over Solver/Averaging length (5 cm); dashed lines: Eq. 6.53 with the
# no-rotation Q (Eqs. 6.12/6.24, Q over b) and y = L^2/k; grey box: the
# chapter's quoted range where it quotes one (k = 400: 6-10 MPa at 10-15 deg;
# k = 50: 32-50 MPa at 30-35 deg). The points of each load are shifted by
# 0.25 deg so that they do not hide each other; the lines are not shifted.
# Usage: sh plot_per_k.sh [output folder]
set -e
here=$(cd "$(dirname "$0")" && pwd)
out=${1:-$here}
csv=$here/sweep_fem_fig6_10_11.csv
mkdir -p "$out"
for k in 400 200 100 50; do
  data=$(mktemp)
  # k phi_h load pointwise averaged eq653 (MPa); blank FEM cells -> NaN
  grep -v '^#' "$csv" | awk -F, -v k="$k" 'NR > 1 && $1 + 0 == k {
      p = ($5 == "converged" && $8 != "") ? $8 / 1e6 : "NaN";
      a = ($5 == "converged" && $9 != "") ? $9 / 1e6 : "NaN";
      e = ($12 != "") ? $12 / 1e6 : "NaN";
      print $4 + 0, $2 + 0, p, a, e }' | sort -k1,1n -k2,2n > "$data"
  box=""
  quote=""
  [ "$k" = 400 ] && box="set object 1 rect from 10,6 to 15,10 fc rgb '#dddddd' fs solid 0.5 noborder behind"
  [ "$k" = 400 ] && quote="; grey: chapter's quote"
  [ "$k" = 50 ] && box="set object 1 rect from 30,32 to 35,50 fc rgb '#dddddd' fs solid 0.5 noborder behind"
  [ "$k" = 50 ] && quote="; grey: chapter's quote"
  gnuplot <<GP
set terminal pngcairo size 900,600 font ',11' noenhanced
set output '$out/sweep_fem_fig6_10_11_k$k.png'
set title "y = x^2/$k: sigma_max at the face joint, phi_v = 30 deg\nfilled: FEM pointwise, open: FEM averaged over 5 cm, dashed: Eq. 6.53 (no-rotation Q)$quote"
set xlabel 'bedding friction angle phi_h (deg)'
set ylabel 'sigma_max (MPa)'
set grid
set key top left title 'support load'
set xrange [9:36]
set yrange [0:*]
$box
plot for [i=0:5] '$data' using (\$1 == 400 + 100*i ? \$2 + 0.25*(i - 2.5) : NaN):3 with points pt 7 ps 1.2 lc i+1 title sprintf('%d t', 400 + 100*i), \
     for [i=0:5] '$data' using (\$1 == 400 + 100*i ? \$2 + 0.25*(i - 2.5) : NaN):4 with points pt 6 ps 1.2 lc i+1 notitle, \
     for [i=0:5] '$data' using (\$1 == 400 + 100*i ? \$2 : NaN):5 with lines dt 2 lc i+1 notitle
GP
  rm -f "$data"
done
