# Time per particle-step against N (log-log): the default scene's density
# and speeds, and the gas at area fraction 0.3; the automatic search, 1 and 2 threads.
# Usage: gnuplot -e "results='bench/results/<machine>'" bench/plot_sizes.gp
set datafile separator ","
set terminal pngcairo size 900,600 font ",11"
set output results."/sizes.png"
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set xlabel "particles N"
set ylabel "seconds per particle-step after the first step (median)"
set key top left
set grid
file = results."/sizes.csv"
# One family and thread count at a time (grep), so that each line joins its own points.
rows(family, threads) = sprintf("< grep \"^%s,\" %s | awk -F, '$7 == %d'", family, file, threads)
plot rows("default density", 1) using 2:($9 / $2) with linespoints title "default density and speeds, 1 thread", \
     rows("default density", 2) using 2:($9 / $2) with linespoints title "default density and speeds, 2 threads", \
     rows("area fraction 0.3", 1) using 2:($9 / $2) with linespoints title "area fraction 0.3, 1 thread", \
     rows("area fraction 0.3", 2) using 2:($9 / $2) with linespoints title "area fraction 0.3, 2 threads"
