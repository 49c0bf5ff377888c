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
0.107728 0.00140448
0.288092 0.00058655
0.729164 0.000463392
EOD
$d1 << EOD
0.0812497 0.00112925
0.245295 1.12934e-08
0.690362 2.88893e-07
EOD
$d2 << EOD
0.189697 0.000661284
0.526019 0.00017279
1.35369 1.84002e-08
EOD
$d3 << EOD
0.115718 1.76629e-07
0.369716 1.00261e-07
0.962013 1.26139e-10
EOD
$d4 << EOD
0.0131543 5.16507e-06
0.0382887 5.37523e-06
0.0757958 0.000211836
EOD
$d5 << EOD
0.00622692 1.16496e-05
0.0103912 1.34009e-06
0.0210887 2.61288e-07
EOD
$d6 << EOD
0.00247457 3.47096e-06
0.00341474 7.85021e-07
0.0056128 7.95204e-07
EOD
$d7 << EOD
0.0145156 1.58587e-05
0.0418615 1.21866e-05
0.0810178 2.40578e-05
EOD
$d8 << EOD
0.149937 0.00238377
0.297851 0.00209909
0.733767 0.00226596
EOD
$d9 << EOD
2.5228 2.0902e-06
3.22947 1.95354e-06
4.35798 3.3256e-07
EOD
$d10 << EOD
2.48357 1.25534e-06
3.24627 7.19491e-06
4.21945 1.12292e-06
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
