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
0.026917 0.00209395
0.102527 0.000979569
0.595946 0.000373881
EOD
$d1 << EOD
0.0260551 0.00197139
0.10045 0.000946673
0.613697 0.000365145
EOD
$d2 << EOD
0.138785 0.00140448
0.452429 0.00058655
0.914442 0.000463392
EOD
$d3 << EOD
0.0293207 0.00161512
0.101141 0.000850659
0.573222 0.000340932
EOD
$d4 << EOD
0.0265554 0.00206861
0.105187 0.0010586
0.570282 0.000382912
EOD
$d5 << EOD
0.032964 2.70666e-09
0.10999 1.94349e-09
0.616944 6.24699e-10
EOD
$d6 << EOD
0.0273956 7.90363e-05
0.107353 2.15431e-05
0.574733 5.87587e-06
EOD
$d7 << EOD
0.117286 0.00112925
0.32395 1.12934e-08
0.834339 2.88893e-07
EOD
$d8 << EOD
0.0286556 0.000488279
0.104203 0.000122068
0.595945 3.05182e-05
EOD
$d9 << EOD
0.0310751 0.000127766
0.108238 7.87754e-05
0.603454 1.15974e-05
EOD
$d10 << EOD
9.19581 1.10957e-09
19.0961 3.01896e-09
26.4026 3.01896e-09
EOD
$d11 << EOD
8.2081 5.12812e-05
17.2147 1.30449e-05
23.5032 1.30449e-05
EOD
$d12 << EOD
0.268854 0.000661284
0.698854 0.00017279
1.61771 1.84002e-08
EOD
$d13 << EOD
8.16533 0.000488282
16.875 0.000122067
23.6303 3.05146e-05
EOD
$d14 << EOD
8.32581 0.000144262
17.2482 1.19271e-05
24.1394 4.33695e-07
EOD
$d15 << EOD
0.0288358 2.43599e-08
0.114256 1.74914e-08
0.610889 5.62238e-09
EOD
$d16 << EOD
0.0287677 0.000225042
0.106139 6.44038e-05
0.592679 2.27206e-05
EOD
$d17 << EOD
0.133209 1.76629e-07
0.381427 1.00261e-07
1.01131 1.26139e-10
EOD
$d18 << EOD
0.0276223 0.000456752
0.108502 0.000143324
0.604902 4.99856e-05
EOD
$d19 << EOD
0.0303517 0.000175449
0.108487 5.49724e-05
0.606039 2.10486e-05
EOD
$d20 << EOD
0.0337563 2.67959e-07
0.102625 1.92406e-07
0.58472 6.18463e-08
EOD
$d21 << EOD
0.0299072 0.000248542
0.113869 7.43886e-05
0.679058 2.47788e-05
EOD
$d22 << EOD
0.139067 2.80108e-05
0.406767 9.13422e-06
1.10982 2.18349e-07
EOD
$d23 << EOD
0.0418756 0.000496145
0.143393 0.000148424
0.682915 4.97556e-05
EOD
$d24 << EOD
0.0321245 0.000337721
0.110639 0.000100401
0.633704 3.34232e-05
EOD
$d25 << EOD
0.0286404 2.70396e-06
0.104166 1.94155e-06
0.578308 6.24085e-07
EOD
$d26 << EOD
0.054026 0.000246846
0.240361 7.28853e-05
1.80861 2.55701e-05
EOD
$d27 << EOD
0.155991 0.000369966
0.482778 1.63687e-05
1.33071 2.0502e-06
EOD
$d28 << EOD
0.128901 0.000496858
0.331525 0.000147982
1.87105 5.06005e-05
EOD
$d29 << EOD
0.0604317 0.000356125
0.211281 0.000104558
1.80593 3.6341e-05
EOD
$d30 << EOD
0.00631458 1.0391e-06
0.00985718 1.75818e-08
0.0253805 1.53455e-06
EOD
$d31 << EOD
0.00655527 1.0391e-06
0.00933905 1.75818e-08
0.0252944 1.53455e-06
EOD
$d32 << EOD
0.0215684 5.16507e-06
0.0374029 5.37523e-06
0.103201 0.000211836
EOD
$d33 << EOD
0.00598668 1.0391e-06
0.0124613 1.75818e-08
0.0177389 1.53455e-06
EOD
$d34 << EOD
0.00557443 1.0391e-06
0.0125497 1.75818e-08
0.0226105 1.53455e-06
EOD
$d35 << EOD
0.00424576 3.65404e-06
0.00600911 2.13873e-05
0.00826071 2.23032e-06
EOD
$d36 << EOD
0.00453932 2.13873e-05
0.00525113 3.65404e-06
0.0100164 2.23032e-06
EOD
$d37 << EOD
0.0131635 1.16496e-05
0.017247 1.34009e-06
0.033029 2.61288e-07
EOD
$d38 << EOD
0.00417612 3.65404e-06
0.00792005 2.23032e-06
0.00815266 2.13873e-05
EOD
$d39 << EOD
0.00473594 2.13873e-05
0.00669486 3.65404e-06
0.00847869 2.23032e-06
EOD
$d40 << EOD
0.00506292 4.12547e-06
0.00506556 6.85998e-05
0.0051305 6.85998e-05
EOD
$d41 << EOD
0.00451429 4.12547e-06
0.00515668 6.85998e-05
0.00525878 6.85998e-05
EOD
$d42 << EOD
0.00739861 3.47096e-06
0.00971 7.85021e-07
0.0115305 7.95204e-07
EOD
$d43 << EOD
0.00398302 6.85998e-05
0.00557301 4.12547e-06
0.00721956 6.85998e-05
EOD
$d44 << EOD
0.00441065 6.85998e-05
0.00735456 4.12547e-06
0.00736304 6.85998e-05
EOD
$d45 << EOD
0.00728593 8.96964e-09
0.0149566 1.20326e-06
0.0595035 4.44147e-07
EOD
$d46 << EOD
0.0094911 8.96964e-09
0.0171786 1.20326e-06
0.0486332 4.44147e-07
EOD
$d47 << EOD
0.022122 1.58587e-05
0.0459757 1.21866e-05
0.111865 2.40578e-05
EOD
$d48 << EOD
0.00723515 8.96964e-09
0.0118707 1.20326e-06
0.0439176 4.44147e-07
EOD
$d49 << EOD
0.00599602 8.96964e-09
0.0116478 1.20326e-06
0.0439767 4.44147e-07
EOD
$d50 << EOD
0.0284311 0.0058445
0.158053 0.00311426
0.830591 0.00104097
EOD
$d51 << EOD
0.0322257 0.00591285
0.149243 0.00313144
0.780069 0.00104488
EOD
$d52 << EOD
0.188512 0.000573591
0.386272 0.000434759
1.03894 0.000368211
EOD
$d53 << EOD
0.0292983 0.00595336
0.150683 0.00316796
0.784861 0.00105199
EOD
$d54 << EOD
0.0161846 0.0157115
0.0181417 0.0157115
0.0427698 0.00434977
EOD
$d55 << EOD
0.0310021 0.005782
0.149538 0.00311275
0.797134 0.00105161
EOD
$d56 << EOD
60.5639 0.777154
60.5753 0.746973
60.605 0.761886
EOD
$d57 << EOD
60.5598 0.751768
60.611 0.761944
60.6132 0.768547
EOD
$d58 << EOD
5.43863 2.0902e-06
7.00019 1.95354e-06
9.29586 3.3256e-07
EOD
$d59 << EOD
60.5562 0.740583
60.5699 0.744175
60.6902 0.757703
EOD
$d60 << EOD
9.69933 0.0126456
13.1596 0.000110728
16.3567 0.000420057
EOD
$d61 << EOD
60.5906 0.909118
60.6425 0.90806
60.6911 0.891765
EOD
$d62 << EOD
60.5554 0.8968
60.6221 0.887402
60.6628 0.886438
EOD
$d63 << EOD
4.16489 1.25534e-06
5.29503 7.19491e-06
7.01192 1.12292e-06
EOD
$d64 << EOD
60.595 0.893261
60.6483 0.903748
60.7162 0.906655
EOD
$d65 << EOD
14.6059 0.00456328
17.3594 0.0037786
19.6671 0.000773283
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
