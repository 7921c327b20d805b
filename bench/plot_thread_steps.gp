# Each step's time, N = 32000 (300 steps) beside one busy process, with -t 1,
# -t 2 and the default thread count (thread_steps_loaded.csv): two threads run
# their steps fast between the other process's turns and stall during them.
#   gnuplot -e "results='bench/results/cpp-2core'" bench/plot_thread_steps.gp
if (!exists("results")) results = "bench/results/cpp-2core"
set terminal pngcairo size 1000,520 font ",11"
set output results."/thread_steps_loaded.png"
set datafile separator ","
set title "N = 32000 beside one busy process (2-core machine): each step's time"
set xlabel "step"
set ylabel "step time (ms)"
set yrange [0:70]
set key top right
set grid ytics
run(name) = "< awk -F, '$1 == \"".name."\"' ".results."/thread_steps_loaded.csv"
plot run("-t 2") using 2:4 with lines lw 1 lc rgb "#fd8d3c" title "-t 2", \
     run("-t 1") using 2:4 with lines lw 2 lc rgb "#3182bd" title "-t 1", \
     run("default threads") using 2:($3 == 1 ? $4 : 1/0) with points pt 7 ps 0.5 lc rgb "#31a354" title "default: a step on one thread", \
     run("default threads") using 2:($3 > 1 ? $4 : 1/0) with points pt 7 ps 0.5 lc rgb "#756bb1" title "default: a step on two threads"
