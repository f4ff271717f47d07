"""KAS painting (thesis §3.3): filled areas on the Sigma T5688, the palette, the operations
file, and whole sequences painted automatically from one painted frame.

Model (pure): ``palette``, ``ops`` / ``opsfile`` (the operations file), ``shape`` (select ->
closed shapes, gap closing), ``vector`` + ``kernels`` + ``seeds`` (seed points guaranteed
inside), ``regions`` (planar faces followed across frames), ``autopaint`` (a plan per frame).
Device-facing: ``planes`` (plane use and LUT), ``areas`` (figure 3.7's four working areas),
``orders`` (plans as Sigma orders), ``mixing`` (the colour-mixing area), ``program`` (the
painting program over the 9600-baud line), ``replay`` (double-buffered replay, export).
"""
