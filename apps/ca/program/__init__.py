"""The interactive ``ca`` program on the Rainbow (thesis sections 7.3.1, 7.3.2).

Pure view and interaction state (``viewport``, ``raster``, ``dialogues``, ``script_events``)
is kept apart from the modules that draw through ``camlab88.protocols.rainbow`` (``drawing``,
``menus``); ``program`` ties them to the model in ``camlab88.apps.ca.session``.
"""
