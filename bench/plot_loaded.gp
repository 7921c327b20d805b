# Two threads against one, quiet and beside a busy process (loaded.csv):
# the time of -t 2 over the time of -t 1, per scene, for this simcli and the
# baseline build. Below 1: two threads are faster.
#   gnuplot -e "results='bench/results/cpp-2core'; baseline='e7a1ba8'" bench/plot_loaded.gp
# (baseline: what the CSV's baseline rows were built from, runs.txt says)
if (!exists("results")) results = "bench/results/cpp-2core"
if (!exists("baseline")) baseline = "the baseline build"
set ylabel "time with 2 threads / time with 1 thread (median)"
set title "2 threads against 1 thread, quiet and beside one busy process (2-core machine)"
set arrow from graph 0, first 1.2 to graph 1, first 1.2 nohead dt 3 lw 1 lc rgb "#cb181d"
set label "target beside a busy process: 1.2" at graph 0.01, first 1.25 tc rgb "#cb181d"
# scene | simcli quiet | simcli loaded | baseline quiet | baseline loaded
pivot = "< awk -F, 'NR > 1 { split($2, p, \" \"); key = $1 \"|\" p[1] \"|\" $3; t[key, p[3]] = $5; scenes[$1] = 1 } " . \
        "END { for (s in scenes) { line = \"\\\"\" s \"\\\"\"; " . \
        "for (k = 1; k <= 4; k++) { prog = (k <= 2) ? \"simcli\" : \"baseline\"; load = (k % 2) ? \"quiet\" : \"loaded\"; " . \
        "key = s \"|\" prog \"|\" load; line = line \" \" ((key, 1) in t ? t[key, 2] / t[key, 1] : \"NaN\") } print line } }' " . \
        results."/loaded.csv | sort"
image = "loaded.png"
call "bench/ratio_bars.gp"
