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
0.860535 0.0113861
0.897986 0.0113861
2.52194 0.00410432
17.4351 0.00181804
30.0967 0.00114579
EOD
$d1 << EOD
11.6078 0.0478041
20.6556 0.0271501
40.51 0.0122948
79.005 0.00651482
316.519 0.00465793
471.572 0.00458622
753.561 0.00449223
EOD
plot $d0 with linespoints title 'furnished-office monte-carlo', \
     $d1 with linespoints title 'furnished-office radiance'
