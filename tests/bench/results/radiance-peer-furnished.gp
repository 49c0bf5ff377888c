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
0.174649 0.028331
0.183864 0.0135319
0.272901 0.00487418
0.643849 0.00241485
1.16736 0.00193613
2.38282 0.00143799
EOD
$d1 << EOD
3.38147 0.0485701
6.0225 0.0273093
10.0678 0.0116023
18.7481 0.00451874
31.6482 0.00169874
EOD
plot $d0 with linespoints title 'furnished-office monte-carlo', \
     $d1 with linespoints title 'furnished-office radiance'
