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
0.113694 0.0106479
0.200205 0.00313405
0.381992 0.00176195
0.861379 0.00138248
3.79489 0.000613843
5.94568 0.000590398
EOD
$d1 << EOD
1.59432 0.11895
3.29262 0.0763555
5.92877 0.0440098
12.2452 0.0172905
22.8742 0.00601025
58.0527 0.00592641
61.6728 0.00107638
EOD
plot $d0 with linespoints title 'furnished-office monte-carlo', \
     $d1 with linespoints title 'furnished-office radiance'
