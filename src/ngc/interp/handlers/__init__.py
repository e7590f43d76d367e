"""Convert-phase handlers, one module per concern; each takes the interpreter and a resolved block."""
