"""Small pieces every layer uses that cross no wire.

Atomic files, kernel loading and its notices, PNG, text input, did-you-mean.
"""
