"""The ring tire model (``[tire] model = "ring"``): coupled in-plane rings of frame elements on a
viscoelastic foundation, tread springs, one-sided contact (:class:`.model.RingModel`).

``spec`` (validated tire files) -> ``mechanics`` (mass and stiffness, built from ``elements``
and the shared rubber laws) -> ``static`` (contact on a flat road or a drum, ``banded`` its
factor) -> ``loaded`` (the tire linearised about its static state) -> ``frf`` (the direct
FRFs :math:`H_{tot}, H_i, G_H`, paper Eq. (i), ``symmetry`` halving them twice) -> ``modes``
(the frozen FET70Hz eigenproblem, ``mode_shapes`` labelling them) -> ``modal_reduction``
(paper Fig. 4-5). ``fe_reference`` holds the FE solves every RM-chain result is checked
against, ``one_sided`` the contact-loss runs, ``cavity`` the coupling of the air cavity to the
belt, ``closed_form`` the ring-on-foundation check. :mod:`.model` is the model the pipeline sees.
"""
