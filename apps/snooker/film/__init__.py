"""From shot to film (thesis 6.4, 6.5): a sequence's frames rendered as independent tasks on
a local process pool or a Dask cluster, resumable, with motion blur and title animation."""
