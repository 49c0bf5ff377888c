set terminal pngcairo size 1280,900 noenhanced
set output 'radiance-peer-furnished.png'
set logscale xy
set format xy '%g'
set grid
set key outside right top
set xlabel 'seconds'
set ylabel 'RMS relative error'
set title 'radiant-bench: error against time'
$d0 << EOD
0.0700232 0.0274694
0.0701411 0.0130534
0.147818 0.00487426
0.432087 0.00258748
0.796095 0.00182276
1.75654 0.00156064
EOD
$d1 << EOD
2.11479 0.0499591
3.92395 0.0288626
6.76565 0.0130269
12.0683 0.00560567
20.5867 0.00272567
60.7732 0.00258809
62.652 0.0021662
EOD
plot $d0 with linespoints title 'furnished-office monte-carlo', \
     $d1 with linespoints title 'furnished-office radiance'
