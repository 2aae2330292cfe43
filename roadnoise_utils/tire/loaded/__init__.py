"""The loaded FE tire: the cross-section tire's construction swept into 3-D solids, for large-deformation statics.

Built so far: the swept mesh (:mod:`.mesh`), the hyperelastic layers consistent with the
cross-section tire's small-strain moduli (:mod:`.material`) and the total Lagrangian 27-node
layered solids with their consistent tangent and mass (:mod:`.solid`). Linearised about the
round, unloaded tire they are the waveguide tire of the same file
(:mod:`roadnoise_utils.tire.cross_section.waveguide`) with the circumference discretised by
elements instead of Fourier harmonics.
"""
