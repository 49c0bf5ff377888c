set terminal pngcairo size 1280,900 noenhanced
set output 'radiance-peer-library.png'
set logscale xy
set format xy '%g'
set grid
set key outside right top
set xlabel 'seconds'
set ylabel 'RMS relative error'
set title 'radiant-bench: error against time'
$d0 << EOD
0.225662 0.0267384
0.336002 0.0109788
0.992178 0.00411024
2.82565 0.00273547
12.642 0.00206588
EOD
$d1 << EOD
1.47723 0.129379
2.74255 0.0616567
4.67995 0.0253794
9.17841 0.0342152
42.9389 0.00975195
108.577 0.00938527
123.083 0.00494524
EOD
plot $d0 with linespoints title 'library monte-carlo', \
     $d1 with linespoints title 'library radiance'
