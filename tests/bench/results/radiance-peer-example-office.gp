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
0.0510236 0.0095514
0.127011 0.00272333
0.24179 0.00168061
0.629524 0.00126011
5.1401 0.00061384
7.72559 0.000593799
EOD
$d1 << EOD
0.911048 0.118881
1.91598 0.0764285
3.51997 0.0444446
7.20961 0.017095
17.1585 0.00610411
44.5119 0.00581071
54.7518 0.00104294
EOD
plot $d0 with linespoints title 'furnished-office monte-carlo', \
     $d1 with linespoints title 'furnished-office radiance'
