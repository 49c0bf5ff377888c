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
0.0984011 0.0022218
0.251713 0.00140161
0.613859 0.00113192
EOD
$d1 << EOD
0.0611764 3.83822e-07
0.226604 2.83907e-07
0.679985 0.000119414
EOD
$d2 << EOD
0.112347 1.83745e-07
0.326003 8.43664e-10
0.841769 2.73246e-08
EOD
$d3 << EOD
0.0926029 5.37122e-06
0.238891 2.22534e-06
0.613423 3.53245e-07
EOD
$d4 << EOD
0.0123097 5.16507e-06
0.0345577 5.37523e-06
0.0906939 0.000211836
EOD
$d5 << EOD
0.00623837 1.16496e-05
0.0119257 1.34009e-06
0.0171873 2.61288e-07
EOD
$d6 << EOD
0.00250305 3.47096e-06
0.00337747 7.85021e-07
0.00491572 7.95204e-07
EOD
$d7 << EOD
0.0110245 1.58587e-05
0.0293503 1.21866e-05
0.0685584 2.40578e-05
EOD
$d8 << EOD
0.113547 0.00158262
0.243078 0.00165214
0.634728 0.00211354
EOD
$d9 << EOD
2.56906 2.0902e-06
3.22611 1.95354e-06
4.50668 3.3256e-07
EOD
$d10 << EOD
2.903 1.25534e-06
4.12858 7.19491e-06
4.98477 1.12292e-06
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
