"""The camera control language (thesis §6.3.1): default space, perspective, view files,
the lexer, parser and interpreter that turn a camera script and ball positions into an
observer, viewpoint and focal length for every frame."""
