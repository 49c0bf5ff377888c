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
0.58994 0.000640155
1.38103 0.000830725
3.34287 0.00141504
28.1773 0.00130908
EOD
$d1 << EOD
0.0275197 0.0209468
0.040432 0.00721854
0.0842933 0.0040715
0.431931 0.00162461
EOD
$d2 << EOD
0.263385 0.0531491
0.539636 0.0256156
0.881256 0.00879552
1.61366 0.00908893
3.3057 0.00214047
9.62494 0.00204921
9.8708 0.00186289
EOD
plot $d0 with linespoints title 'two-rooms-doorway hierarchical', \
     $d1 with linespoints title 'two-rooms-doorway monte-carlo', \
     $d2 with linespoints title 'two-rooms-doorway radiance'
