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
0.136946 0.0268635
0.137722 0.0130263
0.222062 0.00483187
0.553731 0.0026318
0.979953 0.00183522
2.10503 0.00137972
EOD
$d1 << EOD
2.25189 0.0482826
4.15245 0.0273115
6.90895 0.0113649
12.5896 0.00451096
21.1314 0.00169097
60.4545 0.00150296
63.7755 0.00137643
EOD
plot $d0 with linespoints title 'furnished-office monte-carlo', \
     $d1 with linespoints title 'furnished-office radiance'
