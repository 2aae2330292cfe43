"""The cross-section tire model (``[tire] model = "cross-section"``): the tire's construction as a
layered waveguide, expanded in circumferential harmonics, loaded by Green's-function contact.

``spec`` (validated construction files) -> ``laminate`` (layer constants) -> ``geometry`` and
``mesh`` (the layered mesh) -> ``waveguide`` and ``operators`` (harmonic matrices, inflation)
-> ``contact`` and ``static`` (Green's functions, the loaded tire) -> ``dynamics`` (reduced
harmonic receptances) -> ``footprint``, ``footprint_points`` and ``frequency_nodes`` (direct FRFs; the harmonics with no
mode near the band interpolated in frequency), ``modal``
(modal reduction by component-mode synthesis), ``stepping`` and ``one_sided`` (the harmonics
stepped in time, contact loss), ``cavity`` and ``cavity_frf`` (the air cavity); ``checks``
verifies it, ``stages`` caches its stages, :mod:`.model` is the model the pipeline sees
(:class:`.model.CrossSectionModel`).
"""
