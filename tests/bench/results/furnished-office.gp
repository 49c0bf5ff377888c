set terminal pngcairo size 1280,900 noenhanced
set output 'tests/bench/results/furnished-office.png'
set logscale xy
set format xy '%g'
set grid
set key outside right top
set xlabel 'seconds'
set ylabel 'RMS relative error'
set title 'radiant-bench: error against time'
$d0 << EOD
0.197584 0.011311
0.640325 0.00400984
11.3347 0.000964572
EOD
$d1 << EOD
0.388567 0.00644505
0.502107 0.00383338
2.94775 0.000867765
EOD
plot $d0 with linespoints title 'furnished-office monte-carlo', \
     $d1 with linespoints title 'furnished-office-ies monte-carlo'
