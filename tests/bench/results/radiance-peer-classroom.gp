set terminal pngcairo size 1280,900 noenhanced
set output 'radiance-peer-classroom.png'
set logscale xy
set format xy '%g'
set grid
set key outside right top
set xlabel 'seconds'
set ylabel 'RMS relative error'
set title 'radiant-bench: error against time'
$d0 << EOD
0.101541 0.014175
0.134702 0.00555523
0.292682 0.00244875
0.878753 0.00124565
2.01846 0.000790921
3.09053 0.000766302
EOD
$d1 << EOD
0.566044 0.056124
1.11365 0.0315079
1.92397 0.0136776
3.61975 0.00427277
11.7863 0.00276349
32.957 0.00245108
36.4555 0.00166286
EOD
plot $d0 with linespoints title 'furnished-classroom monte-carlo', \
     $d1 with linespoints title 'furnished-classroom radiance'
