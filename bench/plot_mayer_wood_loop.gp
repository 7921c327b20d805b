# The 870 disks' loop (mayer_wood_loop.csv, written by bench/mayer_wood_loop.py):
# beta P (2r)^2 from the exact engine against Li et al. (2022).
#   gnuplot -e "dir='docs/pictures'" bench/plot_mayer_wood_loop.gp
if (!exists("dir")) dir = "docs/pictures"
set terminal pngcairo size 900,560 font ",11" noenhanced
set output dir."/mayer_wood_loop.png"
set datafile separator ","
set title "870 disks, square periodic box: the Mayer-Wood loop"
set xlabel "area fraction eta"
set ylabel "beta P (2r)^2"
set key bottom right
set grid
plot dir."/mayer_wood_loop.csv" using 1:8 every ::1 with lines lw 2 title "Li, Nishikawa, Hoellmer, Maggs, Krauth (2022)", \
     "" using 1:6:7 every ::1 with yerrorbars pt 7 ps 1.2 title "exact engine, 1e5 collisions a disk (block averages)"
