"""``ngc view``: the program in 3D in a browser, with its text, its time and its errors, as one
self-contained HTML page (:func:`~ngc.view.page.build_page`)."""
