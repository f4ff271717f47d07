"""HashLife's binary path: two-state rules (found by running the rules, bits/rule.py) on a
plane of 0s and 1s, with 16 x 16-cell leaves of bits advanced by bit operations (after
lifelib's), so the tree has far fewer nodes than the generic one of life-form values.

Modules: ``rule`` (qualification and the transition table), ``store`` (node and leaf
tables, their memory limit), ``collect`` (the tables' growth and garbage collection),
``leaves`` (the base case), ``evolve`` (the recursion), ``convert`` and ``census`` (the
dense window to a tree, statistics), ``cells`` (cell lists to a tree and back), ``frame``
(the two edges), ``run`` (the jumps and the tree the engine adopts).  Exactly the direct
engine's answers, both edges.
"""
