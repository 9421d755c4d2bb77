# A flat plate over the tube (the die of an oval pre-form, docs/dies.md): a face from the axis to x = 30 mm at
# the top of the tube (Ro = 17.5 mm: it touches the tube at stroke 0), wide enough for the tube it flattens.
line 0 17.5 30 17.5
