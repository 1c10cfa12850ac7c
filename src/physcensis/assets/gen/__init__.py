"""Procedural generators of the built-in catalogue, grouped by shape family."""
