set terminal pngcairo size 1280,900 noenhanced
set output 'radiance-peer-meeting-room.png'
set logscale xy
set format xy '%g'
set grid
set key outside right top
set xlabel 'seconds'
set ylabel 'RMS relative error'
set title 'radiant-bench: error against time'
$d0 << EOD
0.0442117 0.0313117
0.133212 0.0106725
0.701795 0.0043159
3.32362 0.00234087
20.894 0.00106124
EOD
$d1 << EOD
1.24353 0.113671
2.61713 0.0616754
4.85717 0.0372033
10.1642 0.0128494
23.4583 0.00570652
58.7454 0.00424902
69.2811 0.00427328
77.2311 0.00486697
124.064 0.00378849
EOD
plot $d0 with linespoints title 'meeting-room monte-carlo', \
     $d1 with linespoints title 'meeting-room radiance'
