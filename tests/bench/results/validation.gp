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
0.0811632 0.0022218
0.226594 0.00140161
0.634914 0.00113192
EOD
$d1 << EOD
0.0660344 3.83822e-07
0.206297 2.83907e-07
0.622131 0.000119414
EOD
$d2 << EOD
0.130728 1.83745e-07
0.393311 8.43664e-10
0.91236 2.73246e-08
EOD
$d3 << EOD
0.0899676 5.37122e-06
0.225307 2.22534e-06
0.60731 3.53245e-07
EOD
$d4 << EOD
0.0125131 5.16507e-06
0.0295642 5.37523e-06
0.0643806 0.000211836
EOD
$d5 << EOD
0.00605204 1.16496e-05
0.00940598 1.34009e-06
0.0187965 2.61288e-07
EOD
$d6 << EOD
0.00252653 3.47096e-06
0.00332828 7.85021e-07
0.00430049 7.95204e-07
EOD
$d7 << EOD
0.0106231 1.58587e-05
0.0351391 1.21866e-05
0.0639007 2.40578e-05
EOD
$d8 << EOD
0.103796 0.00158262
0.235157 0.00165214
6.637 0.00209738
EOD
$d9 << EOD
2.49328 2.0902e-06
3.20378 1.95354e-06
4.1351 3.3256e-07
EOD
$d10 << EOD
2.46991 1.25534e-06
3.21128 7.19491e-06
4.06848 1.12292e-06
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
