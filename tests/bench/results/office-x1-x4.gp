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
1.14649 0.00301344
1.61093 0.00231696
3.10351 0.00151799
EOD
$d1 << EOD
5.04224 0.00197238
5.2417 0.00288793
6.23313 0.00236116
EOD
plot $d0 with linespoints title 'office-x1 hierarchical', \
     $d1 with linespoints title 'office-x4 hierarchical'
