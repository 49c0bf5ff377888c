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
0.12494 0.00241497
0.245204 0.00160901
0.608699 0.000991378
EOD
$d1 << EOD
0.0573322 3.65369e-07
0.188923 2.78947e-07
0.579965 0.000169378
EOD
$d2 << EOD
0.10326 3.21849e-07
0.34757 2.74879e-07
0.822661 3.7729e-08
EOD
$d3 << EOD
0.071648 6.59488e-05
0.25485 3.41788e-06
0.590784 4.03751e-07
EOD
$d4 << EOD
0.0118982 5.16507e-06
0.0261581 5.37523e-06
0.0647273 6.1829e-07
EOD
$d5 << EOD
0.00701321 1.16496e-05
0.0089451 1.34009e-06
0.022203 2.61288e-07
EOD
$d6 << EOD
0.00337555 3.47096e-06
0.00478458 7.85021e-07
0.00496406 7.95204e-07
EOD
$d7 << EOD
0.0131864 1.58587e-05
0.0366183 1.21866e-05
0.0759756 2.40578e-05
EOD
$d8 << EOD
0.101611 0.00157509
0.227487 0.00161823
0.62902 0.00211776
EOD
$d9 << EOD
2.02921 2.14925e-06
2.83858 1.9538e-06
3.96419 3.3256e-07
EOD
$d10 << EOD
2.02537 7.42204e-07
2.7439 7.36332e-06
3.81899 3.64184e-07
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
