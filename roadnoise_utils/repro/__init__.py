"""Reproduction machinery: paths, the stage cache, cached stages, the claims, the collection, the style.

Kept import-free on purpose: ``paths`` is used by the tire and road readers, and the rest
imports every stage, so each module is imported where it is needed.
"""
