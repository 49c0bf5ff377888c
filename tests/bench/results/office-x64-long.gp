set terminal pngcairo size 1280,900 noenhanced
set output 'tests/bench/results/office-x64-long.png'
set logscale xy
set format xy '%g'
set grid
set key outside right top
set xlabel 'seconds'
set ylabel 'RMS relative error'
set title 'radiant-bench: error against time'
$d0 << EOD
58.9017 0.00549799
EOD
$d1 << EOD
723.843 0.0534559
EOD
plot $d0 with linespoints title 'office-x64 hierarchical', \
     $d1 with linespoints title 'office-x64 shooting'
