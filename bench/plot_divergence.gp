# The largest and the median distance between the same particle in two
# correct programs (the library, the textbook implementation) against the
# step, with the 8-decimal printing's resolution for scale.
# Usage: gnuplot -e "results='bench/results/<machine>'" bench/plot_divergence.gp
set datafile separator ","
set terminal pngcairo size 900,520 font ",11"
set output results."/divergence.png"
file = results."/divergence.csv"
set logscale y
set format y "10^{%L}"
set xlabel "step"
set ylabel "distance between the two programs' positions of a particle"
set grid
set key bottom right
set yrange [1e-17:1e5]
pick(scene, column) = strcol(1) eq scene ? (column(column) > 0 ? column(column) : 1e-17) : NaN
plot file using 4:(pick("default", 5)) with lines linewidth 2 title "default scene (N = 1000, L = 20000): largest", \
     file using 4:(pick("default", 6)) with lines dashtype 2 title "default scene: median", \
     file using 4:(pick("gas 0.3", 5)) with lines linewidth 2 title "gas, area fraction 0.3 (N = 400): largest", \
     file using 4:(pick("gas 0.3", 6)) with lines dashtype 2 title "gas: median", \
     5e-9 with lines linecolor "black" dashtype 3 title "printing resolution (5e-9)"
