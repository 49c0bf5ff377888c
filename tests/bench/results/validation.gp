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
0.0297598 0.00209395
0.11344 0.000979569
0.619344 0.000373881
EOD
$d1 << EOD
0.0274364 0.00197139
0.105596 0.000946673
0.593995 0.000365145
EOD
$d2 << EOD
0.146263 0.00140448
0.390057 0.00058655
0.924535 0.000463392
EOD
$d3 << EOD
0.0272678 0.00161512
0.115047 0.000850659
0.602457 0.000340932
EOD
$d4 << EOD
0.0102833 0.0165596
0.0194703 0.00807572
0.0755819 0.00466826
EOD
$d5 << EOD
0.0307391 0.00206861
0.109694 0.0010586
0.607099 0.000382912
EOD
$d6 << EOD
0.0353043 2.70666e-09
0.1178 1.94349e-09
0.620451 6.24699e-10
EOD
$d7 << EOD
0.0277542 7.90363e-05
0.10693 2.15431e-05
0.59575 5.87587e-06
EOD
$d8 << EOD
0.113294 0.00112925
0.32284 1.12934e-08
0.867647 2.88893e-07
EOD
$d9 << EOD
0.0318886 0.000488279
0.110296 0.000122068
0.600693 3.05182e-05
EOD
$d10 << EOD
0.00898861 0.000854492
0.00959205 0.000854492
0.0253819 0.00231934
EOD
$d11 << EOD
0.0282233 0.000127766
0.111623 7.87754e-05
0.599113 1.15974e-05
EOD
$d12 << EOD
9.1654 1.10957e-09
13.1714 3.01896e-09
19.1928 3.01896e-09
EOD
$d13 << EOD
8.0244 5.12812e-05
13.394 1.30449e-05
17.2286 1.30449e-05
EOD
$d14 << EOD
0.28637 0.000661284
0.709068 0.00017279
1.60323 1.84002e-08
EOD
$d15 << EOD
8.19005 0.000488282
12.8047 3.05146e-05
17.3213 0.000122067
EOD
$d16 << EOD
0.179537 0.0030692
0.183853 0.000854492
0.279804 0.00154215
EOD
$d17 << EOD
9.18972 0.000144262
12.905 4.33695e-07
19.2698 1.19271e-05
EOD
$d18 << EOD
0.034544 2.43599e-08
0.112197 1.74914e-08
0.615217 5.62238e-09
EOD
$d19 << EOD
0.0271668 0.000225042
0.103515 6.44038e-05
0.578113 2.27206e-05
EOD
$d20 << EOD
0.120353 1.76629e-07
0.370318 1.00261e-07
1.10237 1.26139e-10
EOD
$d21 << EOD
0.0297385 0.000456752
0.106023 0.000143324
0.588018 4.99856e-05
EOD
$d22 << EOD
0.0168057 0.0139746
0.0320513 0.0146865
0.114351 0.0084375
EOD
$d23 << EOD
0.0296935 0.000175449
0.101964 5.49724e-05
0.578412 2.10486e-05
EOD
$d24 << EOD
0.0495499 2.67959e-07
0.204293 1.92406e-07
1.24298 6.18463e-08
EOD
$d25 << EOD
0.0630654 0.000248542
0.232052 7.43886e-05
1.33482 2.47788e-05
EOD
$d26 << EOD
0.296947 2.80108e-05
0.897189 9.13422e-06
2.6525 2.18349e-07
EOD
$d27 << EOD
0.0692759 0.000496145
0.220775 0.000148424
1.36775 4.97556e-05
EOD
$d28 << EOD
0.0782127 0.00741533
0.394902 0.00696658
3.21179 0.00020606
EOD
$d29 << EOD
0.0488565 0.000337721
0.208332 0.000100401
1.29331 3.34232e-05
EOD
$d30 << EOD
0.0490802 2.70396e-06
0.213217 1.94155e-06
1.166 6.24085e-07
EOD
$d31 << EOD
0.0697692 0.000246846
0.403006 7.28853e-05
3.17422 2.55701e-05
EOD
$d32 << EOD
0.199392 0.000369966
0.941094 1.63687e-05
2.9317 2.0502e-06
EOD
$d33 << EOD
0.111123 0.000496858
0.507431 0.000147982
5.39964 5.06005e-05
EOD
$d34 << EOD
0.822175 0.0138348
5.38357 0.00173996
32.0994 0.000723343
EOD
$d35 << EOD
0.11535 0.000356125
0.312461 0.000104558
2.40014 3.6341e-05
EOD
$d36 << EOD
0.00502369 1.0391e-06
0.0118463 1.75818e-08
0.0286238 1.53455e-06
EOD
$d37 << EOD
0.00490502 1.0391e-06
0.0116295 1.75818e-08
0.02305 1.53455e-06
EOD
$d38 << EOD
0.0242559 5.16507e-06
0.0436779 5.37523e-06
0.118706 0.000211836
EOD
$d39 << EOD
0.00712616 1.0391e-06
0.0112305 1.75818e-08
0.0206303 1.53455e-06
EOD
$d40 << EOD
0.00578387 0.00575539
0.00818075 0.0194738
0.0127623 0.000324022
EOD
$d41 << EOD
0.0047631 1.0391e-06
0.0111711 1.75818e-08
0.0216283 1.53455e-06
EOD
$d42 << EOD
0.00409238 3.65404e-06
0.00661663 2.13873e-05
0.00809014 2.23032e-06
EOD
$d43 << EOD
0.00429957 2.13873e-05
0.00677201 3.65404e-06
0.0107818 2.23032e-06
EOD
$d44 << EOD
0.00907648 1.16496e-05
0.0165836 1.34009e-06
0.0342443 2.61288e-07
EOD
$d45 << EOD
0.00364887 3.65404e-06
0.0057977 2.13873e-05
0.00664676 2.23032e-06
EOD
$d46 << EOD
0.00598896 0.00953342
0.00742225 0.0262892
0.0142541 1.11042e-05
EOD
$d47 << EOD
0.00495782 3.65404e-06
0.00666917 2.13873e-05
0.00739525 2.23032e-06
EOD
$d48 << EOD
0.00382062 6.85998e-05
0.00407447 4.12547e-06
0.00567716 6.85998e-05
EOD
$d49 << EOD
0.00356044 6.85998e-05
0.00641398 6.85998e-05
0.00668547 4.12547e-06
EOD
$d50 << EOD
0.0065662 7.85021e-07
0.00824764 3.47096e-06
0.0102149 7.95204e-07
EOD
$d51 << EOD
0.00368394 6.85998e-05
0.00395969 6.85998e-05
0.00625465 4.12547e-06
EOD
$d52 << EOD
0.00566487 0.0607136
0.00719243 0.00177442
0.0303969 0.00427606
EOD
$d53 << EOD
0.00352329 6.85998e-05
0.00449109 4.12547e-06
0.00624438 6.85998e-05
EOD
$d54 << EOD
0.00572305 8.96964e-09
0.0157717 1.20326e-06
0.0568873 4.44147e-07
EOD
$d55 << EOD
0.00639278 8.96964e-09
0.0196205 1.20326e-06
0.0417671 4.44147e-07
EOD
$d56 << EOD
0.0209427 1.58587e-05
0.0530414 1.21866e-05
0.112781 2.40578e-05
EOD
$d57 << EOD
0.00576351 8.96964e-09
0.0143179 1.20326e-06
0.0482106 4.44147e-07
EOD
$d58 << EOD
0.00618724 0.0181592
0.00668525 0.00900597
0.0149263 0.000359007
EOD
$d59 << EOD
0.00886167 8.96964e-09
0.01555 1.20326e-06
0.0454918 4.44147e-07
EOD
$d60 << EOD
0.0619734 0.0058445
0.299183 0.00311426
1.60721 0.00104097
EOD
$d61 << EOD
0.0575167 0.00591285
0.299769 0.00313144
1.53304 0.00104488
EOD
$d62 << EOD
0.42059 0.000573591
0.856555 0.000434759
1.82632 0.000368211
EOD
$d63 << EOD
0.0427017 0.00595336
0.25768 0.00316796
1.53256 0.00105199
EOD
$d64 << EOD
0.0330685 0.0152319
0.0422963 0.0152319
0.0857393 0.00411859
EOD
$d65 << EOD
0.0620293 0.005782
0.287462 0.00311275
1.52239 0.00105161
EOD
$d66 << EOD
60.8364 0.749477
60.8778 0.882373
61.8114 0.834578
EOD
$d67 << EOD
60.9485 0.87609
60.9603 0.851914
61.5533 0.890144
EOD
$d68 << EOD
2.64901 2.0902e-06
3.17784 1.95354e-06
4.50419 3.3256e-07
EOD
$d69 << EOD
60.814 0.851456
60.9513 0.855094
61.0984 0.880088
EOD
$d70 << EOD
0.0336166 0.0197754
0.0385672 0.0102539
0.0571852 0.000447591
EOD
$d71 << EOD
10.7683 0.000756383
11.2167 0.00258364
14.8304 0.000937924
EOD
$d72 << EOD
60.677 0.888986
60.684 0.901703
60.6874 0.899681
EOD
$d73 << EOD
60.6953 0.893574
60.7214 0.889419
60.8739 0.911943
EOD
$d74 << EOD
4.72886 1.25534e-06
7.16463 7.19491e-06
10.1951 1.12292e-06
EOD
$d75 << EOD
60.6914 0.901167
60.8896 0.930858
61.6343 0.930066
EOD
$d76 << EOD
0.0341367 0.0205078
0.0488633 0.015293
0.156565 0.00214111
EOD
$d77 << EOD
46.083 0.00746025
54.7197 0.00430403
56.1498 0.000582898
EOD
plot $d0 with linespoints title 'cube-ceiling-rho0.5 direct', \
     $d1 with linespoints title 'cube-ceiling-rho0.5 gauss-seidel', \
     $d2 with linespoints title 'cube-ceiling-rho0.5 hierarchical', \
     $d3 with linespoints title 'cube-ceiling-rho0.5 jacobi', \
     $d4 with linespoints title 'cube-ceiling-rho0.5 monte-carlo', \
     $d5 with linespoints title 'cube-ceiling-rho0.5 shooting', \
     $d6 with linespoints title 'furnace-rho0.5 direct', \
     $d7 with linespoints title 'furnace-rho0.5 gauss-seidel', \
     $d8 with linespoints title 'furnace-rho0.5 hierarchical', \
     $d9 with linespoints title 'furnace-rho0.5 jacobi', \
     $d10 with linespoints title 'furnace-rho0.5 monte-carlo', \
     $d11 with linespoints title 'furnace-rho0.5 shooting', \
     $d12 with linespoints title 'furnace-rho0.5-slab direct', \
     $d13 with linespoints title 'furnace-rho0.5-slab gauss-seidel', \
     $d14 with linespoints title 'furnace-rho0.5-slab hierarchical', \
     $d15 with linespoints title 'furnace-rho0.5-slab jacobi', \
     $d16 with linespoints title 'furnace-rho0.5-slab monte-carlo', \
     $d17 with linespoints title 'furnace-rho0.5-slab shooting', \
     $d18 with linespoints title 'furnace-rho0.9 direct', \
     $d19 with linespoints title 'furnace-rho0.9 gauss-seidel', \
     $d20 with linespoints title 'furnace-rho0.9 hierarchical', \
     $d21 with linespoints title 'furnace-rho0.9 jacobi', \
     $d22 with linespoints title 'furnace-rho0.9 monte-carlo', \
     $d23 with linespoints title 'furnace-rho0.9 shooting', \
     $d24 with linespoints title 'furnace-rho0.99 direct', \
     $d25 with linespoints title 'furnace-rho0.99 gauss-seidel', \
     $d26 with linespoints title 'furnace-rho0.99 hierarchical', \
     $d27 with linespoints title 'furnace-rho0.99 jacobi', \
     $d28 with linespoints title 'furnace-rho0.99 monte-carlo', \
     $d29 with linespoints title 'furnace-rho0.99 shooting', \
     $d30 with linespoints title 'furnace-rho0.999 direct', \
     $d31 with linespoints title 'furnace-rho0.999 gauss-seidel', \
     $d32 with linespoints title 'furnace-rho0.999 hierarchical', \
     $d33 with linespoints title 'furnace-rho0.999 jacobi', \
     $d34 with linespoints title 'furnace-rho0.999 monte-carlo', \
     $d35 with linespoints title 'furnace-rho0.999 shooting', \
     $d36 with linespoints title 'parallel-squares-d0.5 direct', \
     $d37 with linespoints title 'parallel-squares-d0.5 gauss-seidel', \
     $d38 with linespoints title 'parallel-squares-d0.5 hierarchical', \
     $d39 with linespoints title 'parallel-squares-d0.5 jacobi', \
     $d40 with linespoints title 'parallel-squares-d0.5 monte-carlo', \
     $d41 with linespoints title 'parallel-squares-d0.5 shooting', \
     $d42 with linespoints title 'parallel-squares-d1 direct', \
     $d43 with linespoints title 'parallel-squares-d1 gauss-seidel', \
     $d44 with linespoints title 'parallel-squares-d1 hierarchical', \
     $d45 with linespoints title 'parallel-squares-d1 jacobi', \
     $d46 with linespoints title 'parallel-squares-d1 monte-carlo', \
     $d47 with linespoints title 'parallel-squares-d1 shooting', \
     $d48 with linespoints title 'parallel-squares-d2 direct', \
     $d49 with linespoints title 'parallel-squares-d2 gauss-seidel', \
     $d50 with linespoints title 'parallel-squares-d2 hierarchical', \
     $d51 with linespoints title 'parallel-squares-d2 jacobi', \
     $d52 with linespoints title 'parallel-squares-d2 monte-carlo', \
     $d53 with linespoints title 'parallel-squares-d2 shooting', \
     $d54 with linespoints title 'perpendicular-squares direct', \
     $d55 with linespoints title 'perpendicular-squares gauss-seidel', \
     $d56 with linespoints title 'perpendicular-squares hierarchical', \
     $d57 with linespoints title 'perpendicular-squares jacobi', \
     $d58 with linespoints title 'perpendicular-squares monte-carlo', \
     $d59 with linespoints title 'perpendicular-squares shooting', \
     $d60 with linespoints title 'room-s2 direct', \
     $d61 with linespoints title 'room-s2 gauss-seidel', \
     $d62 with linespoints title 'room-s2 hierarchical', \
     $d63 with linespoints title 'room-s2 jacobi', \
     $d64 with linespoints title 'room-s2 monte-carlo', \
     $d65 with linespoints title 'room-s2 shooting', \
     $d66 with linespoints title 'sphere-rho0.5 direct', \
     $d67 with linespoints title 'sphere-rho0.5 gauss-seidel', \
     $d68 with linespoints title 'sphere-rho0.5 hierarchical', \
     $d69 with linespoints title 'sphere-rho0.5 jacobi', \
     $d70 with linespoints title 'sphere-rho0.5 monte-carlo', \
     $d71 with linespoints title 'sphere-rho0.5 shooting', \
     $d72 with linespoints title 'sphere-rho0.8 direct', \
     $d73 with linespoints title 'sphere-rho0.8 gauss-seidel', \
     $d74 with linespoints title 'sphere-rho0.8 hierarchical', \
     $d75 with linespoints title 'sphere-rho0.8 jacobi', \
     $d76 with linespoints title 'sphere-rho0.8 monte-carlo', \
     $d77 with linespoints title 'sphere-rho0.8 shooting'
