CAMLAB88-CA-PATTERN 1
name prime test of 25
rules turing_primes
ref 8 0
cells 15
8 0 2
9 0 1
10 0 1
13 0 1
14 0 2
2 1 40
2 2 40
0 3 40
1 3 40
2 3 40
3 3 40
4 3 40
8 3 3
2 4 40
2 5 40
end
