set terminal pngcairo size 1280,900 noenhanced
set output 'tests/bench/results/validation.png'
set logscale xy
set format xy '%g'
set grid
set key outside right top
set xlabel 'seconds'
set ylabel 'RMS relative error'
set title 'radiant-bench: error against time'
$d0 << EOD
0.158137 0.00174325
0.446149 0.00113912
1.14362 0.000952295
EOD
$d1 << EOD
0.125312 0.00112861
0.381565 0.000481333
1.0272 2.9818e-07
EOD
$d2 << EOD
0.219721 0.000660515
0.683116 0.000173405
1.91559 2.32263e-08
EOD
$d3 << EOD
0.131832 2.74237e-06
0.398589 3.0717e-07
1.10789 3.78089e-07
EOD
$d4 << EOD
0.0120741 5.16507e-06
0.0616407 5.37523e-06
0.119128 0.000211836
EOD
$d5 << EOD
0.00493887 1.16496e-05
0.0124577 1.34009e-06
0.0230764 2.61288e-07
EOD
$d6 << EOD
0.00267034 3.47096e-06
0.00332612 7.85021e-07
0.00699461 7.95204e-07
EOD
$d7 << EOD
0.0221273 1.58587e-05
0.0411425 1.21866e-05
0.124441 2.40578e-05
EOD
$d8 << EOD
0.193281 0.00193282
0.481213 0.00205877
1.23056 0.00227362
EOD
$d9 << EOD
2.75763 2.0902e-06
3.64789 1.95354e-06
4.79097 3.3256e-07
EOD
$d10 << EOD
2.78856 1.25534e-06
3.44507 7.19491e-06
4.39335 1.12292e-06
EOD
plot $d0 with linespoints title 'cube-ceiling-rho0.5 hierarchical', \
     $d1 with linespoints title 'furnace-rho0.5 hierarchical', \
     $d2 with linespoints title 'furnace-rho0.5-slab hierarchical', \
     $d3 with linespoints title 'furnace-rho0.9 hierarchical', \
     $d4 with linespoints title 'parallel-squares-d0.5 hierarchical', \
     $d5 with linespoints title 'parallel-squares-d1 hierarchical', \
     $d6 with linespoints title 'parallel-squares-d2 hierarchical', \
     $d7 with linespoints title 'perpendicular-squares hierarchical', \
     $d8 with linespoints title 'room-s2 hierarchical', \
     $d9 with linespoints title 'sphere-rho0.5 hierarchical', \
     $d10 with linespoints title 'sphere-rho0.8 hierarchical'
