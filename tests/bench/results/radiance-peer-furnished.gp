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
0.228829 0.00732843
0.246878 0.00732843
0.262013 0.0049118
0.521274 0.00251358
1.0837 0.00191077
1.81347 0.00142305
EOD
$d1 << EOD
2.6208 0.0484821
4.89387 0.0275599
8.33485 0.011588
14.3859 0.00471452
24.1506 0.00176312
EOD
plot $d0 with linespoints title 'furnished-office monte-carlo', \
     $d1 with linespoints title 'furnished-office radiance'
