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
2 1 33
2 2 33
0 3 33
1 3 33
2 3 33
3 3 33
4 3 33
8 3 3
2 4 33
2 5 33
end
