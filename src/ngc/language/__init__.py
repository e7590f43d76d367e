"""The RS274/NGC language: reading lines into blocks (lexing, parsing, expressions, the code table)."""
