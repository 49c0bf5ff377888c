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
0.133037 0.0203559
0.2211 0.00476981
2.16938 0.00141278
EOD
$d1 << EOD
0.158176 0.0168518
0.245828 0.00287546
0.944668 0.00129722
EOD
plot $d0 with linespoints title 'furnished-office monte-carlo', \
     $d1 with linespoints title 'furnished-office-ies monte-carlo'
