set terminal pngcairo size 1280,900 noenhanced
set output 'radiance-peer-furnished.png'
set logscale xy
set format xy '%g'
set grid
set key outside right top
set xlabel 'seconds'
set ylabel 'RMS relative error'
set title 'radiant-bench: error against time'
$d0 << EOD
0.0812015 0.029549
0.0819974 0.0135417
0.166892 0.00424778
0.53099 0.00175076
0.869247 0.00149103
1.89732 0.00135791
EOD
$d1 << EOD
2.21576 0.0496993
4.11282 0.0292895
6.92243 0.0130283
12.8388 0.00553968
22.119 0.00282816
62.6696 0.00249831
63.4486 0.00215328
EOD
plot $d0 with linespoints title 'furnished-office monte-carlo', \
     $d1 with linespoints title 'furnished-office radiance'
