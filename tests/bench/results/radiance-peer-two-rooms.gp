set terminal pngcairo size 1280,900 noenhanced
set output 'radiance-peer-two-rooms.png'
set logscale xy
set format xy '%g'
set grid
set key outside right top
set xlabel 'seconds'
set ylabel 'RMS relative error'
set title 'radiant-bench: error against time'
$d0 << EOD
0.452064 0.000640155
1.06575 0.000830725
2.58401 0.00141504
18.0818 0.00130908
EOD
$d1 << EOD
0.020366 0.0211667
0.0294373 0.00731273
0.0602543 0.00421905
0.369315 0.00161705
EOD
$d2 << EOD
0.174195 0.053049
0.320871 0.0249821
0.541291 0.00854774
1.00299 0.00950389
1.95511 0.0021061
5.76084 0.00206877
5.92942 0.00174294
EOD
plot $d0 with linespoints title 'two-rooms-doorway hierarchical', \
     $d1 with linespoints title 'two-rooms-doorway monte-carlo', \
     $d2 with linespoints title 'two-rooms-doorway radiance'
