"""Pictures of the toolpath: a scene of styled primitives in one view (:mod:`.scene`), written
as SVG (:mod:`.svg`) or PNG (:mod:`.png`)."""
