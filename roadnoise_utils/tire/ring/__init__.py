"""The ring tire model (``[tire] model = "ring"``): coupled in-plane rings of frame elements on a
viscoelastic foundation, tread springs, one-sided contact (:class:`.model.RingModel`).

Its numerics live, for now, in :mod:`roadnoise_utils.tire` (``spec``, ``ring_model``, ``static``)
and :mod:`roadnoise_utils.response` (``frf``, ``modes``, ``modal_reduction``, ``one_sided``,
``fe_reference``); :mod:`.model` is the model the pipeline sees.
"""
