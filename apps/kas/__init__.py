"""KAS, the keyframe animation suite of thesis chapter 3: pure models (no device here).

Coordinates are inches of the animator's twelve-field (12" x 8.75"), origin at the field
centre, x to the right and y upwards; see docs/kas.md.
"""
