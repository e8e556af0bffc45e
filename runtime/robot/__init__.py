"""Robot descriptions: the typed description a user writes, its validation, and its split into
the compile-time :class:`~jointplay.robot.structure.Structure` and the run-time parameters."""
