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
0.0817941 0.0140229
0.126827 0.00553645
0.284883 0.00283341
0.845637 0.0018586
4.03892 0.00125113
5.60509 0.00112981
EOD
$d1 << EOD
0.585962 0.0555279
1.15532 0.0310967
1.99059 0.0137482
3.8441 0.00450178
12.5214 0.00260999
34.7451 0.0025175
36.2327 0.00173129
EOD
plot $d0 with linespoints title 'furnished-classroom monte-carlo', \
     $d1 with linespoints title 'furnished-classroom radiance'
