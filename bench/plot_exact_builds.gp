# Collisions a second of two exact-engine builds (bench/exact_builds.py),
# quiet and beside a busy process, at 1e4, 1e5 and 1e6 disks, and the goal of
# 1.5 M a second. Run from the repository root with
#   gnuplot -e "results='bench/results/cpp-2core'; name='exact_calendar'; baseline='linked calendar (d37f390)'" bench/plot_exact_builds.gp
# which reads NAME.csv and NAME_loaded.csv and writes NAME.png.
set terminal pngcairo size 900,580 noenhanced font ",11"
set output results."/".name.".png"
set datafile separator ","
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.85 border -1
set boxwidth 0.9
set yrange [0:*]  # from 0, up to the fastest bar
set grid ytics
set ylabel "million collisions a second (one thread)"
set xlabel "disks (gas, area fraction 0.3)"
set title "The exact engine: this build against ".baseline.", medians of alternating runs"
set key outside bottom center horizontal maxcols 2
set arrow from graph 0, first 1.5 to graph 1, first 1.5 nohead dt 2 lw 1.5
set label "goal: 1.5 M" at graph 0.01, first 1.56
quiet = results."/".name.".csv"
busy = results."/".name."_loaded.csv"
plot quiet every ::1 using ($8/1e6):xtic(1) title "this build, quiet" lc rgb "#9ecae1", \
     busy every ::1 using ($8/1e6) title "this build, beside a busy process" lc rgb "#08519c", \
     quiet every ::1 using ($9/1e6) title baseline.", quiet" lc rgb "#fdae6b", \
     busy every ::1 using ($9/1e6) title baseline.", beside a busy process" lc rgb "#d94801"
