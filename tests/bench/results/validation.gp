set terminal pngcairo size 1280,900 noenhanced
set output 'validation.png'
set logscale xy
set format xy '%g'
set grid
set key outside right top
set xlabel 'seconds'
set ylabel 'RMS relative error'
set title 'radiant-bench: error against time'
$d0 << EOD
0.142906 0.00140448
0.365099 0.00058655
0.92406 0.000463392
EOD
$d1 << EOD
0.111339 0.00112925
0.317692 1.12934e-08
0.858575 2.88893e-07
EOD
$d2 << EOD
0.255865 0.000661284
0.678819 0.00017279
1.60794 1.84002e-08
EOD
$d3 << EOD
0.121148 1.76629e-07
0.358896 1.00261e-07
0.965436 1.26139e-10
EOD
$d4 << EOD
0.132494 2.80108e-05
0.364204 9.13422e-06
1.28333 2.18349e-07
EOD
$d5 << EOD
0.165228 0.000369966
0.48085 1.63687e-05
1.36682 2.0502e-06
EOD
$d6 << EOD
0.0219315 5.16507e-06
0.0383847 5.37523e-06
0.101362 0.000211836
EOD
$d7 << EOD
0.00900849 1.16496e-05
0.0156092 1.34009e-06
0.0324472 2.61288e-07
EOD
$d8 << EOD
0.00525521 3.47096e-06
0.00652398 7.85021e-07
0.0100608 7.95204e-07
EOD
$d9 << EOD
0.0178824 1.58587e-05
0.0461371 1.21866e-05
0.106766 2.40578e-05
EOD
$d10 << EOD
0.174137 0.00238377
0.35365 0.00209909
0.947817 0.00226596
EOD
$d11 << EOD
4.4925 2.0902e-06
5.70749 1.95354e-06
8.04765 3.3256e-07
EOD
$d12 << EOD
4.43104 1.25534e-06
5.85785 7.19491e-06
7.71253 1.12292e-06
EOD
plot $d0 with linespoints title 'cube-ceiling-rho0.5 hierarchical', \
     $d1 with linespoints title 'furnace-rho0.5 hierarchical', \
     $d2 with linespoints title 'furnace-rho0.5-slab hierarchical', \
     $d3 with linespoints title 'furnace-rho0.9 hierarchical', \
     $d4 with linespoints title 'furnace-rho0.99 hierarchical', \
     $d5 with linespoints title 'furnace-rho0.999 hierarchical', \
     $d6 with linespoints title 'parallel-squares-d0.5 hierarchical', \
     $d7 with linespoints title 'parallel-squares-d1 hierarchical', \
     $d8 with linespoints title 'parallel-squares-d2 hierarchical', \
     $d9 with linespoints title 'perpendicular-squares hierarchical', \
     $d10 with linespoints title 'room-s2 hierarchical', \
     $d11 with linespoints title 'sphere-rho0.5 hierarchical', \
     $d12 with linespoints title 'sphere-rho0.8 hierarchical'
