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
0.108628 0.015201
0.165853 0.00444957
0.306744 0.00237909
0.841099 0.00125137
2.00267 0.000779122
3.0149 0.000732263
EOD
$d1 << EOD
0.584769 0.0564507
1.14796 0.0317368
1.91207 0.0135747
3.57959 0.00411849
12.0292 0.00244202
33.6073 0.00245304
35.4161 0.00168396
EOD
plot $d0 with linespoints title 'furnished-classroom monte-carlo', \
     $d1 with linespoints title 'furnished-classroom radiance'
