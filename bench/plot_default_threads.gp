# The default thread count against the faster of -t 1 and -t 2 (loaded.csv),
# per scene, quiet and beside a busy process, for this simcli and the
# baseline build. Above 1: the default was not the fastest choice.
#   gnuplot -e "results='bench/results/cpp-2core'; baseline='73dcb4f'" bench/plot_default_threads.gp
# (baseline: what the CSV's baseline rows were built from, runs.txt says)
if (!exists("results")) results = "bench/results/cpp-2core"
if (!exists("baseline")) baseline = "the baseline build"
set ylabel "default thread count / faster of 1 and 2 threads (medians)"
set title "The default thread count against the best fixed one (2-core machine)"
# scene | simcli quiet | simcli loaded | baseline quiet | baseline loaded
pivot = "< awk -F, 'NR > 1 { split($2, p, \" \"); key = $1 \"|\" p[1] \"|\" $3; " . \
        "t[key, (p[2] == \"default\") ? \"d\" : p[3]] = $5; scenes[$1] = 1 } " . \
        "END { for (s in scenes) { line = \"\\\"\" s \"\\\"\"; " . \
        "for (k = 1; k <= 4; k++) { prog = (k <= 2) ? \"simcli\" : \"baseline\"; load = (k % 2) ? \"quiet\" : \"loaded\"; " . \
        "key = s \"|\" prog \"|\" load; best = (t[key, 1] < t[key, 2]) ? t[key, 1] : t[key, 2]; " . \
        "line = line \" \" (((key, \"d\") in t) ? t[key, \"d\"] / best : \"NaN\") } print line } }' " . \
        results."/loaded.csv | sort"
image = "default_threads.png"
call "bench/ratio_bars.gp"
