"""Cells as three-dimensional actors (thesis 8.1): the model, the solids and their renderer."""
