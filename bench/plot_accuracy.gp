# Error against run time (log-log) for K = 1, 2, 4, ..., 64 substeps, one panel
# per scene; the exact engine (error 0 by definition) is the dashed line at its
# run time. Usage: gnuplot -e "results='bench/results/<machine>'" bench/plot_accuracy.gp
set datafile separator ","
set terminal pngcairo size 1200,520 font ",11"
set output results."/error_vs_time.png"
file = results."/accuracy.csv"
set logscale xy
set format y "10^{%L}"
set xlabel "run time, s (median; stepped engine on 2 threads, exact on 1)"
set ylabel "error"
set grid
set key bottom right
set yrange [1e-5:1]
step(scene, column) = (strcol(1) eq scene && strcol(4) eq "step") ? abs(column(column)) : NaN
label(scene) = (strcol(1) eq scene && strcol(4) eq "step") ? sprintf("K=%d", $5) : ""
set multiplot layout 1,2
do for [scene in "default crowded_box"] {
    name = scene eq "crowded_box" ? "crowded box" : scene
    stats file using ((strcol(1) eq name && strcol(4) eq "exact") ? $8 : NaN) nooutput
    exact_time = STATS_max
    unset arrow
    set arrow from exact_time, graph 0 to exact_time, graph 1 nohead dashtype 2 linewidth 2
    set label 1 sprintf("exact engine\n%.2f s", exact_time) at exact_time, graph 0.9 offset 0.5,0
    set title name
    plot file using 8:(step(name, 11)) with linespoints pointtype 7 title "|particle collision rate error|", \
         file using 8:(step(name, 11)):(label(name)) with labels offset 0,1 font ",9" notitle, \
         file using 8:(step(name, 12)) with linespoints pointtype 5 title "|wall collision rate error|", \
         file using 8:(step(name, 13)) with linespoints pointtype 9 title "overlapping particle-steps", \
         file using 8:(step(name, 14)) with linespoints pointtype 11 title "position error after 1 step / L", \
         file using 8:(step(name, 17)) with lines dashtype 4 linecolor rgb "gray40" title "counting noise of the rates", \
         0.01 with lines dashtype 3 linecolor rgb "gray" title "1 %"
}
unset multiplot
