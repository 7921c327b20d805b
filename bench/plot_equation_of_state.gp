# The equation of state in a periodic box against the virial series
# (equation_of_state.csv, written by bench/equation_of_state.py): Z with its
# error bar over the series to B10, and the difference in standard deviations.
#   gnuplot -e "dir='docs/pictures'" bench/plot_equation_of_state.gp
if (!exists("dir")) dir = "docs/pictures"
set terminal pngcairo size 1200,520 font ",11" noenhanced
set output dir."/equation_of_state.png"
set datafile separator ","
set key autotitle columnhead
set multiplot layout 1,2
set title "Hard disks, 400 in a periodic box: Z = beta P A / N"
set xlabel "area fraction eta"
set ylabel "Z"
set key top left
set grid
plot dir."/equation_of_state.csv" using 1:10 with lines lw 2 title "virial series to B10 (Clisby & McCoy 2006)", \
     "" using 1:8:9 with yerrorbars pt 7 ps 1.2 title "exact engine (block averages)"
set title "Measured minus series, in standard deviations (both errors)"
set ylabel "(Z - Z_series) / sigma"
set yrange [-4:4]
set arrow from graph 0, first 0 to graph 1, first 0 nohead lw 1
plot dir."/equation_of_state.csv" using 1:12 with linespoints pt 7 ps 1.2 lw 2 title "difference"
unset multiplot
