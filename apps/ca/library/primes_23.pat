CAMLAB88-CA-PATTERN 1
name prime test of 23
rules turing_primes
ref 8 0
cells 16
8 0 2
9 0 1
11 0 1
12 0 1
13 0 1
14 0 2
2 1 35
2 2 35
0 3 35
1 3 35
2 3 35
3 3 35
4 3 35
8 3 3
2 4 35
2 5 35
end
