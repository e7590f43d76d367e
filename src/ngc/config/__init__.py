"""Configuration inputs read the way LinuxCNC's ``rs274`` reads them: the INI file (``ini``) and the
parameter file (``varfile``)."""
