"""The snooker renderer (thesis 6.4, 6.4.1): finished frames from ball positions and views.

``scene`` builds the description (table, balls, lights), ``painter`` orders what to draw as
the thesis lists it, ``truecolour`` renders it in 24-bit, ``sigma_host`` sends it to a Sigma
T5688 as orders over the serial line (``period`` with the firmware's line drawer and its leak
defect, ``fixed`` with software Bresenham boundaries, ``adapted`` anti-aliasing along the
firmware's own lines), ``palette`` chooses the 256 colours, ``wood`` shades the surround.
"""
