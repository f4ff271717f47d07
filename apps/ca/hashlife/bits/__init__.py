"""HashLife's binary leaves: two-state rules (found by running the rules, ``rule``) on a
plane of 0s and 1s, with 16 x 16-cell leaves of bits advanced by bit operations (after
lifelib's, ``leaves``: the base case), so the tree has far fewer nodes than one of
life-form values.  ``run`` is the leaf strategy; the store, the recursion, the conversions
and the census are the package's own, shared with the generic leaves.  Exactly the direct
engine's answers, both edges.
"""
