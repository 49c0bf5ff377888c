set terminal pngcairo size 1280,900 noenhanced
set output 'radiance-peer-example-office.png'
set logscale xy
set format xy '%g'
set grid
set key outside right top
set xlabel 'seconds'
set ylabel 'RMS relative error'
set title 'radiant-bench: error against time'
$d0 << EOD
0.0979178 0.00586773
0.142667 0.00356008
0.222436 0.00196452
0.839513 0.00159924
2.73443 0.000721418
4.31753 0.000641319
EOD
$d1 << EOD
1.18051 0.118658
2.4099 0.0765442
4.26942 0.0445291
8.79892 0.0170619
20.6626 0.00591205
55.7206 0.00593877
75.0692 0.00121012
EOD
plot $d0 with linespoints title 'furnished-office monte-carlo', \
     $d1 with linespoints title 'furnished-office radiance'
