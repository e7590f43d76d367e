"""Interpretation: resolving blocks against parameters, checking them, executing them in order."""
