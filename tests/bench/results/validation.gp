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
0.0311489 0.00209395
0.126555 0.000979569
0.711515 0.000373881
EOD
$d1 << EOD
0.0416808 0.00197139
0.124659 0.000946673
0.865369 0.000365145
EOD
$d2 << EOD
0.231185 0.00140448
0.445741 0.00058655
1.15953 0.000463392
EOD
$d3 << EOD
0.0460947 0.00161512
0.173358 0.000850659
1.03015 0.000340932
EOD
$d4 << EOD
0.0474622 0.00206861
0.179158 0.0010586
1.05667 0.000382912
EOD
$d5 << EOD
0.0366811 2.70666e-09
0.1233 1.94349e-09
0.706315 6.24699e-10
EOD
$d6 << EOD
0.0333504 7.90363e-05
0.119273 2.15431e-05
0.669389 5.87587e-06
EOD
$d7 << EOD
0.128817 0.00112925
0.435828 1.12934e-08
1.00604 2.88893e-07
EOD
$d8 << EOD
0.0333442 0.000488279
0.121465 0.000122068
0.673567 3.05182e-05
EOD
$d9 << EOD
0.0397047 0.000127766
0.124258 7.87754e-05
0.666348 1.15974e-05
EOD
$d10 << EOD
11.2626 1.10957e-09
20.0435 3.01896e-09
26.4568 3.01896e-09
EOD
$d11 << EOD
8.41509 5.12812e-05
18.4742 1.30449e-05
24.201 1.30449e-05
EOD
$d12 << EOD
0.249411 0.000661284
0.698279 0.00017279
1.61068 1.84002e-08
EOD
$d13 << EOD
8.50195 0.000488282
17.6887 0.000122067
24.3494 3.05146e-05
EOD
$d14 << EOD
8.59329 0.000144262
18.0526 1.19271e-05
24.7226 4.33695e-07
EOD
$d15 << EOD
0.0276702 2.43599e-08
0.103163 1.74914e-08
0.616552 5.62238e-09
EOD
$d16 << EOD
0.0296991 0.000225042
0.105479 6.44038e-05
0.598709 2.27206e-05
EOD
$d17 << EOD
0.125817 1.76629e-07
0.353268 1.00261e-07
0.932844 1.26139e-10
EOD
$d18 << EOD
0.0311596 0.000456752
0.10537 0.000143324
0.58061 4.99856e-05
EOD
$d19 << EOD
0.028216 0.000175449
0.107197 5.49724e-05
0.583149 2.10486e-05
EOD
$d20 << EOD
0.0366434 2.67959e-07
0.123647 1.92406e-07
0.683141 6.18463e-08
EOD
$d21 << EOD
0.0338965 0.000248542
0.125886 7.43886e-05
0.783673 2.47788e-05
EOD
$d22 << EOD
0.179204 2.80108e-05
0.544406 9.13422e-06
1.43288 2.18349e-07
EOD
$d23 << EOD
0.0359995 0.000496145
0.127758 0.000148424
0.749761 4.97556e-05
EOD
$d24 << EOD
0.0355435 0.000337721
0.133029 0.000100401
0.794054 3.34232e-05
EOD
$d25 << EOD
0.0338511 2.70396e-06
0.12449 1.94155e-06
0.614838 6.24085e-07
EOD
$d26 << EOD
0.0588655 0.000246846
0.251211 7.28853e-05
2.09325 2.55701e-05
EOD
$d27 << EOD
0.155181 0.000369966
0.504791 1.63687e-05
1.33631 2.0502e-06
EOD
$d28 << EOD
0.125877 0.000496858
0.329047 0.000147982
2.02587 5.06005e-05
EOD
$d29 << EOD
0.0653556 0.000356125
0.225256 0.000104558
1.24033 4.55459e-05
EOD
$d30 << EOD
0.00665176 1.0391e-06
0.0108903 1.75818e-08
0.0238957 1.53455e-06
EOD
$d31 << EOD
0.0053209 1.0391e-06
0.0106883 1.75818e-08
0.023277 1.53455e-06
EOD
$d32 << EOD
0.0221617 5.16507e-06
0.0361259 5.37523e-06
0.0966073 0.000211836
EOD
$d33 << EOD
0.00575075 1.0391e-06
0.0100534 1.75818e-08
0.0163406 1.53455e-06
EOD
$d34 << EOD
0.00496948 1.0391e-06
0.00893713 1.75818e-08
0.0209442 1.53455e-06
EOD
$d35 << EOD
0.00335289 3.65404e-06
0.00385492 2.13873e-05
0.00903562 2.23032e-06
EOD
$d36 << EOD
0.00399758 3.65404e-06
0.00413213 2.13873e-05
0.00666222 2.23032e-06
EOD
$d37 << EOD
0.00891449 1.16496e-05
0.0151585 1.34009e-06
0.0268511 2.61288e-07
EOD
$d38 << EOD
0.00289106 3.65404e-06
0.00436765 2.13873e-05
0.00767492 2.23032e-06
EOD
$d39 << EOD
0.00331343 3.65404e-06
0.00469596 2.13873e-05
0.00788264 2.23032e-06
EOD
$d40 << EOD
0.0038888 6.85998e-05
0.00410744 6.85998e-05
0.00486714 4.12547e-06
EOD
$d41 << EOD
0.00348368 6.85998e-05
0.00376423 4.12547e-06
0.00512653 6.85998e-05
EOD
$d42 << EOD
0.00520218 3.47096e-06
0.00719689 7.85021e-07
0.0100317 7.95204e-07
EOD
$d43 << EOD
0.00329667 6.85998e-05
0.0043413 6.85998e-05
0.0044988 4.12547e-06
EOD
$d44 << EOD
0.00326167 6.85998e-05
0.00357081 6.85998e-05
0.0048226 4.12547e-06
EOD
$d45 << EOD
0.00641866 8.96964e-09
0.0127629 1.20326e-06
0.0446061 4.44147e-07
EOD
$d46 << EOD
0.00596509 8.96964e-09
0.0101784 1.20326e-06
0.0412799 4.44147e-07
EOD
$d47 << EOD
0.0223112 1.58587e-05
0.0452182 1.21866e-05
0.105564 2.40578e-05
EOD
$d48 << EOD
0.006439 8.96964e-09
0.0138134 1.20326e-06
0.0391008 4.44147e-07
EOD
$d49 << EOD
0.00598233 8.96964e-09
0.012949 1.20326e-06
0.0399331 4.44147e-07
EOD
$d50 << EOD
0.0301499 0.00403343
0.150886 0.00163828
0.812372 0.00139083
EOD
$d51 << EOD
0.0313541 0.00409414
0.146966 0.00164826
0.744696 0.00138732
EOD
$d52 << EOD
0.183341 0.00238377
0.378964 0.00209909
1.07689 0.00226596
EOD
$d53 << EOD
0.029238 0.00413039
0.141434 0.00167047
0.778923 0.00138102
EOD
$d54 << EOD
0.0151709 0.0158091
0.0179544 0.0158091
0.0380118 0.00368505
EOD
$d55 << EOD
0.0296634 0.0039781
0.151221 0.00163773
0.779707 0.00138146
EOD
$d56 << EOD
60.5942 0.790197
60.6318 0.749733
60.6578 0.760717
EOD
$d57 << EOD
60.592 0.745656
60.608 0.7494
60.6679 0.782583
EOD
$d58 << EOD
5.50627 2.0902e-06
5.71868 1.95354e-06
7.55768 3.3256e-07
EOD
$d59 << EOD
60.551 0.7506
60.5699 0.741548
60.6339 0.76878
EOD
$d60 << EOD
10.1416 0.0126456
14.0204 0.000110728
15.774 0.000420057
EOD
$d61 << EOD
60.5727 0.890894
60.5803 0.892471
60.5979 0.901518
EOD
$d62 << EOD
60.6126 0.889863
60.6128 0.918647
60.7262 0.904338
EOD
$d63 << EOD
5.56535 1.25534e-06
5.5863 7.19491e-06
9.08185 1.12292e-06
EOD
$d64 << EOD
60.5596 0.900494
60.7086 0.90043
60.7251 0.931051
EOD
$d65 << EOD
18.2695 0.00456328
22.4449 0.0037786
28.0465 0.000773283
EOD
plot $d0 with linespoints title 'cube-ceiling-rho0.5 direct', \
     $d1 with linespoints title 'cube-ceiling-rho0.5 gauss-seidel', \
     $d2 with linespoints title 'cube-ceiling-rho0.5 hierarchical', \
     $d3 with linespoints title 'cube-ceiling-rho0.5 jacobi', \
     $d4 with linespoints title 'cube-ceiling-rho0.5 shooting', \
     $d5 with linespoints title 'furnace-rho0.5 direct', \
     $d6 with linespoints title 'furnace-rho0.5 gauss-seidel', \
     $d7 with linespoints title 'furnace-rho0.5 hierarchical', \
     $d8 with linespoints title 'furnace-rho0.5 jacobi', \
     $d9 with linespoints title 'furnace-rho0.5 shooting', \
     $d10 with linespoints title 'furnace-rho0.5-slab direct', \
     $d11 with linespoints title 'furnace-rho0.5-slab gauss-seidel', \
     $d12 with linespoints title 'furnace-rho0.5-slab hierarchical', \
     $d13 with linespoints title 'furnace-rho0.5-slab jacobi', \
     $d14 with linespoints title 'furnace-rho0.5-slab shooting', \
     $d15 with linespoints title 'furnace-rho0.9 direct', \
     $d16 with linespoints title 'furnace-rho0.9 gauss-seidel', \
     $d17 with linespoints title 'furnace-rho0.9 hierarchical', \
     $d18 with linespoints title 'furnace-rho0.9 jacobi', \
     $d19 with linespoints title 'furnace-rho0.9 shooting', \
     $d20 with linespoints title 'furnace-rho0.99 direct', \
     $d21 with linespoints title 'furnace-rho0.99 gauss-seidel', \
     $d22 with linespoints title 'furnace-rho0.99 hierarchical', \
     $d23 with linespoints title 'furnace-rho0.99 jacobi', \
     $d24 with linespoints title 'furnace-rho0.99 shooting', \
     $d25 with linespoints title 'furnace-rho0.999 direct', \
     $d26 with linespoints title 'furnace-rho0.999 gauss-seidel', \
     $d27 with linespoints title 'furnace-rho0.999 hierarchical', \
     $d28 with linespoints title 'furnace-rho0.999 jacobi', \
     $d29 with linespoints title 'furnace-rho0.999 shooting', \
     $d30 with linespoints title 'parallel-squares-d0.5 direct', \
     $d31 with linespoints title 'parallel-squares-d0.5 gauss-seidel', \
     $d32 with linespoints title 'parallel-squares-d0.5 hierarchical', \
     $d33 with linespoints title 'parallel-squares-d0.5 jacobi', \
     $d34 with linespoints title 'parallel-squares-d0.5 shooting', \
     $d35 with linespoints title 'parallel-squares-d1 direct', \
     $d36 with linespoints title 'parallel-squares-d1 gauss-seidel', \
     $d37 with linespoints title 'parallel-squares-d1 hierarchical', \
     $d38 with linespoints title 'parallel-squares-d1 jacobi', \
     $d39 with linespoints title 'parallel-squares-d1 shooting', \
     $d40 with linespoints title 'parallel-squares-d2 direct', \
     $d41 with linespoints title 'parallel-squares-d2 gauss-seidel', \
     $d42 with linespoints title 'parallel-squares-d2 hierarchical', \
     $d43 with linespoints title 'parallel-squares-d2 jacobi', \
     $d44 with linespoints title 'parallel-squares-d2 shooting', \
     $d45 with linespoints title 'perpendicular-squares direct', \
     $d46 with linespoints title 'perpendicular-squares gauss-seidel', \
     $d47 with linespoints title 'perpendicular-squares hierarchical', \
     $d48 with linespoints title 'perpendicular-squares jacobi', \
     $d49 with linespoints title 'perpendicular-squares shooting', \
     $d50 with linespoints title 'room-s2 direct', \
     $d51 with linespoints title 'room-s2 gauss-seidel', \
     $d52 with linespoints title 'room-s2 hierarchical', \
     $d53 with linespoints title 'room-s2 jacobi', \
     $d54 with linespoints title 'room-s2 monte-carlo', \
     $d55 with linespoints title 'room-s2 shooting', \
     $d56 with linespoints title 'sphere-rho0.5 direct', \
     $d57 with linespoints title 'sphere-rho0.5 gauss-seidel', \
     $d58 with linespoints title 'sphere-rho0.5 hierarchical', \
     $d59 with linespoints title 'sphere-rho0.5 jacobi', \
     $d60 with linespoints title 'sphere-rho0.5 shooting', \
     $d61 with linespoints title 'sphere-rho0.8 direct', \
     $d62 with linespoints title 'sphere-rho0.8 gauss-seidel', \
     $d63 with linespoints title 'sphere-rho0.8 hierarchical', \
     $d64 with linespoints title 'sphere-rho0.8 jacobi', \
     $d65 with linespoints title 'sphere-rho0.8 shooting'
