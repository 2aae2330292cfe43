"""The cross-section tire model (``[tire] model = "cross-section"``): the tire's construction as a
layered waveguide, expanded in circumferential harmonics, loaded by Green's-function contact.

``spec`` validates its tire files; :mod:`.stages` caches its stages; :mod:`.model` is the model
the pipeline sees (:class:`.model.CrossSectionModel`). Its mechanics live, for now, in
:mod:`roadnoise_utils.tire` (``laminate``, ``section_*``, ``waveguide``) and
:mod:`roadnoise_utils.response` (``section_*``, ``footprint_points``).
"""
