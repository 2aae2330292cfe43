"""Your own FE tire from files (``[tire] model = "frf-file"``): footprint FRFs as UFF 58 and the
footprint's contact nodes as CSV, per load case, run through the whole RM chain.

``spec`` validates the tire file and reads its data files; :mod:`.model` is the model the
pipeline sees (:class:`.model.FRFFileModel`); :mod:`.export` writes any tire model's load cases
as such files.
"""
