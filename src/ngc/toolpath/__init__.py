"""The toolpath layer: canon in, moves in machine coordinates out (see :mod:`.tracker`)."""
