"""Films of the cellular automaton with its cells as 3-D actors (thesis 8.1): the motion on
two levels (generations in-betweened, each actor's own cycle), the camera over the grid and
the frames, rendered by apps.actors. The one package that may import both apps.ca and
apps.actors."""
