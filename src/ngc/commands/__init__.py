"""The commands of the ``ngc`` command line, one module each, over the library."""
