# Time per step against N (log-log), brute force and grid, 1 and 2 threads.
# Usage: gnuplot -e "results='bench/results/<machine>'" bench/plot_steps.gp
set datafile separator ","
set terminal pngcairo size 900,600 font ",11"
set output results."/time_per_step.png"
set logscale xy
set format y "10^{%L}"
set xlabel "particles N (L = 20000, r = 1, random scene)"
set ylabel "seconds per step (median)"
set key top left
set grid
file = results."/steps.csv"
sel(search, threads) = (strcol(1) eq "sparse" && strcol(6) eq search && $7 == threads) ? $9 : NaN
plot file using 2:(sel("brute", 1)) with linespoints title "brute force, 1 thread", \
     file using 2:(sel("brute", 2)) with linespoints title "brute force, 2 threads", \
     file using 2:(sel("grid", 1)) with linespoints title "grid, 1 thread", \
     file using 2:(sel("grid", 2)) with linespoints title "grid, 2 threads"
