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
0.217237 0.00283777
0.608101 0.00139408
1.40034 0.00109778
EOD
$d1 << EOD
0.148215 0.00195312
0.450192 0.000488281
EOD
$d2 << EOD
0.271461 0.00195312
EOD
$d3 << EOD
0.137077 5.10703e-15
0.392077 3.94129e-14
1.16942 1.0858e-13
EOD
$d4 << EOD
0.026986 5.16507e-06
0.0589134 5.37523e-06
0.146297 6.1829e-07
EOD
$d5 << EOD
0.0100065 1.16496e-05
0.0196335 1.34009e-06
0.0488548 2.61288e-07
EOD
$d6 << EOD
0.00409933 3.47096e-06
0.00638542 7.85021e-07
0.0151807 7.95204e-07
EOD
$d7 << EOD
0.0314298 1.58587e-05
0.0627115 1.21866e-05
0.15022 2.40578e-05
EOD
$d8 << EOD
0.275249 0.00239643
0.718289 0.00172937
1.69536 0.00259742
EOD
$d9 << EOD
5.38175 2.23834e-06
7.54009 1.9543e-06
10.0515 3.3256e-07
EOD
$d10 << EOD
5.86041 3.73004e-06
7.81818 3.19265e-06
9.87856 5.30218e-07
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
