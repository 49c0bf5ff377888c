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
0.204526 0.00241497
0.4874 0.00160901
1.3994 0.000991378
EOD
$d1 << EOD
0.15338 3.65369e-07
0.396659 2.78947e-07
1.22699 0.000169378
EOD
$d2 << EOD
0.254405 3.21849e-07
0.766302 2.74879e-07
1.96167 3.7729e-08
EOD
$d3 << EOD
0.15049 6.59488e-05
0.426126 3.41788e-06
1.17684 4.03751e-07
EOD
$d4 << EOD
0.0312488 5.16507e-06
0.0583545 5.37523e-06
0.162405 6.1829e-07
EOD
$d5 << EOD
0.00795694 1.16496e-05
0.0208721 1.34009e-06
0.0461576 2.61288e-07
EOD
$d6 << EOD
0.00399134 3.47096e-06
0.00504145 7.85021e-07
0.0129703 7.95204e-07
EOD
$d7 << EOD
0.0177212 1.58587e-05
0.0525078 1.21866e-05
0.157861 2.40578e-05
EOD
$d8 << EOD
0.249546 0.00157509
0.603737 0.00161823
1.65693 0.00211776
EOD
$d9 << EOD
6.22443 2.14925e-06
9.16287 1.9538e-06
11.3849 3.3256e-07
EOD
$d10 << EOD
6.113 7.42204e-07
8.34884 7.36332e-06
10.7198 3.64184e-07
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
