set terminal pngcairo size 1280,900 noenhanced
set output 'radiance-peer-open-plan.png'
set logscale xy
set format xy '%g'
set grid
set key outside right top
set xlabel 'seconds'
set ylabel 'RMS relative error'
set title 'radiant-bench: error against time'
$d0 << EOD
0.0623136 0.0384272
0.0797097 0.00764619
0.170944 0.00274128
0.345578 0.00199333
1.70725 0.00123061
EOD
$d1 << EOD
0.634655 0.0886124
1.21675 0.0541571
2.13244 0.0294819
4.31065 0.0100494
10.9276 0.00494207
27.8351 0.00451512
32.0952 0.0017871
EOD
plot $d0 with linespoints title 'open-plan monte-carlo', \
     $d1 with linespoints title 'open-plan radiance'
