set terminal pngcairo size 1280,900 noenhanced
set output 'radiance-peer-example-office.png'
set logscale xy
set format xy '%g'
set grid
set key outside right top
set xlabel 'seconds'
set ylabel 'RMS relative error'
set title 'radiant-bench: error against time'
$d0 << EOD
0.0815607 0.00955194
0.164367 0.00272308
0.296076 0.00167975
0.697546 0.00125901
5.40256 0.000613317
7.90948 0.000593262
EOD
$d1 << EOD
1.0493 0.119505
2.15697 0.0763089
3.91082 0.0441405
7.95975 0.0176665
18.6372 0.00592328
48.0723 0.00598097
56.7295 0.000943718
EOD
plot $d0 with linespoints title 'furnished-office monte-carlo', \
     $d1 with linespoints title 'furnished-office radiance'
