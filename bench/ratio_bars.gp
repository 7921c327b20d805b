# What plot_loaded.gp and plot_default_threads.gp share: clustered bars of
# ratios read from loaded.csv, four a scene (this build and the baseline,
# quiet and beside a busy process), a dashed line at 1. Each sets its
# output, title and `pivot` (scene | four ratios), then calls this file.
set terminal pngcairo size 900,580 noenhanced font ",11"
set output results."/".image
set datafile separator whitespace
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.85 border -1
set boxwidth 0.9
set yrange [0:1.45]
set grid ytics
set key outside bottom center horizontal maxcols 2
set arrow from graph 0, first 1 to graph 1, first 1 nohead dt 2 lw 1.5
plot pivot using 2:xtic(1) title "this build, quiet" lc rgb "#9ecae1", \
     '' using 3 title "this build, beside a busy process" lc rgb "#08519c", \
     '' using 4 title baseline.", quiet" lc rgb "#fdae6b", \
     '' using 5 title baseline.", beside a busy process" lc rgb "#d94801"
