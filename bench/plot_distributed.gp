# The distributed engine's scaling (distributed_model.csv, written by
# bench/distributed_model.py): left, the projected parallel efficiency with a
# cluster's interconnect, weak (1e6 disks a rank) and strong (1e8 disks);
# right, the model against what 1 to 8 ranks measure on this machine.
#   gnuplot -e "dir='bench/results/cpp-2core'" bench/plot_distributed.gp
if (!exists("dir")) dir = "bench/results/cpp-2core"
set terminal pngcairo size 1400,560 font ",11"
set output dir."/distributed.png"
set datafile separator ","
set multiplot layout 1,2
set title "Projected parallel efficiency (alpha 1.5 us, beta 12.5 GB/s)"
set logscale x 2
set xlabel "ranks"
set ylabel "efficiency"
set yrange [0:1.1]
set key bottom left
set grid
plot dir."/distributed_model.csv" using (strcol(1) eq "weak" ? $2 : NaN):6 with linespoints lw 2 pt 7 \
         title "weak: 1e6 disks a rank", \
     "" using (strcol(1) eq "strong" ? $2 : NaN):6 with linespoints lw 2 pt 5 title "strong: 1e8 disks"
set title "Model against measurement on this 2-core machine (dense gas, 10 steps)"
set ylabel "seconds per step"
set logscale y
set yrange [*:*]
set key top left
plot dir."/distributed_model.csv" using (strcol(1) eq "check-weak" ? $2 : NaN):5 with points pt 7 ps 1.5 \
         title "measured, weak (125 000 a rank)", \
     "" using (strcol(1) eq "check-weak" ? $2 : NaN):4 with lines lw 2 title "modelled, weak", \
     "" using (strcol(1) eq "check-strong" ? $2 : NaN):5 with points pt 5 ps 1.5 title "measured, strong (1e6)", \
     "" using (strcol(1) eq "check-strong" ? $2 : NaN):4 with lines lw 2 title "modelled, strong"
unset multiplot
