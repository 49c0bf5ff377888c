set terminal pngcairo size 1280,900 noenhanced
set output 'tests/bench/results/office-x1-x4.png'
set logscale xy
set format xy '%g'
set grid
set key outside right top
set xlabel 'seconds'
set ylabel 'RMS relative error'
set title 'radiant-bench: error against time'
$d0 << EOD
1.12552 0.00185233
1.56204 0.000904801
2.98455 0.000553319
EOD
$d1 << EOD
4.34317 0.00102214
4.82386 0.000585492
6.00232 0.000722915
EOD
plot $d0 with linespoints title 'office-x1 hierarchical', \
     $d1 with linespoints title 'office-x4 hierarchical'
