CAMLAB88-CA-PATTERN 1
name maze runner at a corner
rules maze
comment figure 7.7: a runner (head red, tail blue) along a wall (green) that turns a corner
ref 0 0
cells 15
0 0 1
1 0 1
2 0 1
3 0 1
4 0 1
5 0 1
6 0 1
2 1 3
3 1 2
6 1 1
6 2 1
6 3 1
6 4 1
6 5 1
6 6 1
end
